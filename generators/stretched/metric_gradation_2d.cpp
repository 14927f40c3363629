// SPDX-License-Identifier: MIT
// Metric gradation control (see metric_gradation_2d.hpp).
#include "generators/stretched/metric_gradation_2d.hpp"

#include <cmath>
#include <string>

#include "base/errors.hpp"
#include "base/number_text.hpp"
#include "generators/topology/mesh_edges.hpp"

namespace exactmesh::generators {

namespace {

/// Relative slack under which an intersection counts as no change.
constexpr double kUnchanged = 1e-12;

/// Bounds the metric at q by the metric at p grown along the edge p -> q; true when it changed.
bool correct(const triangulation::Triangulation2& mesh, std::vector<Metric2>& metrics,
             triangulation::VertIdx p, triangulation::VertIdx q, double beta) {
    const double* a = mesh.point(p);
    const double* b = mesh.point(q);
    const Metric2& from = metrics[p];
    const double eta = 1.0 + beta * metric_length(from, b[0] - a[0], b[1] - a[1]);
    const Metric2 grown{from.h1 * eta, from.h2 * eta, from.c, from.s};
    if (!(std::isfinite(grown.h1) && std::isfinite(grown.h2))) return false;  // no bound at all
    const Metric2 bounded = metric_intersection(metrics[q], grown, kUnchanged);
    const Metric2& old = metrics[q];
    if (bounded.h1 == old.h1 && bounded.h2 == old.h2 && bounded.c == old.c && bounded.s == old.s)
        return false;
    metrics[q] = bounded;
    return true;
}

}  // namespace

GradationResult limit_metric_gradation(const triangulation::Triangulation2& mesh,
                                       std::vector<Metric2>& metrics, double beta, int max_passes) {
    if (metrics.size() != mesh.vertex_count()) {
        throw InputError("metric gradation: " + std::to_string(mesh.vertex_count()) +
                         " vertices but " + std::to_string(metrics.size()) + " metrics");
    }
    if (!(std::isfinite(beta) && beta >= 0))
        throw InputError("metric gradation: beta " + format_number(beta) +
                         " is not a finite number >= 0");
    if (max_passes < 1)
        throw InputError("metric gradation: pass limit " + std::to_string(max_passes) + " < 1");
    const std::vector<triangulation::VertIdx> edges = mesh_edges_2d(mesh.triangles);
    GradationResult result;
    while (result.passes < max_passes) {
        ++result.passes;
        std::uint64_t changed = 0;
        for (std::size_t e = 0; e + 1 < edges.size(); e += 2) {
            changed += correct(mesh, metrics, edges[e], edges[e + 1], beta) ? 1 : 0;
            changed += correct(mesh, metrics, edges[e + 1], edges[e], beta) ? 1 : 0;
        }
        result.corrections += changed;
        if (changed == 0) {
            result.converged = true;
            break;
        }
    }
    return result;
}

}  // namespace exactmesh::generators
