; Four cubes on the table, two hands; build the tower c1 (bottom), c2, c3.

(define (problem tower-3)
  (:domain cube-stacking)
  (:objects
    left right - hand
    c1 c2 c3 c4 - cube
    table - table)
  (:init
    (hand-free left)
    (hand-free right)
    (on-top c1 table)
    (on-top c2 table)
    (on-top c3 table)
    (on-top c4 table)
    (clear c1)
    (clear c2)
    (clear c3)
    (clear c4)
    (clear table)
    (= (total-cost) 0)
  )
  (:goal (and
    (on-top c2 c1)
    (on-top c3 c2)))
  (:metric minimize (total-cost))
)
