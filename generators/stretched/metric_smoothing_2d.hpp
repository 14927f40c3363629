// SPDX-License-Identifier: MIT
// Smoothing of a metric per vertex over a triangulation's edges [issue 14, the seed's step 5:
// the stretching vectors smoothed over the unstretched triangulation]: in each pass every
// vertex's log-Euclidean form moves towards the mean of its neighbours',
//     log M_v <- (1 - w_v) log M_v + w_v mean_{u ~ v} log M_u,
// all vertices at once from the previous pass's values (Jacobi, so the result does not depend
// on the vertex order). Progressive smoothing takes a weight per vertex (none at a wall, more
// away from it). Log-Euclidean means keep every metric positive definite, and a field that is
// constant over a vertex's neighbourhood stays constant there.
// Cost: O(passes * E). Scale invariance: coordinates are not read; metrics scaled by 2^k give
// the same result scaled by 2^k (log_euclidean_mean).
#pragma once

#include <span>
#include <vector>

#include "generators/stretched/metric_2d.hpp"
#include "triangulation/mesh/triangulation_2d.hpp"

namespace exactmesh::generators {

/// `passes` >= 0 passes over `metrics` (#V of mesh); `weight` in [0, 1] for every vertex, or
/// `vertex_weights` (#V values in [0, 1]) when not empty. A vertex no triangle uses is left as
/// it is.
/// @throws InputError on a size mismatch, a negative pass count or a weight outside [0, 1].
void smooth_vertex_metrics(const triangulation::Triangulation2& mesh, std::vector<Metric2>& metrics,
                           int passes, double weight, std::span<const double> vertex_weights = {});

}  // namespace exactmesh::generators
