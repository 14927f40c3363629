// SPDX-License-Identifier: MIT
// The points a narrow gap asks for (see gap_estimate_3d.hpp).
#include "generators/mesh_3d/gap_estimate_3d.hpp"

#include "generators/mesh_3d/triangle_tree_3d.hpp"

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

using nearest_3d::Box;
using nearest_3d::box_of;
using nearest_3d::box_squared_distance;
using nearest_3d::closest_on_triangle;
using nearest_3d::dot;
using nearest_3d::squared_distance;
using nearest_3d::sub;
using nearest_3d::triangle_squared_distance;
using nearest_3d::TriangleTree;
using nearest_3d::Vec;
using triangulation::Plc3;
using triangulation::VertIdx;

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
        subfaces[f] = {
            triangulation::sorted3(recovered->subfaces[3 * f], recovered->subfaces[3 * f + 1],
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
            const predicates::Sign side = predicates::orient3d(plc.point(ref[0]), plc.point(ref[1]),
                                                               plc.point(ref[2]), m.point(c[k]));
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
            const double big =
                std::max({std::fabs((*w)[0]), std::fabs((*w)[1]), std::fabs((*w)[2])});
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
                best, start, [&](const Box& box) { return box_squared_distance(p_box, box); },
                apart, distance);
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
                                    std::uint64_t budget, const char* who) {
    const double limit = kGapMargin3 * static_cast<double>(budget);
    const GapEstimate3 estimate = gap_estimate_3d(plc, &recovered, limit);
    if (!(estimate.points > limit)) return;
    throw InputError(std::string(who) + ": Steiner point budget of " + std::to_string(budget) +
                     " exceeded at once: facets " +
                     format_approximate(estimate.smallest_feature, 3) +
                     " apart (a narrow gap between parts of the surface that share no vertex) ask "
                     "for about " +
                     format_approximate(estimate.points, 3) +
                     " points (the surface's area over 4 f^2, f the distance to the nearest such "
                     "part; refused above " +
                     format_approximate(kGapMargin3, 3) +
                     " times the budget: the generators make up to 2.3 times the estimate "
                     "between parallel walls); widen the gap or raise the budget");
}

}  // namespace exactmesh::generators
