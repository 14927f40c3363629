// SPDX-License-Identifier: MIT
// Exact stages of orient3d [Shewchuk97 §4.4]: B when the coordinate differences are exact
// (24 components), C over raw coordinates as det [x y z 1] (96 components), D in GMP.
#include "predicates/orient3d.hpp"

#include "predicates/exact_range.hpp"
#include "predicates/expansion.hpp"
#include "predicates/gmp_fallback.hpp"

namespace exactmesh::predicates {

namespace {

/// px * qy - qx * py exactly.
Expansion<4> minor_xy(double px, double py, double qx, double qy) noexcept {
    return exact_product(px, qy) - exact_product(qx, py);
}

/// det [p; q; r] of raw xyz rows, expanded along z.
Expansion<24> det3_xyz(const double* p, const double* q, const double* r) noexcept {
    return compressed(scale(minor_xy(q[0], q[1], r[0], r[1]), p[2]) -
                      scale(minor_xy(p[0], p[1], r[0], r[1]), q[2]) +
                      scale(minor_xy(p[0], p[1], q[0], q[1]), r[2]));
}

}  // namespace

Sign orient3d_exact(const double* a, const double* b, const double* c, const double* d) {
    const auto coordinates = {a[0], a[1], a[2], b[0], b[1], b[2],
                              c[0], c[1], c[2], d[0], d[1], d[2]};
    detail::require_finite("orient3d", coordinates);
    if (!detail::expansion_safe(3, coordinates)) {
        EM_STAT(orient3d, gmp);
        return orient3d_gmp(a, b, c, d);
    }
    double diff[9], tail[9];
    const double* rows[3] = {a, b, c};
    bool exact = true;
    for (int r = 0; r < 3; ++r) {
        for (int k = 0; k < 3; ++k) {
            two_diff(rows[r][k], d[k], diff[3 * r + k], tail[3 * r + k]);
            exact = exact && tail[3 * r + k] == 0.0;
        }
    }
    if (exact) {
        EM_STAT(orient3d, exact_differences);
        return det3_xyz(diff, diff + 3, diff + 6).sign();
    }
    // det [x y z 1] over rows a, b, c, d, expanded along the column of ones.
    EM_STAT(orient3d, expansion);
    return ((det3_xyz(a, b, c) - det3_xyz(a, b, d)) + (det3_xyz(a, c, d) - det3_xyz(b, c, d)))
        .sign();
}

}  // namespace exactmesh::predicates
