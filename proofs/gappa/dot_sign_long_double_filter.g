# proofs/gappa/dot_sign_long_double_filter.g: Gappa proof of the long double stage of
# exactmesh::predicates::direction_dot_sign (predicates/angle_comparisons_2d.cpp), which decides
# the calls whose differences leave the double window before GMP.
#
# Proves: E = ux vx + uy vy, computed in long double (x86-64's 80-bit format: u = 2^-64, and no
#   difference or product of doubles' differences overflows or underflows there), is within
#   dot_sign_long_double_filter_eps times the computed |ux vx| + |uy vy| (scaled exactly by
#   ldexp) of its exact value. Roundings per monomial: value 4 (two differences, the product, the
#   sum); bound 4 (the same, then the sum of absolute values).
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
# proofs/check_relative_constants.cmake (CTest test proofs.dot_sign_long_double_filter), which requires eps to be a
# power of two that Gappa proves while eps / 2 fails: the least power of two this model allows.
#     @EPS@        dot_sign_long_double_filter_eps
#@ -Eprecision=200
#@ -Echange-threshold=0
#@ -Eno-auto-dichotomy

# u = 2^-64; value: 4 roundings per monomial, bound: 4.
value = (1 + d1) * (1 + d2) * (1 + d3) * (1 + d4);
bound = (1 + e1) * (1 + e2) * (1 + e3) * (1 + e4);

{ |d1| <= 1b-64 /\ |d2| <= 1b-64 /\ |d3| <= 1b-64 /\ |d4| <= 1b-64 /\ |e1| <= 1b-64 /\
  |e2| <= 1b-64 /\ |e3| <= 1b-64 /\ |e4| <= 1b-64
  -> value - 1 - @EPS@ * bound <= 0 /\ 1 - value - @EPS@ * bound <= 0 }
