begin_version
3
end_version
begin_metric
1
end_metric
18
begin_variable
var0
-1
2
Atom acted-on(left, c1)
NegatedAtom acted-on(left, c1)
end_variable
begin_variable
var1
-1
2
Atom acted-on(left, c2)
NegatedAtom acted-on(left, c2)
end_variable
begin_variable
var2
-1
2
Atom acted-on(right, c1)
NegatedAtom acted-on(right, c1)
end_variable
begin_variable
var3
-1
2
Atom acted-on(left, c3)
NegatedAtom acted-on(left, c3)
end_variable
begin_variable
var4
-1
2
Atom acted-on(left, c4)
NegatedAtom acted-on(left, c4)
end_variable
begin_variable
var5
-1
2
Atom acted-on(right, c2)
NegatedAtom acted-on(right, c2)
end_variable
begin_variable
var6
-1
2
Atom acted-on(right, c3)
NegatedAtom acted-on(right, c3)
end_variable
begin_variable
var7
-1
2
Atom acted-on(right, c4)
NegatedAtom acted-on(right, c4)
end_variable
begin_variable
var8
-1
6
Atom in-hand(left, c1)
Atom in-hand(right, c1)
Atom on-top(c1, c2)
Atom on-top(c1, c3)
Atom on-top(c1, c4)
Atom on-top(c1, table)
end_variable
begin_variable
var9
-1
2
Atom clear(c2)
NegatedAtom clear(c2)
end_variable
begin_variable
var10
-1
2
Atom clear(c3)
NegatedAtom clear(c3)
end_variable
begin_variable
var11
-1
2
Atom clear(c4)
NegatedAtom clear(c4)
end_variable
begin_variable
var12
-1
6
Atom in-hand(left, c4)
Atom in-hand(right, c4)
Atom on-top(c4, c1)
Atom on-top(c4, c2)
Atom on-top(c4, c3)
Atom on-top(c4, table)
end_variable
begin_variable
var13
-1
2
Atom clear(c1)
NegatedAtom clear(c1)
end_variable
begin_variable
var14
-1
2
Atom hand-free(left)
NegatedAtom hand-free(left)
end_variable
begin_variable
var15
-1
2
Atom hand-free(right)
NegatedAtom hand-free(right)
end_variable
begin_variable
var16
-1
6
Atom in-hand(left, c2)
Atom in-hand(right, c2)
Atom on-top(c2, c1)
Atom on-top(c2, c3)
Atom on-top(c2, c4)
Atom on-top(c2, table)
end_variable
begin_variable
var17
-1
6
Atom in-hand(left, c3)
Atom in-hand(right, c3)
Atom on-top(c3, c1)
Atom on-top(c3, c2)
Atom on-top(c3, c4)
Atom on-top(c3, table)
end_variable
2
begin_mutex_group
5
14 0
8 0
16 0
17 0
12 0
end_mutex_group
begin_mutex_group
5
15 0
8 1
16 1
17 1
12 1
end_mutex_group
begin_state
1
1
1
1
1
1
1
1
5
0
0
0
5
0
0
0
5
5
end_state
begin_goal
2
16 2
17 3
end_goal
72
begin_operator
put left c1 table
0
2
0 14 -1 0
0 8 0 5
1
end_operator
begin_operator
put left c2 table
0
2
0 14 -1 0
0 16 0 5
1
end_operator
begin_operator
put left c3 table
0
2
0 14 -1 0
0 17 0 5
1
end_operator
begin_operator
put left c4 table
0
2
0 14 -1 0
0 12 0 5
1
end_operator
begin_operator
put right c1 table
0
2
0 15 -1 0
0 8 1 5
1
end_operator
begin_operator
put right c2 table
0
2
0 15 -1 0
0 16 1 5
1
end_operator
begin_operator
put right c3 table
0
2
0 15 -1 0
0 17 1 5
1
end_operator
begin_operator
put right c4 table
0
2
0 15 -1 0
0 12 1 5
1
end_operator
begin_operator
reach left c1
2
13 0
14 0
1
0 0 1 0
1
end_operator
begin_operator
reach left c2
2
9 0
14 0
1
0 1 1 0
1
end_operator
begin_operator
reach left c3
2
10 0
14 0
1
0 3 1 0
1
end_operator
begin_operator
reach left c4
2
11 0
14 0
1
0 4 1 0
1
end_operator
begin_operator
reach right c1
2
13 0
15 0
1
0 2 1 0
1
end_operator
begin_operator
reach right c2
2
9 0
15 0
1
0 5 1 0
1
end_operator
begin_operator
reach right c3
2
10 0
15 0
1
0 6 1 0
1
end_operator
begin_operator
reach right c4
2
11 0
15 0
1
0 7 1 0
1
end_operator
begin_operator
stack left c1 c2
0
3
0 9 0 1
0 14 -1 0
0 8 0 2
1
end_operator
begin_operator
stack left c1 c3
0
3
0 10 0 1
0 14 -1 0
0 8 0 3
1
end_operator
begin_operator
stack left c1 c4
0
3
0 11 0 1
0 14 -1 0
0 8 0 4
1
end_operator
begin_operator
stack left c2 c1
0
3
0 13 0 1
0 14 -1 0
0 16 0 2
1
end_operator
begin_operator
stack left c2 c3
0
3
0 10 0 1
0 14 -1 0
0 16 0 3
1
end_operator
begin_operator
stack left c2 c4
0
3
0 11 0 1
0 14 -1 0
0 16 0 4
1
end_operator
begin_operator
stack left c3 c1
0
3
0 13 0 1
0 14 -1 0
0 17 0 2
1
end_operator
begin_operator
stack left c3 c2
0
3
0 9 0 1
0 14 -1 0
0 17 0 3
1
end_operator
begin_operator
stack left c3 c4
0
3
0 11 0 1
0 14 -1 0
0 17 0 4
1
end_operator
begin_operator
stack left c4 c1
0
3
0 13 0 1
0 14 -1 0
0 12 0 2
1
end_operator
begin_operator
stack left c4 c2
0
3
0 9 0 1
0 14 -1 0
0 12 0 3
1
end_operator
begin_operator
stack left c4 c3
0
3
0 10 0 1
0 14 -1 0
0 12 0 4
1
end_operator
begin_operator
stack right c1 c2
0
3
0 9 0 1
0 15 -1 0
0 8 1 2
1
end_operator
begin_operator
stack right c1 c3
0
3
0 10 0 1
0 15 -1 0
0 8 1 3
1
end_operator
begin_operator
stack right c1 c4
0
3
0 11 0 1
0 15 -1 0
0 8 1 4
1
end_operator
begin_operator
stack right c2 c1
0
3
0 13 0 1
0 15 -1 0
0 16 1 2
1
end_operator
begin_operator
stack right c2 c3
0
3
0 10 0 1
0 15 -1 0
0 16 1 3
1
end_operator
begin_operator
stack right c2 c4
0
3
0 11 0 1
0 15 -1 0
0 16 1 4
1
end_operator
begin_operator
stack right c3 c1
0
3
0 13 0 1
0 15 -1 0
0 17 1 2
1
end_operator
begin_operator
stack right c3 c2
0
3
0 9 0 1
0 15 -1 0
0 17 1 3
1
end_operator
begin_operator
stack right c3 c4
0
3
0 11 0 1
0 15 -1 0
0 17 1 4
1
end_operator
begin_operator
stack right c4 c1
0
3
0 13 0 1
0 15 -1 0
0 12 1 2
1
end_operator
begin_operator
stack right c4 c2
0
3
0 9 0 1
0 15 -1 0
0 12 1 3
1
end_operator
begin_operator
stack right c4 c3
0
3
0 10 0 1
0 15 -1 0
0 12 1 4
1
end_operator
begin_operator
take left c1 c2
1
13 0
4
0 0 0 1
0 9 -1 0
0 14 0 1
0 8 2 0
1
end_operator
begin_operator
take left c1 c3
1
13 0
4
0 0 0 1
0 10 -1 0
0 14 0 1
0 8 3 0
1
end_operator
begin_operator
take left c1 c4
1
13 0
4
0 0 0 1
0 11 -1 0
0 14 0 1
0 8 4 0
1
end_operator
begin_operator
take left c1 table
1
13 0
3
0 0 0 1
0 14 0 1
0 8 5 0
1
end_operator
begin_operator
take left c2 c1
1
9 0
4
0 1 0 1
0 13 -1 0
0 14 0 1
0 16 2 0
1
end_operator
begin_operator
take left c2 c3
1
9 0
4
0 1 0 1
0 10 -1 0
0 14 0 1
0 16 3 0
1
end_operator
begin_operator
take left c2 c4
1
9 0
4
0 1 0 1
0 11 -1 0
0 14 0 1
0 16 4 0
1
end_operator
begin_operator
take left c2 table
1
9 0
3
0 1 0 1
0 14 0 1
0 16 5 0
1
end_operator
begin_operator
take left c3 c1
1
10 0
4
0 3 0 1
0 13 -1 0
0 14 0 1
0 17 2 0
1
end_operator
begin_operator
take left c3 c2
1
10 0
4
0 3 0 1
0 9 -1 0
0 14 0 1
0 17 3 0
1
end_operator
begin_operator
take left c3 c4
1
10 0
4
0 3 0 1
0 11 -1 0
0 14 0 1
0 17 4 0
1
end_operator
begin_operator
take left c3 table
1
10 0
3
0 3 0 1
0 14 0 1
0 17 5 0
1
end_operator
begin_operator
take left c4 c1
1
11 0
4
0 4 0 1
0 13 -1 0
0 14 0 1
0 12 2 0
1
end_operator
begin_operator
take left c4 c2
1
11 0
4
0 4 0 1
0 9 -1 0
0 14 0 1
0 12 3 0
1
end_operator
begin_operator
take left c4 c3
1
11 0
4
0 4 0 1
0 10 -1 0
0 14 0 1
0 12 4 0
1
end_operator
begin_operator
take left c4 table
1
11 0
3
0 4 0 1
0 14 0 1
0 12 5 0
1
end_operator
begin_operator
take right c1 c2
1
13 0
4
0 2 0 1
0 9 -1 0
0 15 0 1
0 8 2 1
1
end_operator
begin_operator
take right c1 c3
1
13 0
4
0 2 0 1
0 10 -1 0
0 15 0 1
0 8 3 1
1
end_operator
begin_operator
take right c1 c4
1
13 0
4
0 2 0 1
0 11 -1 0
0 15 0 1
0 8 4 1
1
end_operator
begin_operator
take right c1 table
1
13 0
3
0 2 0 1
0 15 0 1
0 8 5 1
1
end_operator
begin_operator
take right c2 c1
1
9 0
4
0 5 0 1
0 13 -1 0
0 15 0 1
0 16 2 1
1
end_operator
begin_operator
take right c2 c3
1
9 0
4
0 5 0 1
0 10 -1 0
0 15 0 1
0 16 3 1
1
end_operator
begin_operator
take right c2 c4
1
9 0
4
0 5 0 1
0 11 -1 0
0 15 0 1
0 16 4 1
1
end_operator
begin_operator
take right c2 table
1
9 0
3
0 5 0 1
0 15 0 1
0 16 5 1
1
end_operator
begin_operator
take right c3 c1
1
10 0
4
0 6 0 1
0 13 -1 0
0 15 0 1
0 17 2 1
1
end_operator
begin_operator
take right c3 c2
1
10 0
4
0 6 0 1
0 9 -1 0
0 15 0 1
0 17 3 1
1
end_operator
begin_operator
take right c3 c4
1
10 0
4
0 6 0 1
0 11 -1 0
0 15 0 1
0 17 4 1
1
end_operator
begin_operator
take right c3 table
1
10 0
3
0 6 0 1
0 15 0 1
0 17 5 1
1
end_operator
begin_operator
take right c4 c1
1
11 0
4
0 7 0 1
0 13 -1 0
0 15 0 1
0 12 2 1
1
end_operator
begin_operator
take right c4 c2
1
11 0
4
0 7 0 1
0 9 -1 0
0 15 0 1
0 12 3 1
1
end_operator
begin_operator
take right c4 c3
1
11 0
4
0 7 0 1
0 10 -1 0
0 15 0 1
0 12 4 1
1
end_operator
begin_operator
take right c4 table
1
11 0
3
0 7 0 1
0 15 0 1
0 12 5 1
1
end_operator
0
