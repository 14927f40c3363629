// SPDX-License-Identifier: MIT
// Nearest-triangle queries over a PLC's surface triangles (internal to generators/mesh_3d):
// point-triangle, segment-segment and triangle-triangle squared distances in doubles, and a
// bounding-box tree with branch-and-bound nearest queries. Used by gap_estimate_3d and
// feature_size_3d on coordinates scaled by one power of two (no square overflows or
// underflows there); distances decide how much work to do, never geometry.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <type_traits>
#include <vector>

namespace exactmesh::generators::nearest_3d {

using Vec = std::array<double, 3>;

inline Vec sub(const Vec& a, const Vec& b) {
    return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
inline double dot(const Vec& a, const Vec& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
inline Vec add_scaled(const Vec& a, const Vec& d, double t) {
    return {a[0] + t * d[0], a[1] + t * d[1], a[2] + t * d[2]};
}
inline double squared_distance(const Vec& a, const Vec& b) {
    const Vec d = sub(a, b);
    return dot(d, d);
}

/// The point of triangle abc closest to p (Ericson, Real-Time Collision Detection, 5.1.5).
inline Vec closest_on_triangle(const Vec& p, const Vec& a, const Vec& b, const Vec& c) {
    const Vec ab = sub(b, a), ac = sub(c, a), ap = sub(p, a);
    const double d1 = dot(ab, ap), d2 = dot(ac, ap);
    if (d1 <= 0 && d2 <= 0) return a;
    const Vec bp = sub(p, b);
    const double d3 = dot(ab, bp), d4 = dot(ac, bp);
    if (d3 >= 0 && d4 <= d3) return b;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return add_scaled(a, ab, d1 / (d1 - d3));
    const Vec cp = sub(p, c);
    const double d5 = dot(ab, cp), d6 = dot(ac, cp);
    if (d6 >= 0 && d5 <= d6) return c;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return add_scaled(a, ac, d2 / (d2 - d6));
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
        return add_scaled(b, sub(c, b), (d4 - d3) / ((d4 - d3) + (d5 - d6)));
    const double denominator = va + vb + vc;
    if (!(denominator > 0)) return a;  // degenerate in rounding: a corner is close enough
    const double v = vb / denominator, w = vc / denominator;
    return {a[0] + ab[0] * v + ac[0] * w, a[1] + ab[1] * v + ac[1] * w,
            a[2] + ab[2] * v + ac[2] * w};
}

/// The squared distance of segments pq and rs (Ericson 5.1.9).
inline double segment_squared_distance(const Vec& p, const Vec& q, const Vec& r, const Vec& s) {
    const Vec d1 = sub(q, p), d2 = sub(s, r), w = sub(p, r);
    const double a = dot(d1, d1), e = dot(d2, d2), f = dot(d2, w);
    double t1 = 0, t2 = 0;
    if (a <= 0 && e <= 0) return dot(w, w);
    if (a <= 0) {
        t2 = std::clamp(f / e, 0.0, 1.0);
    } else {
        const double c = dot(d1, w);
        if (e <= 0) {
            t1 = std::clamp(-c / a, 0.0, 1.0);
        } else {
            const double b = dot(d1, d2), denominator = a * e - b * b;
            t1 = denominator > 0 ? std::clamp((b * f - c * e) / denominator, 0.0, 1.0) : 0.0;
            t2 = (b * t1 + f) / e;
            if (t2 < 0) {
                t2 = 0;
                t1 = std::clamp(-c / a, 0.0, 1.0);
            } else if (t2 > 1) {
                t2 = 1;
                t1 = std::clamp((b - c) / a, 0.0, 1.0);
            }
        }
    }
    return squared_distance(add_scaled(p, d1, t1), add_scaled(r, d2, t2));
}

/// The squared distance of two triangles that do not cross (a valid PLC's triangles sharing no
/// vertex): the least of corner-to-triangle and edge-to-edge distances.
inline double triangle_squared_distance(const std::array<Vec, 3>& t, const std::array<Vec, 3>& u) {
    double best = INFINITY;
    for (int k = 0; k < 3; ++k) {
        best = std::min(best, squared_distance(t[k], closest_on_triangle(t[k], u[0], u[1], u[2])));
        best = std::min(best, squared_distance(u[k], closest_on_triangle(u[k], t[0], t[1], t[2])));
        for (int m = 0; m < 3; ++m) {
            best = std::min(best,
                            segment_squared_distance(t[k], t[(k + 1) % 3], u[m], u[(m + 1) % 3]));
        }
    }
    return best;
}

/// A box of the scaled coordinates.
struct Box {
    Vec lo{INFINITY, INFINITY, INFINITY};
    Vec hi{-INFINITY, -INFINITY, -INFINITY};
};

inline Box box_of(const std::array<Vec, 3>& triangle) {
    Box box;
    for (int axis = 0; axis < 3; ++axis) {
        for (int k = 0; k < 3; ++k) {
            box.lo[axis] = std::min(box.lo[axis], triangle[k][axis]);
            box.hi[axis] = std::max(box.hi[axis], triangle[k][axis]);
        }
    }
    return box;
}

/// The squared distance between two boxes (0 when they meet): at most that of any two points
/// of theirs.
inline double box_squared_distance(const Box& a, const Box& b) {
    double sum = 0;
    for (int axis = 0; axis < 3; ++axis) {
        const double d = std::max({a.lo[axis] - b.hi[axis], 0.0, b.lo[axis] - a.hi[axis]});
        sum += d * d;
    }
    return sum;
}

/// A bounding-box tree over the scaled triangles, for nearest-triangle queries that visit
/// only the boxes nearer than the best distance so far. Before it, the estimate compared each
/// triangle with every triangle of a grid's neighbouring cells and sampled against all those
/// near it: the wing's walls are fans of long triangles, each near almost every other, which
/// took 4 10^5 triangle distances and 10^8 point-triangle distances, about a second.
class TriangleTree {
  public:
    explicit TriangleTree(const std::vector<std::array<Vec, 3>>& triangles)
        : triangles_(triangles), order_(triangles.size()) {
        for (std::uint32_t t = 0; t < order_.size(); ++t) order_[t] = t;
        nodes_.reserve(triangles.size());
        if (order_.empty()) return;
        nodes_.emplace_back();
        build(0, 0, static_cast<std::uint32_t>(order_.size()));
    }

    /// Lowers `best` (a squared distance, or any measure bound() bounds) to distance(u) for each
    /// triangle u with take(u) whose box is nearer than best by bound(box); bound(box) must be
    /// at most distance(u) for every u in the box. `distance` takes the triangle, or its index
    /// and the triangle. `found` becomes the u of the last lowering.
    template <class Bound, class Take, class Distance>
    void nearest(double& best, std::uint32_t& found, const Bound& bound, const Take& take,
                 const Distance& distance) const {
        if (nodes_.empty()) return;
        std::array<std::uint32_t, 64> stack{};
        std::size_t depth = 0;
        stack[depth++] = 0;
        while (depth > 0) {
            const Node& node = nodes_[stack[--depth]];
            if (!(bound(node.box) < best)) continue;
            if (node.count > 0) {
                for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
                    const std::uint32_t u = order_[i];
                    if (!take(u)) continue;
                    double d = 0;
                    if constexpr (std::is_invocable_v<const Distance&, std::uint32_t,
                                                      const std::array<Vec, 3>&>) {
                        d = distance(u, triangles_[u]);
                    } else {
                        d = distance(triangles_[u]);
                    }
                    if (d < best) {
                        best = d;
                        found = u;
                    }
                }
                continue;
            }
            // The nearer child last, so that it is visited first.
            const std::uint32_t left = node.first, right = node.first + 1;
            const bool left_nearer = bound(nodes_[left].box) < bound(nodes_[right].box);
            stack[depth++] = left_nearer ? right : left;
            stack[depth++] = left_nearer ? left : right;
        }
    }

  private:
    static constexpr std::uint32_t kLeafSize = 4;
    struct Node {
        Box box;
        std::uint32_t first = 0;  ///< the first of `order_` (a leaf) or the left child
        std::uint32_t count = 0;  ///< triangles of a leaf; 0 for an inner node
    };

    // Fills node `index` with [begin, end) of `order_`. Children are made in pairs, so a
    // node's right child follows its left one; the depth stays below 64 since every split
    // halves the range (median split).
    void build(std::uint32_t index, std::uint32_t begin, std::uint32_t end) {
        Box box, centres;
        for (std::uint32_t i = begin; i < end; ++i) {
            const auto& tri = triangles_[order_[i]];
            const Box own = box_of(tri);
            for (int axis = 0; axis < 3; ++axis) {
                const double centre = tri[0][axis] + tri[1][axis] + tri[2][axis];
                centres.lo[axis] = std::min(centres.lo[axis], centre);
                centres.hi[axis] = std::max(centres.hi[axis], centre);
                box.lo[axis] = std::min(box.lo[axis], own.lo[axis]);
                box.hi[axis] = std::max(box.hi[axis], own.hi[axis]);
            }
        }
        nodes_[index].box = box;
        if (end - begin <= kLeafSize) {
            nodes_[index].first = begin;
            nodes_[index].count = end - begin;
            return;
        }
        int axis = 0;
        for (int a = 1; a < 3; ++a)
            if (centres.hi[a] - centres.lo[a] > centres.hi[axis] - centres.lo[axis]) axis = a;
        const std::uint32_t middle = begin + (end - begin) / 2;
        std::nth_element(order_.begin() + begin, order_.begin() + middle, order_.begin() + end,
                         [&](std::uint32_t a, std::uint32_t b) {
                             const auto& ta = triangles_[a];
                             const auto& tb = triangles_[b];
                             return ta[0][axis] + ta[1][axis] + ta[2][axis] <
                                    tb[0][axis] + tb[1][axis] + tb[2][axis];
                         });
        const auto left = static_cast<std::uint32_t>(nodes_.size());
        nodes_.emplace_back();
        nodes_.emplace_back();
        nodes_[index].first = left;
        build(left, begin, middle);
        build(left + 1, middle, end);
    }

    const std::vector<std::array<Vec, 3>>& triangles_;
    std::vector<std::uint32_t> order_;
    std::vector<Node> nodes_;
};

}  // namespace exactmesh::generators::nearest_3d
