// SPDX-License-Identifier: MIT
// insphere(a, b, c, d, e): sign of det [p-e, |p-e|^2] over rows p = a, b, c, d; Positive when e
// lies inside the sphere through a, b, c, d with orient3d(a, b, c, d) > 0 [Shewchuk97 §4].
// Stages as in orient2d.hpp; filter proof proofs/gappa/insphere_filter.g.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>

#include "predicates/filter_constants.hpp"
#include "predicates/sign.hpp"
#include "predicates/stats.hpp"

namespace exactmesh::predicates {

/// The plain double determinant: the speed baseline, not robust.
inline double insphere_fast(const double* a, const double* b, const double* c, const double* d,
                            const double* e) noexcept {
    const double aex = a[0] - e[0], bex = b[0] - e[0], cex = c[0] - e[0], dex = d[0] - e[0];
    const double aey = a[1] - e[1], bey = b[1] - e[1], cey = c[1] - e[1], dey = d[1] - e[1];
    const double aez = a[2] - e[2], bez = b[2] - e[2], cez = c[2] - e[2], dez = d[2] - e[2];
    const double ab = aex * bey - bex * aey, bc = bex * cey - cex * bey;
    const double cd = cex * dey - dex * cey, da = dex * aey - aex * dey;
    const double ac = aex * cey - cex * aey, bd = bex * dey - dex * bey;
    const double abc = aez * bc - bez * ac + cez * ab;
    const double bcd = bez * cd - cez * bd + dez * bc;
    const double cda = cez * da + dez * ac + aez * cd;
    const double dab = dez * ab + aez * bd + bez * da;
    const double alift = aex * aex + aey * aey + aez * aez;
    const double blift = bex * bex + bey * bey + bez * bez;
    const double clift = cex * cex + cey * cey + cez * cez;
    const double dlift = dex * dex + dey * dey + dez * dez;
    return (dlift * abc - clift * dab) + (blift * cda - alift * bcd);
}

/// Stage A; the evaluation order is the one modelled in proofs/gappa/insphere_filter.g.
inline std::optional<Sign> insphere_filter(const double* a, const double* b, const double* c,
                                           const double* d, const double* e) noexcept {
    const double aex = a[0] - e[0], bex = b[0] - e[0], cex = c[0] - e[0], dex = d[0] - e[0];
    const double aey = a[1] - e[1], bey = b[1] - e[1], cey = c[1] - e[1], dey = d[1] - e[1];
    const double aez = a[2] - e[2], bez = b[2] - e[2], cez = c[2] - e[2], dez = d[2] - e[2];
    const double ab = aex * bey - bex * aey, bc = bex * cey - cex * bey;
    const double cd = cex * dey - dex * cey, da = dex * aey - aex * dey;
    const double ac = aex * cey - cex * aey, bd = bex * dey - dex * bey;
    const double abc = aez * bc - bez * ac + cez * ab;
    const double bcd = bez * cd - cez * bd + dez * bc;
    const double cda = cez * da + dez * ac + aez * cd;
    const double dab = dez * ab + aez * bd + bez * da;
    const double alift = aex * aex + aey * aey + aez * aez;
    const double blift = bex * bex + bey * bey + bez * bez;
    const double clift = cex * cex + cey * cey + cez * cez;
    const double dlift = dex * dex + dey * dey + dez * dez;
    const double det = (dlift * abc - clift * dab) + (blift * cda - alift * bcd);
    const double mx = std::max(std::max(std::fabs(aex), std::fabs(bex)),
                               std::max(std::fabs(cex), std::fabs(dex)));
    const double my = std::max(std::max(std::fabs(aey), std::fabs(bey)),
                               std::max(std::fabs(cey), std::fabs(dey)));
    const double mz = std::max(std::max(std::fabs(aez), std::fabs(bez)),
                               std::max(std::fabs(cez), std::fabs(dez)));
    const double m = std::max(std::max(mx, my), mz);
    const double m2 = m * m;
    const double eps = insphere_filter_eps * m2 * m2 * m;
    if (det > eps || -det > eps) {
        if (m >= insphere_filter_min && m <= insphere_filter_max) {
            return det > 0.0 ? Sign::Positive : Sign::Negative;
        }
    }
    return std::nullopt;
}

/// Stages B-D: always the exact sign. Throws GeometryError on NaN or infinite input.
Sign insphere_exact(const double* a, const double* b, const double* c, const double* d,
                    const double* e);

/// The exact sign of insphere for any finite doubles.
inline Sign insphere(const double* a, const double* b, const double* c, const double* d,
                     const double* e) {
    EM_STAT(insphere, calls);
    if (const auto s = insphere_filter(a, b, c, d, e)) {
        EM_STAT(insphere, filter);
        return *s;
    }
    return insphere_exact(a, b, c, d, e);
}

}  // namespace exactmesh::predicates
