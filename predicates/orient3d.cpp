// SPDX-License-Identifier: MIT
// Exact stages of orient3d [Shewchuk97 §4.4]: B the exact determinant of the rounded
// differences (exact when they are, else certified by an error bound), C its first-order tail
// terms, then the raw-coordinate det [x y z 1] (96 components). Out of the expansion-safe range:
// scaled into it by a power of two when that is exact (detail::rescale_into_safe_range), else GMP.
#include "predicates/orient3d.hpp"

#include "predicates/adaptive_bounds.hpp"
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
        return detail::out_of_range_sign<12>(
            &PredicateStats::orient3d, 3, coordinates,
            [](const double* s) { return orient3d_filter(s, s + 3, s + 6, s + 9); },
            [](const double* s) { return orient3d_exact(s, s + 3, s + 6, s + 9); },
            [&] { return orient3d_gmp(a, b, c, d); });
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
    // Stage B: det [a-d; b-d; c-d] of the rounded differences, exactly.
    const auto det_b = det3_xyz(diff, diff + 3, diff + 6);
    if (exact) {
        EM_STAT(orient3d, exact_differences);
        return det_b.sign();
    }
    const double adx = diff[0], ady = diff[1], adz = diff[2], bdx = diff[3], bdy = diff[4];
    const double bdz = diff[5], cdx = diff[6], cdy = diff[7], cdz = diff[8];
    const double adxt = tail[0], adyt = tail[1], adzt = tail[2], bdxt = tail[3], bdyt = tail[4];
    const double bdzt = tail[5], cdxt = tail[6], cdyt = tail[7], cdzt = tail[8];
    const double permanent = (std::fabs(bdx * cdy) + std::fabs(cdx * bdy)) * std::fabs(adz) +
                             (std::fabs(cdx * ady) + std::fabs(adx * cdy)) * std::fabs(bdz) +
                             (std::fabs(adx * bdy) + std::fabs(bdx * ady)) * std::fabs(cdz);
    double det = det_b.approximate();
    if (adaptive::certified(det, adaptive::o3d_errbound_b * permanent)) {
        EM_STAT(orient3d, adaptive);
        return sign_of(det);
    }
    // Stage C: the first-order terms of the difference tails (expansion along z).
    det += (adz * ((bdx * cdyt + cdy * bdxt) - (bdy * cdxt + cdx * bdyt)) +
            adzt * (bdx * cdy - bdy * cdx)) +
           (bdz * ((cdx * adyt + ady * cdxt) - (cdy * adxt + adx * cdyt)) +
            bdzt * (cdx * ady - cdy * adx)) +
           (cdz * ((adx * bdyt + bdy * adxt) - (ady * bdxt + bdx * adyt)) +
            cdzt * (adx * bdy - ady * bdx));
    if (adaptive::certified(det, adaptive::o3d_errbound_c * permanent +
                                     adaptive::result_errbound * std::fabs(det))) {
        EM_STAT(orient3d, adaptive);
        return sign_of(det);
    }
    // det [x y z 1] over rows a, b, c, d, expanded along the column of ones.
    EM_STAT(orient3d, expansion);
    return ((det3_xyz(a, b, c) - det3_xyz(a, b, d)) + (det3_xyz(a, c, d) - det3_xyz(b, c, d)))
        .sign();
}

}  // namespace exactmesh::predicates
