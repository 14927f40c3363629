# proofs/gappa/orient3d_filter.g: Gappa model of the stage-A filter
# exactmesh::predicates::orient3d_filter (predicates/orient3d.hpp).
#
# Proves: with the x, y and z differences scaled by separate powers of two so that maxx,
#   maxy and maxz lie in [1, 2),
#     |det - Det| <= orient3d_filter_eps   and no intermediate overflows below orient3d_filter_max,
# where det is the double the filter computes and Det the exact determinant of the exact
# differences. proofs/invariants/filters.md turns this into the soundness of the filter.
#
# Model:
# - Lower-case names are the doubles of the C++ code (same names); Capitalised names are exact
#   reals: Adx = (a[0] - d[0]) / 2^kx exactly. Products and sums the code leaves unnamed are named
#   after their operands (bdy_cdz = fl(bdy * cdz)).
# - Every computed difference is at most 2 - 2^-52 in magnitude (a double no larger than a
#   maximum < 2), so every exact difference is below 2 - 2^-53 (from there up, reals round to 2
#   or more).
# - rnd is binary64 round-to-nearest-even with an unbounded exponent range. Differences and
#   sums of two doubles are rounded exactly so: when such a result underflows it is exact.
#   A product may underflow: fl(x) = rnd(x) + u with |u| < 2^-1074 at real scale, hence
#   |u| <= 2^(-1074 + 3 L) in normalised units when
#   all three maxima are >= orient3d_filter_min = 2^-L;
#   3 is the degree of orient3d, and products of lower degree underflow at a finer level still.
# - Built with -ffp-contract=off and SSE2/AArch64 doubles: no FMA, no extended precision;
#   C++ evaluates a + b + c as (a + b) + c.
#
# Placeholders, filled in from predicates/filter_constants.hpp by proofs/check_constants.cmake
# (CTest test proofs.orient3d_filter):
#     @EPS@        orient3d_filter_eps
#     @UNDERFLOW@  2^(-1074 + 3 L), L = -log2(orient3d_filter_min)
#     @OVERFLOW@   2^(1023 - 3 M), M = log2(orient3d_filter_max): at real scale a computed value
#                  is at most 2^(3 M) times larger, so it stays below 2^1023, finite
# Print the best bound this script proves, rounded up to a double:
#     cmake -DPRED=orient3d -DMODE=bound -P proofs/check_constants.cmake
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
adx = rnd(Adx); bdx = rnd(Bdx); cdx = rnd(Cdx); ady = rnd(Ady);
bdy = rnd(Bdy); cdy = rnd(Cdy); adz = rnd(Adz); bdz = rnd(Bdz);
cdz = rnd(Cdz);

# The evaluation, operation by operation, in the C++ order; lower case = computed,
# Capitalised = the same quantity computed exactly from the exact differences.
# const double det = adx * (bdy * cdz - bdz * cdy) + bdx * (cdy * adz - cdz * ady) +
#                    cdx * (ady * bdz - adz * bdy);
#   = ((adx * minor_a) + (bdx * minor_b)) + (cdx * minor_c)
bdy_cdz = rnd(bdy * cdz) + u1;
bdz_cdy = rnd(bdz * cdy) + u2;
minor_a = rnd(bdy_cdz - bdz_cdy);  Minor_a = Bdy * Cdz - Bdz * Cdy;
cdy_adz = rnd(cdy * adz) + u3;
cdz_ady = rnd(cdz * ady) + u4;
minor_b = rnd(cdy_adz - cdz_ady);  Minor_b = Cdy * Adz - Cdz * Ady;
ady_bdz = rnd(ady * bdz) + u5;
adz_bdy = rnd(adz * bdy) + u6;
minor_c = rnd(ady_bdz - adz_bdy);  Minor_c = Ady * Bdz - Adz * Bdy;
term_a = rnd(adx * minor_a) + u7;
term_b = rnd(bdx * minor_b) + u8;
term_c = rnd(cdx * minor_c) + u9;
sum_ab = rnd(term_a + term_b);  Sum_ab = Adx * Minor_a + Bdx * Minor_b;
det = rnd(sum_ab + term_c);  Det = Sum_ab + Cdx * Minor_c;

# 18014398509481983b-53 = 2 - 2^-53 and 9007199254740991b-52 = 2 - 2^-52.
{ |Adx| <= 18014398509481983b-53 /\ |Bdx| <= 18014398509481983b-53 /\
  |Cdx| <= 18014398509481983b-53 /\ |Ady| <= 18014398509481983b-53 /\
  |Bdy| <= 18014398509481983b-53 /\ |Cdy| <= 18014398509481983b-53 /\
  |Adz| <= 18014398509481983b-53 /\ |Bdz| <= 18014398509481983b-53 /\
  |Cdz| <= 18014398509481983b-53 /\
  |adx| <= 9007199254740991b-52 /\ |bdx| <= 9007199254740991b-52 /\
  |cdx| <= 9007199254740991b-52 /\ |ady| <= 9007199254740991b-52 /\
  |bdy| <= 9007199254740991b-52 /\ |cdy| <= 9007199254740991b-52 /\
  |adz| <= 9007199254740991b-52 /\ |bdz| <= 9007199254740991b-52 /\
  |cdz| <= 9007199254740991b-52 /\
  |u1| <= @UNDERFLOW@ /\ |u2| <= @UNDERFLOW@ /\ |u3| <= @UNDERFLOW@ /\ |u4| <= @UNDERFLOW@ /\
  |u5| <= @UNDERFLOW@ /\ |u6| <= @UNDERFLOW@ /\ |u7| <= @UNDERFLOW@ /\ |u8| <= @UNDERFLOW@ /\
  |u9| <= @UNDERFLOW@
  -> |det - Det| <= @EPS@ /\
     # No overflow: every computed value is below 2^(1023 - 3 M) in normalised units.
     |bdy_cdz| <= @OVERFLOW@ /\ |bdz_cdy| <= @OVERFLOW@ /\ |minor_a| <= @OVERFLOW@ /\
     |cdy_adz| <= @OVERFLOW@ /\ |cdz_ady| <= @OVERFLOW@ /\ |minor_b| <= @OVERFLOW@ /\
     |ady_bdz| <= @OVERFLOW@ /\ |adz_bdy| <= @OVERFLOW@ /\ |minor_c| <= @OVERFLOW@ /\
     |term_a| <= @OVERFLOW@ /\ |term_b| <= @OVERFLOW@ /\ |term_c| <= @OVERFLOW@ /\
     |sum_ab| <= @OVERFLOW@ /\ |det| <= @OVERFLOW@ }

# Hints: split each error into the rounding error of the operation, the underflow term,
# and the propagated error of its operands.
bdy_cdz - Bdy * Cdz -> (rnd(bdy * cdz) - bdy * cdz) + u1 + (bdy * cdz - Bdy * Cdz);
bdz_cdy - Bdz * Cdy -> (rnd(bdz * cdy) - bdz * cdy) + u2 + (bdz * cdy - Bdz * Cdy);
minor_a - Minor_a ->
    (minor_a - (bdy_cdz - bdz_cdy)) + ((bdy_cdz - Bdy * Cdz) - (bdz_cdy - Bdz * Cdy));
cdy_adz - Cdy * Adz -> (rnd(cdy * adz) - cdy * adz) + u3 + (cdy * adz - Cdy * Adz);
cdz_ady - Cdz * Ady -> (rnd(cdz * ady) - cdz * ady) + u4 + (cdz * ady - Cdz * Ady);
minor_b - Minor_b ->
    (minor_b - (cdy_adz - cdz_ady)) + ((cdy_adz - Cdy * Adz) - (cdz_ady - Cdz * Ady));
ady_bdz - Ady * Bdz -> (rnd(ady * bdz) - ady * bdz) + u5 + (ady * bdz - Ady * Bdz);
adz_bdy - Adz * Bdy -> (rnd(adz * bdy) - adz * bdy) + u6 + (adz * bdy - Adz * Bdy);
minor_c - Minor_c ->
    (minor_c - (ady_bdz - adz_bdy)) + ((ady_bdz - Ady * Bdz) - (adz_bdy - Adz * Bdy));
term_a - Adx * Minor_a ->
    (rnd(adx * minor_a) - adx * minor_a) + u7 + (adx * minor_a - Adx * Minor_a);
term_b - Bdx * Minor_b ->
    (rnd(bdx * minor_b) - bdx * minor_b) + u8 + (bdx * minor_b - Bdx * Minor_b);
term_c - Cdx * Minor_c ->
    (rnd(cdx * minor_c) - cdx * minor_c) + u9 + (cdx * minor_c - Cdx * Minor_c);
sum_ab - Sum_ab ->
    (sum_ab - (term_a + term_b)) + ((term_a - Adx * Minor_a) + (term_b - Bdx * Minor_b));
det - Det -> (det - (sum_ab + term_c)) + ((sum_ab - Sum_ab) + (term_c - Cdx * Minor_c));
