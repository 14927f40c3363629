// SPDX-License-Identifier: MIT
// Exact stages of insphere [Shewchuk97 §4.6]: B the determinant of the rounded differences,
// first in two terms (double-double, error below 512 u^2 of the permanent; the exact value when
// the differences are exact, else certified by Shewchuk's B bound), C its first-order tail
// corrections [Shewchuk97, insphereadapt]; then B as an exact expansion (1152 components, exact
// differences), or, with inexact differences, the determinant in GMP integers on one
// power-of-two scale (coordinates spanning at most 192 bits; no allocation) or the
// raw-coordinate det [x y z w 1] (5760 components). Out of the expansion-safe range: scaled
// into it by a power of two when exact (detail::rescale_into_safe_range), else GMP.
#include "predicates/insphere.hpp"

#include <gmp.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <optional>

#include "predicates/adaptive_bounds.hpp"
#include "predicates/exact_range.hpp"
#include "predicates/expansion.hpp"
#include "predicates/gmp_fallback.hpp"
#include "predicates/scaled_integers.hpp"
#include "predicates/two_term.hpp"

namespace exactmesh::predicates {

namespace {

/// px * qy - qx * py exactly.
Expansion<4> minor_xy(const double* p, const double* q) noexcept {
    return exact_product(p[0], q[1]) - exact_product(q[0], p[1]);
}

/// det [p; q; r] of xyz rows, expanded along z; compressed, since it is multiplied next.
Expansion<24> det3_xyz(const double* p, const double* q, const double* r) noexcept {
    return compressed(scale(minor_xy(q, r), p[2]) - scale(minor_xy(p, r), q[2]) +
                      scale(minor_xy(p, q), r[2]));
}

/// px^2 + py^2 + pz^2 exactly, compressed (usually 2 components).
Expansion<6> lift(const double* p) noexcept {
    return compressed(exact_product(p[0], p[0]) + exact_product(p[1], p[1]) +
                      exact_product(p[2], p[2]));
}

/// (px^2 + py^2 + pz^2) * m exactly, as a product of two short compressed expansions.
template <int N>
Expansion<12 * N> lift_times(const double* p, const Expansion<N>& m) noexcept {
    return product(lift(p), compressed(m));
}

/// Raw det [x y z 1] over rows p, q, r, s, given their four xyz minors.
Expansion<96> det4_xyz1(const Expansion<24>& pqr, const Expansion<24>& pqs,
                        const Expansion<24>& prs, const Expansion<24>& qrs) noexcept {
    return compressed((pqr - pqs) + (prs - qrs));
}

/// Stage B exactly: det [p-e, |p-e|^2] over the rounded differences diff = (aex, aey, aez, ...,
/// dez), along the lift column.
[[gnu::noinline]] Sign exact_stage_b(const double* diff) noexcept {
    const double* ae = diff;
    const double* be = diff + 3;
    const double* ce = diff + 6;
    const double* de = diff + 9;
    return ((lift_times(be, det3_xyz(ae, ce, de)) - lift_times(ae, det3_xyz(be, ce, de))) +
            (lift_times(de, det3_xyz(ae, be, ce)) - lift_times(ce, det3_xyz(ae, be, de))))
        .sign();
}

/// exact_stage_b's determinant when the twelve differences are integers below 2^8 times one
/// power of two (cospherical lattice points, as on boxes refined in 3D: all 35,000 exact calls
/// of box-with-hole at V = 0.00005 were such ties, each ~4,900 instructions in expansions). The
/// differences scaled by that power of two (exact: the results are integers below 2^8, checked)
/// make every product and partial sum below an integer below 2^53 (minors < 2^17, 3x3
/// determinants < 2^27, lifts < 2^18, terms < 2^45, the sum < 2^47), so plain doubles evaluate
/// it exactly, at any scale. nullopt when the differences are not such integers.
std::optional<Sign> small_integer_stage_b(const double* diff) noexcept {
    double largest = 0;
    for (int i = 0; i < 12; ++i) largest = std::max(largest, std::fabs(diff[i]));
    if (largest == 0) return Sign::Zero;
    const int shift = 7 - std::ilogb(largest);  // largest scaled into [2^7, 2^8)
    // One multiplication by 2^shift when that is a normal double (exact: a product by a power
    // of two is, short of underflow, which the check below catches), else ldexp each.
    const bool normal_scale = shift >= -1022 && shift <= 1023;
    const double scale = normal_scale ? std::ldexp(1.0, shift) : 0.0;
    double x[12];
    for (int i = 0; i < 12; ++i) {
        x[i] = normal_scale ? diff[i] * scale : std::ldexp(diff[i], shift);
        // A non-integer, or a difference lost below the subnormals, is not such a point set.
        if (x[i] != std::trunc(x[i]) || (x[i] == 0) != (diff[i] == 0)) return std::nullopt;
    }
    auto minor = [](const double* p, const double* q) { return p[0] * q[1] - q[0] * p[1]; };
    auto det3 = [&](const double* p, const double* q, const double* r) {
        return minor(q, r) * p[2] - minor(p, r) * q[2] + minor(p, q) * r[2];
    };
    auto lift = [](const double* p) { return p[0] * p[0] + p[1] * p[1] + p[2] * p[2]; };
    const double* ae = x;
    const double* be = x + 3;
    const double* ce = x + 6;
    const double* de = x + 9;
    const double det = (lift(be) * det3(ae, ce, de) - lift(ae) * det3(be, ce, de)) +
                       (lift(de) * det3(ae, be, ce) - lift(ce) * det3(ae, be, de));
    return det > 0 ? Sign::Positive : det < 0 ? Sign::Negative : Sign::Zero;
}

/// det [x y z w 1] over rows a..e, expanded along the lift column w:
/// -w_a O(bcde) + w_b O(acde) - w_c O(abde) + w_d O(abce) - w_e O(abcd).
[[gnu::noinline]] Sign raw_expansion(const double* a, const double* b, const double* c,
                                     const double* d, const double* e) noexcept {
    const auto abc = det3_xyz(a, b, c), abd = det3_xyz(a, b, d), abe = det3_xyz(a, b, e);
    const auto acd = det3_xyz(a, c, d), ace = det3_xyz(a, c, e), ade = det3_xyz(a, d, e);
    const auto bcd = det3_xyz(b, c, d), bce = det3_xyz(b, c, e), bde = det3_xyz(b, d, e);
    const auto cde = det3_xyz(c, d, e);
    const auto o_bcde = det4_xyz1(bcd, bce, bde, cde);
    const auto o_acde = det4_xyz1(acd, ace, ade, cde);
    const auto o_abde = det4_xyz1(abd, abe, ade, bde);
    const auto o_abce = det4_xyz1(abc, abe, ace, bce);
    const auto o_abcd = det4_xyz1(abc, abd, acd, bcd);
    const auto sum = ((lift_times(b, o_acde) - lift_times(a, o_bcde)) +
                      (lift_times(d, o_abce) - lift_times(c, o_abde))) -
                     lift_times(e, o_abcd);
    return sum.sign();
}

/// The GMP integers of integer_stage, kept between calls (one set per thread): no allocation
/// once they have grown to the calls' sizes.
struct InsphereIntegers {
    mpz_t x[5][3];  // a..e scaled to integers
    mpz_t m[4][3];  // rows a..d minus e
    mpz_t lift[4], minor[6], det3[4], value;
    InsphereIntegers() {
        for (auto& row : x)
            for (auto& z : row) mpz_init2(z, 128);
        for (auto& row : m)
            for (auto& z : row) mpz_init2(z, 128);
        for (auto& z : lift) mpz_init2(z, 256);
        for (auto& z : minor) mpz_init2(z, 256);
        for (auto& z : det3) mpz_init2(z, 384);
        mpz_init2(value, 640);
    }
    ~InsphereIntegers() {
        for (auto& row : x)
            for (auto& z : row) mpz_clear(z);
        for (auto& row : m)
            for (auto& z : row) mpz_clear(z);
        for (auto& z : lift) mpz_clear(z);
        for (auto& z : minor) mpz_clear(z);
        for (auto& z : det3) mpz_clear(z);
        mpz_clear(value);
    }
    InsphereIntegers(const InsphereIntegers&) = delete;
    InsphereIntegers& operator=(const InsphereIntegers&) = delete;
};

/// Widest span (bits from the highest to the lowest set bit over all fifteen coordinates) that
/// integer_stage takes: its coordinates are then integers below 2^(kIntegerStageBits + 1) and
/// the determinant is below 2^(5 (kIntegerStageBits + 2) + 8), at most 16 limbs; wider spans (a
/// coordinate near 0 beside large ones) go to raw_expansion, whose length does not grow with the
/// span.
constexpr int kIntegerStageBits = 192;

/// exact_stage_b's determinant over rows a..d minus e, on the coordinates as integers of one
/// common power-of-two scale (each finite double is an integer times 2^k; scaling by 2^-kmin
/// makes every coordinate an integer and multiplies the degree-5 determinant by 2^(-5 kmin) > 0,
/// keeping its sign), so the differences are exact whatever their rounding in doubles. For the
/// calls whose rounded differences are inexact: the wing's cospherical ties (the six corners of
/// two neighbouring strips' rectangles lie on one sphere), 9,700 per run, 21,700 instructions
/// each in raw_expansion's 5,760-component worst case. nullopt when the coordinates span more
/// than kIntegerStageBits bits.
[[gnu::noinline]] std::optional<Sign> integer_stage(const double* a, const double* b,
                                                    const double* c, const double* d,
                                                    const double* e) {
    const double* points[5] = {a, b, c, d, e};
    int low = INT_MAX, high = INT_MIN;
    for (const double* p : points) {
        for (int k = 0; k < 3; ++k) {
            if (p[k] == 0) continue;
            low = std::min(low, detail::least_set_bit_exponent(p[k]));
            high = std::max(high, std::ilogb(p[k]));
        }
    }
    if (low == INT_MAX) return Sign::Zero;  // five times the origin
    if (high - low > kIntegerStageBits) return std::nullopt;
    thread_local InsphereIntegers z;
    for (int j = 0; j < 5; ++j)
        for (int k = 0; k < 3; ++k) detail::set_scaled_integer(z.x[j][k], points[j][k], low);
    for (int r = 0; r < 4; ++r) {
        for (int k = 0; k < 3; ++k) mpz_sub(z.m[r][k], z.x[r][k], z.x[4][k]);
        mpz_mul(z.lift[r], z.m[r][0], z.m[r][0]);
        mpz_addmul(z.lift[r], z.m[r][1], z.m[r][1]);
        mpz_addmul(z.lift[r], z.m[r][2], z.m[r][2]);
    }
    // minor_xy(p, q) = px qy - qx py for the pairs ab, ac, ad, bc, bd, cd.
    constexpr int kPairs[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
    for (int i = 0; i < 6; ++i) {
        const auto& p = z.m[kPairs[i][0]];
        const auto& q = z.m[kPairs[i][1]];
        mpz_mul(z.minor[i], p[0], q[1]);
        mpz_submul(z.minor[i], q[0], p[1]);
    }
    // det3_xyz(p, q, r) = minor(q, r) pz - minor(p, r) qz + minor(p, q) rz for acd, bcd, abc,
    // abd (det3[0..3]); each row: p, q, r, then the minors' indices qr, pr, pq above.
    constexpr int kTriples[4][6] = {
        {0, 2, 3, 5, 2, 1}, {1, 2, 3, 5, 4, 3}, {0, 1, 2, 3, 1, 0}, {0, 1, 3, 4, 2, 0}};
    for (int t = 0; t < 4; ++t) {
        const int* x = kTriples[t];
        mpz_mul(z.det3[t], z.minor[x[3]], z.m[x[0]][2]);
        mpz_submul(z.det3[t], z.minor[x[4]], z.m[x[1]][2]);
        mpz_addmul(z.det3[t], z.minor[x[5]], z.m[x[2]][2]);
    }
    // (lift_b det3(acd) - lift_a det3(bcd)) + (lift_d det3(abc) - lift_c det3(abd)).
    mpz_mul(z.value, z.lift[1], z.det3[0]);
    mpz_submul(z.value, z.lift[0], z.det3[1]);
    mpz_addmul(z.value, z.lift[3], z.det3[2]);
    mpz_submul(z.value, z.lift[2], z.det3[3]);
    const int s = mpz_sgn(z.value);
    return s > 0 ? Sign::Positive : s < 0 ? Sign::Negative : Sign::Zero;
}

}  // namespace

Sign insphere_exact(const double* a, const double* b, const double* c, const double* d,
                    const double* e) {
    const auto coordinates = {a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1],
                              c[2], d[0], d[1], d[2], e[0], e[1], e[2]};
    detail::require_finite("insphere", coordinates);
    if (!detail::expansion_safe(5, coordinates)) {
        return detail::out_of_range_sign<15>(
            &PredicateStats::insphere, 5, coordinates,
            [](const double* s) { return insphere_filter(s, s + 3, s + 6, s + 9, s + 12); },
            [](const double* s) { return insphere_exact(s, s + 3, s + 6, s + 9, s + 12); },
            [&] { return insphere_gmp(a, b, c, d, e); });
    }
    double diff[12], tail[12];
    const double* rows[4] = {a, b, c, d};
    bool exact = true;
    for (int r = 0; r < 4; ++r) {
        for (int k = 0; k < 3; ++k) {
            two_diff(rows[r][k], e[k], diff[3 * r + k], tail[3 * r + k]);
            exact = exact && tail[3 * r + k] == 0.0;
        }
    }
    if (exact) {
        // Cospherical lattice points (the exact calls of 3D refinement on boxes): decided
        // exactly at once, before the two-term stage that could not certify their zero.
        if (const auto s = small_integer_stage_b(diff)) {
            EM_STAT(insphere, exact_differences);
            return *s;
        }
    }
    const double aex = diff[0], aey = diff[1], aez = diff[2], bex = diff[3], bey = diff[4];
    const double bez = diff[5], cex = diff[6], cey = diff[7], cez = diff[8], dex = diff[9];
    const double dey = diff[10], dez = diff[11];
    // The permanent: each lift times the permanent of the other rows' xyz minor.
    auto lift = [](const double* p) { return p[0] * p[0] + p[1] * p[1] + p[2] * p[2]; };
    auto permanent3 = [](const double* p, const double* q, const double* r) {
        return (std::fabs(p[0] * q[1]) + std::fabs(q[0] * p[1])) * std::fabs(r[2]) +
               (std::fabs(q[0] * r[1]) + std::fabs(r[0] * q[1])) * std::fabs(p[2]) +
               (std::fabs(r[0] * p[1]) + std::fabs(p[0] * r[1])) * std::fabs(q[2]);
    };
    const double* ae = diff;
    const double* be = diff + 3;
    const double* ce = diff + 6;
    const double* de = diff + 9;
    const double permanent = lift(ae) * permanent3(be, ce, de) + lift(be) * permanent3(ae, ce, de) +
                             lift(ce) * permanent3(ae, be, de) + lift(de) * permanent3(ae, be, ce);
    // Stage B in two terms: det [p-e, |p-e|^2] of the rounded differences to within
    // isp_errbound_two_term * permanent (proofs/invariants/filters.md, "Two-term stage").
    const detail::TwoTerm det_two_term = detail::insphere_stage_b(diff);
    const double det_b = det_two_term.hi + det_two_term.lo;
    const double two_term_bound = adaptive::isp_errbound_two_term * permanent;
    if (exact) {
        // The differences are exact, so stage B is the determinant itself.
        if (adaptive::certified(det_b, two_term_bound)) {
            EM_STAT(insphere, adaptive);
            return sign_of(det_b);
        }
        EM_STAT(insphere, exact_differences);
        return exact_stage_b(diff);
    }
    if (adaptive::certified(det_b, adaptive::isp_errbound_b * permanent + two_term_bound)) {
        EM_STAT(insphere, adaptive);
        return sign_of(det_b);
    }
    // Stage C: the first-order terms of the difference tails [Shewchuk97, insphereadapt].
    const double aext = tail[0], aeyt = tail[1], aezt = tail[2], bext = tail[3];
    const double beyt = tail[4], bezt = tail[5], cext = tail[6], ceyt = tail[7];
    const double cezt = tail[8], dext = tail[9], deyt = tail[10], dezt = tail[11];
    const double ab3 = aex * bey - bex * aey, bc3 = bex * cey - cex * bey;
    const double cd3 = cex * dey - dex * cey, da3 = dex * aey - aex * dey;
    const double ac3 = aex * cey - cex * aey, bd3 = bex * dey - dex * bey;
    const double abeps = (aex * beyt + bey * aext) - (aey * bext + bex * aeyt);
    const double bceps = (bex * ceyt + cey * bext) - (bey * cext + cex * beyt);
    const double cdeps = (cex * deyt + dey * cext) - (cey * dext + dex * ceyt);
    const double daeps = (dex * aeyt + aey * dext) - (dey * aext + aex * deyt);
    const double aceps = (aex * ceyt + cey * aext) - (aey * cext + cex * aeyt);
    const double bdeps = (bex * deyt + dey * bext) - (bey * dext + dex * beyt);
    const double det_c =
        det_b +
        ((((bex * bex + bey * bey + bez * bez) * ((cez * daeps + dez * aceps + aez * cdeps) +
                                                  (cezt * da3 + dezt * ac3 + aezt * cd3)) +
           (dex * dex + dey * dey + dez * dez) * ((aez * bceps - bez * aceps + cez * abeps) +
                                                  (aezt * bc3 - bezt * ac3 + cezt * ab3))) -
          ((aex * aex + aey * aey + aez * aez) * ((bez * cdeps - cez * bdeps + dez * bceps) +
                                                  (bezt * cd3 - cezt * bd3 + dezt * bc3)) +
           (cex * cex + cey * cey + cez * cez) * ((dez * abeps + aez * bdeps + bez * daeps) +
                                                  (dezt * ab3 + aezt * bd3 + bezt * da3)))) +
         2.0 * (((bex * bext + bey * beyt + bez * bezt) * (cez * da3 + dez * ac3 + aez * cd3) +
                 (dex * dext + dey * deyt + dez * dezt) * (aez * bc3 - bez * ac3 + cez * ab3)) -
                ((aex * aext + aey * aeyt + aez * aezt) * (bez * cd3 - cez * bd3 + dez * bc3) +
                 (cex * cext + cey * ceyt + cez * cezt) * (dez * ab3 + aez * bd3 + bez * da3))));
    if (adaptive::certified(det_c, adaptive::isp_errbound_c * permanent +
                                       adaptive::result_errbound * std::fabs(det_b) +
                                       2.0 * two_term_bound)) {
        EM_STAT(insphere, adaptive);
        return sign_of(det_c);
    }
    EM_STAT(insphere, expansion);
    if (const auto s = integer_stage(a, b, c, d, e)) return *s;
    return raw_expansion(a, b, c, d, e);
}

}  // namespace exactmesh::predicates
