# proofs/gappa/compare_metric_lengths_filter.g: Gappa proof of the double filter of
# exactmesh::predicates::compare_metric_lengths (predicates/metric_lengths.cpp).
#
# Proves: E = s1 - s2, s = (M11 x) x + (2 M12 x) y + (M22 y) y over the computed differences
#   (x, y) of an edge, computed in double, is within compare_metric_lengths_filter_eps times the
#   computed b1 + b2 (the same expressions over absolute values) of its exact value. Roundings
#   per monomial (a metric entry times two exact differences; 2 M12 is exact): value 7 (the two
#   differences, the two products, at most two sums inside s, the final difference); bound 7
#   (the same two differences, two products, two sums, then b1 + b2).
#
# Model: proofs/invariants/filters.md, "Relative filters" (as compare_lengths_filter.g); the
# window of predicates/metric_lengths.cpp excludes underflow and overflow.
#
# Placeholder, filled in from predicates/filter_constants.hpp by
# proofs/check_relative_constants.cmake (CTest test proofs.compare_metric_lengths_filter).
#     @EPS@        compare_metric_lengths_filter_eps
#@ -Eprecision=200
#@ -Echange-threshold=0
#@ -Eno-auto-dichotomy

value = (1 + d1) * (1 + d2) * (1 + d3) * (1 + d4) * (1 + d5) * (1 + d6) * (1 + d7);
bound = (1 + e1) * (1 + e2) * (1 + e3) * (1 + e4) * (1 + e5) * (1 + e6) * (1 + e7);

{ |d1| <= 1b-53 /\ |d2| <= 1b-53 /\ |d3| <= 1b-53 /\ |d4| <= 1b-53 /\ |d5| <= 1b-53 /\
  |d6| <= 1b-53 /\ |d7| <= 1b-53 /\
  |e1| <= 1b-53 /\ |e2| <= 1b-53 /\ |e3| <= 1b-53 /\ |e4| <= 1b-53 /\ |e5| <= 1b-53 /\
  |e6| <= 1b-53 /\ |e7| <= 1b-53
  -> value - 1 - @EPS@ * bound <= 0 /\ 1 - value - @EPS@ * bound <= 0 }
