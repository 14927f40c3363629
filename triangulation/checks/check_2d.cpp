// SPDX-License-Identifier: MIT
// Exact validation of 2D triangulations (see check_2d.hpp).
#include "triangulation/checks/check_2d.hpp"

#include <algorithm>
#include <unordered_map>
#include <utility>

#include "predicates/incircle.hpp"
#include "predicates/orient2d.hpp"

namespace exactmesh::triangulation {

namespace {

using predicates::Sign;

std::uint64_t edge_key(VertIdx a, VertIdx b) {
    return (std::uint64_t{a} << 32) | b;
}

/// Vertices and triangles named in the caller's numbering.
class Namer {
  public:
    Namer(std::span<const VertIdx> tris, CheckNumbering numbering)
        : tris_(tris), numbering_(numbering) {}

    std::string vertex(VertIdx v) const {
        return std::to_string(std::uint64_t{v} + numbering_.first_vertex);
    }
    std::string triangle(TriIdx t) const {
        return "triangle " + std::to_string(std::uint64_t{t} + numbering_.first_triangle) + " (" +
               vertex(tris_[3 * std::size_t{t}]) + ", " + vertex(tris_[3 * std::size_t{t} + 1]) +
               ", " + vertex(tris_[3 * std::size_t{t} + 2]) + ")";
    }

  private:
    std::span<const VertIdx> tris_;
    CheckNumbering numbering_;
};

CheckReport fail(std::string problem, TriIdx t = kNone, std::vector<VertIdx> vertices = {}) {
    return CheckReport{false, std::move(problem), t, std::move(vertices)};
}

bool same_point(const double* p, VertIdx a, VertIdx b) {
    return p[2 * std::size_t{a}] == p[2 * std::size_t{b}] &&
           p[2 * std::size_t{a} + 1] == p[2 * std::size_t{b} + 1];
}

/// Without triangles the points must span no triangle: fails naming three non-collinear points
/// (the first point, the first one elsewhere, the first one off their line).
CheckReport check_collinear(std::span<const double> xy, const Namer& name) {
    const auto n = static_cast<VertIdx>(xy.size() / 2);
    const double* p = xy.data();
    VertIdx b = kNone;
    for (VertIdx v = 1; v < n && b == kNone; ++v) {
        if (!same_point(p, 0, v)) b = v;
    }
    if (b == kNone) return {};
    for (VertIdx c = b + 1; c < n; ++c) {
        if (predicates::orient2d(p, p + 2 * std::size_t{b}, p + 2 * std::size_t{c}) != Sign::Zero) {
            return fail("no triangles, but points " + name.vertex(0) + ", " + name.vertex(b) +
                            ", " + name.vertex(c) + " are not collinear",
                        kNone, {0, b, c});
        }
    }
    return {};
}

}  // namespace

CheckReport check_topology_2d(std::span<const double> xy, std::span<const VertIdx> tris,
                              CheckNumbering numbering) {
    const Namer name(tris, numbering);
    const auto n = static_cast<VertIdx>(xy.size() / 2);
    const auto count = static_cast<TriIdx>(tris.size() / 3);
    const double* p = xy.data();
    auto point = [p](VertIdx v) { return p + 2 * std::size_t{v}; };
    for (TriIdx t = 0; t < count; ++t) {
        for (unsigned k = 0; k < 3; ++k) {
            if (tris[3 * t + k] >= n) {
                return fail(name.triangle(t) + ": vertex out of range", t, {tris[3 * t + k]});
            }
        }
        const VertIdx a = tris[3 * t], b = tris[3 * t + 1], c = tris[3 * t + 2];
        if (predicates::orient2d(point(a), point(b), point(c)) != Sign::Positive) {
            return fail(name.triangle(t) + ": not counter-clockwise (orient2d <= 0)", t);
        }
    }
    // Each directed edge at most once; an edge without its reverse is on the boundary.
    std::unordered_map<std::uint64_t, TriIdx> directed;
    directed.reserve(3 * tris.size());
    for (TriIdx t = 0; t < count; ++t) {
        for (unsigned k = 0; k < 3; ++k) {
            const VertIdx a = tris[3 * t + k], b = tris[3 * t + (k + 1) % 3];
            if (!directed.emplace(edge_key(a, b), t).second) {
                return fail(name.triangle(t) + ": edge " + name.vertex(a) + "-" + name.vertex(b) +
                                " used twice in the same direction",
                            t, {a, b});
            }
        }
    }
    std::vector<VertIdx> boundary_next(n, kNone);
    std::size_t boundary_edges = 0, edges = 0;
    for (const auto& [key, t] : directed) {
        const auto a = static_cast<VertIdx>(key >> 32), b = static_cast<VertIdx>(key & 0xFFFFFFFFu);
        if (directed.count(edge_key(b, a)) == 0) {
            if (boundary_next[a] != kNone) {
                return fail("boundary vertex " + name.vertex(a) + " starts two boundary edges", t,
                            {a});
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
        return p[2 * a] < p[2 * b] || (p[2 * a] == p[2 * b] && p[2 * a + 1] < p[2 * b + 1]) ||
               (p[2 * a] == p[2 * b] && p[2 * a + 1] == p[2 * b + 1] && a < b);
    });
    std::size_t distinct = 0;
    for (std::size_t i = 0; i < order.size();) {
        std::size_t j = i;
        VertIdx first_used = kNone;
        while (j < order.size() && same_point(p, order[j], order[i])) {
            if (used[order[j]]) {
                if (first_used != kNone) {
                    return fail("vertices " + name.vertex(first_used) + " and " +
                                    name.vertex(order[j]) + " have the same coordinates",
                                kNone, {first_used, order[j]});
                }
                first_used = order[j];
            }
            ++j;
        }
        ++distinct;
        if (first_used == kNone && count > 0) {
            return fail("point " + name.vertex(order[i]) + " is not a vertex of any triangle",
                        kNone, {order[i]});
        }
        i = j;
    }
    if (count == 0) return check_collinear(xy, name);
    // One boundary loop, convex (left turns or straight) and counter-clockwise.
    VertIdx start = kNone;
    for (VertIdx v = 0; v < n && start == kNone; ++v) {
        if (boundary_next[v] != kNone) start = v;
    }
    if (start == kNone) return fail("no boundary edge: the triangles do not form a disk");
    std::size_t loop = 0;
    VertIdx v = start;
    do {
        const VertIdx w = boundary_next[v];
        if (w == kNone)
            return fail("boundary is not closed at vertex " + name.vertex(v), kNone, {v});
        const VertIdx x = boundary_next[w];
        if (x == kNone)
            return fail("boundary is not closed at vertex " + name.vertex(w), kNone, {w});
        if (predicates::orient2d(point(v), point(w), point(x)) == Sign::Negative) {
            return fail(
                "boundary turns right at vertex " + name.vertex(w) + ": not the convex hull", kNone,
                {w});
        }
        v = w;
        if (++loop > boundary_edges) break;
    } while (v != start);
    if (loop != boundary_edges) return fail("boundary has more than one loop");
    // Left turns alone admit a loop that winds twice (a pentagram: every turn is left, and its
    // fan of positive triangles covers the centre twice). Seen from its lowest-leftmost vertex
    // (all other points lie in the half-plane beyond it, an angle range below pi), a loop that
    // winds once meets the vertices in counter-clockwise angular order.
    VertIdx lowest = start;
    for (v = boundary_next[start]; v != start; v = boundary_next[v]) {
        const double* a = point(v);
        const double* b = point(lowest);
        if (a[0] < b[0] || (a[0] == b[0] && a[1] < b[1])) lowest = v;
    }
    for (v = boundary_next[lowest]; boundary_next[v] != lowest; v = boundary_next[v]) {
        const VertIdx w = boundary_next[v];
        if (predicates::orient2d(point(lowest), point(v), point(w)) == Sign::Negative) {
            return fail("boundary winds around vertex " + name.vertex(lowest) +
                            " more than once (at edge " + name.vertex(v) + "-" + name.vertex(w) +
                            "): not the convex hull",
                        kNone, {lowest, v, w});
        }
    }
    // Euler for a disk: V - E + F = 1.
    const auto euler = static_cast<long long>(distinct) - static_cast<long long>(edges) +
                       static_cast<long long>(count);
    if (euler != 1) return fail("Euler characteristic " + std::to_string(euler) + " instead of 1");
    return {};
}

CheckReport check_delaunay_2d(std::span<const double> xy, std::span<const VertIdx> tris,
                              CheckNumbering numbering) {
    CheckReport report = check_topology_2d(xy, tris, numbering);
    if (!report.ok) return report;
    const Namer name(tris, numbering);
    const auto count = static_cast<TriIdx>(tris.size() / 3);
    std::unordered_map<std::uint64_t, std::uint32_t> apex;  // directed edge -> opposite vertex
    apex.reserve(3 * tris.size());
    for (TriIdx t = 0; t < count; ++t) {
        for (unsigned k = 0; k < 3; ++k) {
            apex.emplace(edge_key(tris[3 * t + k], tris[3 * t + (k + 1) % 3]),
                         tris[3 * t + (k + 2) % 3]);
        }
    }
    const double* p = xy.data();
    auto point = [p](VertIdx v) { return p + 2 * std::size_t{v}; };
    for (TriIdx t = 0; t < count; ++t) {
        for (unsigned k = 0; k < 3; ++k) {
            const VertIdx a = tris[3 * t + k], b = tris[3 * t + (k + 1) % 3];
            const VertIdx c = tris[3 * t + (k + 2) % 3];
            const auto it = apex.find(edge_key(b, a));
            if (it == apex.end()) continue;
            const VertIdx d = it->second;
            if (predicates::incircle(point(a), point(b), point(c), point(d)) == Sign::Positive) {
                return fail(name.triangle(t) + ": not Delaunay, vertex " + name.vertex(d) +
                                " lies inside its circumcircle",
                            t, {d});
            }
        }
    }
    return {};
}

}  // namespace exactmesh::triangulation
