begin_version
3
end_version
begin_metric
0
end_metric
12
begin_variable
var0
-1
7
Atom on(crate0, container-0-0)
Atom lifting(hoist0, crate0)
Atom on(crate0, depot0-1-2)
Atom on(crate0, depot0-1-1)
Atom on(crate0, depot0-1-3)
Atom lifting(hoist1, crate0)
Atom lifting(hoist2, crate0)
end_variable
begin_variable
var1
-1
5
Atom at(hoist0, depot0-1-2)
Atom at(hoist0, loadarea)
Atom at(hoist0, container-0-0)
Atom at(hoist0, depot0-1-1)
Atom at(hoist0, depot0-1-3)
end_variable
begin_variable
var2
-1
5
Atom at(hoist1, depot0-1-3)
Atom at(hoist1, depot0-1-2)
Atom at(hoist1, depot0-1-1)
Atom at(hoist1, loadarea)
Atom at(hoist1, container-0-0)
end_variable
begin_variable
var3
-1
5
Atom at(hoist2, depot0-1-1)
Atom at(hoist2, depot0-1-2)
Atom at(hoist2, loadarea)
Atom at(hoist2, depot0-1-3)
Atom at(hoist2, container-0-0)
end_variable
begin_variable
var4
-1
2
Atom available(hoist0)
NegatedAtom available(hoist0)
end_variable
begin_variable
var5
-1
2
Atom available(hoist1)
NegatedAtom available(hoist1)
end_variable
begin_variable
var6
-1
2
Atom available(hoist2)
NegatedAtom available(hoist2)
end_variable
begin_variable
var7
-1
2
Atom clear(depot0-1-2)
NegatedAtom clear(depot0-1-2)
end_variable
begin_variable
var8
-1
2
Atom clear(container-0-0)
NegatedAtom clear(container-0-0)
end_variable
begin_variable
var9
-1
2
Atom clear(depot0-1-1)
NegatedAtom clear(depot0-1-1)
end_variable
begin_variable
var10
-1
2
Atom clear(depot0-1-3)
NegatedAtom clear(depot0-1-3)
end_variable
begin_variable
var11
-1
2
Atom in(crate0, depot0)
NegatedAtom in(crate0, depot0)
end_variable
7
begin_mutex_group
5
1 0
1 1
1 2
1 3
1 4
end_mutex_group
begin_mutex_group
5
2 0
2 1
2 2
2 3
2 4
end_mutex_group
begin_mutex_group
5
3 0
3 1
3 2
3 3
3 4
end_mutex_group
begin_mutex_group
2
4 0
0 1
end_mutex_group
begin_mutex_group
2
5 0
0 5
end_mutex_group
begin_mutex_group
2
6 0
0 6
end_mutex_group
begin_mutex_group
7
0 0
0 1
0 2
0 3
0 4
0 5
0 6
end_mutex_group
begin_state
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
1
end_state
begin_goal
1
11 0
end_goal
60
begin_operator
lift hoist0 crate0 depot0-1-1 depot0-1-2 depot0
1
1 0
4
0 0 3 1
0 4 0 1
0 9 -1 0
0 11 -1 1
0
end_operator
begin_operator
lift hoist0 crate0 depot0-1-2 depot0-1-1 depot0
1
1 3
4
0 0 2 1
0 4 0 1
0 7 -1 0
0 11 -1 1
0
end_operator
begin_operator
lift hoist0 crate0 depot0-1-2 depot0-1-3 depot0
1
1 4
4
0 0 2 1
0 4 0 1
0 7 -1 0
0 11 -1 1
0
end_operator
begin_operator
lift hoist0 crate0 depot0-1-2 loadarea depot0
1
1 1
4
0 0 2 1
0 4 0 1
0 7 -1 0
0 11 -1 1
0
end_operator
begin_operator
lift hoist0 crate0 depot0-1-3 depot0-1-2 depot0
1
1 0
4
0 0 4 1
0 4 0 1
0 10 -1 0
0 11 -1 1
0
end_operator
begin_operator
lift hoist0 crate0 container-0-0 loadarea container0
1
1 1
3
0 0 0 1
0 4 0 1
0 8 -1 0
0
end_operator
begin_operator
lift hoist1 crate0 depot0-1-1 depot0-1-2 depot0
1
2 1
4
0 0 3 5
0 5 0 1
0 9 -1 0
0 11 -1 1
0
end_operator
begin_operator
lift hoist1 crate0 depot0-1-2 depot0-1-1 depot0
1
2 2
4
0 0 2 5
0 5 0 1
0 7 -1 0
0 11 -1 1
0
end_operator
begin_operator
lift hoist1 crate0 depot0-1-2 depot0-1-3 depot0
1
2 0
4
0 0 2 5
0 5 0 1
0 7 -1 0
0 11 -1 1
0
end_operator
begin_operator
lift hoist1 crate0 depot0-1-2 loadarea depot0
1
2 3
4
0 0 2 5
0 5 0 1
0 7 -1 0
0 11 -1 1
0
end_operator
begin_operator
lift hoist1 crate0 depot0-1-3 depot0-1-2 depot0
1
2 1
4
0 0 4 5
0 5 0 1
0 10 -1 0
0 11 -1 1
0
end_operator
begin_operator
lift hoist1 crate0 container-0-0 loadarea container0
1
2 3
3
0 0 0 5
0 5 0 1
0 8 -1 0
0
end_operator
begin_operator
lift hoist2 crate0 depot0-1-1 depot0-1-2 depot0
1
3 1
4
0 0 3 6
0 6 0 1
0 9 -1 0
0 11 -1 1
0
end_operator
begin_operator
lift hoist2 crate0 depot0-1-2 depot0-1-1 depot0
1
3 0
4
0 0 2 6
0 6 0 1
0 7 -1 0
0 11 -1 1
0
end_operator
begin_operator
lift hoist2 crate0 depot0-1-2 depot0-1-3 depot0
1
3 3
4
0 0 2 6
0 6 0 1
0 7 -1 0
0 11 -1 1
0
end_operator
begin_operator
lift hoist2 crate0 depot0-1-2 loadarea depot0
1
3 2
4
0 0 2 6
0 6 0 1
0 7 -1 0
0 11 -1 1
0
end_operator
begin_operator
lift hoist2 crate0 depot0-1-3 depot0-1-2 depot0
1
3 1
4
0 0 4 6
0 6 0 1
0 10 -1 0
0 11 -1 1
0
end_operator
begin_operator
lift hoist2 crate0 container-0-0 loadarea container0
1
3 2
3
0 0 0 6
0 6 0 1
0 8 -1 0
0
end_operator
begin_operator
drop hoist0 crate0 depot0-1-1 depot0-1-2 depot0
1
1 0
4
0 0 1 3
0 4 -1 0
0 9 0 1
0 11 -1 0
0
end_operator
begin_operator
drop hoist0 crate0 depot0-1-2 depot0-1-1 depot0
1
1 3
4
0 0 1 2
0 4 -1 0
0 7 0 1
0 11 -1 0
0
end_operator
begin_operator
drop hoist0 crate0 depot0-1-2 depot0-1-3 depot0
1
1 4
4
0 0 1 2
0 4 -1 0
0 7 0 1
0 11 -1 0
0
end_operator
begin_operator
drop hoist0 crate0 depot0-1-2 loadarea depot0
1
1 1
4
0 0 1 2
0 4 -1 0
0 7 0 1
0 11 -1 0
0
end_operator
begin_operator
drop hoist0 crate0 depot0-1-3 depot0-1-2 depot0
1
1 0
4
0 0 1 4
0 4 -1 0
0 10 0 1
0 11 -1 0
0
end_operator
begin_operator
drop hoist0 crate0 container-0-0 loadarea container0
1
1 1
3
0 0 1 0
0 4 -1 0
0 8 0 1
0
end_operator
begin_operator
drop hoist1 crate0 depot0-1-1 depot0-1-2 depot0
1
2 1
4
0 0 5 3
0 5 -1 0
0 9 0 1
0 11 -1 0
0
end_operator
begin_operator
drop hoist1 crate0 depot0-1-2 depot0-1-1 depot0
1
2 2
4
0 0 5 2
0 5 -1 0
0 7 0 1
0 11 -1 0
0
end_operator
begin_operator
drop hoist1 crate0 depot0-1-2 depot0-1-3 depot0
1
2 0
4
0 0 5 2
0 5 -1 0
0 7 0 1
0 11 -1 0
0
end_operator
begin_operator
drop hoist1 crate0 depot0-1-2 loadarea depot0
1
2 3
4
0 0 5 2
0 5 -1 0
0 7 0 1
0 11 -1 0
0
end_operator
begin_operator
drop hoist1 crate0 depot0-1-3 depot0-1-2 depot0
1
2 1
4
0 0 5 4
0 5 -1 0
0 10 0 1
0 11 -1 0
0
end_operator
begin_operator
drop hoist1 crate0 container-0-0 loadarea container0
1
2 3
3
0 0 5 0
0 5 -1 0
0 8 0 1
0
end_operator
begin_operator
drop hoist2 crate0 depot0-1-1 depot0-1-2 depot0
1
3 1
4
0 0 6 3
0 6 -1 0
0 9 0 1
0 11 -1 0
0
end_operator
begin_operator
drop hoist2 crate0 depot0-1-2 depot0-1-1 depot0
1
3 0
4
0 0 6 2
0 6 -1 0
0 7 0 1
0 11 -1 0
0
end_operator
begin_operator
drop hoist2 crate0 depot0-1-2 depot0-1-3 depot0
1
3 3
4
0 0 6 2
0 6 -1 0
0 7 0 1
0 11 -1 0
0
end_operator
begin_operator
drop hoist2 crate0 depot0-1-2 loadarea depot0
1
3 2
4
0 0 6 2
0 6 -1 0
0 7 0 1
0 11 -1 0
0
end_operator
begin_operator
drop hoist2 crate0 depot0-1-3 depot0-1-2 depot0
1
3 1
4
0 0 6 4
0 6 -1 0
0 10 0 1
0 11 -1 0
0
end_operator
begin_operator
drop hoist2 crate0 container-0-0 loadarea container0
1
3 2
3
0 0 6 0
0 6 -1 0
0 8 0 1
0
end_operator
begin_operator
move hoist0 depot0-1-1 depot0-1-2
0
3
0 1 3 0
0 7 0 1
0 9 -1 0
0
end_operator
begin_operator
move hoist0 depot0-1-2 depot0-1-1
0
3
0 1 0 3
0 7 -1 0
0 9 0 1
0
end_operator
begin_operator
move hoist0 depot0-1-2 depot0-1-3
0
3
0 1 0 4
0 7 -1 0
0 10 0 1
0
end_operator
begin_operator
move hoist0 depot0-1-3 depot0-1-2
0
3
0 1 4 0
0 7 0 1
0 10 -1 0
0
end_operator
begin_operator
move hoist1 depot0-1-1 depot0-1-2
0
3
0 2 2 1
0 7 0 1
0 9 -1 0
0
end_operator
begin_operator
move hoist1 depot0-1-2 depot0-1-1
0
3
0 2 1 2
0 7 -1 0
0 9 0 1
0
end_operator
begin_operator
move hoist1 depot0-1-2 depot0-1-3
0
3
0 2 1 0
0 7 -1 0
0 10 0 1
0
end_operator
begin_operator
move hoist1 depot0-1-3 depot0-1-2
0
3
0 2 0 1
0 7 0 1
0 10 -1 0
0
end_operator
begin_operator
move hoist2 depot0-1-1 depot0-1-2
0
3
0 3 0 1
0 7 0 1
0 9 -1 0
0
end_operator
begin_operator
move hoist2 depot0-1-2 depot0-1-1
0
3
0 3 1 0
0 7 -1 0
0 9 0 1
0
end_operator
begin_operator
move hoist2 depot0-1-2 depot0-1-3
0
3
0 3 1 3
0 7 -1 0
0 10 0 1
0
end_operator
begin_operator
move hoist2 depot0-1-3 depot0-1-2
0
3
0 3 3 1
0 7 0 1
0 10 -1 0
0
end_operator
begin_operator
go-out hoist0 depot0-1-2 loadarea
0
2
0 1 0 1
0 7 -1 0
0
end_operator
begin_operator
go-out hoist0 container-0-0 loadarea
0
2
0 1 2 1
0 8 -1 0
0
end_operator
begin_operator
go-out hoist1 depot0-1-2 loadarea
0
2
0 2 1 3
0 7 -1 0
0
end_operator
begin_operator
go-out hoist1 container-0-0 loadarea
0
2
0 2 4 3
0 8 -1 0
0
end_operator
begin_operator
go-out hoist2 depot0-1-2 loadarea
0
2
0 3 1 2
0 7 -1 0
0
end_operator
begin_operator
go-out hoist2 container-0-0 loadarea
0
2
0 3 4 2
0 8 -1 0
0
end_operator
begin_operator
go-in hoist0 loadarea depot0-1-2
0
2
0 1 1 0
0 7 0 1
0
end_operator
begin_operator
go-in hoist0 loadarea container-0-0
0
2
0 1 1 2
0 8 0 1
0
end_operator
begin_operator
go-in hoist1 loadarea depot0-1-2
0
2
0 2 3 1
0 7 0 1
0
end_operator
begin_operator
go-in hoist1 loadarea container-0-0
0
2
0 2 3 4
0 8 0 1
0
end_operator
begin_operator
go-in hoist2 loadarea depot0-1-2
0
2
0 3 2 1
0 7 0 1
0
end_operator
begin_operator
go-in hoist2 loadarea container-0-0
0
2
0 3 2 4
0 8 0 1
0
end_operator
0
