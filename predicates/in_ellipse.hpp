// SPDX-License-Identifier: MIT
// in_ellipse(a, b, c, d, m): incircle in the plane mapped by a constant symmetric 2x2 metric
// M = [m0 m1; m1 m2] (doubles, row m = {M11, M12, M22}): the sign of
//     det [p - d, q(p - d)] over rows p = a, b, c,   q(v) = v^T M v = M11 vx^2 + 2 M12 vx vy + M22
//     vy^2.
// For M = F^T F (SPD, det F > 0) it is det F times incircle(Fa, Fb, Fc, Fd), so Positive means d
// lies inside the ellipse {x : q(x - o) = r^2} through a, b, c given counter-clockwise: the
// Delaunay criterion of the mapped space [GeorgeBorouchaki98 §7; Castro-Díaz et al. 97], used by
// stretched (metric) Delaunay insertion and swapping. Exact for any finite doubles and any
// symmetric M (the geometric reading needs M positive definite); with M the identity it is
// incircle, bit for bit in its sign. Positive scaling of M never changes the sign.
// Stages: A, a filter whose bound is proven in proofs/gappa/in_ellipse_filter.g
// (proofs/invariants/filters.md §6); then the determinant of the exact differences in two terms
// (double-double), certified by the bound of proofs/gappa/two_term_in_ellipse.g; then expansion
// arithmetic (the difference form when the differences are exact, else the raw
// det [x y q(p) 1]); coordinates or M outside the expansion-safe range scaled into it by powers
// of two when exact, else GMP integers.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>

#include "predicates/filter_constants.hpp"
#include "predicates/sign.hpp"
#include "predicates/stats.hpp"

namespace exactmesh::predicates {

/// q(v) for the computed difference v, in the order the filter's proof models.
inline double metric_lift(double vx, double vy, const double* m) noexcept {
    return (m[0] * vx) * vx + ((2.0 * m[1]) * vx) * vy + (m[2] * vy) * vy;
}

/// The plain double determinant: the speed baseline, not robust.
inline double in_ellipse_fast(const double* a, const double* b, const double* c, const double* d,
                              const double* m) noexcept {
    const double adx = a[0] - d[0], ady = a[1] - d[1];
    const double bdx = b[0] - d[0], bdy = b[1] - d[1];
    const double cdx = c[0] - d[0], cdy = c[1] - d[1];
    const double alift = metric_lift(adx, ady, m);
    const double blift = metric_lift(bdx, bdy, m);
    const double clift = metric_lift(cdx, cdy, m);
    return alift * (bdx * cdy - cdx * bdy) + blift * (cdx * ady - adx * cdy) +
           clift * (adx * bdy - bdx * ady);
}

/// Stage A; the evaluation order is the one modelled in proofs/gappa/in_ellipse_filter.g. The
/// bound is in_ellipse_filter_eps * mc^4 * mm, mc the largest |difference| and mm the largest
/// |M entry|, both inside [in_ellipse_filter_min, in_ellipse_filter_max].
inline std::optional<Sign> in_ellipse_filter(const double* a, const double* b, const double* c,
                                             const double* d, const double* m) noexcept {
    const double adx = a[0] - d[0], ady = a[1] - d[1];
    const double bdx = b[0] - d[0], bdy = b[1] - d[1];
    const double cdx = c[0] - d[0], cdy = c[1] - d[1];
    const double alift = metric_lift(adx, ady, m);
    const double blift = metric_lift(bdx, bdy, m);
    const double clift = metric_lift(cdx, cdy, m);
    const double det = alift * (bdx * cdy - cdx * bdy) + blift * (cdx * ady - adx * cdy) +
                       clift * (adx * bdy - bdx * ady);
    const double maxx = std::max(std::max(std::fabs(adx), std::fabs(bdx)), std::fabs(cdx));
    const double maxy = std::max(std::max(std::fabs(ady), std::fabs(bdy)), std::fabs(cdy));
    const double mc = std::max(maxx, maxy);
    const double mm = std::max(std::max(std::fabs(m[0]), std::fabs(m[1])), std::fabs(m[2]));
    const double mc2 = mc * mc;
    const double eps = in_ellipse_filter_eps * mc2 * mc2 * mm;
    if (det > eps || -det > eps) {
        if (mc >= in_ellipse_filter_min && mc <= in_ellipse_filter_max &&
            mm >= in_ellipse_filter_min && mm <= in_ellipse_filter_max) {
            return det > 0.0 ? Sign::Positive : Sign::Negative;
        }
    }
    return std::nullopt;
}

/// The exact stages: always the exact sign. Throws GeometryError on NaN or infinite input.
Sign in_ellipse_exact(const double* a, const double* b, const double* c, const double* d,
                      const double* m);

/// The exact sign of in_ellipse for any finite doubles.
inline Sign in_ellipse(const double* a, const double* b, const double* c, const double* d,
                       const double* m) {
    EM_STAT(in_ellipse, calls);
    if (const auto s = in_ellipse_filter(a, b, c, d, m)) {
        EM_STAT(in_ellipse, filter);
        return *s;
    }
    return in_ellipse_exact(a, b, c, d, m);
}

}  // namespace exactmesh::predicates
