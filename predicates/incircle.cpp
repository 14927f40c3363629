// SPDX-License-Identifier: MIT
// Exact stages of incircle [Shewchuk97 §4.5]: B the determinant of the rounded differences,
// first in two terms (double-double, error below 128 u^2 of the permanent; the exact value when
// the differences are exact, else certified by Shewchuk's B bound), C its first-order tail
// corrections; then B as an exact expansion (exact differences) or the raw-coordinate
// det [x y x^2+y^2 1] (384 components). Out of the expansion-safe range: scaled into it by a
// power of two when that is exact (detail::rescale_into_safe_range), else GMP.
#include "predicates/incircle.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "predicates/adaptive_bounds.hpp"
#include "predicates/exact_range.hpp"
#include "predicates/expansion.hpp"
#include "predicates/gmp_fallback.hpp"
#include "predicates/two_term.hpp"

namespace exactmesh::predicates {

namespace {

/// px * qy - qx * py exactly.
Expansion<4> minor_xy(const double* p, const double* q) noexcept {
    return exact_product(p[0], q[1]) - exact_product(q[0], p[1]);
}

/// px^2 + py^2 exactly, compressed (usually 2 components).
Expansion<4> lift(const double* p) noexcept {
    return compressed(exact_product(p[0], p[0]) + exact_product(p[1], p[1]));
}

/// (px^2 + py^2) * m exactly, as a product of two short compressed expansions.
template <int N>
Expansion<8 * N> lift_times(const double* p, const Expansion<N>& m) noexcept {
    return product(lift(p), compressed(m));
}

/// Raw det [x y 1] over rows p, q, r (orient2d without differences), compressed because it is
/// multiplied next: its value has few significant bits compared with its 12 components.
Expansion<12> det3_xy1(const double* p, const double* q, const double* r) noexcept {
    return compressed(minor_xy(p, q) + minor_xy(q, r) + minor_xy(r, p));
}

/// Stage B exactly: det [p-d, |p-d|^2] over the rounded differences diff = (adx, ady, bdx, bdy,
/// cdx, cdy), along the lift column. Minors are compressed first (2x2 determinants rarely need
/// more than 2 components), which halves the work of the lift products.
[[gnu::noinline]] Sign exact_stage_b(const double* diff) noexcept {
    const double* ad = diff;
    const double* bd = diff + 2;
    const double* cd = diff + 4;
    return ((lift_times(ad, compressed(minor_xy(bd, cd))) -
             lift_times(bd, compressed(minor_xy(ad, cd)))) +
            lift_times(cd, compressed(minor_xy(ad, bd))))
        .sign();
}

/// exact_stage_b's determinant when the six differences are integers below 2^12 times one
/// power of two (cocircular lattice points, the ties of in_equatorial_sphere_3d's planar stage
/// in 3D refinement on boxes: ~2,600 instructions each in expansions). Scaled by that power of
/// two (exact: the results are integers below 2^12, checked), every minor is below 2^25, every
/// lift below 2^25, every term below 2^50 and the sum below 2^52: integers that plain doubles
/// hold exactly, at any scale. nullopt when the differences are not such integers.
std::optional<Sign> small_integer_stage_b(const double* diff) noexcept {
    double largest = 0;
    for (int i = 0; i < 6; ++i) largest = std::max(largest, std::fabs(diff[i]));
    if (largest == 0) return Sign::Zero;
    const int shift = 11 - std::ilogb(largest);  // largest scaled into [2^11, 2^12)
    // One multiplication by 2^shift when that is a normal double (exact short of underflow,
    // which the check below catches), else ldexp each.
    const bool normal_scale = shift >= -1022 && shift <= 1023;
    const double scale = normal_scale ? std::ldexp(1.0, shift) : 0.0;
    double x[6];
    for (int i = 0; i < 6; ++i) {
        x[i] = normal_scale ? diff[i] * scale : std::ldexp(diff[i], shift);
        if (x[i] != std::trunc(x[i]) || (x[i] == 0) != (diff[i] == 0)) return std::nullopt;
    }
    auto minor = [](const double* p, const double* q) { return p[0] * q[1] - q[0] * p[1]; };
    auto lift = [](const double* p) { return p[0] * p[0] + p[1] * p[1]; };
    const double* ad = x;
    const double* bd = x + 2;
    const double* cd = x + 4;
    const double det =
        (lift(ad) * minor(bd, cd) - lift(bd) * minor(ad, cd)) + lift(cd) * minor(ad, bd);
    return det > 0 ? Sign::Positive : det < 0 ? Sign::Negative : Sign::Zero;
}

/// det [x y w 1] over rows a, b, c, d, expanded along the lift column w.
[[gnu::noinline]] Sign raw_expansion(const double* a, const double* b, const double* c,
                                     const double* d) noexcept {
    return ((lift_times(a, det3_xy1(b, c, d)) - lift_times(b, det3_xy1(a, c, d))) +
            (lift_times(c, det3_xy1(a, b, d)) - lift_times(d, det3_xy1(a, b, c))))
        .sign();
}

}  // namespace

Sign incircle_exact(const double* a, const double* b, const double* c, const double* d) {
    const auto coordinates = {a[0], a[1], b[0], b[1], c[0], c[1], d[0], d[1]};
    detail::require_finite("incircle", coordinates);
    if (!detail::expansion_safe(4, coordinates)) {
        return detail::out_of_range_sign<8>(
            &PredicateStats::incircle, 4, coordinates,
            [](const double* s) { return incircle_filter(s, s + 2, s + 4, s + 6); },
            [](const double* s) { return incircle_exact(s, s + 2, s + 4, s + 6); },
            [&] { return incircle_gmp(a, b, c, d); });
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
    const double adx = diff[0], ady = diff[1], bdx = diff[2], bdy = diff[3];
    const double cdx = diff[4], cdy = diff[5];
    const double alift = adx * adx + ady * ady, blift = bdx * bdx + bdy * bdy;
    const double clift = cdx * cdx + cdy * cdy;
    const double permanent = (std::fabs(bdx * cdy) + std::fabs(cdx * bdy)) * alift +
                             (std::fabs(cdx * ady) + std::fabs(adx * cdy)) * blift +
                             (std::fabs(adx * bdy) + std::fabs(bdx * ady)) * clift;
    // Stage B in two terms: det [p-d, |p-d|^2] of the rounded differences to within
    // icc_errbound_two_term * permanent (proofs/invariants/filters.md, "Two-term stage").
    const detail::TwoTerm det_two_term = detail::incircle_stage_b(diff);
    const double det_b = det_two_term.hi + det_two_term.lo;
    const double two_term_bound = adaptive::icc_errbound_two_term * permanent;
    if (exact) {
        // The differences are exact, so stage B is the determinant itself.
        if (adaptive::certified(det_b, two_term_bound)) {
            EM_STAT(incircle, adaptive);
            return sign_of(det_b);
        }
        EM_STAT(incircle, exact_differences);
        if (const auto s = small_integer_stage_b(diff)) return *s;
        return exact_stage_b(diff);
    }
    if (adaptive::certified(det_b, adaptive::icc_errbound_b * permanent + two_term_bound)) {
        EM_STAT(incircle, adaptive);
        return sign_of(det_b);
    }
    // Stage C: the first-order terms of the difference tails.
    const double adxt = tail[0], adyt = tail[1], bdxt = tail[2], bdyt = tail[3];
    const double cdxt = tail[4], cdyt = tail[5];
    const double det_c =
        det_b +
        (((adx * adx + ady * ady) * ((bdx * cdyt + cdy * bdxt) - (bdy * cdxt + cdx * bdyt)) +
          2.0 * (adx * adxt + ady * adyt) * (bdx * cdy - bdy * cdx)) +
         ((bdx * bdx + bdy * bdy) * ((cdx * adyt + ady * cdxt) - (cdy * adxt + adx * cdyt)) +
          2.0 * (bdx * bdxt + bdy * bdyt) * (cdx * ady - cdy * adx)) +
         ((cdx * cdx + cdy * cdy) * ((adx * bdyt + bdy * adxt) - (ady * bdxt + bdx * adyt)) +
          2.0 * (cdx * cdxt + cdy * cdyt) * (adx * bdy - ady * bdx)));
    if (adaptive::certified(det_c, adaptive::icc_errbound_c * permanent +
                                       adaptive::result_errbound * std::fabs(det_b) +
                                       2.0 * two_term_bound)) {
        EM_STAT(incircle, adaptive);
        return sign_of(det_c);
    }
    EM_STAT(incircle, expansion);
    return raw_expansion(a, b, c, d);
}

}  // namespace exactmesh::predicates
