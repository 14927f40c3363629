// SPDX-License-Identifier: MIT
// Gradation control of a metric per vertex: H-correction [Borouchaki-Hecht-Frey98 "Mesh
// gradation control", §3; Frey-George08 §10.6]. Along each edge pq the metric at p, grown in
// every direction by the factor eta = 1 + beta * l_p(pq) (l_p the length of pq in p's metric;
// its sizes times eta, its matrix over eta^2), bounds the metric at q:
//     M_q <- M_q intersected with M_p / eta^2,
// both ways along every edge, edges in increasing (p, q) order, pass after pass until a pass
// changes nothing (each intersection only shrinks sizes, and one within a relative 1e-12 of
// containing the other counts as no change, so the iteration stops) or the pass limit is
// reached. At the fixed point every edge satisfies l_q(v) >= l_p(v) / eta for all vectors v:
// sizes grow by at most a factor 1 + beta per unit of metric length, in every direction.
// Cost: O(passes * E). Scale invariance: coordinates and sizes scaled together by 2^k give the
// same result scaled by 2^k (metric_length, metric_intersection).
#pragma once

#include <cstdint>
#include <vector>

#include "generators/stretched/metric_2d.hpp"
#include "triangulation/mesh/triangulation_2d.hpp"

namespace exactmesh::generators {

struct GradationResult {
    int passes = 0;                 ///< passes made (the last one changed nothing if converged)
    std::uint64_t corrections = 0;  ///< intersections that changed a metric
    bool converged = false;
};

/// H-correction of `metrics` (#V of mesh) with growth `beta` (finite >= 0) within `max_passes`.
/// @throws InputError on a size mismatch, a bad beta or pass limit, or an intersection beyond
///         kMaxAspectRatio.
GradationResult limit_metric_gradation(const triangulation::Triangulation2& mesh,
                                       std::vector<Metric2>& metrics, double beta,
                                       int max_passes = 100);

}  // namespace exactmesh::generators
