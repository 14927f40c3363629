// SPDX-License-Identifier: MIT
// Conditioning of a metric field before meshing [issue 14: the seed's step 5 and gradation
// control; Borouchaki-Hecht-Frey98 §3, and the background mesh on which BAMG smooths and
// grades its metric, Hecht98 "BAMG" §5]: the field is sampled at the vertices of a background
// triangulation (a metric file's own mesh, or a first mesh of the domain made with the raw
// field), those metrics are smoothed (smooth_vertex_metrics: log-Euclidean Jacobi passes over
// the edges) and then graded (limit_metric_gradation: H-correction, sizes grow by at most a
// factor 1 + beta per unit of metric length), and the result is the background-mesh field on
// that triangulation (log-Euclidean interpolation inside, nearest boundary value outside).
// Smoothing comes first so that the gradation bound holds on the field that is returned.
// Scale invariance: coordinates and metrics scaled together by 2^k give the same field scaled
// by 2^k (both steps are; the sampling reads the field at the background's vertices).
#pragma once

#include <array>
#include <cstdint>

#include "base/counter_table.hpp"
#include "generators/stretched/metric_field_2d.hpp"
#include "triangulation/mesh/triangulation_2d.hpp"

namespace exactmesh::generators {

/// The most passes of each step the command allows.
inline constexpr int kMaxMetricConditioningPasses = 1000;

struct MetricConditioning2 {
    int smoothing_passes = 0;       ///< 0: no smoothing
    double smoothing_weight = 0.5;  ///< in [0, 1]: the neighbours' share of each pass
    double gradation = 0;           ///< beta >= 0; 0: no gradation control
    int max_gradation_passes = 100;

    bool active() const { return smoothing_passes > 0 || gradation > 0; }
};

struct MetricConditioningCounters2 {
    std::uint64_t background_vertices = 0;
    std::uint64_t background_triangles = 0;
    std::uint64_t smoothing_passes = 0;
    std::uint64_t gradation_passes = 0;
    std::uint64_t gradation_corrections = 0;  ///< intersections that changed a metric
    std::uint64_t gradation_converged = 0;    ///< 1 when a gradation pass changed nothing
};

inline constexpr std::array kMetricConditioningCounterNames = EM_COUNTER_TABLE(
    MetricConditioningCounters2, background_vertices, background_triangles, smoothing_passes,
    gradation_passes, gradation_corrections, gradation_converged);
static_assert(counter_table_complete(kMetricConditioningCounterNames));

struct ConditionedMetricField2 {
    MetricField2 field;
    MetricConditioningCounters2 counters;
};

/// Checks the options: passes in [0, kMaxMetricConditioningPasses], weight in [0, 1], beta
/// finite >= 0. @throws InputError naming the value.
void check_metric_conditioning(const MetricConditioning2& options);

/// Samples `field` at the vertices of (xy, triangles) (counter-clockwise triangles covering the
/// domain), smooths and grades as above, and returns the background-mesh field.
/// @throws InputError for bad options or a metric the field refuses at a vertex.
ConditionedMetricField2 condition_metric_field_2d(const MetricField2& field,
                                                  const std::vector<double>& xy,
                                                  const std::vector<std::uint32_t>& triangles,
                                                  const MetricConditioning2& options);

/// The same on the field's own background mesh (its vertex metrics are taken as they are).
/// @pre field.background() != nullptr.
ConditionedMetricField2 condition_metric_field_2d(const MetricField2& field,
                                                  const MetricConditioning2& options);

}  // namespace exactmesh::generators
