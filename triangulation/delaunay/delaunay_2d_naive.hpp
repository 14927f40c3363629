// SPDX-License-Identifier: MIT
// Naive 2D Delaunay oracle (geogram's *_naive idea): the empty-circle definition [Delaunay34]
// tested over all triples, O(n^4). Its predicates share no code with the adaptive ones the
// algorithms use: a plain static filter of its own, then the GMP reference (predicates/
// exact_reference). Library code so that the shipped `exactmesh fuzz` can use it (as geogram
// ships its *_naive checks); meant for n up to about 60; also used by the Delaunay fuzz target.
// Its static filter is Shewchuk's a-priori bound with margin, deliberately not the adaptive
// predicates' (an oracle that shared their code could share their bugs); it only ever answers
// far from zero and defers every close call to the GMP reference.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <span>
#include <string>
#include <vector>

#include "predicates/exact_reference.hpp"
#include "predicates/sign.hpp"

namespace exactmesh::triangulation {

/// What the empty-circle definition says about a point set, computed by brute force.
struct NaiveDelaunay2 {
    /// Per input point: the smallest index with the same coordinates ("first occurrence").
    std::vector<std::uint32_t> representative;
    std::size_t distinct = 0;  ///< distinct points
    std::size_t hull = 0;      ///< distinct points on the convex hull's boundary (corners or not)
    bool collinear = true;     ///< all distinct points on one line (or fewer than 3)
    /// 2·distinct - hull - 2 triangles in every triangulation of the points, 0 when collinear.
    std::size_t triangle_count = 0;
    /// Triangles (representatives, counter-clockwise, smallest index first, sorted) whose
    /// circumcircle has every other distinct point strictly outside: they belong to every
    /// Delaunay triangulation.
    std::vector<std::array<std::uint32_t, 3>> strict_triangles;
};

namespace naive_detail {

using predicates::Sign;

inline const double* at(std::span<const double> xy, std::uint32_t v) {
    return xy.data() + 2 * std::size_t{v};
}

/// A static floating-point filter of the oracle's own, so that the O(n^4) loops stay fast: the
/// sign of `det` when |det| exceeds Shewchuk's a-priori bound for the plain evaluation
/// [Shewchuk97 §4.2: ccwerrboundA = (3 + 16u)u, iccerrboundA = (10 + 96u)u, u = 2^-53], taken
/// with margin (3.5u, 11u). The bound holds only without overflow and underflow, so the filter
/// answers only when every nonzero coordinate difference lies in [2^-250, 2^250]: then every
/// product of up to four of them (orient has two, incircle four) lies in [2^-1000, 2^1000],
/// normal and finite, and every sum of such terms is either normal (relative error u) or exact.
/// (A window on the permanent alone is not enough: a product of two subnormal-sized
/// differences underflows by up to 2^-1074 and a lift of 2^700 then multiplies that error far
/// past the bound; fuzz_delaunay_2d found it.) Otherwise 0: ask the GMP reference.
inline bool differences_in_filter_window(std::initializer_list<double> differences) {
    for (const double d : differences) {
        const double a = std::fabs(d);
        if (a != 0.0 && !(a >= 0x1p-250 && a <= 0x1p+250)) return false;
    }
    return true;
}

inline int filtered_sign(double det, double permanent, double relative_bound) {
    const double bound = relative_bound * permanent;
    return det > bound ? 1 : (-det > bound ? -1 : 0);
}

inline Sign orient(std::span<const double> xy, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    const double *pa = at(xy, a), *pb = at(xy, b), *pc = at(xy, c);
    const double acx = pa[0] - pc[0], acy = pa[1] - pc[1];
    const double bcx = pb[0] - pc[0], bcy = pb[1] - pc[1];
    if (!differences_in_filter_window({acx, acy, bcx, bcy})) {
        return predicates::reference::orient2d_differences(pa, pb, pc);
    }
    const double left = acx * bcy;
    const double right = acy * bcx;
    const int s = filtered_sign(left - right, std::fabs(left) + std::fabs(right), 3.5 * 0x1p-53);
    if (s != 0) return s > 0 ? Sign::Positive : Sign::Negative;
    return predicates::reference::orient2d_differences(pa, pb, pc);
}

inline Sign incircle(std::span<const double> xy, std::uint32_t a, std::uint32_t b, std::uint32_t c,
                     std::uint32_t d) {
    const double *pa = at(xy, a), *pb = at(xy, b), *pc = at(xy, c), *pd = at(xy, d);
    const double adx = pa[0] - pd[0], ady = pa[1] - pd[1];
    const double bdx = pb[0] - pd[0], bdy = pb[1] - pd[1];
    const double cdx = pc[0] - pd[0], cdy = pc[1] - pd[1];
    if (!differences_in_filter_window({adx, ady, bdx, bdy, cdx, cdy})) {
        return predicates::reference::incircle_differences(pa, pb, pc, pd);
    }
    const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
    const double cdxady = cdx * ady, adxcdy = adx * cdy;
    const double adxbdy = adx * bdy, bdxady = bdx * ady;
    const double alift = adx * adx + ady * ady;
    const double blift = bdx * bdx + bdy * bdy;
    const double clift = cdx * cdx + cdy * cdy;
    const double det =
        alift * (bdxcdy - cdxbdy) + blift * (cdxady - adxcdy) + clift * (adxbdy - bdxady);
    const double permanent = (std::fabs(bdxcdy) + std::fabs(cdxbdy)) * alift +
                             (std::fabs(cdxady) + std::fabs(adxcdy)) * blift +
                             (std::fabs(adxbdy) + std::fabs(bdxady)) * clift;
    const int s = filtered_sign(det, permanent, 11.0 * 0x1p-53);
    if (s != 0) return s > 0 ? Sign::Positive : Sign::Negative;
    return predicates::reference::incircle_differences(pa, pb, pc, pd);
}
/// The triangle rotated to start at its smallest index (orientation kept).
inline std::array<std::uint32_t, 3> rotated(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    std::array<std::uint32_t, 3> t{a, b, c};
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    return t;
}

}  // namespace naive_detail

/// The brute-force facts about xy (2·#V finite doubles).
inline NaiveDelaunay2 delaunay_2d_naive(std::span<const double> xy) {
    using naive_detail::incircle;
    using naive_detail::orient;
    using predicates::Sign;
    const auto n = static_cast<std::uint32_t>(xy.size() / 2);
    NaiveDelaunay2 out;
    out.representative.resize(n);
    std::vector<std::uint32_t> points;  // one per distinct position, the smallest index
    for (std::uint32_t v = 0; v < n; ++v) {
        out.representative[v] = v;
        for (const std::uint32_t u : points) {
            if (xy[2 * u] == xy[2 * v] && xy[2 * u + 1] == xy[2 * v + 1]) {
                out.representative[v] = u;
                break;
            }
        }
        if (out.representative[v] == v) points.push_back(v);
    }
    out.distinct = points.size();
    // A point is on the hull's boundary when it lies on a supporting line: a line through two
    // points with every point on its left or on it.
    std::vector<bool> on_hull(points.size(), false);
    for (std::size_t i = 0; i < points.size(); ++i) {
        for (std::size_t j = 0; j < points.size(); ++j) {
            if (i == j) continue;
            bool supporting = true;
            for (std::size_t k = 0; k < points.size() && supporting; ++k) {
                if (orient(xy, points[i], points[j], points[k]) == Sign::Negative) {
                    supporting = false;
                    out.collinear = false;
                }
            }
            if (!supporting) continue;
            for (std::size_t k = 0; k < points.size(); ++k) {
                if (orient(xy, points[i], points[j], points[k]) == Sign::Zero) on_hull[k] = true;
            }
        }
    }
    out.hull = static_cast<std::size_t>(std::count(on_hull.begin(), on_hull.end(), true));
    if (!out.collinear) out.triangle_count = 2 * out.distinct - out.hull - 2;
    // Strictly Delaunay triangles: every other point strictly outside the circumcircle.
    for (std::size_t i = 0; i < points.size(); ++i) {
        for (std::size_t j = i + 1; j < points.size(); ++j) {
            for (std::size_t k = j + 1; k < points.size(); ++k) {
                std::uint32_t a = points[i], b = points[j], c = points[k];
                const Sign s = orient(xy, a, b, c);
                if (s == Sign::Zero) continue;
                if (s == Sign::Negative) std::swap(b, c);
                bool empty = true;
                for (std::size_t m = 0; m < points.size() && empty; ++m) {
                    if (m == i || m == j || m == k) continue;
                    empty = incircle(xy, a, b, c, points[m]) == Sign::Negative;
                }
                if (empty) out.strict_triangles.push_back(naive_detail::rotated(a, b, c));
            }
        }
    }
    std::sort(out.strict_triangles.begin(), out.strict_triangles.end());
    return out;
}

/// Compares a claimed Delaunay triangulation (3·#T input indices, counter-clockwise) of xy
/// with the oracle: the triangle count, every vertex a first occurrence, every triangle
/// counter-clockwise with an empty circumcircle (cocircular points allowed), every strictly
/// Delaunay triangle present; and `merged_into`, when given, the first occurrences.
/// @return an empty string when they agree, else the first disagreement in words.
inline std::string compare_with_delaunay_2d_naive(std::span<const double> xy,
                                                  std::span<const std::uint32_t> triangles,
                                                  const NaiveDelaunay2& oracle,
                                                  std::span<const std::uint32_t> merged_into = {}) {
    using naive_detail::incircle;
    using naive_detail::orient;
    using predicates::Sign;
    const auto n = static_cast<std::uint32_t>(xy.size() / 2);
    const std::size_t count = triangles.size() / 3;
    if (!merged_into.empty()) {
        for (std::uint32_t v = 0; v < n && v < merged_into.size(); ++v) {
            if (merged_into[v] != oracle.representative[v]) {
                return "merged_into[" + std::to_string(v) + "] is " +
                       std::to_string(merged_into[v]) +
                       ", the first point with its coordinates is " +
                       std::to_string(oracle.representative[v]);
            }
        }
    }
    if (count != oracle.triangle_count) {
        return std::to_string(count) + " triangles, expected " +
               std::to_string(oracle.triangle_count) + " (" + std::to_string(oracle.distinct) +
               " distinct points, " + std::to_string(oracle.hull) + " on the hull" +
               (oracle.collinear ? ", all collinear)" : ")");
    }
    std::vector<std::array<std::uint32_t, 3>> ours;
    for (std::size_t t = 0; t < count; ++t) {
        const std::uint32_t a = triangles[3 * t], b = triangles[3 * t + 1],
                            c = triangles[3 * t + 2];
        const std::string name = "triangle " + std::to_string(t) + " (" + std::to_string(a) + ", " +
                                 std::to_string(b) + ", " + std::to_string(c) + ")";
        if (a >= n || b >= n || c >= n) return name + ": vertex out of range";
        for (const std::uint32_t v : {a, b, c}) {
            if (oracle.representative[v] != v) {
                return name + ": vertex " + std::to_string(v) + " repeats point " +
                       std::to_string(oracle.representative[v]);
            }
        }
        if (orient(xy, a, b, c) != Sign::Positive) return name + ": not counter-clockwise";
        for (std::uint32_t d = 0; d < n; ++d) {
            if (incircle(xy, a, b, c, d) == Sign::Positive) {
                return name + ": point " + std::to_string(d) + " lies inside its circumcircle";
            }
        }
        ours.push_back(naive_detail::rotated(a, b, c));
    }
    std::sort(ours.begin(), ours.end());
    for (const auto& t : oracle.strict_triangles) {
        if (!std::binary_search(ours.begin(), ours.end(), t)) {
            return "missing the strictly Delaunay triangle (" + std::to_string(t[0]) + ", " +
                   std::to_string(t[1]) + ", " + std::to_string(t[2]) + ")";
        }
    }
    return {};
}

}  // namespace exactmesh::triangulation
