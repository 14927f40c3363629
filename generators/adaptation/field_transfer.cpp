// SPDX-License-Identifier: MIT
// P1 transfer of a vertex field between meshes by exact location (see field_transfer.hpp).
#include "generators/adaptation/field_transfer.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "generators/topology/mesh_edges.hpp"
#include "predicates/orient2d.hpp"
#include "predicates/orient3d.hpp"
#include "triangulation/mesh/locate_2d.hpp"

namespace exactmesh::generators {

using predicates::Sign;
using triangulation::kNone;
using triangulation::VertIdx;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The linear interpolant on the simplex of `count` vertices (1 to dim + 1, sorted by index)
// at p, in unit coordinates: weights from the simplex's measure in its own affine hull (lengths
// on an edge, areas on a triangle, volumes in a tetrahedron), by Cramer's rule on the Gram-free
// form: each weight is the measure with that vertex replaced by p over the whole measure.
double interpolate_on(std::span<const double> unit, unsigned dim, std::array<VertIdx, 4> v,
                      unsigned count, const double* p, std::span<const double> values) {
    for (unsigned i = 1; i < count; ++i)  // insertion sort (std::sort trips -Warray-bounds)
        for (unsigned j = i; j > 0 && v[j] < v[j - 1]; --j) std::swap(v[j], v[j - 1]);
    const auto at = [&](VertIdx i) { return &unit[dim * std::size_t{i}]; };
    if (count == 1) return values[v[0]];
    if (count == 2) {
        // Along the edge, by its longer axis.
        const double* a = at(v[0]);
        const double* b = at(v[1]);
        unsigned axis = 0;
        for (unsigned c = 1; c < dim; ++c)
            if (std::fabs(b[c] - a[c]) > std::fabs(b[axis] - a[axis])) axis = c;
        const double s = (p[axis] - a[axis]) / (b[axis] - a[axis]);
        return values[v[0]] + s * (values[v[1]] - values[v[0]]);
    }
    // A triangle (in 2D, or a face in 3D) or a tetrahedron: signed measures by the cross /
    // triple product; in 3D a face's area vector is compared along its own normal.
    const auto measure = [&](const double* q0, const double* q1, const double* q2, const double* q3,
                             const double* normal) {
        double d1[3] = {0, 0, 0}, d2[3] = {0, 0, 0}, d3[3] = {0, 0, 0};
        for (unsigned c = 0; c < dim; ++c) {
            d1[c] = q1[c] - q0[c];
            d2[c] = q2[c] - q0[c];
            if (q3 != nullptr) d3[c] = q3[c] - q0[c];
        }
        const double cross[3] = {d1[1] * d2[2] - d1[2] * d2[1], d1[2] * d2[0] - d1[0] * d2[2],
                                 d1[0] * d2[1] - d1[1] * d2[0]};
        if (q3 != nullptr) return cross[0] * d3[0] + cross[1] * d3[1] + cross[2] * d3[2];
        if (normal == nullptr) return cross[2];
        return cross[0] * normal[0] + cross[1] * normal[1] + cross[2] * normal[2];
    };
    double value = 0;
    if (count == 3) {
        const double* q[3] = {at(v[0]), at(v[1]), at(v[2])};
        double normal[3] = {0, 0, 1};
        if (dim == 3) {
            double d1[3], d2[3];
            for (unsigned c = 0; c < 3; ++c) {
                d1[c] = q[1][c] - q[0][c];
                d2[c] = q[2][c] - q[0][c];
            }
            normal[0] = d1[1] * d2[2] - d1[2] * d2[1];
            normal[1] = d1[2] * d2[0] - d1[0] * d2[2];
            normal[2] = d1[0] * d2[1] - d1[1] * d2[0];
        }
        const double* n = dim == 3 ? normal : nullptr;
        const double whole = measure(q[0], q[1], q[2], nullptr, n);
        for (unsigned k = 0; k < 3; ++k) {
            const double* r[3] = {q[0], q[1], q[2]};
            r[k] = p;
            value += measure(r[0], r[1], r[2], nullptr, n) / whole * values[v[k]];
        }
        return value;
    }
    const double* q[4] = {at(v[0]), at(v[1]), at(v[2]), at(v[3])};
    const double whole = measure(q[0], q[1], q[2], q[3], nullptr);
    for (unsigned k = 0; k < 4; ++k) {
        const double* r[4] = {q[0], q[1], q[2], q[3]};
        r[k] = p;
        value += measure(r[0], r[1], r[2], r[3], nullptr) / whole * values[v[k]];
    }
    return value;
}

}  // namespace

std::vector<double> transfer_field_2d(std::span<const double> old_xy,
                                      std::span<const VertIdx> old_triangles,
                                      std::span<const double> old_values,
                                      std::span<const double> points) {
    const triangulation::TriangleLocator2 locator(old_xy, old_triangles);
    const int exponent = unit_scale_exponent(old_xy, 2, old_triangles);
    const std::vector<double> unit = scaled_coordinates(old_xy, exponent);
    std::vector<double> result(points.size() / 2, kNaN);
    for (std::size_t i = 0; i < result.size(); ++i) {
        const double* p = &points[2 * i];
        const std::uint32_t t = locator.locate(old_xy, old_triangles, p[0], p[1]);
        if (t == kNone) continue;
        // The corners whose barycentric sign is not zero (the opposite side's orient2d).
        std::array<VertIdx, 4> keep{};
        unsigned count = 0;
        for (unsigned k = 0; k < 3; ++k) {
            const VertIdx b = old_triangles[3 * t + (k + 1) % 3];
            const VertIdx c = old_triangles[3 * t + (k + 2) % 3];
            if (predicates::orient2d(&old_xy[2 * b], &old_xy[2 * c], p) != Sign::Zero)
                keep[count++] = old_triangles[3 * t + k];
        }
        const double up[2] = {std::ldexp(p[0], -exponent), std::ldexp(p[1], -exponent)};
        result[i] = interpolate_on(unit, 2, keep, count, up, old_values);
    }
    return result;
}

std::vector<double> transfer_field_3d(std::span<const double> old_xyz,
                                      std::span<const VertIdx> old_tets,
                                      std::span<const std::uint32_t> old_neighbors,
                                      std::span<const double> old_values,
                                      std::span<const double> points) {
    static constexpr unsigned kFace[4][3] = {{1, 3, 2}, {0, 2, 3}, {0, 3, 1}, {0, 1, 2}};
    const int exponent = unit_scale_exponent(old_xyz, 3, old_tets);
    const std::vector<double> unit = scaled_coordinates(old_xyz, exponent);
    const std::size_t tets = old_tets.size() / 4;
    std::vector<double> result(points.size() / 3, kNaN);
    if (tets == 0) return result;
    const auto face_sign = [&](std::size_t t, unsigned k, const double* p) {
        const VertIdx* v = &old_tets[4 * t];
        return predicates::orient3d(&old_xyz[3 * std::size_t{v[kFace[k][0]]}],
                                    &old_xyz[3 * std::size_t{v[kFace[k][1]]}],
                                    &old_xyz[3 * std::size_t{v[kFace[k][2]]}], p);
    };
    // Visibility walk (orient3d of each face against p; negative: p lies beyond it), from the
    // previous answer; the faces are tried from a rotating start so the walk does not cycle
    // on a Delaunay mesh's degenerate steps, and a step limit bounds it on any other mesh.
    std::size_t current = 0;
    const std::size_t step_limit = 64 + 4 * static_cast<std::size_t>(std::cbrt(double(tets))) * 8;
    for (std::size_t i = 0; i < result.size(); ++i) {
        const double* p = &points[3 * i];
        std::size_t found = kNone;
        std::size_t t = current;
        for (std::size_t step = 0; step < step_limit; ++step) {
            unsigned beyond = 4;
            for (unsigned j = 0; j < 4; ++j) {
                const unsigned k = static_cast<unsigned>((j + step) % 4);
                if (face_sign(t, k, p) == Sign::Negative) {
                    beyond = k;
                    break;
                }
            }
            if (beyond == 4) {
                found = t;
                break;
            }
            const std::uint32_t next = old_neighbors[4 * t + beyond];
            if (next == kNone) break;
            t = next;
        }
        if (found == kNone) {
            for (std::size_t s = 0; s < tets && found == kNone; ++s) {
                bool inside = true;
                for (unsigned k = 0; k < 4 && inside; ++k)
                    inside = face_sign(s, k, p) != Sign::Negative;
                if (inside) found = s;
            }
        }
        if (found == kNone) continue;
        current = found;
        std::array<VertIdx, 4> keep{};
        unsigned count = 0;
        for (unsigned k = 0; k < 4; ++k)
            if (face_sign(found, k, p) != Sign::Zero) keep[count++] = old_tets[4 * found + k];
        const double up[3] = {std::ldexp(p[0], -exponent), std::ldexp(p[1], -exponent),
                              std::ldexp(p[2], -exponent)};
        result[i] = interpolate_on(unit, 3, keep, count, up, old_values);
    }
    return result;
}

void keep_values_of_unmoved(std::vector<double>& values, std::span<const double> points,
                            std::span<const double> before, unsigned dim,
                            std::span<const double> first_values) {
    for (std::size_t v = 0; v < values.size(); ++v) {
        bool moved = false;
        for (unsigned i = 0; i < dim && !moved; ++i)
            moved = points[dim * v + i] != before[dim * v + i];
        if (std::isnan(values[v]) || !moved) values[v] = first_values[v];
    }
}

}  // namespace exactmesh::generators
