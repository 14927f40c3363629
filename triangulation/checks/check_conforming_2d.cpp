// SPDX-License-Identifier: MIT
// Exact validation of conforming (not necessarily Delaunay) meshes (see check_conforming_2d.hpp).
#include "triangulation/checks/check_conforming_2d.hpp"

#include <algorithm>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "predicates/orient2d.hpp"
#include "triangulation/checks/check_constrained_2d.hpp"

namespace exactmesh::triangulation {

namespace {

using predicates::Sign;

/// 0 for directions in [0, pi) (up, or along +x), 1 for [pi, 2 pi): exact, since the sign of a
/// rounded difference of doubles is the sign of the difference.
int half_of(const double* v, const double* a) {
    return (a[1] > v[1] || (a[1] == v[1] && a[0] > v[0])) ? 0 : 1;
}

}  // namespace

CheckReport check_input_vertices_kept_2d(const Triangulation2& mesh,
                                         std::span<const double> input_xy,
                                         CheckNumbering numbering) {
    const std::size_t inputs = input_xy.size() / 2;
    auto vertex = [&](std::size_t v) { return std::to_string(v + numbering.first_vertex); };
    if (inputs > mesh.vertex_count()) {
        return CheckReport{false,
                           "the mesh has " + std::to_string(mesh.vertex_count()) +
                               " vertices, fewer than the " + std::to_string(inputs) +
                               " input vertices",
                           kNone,
                           {}};
    }
    for (std::size_t v = 0; v < inputs; ++v) {
        const double* p = mesh.point(static_cast<VertIdx>(v));
        if (p[0] != input_xy[2 * v] || p[1] != input_xy[2 * v + 1]) {
            return CheckReport{false,
                               "input vertex " + vertex(v) + " has moved in the mesh",
                               kNone,
                               {static_cast<VertIdx>(v)}};
        }
    }
    std::vector<std::uint8_t> used(inputs, 0);
    for (const VertIdx v : mesh.triangles) {
        if (v < inputs) used[v] = 1;
    }
    // The unused input vertices sorted by x: a triangle tests those in its x-range.
    std::vector<VertIdx> unused;
    for (std::size_t v = 0; v < inputs; ++v) {
        if (used[v] == 0) unused.push_back(static_cast<VertIdx>(v));
    }
    if (unused.empty()) return {};
    auto x_of = [&](VertIdx v) { return mesh.point(v)[0]; };
    std::sort(unused.begin(), unused.end(), [&](VertIdx a, VertIdx b) {
        return x_of(a) < x_of(b) || (x_of(a) == x_of(b) && a < b);
    });
    const TriIdx count = mesh.triangle_count();
    for (TriIdx t = 0; t < count; ++t) {
        const double* c[3] = {mesh.point(mesh.triangles[3 * t]),
                              mesh.point(mesh.triangles[3 * t + 1]),
                              mesh.point(mesh.triangles[3 * t + 2])};
        const double x0 = std::min({c[0][0], c[1][0], c[2][0]});
        const double x1 = std::max({c[0][0], c[1][0], c[2][0]});
        const double y0 = std::min({c[0][1], c[1][1], c[2][1]});
        const double y1 = std::max({c[0][1], c[1][1], c[2][1]});
        auto it = std::partition_point(unused.begin(), unused.end(),
                                       [&](VertIdx v) { return x_of(v) < x0; });
        for (; it != unused.end() && x_of(*it) <= x1; ++it) {
            const double* p = mesh.point(*it);
            if (p[1] < y0 || p[1] > y1) continue;
            bool corner = false;
            for (const double* q : c) corner = corner || (q[0] == p[0] && q[1] == p[1]);
            if (corner) continue;
            // Counter-clockwise triangles (checked before): inside when no side has p right.
            if (predicates::orient2d(c[0], c[1], p) != Sign::Negative &&
                predicates::orient2d(c[1], c[2], p) != Sign::Negative &&
                predicates::orient2d(c[2], c[0], p) != Sign::Negative) {
                return CheckReport{false,
                                   "input vertex " + vertex(*it) + " lies in triangle " +
                                       std::to_string(std::uint64_t{t} + numbering.first_triangle) +
                                       " but is no vertex of the mesh (an input vertex left out)",
                                   t,
                                   {*it}};
            }
        }
    }
    return {};
}

CheckReport check_conforming_mesh_2d(const Triangulation2& mesh, std::uint32_t input_vertex_count,
                                     std::span<const VertIdx> segments,
                                     std::span<const VertIdx> pieces, CheckNumbering numbering) {
    // Topology, flags and segment chains first (vertex indices are valid after it).
    CheckReport report = detail::check_constrained_mesh_2d(mesh, input_vertex_count, segments,
                                                           pieces, numbering, false);
    if (!report.ok) return report;
    const std::uint32_t n = mesh.vertex_count();
    const TriIdx count = mesh.triangle_count();
    const auto& tv = mesh.triangles;
    auto vertex = [&](VertIdx v) {
        return std::to_string(std::uint64_t{v} + numbering.first_vertex);
    };
    auto key = [](VertIdx a, VertIdx b) { return (std::uint64_t{a} << 32) | b; };

    // The edges leaving each vertex (CSR), each neighbour once.
    std::vector<std::uint32_t> start(std::size_t{n} + 1, 0);
    std::unordered_set<std::uint64_t> directed;
    directed.reserve(tv.size());
    for (TriIdx t = 0; t < count; ++t) {
        for (unsigned k = 0; k < 3; ++k)
            directed.insert(key(tv[3 * t + k], tv[3 * t + (k + 1) % 3]));
    }
    std::unordered_set<std::uint64_t> undirected;
    undirected.reserve(tv.size());
    for (const std::uint64_t e : directed) {
        const VertIdx a = static_cast<VertIdx>(e >> 32), b = static_cast<VertIdx>(e);
        undirected.insert(key(std::min(a, b), std::max(a, b)));
    }
    for (const std::uint64_t e : undirected) {
        ++start[static_cast<VertIdx>(e >> 32) + 1];
        ++start[static_cast<VertIdx>(e) + 1];
    }
    for (std::uint32_t v = 0; v < n; ++v) start[v + 1] += start[v];
    std::vector<VertIdx> ray(start[n]);
    {
        std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
        for (const std::uint64_t e : undirected) {
            const VertIdx a = static_cast<VertIdx>(e >> 32), b = static_cast<VertIdx>(e);
            ray[fill[a]++] = b;
            ray[fill[b]++] = a;
        }
    }
    // Sorted by angle about the vertex, exactly; the position of each ray.
    std::unordered_map<std::uint64_t, std::uint32_t> position;
    position.reserve(ray.size());
    for (VertIdx v = 0; v < n; ++v) {
        const auto first = ray.begin() + start[v], last = ray.begin() + start[v + 1];
        if (first == last) continue;
        const double* pv = mesh.point(v);
        std::sort(first, last, [&](VertIdx a, VertIdx b) {
            const int ha = half_of(pv, mesh.point(a)), hb = half_of(pv, mesh.point(b));
            if (ha != hb) return ha < hb;
            return predicates::orient2d(pv, mesh.point(a), mesh.point(b)) == Sign::Positive;
        });
        for (auto it = first; it != last; ++it) {
            const auto next = it + 1 == last ? first : it + 1;
            if (next != it && half_of(pv, mesh.point(*it)) == half_of(pv, mesh.point(*next)) &&
                predicates::orient2d(pv, mesh.point(*it), mesh.point(*next)) == Sign::Zero) {
                return CheckReport{false,
                                   "edges " + vertex(v) + " - " + vertex(*it) + " and " +
                                       vertex(v) + " - " + vertex(*next) + " leave vertex " +
                                       vertex(v) + " in the same direction (overlap)",
                                   kNone,
                                   {v, *it, *next}};
            }
            position.emplace(key(v, *it), static_cast<std::uint32_t>(it - first));
        }
    }
    // Each corner (v, a, b) spans from ray a to the next ray: no other edge inside it, so the
    // corners around v do not overlap.
    for (TriIdx t = 0; t < count; ++t) {
        for (unsigned k = 0; k < 3; ++k) {
            const VertIdx v = tv[3 * t + k], a = tv[3 * t + (k + 1) % 3],
                          b = tv[3 * t + (k + 2) % 3];
            const std::uint32_t degree = start[v + 1] - start[v];
            const std::uint32_t pa = position.at(key(v, a)), pb = position.at(key(v, b));
            if ((pa + 1) % degree != pb) {
                const VertIdx inside = ray[start[v] + (pa + 1) % degree];
                return CheckReport{false,
                                   "the triangles around vertex " + vertex(v) + " overlap: edge " +
                                       vertex(v) + " - " + vertex(inside) +
                                       " lies inside the corner of triangle " +
                                       std::to_string(std::uint64_t{t} + numbering.first_triangle) +
                                       " (" + vertex(v) + ", " + vertex(a) + ", " + vertex(b) + ")",
                                   t,
                                   {v, a, b, inside}};
            }
        }
    }
    // The boundary of the mesh is made of pieces.
    std::unordered_set<std::uint64_t> piece_set;
    if (pieces.empty()) {
        for (TriIdx t = 0; t < count; ++t) {
            for (unsigned k = 0; k < 3; ++k) {
                if (!mesh.is_constrained(t, static_cast<int>(k))) continue;
                const VertIdx a = tv[3 * t + k], b = tv[3 * t + (k + 1) % 3];
                piece_set.insert(key(std::min(a, b), std::max(a, b)));
            }
        }
    } else {
        for (std::size_t p = 0; 2 * p + 1 < pieces.size(); ++p) {
            const VertIdx a = pieces[2 * p], b = pieces[2 * p + 1];
            piece_set.insert(key(std::min(a, b), std::max(a, b)));
        }
    }
    for (TriIdx t = 0; t < count; ++t) {
        for (unsigned k = 0; k < 3; ++k) {
            const VertIdx a = tv[3 * t + k], b = tv[3 * t + (k + 1) % 3];
            if (directed.count(key(b, a)) || piece_set.count(key(std::min(a, b), std::max(a, b))))
                continue;
            return CheckReport{
                false,
                "edge " + vertex(a) + " - " + vertex(b) +
                    " bounds the mesh (a triangle on one side only) but is no piece of a segment",
                t,
                {a, b}};
        }
    }
    return check_input_vertices_kept_2d(
        mesh, std::span<const double>(mesh.xy).first(2 * std::size_t{input_vertex_count}),
        numbering);
}

}  // namespace exactmesh::triangulation
