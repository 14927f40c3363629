// SPDX-License-Identifier: MIT
// Gradient recovery, the four edge indicators and the flagging rules (see edge_indicators.hpp).
#include "generators/adaptation/edge_indicators.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "base/enum_names.hpp"
#include "generators/topology/mesh_edges.hpp"

namespace exactmesh::generators {

using triangulation::kNone;
using triangulation::VertIdx;

namespace {

constexpr std::array<EnumName<EdgeIndicator>, 4> kEdgeIndicatorNames{{
    {"first-difference", EdgeIndicator::FirstDifference},
    {"second-difference", EdgeIndicator::SecondDifference},
    {"loehner", EdgeIndicator::Loehner},
    {"length-weighted", EdgeIndicator::LengthWeighted},
}};

// The triangle's area-weighted gradient, 2·area·∇u, and 2·area (both in unit coordinates).
void weighted_gradient_2d(const double* p0, const double* p1, const double* p2, double u0,
                          double u1, double u2, double* weighted, double* weight) {
    const double d1x = p1[0] - p0[0], d1y = p1[1] - p0[1];
    const double d2x = p2[0] - p0[0], d2y = p2[1] - p0[1];
    const double du1 = u1 - u0, du2 = u2 - u0;
    weighted[0] = du1 * d2y - du2 * d1y;
    weighted[1] = du2 * d1x - du1 * d2x;
    *weight = d1x * d2y - d1y * d2x;
}

// The tetrahedron's 6·volume·∇u and 6·volume: ∇u solves D ∇u = du for the edge rows D, so
// det(D) ∇u = adj(D) du, the cofactors' combination.
void weighted_gradient_3d(const double* p[4], const double* u, double* weighted, double* weight) {
    double d[3][3], du[3];
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) d[r][c] = p[r + 1][c] - p[0][c];
        du[r] = u[r + 1] - u[0];
    }
    // Cross products of the rows: adj(D) columns.
    const double c12[3] = {d[1][1] * d[2][2] - d[1][2] * d[2][1],
                           d[1][2] * d[2][0] - d[1][0] * d[2][2],
                           d[1][0] * d[2][1] - d[1][1] * d[2][0]};
    const double c20[3] = {d[2][1] * d[0][2] - d[2][2] * d[0][1],
                           d[2][2] * d[0][0] - d[2][0] * d[0][2],
                           d[2][0] * d[0][1] - d[2][1] * d[0][0]};
    const double c01[3] = {d[0][1] * d[1][2] - d[0][2] * d[1][1],
                           d[0][2] * d[1][0] - d[0][0] * d[1][2],
                           d[0][0] * d[1][1] - d[0][1] * d[1][0]};
    for (int c = 0; c < 3; ++c) weighted[c] = du[0] * c12[c] + du[1] * c20[c] + du[2] * c01[c];
    *weight = d[0][0] * c12[0] + d[0][1] * c12[1] + d[0][2] * c12[2];
}

}  // namespace

std::string_view edge_indicator_name(EdgeIndicator indicator) {
    return name_of(kEdgeIndicatorNames, indicator);
}

EdgeIndicator edge_indicator_from_name(std::string_view name) {
    return parse_name(kEdgeIndicatorNames, name, "indicator");
}

std::vector<double> recover_gradients(std::span<const double> xyz, unsigned dim,
                                      std::span<const VertIdx> elements,
                                      std::span<const double> values) {
    const std::size_t vertices = xyz.size() / dim;
    std::vector<double> sum(dim * vertices, 0.0), weight(vertices, 0.0);
    const unsigned corners = dim + 1;
    for (std::size_t e = 0; e + corners <= elements.size(); e += corners) {
        if (elements[e] == kNone) continue;
        double g[3] = {0, 0, 0}, w = 0;
        if (dim == 2) {
            const VertIdx a = elements[e], b = elements[e + 1], c = elements[e + 2];
            weighted_gradient_2d(&xyz[2 * a], &xyz[2 * b], &xyz[2 * c], values[a], values[b],
                                 values[c], g, &w);
        } else {
            const double* p[4];
            double u[4];
            for (unsigned k = 0; k < 4; ++k) {
                p[k] = &xyz[3 * std::size_t{elements[e + k]}];
                u[k] = values[elements[e + k]];
            }
            weighted_gradient_3d(p, u, g, &w);
        }
        for (unsigned k = 0; k < corners; ++k) {
            const VertIdx v = elements[e + k];
            for (unsigned c = 0; c < dim; ++c) sum[dim * v + c] += g[c];
            weight[v] += w;
        }
    }
    for (std::size_t v = 0; v < vertices; ++v)
        for (unsigned c = 0; c < dim; ++c)
            sum[dim * v + c] = weight[v] != 0 ? sum[dim * v + c] / weight[v] : 0.0;
    return sum;
}

std::vector<double> edge_indicator(EdgeIndicator indicator, std::span<const double> xyz,
                                   unsigned dim, std::span<const VertIdx> edges,
                                   std::span<const double> values,
                                   std::span<const double> gradients) {
    const std::size_t count = edges.size() / 2;
    std::vector<double> result(count);
    for (std::size_t e = 0; e < count; ++e) {
        const VertIdx i = edges[2 * e], j = edges[2 * e + 1];
        double d[3] = {0, 0, 0};
        for (unsigned c = 0; c < dim; ++c) d[c] = xyz[dim * j + c] - xyz[dim * i + c];
        const double first = std::fabs(values[j] - values[i]);
        switch (indicator) {
            case EdgeIndicator::FirstDifference:
                result[e] = first;
                break;
            case EdgeIndicator::LengthWeighted:
                result[e] = first * std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
                break;
            case EdgeIndicator::SecondDifference:
            case EdgeIndicator::Loehner: {
                double gi = 0, gj = 0;
                for (unsigned c = 0; c < dim; ++c) {
                    gi += gradients[dim * i + c] * d[c];
                    gj += gradients[dim * j + c] * d[c];
                }
                const double second = std::fabs(gj - gi);
                if (indicator == EdgeIndicator::SecondDifference) {
                    result[e] = second;
                } else {
                    const double denominator =
                        std::fabs(gi) + std::fabs(gj) +
                        kLoehnerNoiseFilter * (std::fabs(values[i]) + std::fabs(values[j]));
                    result[e] = denominator > 0 ? second / denominator : 0.0;
                }
                break;
            }
        }
    }
    return result;
}

std::vector<double> mesh_edge_indicator(EdgeIndicator indicator, std::span<const double> xyz,
                                        unsigned dim, std::span<const VertIdx> elements,
                                        std::span<const VertIdx> edges,
                                        std::span<const double> values) {
    const int exponent = unit_scale_exponent(xyz, dim, elements);
    const std::vector<double> unit = scaled_coordinates(xyz, exponent);
    std::vector<double> gradients;
    if (indicator == EdgeIndicator::SecondDifference || indicator == EdgeIndicator::Loehner)
        gradients = recover_gradients(unit, dim, elements, values);
    return edge_indicator(indicator, unit, dim, edges, values, gradients);
}

std::vector<double> vertex_indicator(std::span<const VertIdx> edges,
                                     std::span<const double> indicator, std::size_t vertex_count) {
    std::vector<double> result(vertex_count, 0.0);
    for (std::size_t e = 0; e < indicator.size(); ++e)
        for (const VertIdx v : {edges[2 * e], edges[2 * e + 1]})
            result[v] = std::max(result[v], indicator[e]);
    return result;
}

std::vector<double> mesh_vertex_indicator(EdgeIndicator indicator,
                                          std::span<const double> coordinates, unsigned dim,
                                          std::span<const VertIdx> elements,
                                          std::span<const double> values) {
    const std::vector<VertIdx> edges = dim == 2 ? mesh_edges_2d(elements) : mesh_edges_3d(elements);
    const std::vector<double> per_edge =
        mesh_edge_indicator(indicator, coordinates, dim, elements, edges, values);
    return vertex_indicator(edges, per_edge, coordinates.size() / dim);
}

double mean_indicator(std::span<const double> indicator) {
    if (indicator.empty()) return 0;
    return std::accumulate(indicator.begin(), indicator.end(), 0.0) /
           static_cast<double>(indicator.size());
}

std::vector<std::uint8_t> flag_above_mean(std::span<const double> indicator, double threshold,
                                          double reference_mean) {
    std::vector<std::uint8_t> flags(indicator.size(), 0);
    if (indicator.empty()) return flags;
    const double mean = reference_mean > 0 ? reference_mean : mean_indicator(indicator);
    for (std::size_t e = 0; e < indicator.size(); ++e)
        flags[e] = indicator[e] > threshold * mean && indicator[e] > 0 ? 1 : 0;
    return flags;
}

std::vector<std::uint8_t> flag_largest(std::span<const double> indicator, std::size_t count) {
    std::vector<std::uint32_t> order(indicator.size());
    std::iota(order.begin(), order.end(), 0u);
    count = std::min(count, order.size());
    std::partial_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(count),
                      order.end(), [&](std::uint32_t a, std::uint32_t b) {
                          return indicator[a] > indicator[b] ||
                                 (indicator[a] == indicator[b] && a < b);
                      });
    std::vector<std::uint8_t> flags(indicator.size(), 0);
    for (std::size_t k = 0; k < count; ++k)
        if (indicator[order[k]] > 0) flags[order[k]] = 1;
    return flags;
}

namespace {

// The edge numbers of each element's edges (in the element's pair order).
std::vector<std::uint32_t> element_edges(std::span<const VertIdx> elements, unsigned dim,
                                         std::span<const VertIdx> edges) {
    const unsigned corners = dim + 1;
    const MeshEdgeIndex index(edges);
    std::vector<std::uint32_t> result;
    result.reserve(elements.size() / corners * (dim == 2 ? 3 : 6));
    for (std::size_t t = 0; t + corners <= elements.size(); t += corners)
        for (unsigned i = 0; i < corners; ++i)
            for (unsigned j = i + 1; j < corners; ++j)
                result.push_back(index.find(elements[t + i], elements[t + j]));
    return result;
}

// The one-pass closure of `flags` over the elements (per_element edges each), into `closed`;
// the number of flagged edges after it.
std::uint64_t close_flags(std::span<const std::uint32_t> element_edges, unsigned per_element,
                          std::span<const std::uint8_t> flags, std::vector<std::uint8_t>& closed) {
    closed.assign(flags.begin(), flags.end());
    for (std::size_t t = 0; t + per_element <= element_edges.size(); t += per_element) {
        bool any = false;
        for (unsigned k = 0; k < per_element; ++k) any = any || flags[element_edges[t + k]] != 0;
        if (!any) continue;
        for (unsigned k = 0; k < per_element; ++k) closed[element_edges[t + k]] = 1;
    }
    return static_cast<std::uint64_t>(std::count(closed.begin(), closed.end(), 1));
}

}  // namespace

std::vector<std::uint8_t> refinement_flags(std::span<const VertIdx> elements, unsigned dim,
                                           std::span<const VertIdx> edges,
                                           std::span<const double> indicator, double threshold,
                                           std::uint64_t room, bool budget, std::uint64_t* flagged,
                                           std::uint64_t* closure, double reference_mean) {
    const unsigned per_element = dim == 2 ? 3 : 6;
    const std::vector<std::uint32_t> edges_of = element_edges(elements, dim, edges);
    std::vector<std::uint8_t> flags = flag_above_mean(indicator, threshold, reference_mean), closed;
    std::uint64_t count = static_cast<std::uint64_t>(std::count(flags.begin(), flags.end(), 1));
    std::uint64_t total = close_flags(edges_of, per_element, flags, closed);
    if (budget && total > room) {
        // The largest k whose closure fits the room, by bisection (the closure grows with k).
        std::size_t lo = 0, hi = static_cast<std::size_t>(count);
        while (lo < hi) {
            const std::size_t mid = (lo + hi + 1) / 2;
            std::vector<std::uint8_t> trial;
            if (close_flags(edges_of, per_element, flag_largest(indicator, mid), trial) <= room)
                lo = mid;
            else
                hi = mid - 1;
        }
        flags = flag_largest(indicator, lo);
        count = static_cast<std::uint64_t>(std::count(flags.begin(), flags.end(), 1));
        total = close_flags(edges_of, per_element, flags, closed);
    }
    if (flagged != nullptr) *flagged = count;
    if (closure != nullptr) *closure = total - count;
    return closed;
}

}  // namespace exactmesh::generators
