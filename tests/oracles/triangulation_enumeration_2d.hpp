// SPDX-License-Identifier: MIT
// Brute-force oracle for optimal triangulations of small point sets (n <= about 10): every
// triangulation of the points over their convex hull is enumerated as a maximal set of pairwise
// non-crossing segments [a triangulation is exactly a maximal plane straight-line graph on the
// points; de Berg et al., Computational Geometry, Thm 9.1], and the min-max angle over all of
// them is found with exact rational arithmetic (GMP, predicates/exact_reference). Shares no
// code with edge_swap_2d, edge_cutting_2d or angle_comparisons_2d. Test-grade: exponential in n.
#pragma once

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "predicates/exact_reference.hpp"
#include "predicates/sign.hpp"

namespace exactmesh::oracles {

/// An angle in (0, pi) as the exact pair (dot, cross) of its two rays, cross > 0: the angle is
/// atan2(cross, dot), and atan2 of upper half-plane vectors orders like the cross product.
struct ExactAngle {
    mpq_class dot, cross;
};

/// Sign of angle x - angle y.
inline int compare_exact_angles(const ExactAngle& x, const ExactAngle& y) {
    return sgn(y.dot * x.cross - x.dot * y.cross);
}

/// The largest angle of triangle (a, b, c) (any orientation, not degenerate), exactly.
inline ExactAngle largest_exact_angle(std::span<const double> xy, std::uint32_t a, std::uint32_t b,
                                      std::uint32_t c) {
    using predicates::reference::exact;
    const std::array<std::uint32_t, 3> v{a, b, c};
    ExactAngle best;
    bool first = true;
    for (unsigned k = 0; k < 3; ++k) {
        const std::uint32_t o = v[k], p = v[(k + 1) % 3], q = v[(k + 2) % 3];
        const mpq_class ux = exact(xy[2 * p]) - exact(xy[2 * o]);
        const mpq_class uy = exact(xy[2 * p + 1]) - exact(xy[2 * o + 1]);
        const mpq_class vx = exact(xy[2 * q]) - exact(xy[2 * o]);
        const mpq_class vy = exact(xy[2 * q + 1]) - exact(xy[2 * o + 1]);
        ExactAngle angle{ux * vx + uy * vy, ux * vy - uy * vx};
        if (sgn(angle.cross) < 0) angle.cross = -angle.cross;
        if (first || compare_exact_angles(angle, best) > 0) best = angle;
        first = false;
    }
    return best;
}

/// The largest angle over a triangle list (3·#T indices); {0, 0} for an empty list.
inline ExactAngle largest_exact_angle(std::span<const double> xy,
                                      std::span<const std::uint32_t> triangles) {
    ExactAngle best{0, 0};
    for (std::size_t t = 0; t < triangles.size(); t += 3) {
        const ExactAngle angle =
            largest_exact_angle(xy, triangles[t], triangles[t + 1], triangles[t + 2]);
        if (t == 0 || compare_exact_angles(angle, best) > 0) best = angle;
    }
    return best;
}

/// Calls `visit` with the triangles (counter-clockwise, 3·#T indices) of every triangulation of
/// the points xy (distinct, finite). Collinear points: a segment through a third point is never
/// an edge. Returns the number of triangulations (0 when all points are collinear).
inline std::size_t enumerate_triangulations_2d(
    std::span<const double> xy,
    const std::function<void(const std::vector<std::uint32_t>&)>& visit) {
    using predicates::Sign;
    const auto n = static_cast<std::uint32_t>(xy.size() / 2);
    auto at = [&](std::uint32_t v) { return xy.data() + 2 * std::size_t{v}; };
    std::vector<int> orientation(std::size_t{n} * n * n, 0);
    auto orient = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        return orientation[(std::size_t{a} * n + b) * n + c];
    };
    for (std::uint32_t a = 0; a < n; ++a) {
        for (std::uint32_t b = 0; b < n; ++b) {
            for (std::uint32_t c = 0; c < n; ++c) {
                orientation[(std::size_t{a} * n + b) * n + c] =
                    to_int(predicates::reference::orient2d(at(a), at(b), at(c)));
            }
        }
    }
    // Candidate edges: segments with no point on them but their endpoints.
    std::vector<std::array<std::uint32_t, 2>> segments;
    for (std::uint32_t a = 0; a < n; ++a) {
        for (std::uint32_t b = a + 1; b < n; ++b) {
            bool clear = true;
            for (std::uint32_t c = 0; c < n && clear; ++c) {
                if (c == a || c == b || orient(a, b, c) != 0) continue;
                const int k = xy[2 * a] != xy[2 * b] ? 0 : 1;
                const double lo = std::min(xy[2 * a + k], xy[2 * b + k]);
                const double hi = std::max(xy[2 * a + k], xy[2 * b + k]);
                if (lo < xy[2 * c + k] && xy[2 * c + k] < hi) clear = false;
            }
            if (clear) segments.push_back({a, b});
        }
    }
    const std::size_t m = segments.size();
    // Two clear segments cross exactly when their interiors meet at one point: strict signs.
    std::vector<std::uint8_t> crosses(m * m, 0);
    for (std::size_t i = 0; i < m; ++i) {
        for (std::size_t j = 0; j < m; ++j) {
            const auto [a, b] = segments[i];
            const auto [c, d] = segments[j];
            crosses[i * m + j] =
                orient(a, b, c) * orient(a, b, d) < 0 && orient(c, d, a) * orient(c, d, b) < 0;
        }
    }
    std::vector<std::uint8_t> chosen(m, 0);
    std::vector<std::uint32_t> triangles;
    std::size_t count = 0;
    auto blocked = [&](std::size_t j) {
        for (std::size_t i = 0; i < m; ++i) {
            if (chosen[i] && crosses[i * m + j]) return true;
        }
        return false;
    };
    auto emit = [&] {
        // Maximality: every segment left out crosses a chosen one.
        for (std::size_t j = 0; j < m; ++j) {
            if (!chosen[j] && !blocked(j)) return;
        }
        std::vector<std::vector<std::uint8_t>> edge(n, std::vector<std::uint8_t>(n, 0));
        for (std::size_t i = 0; i < m; ++i) {
            if (chosen[i])
                edge[segments[i][0]][segments[i][1]] = edge[segments[i][1]][segments[i][0]] = 1;
        }
        triangles.clear();
        for (std::uint32_t a = 0; a < n; ++a) {
            for (std::uint32_t b = a + 1; b < n; ++b) {
                if (!edge[a][b]) continue;
                for (std::uint32_t c = b + 1; c < n; ++c) {
                    if (!edge[a][c] || !edge[b][c] || orient(a, b, c) == 0) continue;
                    const int s = orient(a, b, c);
                    bool empty = true;
                    for (std::uint32_t v = 0; v < n && empty; ++v) {
                        if (v == a || v == b || v == c) continue;
                        if (orient(a, b, v) == s && orient(b, c, v) == s && orient(c, a, v) == s) {
                            empty = false;
                        }
                    }
                    if (!empty) continue;
                    if (s > 0) {
                        triangles.insert(triangles.end(), {a, b, c});
                    } else {
                        triangles.insert(triangles.end(), {a, c, b});
                    }
                }
            }
        }
        if (triangles.empty()) return;  // collinear points: segments, but no triangulation
        ++count;
        visit(triangles);
    };
    // Include/exclude each segment in order; a segment is excluded only while some later
    // segment could still cross it (a sound prune: choosing more only blocks more).
    std::function<void(std::size_t)> search = [&](std::size_t i) {
        if (i == m) {
            emit();
            return;
        }
        if (blocked(i)) {
            search(i + 1);
            return;
        }
        chosen[i] = 1;
        search(i + 1);
        chosen[i] = 0;
        for (std::size_t j = i + 1; j < m; ++j) {
            if (crosses[i * m + j] && !blocked(j)) {
                search(i + 1);
                return;
            }
        }
    };
    search(0);
    return count;
}

/// The smallest possible largest angle over all triangulations of xy, and how many there are.
struct MinMaxAngleOptimum {
    ExactAngle angle;
    std::size_t triangulations = 0;
};

inline MinMaxAngleOptimum min_max_angle_by_enumeration(std::span<const double> xy) {
    const std::size_t n = xy.size() / 2;
    // Each triangle's largest angle, computed once (indexed by its sorted vertex triple).
    std::vector<ExactAngle> cache(n * n * n);
    std::vector<std::uint8_t> cached(n * n * n, 0);
    MinMaxAngleOptimum best;
    bool first = true;
    best.triangulations = enumerate_triangulations_2d(xy, [&](const std::vector<std::uint32_t>& t) {
        const ExactAngle* worst = nullptr;
        for (std::size_t i = 0; i < t.size(); i += 3) {
            std::array<std::uint32_t, 3> v{t[i], t[i + 1], t[i + 2]};
            std::sort(v.begin(), v.end());
            const std::size_t key = (v[0] * n + v[1]) * n + v[2];
            if (!cached[key]) {
                cache[key] = largest_exact_angle(xy, v[0], v[1], v[2]);
                cached[key] = 1;
            }
            if (worst == nullptr || compare_exact_angles(cache[key], *worst) > 0)
                worst = &cache[key];
        }
        if (worst != nullptr && (first || compare_exact_angles(*worst, best.angle) < 0)) {
            best.angle = *worst;
            first = false;
        }
    });
    return best;
}

}  // namespace exactmesh::oracles
