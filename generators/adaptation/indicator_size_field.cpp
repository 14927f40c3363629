// SPDX-License-Identifier: MIT
// The indicator as a size field (see indicator_size_field.hpp).
#include "generators/adaptation/indicator_size_field.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "predicates/power_of_two.hpp"

namespace exactmesh::generators {

using triangulation::VertIdx;

double indicator_order(EdgeIndicator indicator) {
    return indicator == EdgeIndicator::FirstDifference ? 1.0 : 2.0;
}

std::vector<double> indicator_vertex_sizes(std::span<const double> xyz, unsigned dim,
                                           std::span<const VertIdx> edges,
                                           std::span<const double> indicator, EdgeIndicator kind,
                                           double threshold, double max_factor,
                                           double reference_mean) {
    const std::size_t vertices = xyz.size() / dim;
    constexpr double kInfinity = std::numeric_limits<double>::infinity();
    std::vector<double> wanted(vertices, kInfinity), shortest(vertices, kInfinity);
    const double mean = reference_mean > 0 ? reference_mean
                        : indicator.empty()
                            ? 0.0
                            : std::accumulate(indicator.begin(), indicator.end(), 0.0) /
                                  static_cast<double>(indicator.size());
    const double target = threshold * mean;
    const double inverse_order = 1.0 / indicator_order(kind);
    for (std::size_t e = 0; e < indicator.size(); ++e) {
        const VertIdx a = edges[2 * e], b = edges[2 * e + 1];
        double d[3] = {0, 0, 0};
        for (unsigned c = 0; c < dim; ++c) d[c] = xyz[dim * b + c] - xyz[dim * a + c];
        // |d| scale-free: the 2D norm of (|dx, dy|, dz).
        const double h = predicates::scale_free_norm(predicates::scale_free_norm(d[0], d[1]), d[2]);
        const double ratio = indicator[e] > 0 && target > 0
                                 ? std::pow(target / indicator[e], inverse_order)
                                 : max_factor;
        const double asked = h * std::clamp(ratio, 1.0 / max_factor, max_factor);
        for (const VertIdx v : {a, b}) {
            wanted[v] = std::min(wanted[v], asked);
            shortest[v] = std::min(shortest[v], h);
        }
    }
    for (std::size_t v = 0; v < vertices; ++v)
        if (std::isfinite(shortest[v]))
            wanted[v] = std::clamp(wanted[v], shortest[v] / max_factor, shortest[v] * max_factor);
    return wanted;
}

SizeFunction indicator_size_function_2d(std::span<const double> xy,
                                        std::span<const VertIdx> triangles,
                                        std::vector<double> vertex_sizes) {
    double largest = 0;
    for (const double s : vertex_sizes)
        if (std::isfinite(s)) largest = std::max(largest, s);
    for (double& s : vertex_sizes)
        if (!std::isfinite(s)) s = largest > 0 ? largest : 1.0;
    return SizeFunction::background_mesh(
        std::vector<double>(xy.begin(), xy.end()), std::move(vertex_sizes),
        std::vector<std::uint32_t>(triangles.begin(), triangles.end()));
}

}  // namespace exactmesh::generators
