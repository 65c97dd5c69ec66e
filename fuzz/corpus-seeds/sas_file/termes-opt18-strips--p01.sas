begin_version
3
end_version
begin_metric
0
end_metric
13
begin_variable
var0
-1
12
Atom at(pos-2-0)
Atom at(pos-1-0)
Atom at(pos-3-0)
Atom at(pos-2-1)
Atom at(pos-0-0)
Atom at(pos-1-1)
Atom at(pos-3-1)
Atom at(pos-2-2)
Atom at(pos-0-1)
Atom at(pos-1-2)
Atom at(pos-3-2)
Atom at(pos-0-2)
end_variable
begin_variable
var1
-1
4
Atom height(pos-0-0, n0)
Atom height(pos-0-0, n1)
Atom height(pos-0-0, n2)
Atom height(pos-0-0, n3)
end_variable
begin_variable
var2
-1
4
Atom height(pos-0-1, n0)
Atom height(pos-0-1, n1)
Atom height(pos-0-1, n2)
Atom height(pos-0-1, n3)
end_variable
begin_variable
var3
-1
4
Atom height(pos-0-2, n0)
Atom height(pos-0-2, n1)
Atom height(pos-0-2, n2)
Atom height(pos-0-2, n3)
end_variable
begin_variable
var4
-1
4
Atom height(pos-1-0, n0)
Atom height(pos-1-0, n1)
Atom height(pos-1-0, n2)
Atom height(pos-1-0, n3)
end_variable
begin_variable
var5
-1
4
Atom height(pos-1-1, n0)
Atom height(pos-1-1, n1)
Atom height(pos-1-1, n2)
Atom height(pos-1-1, n3)
end_variable
begin_variable
var6
-1
4
Atom height(pos-1-2, n0)
Atom height(pos-1-2, n1)
Atom height(pos-1-2, n2)
Atom height(pos-1-2, n3)
end_variable
begin_variable
var7
-1
4
Atom height(pos-2-1, n0)
Atom height(pos-2-1, n1)
Atom height(pos-2-1, n2)
Atom height(pos-2-1, n3)
end_variable
begin_variable
var8
-1
4
Atom height(pos-2-2, n0)
Atom height(pos-2-2, n1)
Atom height(pos-2-2, n2)
Atom height(pos-2-2, n3)
end_variable
begin_variable
var9
-1
4
Atom height(pos-3-0, n0)
Atom height(pos-3-0, n1)
Atom height(pos-3-0, n2)
Atom height(pos-3-0, n3)
end_variable
begin_variable
var10
-1
4
Atom height(pos-3-1, n0)
Atom height(pos-3-1, n1)
Atom height(pos-3-1, n2)
Atom height(pos-3-1, n3)
end_variable
begin_variable
var11
-1
4
Atom height(pos-3-2, n0)
Atom height(pos-3-2, n1)
Atom height(pos-3-2, n2)
Atom height(pos-3-2, n3)
end_variable
begin_variable
var12
-1
2
Atom has-block()
NegatedAtom has-block()
end_variable
12
begin_mutex_group
4
1 0
1 1
1 2
1 3
end_mutex_group
begin_mutex_group
4
2 0
2 1
2 2
2 3
end_mutex_group
begin_mutex_group
4
3 0
3 1
3 2
3 3
end_mutex_group
begin_mutex_group
4
4 0
4 1
4 2
4 3
end_mutex_group
begin_mutex_group
4
5 0
5 1
5 2
5 3
end_mutex_group
begin_mutex_group
4
6 0
6 1
6 2
6 3
end_mutex_group
begin_mutex_group
4
7 0
7 1
7 2
7 3
end_mutex_group
begin_mutex_group
4
8 0
8 1
8 2
8 3
end_mutex_group
begin_mutex_group
4
9 0
9 1
9 2
9 3
end_mutex_group
begin_mutex_group
4
10 0
10 1
10 2
10 3
end_mutex_group
begin_mutex_group
4
11 0
11 1
11 2
11 3
end_mutex_group
begin_mutex_group
12
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
1
end_state
begin_goal
12
1 0
2 0
3 0
4 0
5 0
6 3
7 0
8 0
9 0
10 0
11 0
12 1
end_goal
468
begin_operator
move pos-0-0 pos-0-1 n0
2
1 0
2 0
1
0 0 4 8
0
end_operator
begin_operator
move pos-0-0 pos-0-1 n1
2
1 1
2 1
1
0 0 4 8
0
end_operator
begin_operator
move pos-0-0 pos-0-1 n2
2
1 2
2 2
1
0 0 4 8
0
end_operator
begin_operator
move pos-0-0 pos-0-1 n3
2
1 3
2 3
1
0 0 4 8
0
end_operator
begin_operator
move pos-0-0 pos-1-0 n0
2
1 0
4 0
1
0 0 4 1
0
end_operator
begin_operator
move pos-0-0 pos-1-0 n1
2
1 1
4 1
1
0 0 4 1
0
end_operator
begin_operator
move pos-0-0 pos-1-0 n2
2
1 2
4 2
1
0 0 4 1
0
end_operator
begin_operator
move pos-0-0 pos-1-0 n3
2
1 3
4 3
1
0 0 4 1
0
end_operator
begin_operator
move pos-0-1 pos-0-0 n0
2
1 0
2 0
1
0 0 8 4
0
end_operator
begin_operator
move pos-0-1 pos-0-0 n1
2
1 1
2 1
1
0 0 8 4
0
end_operator
begin_operator
move pos-0-1 pos-0-0 n2
2
1 2
2 2
1
0 0 8 4
0
end_operator
begin_operator
move pos-0-1 pos-0-0 n3
2
1 3
2 3
1
0 0 8 4
0
end_operator
begin_operator
move pos-0-1 pos-0-2 n0
2
2 0
3 0
1
0 0 8 11
0
end_operator
begin_operator
move pos-0-1 pos-0-2 n1
2
2 1
3 1
1
0 0 8 11
0
end_operator
begin_operator
move pos-0-1 pos-0-2 n2
2
2 2
3 2
1
0 0 8 11
0
end_operator
begin_operator
move pos-0-1 pos-0-2 n3
2
2 3
3 3
1
0 0 8 11
0
end_operator
begin_operator
move pos-0-1 pos-1-1 n0
2
2 0
5 0
1
0 0 8 5
0
end_operator
begin_operator
move pos-0-1 pos-1-1 n1
2
2 1
5 1
1
0 0 8 5
0
end_operator
begin_operator
move pos-0-1 pos-1-1 n2
2
2 2
5 2
1
0 0 8 5
0
end_operator
begin_operator
move pos-0-1 pos-1-1 n3
2
2 3
5 3
1
0 0 8 5
0
end_operator
begin_operator
move pos-0-2 pos-0-1 n0
2
2 0
3 0
1
0 0 11 8
0
end_operator
begin_operator
move pos-0-2 pos-0-1 n1
2
2 1
3 1
1
0 0 11 8
0
end_operator
begin_operator
move pos-0-2 pos-0-1 n2
2
2 2
3 2
1
0 0 11 8
0
end_operator
begin_operator
move pos-0-2 pos-0-1 n3
2
2 3
3 3
1
0 0 11 8
0
end_operator
begin_operator
move pos-0-2 pos-1-2 n0
2
3 0
6 0
1
0 0 11 9
0
end_operator
begin_operator
move pos-0-2 pos-1-2 n1
2
3 1
6 1
1
0 0 11 9
0
end_operator
begin_operator
move pos-0-2 pos-1-2 n2
2
3 2
6 2
1
0 0 11 9
0
end_operator
begin_operator
move pos-0-2 pos-1-2 n3
2
3 3
6 3
1
0 0 11 9
0
end_operator
begin_operator
move pos-1-0 pos-0-0 n0
2
1 0
4 0
1
0 0 1 4
0
end_operator
begin_operator
move pos-1-0 pos-0-0 n1
2
1 1
4 1
1
0 0 1 4
0
end_operator
begin_operator
move pos-1-0 pos-0-0 n2
2
1 2
4 2
1
0 0 1 4
0
end_operator
begin_operator
move pos-1-0 pos-0-0 n3
2
1 3
4 3
1
0 0 1 4
0
end_operator
begin_operator
move pos-1-0 pos-1-1 n0
2
4 0
5 0
1
0 0 1 5
0
end_operator
begin_operator
move pos-1-0 pos-1-1 n1
2
4 1
5 1
1
0 0 1 5
0
end_operator
begin_operator
move pos-1-0 pos-1-1 n2
2
4 2
5 2
1
0 0 1 5
0
end_operator
begin_operator
move pos-1-0 pos-1-1 n3
2
4 3
5 3
1
0 0 1 5
0
end_operator
begin_operator
move pos-1-0 pos-2-0 n0
1
4 0
1
0 0 1 0
0
end_operator
begin_operator
move pos-1-1 pos-0-1 n0
2
2 0
5 0
1
0 0 5 8
0
end_operator
begin_operator
move pos-1-1 pos-0-1 n1
2
2 1
5 1
1
0 0 5 8
0
end_operator
begin_operator
move pos-1-1 pos-0-1 n2
2
2 2
5 2
1
0 0 5 8
0
end_operator
begin_operator
move pos-1-1 pos-0-1 n3
2
2 3
5 3
1
0 0 5 8
0
end_operator
begin_operator
move pos-1-1 pos-1-0 n0
2
4 0
5 0
1
0 0 5 1
0
end_operator
begin_operator
move pos-1-1 pos-1-0 n1
2
4 1
5 1
1
0 0 5 1
0
end_operator
begin_operator
move pos-1-1 pos-1-0 n2
2
4 2
5 2
1
0 0 5 1
0
end_operator
begin_operator
move pos-1-1 pos-1-0 n3
2
4 3
5 3
1
0 0 5 1
0
end_operator
begin_operator
move pos-1-1 pos-1-2 n0
2
5 0
6 0
1
0 0 5 9
0
end_operator
begin_operator
move pos-1-1 pos-1-2 n1
2
5 1
6 1
1
0 0 5 9
0
end_operator
begin_operator
move pos-1-1 pos-1-2 n2
2
5 2
6 2
1
0 0 5 9
0
end_operator
begin_operator
move pos-1-1 pos-1-2 n3
2
5 3
6 3
1
0 0 5 9
0
end_operator
begin_operator
move pos-1-1 pos-2-1 n0
2
5 0
7 0
1
0 0 5 3
0
end_operator
begin_operator
move pos-1-1 pos-2-1 n1
2
5 1
7 1
1
0 0 5 3
0
end_operator
begin_operator
move pos-1-1 pos-2-1 n2
2
5 2
7 2
1
0 0 5 3
0
end_operator
begin_operator
move pos-1-1 pos-2-1 n3
2
5 3
7 3
1
0 0 5 3
0
end_operator
begin_operator
move pos-1-2 pos-0-2 n0
2
3 0
6 0
1
0 0 9 11
0
end_operator
begin_operator
move pos-1-2 pos-0-2 n1
2
3 1
6 1
1
0 0 9 11
0
end_operator
begin_operator
move pos-1-2 pos-0-2 n2
2
3 2
6 2
1
0 0 9 11
0
end_operator
begin_operator
move pos-1-2 pos-0-2 n3
2
3 3
6 3
1
0 0 9 11
0
end_operator
begin_operator
move pos-1-2 pos-1-1 n0
2
5 0
6 0
1
0 0 9 5
0
end_operator
begin_operator
move pos-1-2 pos-1-1 n1
2
5 1
6 1
1
0 0 9 5
0
end_operator
begin_operator
move pos-1-2 pos-1-1 n2
2
5 2
6 2
1
0 0 9 5
0
end_operator
begin_operator
move pos-1-2 pos-1-1 n3
2
5 3
6 3
1
0 0 9 5
0
end_operator
begin_operator
move pos-1-2 pos-2-2 n0
2
6 0
8 0
1
0 0 9 7
0
end_operator
begin_operator
move pos-1-2 pos-2-2 n1
2
6 1
8 1
1
0 0 9 7
0
end_operator
begin_operator
move pos-1-2 pos-2-2 n2
2
6 2
8 2
1
0 0 9 7
0
end_operator
begin_operator
move pos-1-2 pos-2-2 n3
2
6 3
8 3
1
0 0 9 7
0
end_operator
begin_operator
move pos-2-0 pos-1-0 n0
1
4 0
1
0 0 0 1
0
end_operator
begin_operator
move pos-2-0 pos-2-1 n0
1
7 0
1
0 0 0 3
0
end_operator
begin_operator
move pos-2-0 pos-3-0 n0
1
9 0
1
0 0 0 2
0
end_operator
begin_operator
move pos-2-1 pos-1-1 n0
2
5 0
7 0
1
0 0 3 5
0
end_operator
begin_operator
move pos-2-1 pos-1-1 n1
2
5 1
7 1
1
0 0 3 5
0
end_operator
begin_operator
move pos-2-1 pos-1-1 n2
2
5 2
7 2
1
0 0 3 5
0
end_operator
begin_operator
move pos-2-1 pos-1-1 n3
2
5 3
7 3
1
0 0 3 5
0
end_operator
begin_operator
move pos-2-1 pos-2-0 n0
1
7 0
1
0 0 3 0
0
end_operator
begin_operator
move pos-2-1 pos-2-2 n0
2
7 0
8 0
1
0 0 3 7
0
end_operator
begin_operator
move pos-2-1 pos-2-2 n1
2
7 1
8 1
1
0 0 3 7
0
end_operator
begin_operator
move pos-2-1 pos-2-2 n2
2
7 2
8 2
1
0 0 3 7
0
end_operator
begin_operator
move pos-2-1 pos-2-2 n3
2
7 3
8 3
1
0 0 3 7
0
end_operator
begin_operator
move pos-2-1 pos-3-1 n0
2
7 0
10 0
1
0 0 3 6
0
end_operator
begin_operator
move pos-2-1 pos-3-1 n1
2
7 1
10 1
1
0 0 3 6
0
end_operator
begin_operator
move pos-2-1 pos-3-1 n2
2
7 2
10 2
1
0 0 3 6
0
end_operator
begin_operator
move pos-2-1 pos-3-1 n3
2
7 3
10 3
1
0 0 3 6
0
end_operator
begin_operator
move pos-2-2 pos-1-2 n0
2
6 0
8 0
1
0 0 7 9
0
end_operator
begin_operator
move pos-2-2 pos-1-2 n1
2
6 1
8 1
1
0 0 7 9
0
end_operator
begin_operator
move pos-2-2 pos-1-2 n2
2
6 2
8 2
1
0 0 7 9
0
end_operator
begin_operator
move pos-2-2 pos-1-2 n3
2
6 3
8 3
1
0 0 7 9
0
end_operator
begin_operator
move pos-2-2 pos-2-1 n0
2
7 0
8 0
1
0 0 7 3
0
end_operator
begin_operator
move pos-2-2 pos-2-1 n1
2
7 1
8 1
1
0 0 7 3
0
end_operator
begin_operator
move pos-2-2 pos-2-1 n2
2
7 2
8 2
1
0 0 7 3
0
end_operator
begin_operator
move pos-2-2 pos-2-1 n3
2
7 3
8 3
1
0 0 7 3
0
end_operator
begin_operator
move pos-2-2 pos-3-2 n0
2
8 0
11 0
1
0 0 7 10
0
end_operator
begin_operator
move pos-2-2 pos-3-2 n1
2
8 1
11 1
1
0 0 7 10
0
end_operator
begin_operator
move pos-2-2 pos-3-2 n2
2
8 2
11 2
1
0 0 7 10
0
end_operator
begin_operator
move pos-2-2 pos-3-2 n3
2
8 3
11 3
1
0 0 7 10
0
end_operator
begin_operator
move pos-3-0 pos-2-0 n0
1
9 0
1
0 0 2 0
0
end_operator
begin_operator
move pos-3-0 pos-3-1 n0
2
9 0
10 0
1
0 0 2 6
0
end_operator
begin_operator
move pos-3-0 pos-3-1 n1
2
9 1
10 1
1
0 0 2 6
0
end_operator
begin_operator
move pos-3-0 pos-3-1 n2
2
9 2
10 2
1
0 0 2 6
0
end_operator
begin_operator
move pos-3-0 pos-3-1 n3
2
9 3
10 3
1
0 0 2 6
0
end_operator
begin_operator
move pos-3-1 pos-2-1 n0
2
7 0
10 0
1
0 0 6 3
0
end_operator
begin_operator
move pos-3-1 pos-2-1 n1
2
7 1
10 1
1
0 0 6 3
0
end_operator
begin_operator
move pos-3-1 pos-2-1 n2
2
7 2
10 2
1
0 0 6 3
0
end_operator
begin_operator
move pos-3-1 pos-2-1 n3
2
7 3
10 3
1
0 0 6 3
0
end_operator
begin_operator
move pos-3-1 pos-3-0 n0
2
9 0
10 0
1
0 0 6 2
0
end_operator
begin_operator
move pos-3-1 pos-3-0 n1
2
9 1
10 1
1
0 0 6 2
0
end_operator
begin_operator
move pos-3-1 pos-3-0 n2
2
9 2
10 2
1
0 0 6 2
0
end_operator
begin_operator
move pos-3-1 pos-3-0 n3
2
9 3
10 3
1
0 0 6 2
0
end_operator
begin_operator
move pos-3-1 pos-3-2 n0
2
10 0
11 0
1
0 0 6 10
0
end_operator
begin_operator
move pos-3-1 pos-3-2 n1
2
10 1
11 1
1
0 0 6 10
0
end_operator
begin_operator
move pos-3-1 pos-3-2 n2
2
10 2
11 2
1
0 0 6 10
0
end_operator
begin_operator
move pos-3-1 pos-3-2 n3
2
10 3
11 3
1
0 0 6 10
0
end_operator
begin_operator
move pos-3-2 pos-2-2 n0
2
8 0
11 0
1
0 0 10 7
0
end_operator
begin_operator
move pos-3-2 pos-2-2 n1
2
8 1
11 1
1
0 0 10 7
0
end_operator
begin_operator
move pos-3-2 pos-2-2 n2
2
8 2
11 2
1
0 0 10 7
0
end_operator
begin_operator
move pos-3-2 pos-2-2 n3
2
8 3
11 3
1
0 0 10 7
0
end_operator
begin_operator
move pos-3-2 pos-3-1 n0
2
10 0
11 0
1
0 0 10 6
0
end_operator
begin_operator
move pos-3-2 pos-3-1 n1
2
10 1
11 1
1
0 0 10 6
0
end_operator
begin_operator
move pos-3-2 pos-3-1 n2
2
10 2
11 2
1
0 0 10 6
0
end_operator
begin_operator
move pos-3-2 pos-3-1 n3
2
10 3
11 3
1
0 0 10 6
0
end_operator
begin_operator
move-up pos-0-0 n0 pos-0-1 n1
2
1 0
2 1
1
0 0 4 8
0
end_operator
begin_operator
move-up pos-0-0 n0 pos-1-0 n1
2
1 0
4 1
1
0 0 4 1
0
end_operator
begin_operator
move-up pos-0-0 n1 pos-0-1 n2
2
1 1
2 2
1
0 0 4 8
0
end_operator
begin_operator
move-up pos-0-0 n1 pos-1-0 n2
2
1 1
4 2
1
0 0 4 1
0
end_operator
begin_operator
move-up pos-0-0 n2 pos-0-1 n3
2
1 2
2 3
1
0 0 4 8
0
end_operator
begin_operator
move-up pos-0-0 n2 pos-1-0 n3
2
1 2
4 3
1
0 0 4 1
0
end_operator
begin_operator
move-up pos-0-1 n0 pos-0-0 n1
2
1 1
2 0
1
0 0 8 4
0
end_operator
begin_operator
move-up pos-0-1 n0 pos-0-2 n1
2
2 0
3 1
1
0 0 8 11
0
end_operator
begin_operator
move-up pos-0-1 n0 pos-1-1 n1
2
2 0
5 1
1
0 0 8 5
0
end_operator
begin_operator
move-up pos-0-1 n1 pos-0-0 n2
2
1 2
2 1
1
0 0 8 4
0
end_operator
begin_operator
move-up pos-0-1 n1 pos-0-2 n2
2
2 1
3 2
1
0 0 8 11
0
end_operator
begin_operator
move-up pos-0-1 n1 pos-1-1 n2
2
2 1
5 2
1
0 0 8 5
0
end_operator
begin_operator
move-up pos-0-1 n2 pos-0-0 n3
2
1 3
2 2
1
0 0 8 4
0
end_operator
begin_operator
move-up pos-0-1 n2 pos-0-2 n3
2
2 2
3 3
1
0 0 8 11
0
end_operator
begin_operator
move-up pos-0-1 n2 pos-1-1 n3
2
2 2
5 3
1
0 0 8 5
0
end_operator
begin_operator
move-up pos-0-2 n0 pos-0-1 n1
2
2 1
3 0
1
0 0 11 8
0
end_operator
begin_operator
move-up pos-0-2 n0 pos-1-2 n1
2
3 0
6 1
1
0 0 11 9
0
end_operator
begin_operator
move-up pos-0-2 n1 pos-0-1 n2
2
2 2
3 1
1
0 0 11 8
0
end_operator
begin_operator
move-up pos-0-2 n1 pos-1-2 n2
2
3 1
6 2
1
0 0 11 9
0
end_operator
begin_operator
move-up pos-0-2 n2 pos-0-1 n3
2
2 3
3 2
1
0 0 11 8
0
end_operator
begin_operator
move-up pos-0-2 n2 pos-1-2 n3
2
3 2
6 3
1
0 0 11 9
0
end_operator
begin_operator
move-up pos-1-0 n0 pos-0-0 n1
2
1 1
4 0
1
0 0 1 4
0
end_operator
begin_operator
move-up pos-1-0 n0 pos-1-1 n1
2
4 0
5 1
1
0 0 1 5
0
end_operator
begin_operator
move-up pos-1-0 n1 pos-0-0 n2
2
1 2
4 1
1
0 0 1 4
0
end_operator
begin_operator
move-up pos-1-0 n1 pos-1-1 n2
2
4 1
5 2
1
0 0 1 5
0
end_operator
begin_operator
move-up pos-1-0 n2 pos-0-0 n3
2
1 3
4 2
1
0 0 1 4
0
end_operator
begin_operator
move-up pos-1-0 n2 pos-1-1 n3
2
4 2
5 3
1
0 0 1 5
0
end_operator
begin_operator
move-up pos-1-1 n0 pos-0-1 n1
2
2 1
5 0
1
0 0 5 8
0
end_operator
begin_operator
move-up pos-1-1 n0 pos-1-0 n1
2
4 1
5 0
1
0 0 5 1
0
end_operator
begin_operator
move-up pos-1-1 n0 pos-1-2 n1
2
5 0
6 1
1
0 0 5 9
0
end_operator
begin_operator
move-up pos-1-1 n0 pos-2-1 n1
2
5 0
7 1
1
0 0 5 3
0
end_operator
begin_operator
move-up pos-1-1 n1 pos-0-1 n2
2
2 2
5 1
1
0 0 5 8
0
end_operator
begin_operator
move-up pos-1-1 n1 pos-1-0 n2
2
4 2
5 1
1
0 0 5 1
0
end_operator
begin_operator
move-up pos-1-1 n1 pos-1-2 n2
2
5 1
6 2
1
0 0 5 9
0
end_operator
begin_operator
move-up pos-1-1 n1 pos-2-1 n2
2
5 1
7 2
1
0 0 5 3
0
end_operator
begin_operator
move-up pos-1-1 n2 pos-0-1 n3
2
2 3
5 2
1
0 0 5 8
0
end_operator
begin_operator
move-up pos-1-1 n2 pos-1-0 n3
2
4 3
5 2
1
0 0 5 1
0
end_operator
begin_operator
move-up pos-1-1 n2 pos-1-2 n3
2
5 2
6 3
1
0 0 5 9
0
end_operator
begin_operator
move-up pos-1-1 n2 pos-2-1 n3
2
5 2
7 3
1
0 0 5 3
0
end_operator
begin_operator
move-up pos-1-2 n0 pos-0-2 n1
2
3 1
6 0
1
0 0 9 11
0
end_operator
begin_operator
move-up pos-1-2 n0 pos-1-1 n1
2
5 1
6 0
1
0 0 9 5
0
end_operator
begin_operator
move-up pos-1-2 n0 pos-2-2 n1
2
6 0
8 1
1
0 0 9 7
0
end_operator
begin_operator
move-up pos-1-2 n1 pos-0-2 n2
2
3 2
6 1
1
0 0 9 11
0
end_operator
begin_operator
move-up pos-1-2 n1 pos-1-1 n2
2
5 2
6 1
1
0 0 9 5
0
end_operator
begin_operator
move-up pos-1-2 n1 pos-2-2 n2
2
6 1
8 2
1
0 0 9 7
0
end_operator
begin_operator
move-up pos-1-2 n2 pos-0-2 n3
2
3 3
6 2
1
0 0 9 11
0
end_operator
begin_operator
move-up pos-1-2 n2 pos-1-1 n3
2
5 3
6 2
1
0 0 9 5
0
end_operator
begin_operator
move-up pos-1-2 n2 pos-2-2 n3
2
6 2
8 3
1
0 0 9 7
0
end_operator
begin_operator
move-up pos-2-0 n0 pos-1-0 n1
1
4 1
1
0 0 0 1
0
end_operator
begin_operator
move-up pos-2-0 n0 pos-2-1 n1
1
7 1
1
0 0 0 3
0
end_operator
begin_operator
move-up pos-2-0 n0 pos-3-0 n1
1
9 1
1
0 0 0 2
0
end_operator
begin_operator
move-up pos-2-1 n0 pos-1-1 n1
2
5 1
7 0
1
0 0 3 5
0
end_operator
begin_operator
move-up pos-2-1 n0 pos-2-2 n1
2
7 0
8 1
1
0 0 3 7
0
end_operator
begin_operator
move-up pos-2-1 n0 pos-3-1 n1
2
7 0
10 1
1
0 0 3 6
0
end_operator
begin_operator
move-up pos-2-1 n1 pos-1-1 n2
2
5 2
7 1
1
0 0 3 5
0
end_operator
begin_operator
move-up pos-2-1 n1 pos-2-2 n2
2
7 1
8 2
1
0 0 3 7
0
end_operator
begin_operator
move-up pos-2-1 n1 pos-3-1 n2
2
7 1
10 2
1
0 0 3 6
0
end_operator
begin_operator
move-up pos-2-1 n2 pos-1-1 n3
2
5 3
7 2
1
0 0 3 5
0
end_operator
begin_operator
move-up pos-2-1 n2 pos-2-2 n3
2
7 2
8 3
1
0 0 3 7
0
end_operator
begin_operator
move-up pos-2-1 n2 pos-3-1 n3
2
7 2
10 3
1
0 0 3 6
0
end_operator
begin_operator
move-up pos-2-2 n0 pos-1-2 n1
2
6 1
8 0
1
0 0 7 9
0
end_operator
begin_operator
move-up pos-2-2 n0 pos-2-1 n1
2
7 1
8 0
1
0 0 7 3
0
end_operator
begin_operator
move-up pos-2-2 n0 pos-3-2 n1
2
8 0
11 1
1
0 0 7 10
0
end_operator
begin_operator
move-up pos-2-2 n1 pos-1-2 n2
2
6 2
8 1
1
0 0 7 9
0
end_operator
begin_operator
move-up pos-2-2 n1 pos-2-1 n2
2
7 2
8 1
1
0 0 7 3
0
end_operator
begin_operator
move-up pos-2-2 n1 pos-3-2 n2
2
8 1
11 2
1
0 0 7 10
0
end_operator
begin_operator
move-up pos-2-2 n2 pos-1-2 n3
2
6 3
8 2
1
0 0 7 9
0
end_operator
begin_operator
move-up pos-2-2 n2 pos-2-1 n3
2
7 3
8 2
1
0 0 7 3
0
end_operator
begin_operator
move-up pos-2-2 n2 pos-3-2 n3
2
8 2
11 3
1
0 0 7 10
0
end_operator
begin_operator
move-up pos-3-0 n0 pos-3-1 n1
2
9 0
10 1
1
0 0 2 6
0
end_operator
begin_operator
move-up pos-3-0 n1 pos-3-1 n2
2
9 1
10 2
1
0 0 2 6
0
end_operator
begin_operator
move-up pos-3-0 n2 pos-3-1 n3
2
9 2
10 3
1
0 0 2 6
0
end_operator
begin_operator
move-up pos-3-1 n0 pos-2-1 n1
2
7 1
10 0
1
0 0 6 3
0
end_operator
begin_operator
move-up pos-3-1 n0 pos-3-0 n1
2
9 1
10 0
1
0 0 6 2
0
end_operator
begin_operator
move-up pos-3-1 n0 pos-3-2 n1
2
10 0
11 1
1
0 0 6 10
0
end_operator
begin_operator
move-up pos-3-1 n1 pos-2-1 n2
2
7 2
10 1
1
0 0 6 3
0
end_operator
begin_operator
move-up pos-3-1 n1 pos-3-0 n2
2
9 2
10 1
1
0 0 6 2
0
end_operator
begin_operator
move-up pos-3-1 n1 pos-3-2 n2
2
10 1
11 2
1
0 0 6 10
0
end_operator
begin_operator
move-up pos-3-1 n2 pos-2-1 n3
2
7 3
10 2
1
0 0 6 3
0
end_operator
begin_operator
move-up pos-3-1 n2 pos-3-0 n3
2
9 3
10 2
1
0 0 6 2
0
end_operator
begin_operator
move-up pos-3-1 n2 pos-3-2 n3
2
10 2
11 3
1
0 0 6 10
0
end_operator
begin_operator
move-up pos-3-2 n0 pos-2-2 n1
2
8 1
11 0
1
0 0 10 7
0
end_operator
begin_operator
move-up pos-3-2 n0 pos-3-1 n1
2
10 1
11 0
1
0 0 10 6
0
end_operator
begin_operator
move-up pos-3-2 n1 pos-2-2 n2
2
8 2
11 1
1
0 0 10 7
0
end_operator
begin_operator
move-up pos-3-2 n1 pos-3-1 n2
2
10 2
11 1
1
0 0 10 6
0
end_operator
begin_operator
move-up pos-3-2 n2 pos-2-2 n3
2
8 3
11 2
1
0 0 10 7
0
end_operator
begin_operator
move-up pos-3-2 n2 pos-3-1 n3
2
10 3
11 2
1
0 0 10 6
0
end_operator
begin_operator
move-down pos-0-0 n1 pos-0-1 n0
2
1 1
2 0
1
0 0 4 8
0
end_operator
begin_operator
move-down pos-0-0 n1 pos-1-0 n0
2
1 1
4 0
1
0 0 4 1
0
end_operator
begin_operator
move-down pos-0-0 n2 pos-0-1 n1
2
1 2
2 1
1
0 0 4 8
0
end_operator
begin_operator
move-down pos-0-0 n2 pos-1-0 n1
2
1 2
4 1
1
0 0 4 1
0
end_operator
begin_operator
move-down pos-0-0 n3 pos-0-1 n2
2
1 3
2 2
1
0 0 4 8
0
end_operator
begin_operator
move-down pos-0-0 n3 pos-1-0 n2
2
1 3
4 2
1
0 0 4 1
0
end_operator
begin_operator
move-down pos-0-1 n1 pos-0-0 n0
2
1 0
2 1
1
0 0 8 4
0
end_operator
begin_operator
move-down pos-0-1 n1 pos-0-2 n0
2
2 1
3 0
1
0 0 8 11
0
end_operator
begin_operator
move-down pos-0-1 n1 pos-1-1 n0
2
2 1
5 0
1
0 0 8 5
0
end_operator
begin_operator
move-down pos-0-1 n2 pos-0-0 n1
2
1 1
2 2
1
0 0 8 4
0
end_operator
begin_operator
move-down pos-0-1 n2 pos-0-2 n1
2
2 2
3 1
1
0 0 8 11
0
end_operator
begin_operator
move-down pos-0-1 n2 pos-1-1 n1
2
2 2
5 1
1
0 0 8 5
0
end_operator
begin_operator
move-down pos-0-1 n3 pos-0-0 n2
2
1 2
2 3
1
0 0 8 4
0
end_operator
begin_operator
move-down pos-0-1 n3 pos-0-2 n2
2
2 3
3 2
1
0 0 8 11
0
end_operator
begin_operator
move-down pos-0-1 n3 pos-1-1 n2
2
2 3
5 2
1
0 0 8 5
0
end_operator
begin_operator
move-down pos-0-2 n1 pos-0-1 n0
2
2 0
3 1
1
0 0 11 8
0
end_operator
begin_operator
move-down pos-0-2 n1 pos-1-2 n0
2
3 1
6 0
1
0 0 11 9
0
end_operator
begin_operator
move-down pos-0-2 n2 pos-0-1 n1
2
2 1
3 2
1
0 0 11 8
0
end_operator
begin_operator
move-down pos-0-2 n2 pos-1-2 n1
2
3 2
6 1
1
0 0 11 9
0
end_operator
begin_operator
move-down pos-0-2 n3 pos-0-1 n2
2
2 2
3 3
1
0 0 11 8
0
end_operator
begin_operator
move-down pos-0-2 n3 pos-1-2 n2
2
3 3
6 2
1
0 0 11 9
0
end_operator
begin_operator
move-down pos-1-0 n1 pos-0-0 n0
2
1 0
4 1
1
0 0 1 4
0
end_operator
begin_operator
move-down pos-1-0 n1 pos-1-1 n0
2
4 1
5 0
1
0 0 1 5
0
end_operator
begin_operator
move-down pos-1-0 n1 pos-2-0 n0
1
4 1
1
0 0 1 0
0
end_operator
begin_operator
move-down pos-1-0 n2 pos-0-0 n1
2
1 1
4 2
1
0 0 1 4
0
end_operator
begin_operator
move-down pos-1-0 n2 pos-1-1 n1
2
4 2
5 1
1
0 0 1 5
0
end_operator
begin_operator
move-down pos-1-0 n3 pos-0-0 n2
2
1 2
4 3
1
0 0 1 4
0
end_operator
begin_operator
move-down pos-1-0 n3 pos-1-1 n2
2
4 3
5 2
1
0 0 1 5
0
end_operator
begin_operator
move-down pos-1-1 n1 pos-0-1 n0
2
2 0
5 1
1
0 0 5 8
0
end_operator
begin_operator
move-down pos-1-1 n1 pos-1-0 n0
2
4 0
5 1
1
0 0 5 1
0
end_operator
begin_operator
move-down pos-1-1 n1 pos-1-2 n0
2
5 1
6 0
1
0 0 5 9
0
end_operator
begin_operator
move-down pos-1-1 n1 pos-2-1 n0
2
5 1
7 0
1
0 0 5 3
0
end_operator
begin_operator
move-down pos-1-1 n2 pos-0-1 n1
2
2 1
5 2
1
0 0 5 8
0
end_operator
begin_operator
move-down pos-1-1 n2 pos-1-0 n1
2
4 1
5 2
1
0 0 5 1
0
end_operator
begin_operator
move-down pos-1-1 n2 pos-1-2 n1
2
5 2
6 1
1
0 0 5 9
0
end_operator
begin_operator
move-down pos-1-1 n2 pos-2-1 n1
2
5 2
7 1
1
0 0 5 3
0
end_operator
begin_operator
move-down pos-1-1 n3 pos-0-1 n2
2
2 2
5 3
1
0 0 5 8
0
end_operator
begin_operator
move-down pos-1-1 n3 pos-1-0 n2
2
4 2
5 3
1
0 0 5 1
0
end_operator
begin_operator
move-down pos-1-1 n3 pos-1-2 n2
2
5 3
6 2
1
0 0 5 9
0
end_operator
begin_operator
move-down pos-1-1 n3 pos-2-1 n2
2
5 3
7 2
1
0 0 5 3
0
end_operator
begin_operator
move-down pos-1-2 n1 pos-0-2 n0
2
3 0
6 1
1
0 0 9 11
0
end_operator
begin_operator
move-down pos-1-2 n1 pos-1-1 n0
2
5 0
6 1
1
0 0 9 5
0
end_operator
begin_operator
move-down pos-1-2 n1 pos-2-2 n0
2
6 1
8 0
1
0 0 9 7
0
end_operator
begin_operator
move-down pos-1-2 n2 pos-0-2 n1
2
3 1
6 2
1
0 0 9 11
0
end_operator
begin_operator
move-down pos-1-2 n2 pos-1-1 n1
2
5 1
6 2
1
0 0 9 5
0
end_operator
begin_operator
move-down pos-1-2 n2 pos-2-2 n1
2
6 2
8 1
1
0 0 9 7
0
end_operator
begin_operator
move-down pos-1-2 n3 pos-0-2 n2
2
3 2
6 3
1
0 0 9 11
0
end_operator
begin_operator
move-down pos-1-2 n3 pos-1-1 n2
2
5 2
6 3
1
0 0 9 5
0
end_operator
begin_operator
move-down pos-1-2 n3 pos-2-2 n2
2
6 3
8 2
1
0 0 9 7
0
end_operator
begin_operator
move-down pos-2-1 n1 pos-1-1 n0
2
5 0
7 1
1
0 0 3 5
0
end_operator
begin_operator
move-down pos-2-1 n1 pos-2-0 n0
1
7 1
1
0 0 3 0
0
end_operator
begin_operator
move-down pos-2-1 n1 pos-2-2 n0
2
7 1
8 0
1
0 0 3 7
0
end_operator
begin_operator
move-down pos-2-1 n1 pos-3-1 n0
2
7 1
10 0
1
0 0 3 6
0
end_operator
begin_operator
move-down pos-2-1 n2 pos-1-1 n1
2
5 1
7 2
1
0 0 3 5
0
end_operator
begin_operator
move-down pos-2-1 n2 pos-2-2 n1
2
7 2
8 1
1
0 0 3 7
0
end_operator
begin_operator
move-down pos-2-1 n2 pos-3-1 n1
2
7 2
10 1
1
0 0 3 6
0
end_operator
begin_operator
move-down pos-2-1 n3 pos-1-1 n2
2
5 2
7 3
1
0 0 3 5
0
end_operator
begin_operator
move-down pos-2-1 n3 pos-2-2 n2
2
7 3
8 2
1
0 0 3 7
0
end_operator
begin_operator
move-down pos-2-1 n3 pos-3-1 n2
2
7 3
10 2
1
0 0 3 6
0
end_operator
begin_operator
move-down pos-2-2 n1 pos-1-2 n0
2
6 0
8 1
1
0 0 7 9
0
end_operator
begin_operator
move-down pos-2-2 n1 pos-2-1 n0
2
7 0
8 1
1
0 0 7 3
0
end_operator
begin_operator
move-down pos-2-2 n1 pos-3-2 n0
2
8 1
11 0
1
0 0 7 10
0
end_operator
begin_operator
move-down pos-2-2 n2 pos-1-2 n1
2
6 1
8 2
1
0 0 7 9
0
end_operator
begin_operator
move-down pos-2-2 n2 pos-2-1 n1
2
7 1
8 2
1
0 0 7 3
0
end_operator
begin_operator
move-down pos-2-2 n2 pos-3-2 n1
2
8 2
11 1
1
0 0 7 10
0
end_operator
begin_operator
move-down pos-2-2 n3 pos-1-2 n2
2
6 2
8 3
1
0 0 7 9
0
end_operator
begin_operator
move-down pos-2-2 n3 pos-2-1 n2
2
7 2
8 3
1
0 0 7 3
0
end_operator
begin_operator
move-down pos-2-2 n3 pos-3-2 n2
2
8 3
11 2
1
0 0 7 10
0
end_operator
begin_operator
move-down pos-3-0 n1 pos-2-0 n0
1
9 1
1
0 0 2 0
0
end_operator
begin_operator
move-down pos-3-0 n1 pos-3-1 n0
2
9 1
10 0
1
0 0 2 6
0
end_operator
begin_operator
move-down pos-3-0 n2 pos-3-1 n1
2
9 2
10 1
1
0 0 2 6
0
end_operator
begin_operator
move-down pos-3-0 n3 pos-3-1 n2
2
9 3
10 2
1
0 0 2 6
0
end_operator
begin_operator
move-down pos-3-1 n1 pos-2-1 n0
2
7 0
10 1
1
0 0 6 3
0
end_operator
begin_operator
move-down pos-3-1 n1 pos-3-0 n0
2
9 0
10 1
1
0 0 6 2
0
end_operator
begin_operator
move-down pos-3-1 n1 pos-3-2 n0
2
10 1
11 0
1
0 0 6 10
0
end_operator
begin_operator
move-down pos-3-1 n2 pos-2-1 n1
2
7 1
10 2
1
0 0 6 3
0
end_operator
begin_operator
move-down pos-3-1 n2 pos-3-0 n1
2
9 1
10 2
1
0 0 6 2
0
end_operator
begin_operator
move-down pos-3-1 n2 pos-3-2 n1
2
10 2
11 1
1
0 0 6 10
0
end_operator
begin_operator
move-down pos-3-1 n3 pos-2-1 n2
2
7 2
10 3
1
0 0 6 3
0
end_operator
begin_operator
move-down pos-3-1 n3 pos-3-0 n2
2
9 2
10 3
1
0 0 6 2
0
end_operator
begin_operator
move-down pos-3-1 n3 pos-3-2 n2
2
10 3
11 2
1
0 0 6 10
0
end_operator
begin_operator
move-down pos-3-2 n1 pos-2-2 n0
2
8 0
11 1
1
0 0 10 7
0
end_operator
begin_operator
move-down pos-3-2 n1 pos-3-1 n0
2
10 0
11 1
1
0 0 10 6
0
end_operator
begin_operator
move-down pos-3-2 n2 pos-2-2 n1
2
8 1
11 2
1
0 0 10 7
0
end_operator
begin_operator
move-down pos-3-2 n2 pos-3-1 n1
2
10 1
11 2
1
0 0 10 6
0
end_operator
begin_operator
move-down pos-3-2 n3 pos-2-2 n2
2
8 2
11 3
1
0 0 10 7
0
end_operator
begin_operator
move-down pos-3-2 n3 pos-3-1 n2
2
10 2
11 3
1
0 0 10 6
0
end_operator
begin_operator
place-block pos-0-0 pos-0-1 n0 n1
2
0 4
1 0
2
0 2 0 1
0 12 0 1
0
end_operator
begin_operator
place-block pos-0-0 pos-0-1 n1 n2
2
0 4
1 1
2
0 2 1 2
0 12 0 1
0
end_operator
begin_operator
place-block pos-0-0 pos-0-1 n2 n3
2
0 4
1 2
2
0 2 2 3
0 12 0 1
0
end_operator
begin_operator
place-block pos-0-0 pos-1-0 n0 n1
2
0 4
1 0
2
0 4 0 1
0 12 0 1
0
end_operator
begin_operator
place-block pos-0-0 pos-1-0 n1 n2
2
0 4
1 1
2
0 4 1 2
0 12 0 1
0
end_operator
begin_operator
place-block pos-0-0 pos-1-0 n2 n3
2
0 4
1 2
2
0 4 2 3
0 12 0 1
0
end_operator
begin_operator
place-block pos-0-1 pos-0-0 n0 n1
2
0 8
2 0
2
0 1 0 1
0 12 0 1
0
end_operator
begin_operator
place-block pos-0-1 pos-0-0 n1 n2
2
0 8
2 1
2
0 1 1 2
0 12 0 1
0
end_operator
begin_operator
place-block pos-0-1 pos-0-0 n2 n3
2
0 8
2 2
2
0 1 2 3
0 12 0 1
0
end_operator
begin_operator
place-block pos-0-1 pos-0-2 n0 n1
2
0 8
2 0
2
0 3 0 1
0 12 0 1
0
end_operator
begin_operator
place-block pos-0-1 pos-0-2 n1 n2
2
0 8
2 1
2
0 3 1 2
0 12 0 1
0
end_operator
begin_operator
place-block pos-0-1 pos-0-2 n2 n3
2
0 8
2 2
2
0 3 2 3
0 12 0 1
0
end_operator
begin_operator
place-block pos-0-1 pos-1-1 n0 n1
2
0 8
2 0
2
0 5 0 1
0 12 0 1
0
end_operator
begin_operator
place-block pos-0-1 pos-1-1 n1 n2
2
0 8
2 1
2
0 5 1 2
0 12 0 1
0
end_operator
begin_operator
place-block pos-0-1 pos-1-1 n2 n3
2
0 8
2 2
2
0 5 2 3
0 12 0 1
0
end_operator
begin_operator
place-block pos-0-2 pos-0-1 n0 n1
2
0 11
3 0
2
0 2 0 1
0 12 0 1
0
end_operator
begin_operator
place-block pos-0-2 pos-0-1 n1 n2
2
0 11
3 1
2
0 2 1 2
0 12 0 1
0
end_operator
begin_operator
place-block pos-0-2 pos-0-1 n2 n3
2
0 11
3 2
2
0 2 2 3
0 12 0 1
0
end_operator
begin_operator
place-block pos-0-2 pos-1-2 n0 n1
2
0 11
3 0
2
0 6 0 1
0 12 0 1
0
end_operator
begin_operator
place-block pos-0-2 pos-1-2 n1 n2
2
0 11
3 1
2
0 6 1 2
0 12 0 1
0
end_operator
begin_operator
place-block pos-0-2 pos-1-2 n2 n3
2
0 11
3 2
2
0 6 2 3
0 12 0 1
0
end_operator
begin_operator
place-block pos-1-0 pos-0-0 n0 n1
2
0 1
4 0
2
0 1 0 1
0 12 0 1
0
end_operator
begin_operator
place-block pos-1-0 pos-0-0 n1 n2
2
0 1
4 1
2
0 1 1 2
0 12 0 1
0
end_operator
begin_operator
place-block pos-1-0 pos-0-0 n2 n3
2
0 1
4 2
2
0 1 2 3
0 12 0 1
0
end_operator
begin_operator
place-block pos-1-0 pos-1-1 n0 n1
2
0 1
4 0
2
0 5 0 1
0 12 0 1
0
end_operator
begin_operator
place-block pos-1-0 pos-1-1 n1 n2
2
0 1
4 1
2
0 5 1 2
0 12 0 1
0
end_operator
begin_operator
place-block pos-1-0 pos-1-1 n2 n3
2
0 1
4 2
2
0 5 2 3
0 12 0 1
0
end_operator
begin_operator
place-block pos-1-1 pos-0-1 n0 n1
2
0 5
5 0
2
0 2 0 1
0 12 0 1
0
end_operator
begin_operator
place-block pos-1-1 pos-0-1 n1 n2
2
0 5
5 1
2
0 2 1 2
0 12 0 1
0
end_operator
begin_operator
place-block pos-1-1 pos-0-1 n2 n3
2
0 5
5 2
2
0 2 2 3
0 12 0 1
0
end_operator
begin_operator
place-block pos-1-1 pos-1-0 n0 n1
2
0 5
5 0
2
0 4 0 1
0 12 0 1
0
end_operator
begin_operator
place-block pos-1-1 pos-1-0 n1 n2
2
0 5
5 1
2
0 4 1 2
0 12 0 1
0
end_operator
begin_operator
place-block pos-1-1 pos-1-0 n2 n3
2
0 5
5 2
2
0 4 2 3
0 12 0 1
0
end_operator
begin_operator
place-block pos-1-1 pos-1-2 n0 n1
2
0 5
5 0
2
0 6 0 1
0 12 0 1
0
end_operator
begin_operator
place-block pos-1-1 pos-1-2 n1 n2
2
0 5
5 1
2
0 6 1 2
0 12 0 1
0
end_operator
begin_operator
place-block pos-1-1 pos-1-2 n2 n3
2
0 5
5 2
2
0 6 2 3
0 12 0 1
0
end_operator
begin_operator
place-block pos-1-1 pos-2-1 n0 n1
2
0 5
5 0
2
0 7 0 1
0 12 0 1
0
end_operator
begin_operator
place-block pos-1-1 pos-2-1 n1 n2
2
0 5
5 1
2
0 7 1 2
0 12 0 1
0
end_operator
begin_operator
place-block pos-1-1 pos-2-1 n2 n3
2
0 5
5 2
2
0 7 2 3
0 12 0 1
0
end_operator
begin_operator
place-block pos-1-2 pos-0-2 n0 n1
2
0 9
6 0
2
0 3 0 1
0 12 0 1
0
end_operator
begin_operator
place-block pos-1-2 pos-0-2 n1 n2
2
0 9
6 1
2
0 3 1 2
0 12 0 1
0
end_operator
begin_operator
place-block pos-1-2 pos-0-2 n2 n3
2
0 9
6 2
2
0 3 2 3
0 12 0 1
0
end_operator
begin_operator
place-block pos-1-2 pos-1-1 n0 n1
2
0 9
6 0
2
0 5 0 1
0 12 0 1
0
end_operator
begin_operator
place-block pos-1-2 pos-1-1 n1 n2
2
0 9
6 1
2
0 5 1 2
0 12 0 1
0
end_operator
begin_operator
place-block pos-1-2 pos-1-1 n2 n3
2
0 9
6 2
2
0 5 2 3
0 12 0 1
0
end_operator
begin_operator
place-block pos-1-2 pos-2-2 n0 n1
2
0 9
6 0
2
0 8 0 1
0 12 0 1
0
end_operator
begin_operator
place-block pos-1-2 pos-2-2 n1 n2
2
0 9
6 1
2
0 8 1 2
0 12 0 1
0
end_operator
begin_operator
place-block pos-1-2 pos-2-2 n2 n3
2
0 9
6 2
2
0 8 2 3
0 12 0 1
0
end_operator
begin_operator
place-block pos-2-0 pos-1-0 n0 n1
1
0 0
2
0 4 0 1
0 12 0 1
0
end_operator
begin_operator
place-block pos-2-0 pos-2-1 n0 n1
1
0 0
2
0 7 0 1
0 12 0 1
0
end_operator
begin_operator
place-block pos-2-0 pos-3-0 n0 n1
1
0 0
2
0 9 0 1
0 12 0 1
0
end_operator
begin_operator
place-block pos-2-1 pos-1-1 n0 n1
2
0 3
7 0
2
0 5 0 1
0 12 0 1
0
end_operator
begin_operator
place-block pos-2-1 pos-1-1 n1 n2
2
0 3
7 1
2
0 5 1 2
0 12 0 1
0
end_operator
begin_operator
place-block pos-2-1 pos-1-1 n2 n3
2
0 3
7 2
2
0 5 2 3
0 12 0 1
0
end_operator
begin_operator
place-block pos-2-1 pos-2-2 n0 n1
2
0 3
7 0
2
0 8 0 1
0 12 0 1
0
end_operator
begin_operator
place-block pos-2-1 pos-2-2 n1 n2
2
0 3
7 1
2
0 8 1 2
0 12 0 1
0
end_operator
begin_operator
place-block pos-2-1 pos-2-2 n2 n3
2
0 3
7 2
2
0 8 2 3
0 12 0 1
0
end_operator
begin_operator
place-block pos-2-1 pos-3-1 n0 n1
2
0 3
7 0
2
0 10 0 1
0 12 0 1
0
end_operator
begin_operator
place-block pos-2-1 pos-3-1 n1 n2
2
0 3
7 1
2
0 10 1 2
0 12 0 1
0
end_operator
begin_operator
place-block pos-2-1 pos-3-1 n2 n3
2
0 3
7 2
2
0 10 2 3
0 12 0 1
0
end_operator
begin_operator
place-block pos-2-2 pos-1-2 n0 n1
2
0 7
8 0
2
0 6 0 1
0 12 0 1
0
end_operator
begin_operator
place-block pos-2-2 pos-1-2 n1 n2
2
0 7
8 1
2
0 6 1 2
0 12 0 1
0
end_operator
begin_operator
place-block pos-2-2 pos-1-2 n2 n3
2
0 7
8 2
2
0 6 2 3
0 12 0 1
0
end_operator
begin_operator
place-block pos-2-2 pos-2-1 n0 n1
2
0 7
8 0
2
0 7 0 1
0 12 0 1
0
end_operator
begin_operator
place-block pos-2-2 pos-2-1 n1 n2
2
0 7
8 1
2
0 7 1 2
0 12 0 1
0
end_operator
begin_operator
place-block pos-2-2 pos-2-1 n2 n3
2
0 7
8 2
2
0 7 2 3
0 12 0 1
0
end_operator
begin_operator
place-block pos-2-2 pos-3-2 n0 n1
2
0 7
8 0
2
0 11 0 1
0 12 0 1
0
end_operator
begin_operator
place-block pos-2-2 pos-3-2 n1 n2
2
0 7
8 1
2
0 11 1 2
0 12 0 1
0
end_operator
begin_operator
place-block pos-2-2 pos-3-2 n2 n3
2
0 7
8 2
2
0 11 2 3
0 12 0 1
0
end_operator
begin_operator
place-block pos-3-0 pos-3-1 n0 n1
2
0 2
9 0
2
0 10 0 1
0 12 0 1
0
end_operator
begin_operator
place-block pos-3-0 pos-3-1 n1 n2
2
0 2
9 1
2
0 10 1 2
0 12 0 1
0
end_operator
begin_operator
place-block pos-3-0 pos-3-1 n2 n3
2
0 2
9 2
2
0 10 2 3
0 12 0 1
0
end_operator
begin_operator
place-block pos-3-1 pos-2-1 n0 n1
2
0 6
10 0
2
0 7 0 1
0 12 0 1
0
end_operator
begin_operator
place-block pos-3-1 pos-2-1 n1 n2
2
0 6
10 1
2
0 7 1 2
0 12 0 1
0
end_operator
begin_operator
place-block pos-3-1 pos-2-1 n2 n3
2
0 6
10 2
2
0 7 2 3
0 12 0 1
0
end_operator
begin_operator
place-block pos-3-1 pos-3-0 n0 n1
2
0 6
10 0
2
0 9 0 1
0 12 0 1
0
end_operator
begin_operator
place-block pos-3-1 pos-3-0 n1 n2
2
0 6
10 1
2
0 9 1 2
0 12 0 1
0
end_operator
begin_operator
place-block pos-3-1 pos-3-0 n2 n3
2
0 6
10 2
2
0 9 2 3
0 12 0 1
0
end_operator
begin_operator
place-block pos-3-1 pos-3-2 n0 n1
2
0 6
10 0
2
0 11 0 1
0 12 0 1
0
end_operator
begin_operator
place-block pos-3-1 pos-3-2 n1 n2
2
0 6
10 1
2
0 11 1 2
0 12 0 1
0
end_operator
begin_operator
place-block pos-3-1 pos-3-2 n2 n3
2
0 6
10 2
2
0 11 2 3
0 12 0 1
0
end_operator
begin_operator
place-block pos-3-2 pos-2-2 n0 n1
2
0 10
11 0
2
0 8 0 1
0 12 0 1
0
end_operator
begin_operator
place-block pos-3-2 pos-2-2 n1 n2
2
0 10
11 1
2
0 8 1 2
0 12 0 1
0
end_operator
begin_operator
place-block pos-3-2 pos-2-2 n2 n3
2
0 10
11 2
2
0 8 2 3
0 12 0 1
0
end_operator
begin_operator
place-block pos-3-2 pos-3-1 n0 n1
2
0 10
11 0
2
0 10 0 1
0 12 0 1
0
end_operator
begin_operator
place-block pos-3-2 pos-3-1 n1 n2
2
0 10
11 1
2
0 10 1 2
0 12 0 1
0
end_operator
begin_operator
place-block pos-3-2 pos-3-1 n2 n3
2
0 10
11 2
2
0 10 2 3
0 12 0 1
0
end_operator
begin_operator
remove-block pos-0-0 pos-0-1 n1 n0
2
0 4
1 0
2
0 2 1 0
0 12 1 0
0
end_operator
begin_operator
remove-block pos-0-0 pos-0-1 n2 n1
2
0 4
1 1
2
0 2 2 1
0 12 1 0
0
end_operator
begin_operator
remove-block pos-0-0 pos-0-1 n3 n2
2
0 4
1 2
2
0 2 3 2
0 12 1 0
0
end_operator
begin_operator
remove-block pos-0-0 pos-1-0 n1 n0
2
0 4
1 0
2
0 4 1 0
0 12 1 0
0
end_operator
begin_operator
remove-block pos-0-0 pos-1-0 n2 n1
2
0 4
1 1
2
0 4 2 1
0 12 1 0
0
end_operator
begin_operator
remove-block pos-0-0 pos-1-0 n3 n2
2
0 4
1 2
2
0 4 3 2
0 12 1 0
0
end_operator
begin_operator
remove-block pos-0-1 pos-0-0 n1 n0
2
0 8
2 0
2
0 1 1 0
0 12 1 0
0
end_operator
begin_operator
remove-block pos-0-1 pos-0-0 n2 n1
2
0 8
2 1
2
0 1 2 1
0 12 1 0
0
end_operator
begin_operator
remove-block pos-0-1 pos-0-0 n3 n2
2
0 8
2 2
2
0 1 3 2
0 12 1 0
0
end_operator
begin_operator
remove-block pos-0-1 pos-0-2 n1 n0
2
0 8
2 0
2
0 3 1 0
0 12 1 0
0
end_operator
begin_operator
remove-block pos-0-1 pos-0-2 n2 n1
2
0 8
2 1
2
0 3 2 1
0 12 1 0
0
end_operator
begin_operator
remove-block pos-0-1 pos-0-2 n3 n2
2
0 8
2 2
2
0 3 3 2
0 12 1 0
0
end_operator
begin_operator
remove-block pos-0-1 pos-1-1 n1 n0
2
0 8
2 0
2
0 5 1 0
0 12 1 0
0
end_operator
begin_operator
remove-block pos-0-1 pos-1-1 n2 n1
2
0 8
2 1
2
0 5 2 1
0 12 1 0
0
end_operator
begin_operator
remove-block pos-0-1 pos-1-1 n3 n2
2
0 8
2 2
2
0 5 3 2
0 12 1 0
0
end_operator
begin_operator
remove-block pos-0-2 pos-0-1 n1 n0
2
0 11
3 0
2
0 2 1 0
0 12 1 0
0
end_operator
begin_operator
remove-block pos-0-2 pos-0-1 n2 n1
2
0 11
3 1
2
0 2 2 1
0 12 1 0
0
end_operator
begin_operator
remove-block pos-0-2 pos-0-1 n3 n2
2
0 11
3 2
2
0 2 3 2
0 12 1 0
0
end_operator
begin_operator
remove-block pos-0-2 pos-1-2 n1 n0
2
0 11
3 0
2
0 6 1 0
0 12 1 0
0
end_operator
begin_operator
remove-block pos-0-2 pos-1-2 n2 n1
2
0 11
3 1
2
0 6 2 1
0 12 1 0
0
end_operator
begin_operator
remove-block pos-0-2 pos-1-2 n3 n2
2
0 11
3 2
2
0 6 3 2
0 12 1 0
0
end_operator
begin_operator
remove-block pos-1-0 pos-0-0 n1 n0
2
0 1
4 0
2
0 1 1 0
0 12 1 0
0
end_operator
begin_operator
remove-block pos-1-0 pos-0-0 n2 n1
2
0 1
4 1
2
0 1 2 1
0 12 1 0
0
end_operator
begin_operator
remove-block pos-1-0 pos-0-0 n3 n2
2
0 1
4 2
2
0 1 3 2
0 12 1 0
0
end_operator
begin_operator
remove-block pos-1-0 pos-1-1 n1 n0
2
0 1
4 0
2
0 5 1 0
0 12 1 0
0
end_operator
begin_operator
remove-block pos-1-0 pos-1-1 n2 n1
2
0 1
4 1
2
0 5 2 1
0 12 1 0
0
end_operator
begin_operator
remove-block pos-1-0 pos-1-1 n3 n2
2
0 1
4 2
2
0 5 3 2
0 12 1 0
0
end_operator
begin_operator
remove-block pos-1-1 pos-0-1 n1 n0
2
0 5
5 0
2
0 2 1 0
0 12 1 0
0
end_operator
begin_operator
remove-block pos-1-1 pos-0-1 n2 n1
2
0 5
5 1
2
0 2 2 1
0 12 1 0
0
end_operator
begin_operator
remove-block pos-1-1 pos-0-1 n3 n2
2
0 5
5 2
2
0 2 3 2
0 12 1 0
0
end_operator
begin_operator
remove-block pos-1-1 pos-1-0 n1 n0
2
0 5
5 0
2
0 4 1 0
0 12 1 0
0
end_operator
begin_operator
remove-block pos-1-1 pos-1-0 n2 n1
2
0 5
5 1
2
0 4 2 1
0 12 1 0
0
end_operator
begin_operator
remove-block pos-1-1 pos-1-0 n3 n2
2
0 5
5 2
2
0 4 3 2
0 12 1 0
0
end_operator
begin_operator
remove-block pos-1-1 pos-1-2 n1 n0
2
0 5
5 0
2
0 6 1 0
0 12 1 0
0
end_operator
begin_operator
remove-block pos-1-1 pos-1-2 n2 n1
2
0 5
5 1
2
0 6 2 1
0 12 1 0
0
end_operator
begin_operator
remove-block pos-1-1 pos-1-2 n3 n2
2
0 5
5 2
2
0 6 3 2
0 12 1 0
0
end_operator
begin_operator
remove-block pos-1-1 pos-2-1 n1 n0
2
0 5
5 0
2
0 7 1 0
0 12 1 0
0
end_operator
begin_operator
remove-block pos-1-1 pos-2-1 n2 n1
2
0 5
5 1
2
0 7 2 1
0 12 1 0
0
end_operator
begin_operator
remove-block pos-1-1 pos-2-1 n3 n2
2
0 5
5 2
2
0 7 3 2
0 12 1 0
0
end_operator
begin_operator
remove-block pos-1-2 pos-0-2 n1 n0
2
0 9
6 0
2
0 3 1 0
0 12 1 0
0
end_operator
begin_operator
remove-block pos-1-2 pos-0-2 n2 n1
2
0 9
6 1
2
0 3 2 1
0 12 1 0
0
end_operator
begin_operator
remove-block pos-1-2 pos-0-2 n3 n2
2
0 9
6 2
2
0 3 3 2
0 12 1 0
0
end_operator
begin_operator
remove-block pos-1-2 pos-1-1 n1 n0
2
0 9
6 0
2
0 5 1 0
0 12 1 0
0
end_operator
begin_operator
remove-block pos-1-2 pos-1-1 n2 n1
2
0 9
6 1
2
0 5 2 1
0 12 1 0
0
end_operator
begin_operator
remove-block pos-1-2 pos-1-1 n3 n2
2
0 9
6 2
2
0 5 3 2
0 12 1 0
0
end_operator
begin_operator
remove-block pos-1-2 pos-2-2 n1 n0
2
0 9
6 0
2
0 8 1 0
0 12 1 0
0
end_operator
begin_operator
remove-block pos-1-2 pos-2-2 n2 n1
2
0 9
6 1
2
0 8 2 1
0 12 1 0
0
end_operator
begin_operator
remove-block pos-1-2 pos-2-2 n3 n2
2
0 9
6 2
2
0 8 3 2
0 12 1 0
0
end_operator
begin_operator
remove-block pos-2-0 pos-1-0 n1 n0
1
0 0
2
0 4 1 0
0 12 1 0
0
end_operator
begin_operator
remove-block pos-2-0 pos-2-1 n1 n0
1
0 0
2
0 7 1 0
0 12 1 0
0
end_operator
begin_operator
remove-block pos-2-0 pos-3-0 n1 n0
1
0 0
2
0 9 1 0
0 12 1 0
0
end_operator
begin_operator
remove-block pos-2-1 pos-1-1 n1 n0
2
0 3
7 0
2
0 5 1 0
0 12 1 0
0
end_operator
begin_operator
remove-block pos-2-1 pos-1-1 n2 n1
2
0 3
7 1
2
0 5 2 1
0 12 1 0
0
end_operator
begin_operator
remove-block pos-2-1 pos-1-1 n3 n2
2
0 3
7 2
2
0 5 3 2
0 12 1 0
0
end_operator
begin_operator
remove-block pos-2-1 pos-2-2 n1 n0
2
0 3
7 0
2
0 8 1 0
0 12 1 0
0
end_operator
begin_operator
remove-block pos-2-1 pos-2-2 n2 n1
2
0 3
7 1
2
0 8 2 1
0 12 1 0
0
end_operator
begin_operator
remove-block pos-2-1 pos-2-2 n3 n2
2
0 3
7 2
2
0 8 3 2
0 12 1 0
0
end_operator
begin_operator
remove-block pos-2-1 pos-3-1 n1 n0
2
0 3
7 0
2
0 10 1 0
0 12 1 0
0
end_operator
begin_operator
remove-block pos-2-1 pos-3-1 n2 n1
2
0 3
7 1
2
0 10 2 1
0 12 1 0
0
end_operator
begin_operator
remove-block pos-2-1 pos-3-1 n3 n2
2
0 3
7 2
2
0 10 3 2
0 12 1 0
0
end_operator
begin_operator
remove-block pos-2-2 pos-1-2 n1 n0
2
0 7
8 0
2
0 6 1 0
0 12 1 0
0
end_operator
begin_operator
remove-block pos-2-2 pos-1-2 n2 n1
2
0 7
8 1
2
0 6 2 1
0 12 1 0
0
end_operator
begin_operator
remove-block pos-2-2 pos-1-2 n3 n2
2
0 7
8 2
2
0 6 3 2
0 12 1 0
0
end_operator
begin_operator
remove-block pos-2-2 pos-2-1 n1 n0
2
0 7
8 0
2
0 7 1 0
0 12 1 0
0
end_operator
begin_operator
remove-block pos-2-2 pos-2-1 n2 n1
2
0 7
8 1
2
0 7 2 1
0 12 1 0
0
end_operator
begin_operator
remove-block pos-2-2 pos-2-1 n3 n2
2
0 7
8 2
2
0 7 3 2
0 12 1 0
0
end_operator
begin_operator
remove-block pos-2-2 pos-3-2 n1 n0
2
0 7
8 0
2
0 11 1 0
0 12 1 0
0
end_operator
begin_operator
remove-block pos-2-2 pos-3-2 n2 n1
2
0 7
8 1
2
0 11 2 1
0 12 1 0
0
end_operator
begin_operator
remove-block pos-2-2 pos-3-2 n3 n2
2
0 7
8 2
2
0 11 3 2
0 12 1 0
0
end_operator
begin_operator
remove-block pos-3-0 pos-3-1 n1 n0
2
0 2
9 0
2
0 10 1 0
0 12 1 0
0
end_operator
begin_operator
remove-block pos-3-0 pos-3-1 n2 n1
2
0 2
9 1
2
0 10 2 1
0 12 1 0
0
end_operator
begin_operator
remove-block pos-3-0 pos-3-1 n3 n2
2
0 2
9 2
2
0 10 3 2
0 12 1 0
0
end_operator
begin_operator
remove-block pos-3-1 pos-2-1 n1 n0
2
0 6
10 0
2
0 7 1 0
0 12 1 0
0
end_operator
begin_operator
remove-block pos-3-1 pos-2-1 n2 n1
2
0 6
10 1
2
0 7 2 1
0 12 1 0
0
end_operator
begin_operator
remove-block pos-3-1 pos-2-1 n3 n2
2
0 6
10 2
2
0 7 3 2
0 12 1 0
0
end_operator
begin_operator
remove-block pos-3-1 pos-3-0 n1 n0
2
0 6
10 0
2
0 9 1 0
0 12 1 0
0
end_operator
begin_operator
remove-block pos-3-1 pos-3-0 n2 n1
2
0 6
10 1
2
0 9 2 1
0 12 1 0
0
end_operator
begin_operator
remove-block pos-3-1 pos-3-0 n3 n2
2
0 6
10 2
2
0 9 3 2
0 12 1 0
0
end_operator
begin_operator
remove-block pos-3-1 pos-3-2 n1 n0
2
0 6
10 0
2
0 11 1 0
0 12 1 0
0
end_operator
begin_operator
remove-block pos-3-1 pos-3-2 n2 n1
2
0 6
10 1
2
0 11 2 1
0 12 1 0
0
end_operator
begin_operator
remove-block pos-3-1 pos-3-2 n3 n2
2
0 6
10 2
2
0 11 3 2
0 12 1 0
0
end_operator
begin_operator
remove-block pos-3-2 pos-2-2 n1 n0
2
0 10
11 0
2
0 8 1 0
0 12 1 0
0
end_operator
begin_operator
remove-block pos-3-2 pos-2-2 n2 n1
2
0 10
11 1
2
0 8 2 1
0 12 1 0
0
end_operator
begin_operator
remove-block pos-3-2 pos-2-2 n3 n2
2
0 10
11 2
2
0 8 3 2
0 12 1 0
0
end_operator
begin_operator
remove-block pos-3-2 pos-3-1 n1 n0
2
0 10
11 0
2
0 10 1 0
0 12 1 0
0
end_operator
begin_operator
remove-block pos-3-2 pos-3-1 n2 n1
2
0 10
11 1
2
0 10 2 1
0 12 1 0
0
end_operator
begin_operator
remove-block pos-3-2 pos-3-1 n3 n2
2
0 10
11 2
2
0 10 3 2
0 12 1 0
0
end_operator
begin_operator
create-block pos-2-0
1
0 0
1
0 12 1 0
0
end_operator
begin_operator
destroy-block pos-2-0
1
0 0
1
0 12 0 1
0
end_operator
0
