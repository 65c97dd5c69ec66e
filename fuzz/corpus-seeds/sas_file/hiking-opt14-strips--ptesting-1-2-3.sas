begin_version
3
end_version
begin_metric
0
end_metric
7
begin_variable
var0
-1
3
Atom at_tent(tent0, place0)
Atom at_tent(tent0, place1)
Atom at_tent(tent0, place2)
end_variable
begin_variable
var1
-1
3
Atom at_person(guy0, place0)
Atom at_person(guy0, place1)
Atom at_person(guy0, place2)
end_variable
begin_variable
var2
-1
3
Atom at_person(girl0, place0)
Atom at_person(girl0, place1)
Atom at_person(girl0, place2)
end_variable
begin_variable
var3
-1
3
Atom at_car(car0, place0)
Atom at_car(car0, place1)
Atom at_car(car0, place2)
end_variable
begin_variable
var4
-1
3
Atom at_car(car1, place0)
Atom at_car(car1, place1)
Atom at_car(car1, place2)
end_variable
begin_variable
var5
-1
3
Atom walked(couple0, place0)
Atom walked(couple0, place1)
Atom walked(couple0, place2)
end_variable
begin_variable
var6
-1
2
Atom up(tent0)
Atom down(tent0)
end_variable
7
begin_mutex_group
3
0 0
0 1
0 2
end_mutex_group
begin_mutex_group
3
1 0
1 1
1 2
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
3
4 0
4 1
4 2
end_mutex_group
begin_mutex_group
3
5 0
5 1
5 2
end_mutex_group
begin_mutex_group
2
6 0
6 1
end_mutex_group
begin_state
0
0
0
0
0
0
0
end_state
begin_goal
1
5 2
end_goal
110
begin_operator
put_down guy0 place0 tent0
2
0 0
1 0
1
0 6 0 1
0
end_operator
begin_operator
put_down guy0 place1 tent0
2
0 1
1 1
1
0 6 0 1
0
end_operator
begin_operator
put_down guy0 place2 tent0
2
0 2
1 2
1
0 6 0 1
0
end_operator
begin_operator
put_down girl0 place0 tent0
2
0 0
2 0
1
0 6 0 1
0
end_operator
begin_operator
put_down girl0 place1 tent0
2
0 1
2 1
1
0 6 0 1
0
end_operator
begin_operator
put_down girl0 place2 tent0
2
0 2
2 2
1
0 6 0 1
0
end_operator
begin_operator
put_up guy0 place0 tent0
2
0 0
1 0
1
0 6 1 0
0
end_operator
begin_operator
put_up guy0 place1 tent0
2
0 1
1 1
1
0 6 1 0
0
end_operator
begin_operator
put_up guy0 place2 tent0
2
0 2
1 2
1
0 6 1 0
0
end_operator
begin_operator
put_up girl0 place0 tent0
2
0 0
2 0
1
0 6 1 0
0
end_operator
begin_operator
put_up girl0 place1 tent0
2
0 1
2 1
1
0 6 1 0
0
end_operator
begin_operator
put_up girl0 place2 tent0
2
0 2
2 2
1
0 6 1 0
0
end_operator
begin_operator
drive_passenger guy0 place0 place1 car0 girl0
0
3
0 1 0 1
0 2 0 1
0 3 0 1
0
end_operator
begin_operator
drive_passenger guy0 place0 place1 car1 girl0
0
3
0 1 0 1
0 2 0 1
0 4 0 1
0
end_operator
begin_operator
drive_passenger guy0 place0 place2 car0 girl0
0
3
0 1 0 2
0 2 0 2
0 3 0 2
0
end_operator
begin_operator
drive_passenger guy0 place0 place2 car1 girl0
0
3
0 1 0 2
0 2 0 2
0 4 0 2
0
end_operator
begin_operator
drive_passenger guy0 place1 place0 car0 girl0
0
3
0 1 1 0
0 2 1 0
0 3 1 0
0
end_operator
begin_operator
drive_passenger guy0 place1 place0 car1 girl0
0
3
0 1 1 0
0 2 1 0
0 4 1 0
0
end_operator
begin_operator
drive_passenger guy0 place1 place2 car0 girl0
0
3
0 1 1 2
0 2 1 2
0 3 1 2
0
end_operator
begin_operator
drive_passenger guy0 place1 place2 car1 girl0
0
3
0 1 1 2
0 2 1 2
0 4 1 2
0
end_operator
begin_operator
drive_passenger guy0 place2 place0 car0 girl0
0
3
0 1 2 0
0 2 2 0
0 3 2 0
0
end_operator
begin_operator
drive_passenger guy0 place2 place0 car1 girl0
0
3
0 1 2 0
0 2 2 0
0 4 2 0
0
end_operator
begin_operator
drive_passenger guy0 place2 place1 car0 girl0
0
3
0 1 2 1
0 2 2 1
0 3 2 1
0
end_operator
begin_operator
drive_passenger guy0 place2 place1 car1 girl0
0
3
0 1 2 1
0 2 2 1
0 4 2 1
0
end_operator
begin_operator
drive_passenger girl0 place0 place1 car0 guy0
0
3
0 1 0 1
0 2 0 1
0 3 0 1
0
end_operator
begin_operator
drive_passenger girl0 place0 place1 car1 guy0
0
3
0 1 0 1
0 2 0 1
0 4 0 1
0
end_operator
begin_operator
drive_passenger girl0 place0 place2 car0 guy0
0
3
0 1 0 2
0 2 0 2
0 3 0 2
0
end_operator
begin_operator
drive_passenger girl0 place0 place2 car1 guy0
0
3
0 1 0 2
0 2 0 2
0 4 0 2
0
end_operator
begin_operator
drive_passenger girl0 place1 place0 car0 guy0
0
3
0 1 1 0
0 2 1 0
0 3 1 0
0
end_operator
begin_operator
drive_passenger girl0 place1 place0 car1 guy0
0
3
0 1 1 0
0 2 1 0
0 4 1 0
0
end_operator
begin_operator
drive_passenger girl0 place1 place2 car0 guy0
0
3
0 1 1 2
0 2 1 2
0 3 1 2
0
end_operator
begin_operator
drive_passenger girl0 place1 place2 car1 guy0
0
3
0 1 1 2
0 2 1 2
0 4 1 2
0
end_operator
begin_operator
drive_passenger girl0 place2 place0 car0 guy0
0
3
0 1 2 0
0 2 2 0
0 3 2 0
0
end_operator
begin_operator
drive_passenger girl0 place2 place0 car1 guy0
0
3
0 1 2 0
0 2 2 0
0 4 2 0
0
end_operator
begin_operator
drive_passenger girl0 place2 place1 car0 guy0
0
3
0 1 2 1
0 2 2 1
0 3 2 1
0
end_operator
begin_operator
drive_passenger girl0 place2 place1 car1 guy0
0
3
0 1 2 1
0 2 2 1
0 4 2 1
0
end_operator
begin_operator
drive guy0 place0 place1 car0
0
2
0 1 0 1
0 3 0 1
0
end_operator
begin_operator
drive guy0 place0 place1 car1
0
2
0 1 0 1
0 4 0 1
0
end_operator
begin_operator
drive guy0 place0 place2 car0
0
2
0 1 0 2
0 3 0 2
0
end_operator
begin_operator
drive guy0 place0 place2 car1
0
2
0 1 0 2
0 4 0 2
0
end_operator
begin_operator
drive guy0 place1 place0 car0
0
2
0 1 1 0
0 3 1 0
0
end_operator
begin_operator
drive guy0 place1 place0 car1
0
2
0 1 1 0
0 4 1 0
0
end_operator
begin_operator
drive guy0 place1 place2 car0
0
2
0 1 1 2
0 3 1 2
0
end_operator
begin_operator
drive guy0 place1 place2 car1
0
2
0 1 1 2
0 4 1 2
0
end_operator
begin_operator
drive guy0 place2 place0 car0
0
2
0 1 2 0
0 3 2 0
0
end_operator
begin_operator
drive guy0 place2 place0 car1
0
2
0 1 2 0
0 4 2 0
0
end_operator
begin_operator
drive guy0 place2 place1 car0
0
2
0 1 2 1
0 3 2 1
0
end_operator
begin_operator
drive guy0 place2 place1 car1
0
2
0 1 2 1
0 4 2 1
0
end_operator
begin_operator
drive girl0 place0 place1 car0
0
2
0 2 0 1
0 3 0 1
0
end_operator
begin_operator
drive girl0 place0 place1 car1
0
2
0 2 0 1
0 4 0 1
0
end_operator
begin_operator
drive girl0 place0 place2 car0
0
2
0 2 0 2
0 3 0 2
0
end_operator
begin_operator
drive girl0 place0 place2 car1
0
2
0 2 0 2
0 4 0 2
0
end_operator
begin_operator
drive girl0 place1 place0 car0
0
2
0 2 1 0
0 3 1 0
0
end_operator
begin_operator
drive girl0 place1 place0 car1
0
2
0 2 1 0
0 4 1 0
0
end_operator
begin_operator
drive girl0 place1 place2 car0
0
2
0 2 1 2
0 3 1 2
0
end_operator
begin_operator
drive girl0 place1 place2 car1
0
2
0 2 1 2
0 4 1 2
0
end_operator
begin_operator
drive girl0 place2 place0 car0
0
2
0 2 2 0
0 3 2 0
0
end_operator
begin_operator
drive girl0 place2 place0 car1
0
2
0 2 2 0
0 4 2 0
0
end_operator
begin_operator
drive girl0 place2 place1 car0
0
2
0 2 2 1
0 3 2 1
0
end_operator
begin_operator
drive girl0 place2 place1 car1
0
2
0 2 2 1
0 4 2 1
0
end_operator
begin_operator
drive_tent guy0 place0 place1 car0 tent0
1
6 1
3
0 0 0 1
0 1 0 1
0 3 0 1
0
end_operator
begin_operator
drive_tent guy0 place0 place1 car1 tent0
1
6 1
3
0 0 0 1
0 1 0 1
0 4 0 1
0
end_operator
begin_operator
drive_tent guy0 place0 place2 car0 tent0
1
6 1
3
0 0 0 2
0 1 0 2
0 3 0 2
0
end_operator
begin_operator
drive_tent guy0 place0 place2 car1 tent0
1
6 1
3
0 0 0 2
0 1 0 2
0 4 0 2
0
end_operator
begin_operator
drive_tent guy0 place1 place0 car0 tent0
1
6 1
3
0 0 1 0
0 1 1 0
0 3 1 0
0
end_operator
begin_operator
drive_tent guy0 place1 place0 car1 tent0
1
6 1
3
0 0 1 0
0 1 1 0
0 4 1 0
0
end_operator
begin_operator
drive_tent guy0 place1 place2 car0 tent0
1
6 1
3
0 0 1 2
0 1 1 2
0 3 1 2
0
end_operator
begin_operator
drive_tent guy0 place1 place2 car1 tent0
1
6 1
3
0 0 1 2
0 1 1 2
0 4 1 2
0
end_operator
begin_operator
drive_tent guy0 place2 place0 car0 tent0
1
6 1
3
0 0 2 0
0 1 2 0
0 3 2 0
0
end_operator
begin_operator
drive_tent guy0 place2 place0 car1 tent0
1
6 1
3
0 0 2 0
0 1 2 0
0 4 2 0
0
end_operator
begin_operator
drive_tent guy0 place2 place1 car0 tent0
1
6 1
3
0 0 2 1
0 1 2 1
0 3 2 1
0
end_operator
begin_operator
drive_tent guy0 place2 place1 car1 tent0
1
6 1
3
0 0 2 1
0 1 2 1
0 4 2 1
0
end_operator
begin_operator
drive_tent girl0 place0 place1 car0 tent0
1
6 1
3
0 0 0 1
0 2 0 1
0 3 0 1
0
end_operator
begin_operator
drive_tent girl0 place0 place1 car1 tent0
1
6 1
3
0 0 0 1
0 2 0 1
0 4 0 1
0
end_operator
begin_operator
drive_tent girl0 place0 place2 car0 tent0
1
6 1
3
0 0 0 2
0 2 0 2
0 3 0 2
0
end_operator
begin_operator
drive_tent girl0 place0 place2 car1 tent0
1
6 1
3
0 0 0 2
0 2 0 2
0 4 0 2
0
end_operator
begin_operator
drive_tent girl0 place1 place0 car0 tent0
1
6 1
3
0 0 1 0
0 2 1 0
0 3 1 0
0
end_operator
begin_operator
drive_tent girl0 place1 place0 car1 tent0
1
6 1
3
0 0 1 0
0 2 1 0
0 4 1 0
0
end_operator
begin_operator
drive_tent girl0 place1 place2 car0 tent0
1
6 1
3
0 0 1 2
0 2 1 2
0 3 1 2
0
end_operator
begin_operator
drive_tent girl0 place1 place2 car1 tent0
1
6 1
3
0 0 1 2
0 2 1 2
0 4 1 2
0
end_operator
begin_operator
drive_tent girl0 place2 place0 car0 tent0
1
6 1
3
0 0 2 0
0 2 2 0
0 3 2 0
0
end_operator
begin_operator
drive_tent girl0 place2 place0 car1 tent0
1
6 1
3
0 0 2 0
0 2 2 0
0 4 2 0
0
end_operator
begin_operator
drive_tent girl0 place2 place1 car0 tent0
1
6 1
3
0 0 2 1
0 2 2 1
0 3 2 1
0
end_operator
begin_operator
drive_tent girl0 place2 place1 car1 tent0
1
6 1
3
0 0 2 1
0 2 2 1
0 4 2 1
0
end_operator
begin_operator
drive_tent_passenger guy0 place0 place1 car0 tent0 girl0
1
6 1
4
0 0 0 1
0 1 0 1
0 2 0 1
0 3 0 1
0
end_operator
begin_operator
drive_tent_passenger guy0 place0 place1 car1 tent0 girl0
1
6 1
4
0 0 0 1
0 1 0 1
0 2 0 1
0 4 0 1
0
end_operator
begin_operator
drive_tent_passenger guy0 place0 place2 car0 tent0 girl0
1
6 1
4
0 0 0 2
0 1 0 2
0 2 0 2
0 3 0 2
0
end_operator
begin_operator
drive_tent_passenger guy0 place0 place2 car1 tent0 girl0
1
6 1
4
0 0 0 2
0 1 0 2
0 2 0 2
0 4 0 2
0
end_operator
begin_operator
drive_tent_passenger guy0 place1 place0 car0 tent0 girl0
1
6 1
4
0 0 1 0
0 1 1 0
0 2 1 0
0 3 1 0
0
end_operator
begin_operator
drive_tent_passenger guy0 place1 place0 car1 tent0 girl0
1
6 1
4
0 0 1 0
0 1 1 0
0 2 1 0
0 4 1 0
0
end_operator
begin_operator
drive_tent_passenger guy0 place1 place2 car0 tent0 girl0
1
6 1
4
0 0 1 2
0 1 1 2
0 2 1 2
0 3 1 2
0
end_operator
begin_operator
drive_tent_passenger guy0 place1 place2 car1 tent0 girl0
1
6 1
4
0 0 1 2
0 1 1 2
0 2 1 2
0 4 1 2
0
end_operator
begin_operator
drive_tent_passenger guy0 place2 place0 car0 tent0 girl0
1
6 1
4
0 0 2 0
0 1 2 0
0 2 2 0
0 3 2 0
0
end_operator
begin_operator
drive_tent_passenger guy0 place2 place0 car1 tent0 girl0
1
6 1
4
0 0 2 0
0 1 2 0
0 2 2 0
0 4 2 0
0
end_operator
begin_operator
drive_tent_passenger guy0 place2 place1 car0 tent0 girl0
1
6 1
4
0 0 2 1
0 1 2 1
0 2 2 1
0 3 2 1
0
end_operator
begin_operator
drive_tent_passenger guy0 place2 place1 car1 tent0 girl0
1
6 1
4
0 0 2 1
0 1 2 1
0 2 2 1
0 4 2 1
0
end_operator
begin_operator
drive_tent_passenger girl0 place0 place1 car0 tent0 guy0
1
6 1
4
0 0 0 1
0 1 0 1
0 2 0 1
0 3 0 1
0
end_operator
begin_operator
drive_tent_passenger girl0 place0 place1 car1 tent0 guy0
1
6 1
4
0 0 0 1
0 1 0 1
0 2 0 1
0 4 0 1
0
end_operator
begin_operator
drive_tent_passenger girl0 place0 place2 car0 tent0 guy0
1
6 1
4
0 0 0 2
0 1 0 2
0 2 0 2
0 3 0 2
0
end_operator
begin_operator
drive_tent_passenger girl0 place0 place2 car1 tent0 guy0
1
6 1
4
0 0 0 2
0 1 0 2
0 2 0 2
0 4 0 2
0
end_operator
begin_operator
drive_tent_passenger girl0 place1 place0 car0 tent0 guy0
1
6 1
4
0 0 1 0
0 1 1 0
0 2 1 0
0 3 1 0
0
end_operator
begin_operator
drive_tent_passenger girl0 place1 place0 car1 tent0 guy0
1
6 1
4
0 0 1 0
0 1 1 0
0 2 1 0
0 4 1 0
0
end_operator
begin_operator
drive_tent_passenger girl0 place1 place2 car0 tent0 guy0
1
6 1
4
0 0 1 2
0 1 1 2
0 2 1 2
0 3 1 2
0
end_operator
begin_operator
drive_tent_passenger girl0 place1 place2 car1 tent0 guy0
1
6 1
4
0 0 1 2
0 1 1 2
0 2 1 2
0 4 1 2
0
end_operator
begin_operator
drive_tent_passenger girl0 place2 place0 car0 tent0 guy0
1
6 1
4
0 0 2 0
0 1 2 0
0 2 2 0
0 3 2 0
0
end_operator
begin_operator
drive_tent_passenger girl0 place2 place0 car1 tent0 guy0
1
6 1
4
0 0 2 0
0 1 2 0
0 2 2 0
0 4 2 0
0
end_operator
begin_operator
drive_tent_passenger girl0 place2 place1 car0 tent0 guy0
1
6 1
4
0 0 2 1
0 1 2 1
0 2 2 1
0 3 2 1
0
end_operator
begin_operator
drive_tent_passenger girl0 place2 place1 car1 tent0 guy0
1
6 1
4
0 0 2 1
0 1 2 1
0 2 2 1
0 4 2 1
0
end_operator
begin_operator
walk_together tent0 place1 guy0 place0 girl0 couple0
2
0 1
6 0
3
0 1 0 1
0 2 0 1
0 5 0 1
0
end_operator
begin_operator
walk_together tent0 place2 guy0 place1 girl0 couple0
2
0 2
6 0
3
0 1 1 2
0 2 1 2
0 5 1 2
0
end_operator
0
