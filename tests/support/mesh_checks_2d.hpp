// SPDX-License-Identifier: MIT
// Checks of a 2D quality mesh of a PSLG domain, for the generator tests (ours and CGAL's
// output alike): exact constrained Delaunay (or, for generators that do not promise it, exact
// validity without folds: check_conforming_mesh_2d) with every segment a chain of pieces
// (triangulation/ check_constrained_2d), no triangle outside the domain (its centroid inside by the
// even-odd rule against the input segments, decided with exact orient2d, or within the rounding a
// piece may bend by from a segment), the triangulated region closed by pieces only (every edge with
// one triangle is a piece), every input vertex in the meshed region a mesh vertex at its input
// coordinates (check_input_vertices_kept_2d: no generator may drop a free vertex inside the
// domain), and the smallest angle and longest edge-to-size ratio. Test support, not a library
// algorithm.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <map>
#include <numbers>
#include <set>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "predicates/orient2d.hpp"
#include "triangulation/checks/check_conforming_2d.hpp"
#include "triangulation/checks/check_constrained_2d.hpp"
#include "triangulation/mesh/triangulation_2d.hpp"

namespace exactmesh::testing {

/// Even-odd: is (x, y) inside the region the segments enclose? Segments repeated (by their
/// end points' coordinates, in either direction) count once. Exact crossing decisions.
inline bool inside_by_segments(double x, double y, std::span<const double> xy,
                               std::span<const std::uint32_t> segments) {
    const double c[2] = {x, y};
    bool inside = false;
    std::set<std::array<double, 4>> seen;
    for (std::size_t s = 0; s + 1 < segments.size(); s += 2) {
        const double* a = &xy[2 * std::size_t{segments[s]}];
        const double* b = &xy[2 * std::size_t{segments[s + 1]}];
        if (a[1] == b[1]) continue;
        std::array<double, 4> key{a[0], a[1], b[0], b[1]};
        if (std::make_pair(a[0], a[1]) > std::make_pair(b[0], b[1])) key = {b[0], b[1], a[0], a[1]};
        if (!seen.insert(key).second) continue;
        const bool up = a[1] < b[1];
        const double* lo = up ? a : b;
        const double* hi = up ? b : a;
        if (!(lo[1] <= y && y < hi[1])) continue;
        // The ray to +x crosses the edge when c lies left of lo -> hi.
        if (predicates::orient2d(lo, hi, c) == predicates::Sign::Positive) inside = !inside;
    }
    return inside;
}

/// Distance from (x, y) to the nearest segment (double precision).
inline double distance_to_segments(double x, double y, std::span<const double> xy,
                                   std::span<const std::uint32_t> segments) {
    double best = INFINITY;
    for (std::size_t s = 0; s + 1 < segments.size(); s += 2) {
        const double* a = &xy[2 * std::size_t{segments[s]}];
        const double* b = &xy[2 * std::size_t{segments[s + 1]}];
        const double dx = b[0] - a[0], dy = b[1] - a[1], length2 = dx * dx + dy * dy;
        const double t =
            length2 > 0 ? std::clamp(((x - a[0]) * dx + (y - a[1]) * dy) / length2, 0.0, 1.0) : 0.0;
        best = std::min(best, std::hypot(x - (a[0] + t * dx), y - (a[1] + t * dy)));
    }
    return best;
}

struct MeshCheck {
    bool ok = true;
    std::string problem;
    double min_angle = 180;     ///< degrees, over all triangles
    double max_size_ratio = 0;  ///< longest edge / size at its midpoint
};

/// The checks above. `input_vertex_count`, `segments`, `pieces` as check_constrained_delaunay_2d
/// takes them; `size` may be empty (no size ratio).
/// `closed_loops`: the segments form closed loops only (the even-odd test applies); false for
/// inputs with dangling (slit) segments, which skip the outside test.
/// `delaunay`: false for generators whose meshes need not be Delaunay (quadtree, advancing
/// front): then check_conforming_mesh_2d (no fold at any vertex) replaces the Delaunay check.
inline MeshCheck check_quality_mesh(const triangulation::Triangulation2& mesh,
                                    std::uint32_t input_vertex_count,
                                    std::span<const double> input_xy,
                                    std::span<const std::uint32_t> segments,
                                    std::span<const std::uint32_t> pieces,
                                    const std::function<double(double, double)>& size = {},
                                    bool closed_loops = true, bool delaunay = true) {
    MeshCheck r;
    const auto report = delaunay ? triangulation::check_constrained_delaunay_2d(
                                       mesh, input_vertex_count, segments, pieces)
                                 : triangulation::check_conforming_mesh_2d(mesh, input_vertex_count,
                                                                           segments, pieces);
    if (!report.ok) {
        r.ok = false;
        r.problem = (delaunay ? "not constrained Delaunay: " : "not a valid mesh of the domain: ") +
                    report.problem;
        return r;
    }
    const auto kept = triangulation::check_input_vertices_kept_2d(
        mesh, input_xy.first(std::min(input_xy.size(), 2 * std::size_t{input_vertex_count})));
    if (!kept.ok) {
        r.ok = false;
        r.problem = "input vertices not kept: " + kept.problem;
        return r;
    }
    if (mesh.triangle_count() == 0) {
        r.ok = false;
        r.problem = "no triangle";
        return r;
    }
    std::set<std::pair<std::uint32_t, std::uint32_t>> piece_set;
    for (std::size_t p = 0; p + 1 < pieces.size(); p += 2) {
        piece_set.insert({std::min(pieces[p], pieces[p + 1]), std::max(pieces[p], pieces[p + 1])});
    }
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> edge_count;
    // Pieces may bend by the rounding of their split points (as check_constrained_delaunay_2d
    // allows, 2^-40 of the largest coordinate): a sliver along a segment may lie that far out.
    double magnitude = 0;
    for (const double v : input_xy) magnitude = std::max(magnitude, std::fabs(v));
    const double tolerance = std::ldexp(magnitude, -40);
    for (std::uint32_t t = 0; t < mesh.triangle_count(); ++t) {
        const double* p[3];
        for (int k = 0; k < 3; ++k)
            p[k] = mesh.point(mesh.triangles[3 * t + static_cast<unsigned>(k)]);
        const double cx = (p[0][0] + p[1][0] + p[2][0]) / 3, cy = (p[0][1] + p[1][1] + p[2][1]) / 3;
        if (closed_loops && !inside_by_segments(cx, cy, input_xy, segments) &&
            distance_to_segments(cx, cy, input_xy, segments) > tolerance) {
            r.ok = false;
            r.problem = "triangle " + std::to_string(t) + " lies outside the domain";
            return r;
        }
        for (int k = 0; k < 3; ++k) {
            const double* o = p[k];
            const double* a = p[(k + 1) % 3];
            const double* b = p[(k + 2) % 3];
            const double ux = a[0] - o[0], uy = a[1] - o[1], wx = b[0] - o[0], wy = b[1] - o[1];
            r.min_angle =
                std::min(r.min_angle, std::atan2(std::fabs(ux * wy - uy * wx), ux * wx + uy * wy) *
                                          180 / std::numbers::pi);
            const std::uint32_t u = mesh.triangles[3 * t + static_cast<unsigned>(k)];
            const std::uint32_t v = mesh.triangles[3 * t + static_cast<unsigned>((k + 1) % 3)];
            ++edge_count[{std::min(u, v), std::max(u, v)}];
            if (size) {
                const double s = size(0.5 * (o[0] + a[0]), 0.5 * (o[1] + a[1]));
                r.max_size_ratio = std::max(r.max_size_ratio, std::hypot(ux, uy) / s);
            }
        }
    }
    for (const auto& [edge, count] : edge_count) {
        if (count == 1 && !piece_set.count(edge)) {
            r.ok = false;
            r.problem = "edge " + std::to_string(edge.first) + "-" + std::to_string(edge.second) +
                        " bounds the mesh but is no piece of a segment";
            return r;
        }
    }
    return r;
}

/// The smallest corner angle (degrees) of triangle t.
inline double triangle_min_angle(const triangulation::Triangulation2& mesh, std::uint32_t t) {
    double smallest = 180;
    for (int k = 0; k < 3; ++k) {
        const double* o = mesh.point(mesh.triangles[3 * t + static_cast<unsigned>(k)]);
        const double* a = mesh.point(mesh.triangles[3 * t + static_cast<unsigned>((k + 1) % 3)]);
        const double* b = mesh.point(mesh.triangles[3 * t + static_cast<unsigned>((k + 2) % 3)]);
        const double ux = a[0] - o[0], uy = a[1] - o[1], wx = b[0] - o[0], wy = b[1] - o[1];
        smallest = std::min(smallest, std::atan2(std::fabs(ux * wy - uy * wx), ux * wx + uy * wy) *
                                          180 / std::numbers::pi);
    }
    return smallest;
}

}  // namespace exactmesh::testing
