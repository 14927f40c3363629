# proofs/gappa/compare_angles_filter.g: Gappa proof of the double filter of
# exactmesh::predicates::compare_angles (predicates/angle_comparisons_2d.cpp).
#
# Proves: E = dot_b cross_a - dot_a cross_b (dot, cross of the corners' coordinate differences),
#   computed in double, is within compare_angles_filter_eps times the computed permanent
#   (|dot_b| |cross_a| + |dot_a| |cross_b| with the absolute values of the products) of its exact
#   value. Roundings per monomial: value 10 (4 differences, a product and a sum inside dot or
#   cross, the product dot * cross, the final difference); bound 10 (the same 4 differences, a
#   product and a sum inside |dot| or |cross|, the outer product, the outer sum).
#
# Model (proofs/invariants/filters.md, "Relative filters"): with no underflow and no overflow
# (the predicate's window guarantees both), every operation rounds to nearest with a relative
# error delta, |delta| <= u, so the computed value is the sum of the exact monomials M (products
# of exact coordinate differences), each multiplied by one factor (1 + delta) per rounding on
# its path [Higham02 §3.1]; the computed bound is eps times the sum of |M| with factors of its
# own roundings (a power-of-two eps multiplies exactly). The filter's verdict is sound when, for
# every monomial, |prod (1 + d_i) - 1| <= eps prod (1 + e_j) with kv factors d (the value's
# roundings) and kb factors e (the bound's): summed over the monomials this gives
# |computed - exact| <= computed bound. Sharing of roundings between value and bound (the same
# rounded differences) is ignored: independent factors cover it.
#
# Placeholder, filled in from predicates/filter_constants.hpp by
# proofs/check_relative_constants.cmake (CTest test proofs.compare_angles_filter), which requires eps to be a
# power of two that Gappa proves while eps / 2 fails: the least power of two this model allows.
#     @EPS@        compare_angles_filter_eps
#@ -Eprecision=200
#@ -Echange-threshold=0
#@ -Eno-auto-dichotomy

# u = 2^-53; value: 10 roundings per monomial, bound: 10.
value = (1 + d1) * (1 + d2) * (1 + d3) * (1 + d4) * (1 + d5) * (1 + d6) * (1 + d7) * (1 + d8) * (1 + d9) * (1 + d10);
bound = (1 + e1) * (1 + e2) * (1 + e3) * (1 + e4) * (1 + e5) * (1 + e6) * (1 + e7) * (1 + e8) * (1 + e9) * (1 + e10);

{ |d1| <= 1b-53 /\ |d2| <= 1b-53 /\ |d3| <= 1b-53 /\ |d4| <= 1b-53 /\ |d5| <= 1b-53 /\
  |d6| <= 1b-53 /\ |d7| <= 1b-53 /\ |d8| <= 1b-53 /\ |d9| <= 1b-53 /\ |d10| <= 1b-53 /\
  |e1| <= 1b-53 /\ |e2| <= 1b-53 /\ |e3| <= 1b-53 /\ |e4| <= 1b-53 /\ |e5| <= 1b-53 /\
  |e6| <= 1b-53 /\ |e7| <= 1b-53 /\ |e8| <= 1b-53 /\ |e9| <= 1b-53 /\ |e10| <= 1b-53
  -> value - 1 - @EPS@ * bound <= 0 /\ 1 - value - @EPS@ * bound <= 0 }
