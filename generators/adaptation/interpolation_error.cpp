// SPDX-License-Identifier: MIT
// The interpolation error of a P1 mesh field against its analytic field (see
// interpolation_error.hpp).
#include "generators/adaptation/interpolation_error.hpp"

#include <algorithm>
#include <cmath>

#include "generators/topology/mesh_edges.hpp"

namespace exactmesh::generators {

using triangulation::kNone;
using triangulation::VertIdx;

namespace {

// |det| of the element's edge vectors in unit coordinates (2·area, 6·volume).
double element_measure(std::span<const double> unit, unsigned dim, const VertIdx* v) {
    const double* p0 = &unit[dim * std::size_t{v[0]}];
    double d[3][3];
    for (unsigned r = 0; r < dim; ++r)
        for (unsigned c = 0; c < dim; ++c) d[r][c] = unit[dim * std::size_t{v[r + 1]} + c] - p0[c];
    if (dim == 2) return std::fabs(d[0][0] * d[1][1] - d[0][1] * d[1][0]);
    return std::fabs(d[0][0] * (d[1][1] * d[2][2] - d[1][2] * d[2][1]) -
                     d[0][1] * (d[1][0] * d[2][2] - d[1][2] * d[2][0]) +
                     d[0][2] * (d[1][0] * d[2][1] - d[1][1] * d[2][0]));
}

}  // namespace

InterpolationError interpolation_error(std::span<const double> xyz, unsigned dim,
                                       std::span<const VertIdx> elements,
                                       std::span<const double> values, const AnalyticField& field,
                                       double t) {
    const unsigned corners = dim + 1;
    const int exponent = unit_scale_exponent(xyz, dim, elements);
    const std::vector<double> unit = scaled_coordinates(xyz, exponent);
    // Squared error at each edge's midpoint, each edge once.
    const std::vector<VertIdx> edges = dim == 2 ? mesh_edges_2d(elements) : mesh_edges_3d(elements);
    std::vector<double> edge_error(edges.size() / 2);
    InterpolationError result;
    double point[3];
    for (std::size_t e = 0; e < edge_error.size(); ++e) {
        const VertIdx a = edges[2 * e], b = edges[2 * e + 1];
        for (unsigned c = 0; c < dim; ++c)
            point[c] = 0.5 * xyz[dim * std::size_t{a} + c] + 0.5 * xyz[dim * std::size_t{b} + c];
        const double error =
            std::fabs(0.5 * values[a] + 0.5 * values[b] - field_at(field, point, dim, t));
        result.maximum = std::max(result.maximum, error);
        edge_error[e] = error * error;
    }
    result.samples = edge_error.size();
    double weighted = 0, total = 0;
    const MeshEdgeIndex index(edges);
    for (std::size_t el = 0; el + corners <= elements.size(); el += corners) {
        const VertIdx* v = &elements[el];
        if (v[0] == kNone) continue;
        double mean = 0;
        for (unsigned c = 0; c < dim; ++c) {
            point[c] = 0;
            for (unsigned k = 0; k < corners; ++k)
                point[c] += xyz[dim * std::size_t{v[k]} + c] / corners;
        }
        for (unsigned k = 0; k < corners; ++k) mean += values[v[k]] / corners;
        const double error = std::fabs(mean - field_at(field, point, dim, t));
        result.maximum = std::max(result.maximum, error);
        ++result.samples;
        double squares = error * error;
        unsigned terms = 1;
        for (unsigned i = 0; i < corners; ++i)
            for (unsigned j = i + 1; j < corners; ++j) {
                squares += edge_error[index.find(v[i], v[j])];
                ++terms;
            }
        const double measure = element_measure(unit, dim, v);
        weighted += measure * squares / terms;
        total += measure;
    }
    result.l2 = total > 0 ? std::sqrt(weighted / total) : 0.0;
    return result;
}

}  // namespace exactmesh::generators
