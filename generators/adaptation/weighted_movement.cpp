// SPDX-License-Identifier: MIT
// Solution-weighted mesh movement: indicator-weighted springs in the shared guarded sweep (see
// weighted_movement.hpp).
#include "generators/adaptation/weighted_movement.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "base/errors.hpp"
#include "base/number_text.hpp"
#include "generators/adaptation/mesh_movement_check.hpp"
#include "generators/adaptation/vertex_moves.hpp"

namespace exactmesh::generators {

namespace tri = exactmesh::triangulation;

namespace {

void validate_options(const WeightedMovementOptions& options, std::span<const double> indicator,
                      std::uint32_t n) {
    detail::validate_relaxation(options.relaxation);
    // Bounded so that W = 1 + c w (w <= 2 #V) and its sums stay far inside the double range.
    if (!(options.strength >= 0 && options.strength <= 0x1p50)) {
        throw InputError("weighted movement strength " + format_number(options.strength) +
                         " is not in [0, 2^50]");
    }
    if (indicator.size() != n) {
        throw InputError("weighted movement: " + std::to_string(indicator.size()) +
                         " indicator values for " + std::to_string(n) + " vertices");
    }
    for (std::uint32_t v = 0; v < n; ++v) {
        if (!(std::isfinite(indicator[v]) && indicator[v] >= 0)) {
            throw InputError("weighted movement: indicator value " + format_number(indicator[v]) +
                             " at vertex " + std::to_string(v) + " is not a finite value >= 0");
        }
    }
}

/// W per neighbour slot of `stars` by the header's formula.
std::vector<double> edge_weights(const detail::VertexStars& stars,
                                 std::span<const double> indicator, double strength) {
    const auto n = static_cast<std::uint32_t>(indicator.size());
    const auto used = [&stars](tri::VertIdx v) {
        return stars.element_start[v] != stars.element_start[v + 1];
    };
    double largest = 0;
    for (tri::VertIdx v = 0; v < n; ++v) {
        if (used(v)) largest = std::max(largest, indicator[v]);
    }
    std::vector<double> weights(stars.neighbors.size(), 1.0);
    if (largest == 0 || strength == 0) return weights;  // every W = 1: Laplacian
    std::vector<double> g(n, 0.0);
    double sum = 0;
    std::uint32_t count = 0;
    for (tri::VertIdx v = 0; v < n; ++v) {
        if (!used(v)) continue;
        g[v] = indicator[v] / largest;
        sum += g[v];
        ++count;
    }
    const double mean = sum / count;  // >= 1 / count > 0: the largest value's g is 1
    for (tri::VertIdx v = 0; v < n; ++v) {
        for (std::uint32_t i = stars.neighbor_start[v]; i < stars.neighbor_start[v + 1]; ++i) {
            weights[i] = 1.0 + strength * ((g[v] + g[stars.neighbors[i]]) * 0.5 / mean);
        }
    }
    return weights;
}

}  // namespace

WeightedMovementCounters weighted_movement_2d(tri::Triangulation2& mesh,
                                              std::span<const double> indicator,
                                              std::uint32_t fixed_below,
                                              const WeightedMovementOptions& options,
                                              std::span<const std::uint8_t> protected_vertices) {
    detail::validate_mesh_arrays_2d(mesh);
    validate_options(options, indicator, mesh.vertex_count());
    const std::vector<std::uint8_t> fixed =
        fixed_vertices_2d(mesh, fixed_below, protected_vertices);
    const detail::VertexStars stars = detail::vertex_stars_2d(mesh);
    const std::vector<double> weights = edge_weights(stars, indicator, options.strength);
    return detail::sweep_counters(
        detail::guarded_sweeps_2d(mesh, stars, fixed, weights,
                                  {options.relaxation, options.sweeps, options.smart}),
        fixed);
}

WeightedMovementCounters weighted_movement_3d(tri::Tetrahedralization3& mesh,
                                              std::span<const double> indicator,
                                              std::uint32_t fixed_below,
                                              const WeightedMovementOptions& options,
                                              std::span<const std::uint8_t> protected_vertices) {
    detail::validate_mesh_arrays_3d(mesh);
    validate_options(options, indicator, mesh.vertex_count());
    const std::vector<std::uint8_t> fixed =
        fixed_vertices_3d(mesh, fixed_below, protected_vertices);
    const detail::VertexStars stars = detail::vertex_stars_3d(mesh);
    const std::vector<double> weights = edge_weights(stars, indicator, options.strength);
    return detail::sweep_counters(
        detail::guarded_sweeps_3d(mesh, stars, fixed, weights,
                                  {options.relaxation, options.sweeps, options.smart}),
        fixed);
}

}  // namespace exactmesh::generators
