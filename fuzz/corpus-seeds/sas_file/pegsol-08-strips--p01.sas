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
20
Atom move-ended()
Atom last-visited(pos-1-4)
Atom last-visited(pos-4-4)
Atom last-visited(pos-1-2)
Atom last-visited(pos-3-4)
Atom last-visited(pos-0-4)
Atom last-visited(pos-2-4)
Atom last-visited(pos-5-4)
Atom last-visited(pos-3-2)
Atom last-visited(pos-0-2)
Atom last-visited(pos-6-4)
Atom last-visited(pos-3-0)
Atom last-visited(pos-4-2)
Atom last-visited(pos-3-3)
Atom last-visited(pos-2-2)
Atom last-visited(pos-5-2)
Atom last-visited(pos-3-5)
Atom last-visited(pos-3-1)
Atom last-visited(pos-6-2)
Atom last-visited(pos-3-6)
end_variable
begin_variable
var1
-1
2
Atom free(pos-0-2)
Atom occupied(pos-0-2)
end_variable
begin_variable
var2
-1
2
Atom free(pos-0-4)
Atom occupied(pos-0-4)
end_variable
begin_variable
var3
-1
2
Atom free(pos-1-2)
Atom occupied(pos-1-2)
end_variable
begin_variable
var4
-1
2
Atom occupied(pos-1-3)
Atom free(pos-1-3)
end_variable
begin_variable
var5
-1
2
Atom free(pos-1-4)
Atom occupied(pos-1-4)
end_variable
begin_variable
var6
-1
2
Atom occupied(pos-2-2)
Atom free(pos-2-2)
end_variable
begin_variable
var7
-1
2
Atom occupied(pos-2-4)
Atom free(pos-2-4)
end_variable
begin_variable
var8
-1
2
Atom free(pos-3-0)
Atom occupied(pos-3-0)
end_variable
begin_variable
var9
-1
2
Atom occupied(pos-3-1)
Atom free(pos-3-1)
end_variable
begin_variable
var10
-1
2
Atom free(pos-3-2)
Atom occupied(pos-3-2)
end_variable
begin_variable
var11
-1
2
Atom free(pos-3-3)
Atom occupied(pos-3-3)
end_variable
begin_variable
var12
-1
2
Atom occupied(pos-3-4)
Atom free(pos-3-4)
end_variable
begin_variable
var13
-1
2
Atom free(pos-3-5)
Atom occupied(pos-3-5)
end_variable
begin_variable
var14
-1
2
Atom free(pos-3-6)
Atom occupied(pos-3-6)
end_variable
begin_variable
var15
-1
2
Atom free(pos-4-2)
Atom occupied(pos-4-2)
end_variable
begin_variable
var16
-1
2
Atom free(pos-4-4)
Atom occupied(pos-4-4)
end_variable
begin_variable
var17
-1
2
Atom free(pos-5-2)
Atom occupied(pos-5-2)
end_variable
begin_variable
var18
-1
2
Atom free(pos-5-4)
Atom occupied(pos-5-4)
end_variable
begin_variable
var19
-1
2
Atom free(pos-6-2)
Atom occupied(pos-6-2)
end_variable
begin_variable
var20
-1
2
Atom free(pos-6-4)
Atom occupied(pos-6-4)
end_variable
21
begin_mutex_group
2
1 0
1 1
end_mutex_group
begin_mutex_group
2
2 0
2 1
end_mutex_group
begin_mutex_group
2
3 0
3 1
end_mutex_group
begin_mutex_group
2
4 0
4 1
end_mutex_group
begin_mutex_group
2
5 0
5 1
end_mutex_group
begin_mutex_group
2
6 0
6 1
end_mutex_group
begin_mutex_group
2
7 0
7 1
end_mutex_group
begin_mutex_group
2
8 0
8 1
end_mutex_group
begin_mutex_group
2
9 0
9 1
end_mutex_group
begin_mutex_group
2
10 0
10 1
end_mutex_group
begin_mutex_group
2
11 0
11 1
end_mutex_group
begin_mutex_group
2
12 0
12 1
end_mutex_group
begin_mutex_group
2
13 0
13 1
end_mutex_group
begin_mutex_group
2
14 0
14 1
end_mutex_group
begin_mutex_group
2
15 0
15 1
end_mutex_group
begin_mutex_group
2
16 0
16 1
end_mutex_group
begin_mutex_group
2
17 0
17 1
end_mutex_group
begin_mutex_group
2
18 0
18 1
end_mutex_group
begin_mutex_group
2
19 0
19 1
end_mutex_group
begin_mutex_group
2
20 0
20 1
end_mutex_group
begin_mutex_group
20
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
0 16
0 17
0 18
0 19
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
0
0
0
0
end_state
begin_goal
20
1 0
2 0
3 0
4 1
5 0
6 1
7 1
8 0
9 1
10 0
11 1
12 1
13 0
14 0
15 0
16 0
17 0
18 0
19 0
20 0
end_goal
83
begin_operator
jump-new-move pos-0-2 pos-1-2 pos-2-2
0
4
0 0 0 14
0 1 1 0
0 3 1 0
0 6 1 0
1
end_operator
begin_operator
jump-new-move pos-0-4 pos-1-4 pos-2-4
0
4
0 0 0 6
0 2 1 0
0 5 1 0
0 7 1 0
1
end_operator
begin_operator
jump-new-move pos-1-2 pos-1-3 pos-1-4
0
4
0 0 0 1
0 3 1 0
0 4 0 1
0 5 0 1
1
end_operator
begin_operator
jump-new-move pos-1-2 pos-2-2 pos-3-2
0
4
0 0 0 8
0 3 1 0
0 6 0 1
0 10 0 1
1
end_operator
begin_operator
jump-new-move pos-1-4 pos-1-3 pos-1-2
0
4
0 0 0 3
0 3 0 1
0 4 0 1
0 5 1 0
1
end_operator
begin_operator
jump-new-move pos-1-4 pos-2-4 pos-3-4
0
4
0 0 0 4
0 5 1 0
0 7 0 1
0 12 1 0
1
end_operator
begin_operator
jump-new-move pos-2-2 pos-1-2 pos-0-2
0
4
0 0 0 9
0 1 0 1
0 3 1 0
0 6 0 1
1
end_operator
begin_operator
jump-new-move pos-2-2 pos-3-2 pos-4-2
0
4
0 0 0 12
0 6 0 1
0 10 1 0
0 15 0 1
1
end_operator
begin_operator
jump-new-move pos-2-4 pos-1-4 pos-0-4
0
4
0 0 0 5
0 2 0 1
0 5 1 0
0 7 0 1
1
end_operator
begin_operator
jump-new-move pos-2-4 pos-3-4 pos-4-4
0
4
0 0 0 2
0 7 0 1
0 12 0 1
0 16 0 1
1
end_operator
begin_operator
jump-new-move pos-3-0 pos-3-1 pos-3-2
0
4
0 0 0 8
0 8 1 0
0 9 0 1
0 10 0 1
1
end_operator
begin_operator
jump-new-move pos-3-1 pos-3-2 pos-3-3
0
4
0 0 0 13
0 9 0 1
0 10 1 0
0 11 0 1
1
end_operator
begin_operator
jump-new-move pos-3-2 pos-2-2 pos-1-2
0
4
0 0 0 3
0 3 0 1
0 6 0 1
0 10 1 0
1
end_operator
begin_operator
jump-new-move pos-3-2 pos-3-1 pos-3-0
0
4
0 0 0 11
0 8 0 1
0 9 0 1
0 10 1 0
1
end_operator
begin_operator
jump-new-move pos-3-2 pos-3-3 pos-3-4
0
4
0 0 0 4
0 10 1 0
0 11 1 0
0 12 1 0
1
end_operator
begin_operator
jump-new-move pos-3-2 pos-4-2 pos-5-2
0
4
0 0 0 15
0 10 1 0
0 15 1 0
0 17 0 1
1
end_operator
begin_operator
jump-new-move pos-3-3 pos-3-2 pos-3-1
0
4
0 0 0 17
0 9 1 0
0 10 1 0
0 11 1 0
1
end_operator
begin_operator
jump-new-move pos-3-3 pos-3-4 pos-3-5
0
4
0 0 0 16
0 11 1 0
0 12 0 1
0 13 0 1
1
end_operator
begin_operator
jump-new-move pos-3-4 pos-2-4 pos-1-4
0
4
0 0 0 1
0 5 0 1
0 7 0 1
0 12 0 1
1
end_operator
begin_operator
jump-new-move pos-3-4 pos-3-3 pos-3-2
0
4
0 0 0 8
0 10 0 1
0 11 1 0
0 12 0 1
1
end_operator
begin_operator
jump-new-move pos-3-4 pos-3-5 pos-3-6
0
4
0 0 0 19
0 12 0 1
0 13 1 0
0 14 0 1
1
end_operator
begin_operator
jump-new-move pos-3-4 pos-4-4 pos-5-4
0
4
0 0 0 7
0 12 0 1
0 16 1 0
0 18 0 1
1
end_operator
begin_operator
jump-new-move pos-3-5 pos-3-4 pos-3-3
0
4
0 0 0 13
0 11 0 1
0 12 0 1
0 13 1 0
1
end_operator
begin_operator
jump-new-move pos-3-6 pos-3-5 pos-3-4
0
4
0 0 0 4
0 12 1 0
0 13 1 0
0 14 1 0
1
end_operator
begin_operator
jump-new-move pos-4-2 pos-3-2 pos-2-2
0
4
0 0 0 14
0 6 1 0
0 10 1 0
0 15 1 0
1
end_operator
begin_operator
jump-new-move pos-4-2 pos-5-2 pos-6-2
0
4
0 0 0 18
0 15 1 0
0 17 1 0
0 19 0 1
1
end_operator
begin_operator
jump-new-move pos-4-4 pos-3-4 pos-2-4
0
4
0 0 0 6
0 7 1 0
0 12 0 1
0 16 1 0
1
end_operator
begin_operator
jump-new-move pos-4-4 pos-5-4 pos-6-4
0
4
0 0 0 10
0 16 1 0
0 18 1 0
0 20 0 1
1
end_operator
begin_operator
jump-new-move pos-5-2 pos-4-2 pos-3-2
0
4
0 0 0 8
0 10 0 1
0 15 1 0
0 17 1 0
1
end_operator
begin_operator
jump-new-move pos-5-4 pos-4-4 pos-3-4
0
4
0 0 0 4
0 12 1 0
0 16 1 0
0 18 1 0
1
end_operator
begin_operator
jump-new-move pos-6-2 pos-5-2 pos-4-2
0
4
0 0 0 12
0 15 0 1
0 17 1 0
0 19 1 0
1
end_operator
begin_operator
jump-new-move pos-6-4 pos-5-4 pos-4-4
0
4
0 0 0 2
0 16 0 1
0 18 1 0
0 20 1 0
1
end_operator
begin_operator
jump-continue-move pos-0-2 pos-1-2 pos-2-2
0
4
0 0 9 14
0 1 1 0
0 3 1 0
0 6 1 0
0
end_operator
begin_operator
jump-continue-move pos-0-4 pos-1-4 pos-2-4
0
4
0 0 5 6
0 2 1 0
0 5 1 0
0 7 1 0
0
end_operator
begin_operator
jump-continue-move pos-1-2 pos-1-3 pos-1-4
0
4
0 0 3 1
0 3 1 0
0 4 0 1
0 5 0 1
0
end_operator
begin_operator
jump-continue-move pos-1-2 pos-2-2 pos-3-2
0
4
0 0 3 8
0 3 1 0
0 6 0 1
0 10 0 1
0
end_operator
begin_operator
jump-continue-move pos-1-4 pos-1-3 pos-1-2
0
4
0 0 1 3
0 3 0 1
0 4 0 1
0 5 1 0
0
end_operator
begin_operator
jump-continue-move pos-1-4 pos-2-4 pos-3-4
0
4
0 0 1 4
0 5 1 0
0 7 0 1
0 12 1 0
0
end_operator
begin_operator
jump-continue-move pos-2-2 pos-1-2 pos-0-2
0
4
0 0 14 9
0 1 0 1
0 3 1 0
0 6 0 1
0
end_operator
begin_operator
jump-continue-move pos-2-2 pos-3-2 pos-4-2
0
4
0 0 14 12
0 6 0 1
0 10 1 0
0 15 0 1
0
end_operator
begin_operator
jump-continue-move pos-2-4 pos-1-4 pos-0-4
0
4
0 0 6 5
0 2 0 1
0 5 1 0
0 7 0 1
0
end_operator
begin_operator
jump-continue-move pos-2-4 pos-3-4 pos-4-4
0
4
0 0 6 2
0 7 0 1
0 12 0 1
0 16 0 1
0
end_operator
begin_operator
jump-continue-move pos-3-0 pos-3-1 pos-3-2
0
4
0 0 11 8
0 8 1 0
0 9 0 1
0 10 0 1
0
end_operator
begin_operator
jump-continue-move pos-3-1 pos-3-2 pos-3-3
0
4
0 0 17 13
0 9 0 1
0 10 1 0
0 11 0 1
0
end_operator
begin_operator
jump-continue-move pos-3-2 pos-2-2 pos-1-2
0
4
0 0 8 3
0 3 0 1
0 6 0 1
0 10 1 0
0
end_operator
begin_operator
jump-continue-move pos-3-2 pos-3-1 pos-3-0
0
4
0 0 8 11
0 8 0 1
0 9 0 1
0 10 1 0
0
end_operator
begin_operator
jump-continue-move pos-3-2 pos-3-3 pos-3-4
0
4
0 0 8 4
0 10 1 0
0 11 1 0
0 12 1 0
0
end_operator
begin_operator
jump-continue-move pos-3-2 pos-4-2 pos-5-2
0
4
0 0 8 15
0 10 1 0
0 15 1 0
0 17 0 1
0
end_operator
begin_operator
jump-continue-move pos-3-3 pos-3-2 pos-3-1
0
4
0 0 13 17
0 9 1 0
0 10 1 0
0 11 1 0
0
end_operator
begin_operator
jump-continue-move pos-3-3 pos-3-4 pos-3-5
0
4
0 0 13 16
0 11 1 0
0 12 0 1
0 13 0 1
0
end_operator
begin_operator
jump-continue-move pos-3-4 pos-2-4 pos-1-4
0
4
0 0 4 1
0 5 0 1
0 7 0 1
0 12 0 1
0
end_operator
begin_operator
jump-continue-move pos-3-4 pos-3-3 pos-3-2
0
4
0 0 4 8
0 10 0 1
0 11 1 0
0 12 0 1
0
end_operator
begin_operator
jump-continue-move pos-3-4 pos-3-5 pos-3-6
0
4
0 0 4 19
0 12 0 1
0 13 1 0
0 14 0 1
0
end_operator
begin_operator
jump-continue-move pos-3-4 pos-4-4 pos-5-4
0
4
0 0 4 7
0 12 0 1
0 16 1 0
0 18 0 1
0
end_operator
begin_operator
jump-continue-move pos-3-5 pos-3-4 pos-3-3
0
4
0 0 16 13
0 11 0 1
0 12 0 1
0 13 1 0
0
end_operator
begin_operator
jump-continue-move pos-3-6 pos-3-5 pos-3-4
0
4
0 0 19 4
0 12 1 0
0 13 1 0
0 14 1 0
0
end_operator
begin_operator
jump-continue-move pos-4-2 pos-3-2 pos-2-2
0
4
0 0 12 14
0 6 1 0
0 10 1 0
0 15 1 0
0
end_operator
begin_operator
jump-continue-move pos-4-2 pos-5-2 pos-6-2
0
4
0 0 12 18
0 15 1 0
0 17 1 0
0 19 0 1
0
end_operator
begin_operator
jump-continue-move pos-4-4 pos-3-4 pos-2-4
0
4
0 0 2 6
0 7 1 0
0 12 0 1
0 16 1 0
0
end_operator
begin_operator
jump-continue-move pos-4-4 pos-5-4 pos-6-4
0
4
0 0 2 10
0 16 1 0
0 18 1 0
0 20 0 1
0
end_operator
begin_operator
jump-continue-move pos-5-2 pos-4-2 pos-3-2
0
4
0 0 15 8
0 10 0 1
0 15 1 0
0 17 1 0
0
end_operator
begin_operator
jump-continue-move pos-5-4 pos-4-4 pos-3-4
0
4
0 0 7 4
0 12 1 0
0 16 1 0
0 18 1 0
0
end_operator
begin_operator
jump-continue-move pos-6-2 pos-5-2 pos-4-2
0
4
0 0 18 12
0 15 0 1
0 17 1 0
0 19 1 0
0
end_operator
begin_operator
jump-continue-move pos-6-4 pos-5-4 pos-4-4
0
4
0 0 10 2
0 16 0 1
0 18 1 0
0 20 1 0
0
end_operator
begin_operator
end-move pos-0-2
0
1
0 0 9 0
0
end_operator
begin_operator
end-move pos-0-4
0
1
0 0 5 0
0
end_operator
begin_operator
end-move pos-1-2
0
1
0 0 3 0
0
end_operator
begin_operator
end-move pos-1-4
0
1
0 0 1 0
0
end_operator
begin_operator
end-move pos-2-2
0
1
0 0 14 0
0
end_operator
begin_operator
end-move pos-2-4
0
1
0 0 6 0
0
end_operator
begin_operator
end-move pos-3-0
0
1
0 0 11 0
0
end_operator
begin_operator
end-move pos-3-1
0
1
0 0 17 0
0
end_operator
begin_operator
end-move pos-3-2
0
1
0 0 8 0
0
end_operator
begin_operator
end-move pos-3-3
0
1
0 0 13 0
0
end_operator
begin_operator
end-move pos-3-4
0
1
0 0 4 0
0
end_operator
begin_operator
end-move pos-3-5
0
1
0 0 16 0
0
end_operator
begin_operator
end-move pos-3-6
0
1
0 0 19 0
0
end_operator
begin_operator
end-move pos-4-2
0
1
0 0 12 0
0
end_operator
begin_operator
end-move pos-4-4
0
1
0 0 2 0
0
end_operator
begin_operator
end-move pos-5-2
0
1
0 0 15 0
0
end_operator
begin_operator
end-move pos-5-4
0
1
0 0 7 0
0
end_operator
begin_operator
end-move pos-6-2
0
1
0 0 18 0
0
end_operator
begin_operator
end-move pos-6-4
0
1
0 0 10 0
0
end_operator
0
