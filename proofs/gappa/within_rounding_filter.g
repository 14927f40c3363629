# proofs/gappa/within_rounding_filter.g: Gappa proof of the long double filter of
# exactmesh::predicates::within_rounding_of_segment (predicates/within_rounding_of_segment.cpp).
#
# Proves: both tests of the predicate, evaluated in long double (u = 2^-64; no overflow or
#   underflow of differences and products of doubles there), are within
#   within_rounding_filter_eps times their computed margins of their exact values:
#   - the slab test |(w - s0) x d| - (t_x |dy| + t_y |dx|): value 5 roundings per monomial (two
#     differences, the product, the cross difference, the final difference), bound 5 (two
#     differences, the product, two sums);
#   - the overlap tests (w - t) - hi and lo - (w + t): value 2, bound 3 (covered by 5 and 5).
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
# proofs/check_relative_constants.cmake (CTest test proofs.within_rounding_filter), which requires eps to be a
# power of two that Gappa proves while eps / 2 fails: the least power of two this model allows.
#     @EPS@        within_rounding_filter_eps
#@ -Eprecision=200
#@ -Echange-threshold=0
#@ -Eno-auto-dichotomy

# u = 2^-64; value: 5 roundings per monomial, bound: 5.
value = (1 + d1) * (1 + d2) * (1 + d3) * (1 + d4) * (1 + d5);
bound = (1 + e1) * (1 + e2) * (1 + e3) * (1 + e4) * (1 + e5);

{ |d1| <= 1b-64 /\ |d2| <= 1b-64 /\ |d3| <= 1b-64 /\ |d4| <= 1b-64 /\ |d5| <= 1b-64 /\
  |e1| <= 1b-64 /\ |e2| <= 1b-64 /\ |e3| <= 1b-64 /\ |e4| <= 1b-64 /\ |e5| <= 1b-64
  -> value - 1 - @EPS@ * bound <= 0 /\ 1 - value - @EPS@ * bound <= 0 }
