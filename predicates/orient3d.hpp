// SPDX-License-Identifier: MIT
// orient3d(a, b, c, d): sign of det [a-d; b-d; c-d]; Positive when d lies below the plane of
// a, b, c seen counter-clockwise from above [Shewchuk97 §4]. Stages as in orient2d.hpp;
// filter proof proofs/gappa/orient3d_filter.g.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>

#include "predicates/filter_constants.hpp"
#include "predicates/sign.hpp"
#include "predicates/stats.hpp"

namespace exactmesh::predicates {

/// The plain double determinant: the speed baseline, not robust.
inline double orient3d_fast(const double* a, const double* b, const double* c,
                            const double* d) noexcept {
    const double adx = a[0] - d[0], bdx = b[0] - d[0], cdx = c[0] - d[0];
    const double ady = a[1] - d[1], bdy = b[1] - d[1], cdy = c[1] - d[1];
    const double adz = a[2] - d[2], bdz = b[2] - d[2], cdz = c[2] - d[2];
    return adx * (bdy * cdz - bdz * cdy) + bdx * (cdy * adz - cdz * ady) +
           cdx * (ady * bdz - adz * bdy);
}

/// Stage A; the evaluation order is the one modelled in proofs/gappa/orient3d_filter.g.
inline std::optional<Sign> orient3d_filter(const double* a, const double* b, const double* c,
                                           const double* d) noexcept {
    const double adx = a[0] - d[0], bdx = b[0] - d[0], cdx = c[0] - d[0];
    const double ady = a[1] - d[1], bdy = b[1] - d[1], cdy = c[1] - d[1];
    const double adz = a[2] - d[2], bdz = b[2] - d[2], cdz = c[2] - d[2];
    const double det = adx * (bdy * cdz - bdz * cdy) + bdx * (cdy * adz - cdz * ady) +
                       cdx * (ady * bdz - adz * bdy);
    const double maxx = std::max(std::max(std::fabs(adx), std::fabs(bdx)), std::fabs(cdx));
    const double maxy = std::max(std::max(std::fabs(ady), std::fabs(bdy)), std::fabs(cdy));
    const double maxz = std::max(std::max(std::fabs(adz), std::fabs(bdz)), std::fabs(cdz));
    const double eps = orient3d_filter_eps * maxx * maxy * maxz;
    if (det > eps || -det > eps) {
        const double lo = std::min(std::min(maxx, maxy), maxz);
        const double hi = std::max(std::max(maxx, maxy), maxz);
        if (lo >= orient3d_filter_min && hi <= orient3d_filter_max) {
            return det > 0.0 ? Sign::Positive : Sign::Negative;
        }
    }
    return std::nullopt;
}

/// Stages B-D: always the exact sign. Throws GeometryError on NaN or infinite input.
Sign orient3d_exact(const double* a, const double* b, const double* c, const double* d);

/// The exact sign of orient3d for any finite doubles.
inline Sign orient3d(const double* a, const double* b, const double* c, const double* d) {
    EM_STAT(orient3d, calls);
    if (const auto s = orient3d_filter(a, b, c, d)) {
        EM_STAT(orient3d, filter);
        return *s;
    }
    return orient3d_exact(a, b, c, d);
}

}  // namespace exactmesh::predicates
