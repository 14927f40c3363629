// SPDX-License-Identifier: MIT
// Exact validation of constrained Delaunay triangulations (see check_constrained_2d.hpp).
#include "triangulation/checks/check_constrained_2d.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "predicates/angle_comparisons_2d.hpp"
#include "predicates/exact_reference.hpp"
#include "predicates/incircle.hpp"
#include "predicates/orient2d.hpp"
#include "predicates/within_rounding_of_segment.hpp"

namespace exactmesh::triangulation {

namespace {

using predicates::Sign;

CheckReport fail(std::string problem, TriIdx t = kNone, std::vector<VertIdx> vertices = {}) {
    return CheckReport{false, std::move(problem), t, std::move(vertices)};
}

}  // namespace

namespace detail {

CheckReport check_constrained_mesh_2d(const Triangulation2& mesh, std::uint32_t input_vertex_count,
                                      std::span<const VertIdx> segments,
                                      std::span<const VertIdx> pieces, CheckNumbering numbering,
                                      bool delaunay) {
    const std::uint32_t n = mesh.vertex_count();
    const TriIdx count = mesh.triangle_count();
    const auto& tv = mesh.triangles;
    auto vertex = [&](VertIdx v) {
        return std::to_string(std::uint64_t{v} + numbering.first_vertex);
    };
    auto triangle = [&](TriIdx t) {
        return "triangle " + std::to_string(std::uint64_t{t} + numbering.first_triangle) + " (" +
               vertex(tv[3 * t]) + ", " + vertex(tv[3 * t + 1]) + ", " + vertex(tv[3 * t + 2]) +
               ")";
    };
    if (input_vertex_count > n) {
        return fail(std::to_string(input_vertex_count) + " input vertices, but the mesh has only " +
                    std::to_string(n));
    }
    if (!mesh.constrained.empty() && mesh.constrained.size() != tv.size()) {
        return fail("constraint flags: " + std::to_string(mesh.constrained.size()) + " for " +
                    std::to_string(count) + " triangles");
    }
    // Topology: orientation, directed edges once.
    std::unordered_map<std::uint64_t, EdgeIdx> edge_of;
    edge_of.reserve(tv.size());
    auto key = [](VertIdx a, VertIdx b) { return (std::uint64_t{a} << 32) | b; };
    for (TriIdx t = 0; t < count; ++t) {
        for (unsigned k = 0; k < 3; ++k) {
            if (tv[3 * t + k] >= n)
                return fail(triangle(t) + " names a vertex that does not exist", t);
        }
        if (predicates::orient2d(mesh.point(tv[3 * t]), mesh.point(tv[3 * t + 1]),
                                 mesh.point(tv[3 * t + 2])) != Sign::Positive) {
            return fail(triangle(t) + " is not counter-clockwise (or is degenerate)", t);
        }
        for (unsigned k = 0; k < 3; ++k) {
            const VertIdx a = tv[3 * t + k], b = tv[3 * t + (k + 1) % 3];
            if (!edge_of.emplace(key(a, b), 3 * t + k).second) {
                return fail("edge " + vertex(a) + " -> " + vertex(b) +
                                " appears in two triangles (overlap)",
                            t, {a, b});
            }
        }
    }
    // Flags symmetric; unconstrained interior edges locally Delaunay (when asked).
    for (TriIdx t = 0; t < count; ++t) {
        for (unsigned k = 0; k < 3; ++k) {
            const VertIdx a = tv[3 * t + k], b = tv[3 * t + (k + 1) % 3],
                          c = tv[3 * t + (k + 2) % 3];
            const auto other = edge_of.find(key(b, a));
            if (other == edge_of.end()) continue;
            const EdgeIdx f = other->second;
            const bool constrained = mesh.is_constrained(t, static_cast<int>(k));
            if (constrained != mesh.is_constrained(triangle_of(f), static_cast<int>(f % 3))) {
                return fail(
                    "edge " + vertex(a) + " - " + vertex(b) + " is constrained on one side only", t,
                    {a, b});
            }
            if (!delaunay || constrained || a > b) continue;
            const VertIdx d = tv[3 * triangle_of(f) + (f % 3 + 2) % 3];
            if (predicates::incircle(mesh.point(a), mesh.point(b), mesh.point(c), mesh.point(d)) ==
                Sign::Positive) {
                return fail("unconstrained edge " + vertex(a) + " - " + vertex(b) +
                                " is not locally Delaunay: vertex " + vertex(d) +
                                " lies inside the circumcircle of " + triangle(t),
                            t, {a, b, c, d});
            }
        }
    }
    // Pieces: given, or the flagged edges.
    std::vector<std::vector<VertIdx>> constrained_neighbors(n);
    auto add_piece = [&](VertIdx a, VertIdx b) {
        auto& na = constrained_neighbors[a];
        if (std::find(na.begin(), na.end(), b) == na.end()) na.push_back(b);
        auto& nb = constrained_neighbors[b];
        if (std::find(nb.begin(), nb.end(), a) == nb.end()) nb.push_back(a);
    };
    if (pieces.empty()) {
        for (TriIdx t = 0; t < count; ++t) {
            for (unsigned k = 0; k < 3; ++k) {
                if (mesh.is_constrained(t, static_cast<int>(k)))
                    add_piece(tv[3 * t + k], tv[3 * t + (k + 1) % 3]);
            }
        }
    } else {
        std::vector<std::vector<TriIdx>> triangles_at(n);
        for (TriIdx t = 0; t < count; ++t) {
            for (unsigned k = 0; k < 3; ++k) triangles_at[tv[3 * t + k]].push_back(t);
        }
        for (std::size_t p = 0; 2 * p + 1 < pieces.size(); ++p) {
            const VertIdx a = pieces[2 * p], b = pieces[2 * p + 1];
            const std::string name = "piece " + vertex(a) + " - " + vertex(b);
            if (a >= n || b >= n || a == b)
                return fail(name + " is not an edge between two distinct vertices");
            add_piece(a, b);
            const auto e = edge_of.find(key(a, b));
            const auto f = edge_of.find(key(b, a));
            if (e != edge_of.end() || f != edge_of.end()) {
                const EdgeIdx g = e != edge_of.end() ? e->second : f->second;
                if (!mesh.is_constrained(triangle_of(g), static_cast<int>(g % 3))) {
                    return fail(name + " is an edge of the mesh but not constrained",
                                triangle_of(g), {a, b});
                }
                continue;
            }
            // Not an edge: it must stay outside the mesh at both ends.
            for (const auto& [from, to] : {std::pair{a, b}, std::pair{b, a}}) {
                for (const TriIdx t : triangles_at[from]) {
                    unsigned k = 0;
                    while (tv[3 * t + k] != from) ++k;
                    const VertIdx x = tv[3 * t + (k + 1) % 3], y = tv[3 * t + (k + 2) % 3];
                    const Sign sx =
                        predicates::orient2d(mesh.point(from), mesh.point(x), mesh.point(to));
                    const Sign sy =
                        predicates::orient2d(mesh.point(from), mesh.point(y), mesh.point(to));
                    if (sx == Sign::Positive && sy == Sign::Negative) {
                        return fail(name + " is not an edge of the mesh but enters " + triangle(t),
                                    t, {a, b});
                    }
                }
            }
        }
        for (TriIdx t = 0; t < count; ++t) {
            for (unsigned k = 0; k < 3; ++k) {
                if (!mesh.is_constrained(t, static_cast<int>(k))) continue;
                const VertIdx a = tv[3 * t + k], b = tv[3 * t + (k + 1) % 3];
                const auto& na = constrained_neighbors[a];
                if (std::find(na.begin(), na.end(), b) == na.end()) {
                    return fail("constrained edge " + vertex(a) + " - " + vertex(b) +
                                    " is no piece of a segment",
                                t, {a, b});
                }
            }
        }
    }
    // Segments: chains of pieces (the rule: within_rounding_of_segment and exact progress).
    std::vector<std::uint32_t> visited(n, 0);  // segment number + 1 of the last search that met v
    // A segment may name a duplicate point that no triangle uses: follow the copy that is used
    // (a vertex of a triangle or of a piece) at the same coordinates.
    std::vector<std::uint8_t> used(n, 0);
    for (const VertIdx v : tv) used[v] = 1;
    for (VertIdx v = 0; v < n; ++v) {
        if (!constrained_neighbors[v].empty()) used[v] = 1;
    }
    // Keyed by the exact bits of (x, y): a hash of them as the key let two points collide
    // ((-1, -4) and (-4, -1): fuzz_constrained_2d, 2026-11-23).
    std::map<std::pair<std::uint64_t, std::uint64_t>, VertIdx> used_at;
    auto point_key = [&](VertIdx v) {
        const double x = mesh.point(v)[0] + 0.0,
                     y = mesh.point(v)[1] + 0.0;  // -0 as +0, as == compares
        std::pair<std::uint64_t, std::uint64_t> k;
        std::memcpy(&k.first, &x, 8);
        std::memcpy(&k.second, &y, 8);
        return k;
    };
    for (VertIdx v = 0; v < n; ++v) {
        if (used[v]) used_at.emplace(point_key(v), v);
    }
    auto canonical = [&](VertIdx v) {
        if (used[v]) return v;
        const auto it = used_at.find(point_key(v));
        return it == used_at.end() ? v : it->second;
    };
    for (std::size_t s = 0; 2 * s + 1 < segments.size(); ++s) {
        const std::string name = "segment " + std::to_string(s + numbering.first_vertex) + " (" +
                                 vertex(segments[2 * s]) + ", " + vertex(segments[2 * s + 1]) + ")";
        if (segments[2 * s] >= n || segments[2 * s + 1] >= n)
            return fail(name + " names a vertex that does not exist");
        const VertIdx a = canonical(segments[2 * s]), b = canonical(segments[2 * s + 1]);
        const double* pa = mesh.point(a);
        const double* pb = mesh.point(b);
        if (pa[0] == pb[0] && pa[1] == pb[1]) continue;
        auto near_line = [&](VertIdx v) {
            return predicates::within_rounding_of_segment(mesh.point(v), pa, pb);
        };
        // The step current -> w does not move against a -> b (exact).
        auto onward = [&](VertIdx current, VertIdx w) {
            return predicates::direction_dot_sign(mesh.point(current), mesh.point(w), pa, pb) !=
                   Sign::Negative;
        };
        // Depth-first search over constrained pieces never moving away from b, each vertex
        // expanded once: near-collinear vertices can offer several ways on.
        std::vector<VertIdx> stack{a};
        const auto stamp = static_cast<std::uint32_t>(s + 1);
        visited[a] = stamp;
        VertIdx farthest = a;
        bool found = false;
        while (!stack.empty() && !found) {
            const VertIdx current = stack.back();
            stack.pop_back();
            if (predicates::direction_dot_sign(mesh.point(farthest), mesh.point(current), pa, pb) ==
                Sign::Positive) {
                farthest = current;
            }
            for (const VertIdx w : constrained_neighbors[current]) {
                if (w == b) {
                    found = true;
                    break;
                }
                if (visited[w] == stamp) continue;
                // Not backwards (a step across the direction allowed; the visited stamps keep the
                // search finite).
                if (onward(current, w) && near_line(w)) {
                    visited[w] = stamp;
                    stack.push_back(w);
                }
            }
        }
        if (!found) {
            return fail(
                name + " is missing: no chain of constrained pieces continues it beyond vertex " +
                    vertex(farthest),
                kNone, {a, b, farthest});
        }
    }
    return {};
}

}  // namespace detail

CheckReport check_constrained_delaunay_2d(const Triangulation2& mesh,
                                          std::uint32_t input_vertex_count,
                                          std::span<const VertIdx> segments,
                                          std::span<const VertIdx> pieces,
                                          CheckNumbering numbering) {
    return detail::check_constrained_mesh_2d(mesh, input_vertex_count, segments, pieces, numbering,
                                             true);
}

}  // namespace exactmesh::triangulation
