// SPDX-License-Identifier: MIT
// Exact stages of orient2d [Shewchuk97 §4.3]: B the exact determinant of the rounded
// differences (exact when they are, else certified by an error bound), C first-order tail terms,
// then the exact raw-coordinate expansion (12 components). Out of the expansion-safe range:
// scaled into it by a power of two when that is exact (detail::rescale_into_safe_range), else GMP.
#include "predicates/orient2d.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "predicates/adaptive_bounds.hpp"
#include "predicates/exact_range.hpp"
#include "predicates/expansion.hpp"
#include "predicates/gmp_fallback.hpp"
#include "predicates/power_of_two.hpp"

namespace exactmesh::predicates {

namespace {

/// px * qy - qx * py exactly.
Expansion<4> minor_xy(const double* p, const double* q) noexcept {
    return exact_product(p[0], q[1]) - exact_product(q[0], p[1]);
}

/// The filter on the differences scaled into its range by a power of two per axis, when they
/// lie outside it (a domain scaled by 2^+-600) and the scaling is exact: the sign of the
/// determinant is unchanged (it is multiplied by 2^(kx + ky)), and the filter's proof holds as
/// it is, since proofs/gappa/orient2d_filter.g normalises each axis by its own power of two
/// and takes the differences as rounded from the exact ones (a rounded difference that
/// underflows is exact). Scaling down loses no bit while every nonzero difference stays at
/// least 2^-1022 (one scaled to zero counts as lost). std::nullopt otherwise (in range, zero,
/// non-finite, or undecided): the stages below. Before it, six coordinates were rescaled per call
/// (out_of_range_sign), and the quadtree's box tests of a comb scaled by 2^-600 spent 45% of their
/// time there.
std::optional<Sign> filter_scaled_per_axis(double adx, double ady, double bdx,
                                           double bdy) noexcept {
    const double maxx = std::max(std::fabs(adx), std::fabs(bdx));
    const double maxy = std::max(std::fabs(ady), std::fabs(bdy));
    constexpr double kLargest = std::numeric_limits<double>::max();
    if (!(maxx > 0 && maxy > 0 && maxx <= kLargest && maxy <= kLargest)) return std::nullopt;
    if (std::min(maxx, maxy) >= orient2d_filter_min && std::max(maxx, maxy) <= orient2d_filter_max)
        return std::nullopt;  // in range: the filter has seen these already
    const PowerOfTwo x(-binary_exponent(maxx)), y(-binary_exponent(maxy));
    const double unscaled[4] = {adx, ady, bdx, bdy};
    const double d[4] = {x(adx), y(ady), x(bdx), y(bdy)};
    for (int k = 0; k < 4; ++k) {
        // A nonzero difference scaled below 2^-1022, or to zero, lost bits: not exact.
        if (unscaled[k] != 0.0 && std::fabs(d[k]) < 0x1p-1022) return std::nullopt;
    }
    return orient2d_filter_differences(d[0], d[1], d[2], d[3]);
}

}  // namespace

Sign orient2d_exact(const double* a, const double* b, const double* c) {
    detail::require_finite("orient2d", {a[0], a[1], b[0], b[1], c[0], c[1]});
    if (!detail::expansion_safe(2, {a[0], a[1], b[0], b[1], c[0], c[1]})) {
        // Only here, off the in-range exact path (near-degenerate inputs at ordinary scales).
        if (const auto s =
                filter_scaled_per_axis(a[0] - c[0], a[1] - c[1], b[0] - c[0], b[1] - c[1])) {
            detail::count_stage(&PredicateStats::orient2d, &StageCounts::rescaled);
            detail::count_stage(&PredicateStats::orient2d, &StageCounts::filter);
            return *s;
        }
        return detail::out_of_range_sign<6>(
            &PredicateStats::orient2d, 2, {a[0], a[1], b[0], b[1], c[0], c[1]},
            [](const double* s) { return orient2d_filter(s, s + 2, s + 4); },
            [](const double* s) { return orient2d_exact(s, s + 2, s + 4); },
            [&] { return orient2d_gmp(a, b, c); });
    }
    double adx, bdx, ady, bdy, adx_tail, bdx_tail, ady_tail, bdy_tail;
    two_diff(a[0], c[0], adx, adx_tail);
    two_diff(b[0], c[0], bdx, bdx_tail);
    two_diff(a[1], c[1], ady, ady_tail);
    two_diff(b[1], c[1], bdy, bdy_tail);
    // Stage B: the exact determinant of the rounded differences; exact when they are.
    const auto det_b = exact_product(adx, bdy) - exact_product(ady, bdx);
    if (adx_tail == 0.0 && bdx_tail == 0.0 && ady_tail == 0.0 && bdy_tail == 0.0) {
        EM_STAT(orient2d, exact_differences);
        return det_b.sign();
    }
    const double detsum = std::fabs(adx * bdy) + std::fabs(ady * bdx);
    double det = det_b.approximate();
    if (adaptive::certified(det, adaptive::ccw_errbound_b * detsum)) {
        EM_STAT(orient2d, adaptive);
        return sign_of(det);
    }
    // Stage C: add the first-order terms of the difference tails.
    det += (adx * bdy_tail + bdy * adx_tail) - (ady * bdx_tail + bdx * ady_tail);
    if (adaptive::certified(
            det, adaptive::ccw_errbound_c * detsum + adaptive::result_errbound * std::fabs(det))) {
        EM_STAT(orient2d, adaptive);
        return sign_of(det);
    }
    // det [x y 1] over rows a, b, c = m(a,b) + m(b,c) + m(c,a): no differences, no tails.
    EM_STAT(orient2d, expansion);
    return (minor_xy(a, b) + minor_xy(b, c) + minor_xy(c, a)).sign();
}

}  // namespace exactmesh::predicates
