# proofs/gappa/compare_lengths_filter.g: Gappa proof of the double filter of
# exactmesh::predicates::compare_lengths (predicates/angle_comparisons_2d.cpp).
#
# Proves: E = |p1 - q1|^2 - |p2 - q2|^2, computed in double, is within
#   compare_lengths_filter_eps times the computed s1 + s2 of its exact value. Roundings per
#   monomial: value 5 (the difference twice, as both factors of the square, the product, the sum
#   of squares, the final difference); bound 5 (the same four, then the sum s1 + s2).
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
# proofs/check_relative_constants.cmake (CTest test proofs.compare_lengths_filter), which requires eps to be a
# power of two that Gappa proves while eps / 2 fails: the least power of two this model allows.
#     @EPS@        compare_lengths_filter_eps
#@ -Eprecision=200
#@ -Echange-threshold=0
#@ -Eno-auto-dichotomy

# u = 2^-53; value: 5 roundings per monomial, bound: 5.
value = (1 + d1) * (1 + d2) * (1 + d3) * (1 + d4) * (1 + d5);
bound = (1 + e1) * (1 + e2) * (1 + e3) * (1 + e4) * (1 + e5);

{ |d1| <= 1b-53 /\ |d2| <= 1b-53 /\ |d3| <= 1b-53 /\ |d4| <= 1b-53 /\ |d5| <= 1b-53 /\
  |e1| <= 1b-53 /\ |e2| <= 1b-53 /\ |e3| <= 1b-53 /\ |e4| <= 1b-53 /\ |e5| <= 1b-53
  -> value - 1 - @EPS@ * bound <= 0 /\ 1 - value - @EPS@ * bound <= 0 }
