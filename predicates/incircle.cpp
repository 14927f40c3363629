// SPDX-License-Identifier: MIT
// Exact stages of incircle [Shewchuk97 §4.5]: B when the coordinate differences are exact
// (96 components), C over raw coordinates as det [x y x^2+y^2 1] (384 components), D in GMP.
#include "predicates/incircle.hpp"

#include "predicates/exact_range.hpp"
#include "predicates/expansion.hpp"
#include "predicates/gmp_fallback.hpp"

namespace exactmesh::predicates {

namespace {

/// px * qy - qx * py exactly.
Expansion<4> minor_xy(const double* p, const double* q) noexcept {
    return exact_product(p[0], q[1]) - exact_product(q[0], p[1]);
}

/// (px^2 + py^2) * m exactly, without rounding the lift.
template <int N>
Expansion<8 * N> lift_times(const double* p, const Expansion<N>& m) noexcept {
    return scale_twice(m, p[0]) + scale_twice(m, p[1]);
}

/// Raw det [x y 1] over rows p, q, r (orient2d without differences), compressed because it is
/// multiplied next: its value has few significant bits compared with its 12 components.
Expansion<12> det3_xy1(const double* p, const double* q, const double* r) noexcept {
    return compressed(minor_xy(p, q) + minor_xy(q, r) + minor_xy(r, p));
}

}  // namespace

Sign incircle_exact(const double* a, const double* b, const double* c, const double* d) {
    const auto coordinates = {a[0], a[1], b[0], b[1], c[0], c[1], d[0], d[1]};
    detail::require_finite("incircle", coordinates);
    if (!detail::expansion_safe(4, coordinates)) {
        EM_STAT(incircle, gmp);
        return incircle_gmp(a, b, c, d);
    }
    double diff[6], tail[6];
    const double* rows[3] = {a, b, c};
    bool exact = true;
    for (int r = 0; r < 3; ++r) {
        for (int k = 0; k < 2; ++k) {
            two_diff(rows[r][k], d[k], diff[2 * r + k], tail[2 * r + k]);
            exact = exact && tail[2 * r + k] == 0.0;
        }
    }
    if (exact) {
        // det [p-d, |p-d|^2] expanded along the lift column.
        EM_STAT(incircle, exact_differences);
        const double* ad = diff;
        const double* bd = diff + 2;
        const double* cd = diff + 4;
        return (lift_times(ad, minor_xy(bd, cd)) - lift_times(bd, minor_xy(ad, cd)) +
                lift_times(cd, minor_xy(ad, bd)))
            .sign();
    }
    // det [x y w 1] over rows a, b, c, d, expanded along the lift column w.
    EM_STAT(incircle, expansion);
    return ((lift_times(a, det3_xy1(b, c, d)) - lift_times(b, det3_xy1(a, c, d))) +
            (lift_times(c, det3_xy1(a, b, d)) - lift_times(d, det3_xy1(a, b, c))))
        .sign();
}

}  // namespace exactmesh::predicates
