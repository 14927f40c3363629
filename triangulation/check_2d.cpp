// SPDX-License-Identifier: MIT
// Exact validation of 2D triangulations (see check_2d.hpp).
#include "triangulation/check_2d.hpp"

#include <algorithm>
#include <unordered_map>
#include <vector>

#include "predicates/incircle.hpp"
#include "predicates/orient2d.hpp"

namespace exactmesh::triangulation {

namespace {

using predicates::Sign;

std::uint64_t edge_key(VertIdx a, VertIdx b) { return (std::uint64_t{a} << 32) | b; }

CheckReport fail(std::string problem, TriIdx t = kNone) {
    return CheckReport{false, std::move(problem), t};
}

std::string tri_name(std::span<const VertIdx> tris, TriIdx t) {
    return "triangle " + std::to_string(t) + " (" + std::to_string(tris[3 * t]) + ", " +
           std::to_string(tris[3 * t + 1]) + ", " + std::to_string(tris[3 * t + 2]) + ")";
}

}  // namespace

CheckReport check_topology_2d(std::span<const double> xy, std::span<const VertIdx> tris) {
    const auto n = static_cast<VertIdx>(xy.size() / 2);
    const auto count = static_cast<TriIdx>(tris.size() / 3);
    const double* p = xy.data();
    for (TriIdx t = 0; t < count; ++t) {
        for (unsigned k = 0; k < 3; ++k) {
            if (tris[3 * t + k] >= n) return fail(tri_name(tris, t) + ": vertex out of range", t);
        }
        const VertIdx a = tris[3 * t], b = tris[3 * t + 1], c = tris[3 * t + 2];
        if (predicates::orient2d(p + 2 * a, p + 2 * b, p + 2 * c) != Sign::Positive) {
            return fail(tri_name(tris, t) + ": not counter-clockwise (orient2d <= 0)", t);
        }
    }
    // Each directed edge at most once; an edge without its reverse is on the boundary.
    std::unordered_map<std::uint64_t, TriIdx> directed;
    directed.reserve(3 * tris.size());
    for (TriIdx t = 0; t < count; ++t) {
        for (unsigned k = 0; k < 3; ++k) {
            const VertIdx a = tris[3 * t + k], b = tris[3 * t + (k + 1) % 3];
            if (!directed.emplace(edge_key(a, b), t).second) {
                return fail(tri_name(tris, t) + ": edge " + std::to_string(a) + "-" +
                                std::to_string(b) + " used twice in the same direction", t);
            }
        }
    }
    std::vector<VertIdx> boundary_next(n, kNone);
    std::size_t boundary_edges = 0, edges = 0;
    for (const auto& [key, t] : directed) {
        const auto a = static_cast<VertIdx>(key >> 32), b = static_cast<VertIdx>(key & 0xFFFFFFFFu);
        if (directed.count(edge_key(b, a)) == 0) {
            if (boundary_next[a] != kNone) {
                return fail("boundary vertex " + std::to_string(a) + " starts two boundary edges", t);
            }
            boundary_next[a] = b;
            ++boundary_edges;
            ++edges;
        } else if (a < b) {
            ++edges;
        }
    }
    // Distinct points must all be vertices; duplicates may be absent.
    std::vector<bool> used(n, false);
    for (const VertIdx v : tris) used[v] = true;
    std::vector<VertIdx> order(n);
    for (VertIdx v = 0; v < n; ++v) order[v] = v;
    std::sort(order.begin(), order.end(), [p](VertIdx a, VertIdx b) {
        return p[2 * a] < p[2 * b] || (p[2 * a] == p[2 * b] && p[2 * a + 1] < p[2 * b + 1]);
    });
    std::size_t distinct = 0;
    for (std::size_t i = 0; i < order.size();) {
        std::size_t j = i;
        bool any_used = false;
        while (j < order.size() && p[2 * order[j]] == p[2 * order[i]] &&
               p[2 * order[j] + 1] == p[2 * order[i] + 1]) {
            if (used[order[j]]) {
                if (any_used) return fail("two vertices share the coordinates of point " +
                                          std::to_string(order[j]));
                any_used = true;
            }
            ++j;
        }
        ++distinct;
        if (!any_used && count > 0) {
            return fail("point " + std::to_string(order[i]) + " is not a vertex of any triangle");
        }
        i = j;
    }
    if (count == 0) return {};
    // One boundary loop, convex (left turns or straight) and counter-clockwise.
    VertIdx start = kNone;
    for (VertIdx v = 0; v < n && start == kNone; ++v) {
        if (boundary_next[v] != kNone) start = v;
    }
    std::size_t loop = 0;
    VertIdx v = start;
    do {
        const VertIdx w = boundary_next[v];
        if (w == kNone) return fail("boundary is not closed at vertex " + std::to_string(v));
        const VertIdx x = boundary_next[w];
        if (x == kNone) return fail("boundary is not closed at vertex " + std::to_string(w));
        if (predicates::orient2d(p + 2 * v, p + 2 * w, p + 2 * x) == Sign::Negative) {
            return fail("boundary turns right at vertex " + std::to_string(w) +
                        ": not the convex hull");
        }
        v = w;
        if (++loop > boundary_edges) break;
    } while (v != start);
    if (loop != boundary_edges) return fail("boundary has more than one loop");
    // Euler for a disk: V - E + F = 1.
    const auto euler = static_cast<long long>(distinct) - static_cast<long long>(edges) +
                       static_cast<long long>(count);
    if (euler != 1) return fail("Euler characteristic " + std::to_string(euler) + " instead of 1");
    return {};
}

CheckReport check_delaunay_2d(std::span<const double> xy, std::span<const VertIdx> tris) {
    CheckReport report = check_topology_2d(xy, tris);
    if (!report.ok) return report;
    const auto count = static_cast<TriIdx>(tris.size() / 3);
    std::unordered_map<std::uint64_t, std::uint32_t> apex;  // directed edge -> opposite vertex
    apex.reserve(3 * tris.size());
    for (TriIdx t = 0; t < count; ++t) {
        for (unsigned k = 0; k < 3; ++k) {
            apex.emplace(edge_key(tris[3 * t + k], tris[3 * t + (k + 1) % 3]), tris[3 * t + (k + 2) % 3]);
        }
    }
    const double* p = xy.data();
    for (TriIdx t = 0; t < count; ++t) {
        for (unsigned k = 0; k < 3; ++k) {
            const VertIdx a = tris[3 * t + k], b = tris[3 * t + (k + 1) % 3];
            const VertIdx c = tris[3 * t + (k + 2) % 3];
            const auto it = apex.find(edge_key(b, a));
            if (it == apex.end()) continue;
            const VertIdx d = it->second;
            if (predicates::incircle(p + 2 * a, p + 2 * b, p + 2 * c, p + 2 * d) == Sign::Positive) {
                return fail(tri_name(tris, t) + ": not Delaunay, vertex " + std::to_string(d) +
                                " lies inside its circumcircle",
                            t);
            }
        }
    }
    return {};
}

}  // namespace exactmesh::triangulation
