// SPDX-License-Identifier: MIT
// insphere(a, b, c, d, e): sign of det [p-e, |p-e|^2] over rows p = a, b, c, d; Positive when e
// lies inside the sphere through a, b, c, d with orient3d(a, b, c, d) > 0 [Shewchuk97 §4].
// Stages as in orient2d.hpp; filter proof proofs/gappa/insphere_filter.g.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>
#include <optional>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

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

/// Stage A's decision from the rounded determinant and the largest coordinate difference m.
inline std::optional<Sign> insphere_filter_decision(double det, double m) noexcept {
    const double m2 = m * m;
    const double eps = insphere_filter_eps * m2 * m2 * m;
    if (det > eps || -det > eps) {
        if (m >= insphere_filter_min && m <= insphere_filter_max) {
            return det > 0.0 ? Sign::Positive : Sign::Negative;
        }
    }
    return std::nullopt;
}

/// Stage A in scalar form, the evaluation order modelled in proofs/gappa/insphere_filter.g
/// (insphere_filter's form without SSE2, and the reference its SSE2 form is tested against).
inline std::optional<Sign> insphere_filter_scalar(const double* a, const double* b, const double* c,
                                                  const double* d, const double* e) noexcept {
    // The same rounded determinant as insphere_fast (the differences are recomputed for their
    // largest magnitude: the same exact subtractions, which the compiler shares once inlined).
    const double det = insphere_fast(a, b, c, d, e);
    double m = 0.0;
    for (const double* p : {a, b, c, d}) {
        for (int k = 0; k < 3; ++k) m = std::max(m, std::fabs(p[k] - e[k]));
    }
    return insphere_filter_decision(det, m);
}

/// Stage A; the evaluation order is the one modelled in proofs/gappa/insphere_filter.g.
///
/// With SSE2 (every x86-64) the same operations two at a time, rows paired in the lanes: each
/// value is the same rounded sum, difference or product of the same operands as in the scalar
/// form below (x - y as x + (-y) where a lane pair needs one subtraction and one addition: IEEE
/// defines the difference so, bit for bit but for a NaN's sign, which no comparison sees), and the
/// largest magnitude is taken in another order (exact, and no difference of finite inputs is NaN; a
/// NaN input makes det NaN, refused either way). So the same signs and the same refusals; the
/// filter was a tenth of 3D refinement's instructions (4.5 10^6 calls on the wing at V = 4.46e-5).
inline std::optional<Sign> insphere_filter(const double* a, const double* b, const double* c,
                                           const double* d, const double* e) noexcept {
#if defined(__SSE2__)
    const __m128d ex = _mm_set1_pd(e[0]), ey = _mm_set1_pd(e[1]), ez = _mm_set1_pd(e[2]);
    const __m128d x01 = _mm_sub_pd(_mm_set_pd(b[0], a[0]), ex);  // (aex, bex)
    const __m128d x23 = _mm_sub_pd(_mm_set_pd(d[0], c[0]), ex);  // (cex, dex)
    const __m128d y01 = _mm_sub_pd(_mm_set_pd(b[1], a[1]), ey);
    const __m128d y23 = _mm_sub_pd(_mm_set_pd(d[1], c[1]), ey);
    const __m128d z01 = _mm_sub_pd(_mm_set_pd(b[2], a[2]), ez);
    const __m128d z23 = _mm_sub_pd(_mm_set_pd(d[2], c[2]), ez);
    const __m128d xac = _mm_unpacklo_pd(x01, x23), xbd = _mm_unpackhi_pd(x01, x23);
    const __m128d yac = _mm_unpacklo_pd(y01, y23), ybd = _mm_unpackhi_pd(y01, y23);
    const __m128d zac = _mm_unpacklo_pd(z01, z23), zbd = _mm_unpackhi_pd(z01, z23);
    const __m128d xca = _mm_shuffle_pd(xac, xac, 1), yca = _mm_shuffle_pd(yac, yac, 1);
    const __m128d zca = _mm_shuffle_pd(zac, zac, 1), zdb = _mm_shuffle_pd(zbd, zbd, 1);
    // (ab, cd), (bc, da), (ac, bd).
    const __m128d ab_cd = _mm_sub_pd(_mm_mul_pd(xac, ybd), _mm_mul_pd(xbd, yac));
    const __m128d bc_da = _mm_sub_pd(_mm_mul_pd(xbd, yca), _mm_mul_pd(xca, ybd));
    const __m128d ac_bd = _mm_sub_pd(_mm_mul_pd(x01, y23), _mm_mul_pd(x23, y01));
    // The first lane's middle term is subtracted (abc, bcd), the second's added (cda, dab).
    const __m128d negate_first = _mm_set_pd(0.0, -0.0);
    const __m128d ac_ac = _mm_unpacklo_pd(ac_bd, ac_bd), bd_bd = _mm_unpackhi_pd(ac_bd, ac_bd);
    // (abc, cda) = (aez bc - bez ac + cez ab, cez da + dez ac + aez cd).
    const __m128d abc_cda = _mm_add_pd(
        _mm_add_pd(_mm_mul_pd(zac, bc_da), _mm_xor_pd(_mm_mul_pd(zbd, ac_ac), negate_first)),
        _mm_mul_pd(zca, ab_cd));
    // (bcd, dab) = (bez cd - cez bd + dez bc, dez ab + aez bd + bez da).
    const __m128d bcd_dab = _mm_add_pd(_mm_add_pd(_mm_mul_pd(zbd, _mm_shuffle_pd(ab_cd, ab_cd, 1)),
                                                  _mm_xor_pd(_mm_mul_pd(zca, bd_bd), negate_first)),
                                       _mm_mul_pd(zdb, bc_da));
    // (alift, blift), (clift, dlift).
    const __m128d lift01 =
        _mm_add_pd(_mm_add_pd(_mm_mul_pd(x01, x01), _mm_mul_pd(y01, y01)), _mm_mul_pd(z01, z01));
    const __m128d lift23 =
        _mm_add_pd(_mm_add_pd(_mm_mul_pd(x23, x23), _mm_mul_pd(y23, y23)), _mm_mul_pd(z23, z23));
    // (dlift abc - clift dab, blift cda - alift bcd), then their sum.
    const __m128d halves = _mm_sub_pd(
        _mm_mul_pd(_mm_unpackhi_pd(lift23, lift01), abc_cda),
        _mm_mul_pd(_mm_unpacklo_pd(lift23, lift01), _mm_shuffle_pd(bcd_dab, bcd_dab, 1)));
    const double det = _mm_cvtsd_f64(halves) + _mm_cvtsd_f64(_mm_unpackhi_pd(halves, halves));
    const __m128d magnitude = _mm_castsi128_pd(_mm_set1_epi64x(0x7fffffffffffffffLL));
    const __m128d largest =
        _mm_max_pd(_mm_max_pd(_mm_and_pd(x01, magnitude), _mm_and_pd(x23, magnitude)),
                   _mm_max_pd(_mm_max_pd(_mm_and_pd(y01, magnitude), _mm_and_pd(y23, magnitude)),
                              _mm_max_pd(_mm_and_pd(z01, magnitude), _mm_and_pd(z23, magnitude))));
    const double m =
        std::max(_mm_cvtsd_f64(largest), _mm_cvtsd_f64(_mm_unpackhi_pd(largest, largest)));
    return insphere_filter_decision(det, m);
#else
    return insphere_filter_scalar(a, b, c, d, e);
#endif
}

/// Stage A of two tests with the same fifth point: insphere_filter_scalar(a0, b0, c0, d0, e) and
/// insphere_filter_scalar(a1, b1, c1, d1, e), bit for bit.
///
/// With SSE2 each lane computes one test's scalar form: every value is the same rounded
/// difference, product or sum of the same operands in the same order as in insphere_fast (no
/// contraction: -ffp-contract=off), so the proof of proofs/gappa/insphere_filter.g holds lane by
/// lane. The 3D cavity search tests two or three neighbours of a tetrahedron at once: as many
/// instructions per test as insphere_filter (whose lanes pair the rows of one test), counting
/// the third test paired with itself, but the two tests' chains of dependent operations run side
/// by side (Bowyer-Watson 7% faster at 10^6 uniform points).
inline std::array<std::optional<Sign>, 2> insphere_filter_pair(const double* a0, const double* b0,
                                                               const double* c0, const double* d0,
                                                               const double* a1, const double* b1,
                                                               const double* c1, const double* d1,
                                                               const double* e) noexcept {
#if defined(__SSE2__)
    const __m128d ex = _mm_set1_pd(e[0]), ey = _mm_set1_pd(e[1]), ez = _mm_set1_pd(e[2]);
    // Lane 0 holds the first test, lane 1 the second.
    const auto diff = [](const double* p0, const double* p1, int k, __m128d ek) {
        return _mm_sub_pd(_mm_set_pd(p1[k], p0[k]), ek);
    };
    const __m128d aex = diff(a0, a1, 0, ex), aey = diff(a0, a1, 1, ey), aez = diff(a0, a1, 2, ez);
    const __m128d bex = diff(b0, b1, 0, ex), bey = diff(b0, b1, 1, ey), bez = diff(b0, b1, 2, ez);
    const __m128d cex = diff(c0, c1, 0, ex), cey = diff(c0, c1, 1, ey), cez = diff(c0, c1, 2, ez);
    const __m128d dex = diff(d0, d1, 0, ex), dey = diff(d0, d1, 1, ey), dez = diff(d0, d1, 2, ez);
    const auto mul = [](__m128d x, __m128d y) { return _mm_mul_pd(x, y); };
    const auto minor = [&](__m128d px, __m128d qy, __m128d qx, __m128d py) {
        return _mm_sub_pd(mul(px, qy), mul(qx, py));
    };
    // insphere_fast's terms, in its order.
    const __m128d ab = minor(aex, bey, bex, aey), bc = minor(bex, cey, cex, bey);
    const __m128d cd = minor(cex, dey, dex, cey), da = minor(dex, aey, aex, dey);
    const __m128d ac = minor(aex, cey, cex, aey), bd = minor(bex, dey, dex, bey);
    const __m128d abc = _mm_add_pd(_mm_sub_pd(mul(aez, bc), mul(bez, ac)), mul(cez, ab));
    const __m128d bcd = _mm_add_pd(_mm_sub_pd(mul(bez, cd), mul(cez, bd)), mul(dez, bc));
    const __m128d cda = _mm_add_pd(_mm_add_pd(mul(cez, da), mul(dez, ac)), mul(aez, cd));
    const __m128d dab = _mm_add_pd(_mm_add_pd(mul(dez, ab), mul(aez, bd)), mul(bez, da));
    const auto lift = [&](__m128d x, __m128d y, __m128d z) {
        return _mm_add_pd(_mm_add_pd(mul(x, x), mul(y, y)), mul(z, z));
    };
    const __m128d alift = lift(aex, aey, aez), blift = lift(bex, bey, bez);
    const __m128d clift = lift(cex, cey, cez), dlift = lift(dex, dey, dez);
    const __m128d det = _mm_add_pd(_mm_sub_pd(mul(dlift, abc), mul(clift, dab)),
                                   _mm_sub_pd(mul(blift, cda), mul(alift, bcd)));
    // The largest magnitude (max is exact: any order gives it).
    const __m128d magnitude = _mm_castsi128_pd(_mm_set1_epi64x(0x7fffffffffffffffLL));
    const auto abs_max = [&](__m128d x, __m128d y, __m128d z) {
        return _mm_max_pd(_mm_max_pd(_mm_and_pd(x, magnitude), _mm_and_pd(y, magnitude)),
                          _mm_and_pd(z, magnitude));
    };
    const __m128d m = _mm_max_pd(_mm_max_pd(abs_max(aex, aey, aez), abs_max(bex, bey, bez)),
                                 _mm_max_pd(abs_max(cex, cey, cez), abs_max(dex, dey, dez)));
    // insphere_filter_decision lane by lane: eps = ((insphere_filter_eps m2) m2) m.
    const __m128d m2 = mul(m, m);
    const __m128d eps = mul(mul(mul(_mm_set1_pd(insphere_filter_eps), m2), m2), m);
    const __m128d decided = _mm_and_pd(
        _mm_or_pd(_mm_cmpgt_pd(det, eps), _mm_cmpgt_pd(_mm_xor_pd(det, _mm_set1_pd(-0.0)), eps)),
        _mm_and_pd(_mm_cmpge_pd(m, _mm_set1_pd(insphere_filter_min)),
                   _mm_cmple_pd(m, _mm_set1_pd(insphere_filter_max))));
    const int decided_bits = _mm_movemask_pd(decided);
    const int positive_bits = _mm_movemask_pd(_mm_cmpgt_pd(det, _mm_setzero_pd()));
    std::array<std::optional<Sign>, 2> out;
    for (int lane = 0; lane < 2; ++lane) {
        if ((decided_bits >> lane) & 1) {
            out[static_cast<std::size_t>(lane)] =
                (positive_bits >> lane) & 1 ? Sign::Positive : Sign::Negative;
        }
    }
    return out;
#else
    return {insphere_filter_scalar(a0, b0, c0, d0, e), insphere_filter_scalar(a1, b1, c1, d1, e)};
#endif
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
