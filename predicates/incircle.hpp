// SPDX-License-Identifier: MIT
// incircle(a, b, c, d): sign of det [p-d, |p-d|^2] over rows p = a, b, c; Positive when d lies
// inside the circle through a, b, c given counter-clockwise [Shewchuk97 §4]. Stages as in
// orient2d.hpp; filter proof proofs/gappa/incircle_filter.g.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>

#include "predicates/filter_constants.hpp"
#include "predicates/sign.hpp"
#include "predicates/stats.hpp"

namespace exactmesh::predicates {

/// The plain double determinant: the speed baseline, not robust.
inline double incircle_fast(const double* a, const double* b, const double* c,
                            const double* d) noexcept {
    const double adx = a[0] - d[0], ady = a[1] - d[1];
    const double bdx = b[0] - d[0], bdy = b[1] - d[1];
    const double cdx = c[0] - d[0], cdy = c[1] - d[1];
    const double alift = adx * adx + ady * ady;
    const double blift = bdx * bdx + bdy * bdy;
    const double clift = cdx * cdx + cdy * cdy;
    return alift * (bdx * cdy - cdx * bdy) + blift * (cdx * ady - adx * cdy) +
           clift * (adx * bdy - bdx * ady);
}

/// Stage A; the evaluation order is the one modelled in proofs/gappa/incircle_filter.g.
inline std::optional<Sign> incircle_filter(const double* a, const double* b, const double* c,
                                           const double* d) noexcept {
    const double adx = a[0] - d[0], ady = a[1] - d[1];
    const double bdx = b[0] - d[0], bdy = b[1] - d[1];
    const double cdx = c[0] - d[0], cdy = c[1] - d[1];
    const double alift = adx * adx + ady * ady;
    const double blift = bdx * bdx + bdy * bdy;
    const double clift = cdx * cdx + cdy * cdy;
    const double det = alift * (bdx * cdy - cdx * bdy) + blift * (cdx * ady - adx * cdy) +
                       clift * (adx * bdy - bdx * ady);
    const double maxx = std::max(std::max(std::fabs(adx), std::fabs(bdx)), std::fabs(cdx));
    const double maxy = std::max(std::max(std::fabs(ady), std::fabs(bdy)), std::fabs(cdy));
    const double m = std::max(maxx, maxy);
    const double m2 = m * m;
    const double eps = incircle_filter_eps * m2 * m2;
    if (det > eps || -det > eps) {
        if (m >= incircle_filter_min && m <= incircle_filter_max) {
            return det > 0.0 ? Sign::Positive : Sign::Negative;
        }
    }
    return std::nullopt;
}

/// Stages B-D: always the exact sign. Throws GeometryError on NaN or infinite input.
Sign incircle_exact(const double* a, const double* b, const double* c, const double* d);

/// The exact sign of incircle for any finite doubles.
inline Sign incircle(const double* a, const double* b, const double* c, const double* d) {
    EM_STAT(incircle, calls);
    if (const auto s = incircle_filter(a, b, c, d)) {
        EM_STAT(incircle, filter);
        return *s;
    }
    return incircle_exact(a, b, c, d);
}

}  // namespace exactmesh::predicates
