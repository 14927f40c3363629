// SPDX-License-Identifier: MIT
// The projection of a PLC facet into a coordinate plane, shared by the facet triangulations of
// boundary recovery and its check: the same rule as triangulate_facets_3d (reference corners:
// the first three non-collinear ones in the order listed; drop the axis of the largest normal
// component, chosen on power-of-two-scaled coordinates so that it is the same for the input
// scaled by 2^k; exactness does not depend on the choice: any axis with a non-zero exact normal
// component gives an injective projection of the plane).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

#include "base/errors.hpp"
#include "predicates/orient2d.hpp"
#include "triangulation/mesh/plc_3d.hpp"

namespace exactmesh::triangulation {

/// The coordinates kept when axis `drop` is dropped, in the cyclic order (drop+1, drop+2).
inline std::array<double, 2> project_facet_point(const double* p, int drop) {
    return {p[(drop + 1) % 3], p[(drop + 2) % 3]};
}

inline predicates::Sign projected_orient(const double* a, const double* b, const double* c,
                                         int drop) {
    const auto pa = project_facet_point(a, drop), pb = project_facet_point(b, drop),
               pc = project_facet_point(c, drop);
    return predicates::orient2d(pa.data(), pb.data(), pc.data());
}

/// The projection of a facet: the same rule as triangulate_facets_3d (reference corners: the
/// first three non-collinear ones; drop the axis of the largest normal component, decided on
/// power-of-two-scaled coordinates so that it is the same for the input scaled by 2^k).
struct FacetPlane {
    int drop = 2;
    bool flip = false;  ///< the projection reverses the reference orientation
};

inline FacetPlane facet_plane(const Plc3& plc, const Facet3& facet) {
    VertIdx ref[3] = {kNone, kNone, kNone};
    for (const auto& polygon : facet.polygons) {
        for (const VertIdx v : polygon) {
            if (ref[0] == kNone) {
                ref[0] = v;
            } else if (ref[1] == kNone) {
                if (v != ref[0]) ref[1] = v;
            } else if (ref[2] == kNone) {
                bool collinear = true;
                for (int k = 0; k < 3 && collinear; ++k)
                    collinear = projected_orient(plc.point(ref[0]), plc.point(ref[1]), plc.point(v),
                                                 k) == predicates::Sign::Zero;
                if (!collinear) ref[2] = v;
            }
        }
    }
    EM_ASSERT(ref[2] != kNone);  // validate_plc_3d passed
    const double* a = plc.point(ref[0]);
    const double* b = plc.point(ref[1]);
    const double* c = plc.point(ref[2]);
    double largest = 0;
    for (const double* p : {a, b, c})
        for (int k = 0; k < 3; ++k) largest = std::max(largest, std::fabs(p[k]));
    const double scale = largest > 0 ? std::ldexp(1.0, -std::ilogb(largest)) : 1.0;
    double d1[3], d2[3];
    for (int k = 0; k < 3; ++k) {
        d1[k] = b[k] * scale - a[k] * scale;
        d2[k] = c[k] * scale - a[k] * scale;
    }
    const double normal[3] = {d1[1] * d2[2] - d1[2] * d2[1], d1[2] * d2[0] - d1[0] * d2[2],
                              d1[0] * d2[1] - d1[1] * d2[0]};
    FacetPlane plane;
    int best = -1;
    for (int k = 0; k < 3; ++k) {
        if (projected_orient(a, b, c, k) == predicates::Sign::Zero) continue;
        if (best < 0 || std::fabs(normal[k]) > std::fabs(normal[best])) best = k;
    }
    EM_ASSERT(best >= 0);
    plane.drop = best;
    plane.flip = projected_orient(a, b, c, best) == predicates::Sign::Negative;
    return plane;
}

}  // namespace exactmesh::triangulation
