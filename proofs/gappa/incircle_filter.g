# proofs/gappa/incircle_filter.g: Gappa model of the stage-A filter
# exactmesh::predicates::incircle_filter (predicates/incircle.hpp).
#
# Proves: with all differences scaled by one power of two (the lifts mix x and y) so
#   that m = max(maxx, maxy) lies in [1, 2),
#     |det - Det| <= incircle_filter_eps   and no intermediate overflows below incircle_filter_max,
# where det is the double the filter computes and Det the exact determinant of the exact
# differences. proofs/invariants/filters.md turns this into the soundness of the filter.
#
# Model:
# - Lower-case names are the doubles of the C++ code (same names); Capitalised names are exact
#   reals: Adx = (a[0] - d[0]) / 2^k exactly. Products and sums the code leaves unnamed are named
#   after their operands (adx_adx = fl(adx * adx)).
# - Every computed difference is at most 2 - 2^-52 in magnitude (a double no larger than a
#   maximum < 2), so every exact difference is below 2 - 2^-53 (from there up, reals round to 2
#   or more).
# - rnd is binary64 round-to-nearest-even with an unbounded exponent range. Differences and
#   sums of two doubles are rounded exactly so: when such a result underflows it is exact.
#   A product may underflow: fl(x) = rnd(x) + u with |u| < 2^-1074 at real scale, hence
#   |u| <= 2^(-1074 + 4 L) in normalised units when
#   m >= incircle_filter_min = 2^-L;
#   4 is the degree of incircle, and products of lower degree underflow at a finer level still.
# - Built with -ffp-contract=off and SSE2/AArch64 doubles: no FMA, no extended precision;
#   C++ evaluates a + b + c as (a + b) + c.
#
# Placeholders, filled in from predicates/filter_constants.hpp by proofs/check_constants.cmake
# (CTest test proofs.incircle_filter):
#     @EPS@        incircle_filter_eps
#     @UNDERFLOW@  2^(-1074 + 4 L), L = -log2(incircle_filter_min)
#     @OVERFLOW@   2^(1023 - 4 M), M = log2(incircle_filter_max): at real scale a computed value
#                  is at most 2^(4 M) times larger, so it stays below 2^1023, finite
# Print the best bound this script proves, rounded up to a double:
#     cmake -DPRED=incircle -DMODE=bound -P proofs/check_constants.cmake
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
adx = rnd(Adx); ady = rnd(Ady); bdx = rnd(Bdx); bdy = rnd(Bdy);
cdx = rnd(Cdx); cdy = rnd(Cdy);

# The evaluation, operation by operation, in the C++ order; lower case = computed,
# Capitalised = the same quantity computed exactly from the exact differences.
# const double alift = adx * adx + ady * ady;  (blift, clift alike)
adx_adx = rnd(adx * adx) + u1;
ady_ady = rnd(ady * ady) + u2;
alift = rnd(adx_adx + ady_ady);  Alift = Adx * Adx + Ady * Ady;
bdx_bdx = rnd(bdx * bdx) + u3;
bdy_bdy = rnd(bdy * bdy) + u4;
blift = rnd(bdx_bdx + bdy_bdy);  Blift = Bdx * Bdx + Bdy * Bdy;
cdx_cdx = rnd(cdx * cdx) + u5;
cdy_cdy = rnd(cdy * cdy) + u6;
clift = rnd(cdx_cdx + cdy_cdy);  Clift = Cdx * Cdx + Cdy * Cdy;

# const double det = alift * (bdx * cdy - cdx * bdy) + blift * (cdx * ady - adx * cdy) +
#                    clift * (adx * bdy - bdx * ady);
#   = ((alift * minor_a) + (blift * minor_b)) + (clift * minor_c)
bdx_cdy = rnd(bdx * cdy) + u7;
cdx_bdy = rnd(cdx * bdy) + u8;
minor_a = rnd(bdx_cdy - cdx_bdy);  Minor_a = Bdx * Cdy - Cdx * Bdy;
cdx_ady = rnd(cdx * ady) + u9;
adx_cdy = rnd(adx * cdy) + u10;
minor_b = rnd(cdx_ady - adx_cdy);  Minor_b = Cdx * Ady - Adx * Cdy;
adx_bdy = rnd(adx * bdy) + u11;
bdx_ady = rnd(bdx * ady) + u12;
minor_c = rnd(adx_bdy - bdx_ady);  Minor_c = Adx * Bdy - Bdx * Ady;
term_a = rnd(alift * minor_a) + u13;
term_b = rnd(blift * minor_b) + u14;
term_c = rnd(clift * minor_c) + u15;
sum_ab = rnd(term_a + term_b);  Sum_ab = Alift * Minor_a + Blift * Minor_b;
det = rnd(sum_ab + term_c);  Det = Sum_ab + Clift * Minor_c;

# 18014398509481983b-53 = 2 - 2^-53 and 9007199254740991b-52 = 2 - 2^-52.
{ |Adx| <= 18014398509481983b-53 /\ |Ady| <= 18014398509481983b-53 /\
  |Bdx| <= 18014398509481983b-53 /\ |Bdy| <= 18014398509481983b-53 /\
  |Cdx| <= 18014398509481983b-53 /\ |Cdy| <= 18014398509481983b-53 /\
  |adx| <= 9007199254740991b-52 /\ |ady| <= 9007199254740991b-52 /\
  |bdx| <= 9007199254740991b-52 /\ |bdy| <= 9007199254740991b-52 /\
  |cdx| <= 9007199254740991b-52 /\ |cdy| <= 9007199254740991b-52 /\
  |u1| <= @UNDERFLOW@ /\ |u2| <= @UNDERFLOW@ /\ |u3| <= @UNDERFLOW@ /\ |u4| <= @UNDERFLOW@ /\
  |u5| <= @UNDERFLOW@ /\ |u6| <= @UNDERFLOW@ /\ |u7| <= @UNDERFLOW@ /\ |u8| <= @UNDERFLOW@ /\
  |u9| <= @UNDERFLOW@ /\ |u10| <= @UNDERFLOW@ /\ |u11| <= @UNDERFLOW@ /\ |u12| <= @UNDERFLOW@ /\
  |u13| <= @UNDERFLOW@ /\ |u14| <= @UNDERFLOW@ /\ |u15| <= @UNDERFLOW@
  -> |det - Det| <= @EPS@ /\
     # No overflow: every computed value is below 2^(1023 - 4 M) in normalised units.
     |adx_adx| <= @OVERFLOW@ /\ |ady_ady| <= @OVERFLOW@ /\ |alift| <= @OVERFLOW@ /\
     |bdx_bdx| <= @OVERFLOW@ /\ |bdy_bdy| <= @OVERFLOW@ /\ |blift| <= @OVERFLOW@ /\
     |cdx_cdx| <= @OVERFLOW@ /\ |cdy_cdy| <= @OVERFLOW@ /\ |clift| <= @OVERFLOW@ /\
     |bdx_cdy| <= @OVERFLOW@ /\ |cdx_bdy| <= @OVERFLOW@ /\ |minor_a| <= @OVERFLOW@ /\
     |cdx_ady| <= @OVERFLOW@ /\ |adx_cdy| <= @OVERFLOW@ /\ |minor_b| <= @OVERFLOW@ /\
     |adx_bdy| <= @OVERFLOW@ /\ |bdx_ady| <= @OVERFLOW@ /\ |minor_c| <= @OVERFLOW@ /\
     |term_a| <= @OVERFLOW@ /\ |term_b| <= @OVERFLOW@ /\ |term_c| <= @OVERFLOW@ /\
     |sum_ab| <= @OVERFLOW@ /\ |det| <= @OVERFLOW@ }

# Hints: split each error into the rounding error of the operation, the underflow term,
# and the propagated error of its operands.
adx_adx - Adx * Adx -> (rnd(adx * adx) - adx * adx) + u1 + (adx * adx - Adx * Adx);
ady_ady - Ady * Ady -> (rnd(ady * ady) - ady * ady) + u2 + (ady * ady - Ady * Ady);
alift - Alift -> (alift - (adx_adx + ady_ady)) + ((adx_adx - Adx * Adx) + (ady_ady - Ady * Ady));
bdx_bdx - Bdx * Bdx -> (rnd(bdx * bdx) - bdx * bdx) + u3 + (bdx * bdx - Bdx * Bdx);
bdy_bdy - Bdy * Bdy -> (rnd(bdy * bdy) - bdy * bdy) + u4 + (bdy * bdy - Bdy * Bdy);
blift - Blift -> (blift - (bdx_bdx + bdy_bdy)) + ((bdx_bdx - Bdx * Bdx) + (bdy_bdy - Bdy * Bdy));
cdx_cdx - Cdx * Cdx -> (rnd(cdx * cdx) - cdx * cdx) + u5 + (cdx * cdx - Cdx * Cdx);
cdy_cdy - Cdy * Cdy -> (rnd(cdy * cdy) - cdy * cdy) + u6 + (cdy * cdy - Cdy * Cdy);
clift - Clift -> (clift - (cdx_cdx + cdy_cdy)) + ((cdx_cdx - Cdx * Cdx) + (cdy_cdy - Cdy * Cdy));
bdx_cdy - Bdx * Cdy -> (rnd(bdx * cdy) - bdx * cdy) + u7 + (bdx * cdy - Bdx * Cdy);
cdx_bdy - Cdx * Bdy -> (rnd(cdx * bdy) - cdx * bdy) + u8 + (cdx * bdy - Cdx * Bdy);
minor_a - Minor_a ->
    (minor_a - (bdx_cdy - cdx_bdy)) + ((bdx_cdy - Bdx * Cdy) - (cdx_bdy - Cdx * Bdy));
cdx_ady - Cdx * Ady -> (rnd(cdx * ady) - cdx * ady) + u9 + (cdx * ady - Cdx * Ady);
adx_cdy - Adx * Cdy -> (rnd(adx * cdy) - adx * cdy) + u10 + (adx * cdy - Adx * Cdy);
minor_b - Minor_b ->
    (minor_b - (cdx_ady - adx_cdy)) + ((cdx_ady - Cdx * Ady) - (adx_cdy - Adx * Cdy));
adx_bdy - Adx * Bdy -> (rnd(adx * bdy) - adx * bdy) + u11 + (adx * bdy - Adx * Bdy);
bdx_ady - Bdx * Ady -> (rnd(bdx * ady) - bdx * ady) + u12 + (bdx * ady - Bdx * Ady);
minor_c - Minor_c ->
    (minor_c - (adx_bdy - bdx_ady)) + ((adx_bdy - Adx * Bdy) - (bdx_ady - Bdx * Ady));
term_a - Alift * Minor_a ->
    (rnd(alift * minor_a) - alift * minor_a) + u13 + (alift * minor_a - Alift * Minor_a);
term_b - Blift * Minor_b ->
    (rnd(blift * minor_b) - blift * minor_b) + u14 + (blift * minor_b - Blift * Minor_b);
term_c - Clift * Minor_c ->
    (rnd(clift * minor_c) - clift * minor_c) + u15 + (clift * minor_c - Clift * Minor_c);
sum_ab - Sum_ab ->
    (sum_ab - (term_a + term_b)) + ((term_a - Alift * Minor_a) + (term_b - Blift * Minor_b));
det - Det -> (det - (sum_ab + term_c)) + ((sum_ab - Sum_ab) + (term_c - Clift * Minor_c));
