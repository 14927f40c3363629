// SPDX-License-Identifier: MIT
// orient2d(a, b, c): sign of det [[ax-cx, ay-cy], [bx-cx, by-cy]]; Positive when a, b, c turn
// counter-clockwise (y up) [Shewchuk97 §4]. Stages: A semi-static filter (proofs/gappa/
// orient2d_filter.g), B exact differences, C raw-coordinate expansion, D GMP out of range.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>

#include "predicates/filter_constants.hpp"
#include "predicates/sign.hpp"
#include "predicates/stats.hpp"

namespace exactmesh::predicates {

/// The plain double determinant: the speed baseline, not robust.
inline double orient2d_fast(const double* a, const double* b, const double* c) noexcept {
    const double adx = a[0] - c[0], bdx = b[0] - c[0];
    const double ady = a[1] - c[1], bdy = b[1] - c[1];
    return adx * bdy - ady * bdx;
}

/// Stage A on the differences a - c and b - c, computed by the caller as orient2d_filter
/// computes them (adx = a[0] - c[0], ...): the same evaluation, so the same proof. A caller
/// testing one point c against several edges takes each difference once.
inline std::optional<Sign> orient2d_filter_differences(double adx, double ady, double bdx,
                                                       double bdy) noexcept {
    const double det = adx * bdy - ady * bdx;
    const double maxx = std::max(std::fabs(adx), std::fabs(bdx));
    const double maxy = std::max(std::fabs(ady), std::fabs(bdy));
    const double eps = orient2d_filter_eps * maxx * maxy;
    if (det > eps || -det > eps) {
        // Rarely false; NaN also fails here and goes on to the exact stages.
        const double lo = std::min(maxx, maxy), hi = std::max(maxx, maxy);
        if (lo >= orient2d_filter_min && hi <= orient2d_filter_max) {
            return det > 0.0 ? Sign::Positive : Sign::Negative;
        }
    }
    return std::nullopt;
}

/// Stage A: the sign when the floating-point evaluation certifies it, std::nullopt otherwise.
/// The evaluation order below is the one modelled in proofs/gappa/orient2d_filter.g.
inline std::optional<Sign> orient2d_filter(const double* a, const double* b,
                                           const double* c) noexcept {
    return orient2d_filter_differences(a[0] - c[0], a[1] - c[1], b[0] - c[0], b[1] - c[1]);
}

/// Stages B-D: always the exact sign. Throws GeometryError on NaN or infinite input.
Sign orient2d_exact(const double* a, const double* b, const double* c);

/// orient2d(a, b, c) given the differences a - c and b - c (orient2d_filter_differences): for
/// a caller that tests one point c against several edges and takes each difference once.
inline Sign orient2d_with_differences(const double* a, const double* b, const double* c, double adx,
                                      double ady, double bdx, double bdy) {
    EM_STAT(orient2d, calls);
    if (const auto s = orient2d_filter_differences(adx, ady, bdx, bdy)) {
        EM_STAT(orient2d, filter);
        return *s;
    }
    return orient2d_exact(a, b, c);
}

/// The exact sign of orient2d for any finite doubles.
inline Sign orient2d(const double* a, const double* b, const double* c) {
    return orient2d_with_differences(a, b, c, a[0] - c[0], a[1] - c[1], b[0] - c[0], b[1] - c[1]);
}

}  // namespace exactmesh::predicates
