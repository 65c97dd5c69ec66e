begin_version
3
end_version
begin_metric
1
end_metric
21
begin_variable
var0
-1
16
Atom at(player-01, pos-6-4)
Atom at(player-01, pos-6-3)
Atom at(player-01, pos-6-2)
Atom at(player-01, pos-5-2)
Atom at(player-01, pos-4-2)
Atom at(player-01, pos-3-2)
Atom at(player-01, pos-4-3)
Atom at(player-01, pos-2-2)
Atom at(player-01, pos-4-4)
Atom at(player-01, pos-2-3)
Atom at(player-01, pos-3-4)
Atom at(player-01, pos-4-5)
Atom at(player-01, pos-5-4)
Atom at(player-01, pos-2-4)
Atom at(player-01, pos-3-5)
Atom at(player-01, pos-2-5)
end_variable
begin_variable
var1
-1
14
Atom at(stone-01, pos-4-4)
Atom at(stone-01, pos-4-5)
Atom at(stone-01, pos-4-3)
Atom at(stone-01, pos-3-4)
Atom at(stone-01, pos-4-2)
Atom at(stone-01, pos-5-4)
Atom at(stone-01, pos-2-4)
Atom at(stone-01, pos-3-2)
Atom at(stone-01, pos-5-2)
Atom at(stone-01, pos-6-4)
Atom at(stone-01, pos-2-3)
Atom at(stone-01, pos-2-5)
Atom at(stone-01, pos-2-2)
Atom at(stone-01, pos-6-2)
end_variable
begin_variable
var2
-1
14
Atom at(stone-02, pos-5-4)
Atom at(stone-02, pos-6-4)
Atom at(stone-02, pos-4-4)
Atom at(stone-02, pos-3-4)
Atom at(stone-02, pos-4-3)
Atom at(stone-02, pos-4-5)
Atom at(stone-02, pos-2-4)
Atom at(stone-02, pos-4-2)
Atom at(stone-02, pos-2-3)
Atom at(stone-02, pos-2-5)
Atom at(stone-02, pos-3-2)
Atom at(stone-02, pos-5-2)
Atom at(stone-02, pos-2-2)
Atom at(stone-02, pos-6-2)
end_variable
begin_variable
var3
-1
2
Atom at-goal(stone-02)
NegatedAtom at-goal(stone-02)
end_variable
begin_variable
var4
-1
2
Atom clear(pos-2-2)
NegatedAtom clear(pos-2-2)
end_variable
begin_variable
var5
-1
2
Atom clear(pos-2-3)
NegatedAtom clear(pos-2-3)
end_variable
begin_variable
var6
-1
2
Atom clear(pos-2-4)
NegatedAtom clear(pos-2-4)
end_variable
begin_variable
var7
-1
2
Atom clear(pos-2-5)
NegatedAtom clear(pos-2-5)
end_variable
begin_variable
var8
-1
2
Atom clear(pos-3-2)
NegatedAtom clear(pos-3-2)
end_variable
begin_variable
var9
-1
2
Atom clear(pos-3-4)
NegatedAtom clear(pos-3-4)
end_variable
begin_variable
var10
-1
2
Atom clear(pos-3-5)
NegatedAtom clear(pos-3-5)
end_variable
begin_variable
var11
-1
2
Atom clear(pos-4-2)
NegatedAtom clear(pos-4-2)
end_variable
begin_variable
var12
-1
2
Atom clear(pos-4-3)
NegatedAtom clear(pos-4-3)
end_variable
begin_variable
var13
-1
2
Atom clear(pos-4-5)
NegatedAtom clear(pos-4-5)
end_variable
begin_variable
var14
-1
2
Atom clear(pos-5-2)
NegatedAtom clear(pos-5-2)
end_variable
begin_variable
var15
-1
2
Atom clear(pos-6-2)
NegatedAtom clear(pos-6-2)
end_variable
begin_variable
var16
-1
2
Atom clear(pos-6-3)
NegatedAtom clear(pos-6-3)
end_variable
begin_variable
var17
-1
2
Atom clear(pos-6-4)
NegatedAtom clear(pos-6-4)
end_variable
begin_variable
var18
-1
2
Atom clear(pos-4-4)
NegatedAtom clear(pos-4-4)
end_variable
begin_variable
var19
-1
2
Atom clear(pos-5-4)
NegatedAtom clear(pos-5-4)
end_variable
begin_variable
var20
-1
2
Atom at-goal(stone-01)
NegatedAtom at-goal(stone-01)
end_variable
19
begin_mutex_group
16
0 0
0 1
0 2
0 3
0 4
0 5
0 6
0 7
0 8
0 9
0 10
0 11
0 12
0 13
0 14
0 15
end_mutex_group
begin_mutex_group
14
1 0
1 1
1 2
1 3
1 4
1 5
1 6
1 7
1 8
1 9
1 10
1 11
1 12
1 13
end_mutex_group
begin_mutex_group
14
2 0
2 1
2 2
2 3
2 4
2 5
2 6
2 7
2 8
2 9
2 10
2 11
2 12
2 13
end_mutex_group
begin_mutex_group
4
4 0
0 7
1 12
2 12
end_mutex_group
begin_mutex_group
4
5 0
0 9
1 10
2 8
end_mutex_group
begin_mutex_group
4
6 0
0 13
1 6
2 6
end_mutex_group
begin_mutex_group
4
7 0
0 15
1 11
2 9
end_mutex_group
begin_mutex_group
4
8 0
0 5
1 7
2 10
end_mutex_group
begin_mutex_group
4
9 0
0 10
1 3
2 3
end_mutex_group
begin_mutex_group
2
10 0
0 14
end_mutex_group
begin_mutex_group
4
11 0
0 4
1 4
2 7
end_mutex_group
begin_mutex_group
4
12 0
0 6
1 2
2 4
end_mutex_group
begin_mutex_group
4
1 0
0 8
18 0
2 2
end_mutex_group
begin_mutex_group
4
13 0
1 1
0 11
2 5
end_mutex_group
begin_mutex_group
4
14 0
0 3
1 8
2 11
end_mutex_group
begin_mutex_group
4
2 0
0 12
19 0
1 5
end_mutex_group
begin_mutex_group
4
15 0
0 2
1 13
2 13
end_mutex_group
begin_mutex_group
2
16 0
0 1
end_mutex_group
begin_mutex_group
4
0 0
17 0
2 1
1 9
end_mutex_group
begin_state
0
0
0
0
0
0
0
0
0
0
0
0
0
0
0
0
0
1
1
1
1
end_state
begin_goal
2
3 0
20 0
end_goal
78
begin_operator
move player-01 pos-2-2 pos-2-3 dir-down
0
3
0 0 7 9
0 4 -1 0
0 5 0 1
0
end_operator
begin_operator
move player-01 pos-2-2 pos-3-2 dir-right
0
3
0 0 7 5
0 4 -1 0
0 8 0 1
0
end_operator
begin_operator
move player-01 pos-2-3 pos-2-2 dir-up
0
3
0 0 9 7
0 4 0 1
0 5 -1 0
0
end_operator
begin_operator
move player-01 pos-2-3 pos-2-4 dir-down
0
3
0 0 9 13
0 5 -1 0
0 6 0 1
0
end_operator
begin_operator
move player-01 pos-2-4 pos-2-3 dir-up
0
3
0 0 13 9
0 5 0 1
0 6 -1 0
0
end_operator
begin_operator
move player-01 pos-2-4 pos-2-5 dir-down
0
3
0 0 13 15
0 6 -1 0
0 7 0 1
0
end_operator
begin_operator
move player-01 pos-2-4 pos-3-4 dir-right
0
3
0 0 13 10
0 6 -1 0
0 9 0 1
0
end_operator
begin_operator
move player-01 pos-2-5 pos-2-4 dir-up
0
3
0 0 15 13
0 6 0 1
0 7 -1 0
0
end_operator
begin_operator
move player-01 pos-2-5 pos-3-5 dir-right
0
3
0 0 15 14
0 7 -1 0
0 10 0 1
0
end_operator
begin_operator
move player-01 pos-3-2 pos-2-2 dir-left
0
3
0 0 5 7
0 4 0 1
0 8 -1 0
0
end_operator
begin_operator
move player-01 pos-3-2 pos-4-2 dir-right
0
3
0 0 5 4
0 8 -1 0
0 11 0 1
0
end_operator
begin_operator
move player-01 pos-3-4 pos-2-4 dir-left
0
3
0 0 10 13
0 6 0 1
0 9 -1 0
0
end_operator
begin_operator
move player-01 pos-3-4 pos-3-5 dir-down
0
3
0 0 10 14
0 9 -1 0
0 10 0 1
0
end_operator
begin_operator
move player-01 pos-3-4 pos-4-4 dir-right
0
3
0 0 10 8
0 9 -1 0
0 18 0 1
0
end_operator
begin_operator
move player-01 pos-3-5 pos-2-5 dir-left
0
3
0 0 14 15
0 7 0 1
0 10 -1 0
0
end_operator
begin_operator
move player-01 pos-3-5 pos-3-4 dir-up
0
3
0 0 14 10
0 9 0 1
0 10 -1 0
0
end_operator
begin_operator
move player-01 pos-3-5 pos-4-5 dir-right
0
3
0 0 14 11
0 10 -1 0
0 13 0 1
0
end_operator
begin_operator
move player-01 pos-4-2 pos-3-2 dir-left
0
3
0 0 4 5
0 8 0 1
0 11 -1 0
0
end_operator
begin_operator
move player-01 pos-4-2 pos-4-3 dir-down
0
3
0 0 4 6
0 11 -1 0
0 12 0 1
0
end_operator
begin_operator
move player-01 pos-4-2 pos-5-2 dir-right
0
3
0 0 4 3
0 11 -1 0
0 14 0 1
0
end_operator
begin_operator
move player-01 pos-4-3 pos-4-2 dir-up
0
3
0 0 6 4
0 11 0 1
0 12 -1 0
0
end_operator
begin_operator
move player-01 pos-4-3 pos-4-4 dir-down
0
3
0 0 6 8
0 12 -1 0
0 18 0 1
0
end_operator
begin_operator
move player-01 pos-4-4 pos-3-4 dir-left
0
3
0 0 8 10
0 9 0 1
0 18 -1 0
0
end_operator
begin_operator
move player-01 pos-4-4 pos-4-3 dir-up
0
3
0 0 8 6
0 12 0 1
0 18 -1 0
0
end_operator
begin_operator
move player-01 pos-4-4 pos-4-5 dir-down
0
3
0 0 8 11
0 13 0 1
0 18 -1 0
0
end_operator
begin_operator
move player-01 pos-4-4 pos-5-4 dir-right
0
3
0 0 8 12
0 18 -1 0
0 19 0 1
0
end_operator
begin_operator
move player-01 pos-4-5 pos-3-5 dir-left
0
3
0 0 11 14
0 10 0 1
0 13 -1 0
0
end_operator
begin_operator
move player-01 pos-4-5 pos-4-4 dir-up
0
3
0 0 11 8
0 13 -1 0
0 18 0 1
0
end_operator
begin_operator
move player-01 pos-5-2 pos-4-2 dir-left
0
3
0 0 3 4
0 11 0 1
0 14 -1 0
0
end_operator
begin_operator
move player-01 pos-5-2 pos-6-2 dir-right
0
3
0 0 3 2
0 14 -1 0
0 15 0 1
0
end_operator
begin_operator
move player-01 pos-5-4 pos-4-4 dir-left
0
3
0 0 12 8
0 18 0 1
0 19 -1 0
0
end_operator
begin_operator
move player-01 pos-5-4 pos-6-4 dir-right
0
3
0 0 12 0
0 17 0 1
0 19 -1 0
0
end_operator
begin_operator
move player-01 pos-6-2 pos-5-2 dir-left
0
3
0 0 2 3
0 14 0 1
0 15 -1 0
0
end_operator
begin_operator
move player-01 pos-6-2 pos-6-3 dir-down
0
3
0 0 2 1
0 15 -1 0
0 16 0 1
0
end_operator
begin_operator
move player-01 pos-6-3 pos-6-2 dir-up
0
3
0 0 1 2
0 15 0 1
0 16 -1 0
0
end_operator
begin_operator
move player-01 pos-6-3 pos-6-4 dir-down
0
3
0 0 1 0
0 16 -1 0
0 17 0 1
0
end_operator
begin_operator
move player-01 pos-6-4 pos-5-4 dir-left
0
3
0 0 0 12
0 17 -1 0
0 19 0 1
0
end_operator
begin_operator
move player-01 pos-6-4 pos-6-3 dir-up
0
3
0 0 0 1
0 16 0 1
0 17 -1 0
0
end_operator
begin_operator
push-to-nongoal player-01 stone-01 pos-2-2 pos-3-2 pos-4-2 dir-right
0
5
0 0 7 5
0 1 7 4
0 4 -1 0
0 11 0 1
0 20 -1 1
1
end_operator
begin_operator
push-to-nongoal player-01 stone-01 pos-2-3 pos-2-4 pos-2-5 dir-down
0
5
0 0 9 13
0 1 6 11
0 5 -1 0
0 7 0 1
0 20 -1 1
1
end_operator
begin_operator
push-to-nongoal player-01 stone-01 pos-2-4 pos-2-3 pos-2-2 dir-up
0
5
0 0 13 9
0 1 10 12
0 4 0 1
0 6 -1 0
0 20 -1 1
1
end_operator
begin_operator
push-to-nongoal player-01 stone-01 pos-2-4 pos-3-4 pos-4-4 dir-right
0
5
0 0 13 10
0 1 3 0
0 6 -1 0
0 18 0 1
0 20 -1 1
1
end_operator
begin_operator
push-to-nongoal player-01 stone-01 pos-2-5 pos-2-4 pos-2-3 dir-up
0
5
0 0 15 13
0 1 6 10
0 5 0 1
0 7 -1 0
0 20 -1 1
1
end_operator
begin_operator
push-to-nongoal player-01 stone-01 pos-3-2 pos-4-2 pos-5-2 dir-right
0
5
0 0 5 4
0 1 4 8
0 8 -1 0
0 14 0 1
0 20 -1 1
1
end_operator
begin_operator
push-to-nongoal player-01 stone-01 pos-4-2 pos-3-2 pos-2-2 dir-left
0
5
0 0 4 5
0 1 7 12
0 4 0 1
0 11 -1 0
0 20 -1 1
1
end_operator
begin_operator
push-to-nongoal player-01 stone-01 pos-4-2 pos-4-3 pos-4-4 dir-down
0
5
0 0 4 6
0 1 2 0
0 11 -1 0
0 18 0 1
0 20 -1 1
1
end_operator
begin_operator
push-to-nongoal player-01 stone-01 pos-4-2 pos-5-2 pos-6-2 dir-right
0
5
0 0 4 3
0 1 8 13
0 11 -1 0
0 15 0 1
0 20 -1 1
1
end_operator
begin_operator
push-to-nongoal player-01 stone-01 pos-4-3 pos-4-4 pos-4-5 dir-down
0
5
0 0 6 8
0 1 0 1
0 12 -1 0
0 13 0 1
0 20 -1 1
1
end_operator
begin_operator
push-to-nongoal player-01 stone-01 pos-4-4 pos-4-3 pos-4-2 dir-up
0
5
0 0 8 6
0 1 2 4
0 11 0 1
0 18 -1 0
0 20 -1 1
1
end_operator
begin_operator
push-to-nongoal player-01 stone-01 pos-4-4 pos-5-4 pos-6-4 dir-right
0
5
0 0 8 12
0 1 5 9
0 17 0 1
0 18 -1 0
0 20 -1 1
1
end_operator
begin_operator
push-to-nongoal player-01 stone-01 pos-4-5 pos-4-4 pos-4-3 dir-up
0
5
0 0 11 8
0 1 0 2
0 12 0 1
0 13 -1 0
0 20 -1 1
1
end_operator
begin_operator
push-to-nongoal player-01 stone-01 pos-5-2 pos-4-2 pos-3-2 dir-left
0
5
0 0 3 4
0 1 4 7
0 8 0 1
0 14 -1 0
0 20 -1 1
1
end_operator
begin_operator
push-to-nongoal player-01 stone-01 pos-5-4 pos-4-4 pos-3-4 dir-left
0
5
0 0 12 8
0 1 0 3
0 9 0 1
0 19 -1 0
0 20 -1 1
1
end_operator
begin_operator
push-to-nongoal player-01 stone-01 pos-6-2 pos-5-2 pos-4-2 dir-left
0
5
0 0 2 3
0 1 8 4
0 11 0 1
0 15 -1 0
0 20 -1 1
1
end_operator
begin_operator
push-to-nongoal player-01 stone-01 pos-6-4 pos-5-4 pos-4-4 dir-left
0
5
0 0 0 12
0 1 5 0
0 17 -1 0
0 18 0 1
0 20 -1 1
1
end_operator
begin_operator
push-to-nongoal player-01 stone-02 pos-2-2 pos-3-2 pos-4-2 dir-right
0
5
0 0 7 5
0 2 10 7
0 3 -1 1
0 4 -1 0
0 11 0 1
1
end_operator
begin_operator
push-to-nongoal player-01 stone-02 pos-2-3 pos-2-4 pos-2-5 dir-down
0
5
0 0 9 13
0 2 6 9
0 3 -1 1
0 5 -1 0
0 7 0 1
1
end_operator
begin_operator
push-to-nongoal player-01 stone-02 pos-2-4 pos-2-3 pos-2-2 dir-up
0
5
0 0 13 9
0 2 8 12
0 3 -1 1
0 4 0 1
0 6 -1 0
1
end_operator
begin_operator
push-to-nongoal player-01 stone-02 pos-2-4 pos-3-4 pos-4-4 dir-right
0
5
0 0 13 10
0 2 3 2
0 3 -1 1
0 6 -1 0
0 18 0 1
1
end_operator
begin_operator
push-to-nongoal player-01 stone-02 pos-2-5 pos-2-4 pos-2-3 dir-up
0
5
0 0 15 13
0 2 6 8
0 3 -1 1
0 5 0 1
0 7 -1 0
1
end_operator
begin_operator
push-to-nongoal player-01 stone-02 pos-3-2 pos-4-2 pos-5-2 dir-right
0
5
0 0 5 4
0 2 7 11
0 3 -1 1
0 8 -1 0
0 14 0 1
1
end_operator
begin_operator
push-to-nongoal player-01 stone-02 pos-4-2 pos-3-2 pos-2-2 dir-left
0
5
0 0 4 5
0 2 10 12
0 3 -1 1
0 4 0 1
0 11 -1 0
1
end_operator
begin_operator
push-to-nongoal player-01 stone-02 pos-4-2 pos-4-3 pos-4-4 dir-down
0
5
0 0 4 6
0 2 4 2
0 3 -1 1
0 11 -1 0
0 18 0 1
1
end_operator
begin_operator
push-to-nongoal player-01 stone-02 pos-4-2 pos-5-2 pos-6-2 dir-right
0
5
0 0 4 3
0 2 11 13
0 3 -1 1
0 11 -1 0
0 15 0 1
1
end_operator
begin_operator
push-to-nongoal player-01 stone-02 pos-4-3 pos-4-4 pos-4-5 dir-down
0
5
0 0 6 8
0 2 2 5
0 3 -1 1
0 12 -1 0
0 13 0 1
1
end_operator
begin_operator
push-to-nongoal player-01 stone-02 pos-4-4 pos-4-3 pos-4-2 dir-up
0
5
0 0 8 6
0 2 4 7
0 3 -1 1
0 11 0 1
0 18 -1 0
1
end_operator
begin_operator
push-to-nongoal player-01 stone-02 pos-4-4 pos-5-4 pos-6-4 dir-right
0
5
0 0 8 12
0 2 0 1
0 3 -1 1
0 17 0 1
0 18 -1 0
1
end_operator
begin_operator
push-to-nongoal player-01 stone-02 pos-4-5 pos-4-4 pos-4-3 dir-up
0
5
0 0 11 8
0 2 2 4
0 3 -1 1
0 12 0 1
0 13 -1 0
1
end_operator
begin_operator
push-to-nongoal player-01 stone-02 pos-5-2 pos-4-2 pos-3-2 dir-left
0
5
0 0 3 4
0 2 7 10
0 3 -1 1
0 8 0 1
0 14 -1 0
1
end_operator
begin_operator
push-to-nongoal player-01 stone-02 pos-5-4 pos-4-4 pos-3-4 dir-left
0
5
0 0 12 8
0 2 2 3
0 3 -1 1
0 9 0 1
0 19 -1 0
1
end_operator
begin_operator
push-to-nongoal player-01 stone-02 pos-6-2 pos-5-2 pos-4-2 dir-left
0
5
0 0 2 3
0 2 11 7
0 3 -1 1
0 11 0 1
0 15 -1 0
1
end_operator
begin_operator
push-to-nongoal player-01 stone-02 pos-6-4 pos-5-4 pos-4-4 dir-left
0
5
0 0 0 12
0 2 0 2
0 3 -1 1
0 17 -1 0
0 18 0 1
1
end_operator
begin_operator
push-to-goal player-01 stone-01 pos-2-2 pos-2-3 pos-2-4 dir-down
0
5
0 0 7 9
0 1 10 6
0 4 -1 0
0 6 0 1
0 20 -1 0
1
end_operator
begin_operator
push-to-goal player-01 stone-01 pos-3-4 pos-4-4 pos-5-4 dir-right
0
5
0 0 10 8
0 1 0 5
0 9 -1 0
0 19 0 1
0 20 -1 0
1
end_operator
begin_operator
push-to-goal player-01 stone-01 pos-4-4 pos-3-4 pos-2-4 dir-left
0
5
0 0 8 10
0 1 3 6
0 6 0 1
0 18 -1 0
0 20 -1 0
1
end_operator
begin_operator
push-to-goal player-01 stone-02 pos-2-2 pos-2-3 pos-2-4 dir-down
0
5
0 0 7 9
0 2 8 6
0 3 -1 0
0 4 -1 0
0 6 0 1
1
end_operator
begin_operator
push-to-goal player-01 stone-02 pos-3-4 pos-4-4 pos-5-4 dir-right
0
5
0 0 10 8
0 2 2 0
0 3 -1 0
0 9 -1 0
0 19 0 1
1
end_operator
begin_operator
push-to-goal player-01 stone-02 pos-4-4 pos-3-4 pos-2-4 dir-left
0
5
0 0 8 10
0 2 3 6
0 3 -1 0
0 6 0 1
0 18 -1 0
1
end_operator
0
