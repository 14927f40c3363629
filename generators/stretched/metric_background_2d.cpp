// SPDX-License-Identifier: MIT
// Background metric mesh (see metric_background_2d.hpp).
#include "generators/stretched/metric_background_2d.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

#include "base/number_text.hpp"
#include "predicates/power_of_two.hpp"

namespace exactmesh::generators {

namespace {

using predicates::PowerOfTwo;

/// The sizes the size mesh validating the geometry carries (never read).
std::vector<double> unit_sizes(const std::vector<double>& xy) {
    return std::vector<double>(xy.size() / 2, 1.0);
}

}  // namespace

BackgroundMetricMesh2::BackgroundMetricMesh2(std::vector<double> xy, std::vector<Metric2> metrics,
                                             std::vector<std::uint32_t> triangles)
    : geometry_(xy, unit_sizes(xy), triangles),
      xy_(std::move(xy)),
      triangles_(std::move(triangles)),
      metrics_(std::move(metrics)) {
    using Item = BackgroundMeshError::Item;
    if (metrics_.size() != xy_.size() / 2) {
        throw BackgroundMeshError(Item::Mesh, 0,
                                  std::to_string(xy_.size() / 2) + " vertices but " +
                                      std::to_string(metrics_.size()) + " metrics");
    }
    for (std::size_t v = 0; v < metrics_.size(); ++v) {
        try {
            check_metric(metrics_[v]);
        } catch (const InputError& error) {
            throw BackgroundMeshError(Item::Vertex, v, error.what());
        }
    }
}

Metric2 BackgroundMetricMesh2::inside(std::uint32_t t, double x, double y) const {
    const std::uint32_t* v = &triangles_[3 * std::size_t{t}];
    const double* a = &xy_[2 * std::size_t{v[0]}];
    const double* b = &xy_[2 * std::size_t{v[1]}];
    const double* c = &xy_[2 * std::size_t{v[2]}];
    const std::array<Metric2, 3> corner = {metrics_[v[0]], metrics_[v[1]], metrics_[v[2]]};
    // The vectors from a scaled by the power of two that brings the triangle's extent to [1, 2):
    // the areas neither overflow nor underflow, and a mesh scaled by 2^k gives the same weights.
    const double extent = std::max({std::fabs(b[0] - a[0]), std::fabs(b[1] - a[1]),
                                    std::fabs(c[0] - a[0]), std::fabs(c[1] - a[1])});
    const PowerOfTwo scale(predicates::unit_shift(extent));
    const double bx = scale(b[0] - a[0]), by = scale(b[1] - a[1]);
    const double cx = scale(c[0] - a[0]), cy = scale(c[1] - a[1]);
    const double px = scale(x - a[0]), py = scale(y - a[1]);
    const double area = bx * cy - by * cx;
    if (area > 0) {
        // The point is inside (exact orient2d); rounding may carry a coordinate a few ulps below
        // 0, which a weight must never be.
        const double lb = std::max(0.0, (px * cy - py * cx) / area);
        const double lc = std::max(0.0, (bx * py - by * px) / area);
        const double la = std::max(0.0, 1.0 - lb - lc);
        const std::array<double, 3> weights = {la, lb, lc};
        if (la + lb + lc > 0) return log_euclidean_mean(corner, weights);
    }
    // A sliver, flat in doubles: barycentric coordinates mean nothing there (0 / 0); its
    // nearest vertex's metric.
    const std::array<double, 3> distance = {predicates::scale_free_norm(px, py),
                                            predicates::scale_free_norm(px - bx, py - by),
                                            predicates::scale_free_norm(px - cx, py - cy)};
    const auto nearest = std::min_element(distance.begin(), distance.end()) - distance.begin();
    return corner[static_cast<std::size_t>(nearest)];
}

Metric2 BackgroundMetricMesh2::nearest_boundary(double x, double y) const {
    const std::vector<std::uint32_t>& boundary = geometry_.boundary_edges();
    double best = std::numeric_limits<double>::infinity(), best_f = 0;
    std::uint32_t best_a = triangles_[0], best_b = triangles_[0];
    for (std::size_t e = 0; e + 1 < boundary.size(); e += 2) {
        const std::uint32_t va = boundary[e], vb = boundary[e + 1];
        const double* a = &xy_[2 * std::size_t{va}];
        const double* b = &xy_[2 * std::size_t{vb}];
        // The closest point's parameter on the edge scaled by the power of two of its extent:
        // no square overflows or underflows, the same for the mesh scaled by 2^k.
        const double dx = b[0] - a[0], dy = b[1] - a[1];
        const PowerOfTwo scale(predicates::unit_shift(std::max(std::fabs(dx), std::fabs(dy))));
        const double sx = scale(dx), sy = scale(dy), length2 = sx * sx + sy * sy;
        const double f =
            length2 > 0
                ? std::clamp((scale(x - a[0]) * sx + scale(y - a[1]) * sy) / length2, 0.0, 1.0)
                : 0.0;
        const double distance =
            predicates::scale_free_norm(x - (a[0] + f * dx), y - (a[1] + f * dy));
        if (distance < best) best = distance, best_f = f, best_a = va, best_b = vb;
    }
    const std::array<Metric2, 2> ends = {metrics_[best_a], metrics_[best_b]};
    const std::array<double, 2> weights = {1.0 - best_f, best_f};
    return log_euclidean_mean(ends, weights);
}

Metric2 BackgroundMetricMesh2::operator()(double x, double y) const {
    const triangulation::TriIdx t = geometry_.locate(x, y);
    if (t != triangulation::kNone) return inside(t, x, y);
    return nearest_boundary(x, y);
}

std::size_t metric_file_values(MetricFileForm form) {
    return form == MetricFileForm::Matrices ? 3 : 4;
}

BackgroundMetricMesh2 background_metric_from_file(std::vector<double> xy, MetricFileForm form,
                                                  std::span<const double> values,
                                                  std::vector<std::uint32_t> triangles,
                                                  const MetricFileSource& source) {
    const std::size_t vertices = xy.size() / 2, k = metric_file_values(form);
    if (values.size() != k * vertices) {
        throw InputError(source.node_file + ": " + std::to_string(vertices) + " vertices need " +
                         std::to_string(k * vertices) + " metric values (" +
                         (form == MetricFileForm::Matrices
                              ? "M11 M12 M22"
                              : "DIR_X DIR_Y SIZE_ALONG ASPECT_RATIO") +
                         " each), got " + std::to_string(values.size()));
    }
    std::vector<Metric2> metrics(vertices);
    for (std::size_t v = 0; v < vertices; ++v) {
        const double* a = values.data() + k * v;
        try {
            metrics[v] = form == MetricFileForm::Matrices
                             ? metric_from_matrix(a[0], a[1], a[2])
                             : metric_from_stretching(a[0], a[1], a[2], a[3]);
        } catch (const InputError& error) {
            const std::string line =
                v < source.node_lines.size() ? ":" + std::to_string(source.node_lines[v]) : "";
            throw InputError(source.node_file + line + ": vertex " +
                             std::to_string(v + source.first_index) + ": " + error.what());
        }
    }
    try {
        return BackgroundMetricMesh2(std::move(xy), std::move(metrics), std::move(triangles));
    } catch (const BackgroundMeshError& error) {
        // The vertices' coordinates and metrics were checked above (and by the .node reader):
        // what remains concerns the triangles, the .ele file's.
        throw InputError(source.ele_file + ": " + error.what());
    }
}

}  // namespace exactmesh::generators
