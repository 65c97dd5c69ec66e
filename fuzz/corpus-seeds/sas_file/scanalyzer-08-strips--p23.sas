begin_version
3
end_version
begin_metric
1
end_metric
8
begin_variable
var0
-1
4
Atom on(car-in-1a, seg-in-1a)
Atom on(car-in-1b, seg-in-1a)
Atom on(car-out-1a, seg-in-1a)
Atom on(car-out-1b, seg-in-1a)
end_variable
begin_variable
var1
-1
4
Atom on(car-in-1b, seg-in-1b)
Atom on(car-out-1a, seg-in-1b)
Atom on(car-out-1b, seg-in-1b)
Atom on(car-in-1a, seg-in-1b)
end_variable
begin_variable
var2
-1
4
Atom on(car-out-1a, seg-out-1a)
Atom on(car-out-1b, seg-out-1a)
Atom on(car-in-1a, seg-out-1a)
Atom on(car-in-1b, seg-out-1a)
end_variable
begin_variable
var3
-1
4
Atom on(car-out-1b, seg-out-1b)
Atom on(car-in-1a, seg-out-1b)
Atom on(car-in-1b, seg-out-1b)
Atom on(car-out-1a, seg-out-1b)
end_variable
begin_variable
var4
-1
2
Atom analyzed(car-in-1a)
NegatedAtom analyzed(car-in-1a)
end_variable
begin_variable
var5
-1
2
Atom analyzed(car-in-1b)
NegatedAtom analyzed(car-in-1b)
end_variable
begin_variable
var6
-1
2
Atom analyzed(car-out-1a)
NegatedAtom analyzed(car-out-1a)
end_variable
begin_variable
var7
-1
2
Atom analyzed(car-out-1b)
NegatedAtom analyzed(car-out-1b)
end_variable
4
begin_mutex_group
4
0 0
0 1
0 2
0 3
end_mutex_group
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
begin_state
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
8
0 1
1 1
2 1
3 1
4 0
5 0
6 0
7 0
end_goal
508
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1a car-in-1a car-in-1a
4
0 0
1 3
2 2
3 1
1
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1a car-in-1a car-in-1b
2
0 0
1 3
3
0 2 2 3
0 3 2 1
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1a car-in-1a car-out-1a
2
0 0
1 3
3
0 2 2 0
0 3 3 1
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1a car-in-1a car-out-1b
2
0 0
1 3
3
0 2 2 1
0 3 0 1
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1a car-in-1b car-in-1a
2
0 0
3 1
3
0 1 3 0
0 2 3 2
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1a car-in-1b car-in-1b
2
0 0
2 3
3
0 1 3 0
0 3 2 1
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1a car-in-1b car-out-1a
1
0 0
4
0 1 3 0
0 2 3 0
0 3 3 1
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1a car-in-1b car-out-1b
1
0 0
4
0 1 3 0
0 2 3 1
0 3 0 1
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1a car-out-1a car-in-1a
2
0 0
3 1
3
0 1 3 1
0 2 0 2
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1a car-out-1a car-in-1b
1
0 0
4
0 1 3 1
0 2 0 3
0 3 2 1
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1a car-out-1a car-out-1a
2
0 0
2 0
3
0 1 3 1
0 3 3 1
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1a car-out-1a car-out-1b
1
0 0
4
0 1 3 1
0 2 0 1
0 3 0 1
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1a car-out-1b car-in-1a
2
0 0
3 1
3
0 1 3 2
0 2 1 2
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1a car-out-1b car-in-1b
1
0 0
4
0 1 3 2
0 2 1 3
0 3 2 1
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1a car-out-1b car-out-1a
1
0 0
4
0 1 3 2
0 2 1 0
0 3 3 1
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1a car-out-1b car-out-1b
2
0 0
2 1
3
0 1 3 2
0 3 0 1
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1b car-in-1a car-in-1a
2
2 2
3 1
3
0 0 0 1
0 1 0 3
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1b car-in-1a car-in-1b
0
5
0 0 0 1
0 1 0 3
0 2 2 3
0 3 2 1
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1b car-in-1a car-out-1a
0
5
0 0 0 1
0 1 0 3
0 2 2 0
0 3 3 1
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1b car-in-1a car-out-1b
0
5
0 0 0 1
0 1 0 3
0 2 2 1
0 3 0 1
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1b car-in-1b car-in-1a
2
1 0
3 1
3
0 0 0 1
0 2 3 2
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1b car-in-1b car-in-1b
2
1 0
2 3
3
0 0 0 1
0 3 2 1
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1b car-in-1b car-out-1a
1
1 0
4
0 0 0 1
0 2 3 0
0 3 3 1
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1b car-in-1b car-out-1b
1
1 0
4
0 0 0 1
0 2 3 1
0 3 0 1
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1b car-out-1a car-in-1a
1
3 1
4
0 0 0 1
0 1 0 1
0 2 0 2
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1b car-out-1a car-in-1b
0
5
0 0 0 1
0 1 0 1
0 2 0 3
0 3 2 1
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1b car-out-1a car-out-1a
1
2 0
4
0 0 0 1
0 1 0 1
0 3 3 1
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1b car-out-1a car-out-1b
0
5
0 0 0 1
0 1 0 1
0 2 0 1
0 3 0 1
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1b car-out-1b car-in-1a
1
3 1
4
0 0 0 1
0 1 0 2
0 2 1 2
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1b car-out-1b car-in-1b
0
5
0 0 0 1
0 1 0 2
0 2 1 3
0 3 2 1
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1b car-out-1b car-out-1a
0
5
0 0 0 1
0 1 0 2
0 2 1 0
0 3 3 1
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1b car-out-1b car-out-1b
1
2 1
4
0 0 0 1
0 1 0 2
0 3 0 1
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1a car-in-1a car-in-1a
2
2 2
3 1
3
0 0 0 2
0 1 1 3
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1a car-in-1a car-in-1b
0
5
0 0 0 2
0 1 1 3
0 2 2 3
0 3 2 1
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1a car-in-1a car-out-1a
0
5
0 0 0 2
0 1 1 3
0 2 2 0
0 3 3 1
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1a car-in-1a car-out-1b
0
5
0 0 0 2
0 1 1 3
0 2 2 1
0 3 0 1
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1a car-in-1b car-in-1a
1
3 1
4
0 0 0 2
0 1 1 0
0 2 3 2
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1a car-in-1b car-in-1b
1
2 3
4
0 0 0 2
0 1 1 0
0 3 2 1
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1a car-in-1b car-out-1a
0
5
0 0 0 2
0 1 1 0
0 2 3 0
0 3 3 1
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1a car-in-1b car-out-1b
0
5
0 0 0 2
0 1 1 0
0 2 3 1
0 3 0 1
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1a car-out-1a car-in-1a
2
1 1
3 1
3
0 0 0 2
0 2 0 2
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1a car-out-1a car-in-1b
1
1 1
4
0 0 0 2
0 2 0 3
0 3 2 1
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1a car-out-1a car-out-1a
2
1 1
2 0
3
0 0 0 2
0 3 3 1
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1a car-out-1a car-out-1b
1
1 1
4
0 0 0 2
0 2 0 1
0 3 0 1
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1a car-out-1b car-in-1a
1
3 1
4
0 0 0 2
0 1 1 2
0 2 1 2
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1a car-out-1b car-in-1b
0
5
0 0 0 2
0 1 1 2
0 2 1 3
0 3 2 1
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1a car-out-1b car-out-1a
0
5
0 0 0 2
0 1 1 2
0 2 1 0
0 3 3 1
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1a car-out-1b car-out-1b
1
2 1
4
0 0 0 2
0 1 1 2
0 3 0 1
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1b car-in-1a car-in-1a
2
2 2
3 1
3
0 0 0 3
0 1 2 3
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1b car-in-1a car-in-1b
0
5
0 0 0 3
0 1 2 3
0 2 2 3
0 3 2 1
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1b car-in-1a car-out-1a
0
5
0 0 0 3
0 1 2 3
0 2 2 0
0 3 3 1
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1b car-in-1a car-out-1b
0
5
0 0 0 3
0 1 2 3
0 2 2 1
0 3 0 1
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1b car-in-1b car-in-1a
1
3 1
4
0 0 0 3
0 1 2 0
0 2 3 2
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1b car-in-1b car-in-1b
1
2 3
4
0 0 0 3
0 1 2 0
0 3 2 1
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1b car-in-1b car-out-1a
0
5
0 0 0 3
0 1 2 0
0 2 3 0
0 3 3 1
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1b car-in-1b car-out-1b
0
5
0 0 0 3
0 1 2 0
0 2 3 1
0 3 0 1
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1b car-out-1a car-in-1a
1
3 1
4
0 0 0 3
0 1 2 1
0 2 0 2
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1b car-out-1a car-in-1b
0
5
0 0 0 3
0 1 2 1
0 2 0 3
0 3 2 1
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1b car-out-1a car-out-1a
1
2 0
4
0 0 0 3
0 1 2 1
0 3 3 1
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1b car-out-1a car-out-1b
0
5
0 0 0 3
0 1 2 1
0 2 0 1
0 3 0 1
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1b car-out-1b car-in-1a
2
1 2
3 1
3
0 0 0 3
0 2 1 2
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1b car-out-1b car-in-1b
1
1 2
4
0 0 0 3
0 2 1 3
0 3 2 1
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1b car-out-1b car-out-1a
1
1 2
4
0 0 0 3
0 2 1 0
0 3 3 1
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1b car-out-1b car-out-1b
2
1 2
2 1
3
0 0 0 3
0 3 0 1
0 4 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1a car-in-1a car-in-1a
2
1 3
2 2
3
0 0 1 0
0 3 1 2
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1a car-in-1a car-in-1b
2
1 3
3 2
3
0 0 1 0
0 2 2 3
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1a car-in-1a car-out-1a
1
1 3
4
0 0 1 0
0 2 2 0
0 3 3 2
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1a car-in-1a car-out-1b
1
1 3
4
0 0 1 0
0 2 2 1
0 3 0 2
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1a car-in-1b car-in-1a
0
5
0 0 1 0
0 1 3 0
0 2 3 2
0 3 1 2
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1a car-in-1b car-in-1b
2
2 3
3 2
3
0 0 1 0
0 1 3 0
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1a car-in-1b car-out-1a
0
5
0 0 1 0
0 1 3 0
0 2 3 0
0 3 3 2
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1a car-in-1b car-out-1b
0
5
0 0 1 0
0 1 3 0
0 2 3 1
0 3 0 2
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1a car-out-1a car-in-1a
0
5
0 0 1 0
0 1 3 1
0 2 0 2
0 3 1 2
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1a car-out-1a car-in-1b
1
3 2
4
0 0 1 0
0 1 3 1
0 2 0 3
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1a car-out-1a car-out-1a
1
2 0
4
0 0 1 0
0 1 3 1
0 3 3 2
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1a car-out-1a car-out-1b
0
5
0 0 1 0
0 1 3 1
0 2 0 1
0 3 0 2
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1a car-out-1b car-in-1a
0
5
0 0 1 0
0 1 3 2
0 2 1 2
0 3 1 2
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1a car-out-1b car-in-1b
1
3 2
4
0 0 1 0
0 1 3 2
0 2 1 3
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1a car-out-1b car-out-1a
0
5
0 0 1 0
0 1 3 2
0 2 1 0
0 3 3 2
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1a car-out-1b car-out-1b
1
2 1
4
0 0 1 0
0 1 3 2
0 3 0 2
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1b car-in-1a car-in-1a
2
0 1
2 2
3
0 1 0 3
0 3 1 2
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1b car-in-1a car-in-1b
2
0 1
3 2
3
0 1 0 3
0 2 2 3
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1b car-in-1a car-out-1a
1
0 1
4
0 1 0 3
0 2 2 0
0 3 3 2
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1b car-in-1a car-out-1b
1
0 1
4
0 1 0 3
0 2 2 1
0 3 0 2
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1b car-in-1b car-in-1a
2
0 1
1 0
3
0 2 3 2
0 3 1 2
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1b car-in-1b car-in-1b
4
0 1
1 0
2 3
3 2
1
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1b car-in-1b car-out-1a
2
0 1
1 0
3
0 2 3 0
0 3 3 2
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1b car-in-1b car-out-1b
2
0 1
1 0
3
0 2 3 1
0 3 0 2
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1b car-out-1a car-in-1a
1
0 1
4
0 1 0 1
0 2 0 2
0 3 1 2
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1b car-out-1a car-in-1b
2
0 1
3 2
3
0 1 0 1
0 2 0 3
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1b car-out-1a car-out-1a
2
0 1
2 0
3
0 1 0 1
0 3 3 2
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1b car-out-1a car-out-1b
1
0 1
4
0 1 0 1
0 2 0 1
0 3 0 2
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1b car-out-1b car-in-1a
1
0 1
4
0 1 0 2
0 2 1 2
0 3 1 2
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1b car-out-1b car-in-1b
2
0 1
3 2
3
0 1 0 2
0 2 1 3
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1b car-out-1b car-out-1a
1
0 1
4
0 1 0 2
0 2 1 0
0 3 3 2
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1b car-out-1b car-out-1b
2
0 1
2 1
3
0 1 0 2
0 3 0 2
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1a car-in-1a car-in-1a
1
2 2
4
0 0 1 2
0 1 1 3
0 3 1 2
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1a car-in-1a car-in-1b
1
3 2
4
0 0 1 2
0 1 1 3
0 2 2 3
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1a car-in-1a car-out-1a
0
5
0 0 1 2
0 1 1 3
0 2 2 0
0 3 3 2
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1a car-in-1a car-out-1b
0
5
0 0 1 2
0 1 1 3
0 2 2 1
0 3 0 2
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1a car-in-1b car-in-1a
0
5
0 0 1 2
0 1 1 0
0 2 3 2
0 3 1 2
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1a car-in-1b car-in-1b
2
2 3
3 2
3
0 0 1 2
0 1 1 0
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1a car-in-1b car-out-1a
0
5
0 0 1 2
0 1 1 0
0 2 3 0
0 3 3 2
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1a car-in-1b car-out-1b
0
5
0 0 1 2
0 1 1 0
0 2 3 1
0 3 0 2
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1a car-out-1a car-in-1a
1
1 1
4
0 0 1 2
0 2 0 2
0 3 1 2
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1a car-out-1a car-in-1b
2
1 1
3 2
3
0 0 1 2
0 2 0 3
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1a car-out-1a car-out-1a
2
1 1
2 0
3
0 0 1 2
0 3 3 2
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1a car-out-1a car-out-1b
1
1 1
4
0 0 1 2
0 2 0 1
0 3 0 2
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1a car-out-1b car-in-1a
0
5
0 0 1 2
0 1 1 2
0 2 1 2
0 3 1 2
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1a car-out-1b car-in-1b
1
3 2
4
0 0 1 2
0 1 1 2
0 2 1 3
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1a car-out-1b car-out-1a
0
5
0 0 1 2
0 1 1 2
0 2 1 0
0 3 3 2
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1a car-out-1b car-out-1b
1
2 1
4
0 0 1 2
0 1 1 2
0 3 0 2
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1b car-in-1a car-in-1a
1
2 2
4
0 0 1 3
0 1 2 3
0 3 1 2
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1b car-in-1a car-in-1b
1
3 2
4
0 0 1 3
0 1 2 3
0 2 2 3
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1b car-in-1a car-out-1a
0
5
0 0 1 3
0 1 2 3
0 2 2 0
0 3 3 2
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1b car-in-1a car-out-1b
0
5
0 0 1 3
0 1 2 3
0 2 2 1
0 3 0 2
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1b car-in-1b car-in-1a
0
5
0 0 1 3
0 1 2 0
0 2 3 2
0 3 1 2
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1b car-in-1b car-in-1b
2
2 3
3 2
3
0 0 1 3
0 1 2 0
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1b car-in-1b car-out-1a
0
5
0 0 1 3
0 1 2 0
0 2 3 0
0 3 3 2
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1b car-in-1b car-out-1b
0
5
0 0 1 3
0 1 2 0
0 2 3 1
0 3 0 2
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1b car-out-1a car-in-1a
0
5
0 0 1 3
0 1 2 1
0 2 0 2
0 3 1 2
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1b car-out-1a car-in-1b
1
3 2
4
0 0 1 3
0 1 2 1
0 2 0 3
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1b car-out-1a car-out-1a
1
2 0
4
0 0 1 3
0 1 2 1
0 3 3 2
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1b car-out-1a car-out-1b
0
5
0 0 1 3
0 1 2 1
0 2 0 1
0 3 0 2
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1b car-out-1b car-in-1a
1
1 2
4
0 0 1 3
0 2 1 2
0 3 1 2
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1b car-out-1b car-in-1b
2
1 2
3 2
3
0 0 1 3
0 2 1 3
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1b car-out-1b car-out-1a
1
1 2
4
0 0 1 3
0 2 1 0
0 3 3 2
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1b car-out-1b car-out-1b
2
1 2
2 1
3
0 0 1 3
0 3 0 2
0 5 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1a car-in-1a car-in-1a
2
1 3
2 2
3
0 0 2 0
0 3 1 3
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1a car-in-1a car-in-1b
1
1 3
4
0 0 2 0
0 2 2 3
0 3 2 3
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1a car-in-1a car-out-1a
2
1 3
3 3
3
0 0 2 0
0 2 2 0
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1a car-in-1a car-out-1b
1
1 3
4
0 0 2 0
0 2 2 1
0 3 0 3
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1a car-in-1b car-in-1a
0
5
0 0 2 0
0 1 3 0
0 2 3 2
0 3 1 3
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1a car-in-1b car-in-1b
1
2 3
4
0 0 2 0
0 1 3 0
0 3 2 3
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1a car-in-1b car-out-1a
1
3 3
4
0 0 2 0
0 1 3 0
0 2 3 0
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1a car-in-1b car-out-1b
0
5
0 0 2 0
0 1 3 0
0 2 3 1
0 3 0 3
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1a car-out-1a car-in-1a
0
5
0 0 2 0
0 1 3 1
0 2 0 2
0 3 1 3
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1a car-out-1a car-in-1b
0
5
0 0 2 0
0 1 3 1
0 2 0 3
0 3 2 3
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1a car-out-1a car-out-1a
2
2 0
3 3
3
0 0 2 0
0 1 3 1
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1a car-out-1a car-out-1b
0
5
0 0 2 0
0 1 3 1
0 2 0 1
0 3 0 3
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1a car-out-1b car-in-1a
0
5
0 0 2 0
0 1 3 2
0 2 1 2
0 3 1 3
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1a car-out-1b car-in-1b
0
5
0 0 2 0
0 1 3 2
0 2 1 3
0 3 2 3
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1a car-out-1b car-out-1a
1
3 3
4
0 0 2 0
0 1 3 2
0 2 1 0
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1a car-out-1b car-out-1b
1
2 1
4
0 0 2 0
0 1 3 2
0 3 0 3
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1b car-in-1a car-in-1a
1
2 2
4
0 0 2 1
0 1 0 3
0 3 1 3
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1b car-in-1a car-in-1b
0
5
0 0 2 1
0 1 0 3
0 2 2 3
0 3 2 3
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1b car-in-1a car-out-1a
1
3 3
4
0 0 2 1
0 1 0 3
0 2 2 0
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1b car-in-1a car-out-1b
0
5
0 0 2 1
0 1 0 3
0 2 2 1
0 3 0 3
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1b car-in-1b car-in-1a
1
1 0
4
0 0 2 1
0 2 3 2
0 3 1 3
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1b car-in-1b car-in-1b
2
1 0
2 3
3
0 0 2 1
0 3 2 3
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1b car-in-1b car-out-1a
2
1 0
3 3
3
0 0 2 1
0 2 3 0
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1b car-in-1b car-out-1b
1
1 0
4
0 0 2 1
0 2 3 1
0 3 0 3
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1b car-out-1a car-in-1a
0
5
0 0 2 1
0 1 0 1
0 2 0 2
0 3 1 3
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1b car-out-1a car-in-1b
0
5
0 0 2 1
0 1 0 1
0 2 0 3
0 3 2 3
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1b car-out-1a car-out-1a
2
2 0
3 3
3
0 0 2 1
0 1 0 1
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1b car-out-1a car-out-1b
0
5
0 0 2 1
0 1 0 1
0 2 0 1
0 3 0 3
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1b car-out-1b car-in-1a
0
5
0 0 2 1
0 1 0 2
0 2 1 2
0 3 1 3
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1b car-out-1b car-in-1b
0
5
0 0 2 1
0 1 0 2
0 2 1 3
0 3 2 3
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1b car-out-1b car-out-1a
1
3 3
4
0 0 2 1
0 1 0 2
0 2 1 0
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1b car-out-1b car-out-1b
1
2 1
4
0 0 2 1
0 1 0 2
0 3 0 3
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1a car-in-1a car-in-1a
2
0 2
2 2
3
0 1 1 3
0 3 1 3
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1a car-in-1a car-in-1b
1
0 2
4
0 1 1 3
0 2 2 3
0 3 2 3
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1a car-in-1a car-out-1a
2
0 2
3 3
3
0 1 1 3
0 2 2 0
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1a car-in-1a car-out-1b
1
0 2
4
0 1 1 3
0 2 2 1
0 3 0 3
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1a car-in-1b car-in-1a
1
0 2
4
0 1 1 0
0 2 3 2
0 3 1 3
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1a car-in-1b car-in-1b
2
0 2
2 3
3
0 1 1 0
0 3 2 3
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1a car-in-1b car-out-1a
2
0 2
3 3
3
0 1 1 0
0 2 3 0
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1a car-in-1b car-out-1b
1
0 2
4
0 1 1 0
0 2 3 1
0 3 0 3
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1a car-out-1a car-in-1a
2
0 2
1 1
3
0 2 0 2
0 3 1 3
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1a car-out-1a car-in-1b
2
0 2
1 1
3
0 2 0 3
0 3 2 3
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1a car-out-1a car-out-1a
4
0 2
1 1
2 0
3 3
1
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1a car-out-1a car-out-1b
2
0 2
1 1
3
0 2 0 1
0 3 0 3
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1a car-out-1b car-in-1a
1
0 2
4
0 1 1 2
0 2 1 2
0 3 1 3
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1a car-out-1b car-in-1b
1
0 2
4
0 1 1 2
0 2 1 3
0 3 2 3
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1a car-out-1b car-out-1a
2
0 2
3 3
3
0 1 1 2
0 2 1 0
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1a car-out-1b car-out-1b
2
0 2
2 1
3
0 1 1 2
0 3 0 3
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1b car-in-1a car-in-1a
1
2 2
4
0 0 2 3
0 1 2 3
0 3 1 3
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1b car-in-1a car-in-1b
0
5
0 0 2 3
0 1 2 3
0 2 2 3
0 3 2 3
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1b car-in-1a car-out-1a
1
3 3
4
0 0 2 3
0 1 2 3
0 2 2 0
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1b car-in-1a car-out-1b
0
5
0 0 2 3
0 1 2 3
0 2 2 1
0 3 0 3
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1b car-in-1b car-in-1a
0
5
0 0 2 3
0 1 2 0
0 2 3 2
0 3 1 3
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1b car-in-1b car-in-1b
1
2 3
4
0 0 2 3
0 1 2 0
0 3 2 3
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1b car-in-1b car-out-1a
1
3 3
4
0 0 2 3
0 1 2 0
0 2 3 0
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1b car-in-1b car-out-1b
0
5
0 0 2 3
0 1 2 0
0 2 3 1
0 3 0 3
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1b car-out-1a car-in-1a
0
5
0 0 2 3
0 1 2 1
0 2 0 2
0 3 1 3
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1b car-out-1a car-in-1b
0
5
0 0 2 3
0 1 2 1
0 2 0 3
0 3 2 3
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1b car-out-1a car-out-1a
2
2 0
3 3
3
0 0 2 3
0 1 2 1
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1b car-out-1a car-out-1b
0
5
0 0 2 3
0 1 2 1
0 2 0 1
0 3 0 3
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1b car-out-1b car-in-1a
1
1 2
4
0 0 2 3
0 2 1 2
0 3 1 3
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1b car-out-1b car-in-1b
1
1 2
4
0 0 2 3
0 2 1 3
0 3 2 3
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1b car-out-1b car-out-1a
2
1 2
3 3
3
0 0 2 3
0 2 1 0
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1b car-out-1b car-out-1b
2
1 2
2 1
3
0 0 2 3
0 3 0 3
0 6 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1a car-in-1a car-in-1a
2
1 3
2 2
3
0 0 3 0
0 3 1 0
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1a car-in-1a car-in-1b
1
1 3
4
0 0 3 0
0 2 2 3
0 3 2 0
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1a car-in-1a car-out-1a
1
1 3
4
0 0 3 0
0 2 2 0
0 3 3 0
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1a car-in-1a car-out-1b
2
1 3
3 0
3
0 0 3 0
0 2 2 1
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1a car-in-1b car-in-1a
0
5
0 0 3 0
0 1 3 0
0 2 3 2
0 3 1 0
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1a car-in-1b car-in-1b
1
2 3
4
0 0 3 0
0 1 3 0
0 3 2 0
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1a car-in-1b car-out-1a
0
5
0 0 3 0
0 1 3 0
0 2 3 0
0 3 3 0
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1a car-in-1b car-out-1b
1
3 0
4
0 0 3 0
0 1 3 0
0 2 3 1
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1a car-out-1a car-in-1a
0
5
0 0 3 0
0 1 3 1
0 2 0 2
0 3 1 0
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1a car-out-1a car-in-1b
0
5
0 0 3 0
0 1 3 1
0 2 0 3
0 3 2 0
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1a car-out-1a car-out-1a
1
2 0
4
0 0 3 0
0 1 3 1
0 3 3 0
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1a car-out-1a car-out-1b
1
3 0
4
0 0 3 0
0 1 3 1
0 2 0 1
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1a car-out-1b car-in-1a
0
5
0 0 3 0
0 1 3 2
0 2 1 2
0 3 1 0
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1a car-out-1b car-in-1b
0
5
0 0 3 0
0 1 3 2
0 2 1 3
0 3 2 0
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1a car-out-1b car-out-1a
0
5
0 0 3 0
0 1 3 2
0 2 1 0
0 3 3 0
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1a car-out-1b car-out-1b
2
2 1
3 0
3
0 0 3 0
0 1 3 2
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1b car-in-1a car-in-1a
1
2 2
4
0 0 3 1
0 1 0 3
0 3 1 0
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1b car-in-1a car-in-1b
0
5
0 0 3 1
0 1 0 3
0 2 2 3
0 3 2 0
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1b car-in-1a car-out-1a
0
5
0 0 3 1
0 1 0 3
0 2 2 0
0 3 3 0
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1b car-in-1a car-out-1b
1
3 0
4
0 0 3 1
0 1 0 3
0 2 2 1
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1b car-in-1b car-in-1a
1
1 0
4
0 0 3 1
0 2 3 2
0 3 1 0
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1b car-in-1b car-in-1b
2
1 0
2 3
3
0 0 3 1
0 3 2 0
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1b car-in-1b car-out-1a
1
1 0
4
0 0 3 1
0 2 3 0
0 3 3 0
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1b car-in-1b car-out-1b
2
1 0
3 0
3
0 0 3 1
0 2 3 1
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1b car-out-1a car-in-1a
0
5
0 0 3 1
0 1 0 1
0 2 0 2
0 3 1 0
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1b car-out-1a car-in-1b
0
5
0 0 3 1
0 1 0 1
0 2 0 3
0 3 2 0
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1b car-out-1a car-out-1a
1
2 0
4
0 0 3 1
0 1 0 1
0 3 3 0
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1b car-out-1a car-out-1b
1
3 0
4
0 0 3 1
0 1 0 1
0 2 0 1
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1b car-out-1b car-in-1a
0
5
0 0 3 1
0 1 0 2
0 2 1 2
0 3 1 0
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1b car-out-1b car-in-1b
0
5
0 0 3 1
0 1 0 2
0 2 1 3
0 3 2 0
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1b car-out-1b car-out-1a
0
5
0 0 3 1
0 1 0 2
0 2 1 0
0 3 3 0
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1b car-out-1b car-out-1b
2
2 1
3 0
3
0 0 3 1
0 1 0 2
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1a car-in-1a car-in-1a
1
2 2
4
0 0 3 2
0 1 1 3
0 3 1 0
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1a car-in-1a car-in-1b
0
5
0 0 3 2
0 1 1 3
0 2 2 3
0 3 2 0
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1a car-in-1a car-out-1a
0
5
0 0 3 2
0 1 1 3
0 2 2 0
0 3 3 0
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1a car-in-1a car-out-1b
1
3 0
4
0 0 3 2
0 1 1 3
0 2 2 1
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1a car-in-1b car-in-1a
0
5
0 0 3 2
0 1 1 0
0 2 3 2
0 3 1 0
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1a car-in-1b car-in-1b
1
2 3
4
0 0 3 2
0 1 1 0
0 3 2 0
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1a car-in-1b car-out-1a
0
5
0 0 3 2
0 1 1 0
0 2 3 0
0 3 3 0
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1a car-in-1b car-out-1b
1
3 0
4
0 0 3 2
0 1 1 0
0 2 3 1
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1a car-out-1a car-in-1a
1
1 1
4
0 0 3 2
0 2 0 2
0 3 1 0
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1a car-out-1a car-in-1b
1
1 1
4
0 0 3 2
0 2 0 3
0 3 2 0
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1a car-out-1a car-out-1a
2
1 1
2 0
3
0 0 3 2
0 3 3 0
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1a car-out-1a car-out-1b
2
1 1
3 0
3
0 0 3 2
0 2 0 1
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1a car-out-1b car-in-1a
0
5
0 0 3 2
0 1 1 2
0 2 1 2
0 3 1 0
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1a car-out-1b car-in-1b
0
5
0 0 3 2
0 1 1 2
0 2 1 3
0 3 2 0
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1a car-out-1b car-out-1a
0
5
0 0 3 2
0 1 1 2
0 2 1 0
0 3 3 0
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1a car-out-1b car-out-1b
2
2 1
3 0
3
0 0 3 2
0 1 1 2
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1b car-in-1a car-in-1a
2
0 3
2 2
3
0 1 2 3
0 3 1 0
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1b car-in-1a car-in-1b
1
0 3
4
0 1 2 3
0 2 2 3
0 3 2 0
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1b car-in-1a car-out-1a
1
0 3
4
0 1 2 3
0 2 2 0
0 3 3 0
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1b car-in-1a car-out-1b
2
0 3
3 0
3
0 1 2 3
0 2 2 1
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1b car-in-1b car-in-1a
1
0 3
4
0 1 2 0
0 2 3 2
0 3 1 0
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1b car-in-1b car-in-1b
2
0 3
2 3
3
0 1 2 0
0 3 2 0
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1b car-in-1b car-out-1a
1
0 3
4
0 1 2 0
0 2 3 0
0 3 3 0
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1b car-in-1b car-out-1b
2
0 3
3 0
3
0 1 2 0
0 2 3 1
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1b car-out-1a car-in-1a
1
0 3
4
0 1 2 1
0 2 0 2
0 3 1 0
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1b car-out-1a car-in-1b
1
0 3
4
0 1 2 1
0 2 0 3
0 3 2 0
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1b car-out-1a car-out-1a
2
0 3
2 0
3
0 1 2 1
0 3 3 0
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1b car-out-1a car-out-1b
2
0 3
3 0
3
0 1 2 1
0 2 0 1
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1b car-out-1b car-in-1a
2
0 3
1 2
3
0 2 1 2
0 3 1 0
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1b car-out-1b car-in-1b
2
0 3
1 2
3
0 2 1 3
0 3 2 0
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1b car-out-1b car-out-1a
2
0 3
1 2
3
0 2 1 0
0 3 3 0
0 7 -1 0
3
end_operator
begin_operator
analyze-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1b car-out-1b car-out-1b
4
0 3
1 2
2 1
3 0
1
0 7 -1 0
3
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1a car-in-1a car-in-1b
2
0 0
1 3
2
0 2 2 3
0 3 2 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1a car-in-1a car-out-1a
2
0 0
1 3
2
0 2 2 0
0 3 3 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1a car-in-1a car-out-1b
2
0 0
1 3
2
0 2 2 1
0 3 0 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1a car-in-1b car-in-1a
2
0 0
3 1
2
0 1 3 0
0 2 3 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1a car-in-1b car-in-1b
2
0 0
2 3
2
0 1 3 0
0 3 2 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1a car-in-1b car-out-1a
1
0 0
3
0 1 3 0
0 2 3 0
0 3 3 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1a car-in-1b car-out-1b
1
0 0
3
0 1 3 0
0 2 3 1
0 3 0 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1a car-out-1a car-in-1a
2
0 0
3 1
2
0 1 3 1
0 2 0 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1a car-out-1a car-in-1b
1
0 0
3
0 1 3 1
0 2 0 3
0 3 2 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1a car-out-1a car-out-1a
2
0 0
2 0
2
0 1 3 1
0 3 3 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1a car-out-1a car-out-1b
1
0 0
3
0 1 3 1
0 2 0 1
0 3 0 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1a car-out-1b car-in-1a
2
0 0
3 1
2
0 1 3 2
0 2 1 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1a car-out-1b car-in-1b
1
0 0
3
0 1 3 2
0 2 1 3
0 3 2 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1a car-out-1b car-out-1a
1
0 0
3
0 1 3 2
0 2 1 0
0 3 3 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1a car-out-1b car-out-1b
2
0 0
2 1
2
0 1 3 2
0 3 0 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1b car-in-1a car-in-1a
2
2 2
3 1
2
0 0 0 1
0 1 0 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1b car-in-1a car-in-1b
0
4
0 0 0 1
0 1 0 3
0 2 2 3
0 3 2 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1b car-in-1a car-out-1a
0
4
0 0 0 1
0 1 0 3
0 2 2 0
0 3 3 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1b car-in-1a car-out-1b
0
4
0 0 0 1
0 1 0 3
0 2 2 1
0 3 0 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1b car-in-1b car-in-1a
2
1 0
3 1
2
0 0 0 1
0 2 3 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1b car-in-1b car-in-1b
2
1 0
2 3
2
0 0 0 1
0 3 2 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1b car-in-1b car-out-1a
1
1 0
3
0 0 0 1
0 2 3 0
0 3 3 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1b car-in-1b car-out-1b
1
1 0
3
0 0 0 1
0 2 3 1
0 3 0 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1b car-out-1a car-in-1a
1
3 1
3
0 0 0 1
0 1 0 1
0 2 0 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1b car-out-1a car-in-1b
0
4
0 0 0 1
0 1 0 1
0 2 0 3
0 3 2 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1b car-out-1a car-out-1a
1
2 0
3
0 0 0 1
0 1 0 1
0 3 3 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1b car-out-1a car-out-1b
0
4
0 0 0 1
0 1 0 1
0 2 0 1
0 3 0 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1b car-out-1b car-in-1a
1
3 1
3
0 0 0 1
0 1 0 2
0 2 1 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1b car-out-1b car-in-1b
0
4
0 0 0 1
0 1 0 2
0 2 1 3
0 3 2 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1b car-out-1b car-out-1a
0
4
0 0 0 1
0 1 0 2
0 2 1 0
0 3 3 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-in-1b car-out-1b car-out-1b
1
2 1
3
0 0 0 1
0 1 0 2
0 3 0 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1a car-in-1a car-in-1a
2
2 2
3 1
2
0 0 0 2
0 1 1 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1a car-in-1a car-in-1b
0
4
0 0 0 2
0 1 1 3
0 2 2 3
0 3 2 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1a car-in-1a car-out-1a
0
4
0 0 0 2
0 1 1 3
0 2 2 0
0 3 3 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1a car-in-1a car-out-1b
0
4
0 0 0 2
0 1 1 3
0 2 2 1
0 3 0 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1a car-in-1b car-in-1a
1
3 1
3
0 0 0 2
0 1 1 0
0 2 3 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1a car-in-1b car-in-1b
1
2 3
3
0 0 0 2
0 1 1 0
0 3 2 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1a car-in-1b car-out-1a
0
4
0 0 0 2
0 1 1 0
0 2 3 0
0 3 3 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1a car-in-1b car-out-1b
0
4
0 0 0 2
0 1 1 0
0 2 3 1
0 3 0 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1a car-out-1a car-in-1a
2
1 1
3 1
2
0 0 0 2
0 2 0 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1a car-out-1a car-in-1b
1
1 1
3
0 0 0 2
0 2 0 3
0 3 2 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1a car-out-1a car-out-1a
2
1 1
2 0
2
0 0 0 2
0 3 3 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1a car-out-1a car-out-1b
1
1 1
3
0 0 0 2
0 2 0 1
0 3 0 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1a car-out-1b car-in-1a
1
3 1
3
0 0 0 2
0 1 1 2
0 2 1 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1a car-out-1b car-in-1b
0
4
0 0 0 2
0 1 1 2
0 2 1 3
0 3 2 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1a car-out-1b car-out-1a
0
4
0 0 0 2
0 1 1 2
0 2 1 0
0 3 3 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1a car-out-1b car-out-1b
1
2 1
3
0 0 0 2
0 1 1 2
0 3 0 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1b car-in-1a car-in-1a
2
2 2
3 1
2
0 0 0 3
0 1 2 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1b car-in-1a car-in-1b
0
4
0 0 0 3
0 1 2 3
0 2 2 3
0 3 2 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1b car-in-1a car-out-1a
0
4
0 0 0 3
0 1 2 3
0 2 2 0
0 3 3 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1b car-in-1a car-out-1b
0
4
0 0 0 3
0 1 2 3
0 2 2 1
0 3 0 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1b car-in-1b car-in-1a
1
3 1
3
0 0 0 3
0 1 2 0
0 2 3 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1b car-in-1b car-in-1b
1
2 3
3
0 0 0 3
0 1 2 0
0 3 2 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1b car-in-1b car-out-1a
0
4
0 0 0 3
0 1 2 0
0 2 3 0
0 3 3 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1b car-in-1b car-out-1b
0
4
0 0 0 3
0 1 2 0
0 2 3 1
0 3 0 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1b car-out-1a car-in-1a
1
3 1
3
0 0 0 3
0 1 2 1
0 2 0 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1b car-out-1a car-in-1b
0
4
0 0 0 3
0 1 2 1
0 2 0 3
0 3 2 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1b car-out-1a car-out-1a
1
2 0
3
0 0 0 3
0 1 2 1
0 3 3 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1b car-out-1a car-out-1b
0
4
0 0 0 3
0 1 2 1
0 2 0 1
0 3 0 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1b car-out-1b car-in-1a
2
1 2
3 1
2
0 0 0 3
0 2 1 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1b car-out-1b car-in-1b
1
1 2
3
0 0 0 3
0 2 1 3
0 3 2 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1b car-out-1b car-out-1a
1
1 2
3
0 0 0 3
0 2 1 0
0 3 3 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1a car-out-1b car-out-1b car-out-1b
2
1 2
2 1
2
0 0 0 3
0 3 0 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1a car-in-1a car-in-1a
2
1 3
2 2
2
0 0 1 0
0 3 1 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1a car-in-1a car-in-1b
2
1 3
3 2
2
0 0 1 0
0 2 2 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1a car-in-1a car-out-1a
1
1 3
3
0 0 1 0
0 2 2 0
0 3 3 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1a car-in-1a car-out-1b
1
1 3
3
0 0 1 0
0 2 2 1
0 3 0 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1a car-in-1b car-in-1a
0
4
0 0 1 0
0 1 3 0
0 2 3 2
0 3 1 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1a car-in-1b car-in-1b
2
2 3
3 2
2
0 0 1 0
0 1 3 0
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1a car-in-1b car-out-1a
0
4
0 0 1 0
0 1 3 0
0 2 3 0
0 3 3 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1a car-in-1b car-out-1b
0
4
0 0 1 0
0 1 3 0
0 2 3 1
0 3 0 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1a car-out-1a car-in-1a
0
4
0 0 1 0
0 1 3 1
0 2 0 2
0 3 1 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1a car-out-1a car-in-1b
1
3 2
3
0 0 1 0
0 1 3 1
0 2 0 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1a car-out-1a car-out-1a
1
2 0
3
0 0 1 0
0 1 3 1
0 3 3 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1a car-out-1a car-out-1b
0
4
0 0 1 0
0 1 3 1
0 2 0 1
0 3 0 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1a car-out-1b car-in-1a
0
4
0 0 1 0
0 1 3 2
0 2 1 2
0 3 1 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1a car-out-1b car-in-1b
1
3 2
3
0 0 1 0
0 1 3 2
0 2 1 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1a car-out-1b car-out-1a
0
4
0 0 1 0
0 1 3 2
0 2 1 0
0 3 3 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1a car-out-1b car-out-1b
1
2 1
3
0 0 1 0
0 1 3 2
0 3 0 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1b car-in-1a car-in-1a
2
0 1
2 2
2
0 1 0 3
0 3 1 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1b car-in-1a car-in-1b
2
0 1
3 2
2
0 1 0 3
0 2 2 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1b car-in-1a car-out-1a
1
0 1
3
0 1 0 3
0 2 2 0
0 3 3 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1b car-in-1a car-out-1b
1
0 1
3
0 1 0 3
0 2 2 1
0 3 0 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1b car-in-1b car-in-1a
2
0 1
1 0
2
0 2 3 2
0 3 1 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1b car-in-1b car-out-1a
2
0 1
1 0
2
0 2 3 0
0 3 3 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1b car-in-1b car-out-1b
2
0 1
1 0
2
0 2 3 1
0 3 0 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1b car-out-1a car-in-1a
1
0 1
3
0 1 0 1
0 2 0 2
0 3 1 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1b car-out-1a car-in-1b
2
0 1
3 2
2
0 1 0 1
0 2 0 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1b car-out-1a car-out-1a
2
0 1
2 0
2
0 1 0 1
0 3 3 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1b car-out-1a car-out-1b
1
0 1
3
0 1 0 1
0 2 0 1
0 3 0 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1b car-out-1b car-in-1a
1
0 1
3
0 1 0 2
0 2 1 2
0 3 1 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1b car-out-1b car-in-1b
2
0 1
3 2
2
0 1 0 2
0 2 1 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1b car-out-1b car-out-1a
1
0 1
3
0 1 0 2
0 2 1 0
0 3 3 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-in-1b car-out-1b car-out-1b
2
0 1
2 1
2
0 1 0 2
0 3 0 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1a car-in-1a car-in-1a
1
2 2
3
0 0 1 2
0 1 1 3
0 3 1 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1a car-in-1a car-in-1b
1
3 2
3
0 0 1 2
0 1 1 3
0 2 2 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1a car-in-1a car-out-1a
0
4
0 0 1 2
0 1 1 3
0 2 2 0
0 3 3 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1a car-in-1a car-out-1b
0
4
0 0 1 2
0 1 1 3
0 2 2 1
0 3 0 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1a car-in-1b car-in-1a
0
4
0 0 1 2
0 1 1 0
0 2 3 2
0 3 1 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1a car-in-1b car-in-1b
2
2 3
3 2
2
0 0 1 2
0 1 1 0
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1a car-in-1b car-out-1a
0
4
0 0 1 2
0 1 1 0
0 2 3 0
0 3 3 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1a car-in-1b car-out-1b
0
4
0 0 1 2
0 1 1 0
0 2 3 1
0 3 0 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1a car-out-1a car-in-1a
1
1 1
3
0 0 1 2
0 2 0 2
0 3 1 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1a car-out-1a car-in-1b
2
1 1
3 2
2
0 0 1 2
0 2 0 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1a car-out-1a car-out-1a
2
1 1
2 0
2
0 0 1 2
0 3 3 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1a car-out-1a car-out-1b
1
1 1
3
0 0 1 2
0 2 0 1
0 3 0 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1a car-out-1b car-in-1a
0
4
0 0 1 2
0 1 1 2
0 2 1 2
0 3 1 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1a car-out-1b car-in-1b
1
3 2
3
0 0 1 2
0 1 1 2
0 2 1 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1a car-out-1b car-out-1a
0
4
0 0 1 2
0 1 1 2
0 2 1 0
0 3 3 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1a car-out-1b car-out-1b
1
2 1
3
0 0 1 2
0 1 1 2
0 3 0 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1b car-in-1a car-in-1a
1
2 2
3
0 0 1 3
0 1 2 3
0 3 1 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1b car-in-1a car-in-1b
1
3 2
3
0 0 1 3
0 1 2 3
0 2 2 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1b car-in-1a car-out-1a
0
4
0 0 1 3
0 1 2 3
0 2 2 0
0 3 3 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1b car-in-1a car-out-1b
0
4
0 0 1 3
0 1 2 3
0 2 2 1
0 3 0 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1b car-in-1b car-in-1a
0
4
0 0 1 3
0 1 2 0
0 2 3 2
0 3 1 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1b car-in-1b car-in-1b
2
2 3
3 2
2
0 0 1 3
0 1 2 0
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1b car-in-1b car-out-1a
0
4
0 0 1 3
0 1 2 0
0 2 3 0
0 3 3 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1b car-in-1b car-out-1b
0
4
0 0 1 3
0 1 2 0
0 2 3 1
0 3 0 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1b car-out-1a car-in-1a
0
4
0 0 1 3
0 1 2 1
0 2 0 2
0 3 1 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1b car-out-1a car-in-1b
1
3 2
3
0 0 1 3
0 1 2 1
0 2 0 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1b car-out-1a car-out-1a
1
2 0
3
0 0 1 3
0 1 2 1
0 3 3 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1b car-out-1a car-out-1b
0
4
0 0 1 3
0 1 2 1
0 2 0 1
0 3 0 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1b car-out-1b car-in-1a
1
1 2
3
0 0 1 3
0 2 1 2
0 3 1 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1b car-out-1b car-in-1b
2
1 2
3 2
2
0 0 1 3
0 2 1 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1b car-out-1b car-out-1a
1
1 2
3
0 0 1 3
0 2 1 0
0 3 3 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-in-1b car-out-1b car-out-1b car-out-1b
2
1 2
2 1
2
0 0 1 3
0 3 0 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1a car-in-1a car-in-1a
2
1 3
2 2
2
0 0 2 0
0 3 1 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1a car-in-1a car-in-1b
1
1 3
3
0 0 2 0
0 2 2 3
0 3 2 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1a car-in-1a car-out-1a
2
1 3
3 3
2
0 0 2 0
0 2 2 0
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1a car-in-1a car-out-1b
1
1 3
3
0 0 2 0
0 2 2 1
0 3 0 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1a car-in-1b car-in-1a
0
4
0 0 2 0
0 1 3 0
0 2 3 2
0 3 1 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1a car-in-1b car-in-1b
1
2 3
3
0 0 2 0
0 1 3 0
0 3 2 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1a car-in-1b car-out-1a
1
3 3
3
0 0 2 0
0 1 3 0
0 2 3 0
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1a car-in-1b car-out-1b
0
4
0 0 2 0
0 1 3 0
0 2 3 1
0 3 0 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1a car-out-1a car-in-1a
0
4
0 0 2 0
0 1 3 1
0 2 0 2
0 3 1 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1a car-out-1a car-in-1b
0
4
0 0 2 0
0 1 3 1
0 2 0 3
0 3 2 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1a car-out-1a car-out-1a
2
2 0
3 3
2
0 0 2 0
0 1 3 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1a car-out-1a car-out-1b
0
4
0 0 2 0
0 1 3 1
0 2 0 1
0 3 0 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1a car-out-1b car-in-1a
0
4
0 0 2 0
0 1 3 2
0 2 1 2
0 3 1 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1a car-out-1b car-in-1b
0
4
0 0 2 0
0 1 3 2
0 2 1 3
0 3 2 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1a car-out-1b car-out-1a
1
3 3
3
0 0 2 0
0 1 3 2
0 2 1 0
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1a car-out-1b car-out-1b
1
2 1
3
0 0 2 0
0 1 3 2
0 3 0 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1b car-in-1a car-in-1a
1
2 2
3
0 0 2 1
0 1 0 3
0 3 1 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1b car-in-1a car-in-1b
0
4
0 0 2 1
0 1 0 3
0 2 2 3
0 3 2 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1b car-in-1a car-out-1a
1
3 3
3
0 0 2 1
0 1 0 3
0 2 2 0
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1b car-in-1a car-out-1b
0
4
0 0 2 1
0 1 0 3
0 2 2 1
0 3 0 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1b car-in-1b car-in-1a
1
1 0
3
0 0 2 1
0 2 3 2
0 3 1 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1b car-in-1b car-in-1b
2
1 0
2 3
2
0 0 2 1
0 3 2 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1b car-in-1b car-out-1a
2
1 0
3 3
2
0 0 2 1
0 2 3 0
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1b car-in-1b car-out-1b
1
1 0
3
0 0 2 1
0 2 3 1
0 3 0 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1b car-out-1a car-in-1a
0
4
0 0 2 1
0 1 0 1
0 2 0 2
0 3 1 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1b car-out-1a car-in-1b
0
4
0 0 2 1
0 1 0 1
0 2 0 3
0 3 2 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1b car-out-1a car-out-1a
2
2 0
3 3
2
0 0 2 1
0 1 0 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1b car-out-1a car-out-1b
0
4
0 0 2 1
0 1 0 1
0 2 0 1
0 3 0 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1b car-out-1b car-in-1a
0
4
0 0 2 1
0 1 0 2
0 2 1 2
0 3 1 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1b car-out-1b car-in-1b
0
4
0 0 2 1
0 1 0 2
0 2 1 3
0 3 2 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1b car-out-1b car-out-1a
1
3 3
3
0 0 2 1
0 1 0 2
0 2 1 0
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-in-1b car-out-1b car-out-1b
1
2 1
3
0 0 2 1
0 1 0 2
0 3 0 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1a car-in-1a car-in-1a
2
0 2
2 2
2
0 1 1 3
0 3 1 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1a car-in-1a car-in-1b
1
0 2
3
0 1 1 3
0 2 2 3
0 3 2 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1a car-in-1a car-out-1a
2
0 2
3 3
2
0 1 1 3
0 2 2 0
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1a car-in-1a car-out-1b
1
0 2
3
0 1 1 3
0 2 2 1
0 3 0 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1a car-in-1b car-in-1a
1
0 2
3
0 1 1 0
0 2 3 2
0 3 1 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1a car-in-1b car-in-1b
2
0 2
2 3
2
0 1 1 0
0 3 2 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1a car-in-1b car-out-1a
2
0 2
3 3
2
0 1 1 0
0 2 3 0
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1a car-in-1b car-out-1b
1
0 2
3
0 1 1 0
0 2 3 1
0 3 0 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1a car-out-1a car-in-1a
2
0 2
1 1
2
0 2 0 2
0 3 1 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1a car-out-1a car-in-1b
2
0 2
1 1
2
0 2 0 3
0 3 2 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1a car-out-1a car-out-1b
2
0 2
1 1
2
0 2 0 1
0 3 0 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1a car-out-1b car-in-1a
1
0 2
3
0 1 1 2
0 2 1 2
0 3 1 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1a car-out-1b car-in-1b
1
0 2
3
0 1 1 2
0 2 1 3
0 3 2 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1a car-out-1b car-out-1a
2
0 2
3 3
2
0 1 1 2
0 2 1 0
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1a car-out-1b car-out-1b
2
0 2
2 1
2
0 1 1 2
0 3 0 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1b car-in-1a car-in-1a
1
2 2
3
0 0 2 3
0 1 2 3
0 3 1 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1b car-in-1a car-in-1b
0
4
0 0 2 3
0 1 2 3
0 2 2 3
0 3 2 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1b car-in-1a car-out-1a
1
3 3
3
0 0 2 3
0 1 2 3
0 2 2 0
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1b car-in-1a car-out-1b
0
4
0 0 2 3
0 1 2 3
0 2 2 1
0 3 0 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1b car-in-1b car-in-1a
0
4
0 0 2 3
0 1 2 0
0 2 3 2
0 3 1 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1b car-in-1b car-in-1b
1
2 3
3
0 0 2 3
0 1 2 0
0 3 2 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1b car-in-1b car-out-1a
1
3 3
3
0 0 2 3
0 1 2 0
0 2 3 0
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1b car-in-1b car-out-1b
0
4
0 0 2 3
0 1 2 0
0 2 3 1
0 3 0 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1b car-out-1a car-in-1a
0
4
0 0 2 3
0 1 2 1
0 2 0 2
0 3 1 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1b car-out-1a car-in-1b
0
4
0 0 2 3
0 1 2 1
0 2 0 3
0 3 2 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1b car-out-1a car-out-1a
2
2 0
3 3
2
0 0 2 3
0 1 2 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1b car-out-1a car-out-1b
0
4
0 0 2 3
0 1 2 1
0 2 0 1
0 3 0 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1b car-out-1b car-in-1a
1
1 2
3
0 0 2 3
0 2 1 2
0 3 1 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1b car-out-1b car-in-1b
1
1 2
3
0 0 2 3
0 2 1 3
0 3 2 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1b car-out-1b car-out-1a
2
1 2
3 3
2
0 0 2 3
0 2 1 0
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1a car-out-1b car-out-1b car-out-1b
2
1 2
2 1
2
0 0 2 3
0 3 0 3
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1a car-in-1a car-in-1a
2
1 3
2 2
2
0 0 3 0
0 3 1 0
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1a car-in-1a car-in-1b
1
1 3
3
0 0 3 0
0 2 2 3
0 3 2 0
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1a car-in-1a car-out-1a
1
1 3
3
0 0 3 0
0 2 2 0
0 3 3 0
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1a car-in-1a car-out-1b
2
1 3
3 0
2
0 0 3 0
0 2 2 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1a car-in-1b car-in-1a
0
4
0 0 3 0
0 1 3 0
0 2 3 2
0 3 1 0
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1a car-in-1b car-in-1b
1
2 3
3
0 0 3 0
0 1 3 0
0 3 2 0
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1a car-in-1b car-out-1a
0
4
0 0 3 0
0 1 3 0
0 2 3 0
0 3 3 0
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1a car-in-1b car-out-1b
1
3 0
3
0 0 3 0
0 1 3 0
0 2 3 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1a car-out-1a car-in-1a
0
4
0 0 3 0
0 1 3 1
0 2 0 2
0 3 1 0
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1a car-out-1a car-in-1b
0
4
0 0 3 0
0 1 3 1
0 2 0 3
0 3 2 0
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1a car-out-1a car-out-1a
1
2 0
3
0 0 3 0
0 1 3 1
0 3 3 0
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1a car-out-1a car-out-1b
1
3 0
3
0 0 3 0
0 1 3 1
0 2 0 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1a car-out-1b car-in-1a
0
4
0 0 3 0
0 1 3 2
0 2 1 2
0 3 1 0
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1a car-out-1b car-in-1b
0
4
0 0 3 0
0 1 3 2
0 2 1 3
0 3 2 0
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1a car-out-1b car-out-1a
0
4
0 0 3 0
0 1 3 2
0 2 1 0
0 3 3 0
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1a car-out-1b car-out-1b
2
2 1
3 0
2
0 0 3 0
0 1 3 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1b car-in-1a car-in-1a
1
2 2
3
0 0 3 1
0 1 0 3
0 3 1 0
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1b car-in-1a car-in-1b
0
4
0 0 3 1
0 1 0 3
0 2 2 3
0 3 2 0
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1b car-in-1a car-out-1a
0
4
0 0 3 1
0 1 0 3
0 2 2 0
0 3 3 0
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1b car-in-1a car-out-1b
1
3 0
3
0 0 3 1
0 1 0 3
0 2 2 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1b car-in-1b car-in-1a
1
1 0
3
0 0 3 1
0 2 3 2
0 3 1 0
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1b car-in-1b car-in-1b
2
1 0
2 3
2
0 0 3 1
0 3 2 0
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1b car-in-1b car-out-1a
1
1 0
3
0 0 3 1
0 2 3 0
0 3 3 0
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1b car-in-1b car-out-1b
2
1 0
3 0
2
0 0 3 1
0 2 3 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1b car-out-1a car-in-1a
0
4
0 0 3 1
0 1 0 1
0 2 0 2
0 3 1 0
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1b car-out-1a car-in-1b
0
4
0 0 3 1
0 1 0 1
0 2 0 3
0 3 2 0
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1b car-out-1a car-out-1a
1
2 0
3
0 0 3 1
0 1 0 1
0 3 3 0
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1b car-out-1a car-out-1b
1
3 0
3
0 0 3 1
0 1 0 1
0 2 0 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1b car-out-1b car-in-1a
0
4
0 0 3 1
0 1 0 2
0 2 1 2
0 3 1 0
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1b car-out-1b car-in-1b
0
4
0 0 3 1
0 1 0 2
0 2 1 3
0 3 2 0
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1b car-out-1b car-out-1a
0
4
0 0 3 1
0 1 0 2
0 2 1 0
0 3 3 0
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-in-1b car-out-1b car-out-1b
2
2 1
3 0
2
0 0 3 1
0 1 0 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1a car-in-1a car-in-1a
1
2 2
3
0 0 3 2
0 1 1 3
0 3 1 0
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1a car-in-1a car-in-1b
0
4
0 0 3 2
0 1 1 3
0 2 2 3
0 3 2 0
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1a car-in-1a car-out-1a
0
4
0 0 3 2
0 1 1 3
0 2 2 0
0 3 3 0
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1a car-in-1a car-out-1b
1
3 0
3
0 0 3 2
0 1 1 3
0 2 2 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1a car-in-1b car-in-1a
0
4
0 0 3 2
0 1 1 0
0 2 3 2
0 3 1 0
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1a car-in-1b car-in-1b
1
2 3
3
0 0 3 2
0 1 1 0
0 3 2 0
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1a car-in-1b car-out-1a
0
4
0 0 3 2
0 1 1 0
0 2 3 0
0 3 3 0
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1a car-in-1b car-out-1b
1
3 0
3
0 0 3 2
0 1 1 0
0 2 3 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1a car-out-1a car-in-1a
1
1 1
3
0 0 3 2
0 2 0 2
0 3 1 0
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1a car-out-1a car-in-1b
1
1 1
3
0 0 3 2
0 2 0 3
0 3 2 0
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1a car-out-1a car-out-1a
2
1 1
2 0
2
0 0 3 2
0 3 3 0
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1a car-out-1a car-out-1b
2
1 1
3 0
2
0 0 3 2
0 2 0 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1a car-out-1b car-in-1a
0
4
0 0 3 2
0 1 1 2
0 2 1 2
0 3 1 0
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1a car-out-1b car-in-1b
0
4
0 0 3 2
0 1 1 2
0 2 1 3
0 3 2 0
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1a car-out-1b car-out-1a
0
4
0 0 3 2
0 1 1 2
0 2 1 0
0 3 3 0
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1a car-out-1b car-out-1b
2
2 1
3 0
2
0 0 3 2
0 1 1 2
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1b car-in-1a car-in-1a
2
0 3
2 2
2
0 1 2 3
0 3 1 0
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1b car-in-1a car-in-1b
1
0 3
3
0 1 2 3
0 2 2 3
0 3 2 0
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1b car-in-1a car-out-1a
1
0 3
3
0 1 2 3
0 2 2 0
0 3 3 0
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1b car-in-1a car-out-1b
2
0 3
3 0
2
0 1 2 3
0 2 2 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1b car-in-1b car-in-1a
1
0 3
3
0 1 2 0
0 2 3 2
0 3 1 0
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1b car-in-1b car-in-1b
2
0 3
2 3
2
0 1 2 0
0 3 2 0
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1b car-in-1b car-out-1a
1
0 3
3
0 1 2 0
0 2 3 0
0 3 3 0
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1b car-in-1b car-out-1b
2
0 3
3 0
2
0 1 2 0
0 2 3 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1b car-out-1a car-in-1a
1
0 3
3
0 1 2 1
0 2 0 2
0 3 1 0
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1b car-out-1a car-in-1b
1
0 3
3
0 1 2 1
0 2 0 3
0 3 2 0
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1b car-out-1a car-out-1a
2
0 3
2 0
2
0 1 2 1
0 3 3 0
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1b car-out-1a car-out-1b
2
0 3
3 0
2
0 1 2 1
0 2 0 1
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1b car-out-1b car-in-1a
2
0 3
1 2
2
0 2 1 2
0 3 1 0
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1b car-out-1b car-in-1b
2
0 3
1 2
2
0 2 1 3
0 3 2 0
1
end_operator
begin_operator
rotate-4 seg-in-1a seg-in-1b seg-out-1a seg-out-1b car-out-1b car-out-1b car-out-1b car-out-1a
2
0 3
1 2
2
0 2 1 0
0 3 3 0
1
end_operator
0
