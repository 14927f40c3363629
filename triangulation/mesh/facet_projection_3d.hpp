// SPDX-License-Identifier: MIT
// The projection of a PLC facet into a coordinate plane: the one rule shared by
// triangulate_facets_3d, boundary recovery and its check (reference corners: the first three
// non-collinear ones in the order listed; drop the axis of the largest normal component, chosen
// on power-of-two-scaled coordinates so that it is the same for the input scaled by 2^k;
// exactness does not depend on the choice: any axis with a non-zero exact normal component gives
// an injective projection of the plane).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

#include "base/errors.hpp"
#include "predicates/orient2d.hpp"
#include "predicates/power_of_two.hpp"
#include "triangulation/mesh/plc_3d.hpp"

namespace exactmesh::triangulation {

/// The coordinates kept when axis `drop` is dropped, in the cyclic order (drop+1, drop+2): the
/// projected orient2d then has the sign of the normal's component along `drop`.
inline std::array<double, 2> project_facet_point(const double* p, int drop) {
    return {p[(drop + 1) % 3], p[(drop + 2) % 3]};
}

inline predicates::Sign projected_orient(const double* a, const double* b, const double* c,
                                         int drop) {
    const auto pa = project_facet_point(a, drop), pb = project_facet_point(b, drop),
               pc = project_facet_point(c, drop);
    return predicates::orient2d(pa.data(), pb.data(), pc.data());
}

/// Whether a, b, c lie on one line of space (every projection degenerate; exact).
inline bool collinear_3d(const double* a, const double* b, const double* c) {
    for (int drop = 0; drop < 3; ++drop) {
        if (projected_orient(a, b, c, drop) != predicates::Sign::Zero) return false;
    }
    return true;
}

/// Whether q's projection lies in the closed triangle (a, b, c)'s projection (dropping axis
/// `drop`), exactly (orient2d); either orientation of the triangle.
inline bool in_projected_triangle(const double* q, const double* a, const double* b,
                                  const double* c, int drop) {
    const auto pq = project_facet_point(q, drop);
    const std::array<std::array<double, 2>, 3> t{
        project_facet_point(a, drop), project_facet_point(b, drop), project_facet_point(c, drop)};
    predicates::Sign sides[3];
    for (unsigned k = 0; k < 3; ++k)
        sides[k] = predicates::orient2d(t[k].data(), t[(k + 1) % 3].data(), pq.data());
    using predicates::Sign;
    return (sides[0] != Sign::Negative && sides[1] != Sign::Negative &&
            sides[2] != Sign::Negative) ||
           (sides[0] != Sign::Positive && sides[1] != Sign::Positive && sides[2] != Sign::Positive);
}

/// The axis whose projection keeps triangle abc (not collinear) non-degenerate, preferring the
/// largest normal component. The approximate normal is computed on coordinates scaled by a
/// power of two (exact; the exponent clamped so that subnormal coordinates cannot scale to
/// infinity), so the choice is the same for the input scaled by 2^k; exactness does not depend
/// on it (any axis with a non-zero exact component gives an injective projection).
inline int drop_axis(const double* a, const double* b, const double* c) {
    predicates::Sign exact[3];
    for (int k = 0; k < 3; ++k) exact[k] = projected_orient(a, b, c, k);
    double largest = 0;
    for (const double* p : {a, b, c}) {
        for (int k = 0; k < 3; ++k) largest = std::max(largest, std::fabs(p[k]));
    }
    const double scale =
        largest > 0 ? std::ldexp(1.0, std::clamp(-std::ilogb(largest), -1000, 1000)) : 1.0;
    double d1[3], d2[3];
    for (int k = 0; k < 3; ++k) {
        d1[k] = b[k] * scale - a[k] * scale;
        d2[k] = c[k] * scale - a[k] * scale;
    }
    const double normal[3] = {d1[1] * d2[2] - d1[2] * d2[1], d1[2] * d2[0] - d1[0] * d2[2],
                              d1[0] * d2[1] - d1[1] * d2[0]};
    int best = -1;
    for (int k = 0; k < 3; ++k) {
        if (exact[k] == predicates::Sign::Zero) continue;
        if (best < 0 || std::fabs(normal[k]) > std::fabs(normal[best])) best = k;
    }
    EM_ASSERT(best >= 0);
    return best;
}

/// Whether p lies farther from the plane through a, b and c than rounding explains: more than
/// 2^-40 of the largest coordinate magnitude among the four (a facet's Steiner points are
/// rounded once from points of its plane; attached free vertices lie within 2^-48 of their
/// coordinates), plus the uncertainty of the plane's normal for a needle triangle. Doubles on
/// differences scaled by one power of two (a classification, the same for the points scaled by
/// 2^k); false when a, b and c are collinear in doubles. A generator checking its own constructions
/// asks with a larger `bits` (a smaller allowance), so that what it keeps passes this test against
/// any triangle of the facet (whose corners may be smaller).
inline bool beyond_rounding_of_plane(const double* p, const double* a, const double* b,
                                     const double* c, int bits = 40) {
    double u[3], v[3], w[3];
    double largest = 0, magnitude = 0;
    for (int k = 0; k < 3; ++k) {
        u[k] = b[k] - a[k];
        v[k] = c[k] - a[k];
        w[k] = p[k] - a[k];
        largest = std::max({largest, std::fabs(u[k]), std::fabs(v[k]), std::fabs(w[k])});
        magnitude = std::max(
            {magnitude, std::fabs(p[k]), std::fabs(a[k]), std::fabs(b[k]), std::fabs(c[k])});
    }
    if (!(largest > 0) || !std::isfinite(largest)) return false;
    const predicates::PowerOfTwo unit(predicates::unit_shift(largest));
    for (int k = 0; k < 3; ++k) u[k] = unit(u[k]), v[k] = unit(v[k]), w[k] = unit(w[k]);
    const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                         u[0] * v[1] - u[1] * v[0]};
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!(length > 0)) return false;
    const double distance = std::fabs(n[0] * w[0] + n[1] * w[1] + n[2] * w[2]) / length;
    // The normal's direction is known to about eps |u| |v| / |n| (the cross product of two
    // nearly parallel sides cancels: a needle input triangle 1 by 4.4e-5 tilts it by 2.5e-12),
    // which moves the distance by that times |w|: allowed too, with a margin.
    const auto norm = [](const double* x) {
        return std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
    };
    const double conditioning = norm(u) * norm(v) / length * norm(w);
    return distance > std::ldexp(unit(magnitude), -bits) + std::ldexp(conditioning, -44);
}

/// A facet's reference corners: the first three non-collinear ones in the order listed
/// (ref[2] == kNone when every corner lies on one line).
inline std::array<VertIdx, 3> facet_reference_corners(const Plc3& plc, const Facet3& facet) {
    std::array<VertIdx, 3> ref = {kNone, kNone, kNone};
    for (const auto& polygon : facet.polygons) {
        for (const VertIdx v : polygon) {
            if (ref[0] == kNone) {
                ref[0] = v;
            } else if (ref[1] == kNone) {
                if (v != ref[0]) ref[1] = v;
            } else if (ref[2] == kNone) {
                if (!collinear_3d(plc.point(ref[0]), plc.point(ref[1]), plc.point(v))) ref[2] = v;
            }
        }
    }
    return ref;
}

/// The projection of a facet (validate_plc_3d passed): the axis dropped, and whether the
/// projection reverses the reference corners' orientation.
struct FacetPlane {
    int drop = 2;
    bool flip = false;  ///< the projection reverses the reference orientation
};

inline FacetPlane facet_plane(const Plc3& plc, const Facet3& facet) {
    const auto ref = facet_reference_corners(plc, facet);
    EM_ASSERT(ref[2] != kNone);  // validate_plc_3d passed
    const double* a = plc.point(ref[0]);
    const double* b = plc.point(ref[1]);
    const double* c = plc.point(ref[2]);
    FacetPlane plane;
    plane.drop = drop_axis(a, b, c);
    plane.flip = projected_orient(a, b, c, plane.drop) == predicates::Sign::Negative;
    return plane;
}

}  // namespace exactmesh::triangulation
