begin_version
3
end_version
begin_metric
1
end_metric
34
begin_variable
var0
-1
34
Atom move-ended()
Atom last-visited(pos-3-1)
Atom last-visited(pos-3-4)
Atom last-visited(pos-2-3)
Atom last-visited(pos-4-2)
Atom last-visited(pos-4-5)
Atom last-visited(pos-6-3)
Atom last-visited(pos-3-3)
Atom last-visited(pos-3-0)
Atom last-visited(pos-1-4)
Atom last-visited(pos-3-2)
Atom last-visited(pos-5-4)
Atom last-visited(pos-3-5)
Atom last-visited(pos-2-5)
Atom last-visited(pos-4-3)
Atom last-visited(pos-2-2)
Atom last-visited(pos-1-3)
Atom last-visited(pos-4-4)
Atom last-visited(pos-5-2)
Atom last-visited(pos-4-1)
Atom last-visited(pos-4-6)
Atom last-visited(pos-5-3)
Atom last-visited(pos-2-4)
Atom last-visited(pos-0-4)
Atom last-visited(pos-6-4)
Atom last-visited(pos-3-6)
Atom last-visited(pos-2-6)
Atom last-visited(pos-1-2)
Atom last-visited(pos-2-1)
Atom last-visited(pos-0-3)
Atom last-visited(pos-6-2)
Atom last-visited(pos-4-0)
Atom last-visited(pos-0-2)
Atom last-visited(pos-2-0)
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
Atom free(pos-0-3)
Atom occupied(pos-0-3)
end_variable
begin_variable
var3
-1
2
Atom free(pos-0-4)
Atom occupied(pos-0-4)
end_variable
begin_variable
var4
-1
2
Atom free(pos-1-2)
Atom occupied(pos-1-2)
end_variable
begin_variable
var5
-1
2
Atom free(pos-1-3)
Atom occupied(pos-1-3)
end_variable
begin_variable
var6
-1
2
Atom free(pos-1-4)
Atom occupied(pos-1-4)
end_variable
begin_variable
var7
-1
2
Atom free(pos-2-0)
Atom occupied(pos-2-0)
end_variable
begin_variable
var8
-1
2
Atom free(pos-2-1)
Atom occupied(pos-2-1)
end_variable
begin_variable
var9
-1
2
Atom free(pos-2-2)
Atom occupied(pos-2-2)
end_variable
begin_variable
var10
-1
2
Atom free(pos-2-3)
Atom occupied(pos-2-3)
end_variable
begin_variable
var11
-1
2
Atom occupied(pos-2-4)
Atom free(pos-2-4)
end_variable
begin_variable
var12
-1
2
Atom free(pos-2-5)
Atom occupied(pos-2-5)
end_variable
begin_variable
var13
-1
2
Atom free(pos-2-6)
Atom occupied(pos-2-6)
end_variable
begin_variable
var14
-1
2
Atom free(pos-3-0)
Atom occupied(pos-3-0)
end_variable
begin_variable
var15
-1
2
Atom free(pos-3-1)
Atom occupied(pos-3-1)
end_variable
begin_variable
var16
-1
2
Atom occupied(pos-3-2)
Atom free(pos-3-2)
end_variable
begin_variable
var17
-1
2
Atom occupied(pos-3-3)
Atom free(pos-3-3)
end_variable
begin_variable
var18
-1
2
Atom free(pos-3-4)
Atom occupied(pos-3-4)
end_variable
begin_variable
var19
-1
2
Atom free(pos-3-5)
Atom occupied(pos-3-5)
end_variable
begin_variable
var20
-1
2
Atom free(pos-3-6)
Atom occupied(pos-3-6)
end_variable
begin_variable
var21
-1
2
Atom free(pos-4-0)
Atom occupied(pos-4-0)
end_variable
begin_variable
var22
-1
2
Atom free(pos-4-1)
Atom occupied(pos-4-1)
end_variable
begin_variable
var23
-1
2
Atom free(pos-4-2)
Atom occupied(pos-4-2)
end_variable
begin_variable
var24
-1
2
Atom occupied(pos-4-3)
Atom free(pos-4-3)
end_variable
begin_variable
var25
-1
2
Atom occupied(pos-4-4)
Atom free(pos-4-4)
end_variable
begin_variable
var26
-1
2
Atom free(pos-4-5)
Atom occupied(pos-4-5)
end_variable
begin_variable
var27
-1
2
Atom free(pos-4-6)
Atom occupied(pos-4-6)
end_variable
begin_variable
var28
-1
2
Atom free(pos-5-2)
Atom occupied(pos-5-2)
end_variable
begin_variable
var29
-1
2
Atom occupied(pos-5-3)
Atom free(pos-5-3)
end_variable
begin_variable
var30
-1
2
Atom free(pos-5-4)
Atom occupied(pos-5-4)
end_variable
begin_variable
var31
-1
2
Atom free(pos-6-2)
Atom occupied(pos-6-2)
end_variable
begin_variable
var32
-1
2
Atom free(pos-6-3)
Atom occupied(pos-6-3)
end_variable
begin_variable
var33
-1
2
Atom free(pos-6-4)
Atom occupied(pos-6-4)
end_variable
34
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
2
21 0
21 1
end_mutex_group
begin_mutex_group
2
22 0
22 1
end_mutex_group
begin_mutex_group
2
23 0
23 1
end_mutex_group
begin_mutex_group
2
24 0
24 1
end_mutex_group
begin_mutex_group
2
25 0
25 1
end_mutex_group
begin_mutex_group
2
26 0
26 1
end_mutex_group
begin_mutex_group
2
27 0
27 1
end_mutex_group
begin_mutex_group
2
28 0
28 1
end_mutex_group
begin_mutex_group
2
29 0
29 1
end_mutex_group
begin_mutex_group
2
30 0
30 1
end_mutex_group
begin_mutex_group
2
31 0
31 1
end_mutex_group
begin_mutex_group
2
32 0
32 1
end_mutex_group
begin_mutex_group
2
33 0
33 1
end_mutex_group
begin_mutex_group
34
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
0 20
0 21
0 22
0 23
0 24
0 25
0 26
0 27
0 28
0 29
0 30
0 31
0 32
0 33
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
33
1 0
2 0
3 0
4 0
5 0
6 0
7 0
8 0
9 0
10 0
11 1
12 0
13 0
14 0
15 0
16 1
17 0
18 0
19 0
20 0
21 0
22 0
23 0
24 1
25 1
26 0
27 0
28 0
29 1
30 0
31 0
32 0
33 0
end_goal
185
begin_operator
jump-new-move pos-0-2 pos-0-3 pos-0-4
0
4
0 0 0 23
0 1 1 0
0 2 1 0
0 3 0 1
1
end_operator
begin_operator
jump-new-move pos-0-2 pos-1-2 pos-2-2
0
4
0 0 0 15
0 1 1 0
0 4 1 0
0 9 0 1
1
end_operator
begin_operator
jump-new-move pos-0-3 pos-1-3 pos-2-3
0
4
0 0 0 3
0 2 1 0
0 5 1 0
0 10 0 1
1
end_operator
begin_operator
jump-new-move pos-0-4 pos-0-3 pos-0-2
0
4
0 0 0 32
0 1 0 1
0 2 1 0
0 3 1 0
1
end_operator
begin_operator
jump-new-move pos-0-4 pos-1-4 pos-2-4
0
4
0 0 0 22
0 3 1 0
0 6 1 0
0 11 1 0
1
end_operator
begin_operator
jump-new-move pos-1-2 pos-1-3 pos-1-4
0
4
0 0 0 9
0 4 1 0
0 5 1 0
0 6 0 1
1
end_operator
begin_operator
jump-new-move pos-1-2 pos-2-2 pos-3-2
0
4
0 0 0 10
0 4 1 0
0 9 1 0
0 16 1 0
1
end_operator
begin_operator
jump-new-move pos-1-3 pos-2-3 pos-3-3
0
4
0 0 0 7
0 5 1 0
0 10 1 0
0 17 1 0
1
end_operator
begin_operator
jump-new-move pos-1-4 pos-1-3 pos-1-2
0
4
0 0 0 27
0 4 0 1
0 5 1 0
0 6 1 0
1
end_operator
begin_operator
jump-new-move pos-1-4 pos-2-4 pos-3-4
0
4
0 0 0 2
0 6 1 0
0 11 0 1
0 18 0 1
1
end_operator
begin_operator
jump-new-move pos-2-0 pos-2-1 pos-2-2
0
4
0 0 0 15
0 7 1 0
0 8 1 0
0 9 0 1
1
end_operator
begin_operator
jump-new-move pos-2-0 pos-3-0 pos-4-0
0
4
0 0 0 31
0 7 1 0
0 14 1 0
0 21 0 1
1
end_operator
begin_operator
jump-new-move pos-2-1 pos-2-2 pos-2-3
0
4
0 0 0 3
0 8 1 0
0 9 1 0
0 10 0 1
1
end_operator
begin_operator
jump-new-move pos-2-1 pos-3-1 pos-4-1
0
4
0 0 0 19
0 8 1 0
0 15 1 0
0 22 0 1
1
end_operator
begin_operator
jump-new-move pos-2-2 pos-1-2 pos-0-2
0
4
0 0 0 32
0 1 0 1
0 4 1 0
0 9 1 0
1
end_operator
begin_operator
jump-new-move pos-2-2 pos-2-1 pos-2-0
0
4
0 0 0 33
0 7 0 1
0 8 1 0
0 9 1 0
1
end_operator
begin_operator
jump-new-move pos-2-2 pos-2-3 pos-2-4
0
4
0 0 0 22
0 9 1 0
0 10 1 0
0 11 1 0
1
end_operator
begin_operator
jump-new-move pos-2-2 pos-3-2 pos-4-2
0
4
0 0 0 4
0 9 1 0
0 16 0 1
0 23 0 1
1
end_operator
begin_operator
jump-new-move pos-2-3 pos-1-3 pos-0-3
0
4
0 0 0 29
0 2 0 1
0 5 1 0
0 10 1 0
1
end_operator
begin_operator
jump-new-move pos-2-3 pos-2-2 pos-2-1
0
4
0 0 0 28
0 8 0 1
0 9 1 0
0 10 1 0
1
end_operator
begin_operator
jump-new-move pos-2-3 pos-2-4 pos-2-5
0
4
0 0 0 13
0 10 1 0
0 11 0 1
0 12 0 1
1
end_operator
begin_operator
jump-new-move pos-2-3 pos-3-3 pos-4-3
0
4
0 0 0 14
0 10 1 0
0 17 0 1
0 24 1 0
1
end_operator
begin_operator
jump-new-move pos-2-4 pos-1-4 pos-0-4
0
4
0 0 0 23
0 3 0 1
0 6 1 0
0 11 0 1
1
end_operator
begin_operator
jump-new-move pos-2-4 pos-2-3 pos-2-2
0
4
0 0 0 15
0 9 0 1
0 10 1 0
0 11 0 1
1
end_operator
begin_operator
jump-new-move pos-2-4 pos-2-5 pos-2-6
0
4
0 0 0 26
0 11 0 1
0 12 1 0
0 13 0 1
1
end_operator
begin_operator
jump-new-move pos-2-4 pos-3-4 pos-4-4
0
4
0 0 0 17
0 11 0 1
0 18 1 0
0 25 1 0
1
end_operator
begin_operator
jump-new-move pos-2-5 pos-2-4 pos-2-3
0
4
0 0 0 3
0 10 0 1
0 11 0 1
0 12 1 0
1
end_operator
begin_operator
jump-new-move pos-2-5 pos-3-5 pos-4-5
0
4
0 0 0 5
0 12 1 0
0 19 1 0
0 26 0 1
1
end_operator
begin_operator
jump-new-move pos-2-6 pos-2-5 pos-2-4
0
4
0 0 0 22
0 11 1 0
0 12 1 0
0 13 1 0
1
end_operator
begin_operator
jump-new-move pos-2-6 pos-3-6 pos-4-6
0
4
0 0 0 20
0 13 1 0
0 20 1 0
0 27 0 1
1
end_operator
begin_operator
jump-new-move pos-3-0 pos-3-1 pos-3-2
0
4
0 0 0 10
0 14 1 0
0 15 1 0
0 16 1 0
1
end_operator
begin_operator
jump-new-move pos-3-1 pos-3-2 pos-3-3
0
4
0 0 0 7
0 15 1 0
0 16 0 1
0 17 1 0
1
end_operator
begin_operator
jump-new-move pos-3-2 pos-2-2 pos-1-2
0
4
0 0 0 27
0 4 0 1
0 9 1 0
0 16 0 1
1
end_operator
begin_operator
jump-new-move pos-3-2 pos-3-1 pos-3-0
0
4
0 0 0 8
0 14 0 1
0 15 1 0
0 16 0 1
1
end_operator
begin_operator
jump-new-move pos-3-2 pos-3-3 pos-3-4
0
4
0 0 0 2
0 16 0 1
0 17 0 1
0 18 0 1
1
end_operator
begin_operator
jump-new-move pos-3-2 pos-4-2 pos-5-2
0
4
0 0 0 18
0 16 0 1
0 23 1 0
0 28 0 1
1
end_operator
begin_operator
jump-new-move pos-3-3 pos-2-3 pos-1-3
0
4
0 0 0 16
0 5 0 1
0 10 1 0
0 17 0 1
1
end_operator
begin_operator
jump-new-move pos-3-3 pos-3-2 pos-3-1
0
4
0 0 0 1
0 15 0 1
0 16 0 1
0 17 0 1
1
end_operator
begin_operator
jump-new-move pos-3-3 pos-3-4 pos-3-5
0
4
0 0 0 12
0 17 0 1
0 18 1 0
0 19 0 1
1
end_operator
begin_operator
jump-new-move pos-3-3 pos-4-3 pos-5-3
0
4
0 0 0 21
0 17 0 1
0 24 0 1
0 29 1 0
1
end_operator
begin_operator
jump-new-move pos-3-4 pos-2-4 pos-1-4
0
4
0 0 0 9
0 6 0 1
0 11 0 1
0 18 1 0
1
end_operator
begin_operator
jump-new-move pos-3-4 pos-3-3 pos-3-2
0
4
0 0 0 10
0 16 1 0
0 17 0 1
0 18 1 0
1
end_operator
begin_operator
jump-new-move pos-3-4 pos-3-5 pos-3-6
0
4
0 0 0 25
0 18 1 0
0 19 1 0
0 20 0 1
1
end_operator
begin_operator
jump-new-move pos-3-4 pos-4-4 pos-5-4
0
4
0 0 0 11
0 18 1 0
0 25 0 1
0 30 0 1
1
end_operator
begin_operator
jump-new-move pos-3-5 pos-3-4 pos-3-3
0
4
0 0 0 7
0 17 1 0
0 18 1 0
0 19 1 0
1
end_operator
begin_operator
jump-new-move pos-3-6 pos-3-5 pos-3-4
0
4
0 0 0 2
0 18 0 1
0 19 1 0
0 20 1 0
1
end_operator
begin_operator
jump-new-move pos-4-0 pos-3-0 pos-2-0
0
4
0 0 0 33
0 7 0 1
0 14 1 0
0 21 1 0
1
end_operator
begin_operator
jump-new-move pos-4-0 pos-4-1 pos-4-2
0
4
0 0 0 4
0 21 1 0
0 22 1 0
0 23 0 1
1
end_operator
begin_operator
jump-new-move pos-4-1 pos-3-1 pos-2-1
0
4
0 0 0 28
0 8 0 1
0 15 1 0
0 22 1 0
1
end_operator
begin_operator
jump-new-move pos-4-1 pos-4-2 pos-4-3
0
4
0 0 0 14
0 22 1 0
0 23 1 0
0 24 1 0
1
end_operator
begin_operator
jump-new-move pos-4-2 pos-3-2 pos-2-2
0
4
0 0 0 15
0 9 0 1
0 16 0 1
0 23 1 0
1
end_operator
begin_operator
jump-new-move pos-4-2 pos-4-1 pos-4-0
0
4
0 0 0 31
0 21 0 1
0 22 1 0
0 23 1 0
1
end_operator
begin_operator
jump-new-move pos-4-2 pos-4-3 pos-4-4
0
4
0 0 0 17
0 23 1 0
0 24 0 1
0 25 1 0
1
end_operator
begin_operator
jump-new-move pos-4-2 pos-5-2 pos-6-2
0
4
0 0 0 30
0 23 1 0
0 28 1 0
0 31 0 1
1
end_operator
begin_operator
jump-new-move pos-4-3 pos-3-3 pos-2-3
0
4
0 0 0 3
0 10 0 1
0 17 0 1
0 24 0 1
1
end_operator
begin_operator
jump-new-move pos-4-3 pos-4-2 pos-4-1
0
4
0 0 0 19
0 22 0 1
0 23 1 0
0 24 0 1
1
end_operator
begin_operator
jump-new-move pos-4-3 pos-4-4 pos-4-5
0
4
0 0 0 5
0 24 0 1
0 25 0 1
0 26 0 1
1
end_operator
begin_operator
jump-new-move pos-4-3 pos-5-3 pos-6-3
0
4
0 0 0 6
0 24 0 1
0 29 0 1
0 32 0 1
1
end_operator
begin_operator
jump-new-move pos-4-4 pos-3-4 pos-2-4
0
4
0 0 0 22
0 11 1 0
0 18 1 0
0 25 0 1
1
end_operator
begin_operator
jump-new-move pos-4-4 pos-4-3 pos-4-2
0
4
0 0 0 4
0 23 0 1
0 24 0 1
0 25 0 1
1
end_operator
begin_operator
jump-new-move pos-4-4 pos-4-5 pos-4-6
0
4
0 0 0 20
0 25 0 1
0 26 1 0
0 27 0 1
1
end_operator
begin_operator
jump-new-move pos-4-4 pos-5-4 pos-6-4
0
4
0 0 0 24
0 25 0 1
0 30 1 0
0 33 0 1
1
end_operator
begin_operator
jump-new-move pos-4-5 pos-3-5 pos-2-5
0
4
0 0 0 13
0 12 0 1
0 19 1 0
0 26 1 0
1
end_operator
begin_operator
jump-new-move pos-4-5 pos-4-4 pos-4-3
0
4
0 0 0 14
0 24 1 0
0 25 0 1
0 26 1 0
1
end_operator
begin_operator
jump-new-move pos-4-6 pos-3-6 pos-2-6
0
4
0 0 0 26
0 13 0 1
0 20 1 0
0 27 1 0
1
end_operator
begin_operator
jump-new-move pos-4-6 pos-4-5 pos-4-4
0
4
0 0 0 17
0 25 1 0
0 26 1 0
0 27 1 0
1
end_operator
begin_operator
jump-new-move pos-5-2 pos-4-2 pos-3-2
0
4
0 0 0 10
0 16 1 0
0 23 1 0
0 28 1 0
1
end_operator
begin_operator
jump-new-move pos-5-2 pos-5-3 pos-5-4
0
4
0 0 0 11
0 28 1 0
0 29 0 1
0 30 0 1
1
end_operator
begin_operator
jump-new-move pos-5-3 pos-4-3 pos-3-3
0
4
0 0 0 7
0 17 1 0
0 24 0 1
0 29 0 1
1
end_operator
begin_operator
jump-new-move pos-5-4 pos-4-4 pos-3-4
0
4
0 0 0 2
0 18 0 1
0 25 0 1
0 30 1 0
1
end_operator
begin_operator
jump-new-move pos-5-4 pos-5-3 pos-5-2
0
4
0 0 0 18
0 28 0 1
0 29 0 1
0 30 1 0
1
end_operator
begin_operator
jump-new-move pos-6-2 pos-5-2 pos-4-2
0
4
0 0 0 4
0 23 0 1
0 28 1 0
0 31 1 0
1
end_operator
begin_operator
jump-new-move pos-6-2 pos-6-3 pos-6-4
0
4
0 0 0 24
0 31 1 0
0 32 1 0
0 33 0 1
1
end_operator
begin_operator
jump-new-move pos-6-3 pos-5-3 pos-4-3
0
4
0 0 0 14
0 24 1 0
0 29 0 1
0 32 1 0
1
end_operator
begin_operator
jump-new-move pos-6-4 pos-5-4 pos-4-4
0
4
0 0 0 17
0 25 1 0
0 30 1 0
0 33 1 0
1
end_operator
begin_operator
jump-new-move pos-6-4 pos-6-3 pos-6-2
0
4
0 0 0 30
0 31 0 1
0 32 1 0
0 33 1 0
1
end_operator
begin_operator
jump-continue-move pos-0-2 pos-0-3 pos-0-4
0
4
0 0 32 23
0 1 1 0
0 2 1 0
0 3 0 1
0
end_operator
begin_operator
jump-continue-move pos-0-2 pos-1-2 pos-2-2
0
4
0 0 32 15
0 1 1 0
0 4 1 0
0 9 0 1
0
end_operator
begin_operator
jump-continue-move pos-0-3 pos-1-3 pos-2-3
0
4
0 0 29 3
0 2 1 0
0 5 1 0
0 10 0 1
0
end_operator
begin_operator
jump-continue-move pos-0-4 pos-0-3 pos-0-2
0
4
0 0 23 32
0 1 0 1
0 2 1 0
0 3 1 0
0
end_operator
begin_operator
jump-continue-move pos-0-4 pos-1-4 pos-2-4
0
4
0 0 23 22
0 3 1 0
0 6 1 0
0 11 1 0
0
end_operator
begin_operator
jump-continue-move pos-1-2 pos-1-3 pos-1-4
0
4
0 0 27 9
0 4 1 0
0 5 1 0
0 6 0 1
0
end_operator
begin_operator
jump-continue-move pos-1-2 pos-2-2 pos-3-2
0
4
0 0 27 10
0 4 1 0
0 9 1 0
0 16 1 0
0
end_operator
begin_operator
jump-continue-move pos-1-3 pos-2-3 pos-3-3
0
4
0 0 16 7
0 5 1 0
0 10 1 0
0 17 1 0
0
end_operator
begin_operator
jump-continue-move pos-1-4 pos-1-3 pos-1-2
0
4
0 0 9 27
0 4 0 1
0 5 1 0
0 6 1 0
0
end_operator
begin_operator
jump-continue-move pos-1-4 pos-2-4 pos-3-4
0
4
0 0 9 2
0 6 1 0
0 11 0 1
0 18 0 1
0
end_operator
begin_operator
jump-continue-move pos-2-0 pos-2-1 pos-2-2
0
4
0 0 33 15
0 7 1 0
0 8 1 0
0 9 0 1
0
end_operator
begin_operator
jump-continue-move pos-2-0 pos-3-0 pos-4-0
0
4
0 0 33 31
0 7 1 0
0 14 1 0
0 21 0 1
0
end_operator
begin_operator
jump-continue-move pos-2-1 pos-2-2 pos-2-3
0
4
0 0 28 3
0 8 1 0
0 9 1 0
0 10 0 1
0
end_operator
begin_operator
jump-continue-move pos-2-1 pos-3-1 pos-4-1
0
4
0 0 28 19
0 8 1 0
0 15 1 0
0 22 0 1
0
end_operator
begin_operator
jump-continue-move pos-2-2 pos-1-2 pos-0-2
0
4
0 0 15 32
0 1 0 1
0 4 1 0
0 9 1 0
0
end_operator
begin_operator
jump-continue-move pos-2-2 pos-2-1 pos-2-0
0
4
0 0 15 33
0 7 0 1
0 8 1 0
0 9 1 0
0
end_operator
begin_operator
jump-continue-move pos-2-2 pos-2-3 pos-2-4
0
4
0 0 15 22
0 9 1 0
0 10 1 0
0 11 1 0
0
end_operator
begin_operator
jump-continue-move pos-2-2 pos-3-2 pos-4-2
0
4
0 0 15 4
0 9 1 0
0 16 0 1
0 23 0 1
0
end_operator
begin_operator
jump-continue-move pos-2-3 pos-1-3 pos-0-3
0
4
0 0 3 29
0 2 0 1
0 5 1 0
0 10 1 0
0
end_operator
begin_operator
jump-continue-move pos-2-3 pos-2-2 pos-2-1
0
4
0 0 3 28
0 8 0 1
0 9 1 0
0 10 1 0
0
end_operator
begin_operator
jump-continue-move pos-2-3 pos-2-4 pos-2-5
0
4
0 0 3 13
0 10 1 0
0 11 0 1
0 12 0 1
0
end_operator
begin_operator
jump-continue-move pos-2-3 pos-3-3 pos-4-3
0
4
0 0 3 14
0 10 1 0
0 17 0 1
0 24 1 0
0
end_operator
begin_operator
jump-continue-move pos-2-4 pos-1-4 pos-0-4
0
4
0 0 22 23
0 3 0 1
0 6 1 0
0 11 0 1
0
end_operator
begin_operator
jump-continue-move pos-2-4 pos-2-3 pos-2-2
0
4
0 0 22 15
0 9 0 1
0 10 1 0
0 11 0 1
0
end_operator
begin_operator
jump-continue-move pos-2-4 pos-2-5 pos-2-6
0
4
0 0 22 26
0 11 0 1
0 12 1 0
0 13 0 1
0
end_operator
begin_operator
jump-continue-move pos-2-4 pos-3-4 pos-4-4
0
4
0 0 22 17
0 11 0 1
0 18 1 0
0 25 1 0
0
end_operator
begin_operator
jump-continue-move pos-2-5 pos-2-4 pos-2-3
0
4
0 0 13 3
0 10 0 1
0 11 0 1
0 12 1 0
0
end_operator
begin_operator
jump-continue-move pos-2-5 pos-3-5 pos-4-5
0
4
0 0 13 5
0 12 1 0
0 19 1 0
0 26 0 1
0
end_operator
begin_operator
jump-continue-move pos-2-6 pos-2-5 pos-2-4
0
4
0 0 26 22
0 11 1 0
0 12 1 0
0 13 1 0
0
end_operator
begin_operator
jump-continue-move pos-2-6 pos-3-6 pos-4-6
0
4
0 0 26 20
0 13 1 0
0 20 1 0
0 27 0 1
0
end_operator
begin_operator
jump-continue-move pos-3-0 pos-3-1 pos-3-2
0
4
0 0 8 10
0 14 1 0
0 15 1 0
0 16 1 0
0
end_operator
begin_operator
jump-continue-move pos-3-1 pos-3-2 pos-3-3
0
4
0 0 1 7
0 15 1 0
0 16 0 1
0 17 1 0
0
end_operator
begin_operator
jump-continue-move pos-3-2 pos-2-2 pos-1-2
0
4
0 0 10 27
0 4 0 1
0 9 1 0
0 16 0 1
0
end_operator
begin_operator
jump-continue-move pos-3-2 pos-3-1 pos-3-0
0
4
0 0 10 8
0 14 0 1
0 15 1 0
0 16 0 1
0
end_operator
begin_operator
jump-continue-move pos-3-2 pos-3-3 pos-3-4
0
4
0 0 10 2
0 16 0 1
0 17 0 1
0 18 0 1
0
end_operator
begin_operator
jump-continue-move pos-3-2 pos-4-2 pos-5-2
0
4
0 0 10 18
0 16 0 1
0 23 1 0
0 28 0 1
0
end_operator
begin_operator
jump-continue-move pos-3-3 pos-2-3 pos-1-3
0
4
0 0 7 16
0 5 0 1
0 10 1 0
0 17 0 1
0
end_operator
begin_operator
jump-continue-move pos-3-3 pos-3-2 pos-3-1
0
4
0 0 7 1
0 15 0 1
0 16 0 1
0 17 0 1
0
end_operator
begin_operator
jump-continue-move pos-3-3 pos-3-4 pos-3-5
0
4
0 0 7 12
0 17 0 1
0 18 1 0
0 19 0 1
0
end_operator
begin_operator
jump-continue-move pos-3-3 pos-4-3 pos-5-3
0
4
0 0 7 21
0 17 0 1
0 24 0 1
0 29 1 0
0
end_operator
begin_operator
jump-continue-move pos-3-4 pos-2-4 pos-1-4
0
4
0 0 2 9
0 6 0 1
0 11 0 1
0 18 1 0
0
end_operator
begin_operator
jump-continue-move pos-3-4 pos-3-3 pos-3-2
0
4
0 0 2 10
0 16 1 0
0 17 0 1
0 18 1 0
0
end_operator
begin_operator
jump-continue-move pos-3-4 pos-3-5 pos-3-6
0
4
0 0 2 25
0 18 1 0
0 19 1 0
0 20 0 1
0
end_operator
begin_operator
jump-continue-move pos-3-4 pos-4-4 pos-5-4
0
4
0 0 2 11
0 18 1 0
0 25 0 1
0 30 0 1
0
end_operator
begin_operator
jump-continue-move pos-3-5 pos-3-4 pos-3-3
0
4
0 0 12 7
0 17 1 0
0 18 1 0
0 19 1 0
0
end_operator
begin_operator
jump-continue-move pos-3-6 pos-3-5 pos-3-4
0
4
0 0 25 2
0 18 0 1
0 19 1 0
0 20 1 0
0
end_operator
begin_operator
jump-continue-move pos-4-0 pos-3-0 pos-2-0
0
4
0 0 31 33
0 7 0 1
0 14 1 0
0 21 1 0
0
end_operator
begin_operator
jump-continue-move pos-4-0 pos-4-1 pos-4-2
0
4
0 0 31 4
0 21 1 0
0 22 1 0
0 23 0 1
0
end_operator
begin_operator
jump-continue-move pos-4-1 pos-3-1 pos-2-1
0
4
0 0 19 28
0 8 0 1
0 15 1 0
0 22 1 0
0
end_operator
begin_operator
jump-continue-move pos-4-1 pos-4-2 pos-4-3
0
4
0 0 19 14
0 22 1 0
0 23 1 0
0 24 1 0
0
end_operator
begin_operator
jump-continue-move pos-4-2 pos-3-2 pos-2-2
0
4
0 0 4 15
0 9 0 1
0 16 0 1
0 23 1 0
0
end_operator
begin_operator
jump-continue-move pos-4-2 pos-4-1 pos-4-0
0
4
0 0 4 31
0 21 0 1
0 22 1 0
0 23 1 0
0
end_operator
begin_operator
jump-continue-move pos-4-2 pos-4-3 pos-4-4
0
4
0 0 4 17
0 23 1 0
0 24 0 1
0 25 1 0
0
end_operator
begin_operator
jump-continue-move pos-4-2 pos-5-2 pos-6-2
0
4
0 0 4 30
0 23 1 0
0 28 1 0
0 31 0 1
0
end_operator
begin_operator
jump-continue-move pos-4-3 pos-3-3 pos-2-3
0
4
0 0 14 3
0 10 0 1
0 17 0 1
0 24 0 1
0
end_operator
begin_operator
jump-continue-move pos-4-3 pos-4-2 pos-4-1
0
4
0 0 14 19
0 22 0 1
0 23 1 0
0 24 0 1
0
end_operator
begin_operator
jump-continue-move pos-4-3 pos-4-4 pos-4-5
0
4
0 0 14 5
0 24 0 1
0 25 0 1
0 26 0 1
0
end_operator
begin_operator
jump-continue-move pos-4-3 pos-5-3 pos-6-3
0
4
0 0 14 6
0 24 0 1
0 29 0 1
0 32 0 1
0
end_operator
begin_operator
jump-continue-move pos-4-4 pos-3-4 pos-2-4
0
4
0 0 17 22
0 11 1 0
0 18 1 0
0 25 0 1
0
end_operator
begin_operator
jump-continue-move pos-4-4 pos-4-3 pos-4-2
0
4
0 0 17 4
0 23 0 1
0 24 0 1
0 25 0 1
0
end_operator
begin_operator
jump-continue-move pos-4-4 pos-4-5 pos-4-6
0
4
0 0 17 20
0 25 0 1
0 26 1 0
0 27 0 1
0
end_operator
begin_operator
jump-continue-move pos-4-4 pos-5-4 pos-6-4
0
4
0 0 17 24
0 25 0 1
0 30 1 0
0 33 0 1
0
end_operator
begin_operator
jump-continue-move pos-4-5 pos-3-5 pos-2-5
0
4
0 0 5 13
0 12 0 1
0 19 1 0
0 26 1 0
0
end_operator
begin_operator
jump-continue-move pos-4-5 pos-4-4 pos-4-3
0
4
0 0 5 14
0 24 1 0
0 25 0 1
0 26 1 0
0
end_operator
begin_operator
jump-continue-move pos-4-6 pos-3-6 pos-2-6
0
4
0 0 20 26
0 13 0 1
0 20 1 0
0 27 1 0
0
end_operator
begin_operator
jump-continue-move pos-4-6 pos-4-5 pos-4-4
0
4
0 0 20 17
0 25 1 0
0 26 1 0
0 27 1 0
0
end_operator
begin_operator
jump-continue-move pos-5-2 pos-4-2 pos-3-2
0
4
0 0 18 10
0 16 1 0
0 23 1 0
0 28 1 0
0
end_operator
begin_operator
jump-continue-move pos-5-2 pos-5-3 pos-5-4
0
4
0 0 18 11
0 28 1 0
0 29 0 1
0 30 0 1
0
end_operator
begin_operator
jump-continue-move pos-5-3 pos-4-3 pos-3-3
0
4
0 0 21 7
0 17 1 0
0 24 0 1
0 29 0 1
0
end_operator
begin_operator
jump-continue-move pos-5-4 pos-4-4 pos-3-4
0
4
0 0 11 2
0 18 0 1
0 25 0 1
0 30 1 0
0
end_operator
begin_operator
jump-continue-move pos-5-4 pos-5-3 pos-5-2
0
4
0 0 11 18
0 28 0 1
0 29 0 1
0 30 1 0
0
end_operator
begin_operator
jump-continue-move pos-6-2 pos-5-2 pos-4-2
0
4
0 0 30 4
0 23 0 1
0 28 1 0
0 31 1 0
0
end_operator
begin_operator
jump-continue-move pos-6-2 pos-6-3 pos-6-4
0
4
0 0 30 24
0 31 1 0
0 32 1 0
0 33 0 1
0
end_operator
begin_operator
jump-continue-move pos-6-3 pos-5-3 pos-4-3
0
4
0 0 6 14
0 24 1 0
0 29 0 1
0 32 1 0
0
end_operator
begin_operator
jump-continue-move pos-6-4 pos-5-4 pos-4-4
0
4
0 0 24 17
0 25 1 0
0 30 1 0
0 33 1 0
0
end_operator
begin_operator
jump-continue-move pos-6-4 pos-6-3 pos-6-2
0
4
0 0 24 30
0 31 0 1
0 32 1 0
0 33 1 0
0
end_operator
begin_operator
end-move pos-0-2
0
1
0 0 32 0
0
end_operator
begin_operator
end-move pos-0-3
0
1
0 0 29 0
0
end_operator
begin_operator
end-move pos-0-4
0
1
0 0 23 0
0
end_operator
begin_operator
end-move pos-1-2
0
1
0 0 27 0
0
end_operator
begin_operator
end-move pos-1-3
0
1
0 0 16 0
0
end_operator
begin_operator
end-move pos-1-4
0
1
0 0 9 0
0
end_operator
begin_operator
end-move pos-2-0
0
1
0 0 33 0
0
end_operator
begin_operator
end-move pos-2-1
0
1
0 0 28 0
0
end_operator
begin_operator
end-move pos-2-2
0
1
0 0 15 0
0
end_operator
begin_operator
end-move pos-2-3
0
1
0 0 3 0
0
end_operator
begin_operator
end-move pos-2-4
0
1
0 0 22 0
0
end_operator
begin_operator
end-move pos-2-5
0
1
0 0 13 0
0
end_operator
begin_operator
end-move pos-2-6
0
1
0 0 26 0
0
end_operator
begin_operator
end-move pos-3-0
0
1
0 0 8 0
0
end_operator
begin_operator
end-move pos-3-1
0
1
0 0 1 0
0
end_operator
begin_operator
end-move pos-3-2
0
1
0 0 10 0
0
end_operator
begin_operator
end-move pos-3-3
0
1
0 0 7 0
0
end_operator
begin_operator
end-move pos-3-4
0
1
0 0 2 0
0
end_operator
begin_operator
end-move pos-3-5
0
1
0 0 12 0
0
end_operator
begin_operator
end-move pos-3-6
0
1
0 0 25 0
0
end_operator
begin_operator
end-move pos-4-0
0
1
0 0 31 0
0
end_operator
begin_operator
end-move pos-4-1
0
1
0 0 19 0
0
end_operator
begin_operator
end-move pos-4-2
0
1
0 0 4 0
0
end_operator
begin_operator
end-move pos-4-3
0
1
0 0 14 0
0
end_operator
begin_operator
end-move pos-4-4
0
1
0 0 17 0
0
end_operator
begin_operator
end-move pos-4-5
0
1
0 0 5 0
0
end_operator
begin_operator
end-move pos-4-6
0
1
0 0 20 0
0
end_operator
begin_operator
end-move pos-5-2
0
1
0 0 18 0
0
end_operator
begin_operator
end-move pos-5-3
0
1
0 0 21 0
0
end_operator
begin_operator
end-move pos-5-4
0
1
0 0 11 0
0
end_operator
begin_operator
end-move pos-6-2
0
1
0 0 30 0
0
end_operator
begin_operator
end-move pos-6-3
0
1
0 0 6 0
0
end_operator
begin_operator
end-move pos-6-4
0
1
0 0 24 0
0
end_operator
0
