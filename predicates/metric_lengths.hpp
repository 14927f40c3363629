// SPDX-License-Identifier: MIT
// Exact comparison of two edges' lengths in constant metrics: the sign of
//     (q1 - p1)^T M1 (q1 - p1) - (q2 - p2)^T M2 (q2 - p2),   M = {M11, M12, M22} as doubles,
// the decision "is this edge longer than that one in the metric" of stretched-mesh generators
// (the longest edge to split, the shortest to collapse, unit-length tests against a reference
// edge). M1 and M2 must share one scale (the caller scales both by the same factor); with both
// the identity it is compare_lengths. Stages as angle_comparisons_2d.cpp's: a relative filter
// (proofs/gappa/compare_metric_lengths_filter.g), expansions on exact differences, coordinates
// and metrics scaled by powers of two when out of the window, GMP last.
#pragma once

#include <optional>

#include "predicates/sign.hpp"

namespace exactmesh::predicates {

/// Positive when edge (p1, q1) is longer in M1 than edge (p2, q2) in M2, Zero when equal.
/// Throws GeometryError on NaN or infinite input.
Sign compare_metric_lengths(const double* p1, const double* q1, const double* m1, const double* p2,
                            const double* q2, const double* m2);

/// The relative filter alone (benchmarks, tests): a sign only when certified.
std::optional<Sign> compare_metric_lengths_filter(const double* p1, const double* q1,
                                                  const double* m1, const double* p2,
                                                  const double* q2, const double* m2);

}  // namespace exactmesh::predicates
