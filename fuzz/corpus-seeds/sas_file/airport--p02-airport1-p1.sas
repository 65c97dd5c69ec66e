begin_version
3
end_version
begin_metric
0
end_metric
29
begin_variable
var0
-1
15
Atom at-segment(airplane_daewh, seg_pp_0_60)
Atom at-segment(airplane_daewh, seg_ppdoor_0_40)
Atom at-segment(airplane_daewh, seg_tww1_0_200)
Atom at-segment(airplane_daewh, seg_twe1_0_200)
Atom at-segment(airplane_daewh, seg_twe2_0_50)
Atom at-segment(airplane_daewh, seg_twe3_0_50)
Atom at-segment(airplane_daewh, seg_twe4_0_50)
Atom at-segment(airplane_daewh, seg_rwe_0_50)
Atom at-segment(airplane_daewh, seg_rw_0_400)
Atom airborne(airplane_daewh, seg_rwe_0_50)
Atom at-segment(airplane_daewh, seg_rww_0_50)
Atom at-segment(airplane_daewh, seg_tww4_0_50)
Atom airborne(airplane_daewh, seg_rww_0_50)
Atom at-segment(airplane_daewh, seg_tww3_0_50)
Atom at-segment(airplane_daewh, seg_tww2_0_50)
end_variable
begin_variable
var1
-1
4
Atom is-pushing(airplane_daewh)
Atom is-moving(airplane_daewh)
Atom is-parked(airplane_daewh, seg_pp_0_60)
<none of those>
end_variable
begin_variable
var2
-1
2
Atom facing(airplane_daewh, south)
Atom facing(airplane_daewh, north)
end_variable
begin_variable
var3
-1
2
Atom not_blocked(seg_ppdoor_0_40, airplane_daewh)
NegatedAtom not_blocked(seg_ppdoor_0_40, airplane_daewh)
end_variable
begin_variable
var4
-1
2
Atom not_blocked(seg_tww1_0_200, airplane_daewh)
NegatedAtom not_blocked(seg_tww1_0_200, airplane_daewh)
end_variable
begin_variable
var5
-1
2
Atom not_blocked(seg_twe1_0_200, airplane_daewh)
NegatedAtom not_blocked(seg_twe1_0_200, airplane_daewh)
end_variable
begin_variable
var6
-1
2
Atom not_blocked(seg_tww2_0_50, airplane_daewh)
NegatedAtom not_blocked(seg_tww2_0_50, airplane_daewh)
end_variable
begin_variable
var7
-1
2
Atom not_blocked(seg_tww3_0_50, airplane_daewh)
NegatedAtom not_blocked(seg_tww3_0_50, airplane_daewh)
end_variable
begin_variable
var8
-1
2
Atom not_blocked(seg_tww4_0_50, airplane_daewh)
NegatedAtom not_blocked(seg_tww4_0_50, airplane_daewh)
end_variable
begin_variable
var9
-1
2
Atom not_blocked(seg_rww_0_50, airplane_daewh)
NegatedAtom not_blocked(seg_rww_0_50, airplane_daewh)
end_variable
begin_variable
var10
-1
2
Atom not_blocked(seg_rw_0_400, airplane_daewh)
NegatedAtom not_blocked(seg_rw_0_400, airplane_daewh)
end_variable
begin_variable
var11
-1
2
Atom not_blocked(seg_rwe_0_50, airplane_daewh)
NegatedAtom not_blocked(seg_rwe_0_50, airplane_daewh)
end_variable
begin_variable
var12
-1
2
Atom not_blocked(seg_twe4_0_50, airplane_daewh)
NegatedAtom not_blocked(seg_twe4_0_50, airplane_daewh)
end_variable
begin_variable
var13
-1
2
Atom not_blocked(seg_twe3_0_50, airplane_daewh)
NegatedAtom not_blocked(seg_twe3_0_50, airplane_daewh)
end_variable
begin_variable
var14
-1
2
Atom not_blocked(seg_twe2_0_50, airplane_daewh)
NegatedAtom not_blocked(seg_twe2_0_50, airplane_daewh)
end_variable
begin_variable
var15
-1
2
Atom not_occupied(seg_ppdoor_0_40)
NegatedAtom not_occupied(seg_ppdoor_0_40)
end_variable
begin_variable
var16
-1
2
Atom not_occupied(seg_tww1_0_200)
NegatedAtom not_occupied(seg_tww1_0_200)
end_variable
begin_variable
var17
-1
2
Atom not_occupied(seg_twe1_0_200)
NegatedAtom not_occupied(seg_twe1_0_200)
end_variable
begin_variable
var18
-1
2
Atom not_occupied(seg_tww2_0_50)
NegatedAtom not_occupied(seg_tww2_0_50)
end_variable
begin_variable
var19
-1
2
Atom not_occupied(seg_tww3_0_50)
NegatedAtom not_occupied(seg_tww3_0_50)
end_variable
begin_variable
var20
-1
2
Atom not_occupied(seg_tww4_0_50)
NegatedAtom not_occupied(seg_tww4_0_50)
end_variable
begin_variable
var21
-1
2
Atom not_occupied(seg_rww_0_50)
NegatedAtom not_occupied(seg_rww_0_50)
end_variable
begin_variable
var22
-1
2
Atom not_occupied(seg_rw_0_400)
NegatedAtom not_occupied(seg_rw_0_400)
end_variable
begin_variable
var23
-1
2
Atom not_occupied(seg_rwe_0_50)
NegatedAtom not_occupied(seg_rwe_0_50)
end_variable
begin_variable
var24
-1
2
Atom not_occupied(seg_twe4_0_50)
NegatedAtom not_occupied(seg_twe4_0_50)
end_variable
begin_variable
var25
-1
2
Atom not_occupied(seg_twe3_0_50)
NegatedAtom not_occupied(seg_twe3_0_50)
end_variable
begin_variable
var26
-1
2
Atom not_occupied(seg_twe2_0_50)
NegatedAtom not_occupied(seg_twe2_0_50)
end_variable
begin_variable
var27
-1
2
Atom not_occupied(seg_pp_0_60)
NegatedAtom not_occupied(seg_pp_0_60)
end_variable
begin_variable
var28
-1
2
Atom not_blocked(seg_pp_0_60, airplane_daewh)
NegatedAtom not_blocked(seg_pp_0_60, airplane_daewh)
end_variable
19
begin_mutex_group
13
0 0
0 1
0 2
0 3
0 4
0 5
0 6
0 7
0 8
0 10
0 11
0 13
0 14
end_mutex_group
begin_mutex_group
2
2 0
2 1
end_mutex_group
begin_mutex_group
2
0 0
27 0
end_mutex_group
begin_mutex_group
2
15 0
0 1
end_mutex_group
begin_mutex_group
2
16 0
0 2
end_mutex_group
begin_mutex_group
2
17 0
0 3
end_mutex_group
begin_mutex_group
2
18 0
0 14
end_mutex_group
begin_mutex_group
2
19 0
0 13
end_mutex_group
begin_mutex_group
2
20 0
0 11
end_mutex_group
begin_mutex_group
2
21 0
0 10
end_mutex_group
begin_mutex_group
2
22 0
0 8
end_mutex_group
begin_mutex_group
2
23 0
0 7
end_mutex_group
begin_mutex_group
2
24 0
0 6
end_mutex_group
begin_mutex_group
2
25 0
0 5
end_mutex_group
begin_mutex_group
2
26 0
0 4
end_mutex_group
begin_mutex_group
15
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
end_mutex_group
begin_mutex_group
2
1 0
1 1
end_mutex_group
begin_mutex_group
4
1 0
1 1
0 9
0 12
end_mutex_group
begin_mutex_group
3
1 0
1 1
1 2
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
1
1
end_state
begin_goal
1
0 9
end_goal
41
begin_operator
move_seg_pp_0_60_seg_ppdoor_0_40_north_north_medium airplane_daewh
2
1 1
2 1
4
0 0 0 1
0 3 0 1
0 15 0 1
0 27 -1 0
0
end_operator
begin_operator
move_seg_ppdoor_0_40_seg_tww1_0_200_north_south_medium airplane_daewh
2
1 1
17 0
7
0 0 1 2
0 2 1 0
0 4 0 1
0 5 -1 1
0 15 -1 0
0 16 0 1
0 28 -1 0
0
end_operator
begin_operator
move_seg_tww1_0_200_seg_twe1_0_200_north_south_medium airplane_daewh
2
1 1
15 0
7
0 0 2 3
0 2 1 0
0 3 -1 1
0 5 0 1
0 6 -1 0
0 16 -1 0
0 17 0 1
0
end_operator
begin_operator
move_seg_twe1_0_200_seg_twe2_0_50_south_south_medium airplane_daewh
2
1 1
2 0
6
0 0 3 4
0 3 -1 0
0 4 -1 0
0 14 0 1
0 17 -1 0
0 26 0 1
0
end_operator
begin_operator
move_seg_twe2_0_50_seg_twe3_0_50_south_south_medium airplane_daewh
2
1 1
2 0
5
0 0 4 5
0 5 -1 0
0 13 0 1
0 25 0 1
0 26 -1 0
0
end_operator
begin_operator
move_seg_twe3_0_50_seg_twe4_0_50_south_south_medium airplane_daewh
2
1 1
2 0
5
0 0 5 6
0 12 0 1
0 14 -1 0
0 24 0 1
0 25 -1 0
0
end_operator
begin_operator
move_seg_twe4_0_50_seg_rwe_0_50_south_south_medium airplane_daewh
2
1 1
2 0
5
0 0 6 7
0 11 0 1
0 13 -1 0
0 23 0 1
0 24 -1 0
0
end_operator
begin_operator
move_seg_rwe_0_50_seg_rw_0_400_south_south_medium airplane_daewh
2
1 1
2 0
5
0 0 7 8
0 10 0 1
0 12 -1 0
0 22 0 1
0 23 -1 0
0
end_operator
begin_operator
move_seg_rw_0_400_seg_rww_0_50_south_south_medium airplane_daewh
3
1 1
2 0
23 0
4
0 0 8 10
0 9 0 1
0 21 0 1
0 22 -1 0
0
end_operator
begin_operator
move_seg_rww_0_50_seg_tww4_0_50_south_north_medium airplane_daewh
1
1 1
7
0 0 10 11
0 2 0 1
0 8 0 1
0 10 -1 0
0 11 -1 0
0 20 0 1
0 21 -1 0
0
end_operator
begin_operator
move_seg_tww4_0_50_seg_tww3_0_50_north_north_medium airplane_daewh
2
1 1
2 1
5
0 0 11 13
0 7 0 1
0 9 -1 0
0 19 0 1
0 20 -1 0
0
end_operator
begin_operator
move_seg_tww3_0_50_seg_tww2_0_50_north_north_medium airplane_daewh
2
1 1
2 1
5
0 0 13 14
0 6 0 1
0 8 -1 0
0 18 0 1
0 19 -1 0
0
end_operator
begin_operator
move_seg_tww2_0_50_seg_tww1_0_200_north_north_medium airplane_daewh
2
1 1
2 1
5
0 0 14 2
0 4 0 1
0 7 -1 0
0 16 0 1
0 18 -1 0
0
end_operator
begin_operator
move_seg_tww1_0_200_seg_ppdoor_0_40_north_south_medium airplane_daewh
2
1 1
17 0
7
0 0 2 1
0 2 1 0
0 3 0 1
0 5 -1 1
0 6 -1 0
0 15 0 1
0 16 -1 0
0
end_operator
begin_operator
move_seg_ppdoor_0_40_seg_pp_0_60_south_south_medium airplane_daewh
2
1 1
2 0
6
0 0 1 0
0 4 -1 0
0 5 -1 0
0 15 -1 0
0 27 0 1
0 28 0 1
0
end_operator
begin_operator
pushback_seg_pp_0_60_seg_ppdoor_0_40_south_south_medium airplane_daewh
2
1 0
2 0
5
0 0 0 1
0 3 0 1
0 15 0 1
0 27 -1 0
0 28 -1 0
0
end_operator
begin_operator
pushback_seg_ppdoor_0_40_seg_tww1_0_200_south_north_medium airplane_daewh
1
1 0
6
0 0 1 2
0 2 0 1
0 3 -1 0
0 4 0 1
0 15 -1 0
0 16 0 1
0
end_operator
begin_operator
takeoff_seg_rww_0_50_north airplane_daewh
1
2 1
5
0 0 10 12
0 1 1 3
0 8 -1 0
0 9 -1 0
0 21 -1 0
0
end_operator
begin_operator
takeoff_seg_rwe_0_50_south airplane_daewh
1
2 0
5
0 0 7 9
0 1 1 3
0 11 -1 0
0 12 -1 0
0 23 -1 0
0
end_operator
begin_operator
park_seg_pp_0_60_north airplane_daewh
2
0 0
2 1
1
0 1 1 2
0
end_operator
begin_operator
park_seg_pp_0_60_south airplane_daewh
2
0 0
2 0
2
0 1 1 2
0 3 -1 0
0
end_operator
begin_operator
startup_seg_pp_0_60_north_medium airplane_daewh
1
0 0
1
0 1 0 1
0
end_operator
begin_operator
startup_seg_pp_0_60_south_medium airplane_daewh
2
0 0
15 0
2
0 1 0 1
0 3 -1 1
0
end_operator
begin_operator
startup_seg_ppdoor_0_40_north_medium airplane_daewh
2
0 1
27 0
2
0 1 0 1
0 28 -1 1
0
end_operator
begin_operator
startup_seg_ppdoor_0_40_south_medium airplane_daewh
3
0 1
16 0
17 0
3
0 1 0 1
0 4 -1 1
0 5 -1 1
0
end_operator
begin_operator
startup_seg_tww1_0_200_north_medium airplane_daewh
2
0 2
18 0
2
0 1 0 1
0 6 -1 1
0
end_operator
begin_operator
startup_seg_tww1_0_200_south_medium airplane_daewh
3
0 2
15 0
17 0
3
0 1 0 1
0 3 -1 1
0 5 -1 1
0
end_operator
begin_operator
startup_seg_twe1_0_200_north_medium airplane_daewh
2
0 3
26 0
2
0 1 0 1
0 14 -1 1
0
end_operator
begin_operator
startup_seg_twe1_0_200_south_medium airplane_daewh
3
0 3
15 0
16 0
3
0 1 0 1
0 3 -1 1
0 4 -1 1
0
end_operator
begin_operator
startup_seg_tww2_0_50_north_medium airplane_daewh
2
0 14
19 0
2
0 1 0 1
0 7 -1 1
0
end_operator
begin_operator
startup_seg_tww2_0_50_south_medium airplane_daewh
2
0 14
16 0
2
0 1 0 1
0 4 -1 1
0
end_operator
begin_operator
startup_seg_tww3_0_50_north_medium airplane_daewh
2
0 13
20 0
2
0 1 0 1
0 8 -1 1
0
end_operator
begin_operator
startup_seg_tww3_0_50_south_medium airplane_daewh
2
0 13
18 0
2
0 1 0 1
0 6 -1 1
0
end_operator
begin_operator
startup_seg_tww4_0_50_north_medium airplane_daewh
2
0 11
21 0
2
0 1 0 1
0 9 -1 1
0
end_operator
begin_operator
startup_seg_tww4_0_50_south_medium airplane_daewh
2
0 11
19 0
2
0 1 0 1
0 7 -1 1
0
end_operator
begin_operator
startup_seg_twe4_0_50_north_medium airplane_daewh
2
0 6
23 0
2
0 1 0 1
0 11 -1 1
0
end_operator
begin_operator
startup_seg_twe4_0_50_south_medium airplane_daewh
2
0 6
25 0
2
0 1 0 1
0 13 -1 1
0
end_operator
begin_operator
startup_seg_twe3_0_50_north_medium airplane_daewh
2
0 5
24 0
2
0 1 0 1
0 12 -1 1
0
end_operator
begin_operator
startup_seg_twe3_0_50_south_medium airplane_daewh
2
0 5
26 0
2
0 1 0 1
0 14 -1 1
0
end_operator
begin_operator
startup_seg_twe2_0_50_north_medium airplane_daewh
2
0 4
25 0
2
0 1 0 1
0 13 -1 1
0
end_operator
begin_operator
startup_seg_twe2_0_50_south_medium airplane_daewh
2
0 4
17 0
2
0 1 0 1
0 5 -1 1
0
end_operator
0
