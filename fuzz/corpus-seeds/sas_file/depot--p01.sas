begin_version
3
end_version
begin_metric
0
end_metric
14
begin_variable
var0
-1
9
Atom on(crate0, pallet1)
Atom lifting(hoist1, crate0)
Atom in(crate0, truck1)
Atom in(crate0, truck0)
Atom lifting(hoist0, crate0)
Atom lifting(hoist2, crate0)
Atom on(crate0, pallet0)
Atom on(crate0, crate1)
Atom on(crate0, pallet2)
end_variable
begin_variable
var1
-1
9
Atom on(crate1, pallet0)
Atom lifting(hoist0, crate1)
Atom in(crate1, truck1)
Atom in(crate1, truck0)
Atom lifting(hoist1, crate1)
Atom lifting(hoist2, crate1)
Atom on(crate1, pallet1)
Atom on(crate1, crate0)
Atom on(crate1, pallet2)
end_variable
begin_variable
var2
-1
3
Atom at(truck0, distributor1)
Atom at(truck0, depot0)
Atom at(truck0, distributor0)
end_variable
begin_variable
var3
-1
3
Atom at(truck1, depot0)
Atom at(truck1, distributor0)
Atom at(truck1, distributor1)
end_variable
begin_variable
var4
-1
4
Atom at(crate0, distributor0)
Atom at(crate0, depot0)
Atom at(crate0, distributor1)
<none of those>
end_variable
begin_variable
var5
-1
4
Atom at(crate1, depot0)
Atom at(crate1, distributor0)
Atom at(crate1, distributor1)
<none of those>
end_variable
begin_variable
var6
-1
2
Atom clear(crate1)
NegatedAtom clear(crate1)
end_variable
begin_variable
var7
-1
2
Atom clear(crate0)
NegatedAtom clear(crate0)
end_variable
begin_variable
var8
-1
2
Atom clear(pallet2)
NegatedAtom clear(pallet2)
end_variable
begin_variable
var9
-1
2
Atom available(hoist0)
NegatedAtom available(hoist0)
end_variable
begin_variable
var10
-1
2
Atom available(hoist1)
NegatedAtom available(hoist1)
end_variable
begin_variable
var11
-1
2
Atom available(hoist2)
NegatedAtom available(hoist2)
end_variable
begin_variable
var12
-1
2
Atom clear(pallet0)
NegatedAtom clear(pallet0)
end_variable
begin_variable
var13
-1
2
Atom clear(pallet1)
NegatedAtom clear(pallet1)
end_variable
9
begin_mutex_group
3
9 0
1 1
0 4
end_mutex_group
begin_mutex_group
3
10 0
0 1
1 4
end_mutex_group
begin_mutex_group
3
11 0
1 5
0 5
end_mutex_group
begin_mutex_group
3
2 0
2 1
2 2
end_mutex_group
begin_mutex_group
3
3 0
3 1
3 2
end_mutex_group
begin_mutex_group
8
4 0
0 1
0 2
0 3
0 4
0 5
4 1
4 2
end_mutex_group
begin_mutex_group
8
5 0
1 1
1 2
1 3
1 4
1 5
5 1
5 2
end_mutex_group
begin_mutex_group
9
0 0
0 1
0 2
0 3
0 4
0 5
0 6
0 7
0 8
end_mutex_group
begin_mutex_group
9
1 0
1 1
1 2
1 3
1 4
1 5
1 6
1 7
1 8
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
1
end_state
begin_goal
2
0 8
1 6
end_goal
72
begin_operator
drive truck0 depot0 distributor0
0
1
0 2 1 2
0
end_operator
begin_operator
drive truck0 depot0 distributor1
0
1
0 2 1 0
0
end_operator
begin_operator
drive truck0 distributor0 depot0
0
1
0 2 2 1
0
end_operator
begin_operator
drive truck0 distributor0 distributor1
0
1
0 2 2 0
0
end_operator
begin_operator
drive truck0 distributor1 depot0
0
1
0 2 0 1
0
end_operator
begin_operator
drive truck0 distributor1 distributor0
0
1
0 2 0 2
0
end_operator
begin_operator
drive truck1 depot0 distributor0
0
1
0 3 0 1
0
end_operator
begin_operator
drive truck1 depot0 distributor1
0
1
0 3 0 2
0
end_operator
begin_operator
drive truck1 distributor0 depot0
0
1
0 3 1 0
0
end_operator
begin_operator
drive truck1 distributor0 distributor1
0
1
0 3 1 2
0
end_operator
begin_operator
drive truck1 distributor1 depot0
0
1
0 3 2 0
0
end_operator
begin_operator
drive truck1 distributor1 distributor0
0
1
0 3 2 1
0
end_operator
begin_operator
lift hoist0 crate0 pallet0 depot0
0
5
0 0 6 4
0 4 1 3
0 7 0 1
0 9 0 1
0 12 -1 0
0
end_operator
begin_operator
lift hoist0 crate0 pallet1 depot0
0
5
0 0 0 4
0 4 1 3
0 7 0 1
0 9 0 1
0 13 -1 0
0
end_operator
begin_operator
lift hoist0 crate0 pallet2 depot0
0
5
0 0 8 4
0 4 1 3
0 7 0 1
0 8 -1 0
0 9 0 1
0
end_operator
begin_operator
lift hoist0 crate0 crate1 depot0
0
5
0 0 7 4
0 4 1 3
0 6 -1 0
0 7 0 1
0 9 0 1
0
end_operator
begin_operator
lift hoist0 crate1 pallet0 depot0
0
5
0 1 0 1
0 5 0 3
0 6 0 1
0 9 0 1
0 12 -1 0
0
end_operator
begin_operator
lift hoist0 crate1 pallet1 depot0
0
5
0 1 6 1
0 5 0 3
0 6 0 1
0 9 0 1
0 13 -1 0
0
end_operator
begin_operator
lift hoist0 crate1 pallet2 depot0
0
5
0 1 8 1
0 5 0 3
0 6 0 1
0 8 -1 0
0 9 0 1
0
end_operator
begin_operator
lift hoist0 crate1 crate0 depot0
0
5
0 1 7 1
0 5 0 3
0 6 0 1
0 7 -1 0
0 9 0 1
0
end_operator
begin_operator
lift hoist1 crate0 pallet0 distributor0
0
5
0 0 6 1
0 4 0 3
0 7 0 1
0 10 0 1
0 12 -1 0
0
end_operator
begin_operator
lift hoist1 crate0 pallet1 distributor0
0
5
0 0 0 1
0 4 0 3
0 7 0 1
0 10 0 1
0 13 -1 0
0
end_operator
begin_operator
lift hoist1 crate0 pallet2 distributor0
0
5
0 0 8 1
0 4 0 3
0 7 0 1
0 8 -1 0
0 10 0 1
0
end_operator
begin_operator
lift hoist1 crate0 crate1 distributor0
0
5
0 0 7 1
0 4 0 3
0 6 -1 0
0 7 0 1
0 10 0 1
0
end_operator
begin_operator
lift hoist1 crate1 pallet0 distributor0
0
5
0 1 0 4
0 5 1 3
0 6 0 1
0 10 0 1
0 12 -1 0
0
end_operator
begin_operator
lift hoist1 crate1 pallet1 distributor0
0
5
0 1 6 4
0 5 1 3
0 6 0 1
0 10 0 1
0 13 -1 0
0
end_operator
begin_operator
lift hoist1 crate1 pallet2 distributor0
0
5
0 1 8 4
0 5 1 3
0 6 0 1
0 8 -1 0
0 10 0 1
0
end_operator
begin_operator
lift hoist1 crate1 crate0 distributor0
0
5
0 1 7 4
0 5 1 3
0 6 0 1
0 7 -1 0
0 10 0 1
0
end_operator
begin_operator
lift hoist2 crate0 pallet0 distributor1
0
5
0 0 6 5
0 4 2 3
0 7 0 1
0 11 0 1
0 12 -1 0
0
end_operator
begin_operator
lift hoist2 crate0 pallet1 distributor1
0
5
0 0 0 5
0 4 2 3
0 7 0 1
0 11 0 1
0 13 -1 0
0
end_operator
begin_operator
lift hoist2 crate0 pallet2 distributor1
0
5
0 0 8 5
0 4 2 3
0 7 0 1
0 8 -1 0
0 11 0 1
0
end_operator
begin_operator
lift hoist2 crate0 crate1 distributor1
0
5
0 0 7 5
0 4 2 3
0 6 -1 0
0 7 0 1
0 11 0 1
0
end_operator
begin_operator
lift hoist2 crate1 pallet0 distributor1
0
5
0 1 0 5
0 5 2 3
0 6 0 1
0 11 0 1
0 12 -1 0
0
end_operator
begin_operator
lift hoist2 crate1 pallet1 distributor1
0
5
0 1 6 5
0 5 2 3
0 6 0 1
0 11 0 1
0 13 -1 0
0
end_operator
begin_operator
lift hoist2 crate1 pallet2 distributor1
0
5
0 1 8 5
0 5 2 3
0 6 0 1
0 8 -1 0
0 11 0 1
0
end_operator
begin_operator
lift hoist2 crate1 crate0 distributor1
0
5
0 1 7 5
0 5 2 3
0 6 0 1
0 7 -1 0
0 11 0 1
0
end_operator
begin_operator
drop hoist0 crate0 pallet0 depot0
0
5
0 0 4 6
0 4 -1 1
0 7 -1 0
0 9 -1 0
0 12 0 1
0
end_operator
begin_operator
drop hoist0 crate0 crate1 depot0
1
5 0
5
0 0 4 7
0 4 -1 1
0 6 0 1
0 7 -1 0
0 9 -1 0
0
end_operator
begin_operator
drop hoist0 crate1 pallet0 depot0
0
5
0 1 1 0
0 5 -1 0
0 6 -1 0
0 9 -1 0
0 12 0 1
0
end_operator
begin_operator
drop hoist0 crate1 crate0 depot0
1
4 1
5
0 1 1 7
0 5 -1 0
0 6 -1 0
0 7 0 1
0 9 -1 0
0
end_operator
begin_operator
drop hoist1 crate0 pallet1 distributor0
0
5
0 0 1 0
0 4 -1 0
0 7 -1 0
0 10 -1 0
0 13 0 1
0
end_operator
begin_operator
drop hoist1 crate0 crate1 distributor0
1
5 1
5
0 0 1 7
0 4 -1 0
0 6 0 1
0 7 -1 0
0 10 -1 0
0
end_operator
begin_operator
drop hoist1 crate1 pallet1 distributor0
0
5
0 1 4 6
0 5 -1 1
0 6 -1 0
0 10 -1 0
0 13 0 1
0
end_operator
begin_operator
drop hoist1 crate1 crate0 distributor0
1
4 0
5
0 1 4 7
0 5 -1 1
0 6 -1 0
0 7 0 1
0 10 -1 0
0
end_operator
begin_operator
drop hoist2 crate0 pallet2 distributor1
0
5
0 0 5 8
0 4 -1 2
0 7 -1 0
0 8 0 1
0 11 -1 0
0
end_operator
begin_operator
drop hoist2 crate0 crate1 distributor1
1
5 2
5
0 0 5 7
0 4 -1 2
0 6 0 1
0 7 -1 0
0 11 -1 0
0
end_operator
begin_operator
drop hoist2 crate1 pallet2 distributor1
0
5
0 1 5 8
0 5 -1 2
0 6 -1 0
0 8 0 1
0 11 -1 0
0
end_operator
begin_operator
drop hoist2 crate1 crate0 distributor1
1
4 2
5
0 1 5 7
0 5 -1 2
0 6 -1 0
0 7 0 1
0 11 -1 0
0
end_operator
begin_operator
load hoist0 crate0 truck0 depot0
1
2 1
2
0 0 4 3
0 9 -1 0
0
end_operator
begin_operator
load hoist0 crate0 truck1 depot0
1
3 0
2
0 0 4 2
0 9 -1 0
0
end_operator
begin_operator
load hoist0 crate1 truck0 depot0
1
2 1
2
0 1 1 3
0 9 -1 0
0
end_operator
begin_operator
load hoist0 crate1 truck1 depot0
1
3 0
2
0 1 1 2
0 9 -1 0
0
end_operator
begin_operator
load hoist1 crate0 truck0 distributor0
1
2 2
2
0 0 1 3
0 10 -1 0
0
end_operator
begin_operator
load hoist1 crate0 truck1 distributor0
1
3 1
2
0 0 1 2
0 10 -1 0
0
end_operator
begin_operator
load hoist1 crate1 truck0 distributor0
1
2 2
2
0 1 4 3
0 10 -1 0
0
end_operator
begin_operator
load hoist1 crate1 truck1 distributor0
1
3 1
2
0 1 4 2
0 10 -1 0
0
end_operator
begin_operator
load hoist2 crate0 truck0 distributor1
1
2 0
2
0 0 5 3
0 11 -1 0
0
end_operator
begin_operator
load hoist2 crate0 truck1 distributor1
1
3 2
2
0 0 5 2
0 11 -1 0
0
end_operator
begin_operator
load hoist2 crate1 truck0 distributor1
1
2 0
2
0 1 5 3
0 11 -1 0
0
end_operator
begin_operator
load hoist2 crate1 truck1 distributor1
1
3 2
2
0 1 5 2
0 11 -1 0
0
end_operator
begin_operator
unload hoist0 crate0 truck0 depot0
1
2 1
2
0 0 3 4
0 9 0 1
0
end_operator
begin_operator
unload hoist0 crate0 truck1 depot0
1
3 0
2
0 0 2 4
0 9 0 1
0
end_operator
begin_operator
unload hoist0 crate1 truck0 depot0
1
2 1
2
0 1 3 1
0 9 0 1
0
end_operator
begin_operator
unload hoist0 crate1 truck1 depot0
1
3 0
2
0 1 2 1
0 9 0 1
0
end_operator
begin_operator
unload hoist1 crate0 truck0 distributor0
1
2 2
2
0 0 3 1
0 10 0 1
0
end_operator
begin_operator
unload hoist1 crate0 truck1 distributor0
1
3 1
2
0 0 2 1
0 10 0 1
0
end_operator
begin_operator
unload hoist1 crate1 truck0 distributor0
1
2 2
2
0 1 3 4
0 10 0 1
0
end_operator
begin_operator
unload hoist1 crate1 truck1 distributor0
1
3 1
2
0 1 2 4
0 10 0 1
0
end_operator
begin_operator
unload hoist2 crate0 truck0 distributor1
1
2 0
2
0 0 3 5
0 11 0 1
0
end_operator
begin_operator
unload hoist2 crate0 truck1 distributor1
1
3 2
2
0 0 2 5
0 11 0 1
0
end_operator
begin_operator
unload hoist2 crate1 truck0 distributor1
1
2 0
2
0 1 3 5
0 11 0 1
0
end_operator
begin_operator
unload hoist2 crate1 truck1 distributor1
1
3 2
2
0 1 2 5
0 11 0 1
0
end_operator
0
