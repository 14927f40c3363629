// SPDX-License-Identifier: MIT
// The points a narrow gap asks for (see gap_estimate_3d.hpp).
#include "generators/mesh_3d/gap_estimate_3d.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <unordered_map>
#include <vector>

#include "base/errors.hpp"
#include "base/number_text.hpp"
#include "predicates/orient3d.hpp"
#include "predicates/power_of_two.hpp"
#include "triangulation/mesh/facet_projection_3d.hpp"
#include "triangulation/mesh/vertex_keys_3d.hpp"
#include "triangulation/recovery_3d/plc_3d.hpp"

namespace exactmesh::generators {

namespace {

using triangulation::Plc3;
using triangulation::VertIdx;
using Vec = std::array<double, 3>;

Vec sub(const Vec& a, const Vec& b) {
    return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
double dot(const Vec& a, const Vec& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
Vec add_scaled(const Vec& a, const Vec& d, double t) {
    return {a[0] + t * d[0], a[1] + t * d[1], a[2] + t * d[2]};
}
double squared_distance(const Vec& a, const Vec& b) {
    const Vec d = sub(a, b);
    return dot(d, d);
}

/// The point of triangle abc closest to p (Ericson, Real-Time Collision Detection, 5.1.5).
Vec closest_on_triangle(const Vec& p, const Vec& a, const Vec& b, const Vec& c) {
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
double segment_squared_distance(const Vec& p, const Vec& q, const Vec& r, const Vec& s) {
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
double triangle_squared_distance(const std::array<Vec, 3>& t, const std::array<Vec, 3>& u) {
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

Box box_of(const std::array<Vec, 3>& triangle) {
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
double box_squared_distance(const Box& a, const Box& b) {
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

    /// Lowers `best` (a squared distance) to distance(u) for each triangle u with take(u)
    /// whose box is nearer than best by bound(box); bound(box) must be at most distance(u)
    /// for every u in the box. `found` becomes the u of the last lowering.
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
                    const double d = distance(triangles_[u]);
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

constexpr std::uint32_t kNone = ~std::uint32_t{0};

/// Which sides of each facet the domain lies on: bit 1 the side where orient3d of the facet's
/// reference corners and a point is positive, bit 2 the negative one. Read from the recovered
/// mesh (the tetrahedron on each subface, by the sign of its far corner); both bits when no
/// mesh is given or a facet's every tetrahedron there is flat against it.
std::vector<std::uint8_t> domain_sides(const Plc3& plc,
                                       const std::vector<std::array<VertIdx, 3>>& reference,
                                       const triangulation::ConformingMesh3* recovered) {
    std::vector<std::uint8_t> sides(plc.facets.size(), 3);
    if (recovered == nullptr) return sides;
    const auto& m = recovered->mesh;
    const std::size_t subface_count = recovered->subface_facet.size();
    std::vector<std::pair<triangulation::Key3, std::uint32_t>> subfaces(subface_count);
    for (std::size_t f = 0; f < subface_count; ++f) {
        const std::uint32_t facet = recovered->subface_facet[f];
        if (facet >= plc.facets.size()) return sides;
        subfaces[f] = {triangulation::sorted3(recovered->subfaces[3 * f],
                                              recovered->subfaces[3 * f + 1],
                                              recovered->subfaces[3 * f + 2]),
                       facet};
    }
    std::sort(subfaces.begin(), subfaces.end());
    std::vector<std::uint8_t> seen(plc.facets.size(), 0);
    for (triangulation::TetIdx t = 0; t < m.tet_count(); ++t) {
        const VertIdx* c = &m.tets[4 * std::size_t{t}];
        for (unsigned k = 0; k < 4; ++k) {
            const triangulation::Key3 key =
                triangulation::sorted3(c[(k + 1) % 4], c[(k + 2) % 4], c[(k + 3) % 4]);
            const auto it = std::lower_bound(
                subfaces.begin(), subfaces.end(), key,
                [](const auto& entry, const triangulation::Key3& k3) { return entry.first < k3; });
            if (it == subfaces.end() || it->first != key) continue;
            const auto& ref = reference[it->second];
            const predicates::Sign side =
                predicates::orient3d(plc.point(ref[0]), plc.point(ref[1]), plc.point(ref[2]),
                                     m.point(c[k]));
            if (side != predicates::Sign::Zero)
                seen[it->second] |= side == predicates::Sign::Positive ? 1 : 2;
        }
    }
    for (std::size_t f = 0; f < sides.size(); ++f)
        if (seen[f] != 0) sides[f] = seen[f];
    return sides;
}
/// A triangle with a close feature is sampled at up to this many points per side (squared).
constexpr int kMaxSamplesPerSide = 16;

}  // namespace

GapEstimate3 gap_estimate_3d(const Plc3& plc, const triangulation::ConformingMesh3* recovered,
                             double enough) {
    GapEstimate3 estimate;
    const triangulation::SurfaceTriangles3 surface = triangulation::triangulate_facets_3d(plc);
    const std::uint32_t count = surface.triangle_count();
    if (count == 0) return estimate;
    std::vector<std::array<VertIdx, 3>> reference(plc.facets.size());
    for (std::size_t f = 0; f < plc.facets.size(); ++f)
        reference[f] = triangulation::facet_reference_corners(plc, plc.facets[f]);
    std::vector<std::uint8_t> sides = domain_sides(plc, reference, recovered);
    // Each one-sided facet's unit normal, oriented as orient3d's positive side of its reference
    // corners, and a point of it (scaled coordinates, defined below).
    std::vector<std::pair<Vec, Vec>> planes(plc.facets.size());
    double largest = 0;
    for (const double x : plc.xyz) largest = std::max(largest, std::fabs(x));
    const int shift = predicates::unit_shift(largest);
    const predicates::PowerOfTwo unit(shift);
    std::vector<std::array<Vec, 3>> triangles(count);
    std::vector<double> longest(count);
    for (std::uint32_t t = 0; t < count; ++t) {
        for (int k = 0; k < 3; ++k) {
            const double* p = plc.point(surface.triangles[3 * std::size_t{t} + k]);
            triangles[t][k] = {unit(p[0]), unit(p[1]), unit(p[2])};
        }
        double l2 = 0;
        for (int k = 0; k < 3; ++k)
            l2 = std::max(l2, squared_distance(triangles[t][k], triangles[t][(k + 1) % 3]));
        longest[t] = std::sqrt(l2);
    }
    for (std::size_t f = 0; f < plc.facets.size(); ++f) {
        if (sides[f] == 3) continue;
        Vec q[3];
        for (int k = 0; k < 3; ++k) {
            const double* p = plc.point(reference[f][k]);
            q[k] = {unit(p[0]), unit(p[1]), unit(p[2])};
        }
        // The two edge vectors each scaled by a power of two to a largest component in
        // [1, 2) (the normal's direction unchanged): a facet 2^-600 of the extent wide would
        // make their cross product underflow.
        Vec u = sub(q[1], q[0]), v = sub(q[2], q[0]);
        for (Vec* w : {&u, &v}) {
            const double big = std::max({std::fabs((*w)[0]), std::fabs((*w)[1]), std::fabs((*w)[2])});
            if (big > 0)
                for (double& x : *w) x = std::ldexp(x, -std::ilogb(big));
        }
        // orient3d(a, b, c, d) > 0 when d is below the plane seen counter-clockwise from above,
        // that is on the side of -(b - a) x (c - a).
        Vec n = {-(u[1] * v[2] - u[2] * v[1]), -(u[2] * v[0] - u[0] * v[2]),
                 -(u[0] * v[1] - u[1] * v[0])};
        const double length = std::sqrt(dot(n, n));
        if (!(length > 0) || !std::isfinite(length)) {
            sides[f] = 3;  // no plane to tell the sides by: both count
            continue;
        }
        for (double& x : n) x /= length;
        planes[f] = {n, q[0]};
    }
    // A triangle u faces t across the domain unless u lies wholly on a side of t's facet
    // without the domain (the far wall of a thin hole, seen from the near one), or the other
    // way round. A corner within 2^-40 of the plane (scaled coordinates in [1, 2)) counts as
    // facing. Doubles: this decides how much work to accept, not geometry (exact orient3d
    // here, on walls of coplanar corners, was a third of the wing's refinement at V = 0.1).
    auto faces_across_domain = [&](std::uint32_t from, std::uint32_t to) {
        const std::uint32_t facet = surface.facets[from];
        if (sides[facet] == 3) return true;
        const auto& [normal, origin] = planes[facet];
        for (int i = 0; i < 3; ++i) {
            const double height = dot(normal, sub(triangles[to][i], origin));
            if (std::fabs(height) <= 0x1p-40 || (sides[facet] & (height > 0 ? 1 : 2)) != 0)
                return true;
        }
        return false;
    };
    // The floor: 2^-44 of the scaled coordinates' magnitude (in [1, 2)): no feature below it
    // counts.
    const double floor = 0x1p-44;
    const TriangleTree tree(triangles);
    // First pass: each triangle's nearest triangle sharing no vertex with it (if nearer than
    // its longest edge), and an upper bound of the estimate from those distances alone.
    std::vector<double> nearest(count);
    std::vector<std::uint32_t> nearest_triangle(count, kNone);
    std::vector<double> area(count);
    std::vector<Vec> edge1(count), edge2(count);
    double smallest = INFINITY;
    double upper = 0;
    auto apart_from = [&](std::uint32_t t) {
        const VertIdx* tv = &surface.triangles[3 * std::size_t{t}];
        return [&, t, tv](std::uint32_t u) {
            const VertIdx* uv = &surface.triangles[3 * std::size_t{u}];
            for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 3; ++j)
                    if (tv[i] == uv[j]) return false;
            return faces_across_domain(t, u) && faces_across_domain(u, t);
        };
    };
    for (std::uint32_t t = 0; t < count; ++t) {
        edge1[t] = sub(triangles[t][1], triangles[t][0]);
        edge2[t] = sub(triangles[t][2], triangles[t][0]);
        const Vec& e1 = edge1[t];
        const Vec& e2 = edge2[t];
        const Vec normal = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                            e1[0] * e2[1] - e1[1] * e2[0]};
        area[t] = 0.5 * std::sqrt(dot(normal, normal));
        const double own = std::max(longest[t], floor);
        const Box t_box = box_of(triangles[t]);
        nearest[t] = longest[t] * longest[t];
        tree.nearest(
            nearest[t], nearest_triangle[t],
            [&](const Box& box) { return box_squared_distance(t_box, box); }, apart_from(t),
            [&](const std::array<Vec, 3>& u) {
                return triangle_squared_distance(triangles[t], u);
            });
        smallest = std::min(smallest, std::max(std::sqrt(nearest[t]), floor));
        if (!(nearest[t] < longest[t] * longest[t])) {
            estimate.points += area[t] / (4 * own * own);
            upper += area[t] / (4 * own * own);
            continue;
        }
        // Every sample below lies within rounding (2^-48 of the scaled coordinates) of t, so
        // its distance f is at least this one's, less that: its area / (4 f^2) bounds t's share.
        const double low = std::max(std::sqrt(nearest[t]) - 0x1p-46, floor);
        upper += area[t] / (4 * low * low);
    }
    if (!(upper > enough)) {
        estimate.points = upper;
        estimate.smallest_feature = std::ldexp(smallest, -shift);
        estimate.upper_bound_only = true;
        return estimate;
    }
    for (std::uint32_t t = 0; t < count; ++t) {
        if (nearest_triangle[t] == kNone || !(nearest[t] < longest[t] * longest[t])) continue;
        const double own = std::max(longest[t], floor);
        const Vec& e1 = edge1[t];
        const Vec& e2 = edge2[t];
        const auto apart = apart_from(t);
        std::uint32_t start = nearest_triangle[t];
        // A close feature faces only part of t (the outer wall's triangle beside a small
        // hole): t is sampled at the centres of its k^2 congruent sub-triangles, each with
        // the distance from its centre to the triangles sharing no vertex with t (capped and
        // floored as f).
        // Clamped as a double: the ratio can exceed any int (1.9e11 from a fuzzed PLC, an
        // undefined conversion), or be infinite when the nearest distance is 0.
        const double ratio = std::ceil(longest[t] / std::sqrt(nearest[t]));
        const int k = !(ratio < kMaxSamplesPerSide) ? kMaxSamplesPerSide
                                                    : std::max(1, static_cast<int>(ratio));
        const double piece = area[t] / (static_cast<double>(k) * k);
        auto sample = [&](double a, double b) {
            const Vec p = {triangles[t][0][0] + a * e1[0] + b * e2[0],
                           triangles[t][0][1] + a * e1[1] + b * e2[1],
                           triangles[t][0][2] + a * e1[2] + b * e2[2]};
            const Box p_box{p, p};
            auto distance = [&](const std::array<Vec, 3>& u) {
                return squared_distance(p, closest_on_triangle(p, u[0], u[1], u[2]));
            };
            // Started from the previous sample's nearest triangle (the same least distance,
            // found with fewer boxes opened).
            double best = std::min(own * own, distance(triangles[start]));
            tree.nearest(
                best, start,
                [&](const Box& box) { return box_squared_distance(p_box, box); }, apart, distance);
            const double f = std::max(std::sqrt(best), floor);
            estimate.points += piece / (4 * f * f);
        };
        for (int i = 0; i < k; ++i) {
            for (int j = 0; i + j < k; ++j) {
                sample((i + 1.0 / 3) / k, (j + 1.0 / 3) / k);  // the upward sub-triangle
                if (i + j + 1 < k) sample((i + 2.0 / 3) / k, (j + 2.0 / 3) / k);  // downward
            }
        }
    }
    estimate.smallest_feature = std::ldexp(smallest, -shift);
    return estimate;
}

void refuse_gaps_far_over_budget_3d(const Plc3& plc,
                                    const triangulation::ConformingMesh3& recovered,
                                    std::uint64_t budget, const char* who, double margin) {
    const double limit = margin * static_cast<double>(budget);
    const GapEstimate3 estimate = gap_estimate_3d(plc, &recovered, limit);
    if (!(estimate.points > limit)) return;
    throw InputError(std::string(who) + ": Steiner point budget of " + std::to_string(budget) +
                     " exceeded at once: facets " +
                     format_approximate(estimate.smallest_feature, 3) +
                     " apart (a narrow gap between parts of the surface that share no vertex) ask "
                     "for about " +
                     format_approximate(estimate.points, 3) +
                     " points (the surface's area over 4 f^2, f the distance to the nearest such "
                     "part); widen the gap or raise the budget");
}

}  // namespace exactmesh::generators
