# proofs/gappa/dot_sign_3d_filter.g: Gappa proof of the double filter of
# exactmesh::predicates::dot_sign_3d (predicates/dot_sign_3d.cpp).
#
# Proves: (a - p) . (b - p), computed in double from the rounded and scaled differences, is within
#   dot_sign_3d_filter_eps times the computed sum of |products| of its exact value. Roundings per
#   monomial: 5 (two differences, the product, two sums: ((p0 + p1) + p2)).
#
# Model (proofs/invariants/filters.md, "Relative filters" and "dot_sign_3d and
# tet_quality_3d"): inside the filter's window nothing underflows or overflows, so every
# operation rounds to nearest with a relative error delta, |delta| <= u = 2^-53, and the
# computed value is the sum of the exact monomials M (products of exact coordinate
# differences, and the constants), each multiplied by one factor (1 + delta) per rounding on
# its path [Higham02 §3.1]; the computed permanent is the sum of |M| with factors of its own
# roundings, and eps (a power of two) multiplies it exactly. The verdict |value| > eps
# permanent is sound when, for every monomial, |prod_{i<=k} (1 + d_i) - 1| <= eps
# prod_{j<=k} (1 + e_j), k the most roundings on a path (value and permanent go through the
# same operations): summed over the monomials, |computed - exact| <= eps computed
# permanent. Sharing of roundings between value and permanent is ignored: independent
# factors cover it. valueK and boundK below have K factors; the goals are stated for the
# counts the code uses (the header's *_roundings constants, checked by the CTest test).
#
# Placeholder, filled in from predicates/filter_constants.hpp by
# proofs/check_relative_constants.cmake (CTest test proofs.dot_sign_3d_filter), which requires eps
# to be a power of two that Gappa proves while eps / 2 fails: the least power of two this
# model allows for the largest count.
#     @EPS@        dot_sign_3d_filter_eps
#@ -Eprecision=200
#@ -Echange-threshold=0
#@ -Eno-auto-dichotomy

# u = 2^-53; value_k, bound_k: k roundings.
value1 = 1 + d1;
bound1 = 1 + e1;
value2 = value1 * (1 + d2);
bound2 = bound1 * (1 + e2);
value3 = value2 * (1 + d3);
bound3 = bound2 * (1 + e3);
value4 = value3 * (1 + d4);
bound4 = bound3 * (1 + e4);
value5 = value4 * (1 + d5);
bound5 = bound4 * (1 + e5);

{ |d1| <= 1b-53 /\ |d2| <= 1b-53 /\ |d3| <= 1b-53 /\ |d4| <= 1b-53 /\ |d5| <= 1b-53 /\
  |e1| <= 1b-53 /\ |e2| <= 1b-53 /\ |e3| <= 1b-53 /\ |e4| <= 1b-53 /\ |e5| <= 1b-53
  ->
     value5 - 1 - @EPS@ * bound5 <= 0 /\ 1 - value5 - @EPS@ * bound5 <= 0 }
