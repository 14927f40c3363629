// SPDX-License-Identifier: MIT
// Metric smoothing and gradation on a background mesh (see metric_conditioning_2d.hpp).
#include "generators/stretched/metric_conditioning_2d.hpp"

#include <cmath>
#include <string>
#include <utility>

#include "base/errors.hpp"
#include "base/number_text.hpp"
#include "generators/stretched/metric_background_2d.hpp"
#include "generators/stretched/metric_gradation_2d.hpp"
#include "generators/stretched/metric_smoothing_2d.hpp"

namespace exactmesh::generators {

namespace {

ConditionedMetricField2 condition(std::vector<double> xy, std::vector<Metric2> metrics,
                                  std::vector<std::uint32_t> triangles,
                                  const MetricConditioning2& options) {
    check_metric_conditioning(options);
    MetricConditioningCounters2 counters;
    triangulation::Triangulation2 mesh;
    mesh.xy = std::move(xy);
    mesh.triangles = std::move(triangles);
    counters.background_vertices = mesh.vertex_count();
    counters.background_triangles = mesh.triangle_count();
    if (options.smoothing_passes > 0) {
        smooth_vertex_metrics(mesh, metrics, options.smoothing_passes, options.smoothing_weight);
        counters.smoothing_passes = static_cast<std::uint64_t>(options.smoothing_passes);
    }
    if (options.gradation > 0) {
        const GradationResult graded =
            limit_metric_gradation(mesh, metrics, options.gradation, options.max_gradation_passes);
        counters.gradation_passes = static_cast<std::uint64_t>(graded.passes);
        counters.gradation_corrections = graded.corrections;
        counters.gradation_converged = graded.converged ? 1 : 0;
    }
    return {MetricField2::background_mesh(std::move(mesh.xy), std::move(metrics),
                                          std::move(mesh.triangles)),
            counters};
}

}  // namespace

void check_metric_conditioning(const MetricConditioning2& options) {
    const auto passes = [](int n, const char* what) {
        if (n < 0 || n > kMaxMetricConditioningPasses) {
            throw InputError(std::string(what) + " " + std::to_string(n) + ": must be in [0, " +
                             std::to_string(kMaxMetricConditioningPasses) + "]");
        }
    };
    passes(options.smoothing_passes, "metric smoothing passes");
    passes(options.max_gradation_passes, "metric gradation passes");
    if (!(options.smoothing_weight >= 0 && options.smoothing_weight <= 1)) {
        throw InputError("metric smoothing weight " + format_number(options.smoothing_weight) +
                         ": must be in [0, 1]");
    }
    if (!(options.gradation >= 0 && std::isfinite(options.gradation))) {
        throw InputError("metric gradation " + format_number(options.gradation) +
                         ": must be finite and >= 0");
    }
}

ConditionedMetricField2 condition_metric_field_2d(const MetricField2& field,
                                                  const std::vector<double>& xy,
                                                  const std::vector<std::uint32_t>& triangles,
                                                  const MetricConditioning2& options) {
    check_metric_conditioning(options);
    std::vector<Metric2> metrics(xy.size() / 2);
    for (std::size_t v = 0; v < metrics.size(); ++v) metrics[v] = field(xy[2 * v], xy[2 * v + 1]);
    return condition(xy, std::move(metrics), triangles, options);
}

ConditionedMetricField2 condition_metric_field_2d(const MetricField2& field,
                                                  const MetricConditioning2& options) {
    const BackgroundMetricMesh2& background = *field.background();
    return condition(background.xy(), background.metrics(), background.triangles(), options);
}

}  // namespace exactmesh::generators
