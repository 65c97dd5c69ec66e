begin_version
3
end_version
begin_metric
0
end_metric
42
begin_variable
var0
-1
2
Atom on(b0, a1)
NegatedAtom on(b0, a1)
end_variable
begin_variable
var1
-1
2
Atom on(b3, a1)
NegatedAtom on(b3, a1)
end_variable
begin_variable
var2
-1
2
Atom on(b1, a3)
NegatedAtom on(b1, a3)
end_variable
begin_variable
var3
-1
2
Atom on(b2, a1)
NegatedAtom on(b2, a1)
end_variable
begin_variable
var4
-1
2
Atom first(b4, s12)
NegatedAtom first(b4, s12)
end_variable
begin_variable
var5
-1
2
Atom last(b4, s12)
NegatedAtom last(b4, s12)
end_variable
begin_variable
var6
-1
2
Atom first(b5, s13)
NegatedAtom first(b5, s13)
end_variable
begin_variable
var7
-1
2
Atom last(b5, s13)
NegatedAtom last(b5, s13)
end_variable
begin_variable
var8
-1
2
Atom first(b2, s12)
NegatedAtom first(b2, s12)
end_variable
begin_variable
var9
-1
2
Atom last(b2, s12)
NegatedAtom last(b2, s12)
end_variable
begin_variable
var10
-1
2
Atom on(b4, a2)
NegatedAtom on(b4, a2)
end_variable
begin_variable
var11
-1
2
Atom first(b0, s12)
NegatedAtom first(b0, s12)
end_variable
begin_variable
var12
-1
2
Atom last(b0, s12)
NegatedAtom last(b0, s12)
end_variable
begin_variable
var13
-1
2
Atom first(b3, s12)
NegatedAtom first(b3, s12)
end_variable
begin_variable
var14
-1
2
Atom last(b3, s12)
NegatedAtom last(b3, s12)
end_variable
begin_variable
var15
-1
2
Atom first(b2, s13)
NegatedAtom first(b2, s13)
end_variable
begin_variable
var16
-1
2
Atom last(b2, s13)
NegatedAtom last(b2, s13)
end_variable
begin_variable
var17
-1
2
Atom on(b5, a3)
NegatedAtom on(b5, a3)
end_variable
begin_variable
var18
-1
2
Atom first(b0, s13)
NegatedAtom first(b0, s13)
end_variable
begin_variable
var19
-1
2
Atom last(b0, s13)
NegatedAtom last(b0, s13)
end_variable
begin_variable
var20
-1
2
Atom last(b1, s13)
NegatedAtom last(b1, s13)
end_variable
begin_variable
var21
-1
2
Atom first(b1, s13)
NegatedAtom first(b1, s13)
end_variable
begin_variable
var22
-1
2
Atom on(b5, a1)
NegatedAtom on(b5, a1)
end_variable
begin_variable
var23
-1
2
Atom on(b2, a2)
NegatedAtom on(b2, a2)
end_variable
begin_variable
var24
-1
2
Atom on(b4, a1)
NegatedAtom on(b4, a1)
end_variable
begin_variable
var25
-1
2
Atom on(b0, a2)
NegatedAtom on(b0, a2)
end_variable
begin_variable
var26
-1
2
Atom on(b3, a2)
NegatedAtom on(b3, a2)
end_variable
begin_variable
var27
-1
2
Atom on(b2, a3)
NegatedAtom on(b2, a3)
end_variable
begin_variable
var28
-1
2
Atom first(b3, s13)
NegatedAtom first(b3, s13)
end_variable
begin_variable
var29
-1
2
Atom last(b3, s13)
NegatedAtom last(b3, s13)
end_variable
begin_variable
var30
-1
2
Atom on(b0, a3)
NegatedAtom on(b0, a3)
end_variable
begin_variable
var31
-1
2
Atom on(b1, a1)
NegatedAtom on(b1, a1)
end_variable
begin_variable
var32
-1
2
Atom first(b5, s12)
NegatedAtom first(b5, s12)
end_variable
begin_variable
var33
-1
2
Atom last(b5, s12)
NegatedAtom last(b5, s12)
end_variable
begin_variable
var34
-1
2
Atom first(b4, s13)
NegatedAtom first(b4, s13)
end_variable
begin_variable
var35
-1
2
Atom last(b4, s13)
NegatedAtom last(b4, s13)
end_variable
begin_variable
var36
-1
2
Atom on(b3, a3)
NegatedAtom on(b3, a3)
end_variable
begin_variable
var37
-1
2
Atom first(b1, s12)
NegatedAtom first(b1, s12)
end_variable
begin_variable
var38
-1
2
Atom last(b1, s12)
NegatedAtom last(b1, s12)
end_variable
begin_variable
var39
-1
2
Atom on(b5, a2)
NegatedAtom on(b5, a2)
end_variable
begin_variable
var40
-1
2
Atom on(b4, a3)
NegatedAtom on(b4, a3)
end_variable
begin_variable
var41
-1
2
Atom on(b1, a2)
NegatedAtom on(b1, a2)
end_variable
0
begin_state
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
1
1
1
1
1
1
1
1
1
1
1
1
1
1
1
1
1
1
1
1
1
1
1
1
1
1
1
1
1
1
end_state
begin_goal
2
27 0
39 0
end_goal
128
begin_operator
push-unitarypipe s12 b0 a1 a2 b0 oc1b oc1b
1
11 0
3
0 0 0 1
0 12 -1 0
0 25 -1 0
0
end_operator
begin_operator
push-unitarypipe s12 b0 a1 a2 b1 oc1b lco
0
6
0 0 0 1
0 11 -1 0
0 12 -1 0
0 37 0 1
0 38 -1 1
0 41 -1 0
0
end_operator
begin_operator
push-unitarypipe s12 b0 a1 a2 b4 oc1b lco
0
6
0 0 0 1
0 4 0 1
0 5 -1 1
0 10 -1 0
0 11 -1 0
0 12 -1 0
0
end_operator
begin_operator
push-unitarypipe s12 b0 a1 a2 b2 oc1b gasoleo
0
6
0 0 0 1
0 8 0 1
0 9 -1 1
0 11 -1 0
0 12 -1 0
0 23 -1 0
0
end_operator
begin_operator
push-unitarypipe s12 b0 a1 a2 b5 oc1b oca1
0
6
0 0 0 1
0 11 -1 0
0 12 -1 0
0 32 0 1
0 33 -1 1
0 39 -1 0
0
end_operator
begin_operator
push-unitarypipe s12 b3 a1 a2 b3 rat-a rat-a
1
13 0
3
0 1 0 1
0 14 -1 0
0 26 -1 0
0
end_operator
begin_operator
push-unitarypipe s12 b3 a1 a2 b1 rat-a lco
0
6
0 1 0 1
0 13 -1 0
0 14 -1 0
0 37 0 1
0 38 -1 1
0 41 -1 0
0
end_operator
begin_operator
push-unitarypipe s12 b3 a1 a2 b4 rat-a lco
0
6
0 1 0 1
0 4 0 1
0 5 -1 1
0 10 -1 0
0 13 -1 0
0 14 -1 0
0
end_operator
begin_operator
push-unitarypipe s12 b3 a1 a2 b2 rat-a gasoleo
0
6
0 1 0 1
0 8 0 1
0 9 -1 1
0 13 -1 0
0 14 -1 0
0 23 -1 0
0
end_operator
begin_operator
push-unitarypipe s12 b1 a1 a2 b0 lco oc1b
0
6
0 11 0 1
0 12 -1 1
0 25 -1 0
0 31 0 1
0 37 -1 0
0 38 -1 0
0
end_operator
begin_operator
push-unitarypipe s12 b1 a1 a2 b3 lco rat-a
0
6
0 13 0 1
0 14 -1 1
0 26 -1 0
0 31 0 1
0 37 -1 0
0 38 -1 0
0
end_operator
begin_operator
push-unitarypipe s12 b1 a1 a2 b1 lco lco
1
37 0
3
0 31 0 1
0 38 -1 0
0 41 -1 0
0
end_operator
begin_operator
push-unitarypipe s12 b1 a1 a2 b4 lco lco
0
6
0 4 0 1
0 5 -1 1
0 10 -1 0
0 31 0 1
0 37 -1 0
0 38 -1 0
0
end_operator
begin_operator
push-unitarypipe s12 b1 a1 a2 b2 lco gasoleo
0
6
0 8 0 1
0 9 -1 1
0 23 -1 0
0 31 0 1
0 37 -1 0
0 38 -1 0
0
end_operator
begin_operator
push-unitarypipe s12 b1 a1 a2 b5 lco oca1
0
6
0 31 0 1
0 32 0 1
0 33 -1 1
0 37 -1 0
0 38 -1 0
0 39 -1 0
0
end_operator
begin_operator
push-unitarypipe s12 b4 a1 a2 b0 lco oc1b
0
6
0 4 -1 0
0 5 -1 0
0 11 0 1
0 12 -1 1
0 24 0 1
0 25 -1 0
0
end_operator
begin_operator
push-unitarypipe s12 b4 a1 a2 b3 lco rat-a
0
6
0 4 -1 0
0 5 -1 0
0 13 0 1
0 14 -1 1
0 24 0 1
0 26 -1 0
0
end_operator
begin_operator
push-unitarypipe s12 b4 a1 a2 b1 lco lco
0
6
0 4 -1 0
0 5 -1 0
0 24 0 1
0 37 0 1
0 38 -1 1
0 41 -1 0
0
end_operator
begin_operator
push-unitarypipe s12 b4 a1 a2 b4 lco lco
1
4 0
3
0 5 -1 0
0 10 -1 0
0 24 0 1
0
end_operator
begin_operator
push-unitarypipe s12 b4 a1 a2 b2 lco gasoleo
0
6
0 4 -1 0
0 5 -1 0
0 8 0 1
0 9 -1 1
0 23 -1 0
0 24 0 1
0
end_operator
begin_operator
push-unitarypipe s12 b4 a1 a2 b5 lco oca1
0
6
0 4 -1 0
0 5 -1 0
0 24 0 1
0 32 0 1
0 33 -1 1
0 39 -1 0
0
end_operator
begin_operator
push-unitarypipe s12 b2 a1 a2 b0 gasoleo oc1b
0
6
0 3 0 1
0 8 -1 0
0 9 -1 0
0 11 0 1
0 12 -1 1
0 25 -1 0
0
end_operator
begin_operator
push-unitarypipe s12 b2 a1 a2 b3 gasoleo rat-a
0
6
0 3 0 1
0 8 -1 0
0 9 -1 0
0 13 0 1
0 14 -1 1
0 26 -1 0
0
end_operator
begin_operator
push-unitarypipe s12 b2 a1 a2 b1 gasoleo lco
0
6
0 3 0 1
0 8 -1 0
0 9 -1 0
0 37 0 1
0 38 -1 1
0 41 -1 0
0
end_operator
begin_operator
push-unitarypipe s12 b2 a1 a2 b4 gasoleo lco
0
6
0 3 0 1
0 4 0 1
0 5 -1 1
0 8 -1 0
0 9 -1 0
0 10 -1 0
0
end_operator
begin_operator
push-unitarypipe s12 b2 a1 a2 b2 gasoleo gasoleo
1
8 0
3
0 3 0 1
0 9 -1 0
0 23 -1 0
0
end_operator
begin_operator
push-unitarypipe s12 b2 a1 a2 b5 gasoleo oca1
0
6
0 3 0 1
0 8 -1 0
0 9 -1 0
0 32 0 1
0 33 -1 1
0 39 -1 0
0
end_operator
begin_operator
push-unitarypipe s12 b5 a1 a2 b0 oca1 oc1b
0
6
0 11 0 1
0 12 -1 1
0 22 0 1
0 25 -1 0
0 32 -1 0
0 33 -1 0
0
end_operator
begin_operator
push-unitarypipe s12 b5 a1 a2 b1 oca1 lco
0
6
0 22 0 1
0 32 -1 0
0 33 -1 0
0 37 0 1
0 38 -1 1
0 41 -1 0
0
end_operator
begin_operator
push-unitarypipe s12 b5 a1 a2 b4 oca1 lco
0
6
0 4 0 1
0 5 -1 1
0 10 -1 0
0 22 0 1
0 32 -1 0
0 33 -1 0
0
end_operator
begin_operator
push-unitarypipe s12 b5 a1 a2 b2 oca1 gasoleo
0
6
0 8 0 1
0 9 -1 1
0 22 0 1
0 23 -1 0
0 32 -1 0
0 33 -1 0
0
end_operator
begin_operator
push-unitarypipe s12 b5 a1 a2 b5 oca1 oca1
1
32 0
3
0 22 0 1
0 33 -1 0
0 39 -1 0
0
end_operator
begin_operator
push-unitarypipe s13 b0 a1 a3 b0 oc1b oc1b
1
18 0
3
0 0 0 1
0 19 -1 0
0 30 -1 0
0
end_operator
begin_operator
push-unitarypipe s13 b0 a1 a3 b1 oc1b lco
0
6
0 0 0 1
0 2 -1 0
0 18 -1 0
0 19 -1 0
0 20 -1 1
0 21 0 1
0
end_operator
begin_operator
push-unitarypipe s13 b0 a1 a3 b4 oc1b lco
0
6
0 0 0 1
0 18 -1 0
0 19 -1 0
0 34 0 1
0 35 -1 1
0 40 -1 0
0
end_operator
begin_operator
push-unitarypipe s13 b0 a1 a3 b2 oc1b gasoleo
0
6
0 0 0 1
0 15 0 1
0 16 -1 1
0 18 -1 0
0 19 -1 0
0 27 -1 0
0
end_operator
begin_operator
push-unitarypipe s13 b0 a1 a3 b5 oc1b oca1
0
6
0 0 0 1
0 6 0 1
0 7 -1 1
0 17 -1 0
0 18 -1 0
0 19 -1 0
0
end_operator
begin_operator
push-unitarypipe s13 b3 a1 a3 b3 rat-a rat-a
1
28 0
3
0 1 0 1
0 29 -1 0
0 36 -1 0
0
end_operator
begin_operator
push-unitarypipe s13 b3 a1 a3 b1 rat-a lco
0
6
0 1 0 1
0 2 -1 0
0 20 -1 1
0 21 0 1
0 28 -1 0
0 29 -1 0
0
end_operator
begin_operator
push-unitarypipe s13 b3 a1 a3 b4 rat-a lco
0
6
0 1 0 1
0 28 -1 0
0 29 -1 0
0 34 0 1
0 35 -1 1
0 40 -1 0
0
end_operator
begin_operator
push-unitarypipe s13 b3 a1 a3 b2 rat-a gasoleo
0
6
0 1 0 1
0 15 0 1
0 16 -1 1
0 27 -1 0
0 28 -1 0
0 29 -1 0
0
end_operator
begin_operator
push-unitarypipe s13 b1 a1 a3 b0 lco oc1b
0
6
0 18 0 1
0 19 -1 1
0 20 -1 0
0 21 -1 0
0 30 -1 0
0 31 0 1
0
end_operator
begin_operator
push-unitarypipe s13 b1 a1 a3 b3 lco rat-a
0
6
0 20 -1 0
0 21 -1 0
0 28 0 1
0 29 -1 1
0 31 0 1
0 36 -1 0
0
end_operator
begin_operator
push-unitarypipe s13 b1 a1 a3 b1 lco lco
1
21 0
3
0 2 -1 0
0 20 -1 0
0 31 0 1
0
end_operator
begin_operator
push-unitarypipe s13 b1 a1 a3 b4 lco lco
0
6
0 20 -1 0
0 21 -1 0
0 31 0 1
0 34 0 1
0 35 -1 1
0 40 -1 0
0
end_operator
begin_operator
push-unitarypipe s13 b1 a1 a3 b2 lco gasoleo
0
6
0 15 0 1
0 16 -1 1
0 20 -1 0
0 21 -1 0
0 27 -1 0
0 31 0 1
0
end_operator
begin_operator
push-unitarypipe s13 b1 a1 a3 b5 lco oca1
0
6
0 6 0 1
0 7 -1 1
0 17 -1 0
0 20 -1 0
0 21 -1 0
0 31 0 1
0
end_operator
begin_operator
push-unitarypipe s13 b4 a1 a3 b0 lco oc1b
0
6
0 18 0 1
0 19 -1 1
0 24 0 1
0 30 -1 0
0 34 -1 0
0 35 -1 0
0
end_operator
begin_operator
push-unitarypipe s13 b4 a1 a3 b3 lco rat-a
0
6
0 24 0 1
0 28 0 1
0 29 -1 1
0 34 -1 0
0 35 -1 0
0 36 -1 0
0
end_operator
begin_operator
push-unitarypipe s13 b4 a1 a3 b1 lco lco
0
6
0 2 -1 0
0 20 -1 1
0 21 0 1
0 24 0 1
0 34 -1 0
0 35 -1 0
0
end_operator
begin_operator
push-unitarypipe s13 b4 a1 a3 b4 lco lco
1
34 0
3
0 24 0 1
0 35 -1 0
0 40 -1 0
0
end_operator
begin_operator
push-unitarypipe s13 b4 a1 a3 b2 lco gasoleo
0
6
0 15 0 1
0 16 -1 1
0 24 0 1
0 27 -1 0
0 34 -1 0
0 35 -1 0
0
end_operator
begin_operator
push-unitarypipe s13 b4 a1 a3 b5 lco oca1
0
6
0 6 0 1
0 7 -1 1
0 17 -1 0
0 24 0 1
0 34 -1 0
0 35 -1 0
0
end_operator
begin_operator
push-unitarypipe s13 b2 a1 a3 b0 gasoleo oc1b
0
6
0 3 0 1
0 15 -1 0
0 16 -1 0
0 18 0 1
0 19 -1 1
0 30 -1 0
0
end_operator
begin_operator
push-unitarypipe s13 b2 a1 a3 b3 gasoleo rat-a
0
6
0 3 0 1
0 15 -1 0
0 16 -1 0
0 28 0 1
0 29 -1 1
0 36 -1 0
0
end_operator
begin_operator
push-unitarypipe s13 b2 a1 a3 b1 gasoleo lco
0
6
0 2 -1 0
0 3 0 1
0 15 -1 0
0 16 -1 0
0 20 -1 1
0 21 0 1
0
end_operator
begin_operator
push-unitarypipe s13 b2 a1 a3 b4 gasoleo lco
0
6
0 3 0 1
0 15 -1 0
0 16 -1 0
0 34 0 1
0 35 -1 1
0 40 -1 0
0
end_operator
begin_operator
push-unitarypipe s13 b2 a1 a3 b2 gasoleo gasoleo
1
15 0
3
0 3 0 1
0 16 -1 0
0 27 -1 0
0
end_operator
begin_operator
push-unitarypipe s13 b2 a1 a3 b5 gasoleo oca1
0
6
0 3 0 1
0 6 0 1
0 7 -1 1
0 15 -1 0
0 16 -1 0
0 17 -1 0
0
end_operator
begin_operator
push-unitarypipe s13 b5 a1 a3 b0 oca1 oc1b
0
6
0 6 -1 0
0 7 -1 0
0 18 0 1
0 19 -1 1
0 22 0 1
0 30 -1 0
0
end_operator
begin_operator
push-unitarypipe s13 b5 a1 a3 b1 oca1 lco
0
6
0 2 -1 0
0 6 -1 0
0 7 -1 0
0 20 -1 1
0 21 0 1
0 22 0 1
0
end_operator
begin_operator
push-unitarypipe s13 b5 a1 a3 b4 oca1 lco
0
6
0 6 -1 0
0 7 -1 0
0 22 0 1
0 34 0 1
0 35 -1 1
0 40 -1 0
0
end_operator
begin_operator
push-unitarypipe s13 b5 a1 a3 b2 oca1 gasoleo
0
6
0 6 -1 0
0 7 -1 0
0 15 0 1
0 16 -1 1
0 22 0 1
0 27 -1 0
0
end_operator
begin_operator
push-unitarypipe s13 b5 a1 a3 b5 oca1 oca1
1
6 0
3
0 7 -1 0
0 17 -1 0
0 22 0 1
0
end_operator
begin_operator
pop-unitarypipe s12 b0 a1 a2 b0 oc1b oc1b
1
12 0
3
0 0 -1 0
0 11 -1 0
0 25 0 1
0
end_operator
begin_operator
pop-unitarypipe s12 b0 a1 a2 b1 oc1b lco
0
6
0 11 -1 0
0 12 -1 0
0 25 0 1
0 31 -1 0
0 37 -1 1
0 38 0 1
0
end_operator
begin_operator
pop-unitarypipe s12 b0 a1 a2 b4 oc1b lco
0
6
0 4 -1 1
0 5 0 1
0 11 -1 0
0 12 -1 0
0 24 -1 0
0 25 0 1
0
end_operator
begin_operator
pop-unitarypipe s12 b0 a1 a2 b2 oc1b gasoleo
0
6
0 3 -1 0
0 8 -1 1
0 9 0 1
0 11 -1 0
0 12 -1 0
0 25 0 1
0
end_operator
begin_operator
pop-unitarypipe s12 b0 a1 a2 b5 oc1b oca1
0
6
0 11 -1 0
0 12 -1 0
0 22 -1 0
0 25 0 1
0 32 -1 1
0 33 0 1
0
end_operator
begin_operator
pop-unitarypipe s12 b3 a1 a2 b3 rat-a rat-a
1
14 0
3
0 1 -1 0
0 13 -1 0
0 26 0 1
0
end_operator
begin_operator
pop-unitarypipe s12 b3 a1 a2 b1 rat-a lco
0
6
0 13 -1 0
0 14 -1 0
0 26 0 1
0 31 -1 0
0 37 -1 1
0 38 0 1
0
end_operator
begin_operator
pop-unitarypipe s12 b3 a1 a2 b4 rat-a lco
0
6
0 4 -1 1
0 5 0 1
0 13 -1 0
0 14 -1 0
0 24 -1 0
0 26 0 1
0
end_operator
begin_operator
pop-unitarypipe s12 b3 a1 a2 b2 rat-a gasoleo
0
6
0 3 -1 0
0 8 -1 1
0 9 0 1
0 13 -1 0
0 14 -1 0
0 26 0 1
0
end_operator
begin_operator
pop-unitarypipe s12 b1 a1 a2 b0 lco oc1b
0
6
0 0 -1 0
0 11 -1 1
0 12 0 1
0 37 -1 0
0 38 -1 0
0 41 0 1
0
end_operator
begin_operator
pop-unitarypipe s12 b1 a1 a2 b3 lco rat-a
0
6
0 1 -1 0
0 13 -1 1
0 14 0 1
0 37 -1 0
0 38 -1 0
0 41 0 1
0
end_operator
begin_operator
pop-unitarypipe s12 b1 a1 a2 b1 lco lco
1
38 0
3
0 31 -1 0
0 37 -1 0
0 41 0 1
0
end_operator
begin_operator
pop-unitarypipe s12 b1 a1 a2 b4 lco lco
0
6
0 4 -1 1
0 5 0 1
0 24 -1 0
0 37 -1 0
0 38 -1 0
0 41 0 1
0
end_operator
begin_operator
pop-unitarypipe s12 b1 a1 a2 b2 lco gasoleo
0
6
0 3 -1 0
0 8 -1 1
0 9 0 1
0 37 -1 0
0 38 -1 0
0 41 0 1
0
end_operator
begin_operator
pop-unitarypipe s12 b1 a1 a2 b5 lco oca1
0
6
0 22 -1 0
0 32 -1 1
0 33 0 1
0 37 -1 0
0 38 -1 0
0 41 0 1
0
end_operator
begin_operator
pop-unitarypipe s12 b4 a1 a2 b0 lco oc1b
0
6
0 0 -1 0
0 4 -1 0
0 5 -1 0
0 10 0 1
0 11 -1 1
0 12 0 1
0
end_operator
begin_operator
pop-unitarypipe s12 b4 a1 a2 b3 lco rat-a
0
6
0 1 -1 0
0 4 -1 0
0 5 -1 0
0 10 0 1
0 13 -1 1
0 14 0 1
0
end_operator
begin_operator
pop-unitarypipe s12 b4 a1 a2 b1 lco lco
0
6
0 4 -1 0
0 5 -1 0
0 10 0 1
0 31 -1 0
0 37 -1 1
0 38 0 1
0
end_operator
begin_operator
pop-unitarypipe s12 b4 a1 a2 b4 lco lco
1
5 0
3
0 4 -1 0
0 10 0 1
0 24 -1 0
0
end_operator
begin_operator
pop-unitarypipe s12 b4 a1 a2 b2 lco gasoleo
0
6
0 3 -1 0
0 4 -1 0
0 5 -1 0
0 8 -1 1
0 9 0 1
0 10 0 1
0
end_operator
begin_operator
pop-unitarypipe s12 b4 a1 a2 b5 lco oca1
0
6
0 4 -1 0
0 5 -1 0
0 10 0 1
0 22 -1 0
0 32 -1 1
0 33 0 1
0
end_operator
begin_operator
pop-unitarypipe s12 b2 a1 a2 b0 gasoleo oc1b
0
6
0 0 -1 0
0 8 -1 0
0 9 -1 0
0 11 -1 1
0 12 0 1
0 23 0 1
0
end_operator
begin_operator
pop-unitarypipe s12 b2 a1 a2 b3 gasoleo rat-a
0
6
0 1 -1 0
0 8 -1 0
0 9 -1 0
0 13 -1 1
0 14 0 1
0 23 0 1
0
end_operator
begin_operator
pop-unitarypipe s12 b2 a1 a2 b1 gasoleo lco
0
6
0 8 -1 0
0 9 -1 0
0 23 0 1
0 31 -1 0
0 37 -1 1
0 38 0 1
0
end_operator
begin_operator
pop-unitarypipe s12 b2 a1 a2 b4 gasoleo lco
0
6
0 4 -1 1
0 5 0 1
0 8 -1 0
0 9 -1 0
0 23 0 1
0 24 -1 0
0
end_operator
begin_operator
pop-unitarypipe s12 b2 a1 a2 b2 gasoleo gasoleo
1
9 0
3
0 3 -1 0
0 8 -1 0
0 23 0 1
0
end_operator
begin_operator
pop-unitarypipe s12 b2 a1 a2 b5 gasoleo oca1
0
6
0 8 -1 0
0 9 -1 0
0 22 -1 0
0 23 0 1
0 32 -1 1
0 33 0 1
0
end_operator
begin_operator
pop-unitarypipe s12 b5 a1 a2 b0 oca1 oc1b
0
6
0 0 -1 0
0 11 -1 1
0 12 0 1
0 32 -1 0
0 33 -1 0
0 39 0 1
0
end_operator
begin_operator
pop-unitarypipe s12 b5 a1 a2 b1 oca1 lco
0
6
0 31 -1 0
0 32 -1 0
0 33 -1 0
0 37 -1 1
0 38 0 1
0 39 0 1
0
end_operator
begin_operator
pop-unitarypipe s12 b5 a1 a2 b4 oca1 lco
0
6
0 4 -1 1
0 5 0 1
0 24 -1 0
0 32 -1 0
0 33 -1 0
0 39 0 1
0
end_operator
begin_operator
pop-unitarypipe s12 b5 a1 a2 b2 oca1 gasoleo
0
6
0 3 -1 0
0 8 -1 1
0 9 0 1
0 32 -1 0
0 33 -1 0
0 39 0 1
0
end_operator
begin_operator
pop-unitarypipe s12 b5 a1 a2 b5 oca1 oca1
1
33 0
3
0 22 -1 0
0 32 -1 0
0 39 0 1
0
end_operator
begin_operator
pop-unitarypipe s13 b0 a1 a3 b0 oc1b oc1b
1
19 0
3
0 0 -1 0
0 18 -1 0
0 30 0 1
0
end_operator
begin_operator
pop-unitarypipe s13 b0 a1 a3 b1 oc1b lco
0
6
0 18 -1 0
0 19 -1 0
0 20 0 1
0 21 -1 1
0 30 0 1
0 31 -1 0
0
end_operator
begin_operator
pop-unitarypipe s13 b0 a1 a3 b4 oc1b lco
0
6
0 18 -1 0
0 19 -1 0
0 24 -1 0
0 30 0 1
0 34 -1 1
0 35 0 1
0
end_operator
begin_operator
pop-unitarypipe s13 b0 a1 a3 b2 oc1b gasoleo
0
6
0 3 -1 0
0 15 -1 1
0 16 0 1
0 18 -1 0
0 19 -1 0
0 30 0 1
0
end_operator
begin_operator
pop-unitarypipe s13 b0 a1 a3 b5 oc1b oca1
0
6
0 6 -1 1
0 7 0 1
0 18 -1 0
0 19 -1 0
0 22 -1 0
0 30 0 1
0
end_operator
begin_operator
pop-unitarypipe s13 b3 a1 a3 b3 rat-a rat-a
1
29 0
3
0 1 -1 0
0 28 -1 0
0 36 0 1
0
end_operator
begin_operator
pop-unitarypipe s13 b3 a1 a3 b1 rat-a lco
0
6
0 20 0 1
0 21 -1 1
0 28 -1 0
0 29 -1 0
0 31 -1 0
0 36 0 1
0
end_operator
begin_operator
pop-unitarypipe s13 b3 a1 a3 b4 rat-a lco
0
6
0 24 -1 0
0 28 -1 0
0 29 -1 0
0 34 -1 1
0 35 0 1
0 36 0 1
0
end_operator
begin_operator
pop-unitarypipe s13 b3 a1 a3 b2 rat-a gasoleo
0
6
0 3 -1 0
0 15 -1 1
0 16 0 1
0 28 -1 0
0 29 -1 0
0 36 0 1
0
end_operator
begin_operator
pop-unitarypipe s13 b1 a1 a3 b0 lco oc1b
0
6
0 0 -1 0
0 2 0 1
0 18 -1 1
0 19 0 1
0 20 -1 0
0 21 -1 0
0
end_operator
begin_operator
pop-unitarypipe s13 b1 a1 a3 b3 lco rat-a
0
6
0 1 -1 0
0 2 0 1
0 20 -1 0
0 21 -1 0
0 28 -1 1
0 29 0 1
0
end_operator
begin_operator
pop-unitarypipe s13 b1 a1 a3 b1 lco lco
1
20 0
3
0 2 0 1
0 21 -1 0
0 31 -1 0
0
end_operator
begin_operator
pop-unitarypipe s13 b1 a1 a3 b4 lco lco
0
6
0 2 0 1
0 20 -1 0
0 21 -1 0
0 24 -1 0
0 34 -1 1
0 35 0 1
0
end_operator
begin_operator
pop-unitarypipe s13 b1 a1 a3 b2 lco gasoleo
0
6
0 2 0 1
0 3 -1 0
0 15 -1 1
0 16 0 1
0 20 -1 0
0 21 -1 0
0
end_operator
begin_operator
pop-unitarypipe s13 b1 a1 a3 b5 lco oca1
0
6
0 2 0 1
0 6 -1 1
0 7 0 1
0 20 -1 0
0 21 -1 0
0 22 -1 0
0
end_operator
begin_operator
pop-unitarypipe s13 b4 a1 a3 b0 lco oc1b
0
6
0 0 -1 0
0 18 -1 1
0 19 0 1
0 34 -1 0
0 35 -1 0
0 40 0 1
0
end_operator
begin_operator
pop-unitarypipe s13 b4 a1 a3 b3 lco rat-a
0
6
0 1 -1 0
0 28 -1 1
0 29 0 1
0 34 -1 0
0 35 -1 0
0 40 0 1
0
end_operator
begin_operator
pop-unitarypipe s13 b4 a1 a3 b1 lco lco
0
6
0 20 0 1
0 21 -1 1
0 31 -1 0
0 34 -1 0
0 35 -1 0
0 40 0 1
0
end_operator
begin_operator
pop-unitarypipe s13 b4 a1 a3 b4 lco lco
1
35 0
3
0 24 -1 0
0 34 -1 0
0 40 0 1
0
end_operator
begin_operator
pop-unitarypipe s13 b4 a1 a3 b2 lco gasoleo
0
6
0 3 -1 0
0 15 -1 1
0 16 0 1
0 34 -1 0
0 35 -1 0
0 40 0 1
0
end_operator
begin_operator
pop-unitarypipe s13 b4 a1 a3 b5 lco oca1
0
6
0 6 -1 1
0 7 0 1
0 22 -1 0
0 34 -1 0
0 35 -1 0
0 40 0 1
0
end_operator
begin_operator
pop-unitarypipe s13 b2 a1 a3 b0 gasoleo oc1b
0
6
0 0 -1 0
0 15 -1 0
0 16 -1 0
0 18 -1 1
0 19 0 1
0 27 0 1
0
end_operator
begin_operator
pop-unitarypipe s13 b2 a1 a3 b3 gasoleo rat-a
0
6
0 1 -1 0
0 15 -1 0
0 16 -1 0
0 27 0 1
0 28 -1 1
0 29 0 1
0
end_operator
begin_operator
pop-unitarypipe s13 b2 a1 a3 b1 gasoleo lco
0
6
0 15 -1 0
0 16 -1 0
0 20 0 1
0 21 -1 1
0 27 0 1
0 31 -1 0
0
end_operator
begin_operator
pop-unitarypipe s13 b2 a1 a3 b4 gasoleo lco
0
6
0 15 -1 0
0 16 -1 0
0 24 -1 0
0 27 0 1
0 34 -1 1
0 35 0 1
0
end_operator
begin_operator
pop-unitarypipe s13 b2 a1 a3 b2 gasoleo gasoleo
1
16 0
3
0 3 -1 0
0 15 -1 0
0 27 0 1
0
end_operator
begin_operator
pop-unitarypipe s13 b2 a1 a3 b5 gasoleo oca1
0
6
0 6 -1 1
0 7 0 1
0 15 -1 0
0 16 -1 0
0 22 -1 0
0 27 0 1
0
end_operator
begin_operator
pop-unitarypipe s13 b5 a1 a3 b0 oca1 oc1b
0
6
0 0 -1 0
0 6 -1 0
0 7 -1 0
0 17 0 1
0 18 -1 1
0 19 0 1
0
end_operator
begin_operator
pop-unitarypipe s13 b5 a1 a3 b1 oca1 lco
0
6
0 6 -1 0
0 7 -1 0
0 17 0 1
0 20 0 1
0 21 -1 1
0 31 -1 0
0
end_operator
begin_operator
pop-unitarypipe s13 b5 a1 a3 b4 oca1 lco
0
6
0 6 -1 0
0 7 -1 0
0 17 0 1
0 24 -1 0
0 34 -1 1
0 35 0 1
0
end_operator
begin_operator
pop-unitarypipe s13 b5 a1 a3 b2 oca1 gasoleo
0
6
0 3 -1 0
0 6 -1 0
0 7 -1 0
0 15 -1 1
0 16 0 1
0 17 0 1
0
end_operator
begin_operator
pop-unitarypipe s13 b5 a1 a3 b5 oca1 oca1
1
7 0
3
0 6 -1 0
0 17 0 1
0 22 -1 0
0
end_operator
0
