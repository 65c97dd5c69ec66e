; A hand-written cube-stacking domain in the shape of the paper's learned operators
; (Reach, Take, Put, Stack), for trying demoplan before any demonstration is learned.

(define (domain cube-stacking)
  (:requirements :strips :typing :negative-preconditions :equality :action-costs)
  (:types
    hand thing - object
    cube table - thing)
  (:predicates
    (acted-on ?h - hand ?t - thing)
    (in-hand ?h - hand ?c - cube)
    (on-top ?c - cube ?t - thing)
    (clear ?t - thing)
    (hand-free ?h - hand))
  (:functions
    (total-cost) - number)
  (:action reach
    :parameters (?h - hand ?c - cube)
    :precondition (and
      (hand-free ?h)
      (clear ?c)
      (not (acted-on ?h ?c)))
    :effect (and
      (acted-on ?h ?c)
      (increase (total-cost) 1)))
  (:action take
    :parameters (?h - hand ?c - cube ?t - thing)
    :precondition (and
      (acted-on ?h ?c)
      (hand-free ?h)
      (on-top ?c ?t)
      (clear ?c))
    :effect (and
      (in-hand ?h ?c)
      (clear ?t)
      (not (hand-free ?h))
      (not (acted-on ?h ?c))
      (not (on-top ?c ?t))
      (increase (total-cost) 1)))
  (:action put
    :parameters (?h - hand ?c - cube ?t - table)
    :precondition (in-hand ?h ?c)
    :effect (and
      (on-top ?c ?t)
      (hand-free ?h)
      (not (in-hand ?h ?c))
      (increase (total-cost) 1)))
  (:action stack
    :parameters (?h - hand ?c ?d - cube)
    :precondition (and
      (in-hand ?h ?c)
      (clear ?d)
      (not (= ?c ?d)))
    :effect (and
      (on-top ?c ?d)
      (hand-free ?h)
      (not (clear ?d))
      (not (in-hand ?h ?c))
      (increase (total-cost) 1)))
)
