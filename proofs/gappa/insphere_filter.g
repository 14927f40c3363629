# proofs/gappa/insphere_filter.g: Gappa model of the stage-A filter
# exactmesh::predicates::insphere_filter (predicates/insphere.hpp).
#
# Proves: with all differences scaled by one power of two (the lifts mix x, y and z)
#   so that m = max(mx, my, mz) lies in [1, 2),
#     |det - Det| <= insphere_filter_eps   and no intermediate overflows below insphere_filter_max,
# where det is the double the filter computes and Det the exact determinant of the exact
# differences. proofs/invariants/filters.md turns this into the soundness of the filter.
#
# Model:
# - Lower-case names are the doubles of the C++ code (same names); Capitalised names are exact
#   reals: Aex = (a[0] - e[0]) / 2^k exactly. Products and sums the code leaves unnamed are named
#   after their operands (aex_bey = fl(aex * bey)).
# - Every computed difference is at most 2 - 2^-52 in magnitude (a double no larger than a
#   maximum < 2), so every exact difference is below 2 - 2^-53 (from there up, reals round to 2
#   or more).
# - rnd is binary64 round-to-nearest-even with an unbounded exponent range. Differences and
#   sums of two doubles are rounded exactly so: when such a result underflows it is exact.
#   A product may underflow: fl(x) = rnd(x) + u with |u| < 2^-1074 at real scale, hence
#   |u| <= 2^(-1074 + 5 L) in normalised units when
#   m >= insphere_filter_min = 2^-L;
#   5 is the degree of insphere, and products of lower degree underflow at a finer level still.
# - Built with -ffp-contract=off and SSE2/AArch64 doubles: no FMA, no extended precision;
#   C++ evaluates a + b + c as (a + b) + c.
#
# Placeholders, filled in from predicates/filter_constants.hpp by proofs/check_constants.cmake
# (CTest test proofs.insphere_filter):
#     @EPS@        insphere_filter_eps
#     @UNDERFLOW@  2^(-1074 + 5 L), L = -log2(insphere_filter_min)
#     @OVERFLOW@   2^(1023 - 5 M), M = log2(insphere_filter_max): at real scale a computed value
#                  is at most 2^(5 M) times larger, so it stays below 2^1023, finite
# Print the best bound this script proves, rounded up to a double:
#     cmake -DPRED=insphere -DMODE=bound -P proofs/check_constants.cmake
#
# -Eprecision=200: the default 60 bits cannot represent (2 - 2^-52)^2 and similar interval
# ends, and loses a binade at the top of a range. -Echange-threshold=0: keep improvements of
# an ulp, which the default (1 %) discards. -Eno-auto-dichotomy: the hints suffice, and the
# check that the next double below the constant is NOT provable then fails in seconds; the
# same engine settings hold for the proof, the failure and the bound.
#@ -Eprecision=200
#@ -Echange-threshold=0
#@ -Eno-auto-dichotomy

@rnd = float<53, ne>;   # binary64 rounding to nearest, no underflow (see header)

# Rounded coordinate differences (rounding of a difference of doubles never underflows).
aex = rnd(Aex); bex = rnd(Bex); cex = rnd(Cex); dex = rnd(Dex);
aey = rnd(Aey); bey = rnd(Bey); cey = rnd(Cey); dey = rnd(Dey);
aez = rnd(Aez); bez = rnd(Bez); cez = rnd(Cez); dez = rnd(Dez);

# The evaluation, operation by operation, in the C++ order; lower case = computed,
# Capitalised = the same quantity computed exactly from the exact differences.
# const double ab = aex * bey - bex * aey, bc = ..., cd, da, ac, bd alike;
aex_bey = rnd(aex * bey) + u1;
bex_aey = rnd(bex * aey) + u2;
ab = rnd(aex_bey - bex_aey);  AB = Aex * Bey - Bex * Aey;
bex_cey = rnd(bex * cey) + u3;
cex_bey = rnd(cex * bey) + u4;
bc = rnd(bex_cey - cex_bey);  BC = Bex * Cey - Cex * Bey;
cex_dey = rnd(cex * dey) + u5;
dex_cey = rnd(dex * cey) + u6;
cd = rnd(cex_dey - dex_cey);  CD = Cex * Dey - Dex * Cey;
dex_aey = rnd(dex * aey) + u7;
aex_dey = rnd(aex * dey) + u8;
da = rnd(dex_aey - aex_dey);  DA = Dex * Aey - Aex * Dey;
aex_cey = rnd(aex * cey) + u9;
cex_aey = rnd(cex * aey) + u10;
ac = rnd(aex_cey - cex_aey);  AC = Aex * Cey - Cex * Aey;
bex_dey = rnd(bex * dey) + u11;
dex_bey = rnd(dex * bey) + u12;
bd = rnd(bex_dey - dex_bey);  BD = Bex * Dey - Dex * Bey;

# const double abc = aez * bc - bez * ac + cez * ab;   = (aez*bc - bez*ac) + cez*ab
# bcd = bez * cd - cez * bd + dez * bc;  cda = cez * da + dez * ac + aez * cd;
# dab = dez * ab + aez * bd + bez * da;  each (x + y) + z
aez_bc = rnd(aez * bc) + u13;
bez_ac = rnd(bez * ac) + u14;
abc_1 = rnd(aez_bc - bez_ac);  ABC_1 = Aez * BC - Bez * AC;
cez_ab = rnd(cez * ab) + u15;
abc = rnd(abc_1 + cez_ab);  ABC = ABC_1 + Cez * AB;
bez_cd = rnd(bez * cd) + u16;
cez_bd = rnd(cez * bd) + u17;
bcd_1 = rnd(bez_cd - cez_bd);  BCD_1 = Bez * CD - Cez * BD;
dez_bc = rnd(dez * bc) + u18;
bcd = rnd(bcd_1 + dez_bc);  BCD = BCD_1 + Dez * BC;
cez_da = rnd(cez * da) + u19;
dez_ac = rnd(dez * ac) + u20;
cda_1 = rnd(cez_da + dez_ac);  CDA_1 = Cez * DA + Dez * AC;
aez_cd = rnd(aez * cd) + u21;
cda = rnd(cda_1 + aez_cd);  CDA = CDA_1 + Aez * CD;
dez_ab = rnd(dez * ab) + u22;
aez_bd = rnd(aez * bd) + u23;
dab_1 = rnd(dez_ab + aez_bd);  DAB_1 = Dez * AB + Aez * BD;
bez_da = rnd(bez * da) + u24;
dab = rnd(dab_1 + bez_da);  DAB = DAB_1 + Bez * DA;

# const double alift = aex * aex + aey * aey + aez * aez;  = (x + y) + z; b, c, d alike
aex_aex = rnd(aex * aex) + u25;
aey_aey = rnd(aey * aey) + u26;
aez_aez = rnd(aez * aez) + u27;
alift_1 = rnd(aex_aex + aey_aey);  Alift_1 = Aex * Aex + Aey * Aey;
alift = rnd(alift_1 + aez_aez);  Alift = Alift_1 + Aez * Aez;
bex_bex = rnd(bex * bex) + u28;
bey_bey = rnd(bey * bey) + u29;
bez_bez = rnd(bez * bez) + u30;
blift_1 = rnd(bex_bex + bey_bey);  Blift_1 = Bex * Bex + Bey * Bey;
blift = rnd(blift_1 + bez_bez);  Blift = Blift_1 + Bez * Bez;
cex_cex = rnd(cex * cex) + u31;
cey_cey = rnd(cey * cey) + u32;
cez_cez = rnd(cez * cez) + u33;
clift_1 = rnd(cex_cex + cey_cey);  Clift_1 = Cex * Cex + Cey * Cey;
clift = rnd(clift_1 + cez_cez);  Clift = Clift_1 + Cez * Cez;
dex_dex = rnd(dex * dex) + u34;
dey_dey = rnd(dey * dey) + u35;
dez_dez = rnd(dez * dez) + u36;
dlift_1 = rnd(dex_dex + dey_dey);  Dlift_1 = Dex * Dex + Dey * Dey;
dlift = rnd(dlift_1 + dez_dez);  Dlift = Dlift_1 + Dez * Dez;

# const double det = (dlift * abc - clift * dab) + (blift * cda - alift * bcd);
dlift_abc = rnd(dlift * abc) + u37;
clift_dab = rnd(clift * dab) + u38;
det_1 = rnd(dlift_abc - clift_dab);  Det_1 = Dlift * ABC - Clift * DAB;
blift_cda = rnd(blift * cda) + u39;
alift_bcd = rnd(alift * bcd) + u40;
det_2 = rnd(blift_cda - alift_bcd);  Det_2 = Blift * CDA - Alift * BCD;
det = rnd(det_1 + det_2);  Det = Det_1 + Det_2;

# 18014398509481983b-53 = 2 - 2^-53 and 9007199254740991b-52 = 2 - 2^-52.
{ |Aex| <= 18014398509481983b-53 /\ |Bex| <= 18014398509481983b-53 /\
  |Cex| <= 18014398509481983b-53 /\ |Dex| <= 18014398509481983b-53 /\
  |Aey| <= 18014398509481983b-53 /\ |Bey| <= 18014398509481983b-53 /\
  |Cey| <= 18014398509481983b-53 /\ |Dey| <= 18014398509481983b-53 /\
  |Aez| <= 18014398509481983b-53 /\ |Bez| <= 18014398509481983b-53 /\
  |Cez| <= 18014398509481983b-53 /\ |Dez| <= 18014398509481983b-53 /\
  |aex| <= 9007199254740991b-52 /\ |bex| <= 9007199254740991b-52 /\
  |cex| <= 9007199254740991b-52 /\ |dex| <= 9007199254740991b-52 /\
  |aey| <= 9007199254740991b-52 /\ |bey| <= 9007199254740991b-52 /\
  |cey| <= 9007199254740991b-52 /\ |dey| <= 9007199254740991b-52 /\
  |aez| <= 9007199254740991b-52 /\ |bez| <= 9007199254740991b-52 /\
  |cez| <= 9007199254740991b-52 /\ |dez| <= 9007199254740991b-52 /\
  |u1| <= @UNDERFLOW@ /\ |u2| <= @UNDERFLOW@ /\ |u3| <= @UNDERFLOW@ /\ |u4| <= @UNDERFLOW@ /\
  |u5| <= @UNDERFLOW@ /\ |u6| <= @UNDERFLOW@ /\ |u7| <= @UNDERFLOW@ /\ |u8| <= @UNDERFLOW@ /\
  |u9| <= @UNDERFLOW@ /\ |u10| <= @UNDERFLOW@ /\ |u11| <= @UNDERFLOW@ /\ |u12| <= @UNDERFLOW@ /\
  |u13| <= @UNDERFLOW@ /\ |u14| <= @UNDERFLOW@ /\ |u15| <= @UNDERFLOW@ /\ |u16| <= @UNDERFLOW@ /\
  |u17| <= @UNDERFLOW@ /\ |u18| <= @UNDERFLOW@ /\ |u19| <= @UNDERFLOW@ /\ |u20| <= @UNDERFLOW@ /\
  |u21| <= @UNDERFLOW@ /\ |u22| <= @UNDERFLOW@ /\ |u23| <= @UNDERFLOW@ /\ |u24| <= @UNDERFLOW@ /\
  |u25| <= @UNDERFLOW@ /\ |u26| <= @UNDERFLOW@ /\ |u27| <= @UNDERFLOW@ /\ |u28| <= @UNDERFLOW@ /\
  |u29| <= @UNDERFLOW@ /\ |u30| <= @UNDERFLOW@ /\ |u31| <= @UNDERFLOW@ /\ |u32| <= @UNDERFLOW@ /\
  |u33| <= @UNDERFLOW@ /\ |u34| <= @UNDERFLOW@ /\ |u35| <= @UNDERFLOW@ /\ |u36| <= @UNDERFLOW@ /\
  |u37| <= @UNDERFLOW@ /\ |u38| <= @UNDERFLOW@ /\ |u39| <= @UNDERFLOW@ /\ |u40| <= @UNDERFLOW@
  -> |det - Det| <= @EPS@ /\
     # No overflow: every computed value is below 2^(1023 - 5 M) in normalised units.
     |aex_bey| <= @OVERFLOW@ /\ |bex_aey| <= @OVERFLOW@ /\ |ab| <= @OVERFLOW@ /\
     |bex_cey| <= @OVERFLOW@ /\ |cex_bey| <= @OVERFLOW@ /\ |bc| <= @OVERFLOW@ /\
     |cex_dey| <= @OVERFLOW@ /\ |dex_cey| <= @OVERFLOW@ /\ |cd| <= @OVERFLOW@ /\
     |dex_aey| <= @OVERFLOW@ /\ |aex_dey| <= @OVERFLOW@ /\ |da| <= @OVERFLOW@ /\
     |aex_cey| <= @OVERFLOW@ /\ |cex_aey| <= @OVERFLOW@ /\ |ac| <= @OVERFLOW@ /\
     |bex_dey| <= @OVERFLOW@ /\ |dex_bey| <= @OVERFLOW@ /\ |bd| <= @OVERFLOW@ /\
     |aez_bc| <= @OVERFLOW@ /\ |bez_ac| <= @OVERFLOW@ /\ |abc_1| <= @OVERFLOW@ /\
     |cez_ab| <= @OVERFLOW@ /\ |abc| <= @OVERFLOW@ /\ |bez_cd| <= @OVERFLOW@ /\
     |cez_bd| <= @OVERFLOW@ /\ |bcd_1| <= @OVERFLOW@ /\ |dez_bc| <= @OVERFLOW@ /\
     |bcd| <= @OVERFLOW@ /\ |cez_da| <= @OVERFLOW@ /\ |dez_ac| <= @OVERFLOW@ /\
     |cda_1| <= @OVERFLOW@ /\ |aez_cd| <= @OVERFLOW@ /\ |cda| <= @OVERFLOW@ /\
     |dez_ab| <= @OVERFLOW@ /\ |aez_bd| <= @OVERFLOW@ /\ |dab_1| <= @OVERFLOW@ /\
     |bez_da| <= @OVERFLOW@ /\ |dab| <= @OVERFLOW@ /\ |aex_aex| <= @OVERFLOW@ /\
     |aey_aey| <= @OVERFLOW@ /\ |aez_aez| <= @OVERFLOW@ /\ |alift_1| <= @OVERFLOW@ /\
     |alift| <= @OVERFLOW@ /\ |bex_bex| <= @OVERFLOW@ /\ |bey_bey| <= @OVERFLOW@ /\
     |bez_bez| <= @OVERFLOW@ /\ |blift_1| <= @OVERFLOW@ /\ |blift| <= @OVERFLOW@ /\
     |cex_cex| <= @OVERFLOW@ /\ |cey_cey| <= @OVERFLOW@ /\ |cez_cez| <= @OVERFLOW@ /\
     |clift_1| <= @OVERFLOW@ /\ |clift| <= @OVERFLOW@ /\ |dex_dex| <= @OVERFLOW@ /\
     |dey_dey| <= @OVERFLOW@ /\ |dez_dez| <= @OVERFLOW@ /\ |dlift_1| <= @OVERFLOW@ /\
     |dlift| <= @OVERFLOW@ /\ |dlift_abc| <= @OVERFLOW@ /\ |clift_dab| <= @OVERFLOW@ /\
     |det_1| <= @OVERFLOW@ /\ |blift_cda| <= @OVERFLOW@ /\ |alift_bcd| <= @OVERFLOW@ /\
     |det_2| <= @OVERFLOW@ /\ |det| <= @OVERFLOW@ }

# Hints: split each error into the rounding error of the operation, the underflow term,
# and the propagated error of its operands.
aex_bey - Aex * Bey -> (rnd(aex * bey) - aex * bey) + u1 + (aex * bey - Aex * Bey);
bex_aey - Bex * Aey -> (rnd(bex * aey) - bex * aey) + u2 + (bex * aey - Bex * Aey);
ab - AB -> (ab - (aex_bey - bex_aey)) + ((aex_bey - Aex * Bey) - (bex_aey - Bex * Aey));
bex_cey - Bex * Cey -> (rnd(bex * cey) - bex * cey) + u3 + (bex * cey - Bex * Cey);
cex_bey - Cex * Bey -> (rnd(cex * bey) - cex * bey) + u4 + (cex * bey - Cex * Bey);
bc - BC -> (bc - (bex_cey - cex_bey)) + ((bex_cey - Bex * Cey) - (cex_bey - Cex * Bey));
cex_dey - Cex * Dey -> (rnd(cex * dey) - cex * dey) + u5 + (cex * dey - Cex * Dey);
dex_cey - Dex * Cey -> (rnd(dex * cey) - dex * cey) + u6 + (dex * cey - Dex * Cey);
cd - CD -> (cd - (cex_dey - dex_cey)) + ((cex_dey - Cex * Dey) - (dex_cey - Dex * Cey));
dex_aey - Dex * Aey -> (rnd(dex * aey) - dex * aey) + u7 + (dex * aey - Dex * Aey);
aex_dey - Aex * Dey -> (rnd(aex * dey) - aex * dey) + u8 + (aex * dey - Aex * Dey);
da - DA -> (da - (dex_aey - aex_dey)) + ((dex_aey - Dex * Aey) - (aex_dey - Aex * Dey));
aex_cey - Aex * Cey -> (rnd(aex * cey) - aex * cey) + u9 + (aex * cey - Aex * Cey);
cex_aey - Cex * Aey -> (rnd(cex * aey) - cex * aey) + u10 + (cex * aey - Cex * Aey);
ac - AC -> (ac - (aex_cey - cex_aey)) + ((aex_cey - Aex * Cey) - (cex_aey - Cex * Aey));
bex_dey - Bex * Dey -> (rnd(bex * dey) - bex * dey) + u11 + (bex * dey - Bex * Dey);
dex_bey - Dex * Bey -> (rnd(dex * bey) - dex * bey) + u12 + (dex * bey - Dex * Bey);
bd - BD -> (bd - (bex_dey - dex_bey)) + ((bex_dey - Bex * Dey) - (dex_bey - Dex * Bey));
aez_bc - Aez * BC -> (rnd(aez * bc) - aez * bc) + u13 + (aez * bc - Aez * BC);
bez_ac - Bez * AC -> (rnd(bez * ac) - bez * ac) + u14 + (bez * ac - Bez * AC);
abc_1 - ABC_1 -> (abc_1 - (aez_bc - bez_ac)) + ((aez_bc - Aez * BC) - (bez_ac - Bez * AC));
cez_ab - Cez * AB -> (rnd(cez * ab) - cez * ab) + u15 + (cez * ab - Cez * AB);
abc - ABC -> (abc - (abc_1 + cez_ab)) + ((abc_1 - ABC_1) + (cez_ab - Cez * AB));
bez_cd - Bez * CD -> (rnd(bez * cd) - bez * cd) + u16 + (bez * cd - Bez * CD);
cez_bd - Cez * BD -> (rnd(cez * bd) - cez * bd) + u17 + (cez * bd - Cez * BD);
bcd_1 - BCD_1 -> (bcd_1 - (bez_cd - cez_bd)) + ((bez_cd - Bez * CD) - (cez_bd - Cez * BD));
dez_bc - Dez * BC -> (rnd(dez * bc) - dez * bc) + u18 + (dez * bc - Dez * BC);
bcd - BCD -> (bcd - (bcd_1 + dez_bc)) + ((bcd_1 - BCD_1) + (dez_bc - Dez * BC));
cez_da - Cez * DA -> (rnd(cez * da) - cez * da) + u19 + (cez * da - Cez * DA);
dez_ac - Dez * AC -> (rnd(dez * ac) - dez * ac) + u20 + (dez * ac - Dez * AC);
cda_1 - CDA_1 -> (cda_1 - (cez_da + dez_ac)) + ((cez_da - Cez * DA) + (dez_ac - Dez * AC));
aez_cd - Aez * CD -> (rnd(aez * cd) - aez * cd) + u21 + (aez * cd - Aez * CD);
cda - CDA -> (cda - (cda_1 + aez_cd)) + ((cda_1 - CDA_1) + (aez_cd - Aez * CD));
dez_ab - Dez * AB -> (rnd(dez * ab) - dez * ab) + u22 + (dez * ab - Dez * AB);
aez_bd - Aez * BD -> (rnd(aez * bd) - aez * bd) + u23 + (aez * bd - Aez * BD);
dab_1 - DAB_1 -> (dab_1 - (dez_ab + aez_bd)) + ((dez_ab - Dez * AB) + (aez_bd - Aez * BD));
bez_da - Bez * DA -> (rnd(bez * da) - bez * da) + u24 + (bez * da - Bez * DA);
dab - DAB -> (dab - (dab_1 + bez_da)) + ((dab_1 - DAB_1) + (bez_da - Bez * DA));
aex_aex - Aex * Aex -> (rnd(aex * aex) - aex * aex) + u25 + (aex * aex - Aex * Aex);
aey_aey - Aey * Aey -> (rnd(aey * aey) - aey * aey) + u26 + (aey * aey - Aey * Aey);
aez_aez - Aez * Aez -> (rnd(aez * aez) - aez * aez) + u27 + (aez * aez - Aez * Aez);
alift_1 - Alift_1 ->
    (alift_1 - (aex_aex + aey_aey)) + ((aex_aex - Aex * Aex) + (aey_aey - Aey * Aey));
alift - Alift -> (alift - (alift_1 + aez_aez)) + ((alift_1 - Alift_1) + (aez_aez - Aez * Aez));
bex_bex - Bex * Bex -> (rnd(bex * bex) - bex * bex) + u28 + (bex * bex - Bex * Bex);
bey_bey - Bey * Bey -> (rnd(bey * bey) - bey * bey) + u29 + (bey * bey - Bey * Bey);
bez_bez - Bez * Bez -> (rnd(bez * bez) - bez * bez) + u30 + (bez * bez - Bez * Bez);
blift_1 - Blift_1 ->
    (blift_1 - (bex_bex + bey_bey)) + ((bex_bex - Bex * Bex) + (bey_bey - Bey * Bey));
blift - Blift -> (blift - (blift_1 + bez_bez)) + ((blift_1 - Blift_1) + (bez_bez - Bez * Bez));
cex_cex - Cex * Cex -> (rnd(cex * cex) - cex * cex) + u31 + (cex * cex - Cex * Cex);
cey_cey - Cey * Cey -> (rnd(cey * cey) - cey * cey) + u32 + (cey * cey - Cey * Cey);
cez_cez - Cez * Cez -> (rnd(cez * cez) - cez * cez) + u33 + (cez * cez - Cez * Cez);
clift_1 - Clift_1 ->
    (clift_1 - (cex_cex + cey_cey)) + ((cex_cex - Cex * Cex) + (cey_cey - Cey * Cey));
clift - Clift -> (clift - (clift_1 + cez_cez)) + ((clift_1 - Clift_1) + (cez_cez - Cez * Cez));
dex_dex - Dex * Dex -> (rnd(dex * dex) - dex * dex) + u34 + (dex * dex - Dex * Dex);
dey_dey - Dey * Dey -> (rnd(dey * dey) - dey * dey) + u35 + (dey * dey - Dey * Dey);
dez_dez - Dez * Dez -> (rnd(dez * dez) - dez * dez) + u36 + (dez * dez - Dez * Dez);
dlift_1 - Dlift_1 ->
    (dlift_1 - (dex_dex + dey_dey)) + ((dex_dex - Dex * Dex) + (dey_dey - Dey * Dey));
dlift - Dlift -> (dlift - (dlift_1 + dez_dez)) + ((dlift_1 - Dlift_1) + (dez_dez - Dez * Dez));
dlift_abc - Dlift * ABC -> (rnd(dlift * abc) - dlift * abc) + u37 + (dlift * abc - Dlift * ABC);
clift_dab - Clift * DAB -> (rnd(clift * dab) - clift * dab) + u38 + (clift * dab - Clift * DAB);
det_1 - Det_1 ->
    (det_1 - (dlift_abc - clift_dab)) + ((dlift_abc - Dlift * ABC) - (clift_dab - Clift * DAB));
blift_cda - Blift * CDA -> (rnd(blift * cda) - blift * cda) + u39 + (blift * cda - Blift * CDA);
alift_bcd - Alift * BCD -> (rnd(alift * bcd) - alift * bcd) + u40 + (alift * bcd - Alift * BCD);
det_2 - Det_2 ->
    (det_2 - (blift_cda - alift_bcd)) + ((blift_cda - Blift * CDA) - (alift_bcd - Alift * BCD));
det - Det -> (det - (det_1 + det_2)) + ((det_1 - Det_1) + (det_2 - Det_2));
