// SPDX-License-Identifier: MIT
// Exact stages of in_ellipse (in_ellipse.hpp). First the determinant of the exact differences
// (each kept as its two_diff pair) in two terms, certified by its Gappa-proven error bound
// (proofs/gappa/two_term_in_ellipse.g); then expansions: q(v) = M11 vx^2 + 2 M12 vx vy + M22 vy^2
// is an exact expansion of at most 12 components (three products of three doubles); the
// determinant is expanded along the lift column, as incircle's stages are. Any symmetric M is
// accepted: the determinant's sign is exact for it; the geometry needs M positive definite.
#include "predicates/in_ellipse.hpp"

#include <cmath>
#include <optional>

#include "predicates/adaptive_bounds.hpp"
#include "predicates/exact_range.hpp"
#include "predicates/expansion.hpp"
#include "predicates/gmp_fallback.hpp"
#include "predicates/two_term.hpp"

namespace exactmesh::predicates {

namespace {

// Degree of every monomial of det [x y q(p) 1] in the doubles it multiplies: q is M times two
// coordinates, its cofactor two more coordinates.
constexpr int kDegree = 5;

/// px * qy - qx * py exactly.
Expansion<4> minor_xy(const double* p, const double* q) noexcept {
    return exact_product(p[0], q[1]) - exact_product(q[0], p[1]);
}

/// q(v) = v^T M v exactly, compressed (it is multiplied next).
Expansion<12> metric_lift_exact(const double* v, const double* m) noexcept {
    return compressed(
        (scale(exact_product(v[0], v[0]), m[0]) + scale(exact_product(v[0], v[1]), 2.0 * m[1])) +
        scale(exact_product(v[1], v[1]), m[2]));
}

/// Raw det [x y 1] over rows p, q, r, compressed because it is multiplied next.
Expansion<12> det3_xy1(const double* p, const double* q, const double* r) noexcept {
    return compressed(minor_xy(p, q) + minor_xy(q, r) + minor_xy(r, p));
}

/// det [p-d, q(p-d)] over the exact differences diff = (adx, ady, bdx, bdy, cdx, cdy).
[[gnu::noinline]] Sign exact_differences_sign(const double* diff, const double* m) noexcept {
    const double* ad = diff;
    const double* bd = diff + 2;
    const double* cd = diff + 4;
    return ((product(metric_lift_exact(ad, m), compressed(minor_xy(bd, cd))) -
             product(metric_lift_exact(bd, m), compressed(minor_xy(ad, cd)))) +
            product(metric_lift_exact(cd, m), compressed(minor_xy(ad, bd))))
        .sign();
}

/// det [x y q(p) 1] over rows a, b, c, d, expanded along the lift column. Equal to the difference
/// form: q(p - d) = q(p) - 2 p^T M d + q(d), and the last two terms are combinations of the
/// x, y and 1 columns.
[[gnu::noinline]] Sign raw_expansion_sign(const double* a, const double* b, const double* c,
                                          const double* d, const double* m) noexcept {
    return ((product(metric_lift_exact(a, m), det3_xy1(b, c, d)) -
             product(metric_lift_exact(b, m), det3_xy1(a, c, d))) +
            (product(metric_lift_exact(c, m), det3_xy1(a, b, d)) -
             product(metric_lift_exact(d, m), det3_xy1(a, b, c))))
        .sign();
}

/// The two-term stage: the sign of det [p-d, q(p-d)] over the exact differences
/// diff[i] = (hi, lo) when its double-double value certainly exceeds its error, else nullopt.
/// |hi + lo - Det| <= 138.32 u^2 P, P the permanent in the exact differences
/// (proofs/gappa/two_term_in_ellipse.g); the permanent computed from the rounded differences,
/// times in_ellipse_errbound_two_term, is at least twice that (the same script, its last goal;
/// proofs/invariants/filters.md, "Two-term stage of in_ellipse").
std::optional<Sign> two_term_sign(const detail::TwoTerm* diff, const double* m) noexcept {
    const double m11 = m[0], m12x2 = 2.0 * m[1], m22 = m[2];
    const detail::TwoTerm det = detail::in_ellipse_two_term(diff, m11, m12x2, m22);
    // The permanent, in the order the proof counts: 4 roundings in a lift monomial, 2 in a minor
    // monomial, 1 for their product and 2 for the sum of the three terms.
    const double am11 = std::fabs(m11), am12x2 = std::fabs(m12x2), am22 = std::fabs(m22);
    const auto lift = [&](double x, double y) {
        return (am11 * (x * x) + am12x2 * std::fabs(x * y)) + am22 * (y * y);
    };
    const auto minor = [](double px, double py, double qx, double qy) {
        return std::fabs(px * qy) + std::fabs(qx * py);
    };
    const double adx = diff[0].hi, ady = diff[1].hi, bdx = diff[2].hi, bdy = diff[3].hi;
    const double cdx = diff[4].hi, cdy = diff[5].hi;
    const double permanent =
        (lift(adx, ady) * minor(bdx, bdy, cdx, cdy) + lift(bdx, bdy) * minor(cdx, cdy, adx, ady)) +
        lift(cdx, cdy) * minor(adx, ady, bdx, bdy);
    // K u^2 is a power of two: the product is exact unless it falls below the normal range,
    // where a rounded-down bound would no longer be one (certified() refuses it, and the
    // expansions decide).
    const double bound = adaptive::in_ellipse_errbound_two_term * permanent;
    const double value = det.hi + det.lo;
    if (adaptive::certified(value, bound)) return sign_of(value);
    return std::nullopt;
}

/// The stages after the filter, for coordinates and M that are expansion-safe together: the
/// two-term stage, then the expansions.
Sign expansion_sign(const double* a, const double* b, const double* c, const double* d,
                    const double* m) noexcept {
    detail::TwoTerm pairs[6];
    const double* rows[3] = {a, b, c};
    bool exact = true;
    for (int r = 0; r < 3; ++r) {
        for (int k = 0; k < 2; ++k) {
            detail::TwoTerm& p = pairs[2 * r + k];
            two_diff(rows[r][k], d[k], p.hi, p.lo);
            exact = exact && p.lo == 0.0;
        }
    }
    if (const auto s = two_term_sign(pairs, m)) {
        EM_STAT(in_ellipse, adaptive);
        return *s;
    }
    if (exact) {
        EM_STAT(in_ellipse, exact_differences);
        const double diff[6] = {pairs[0].hi, pairs[1].hi, pairs[2].hi,
                                pairs[3].hi, pairs[4].hi, pairs[5].hi};
        return exact_differences_sign(diff, m);
    }
    EM_STAT(in_ellipse, expansion);
    return raw_expansion_sign(a, b, c, d, m);
}

}  // namespace

Sign in_ellipse_exact(const double* a, const double* b, const double* c, const double* d,
                      const double* m) {
    detail::require_finite("in_ellipse",
                           {a[0], a[1], b[0], b[1], c[0], c[1], d[0], d[1], m[0], m[1], m[2]});
    if (detail::expansion_safe(
            kDegree, {a[0], a[1], b[0], b[1], c[0], c[1], d[0], d[1], m[0], m[1], m[2]})) {
        return expansion_sign(a, b, c, d, m);
    }
    // The determinant is homogeneous of degree 4 in the coordinates and 1 in M: each group scaled
    // by its own power of two keeps the sign. Both groups end with their largest magnitude in
    // [1, 2) and every bit kept, so together they are expansion-safe.
    double s[8], ms[3];
    if (detail::rescale_into_safe_range(kDegree, {a[0], a[1], b[0], b[1], c[0], c[1], d[0], d[1]},
                                        s) &&
        detail::rescale_into_safe_range(kDegree, {m[0], m[1], m[2]}, ms)) {
        EM_STAT(in_ellipse, rescaled);
        if (const auto sign = in_ellipse_filter(s, s + 2, s + 4, s + 6, ms)) {
            EM_STAT(in_ellipse, filter);
            return *sign;
        }
        return expansion_sign(s, s + 2, s + 4, s + 6, ms);
    }
    EM_STAT(in_ellipse, gmp);
    return in_ellipse_gmp(a, b, c, d, m);
}

}  // namespace exactmesh::predicates
