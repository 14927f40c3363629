# proofs/gappa/orient2d_filter.g: Gappa model of the stage-A filter
# exactmesh::predicates::orient2d_filter (predicates/orient2d.hpp).
#
# Proves: with the x and y differences scaled by separate powers of two so that maxx and
#   maxy lie in [1, 2),
#     |det - Det| <= orient2d_filter_eps   and no intermediate overflows below orient2d_filter_max,
# where det is the double the filter computes and Det the exact determinant of the exact
# differences. proofs/invariants/filters.md turns this into the soundness of the filter.
#
# Model:
# - Lower-case names are the doubles of the C++ code (same names); Capitalised names are exact
#   reals: Adx = (a[0] - c[0]) / 2^kx exactly. Products and sums the code leaves unnamed are named
#   after their operands (adx_bdy = fl(adx * bdy)).
# - Every computed difference is at most 2 - 2^-52 in magnitude (a double no larger than a
#   maximum < 2), so every exact difference is below 2 - 2^-53 (from there up, reals round to 2
#   or more).
# - rnd is binary64 round-to-nearest-even with an unbounded exponent range. Differences and
#   sums of two doubles are rounded exactly so: when such a result underflows it is exact.
#   A product may underflow: fl(x) = rnd(x) + u with |u| < 2^-1074 at real scale, hence
#   |u| <= 2^(-1074 + 2 L) in normalised units when
#   both maxima are >= orient2d_filter_min = 2^-L;
#   2 is the degree of orient2d, and products of lower degree underflow at a finer level still.
# - Built with -ffp-contract=off and SSE2/AArch64 doubles: no FMA, no extended precision;
#   C++ evaluates a + b + c as (a + b) + c.
#
# Placeholders, filled in from predicates/filter_constants.hpp by proofs/check_constants.cmake
# (CTest test proofs.orient2d_filter):
#     @EPS@        orient2d_filter_eps
#     @UNDERFLOW@  2^(-1074 + 2 L), L = -log2(orient2d_filter_min)
#     @OVERFLOW@   2^(1023 - 2 M), M = log2(orient2d_filter_max): at real scale a computed value
#                  is at most 2^(2 M) times larger, so it stays below 2^1023, finite
# Print the best bound this script proves, rounded up to a double:
#     cmake -DPRED=orient2d -DMODE=bound -P proofs/check_constants.cmake
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
adx = rnd(Adx); bdx = rnd(Bdx); ady = rnd(Ady); bdy = rnd(Bdy);

# The evaluation, operation by operation, in the C++ order; lower case = computed,
# Capitalised = the same quantity computed exactly from the exact differences.
# const double det = adx * bdy - ady * bdx;
adx_bdy = rnd(adx * bdy) + u1;
ady_bdx = rnd(ady * bdx) + u2;
det = rnd(adx_bdy - ady_bdx);  Det = Adx * Bdy - Ady * Bdx;

# 18014398509481983b-53 = 2 - 2^-53 and 9007199254740991b-52 = 2 - 2^-52.
{ |Adx| <= 18014398509481983b-53 /\ |Bdx| <= 18014398509481983b-53 /\
  |Ady| <= 18014398509481983b-53 /\ |Bdy| <= 18014398509481983b-53 /\
  |adx| <= 9007199254740991b-52 /\ |bdx| <= 9007199254740991b-52 /\
  |ady| <= 9007199254740991b-52 /\ |bdy| <= 9007199254740991b-52 /\
  |u1| <= @UNDERFLOW@ /\ |u2| <= @UNDERFLOW@
  -> |det - Det| <= @EPS@ /\
     # No overflow: every computed value is below 2^(1023 - 2 M) in normalised units.
     |adx_bdy| <= @OVERFLOW@ /\ |ady_bdx| <= @OVERFLOW@ /\ |det| <= @OVERFLOW@ }

# Hints: split each error into the rounding error of the operation, the underflow term,
# and the propagated error of its operands.
adx_bdy - Adx * Bdy -> (rnd(adx * bdy) - adx * bdy) + u1 + (adx * bdy - Adx * Bdy);
ady_bdx - Ady * Bdx -> (rnd(ady * bdx) - ady * bdx) + u2 + (ady * bdx - Ady * Bdx);
det - Det -> (det - (adx_bdy - ady_bdx)) + ((adx_bdy - Adx * Bdy) - (ady_bdx - Ady * Bdx));
