// SPDX-License-Identifier: MIT
// Two-term (double-double) evaluation of polynomials in doubles with a-priori error bounds:
// each operation keeps its value as hi + lo, hi from an error-free transformation and lo the
// rounded sum of the tails [Dekker71; Ogita, Rump, Oishi 2005, Dot2]. Used by incircle and
// insphere to decide the determinant of the rounded differences, and by in_ellipse the
// determinant of the exact differences (each a two_diff pair), to about u^2 (u = 2^-53) of its
// permanent, before any expansion. The bounds (E, H, L below, in units of the permanent P of the
// value: |hi + lo - X| <= E u^2 P, |hi| <= H P, |lo| <= L u P) are derived in
// proofs/invariants/filters.md, "Two-term stage" (by hand; the instances used by incircle,
// insphere and in_ellipse are re-proved, tighter, by proofs/gappa/two_term_*.g); they need no
// underflow and no overflow, which the expansion-safe range check guarantees. Internal to
// predicates/.
#pragma once

#include "predicates/expansion.hpp"

namespace exactmesh::predicates::detail {

/// hi + lo approximates a value; hi is not the rounded value (lo is not normalised).
struct TwoTerm {
    double hi;
    double lo;
};

/// a * b - c * d: E = 3, H = 1, L = 2 (lemma A).
inline TwoTerm two_term_diff_of_products(double a, double b, double c, double d) noexcept {
    double p, p_tail, q, q_tail, hi, s;
    two_product(a, b, p, p_tail);
    two_product(c, d, q, q_tail);
    two_diff(p, q, hi, s);
    return {hi, s + (p_tail - q_tail)};
}

/// a^2 + b^2: E = 3, H = 1, L = 2 (lemma A).
inline TwoTerm two_term_sum_of_squares(double a, double b) noexcept {
    double p, p_tail, q, q_tail, hi, s;
    two_product(a, a, p, p_tail);
    two_product(b, b, q, q_tail);
    two_sum(p, q, hi, s);
    return {hi, s + (p_tail + q_tail)};
}

/// a^2 + b^2 + c^2: E = 7, H = 1, L = 3 (lemma A').
inline TwoTerm two_term_sum_of_squares(double a, double b, double c) noexcept {
    double p, p_tail, q, q_tail, r, r_tail, pq, s1, hi, s2;
    two_product(a, a, p, p_tail);
    two_product(b, b, q, q_tail);
    two_product(c, c, r, r_tail);
    two_sum(p, q, pq, s1);
    two_sum(pq, r, hi, s2);
    return {hi, (s1 + s2) + ((p_tail + q_tail) + r_tail)};
}

/// z * y (lemma B).
inline TwoTerm two_term_scale(const TwoTerm& y, double z) noexcept {
    double hi, e;
    two_product(z, y.hi, hi, e);
    return {hi, e + z * y.lo};
}

/// y * z, dropping y.lo * z.lo (lemma C).
inline TwoTerm two_term_product(const TwoTerm& y, const TwoTerm& z) noexcept {
    double hi, e;
    two_product(y.hi, z.hi, hi, e);
    return {hi, e + (y.hi * z.lo + y.lo * z.hi)};
}

/// x + y (lemma D, n = 2).
inline TwoTerm two_term_sum(const TwoTerm& x, const TwoTerm& y) noexcept {
    double hi, e;
    two_sum(x.hi, y.hi, hi, e);
    return {hi, (x.lo + y.lo) + e};
}

/// x + y + z (lemma D, n = 3).
inline TwoTerm two_term_sum(const TwoTerm& x, const TwoTerm& y, const TwoTerm& z) noexcept {
    double s, e1, hi, e2;
    two_sum(x.hi, y.hi, s, e1);
    two_sum(s, z.hi, hi, e2);
    return {hi, ((x.lo + y.lo) + z.lo) + (e1 + e2)};
}

/// w + x + y + z (lemma D, n = 4).
inline TwoTerm two_term_sum(const TwoTerm& w, const TwoTerm& x, const TwoTerm& y,
                            const TwoTerm& z) noexcept {
    double s1, e1, s2, e2, hi, e3;
    two_sum(w.hi, x.hi, s1, e1);
    two_sum(y.hi, z.hi, s2, e2);
    two_sum(s1, s2, hi, e3);
    return {hi, ((w.lo + x.lo) + (y.lo + z.lo)) + ((e1 + e2) + e3)};
}

inline TwoTerm operator-(const TwoTerm& x) noexcept {
    return {-x.hi, -x.lo};
}

/// incircle's stage B, det [p-d, |p-d|^2] over the rounded differences
/// diff = (adx, ady, bdx, bdy, cdx, cdy), along the lift column: within 42.05 u^2 of its permanent
/// (Gappa).
inline TwoTerm incircle_stage_b(const double* diff) noexcept {
    const double adx = diff[0], ady = diff[1], bdx = diff[2], bdy = diff[3];
    const double cdx = diff[4], cdy = diff[5];
    return two_term_sum(two_term_product(two_term_sum_of_squares(adx, ady),
                                         two_term_diff_of_products(bdx, cdy, cdx, bdy)),
                        two_term_product(two_term_sum_of_squares(bdx, bdy),
                                         two_term_diff_of_products(cdx, ady, adx, cdy)),
                        two_term_product(two_term_sum_of_squares(cdx, cdy),
                                         two_term_diff_of_products(adx, bdy, bdx, ady)));
}

/// insphere's stage B, det [p-e, |p-e|^2] over the rounded differences
/// diff = (aex, aey, aez, bex, ..., dez), as (dlift abc - clift dab) + (blift cda - alift bcd)
/// with the 3x3 minors along z (insphere_fast's order): within 100.18 u^2 of its permanent
/// (Gappa).
inline TwoTerm insphere_stage_b(const double* diff) noexcept {
    const double aex = diff[0], aey = diff[1], aez = diff[2], bex = diff[3], bey = diff[4];
    const double bez = diff[5], cex = diff[6], cey = diff[7], cez = diff[8], dex = diff[9];
    const double dey = diff[10], dez = diff[11];
    const TwoTerm ab = two_term_diff_of_products(aex, bey, bex, aey);
    const TwoTerm bc = two_term_diff_of_products(bex, cey, cex, bey);
    const TwoTerm cd = two_term_diff_of_products(cex, dey, dex, cey);
    const TwoTerm da = two_term_diff_of_products(dex, aey, aex, dey);
    const TwoTerm ac = two_term_diff_of_products(aex, cey, cex, aey);
    const TwoTerm bd = two_term_diff_of_products(bex, dey, dex, bey);
    const TwoTerm abc =
        two_term_sum(two_term_scale(bc, aez), two_term_scale(-ac, bez), two_term_scale(ab, cez));
    const TwoTerm bcd =
        two_term_sum(two_term_scale(cd, bez), two_term_scale(-bd, cez), two_term_scale(bc, dez));
    const TwoTerm cda =
        two_term_sum(two_term_scale(da, cez), two_term_scale(ac, dez), two_term_scale(cd, aez));
    const TwoTerm dab =
        two_term_sum(two_term_scale(ab, dez), two_term_scale(bd, aez), two_term_scale(da, bez));
    return two_term_sum(two_term_product(two_term_sum_of_squares(dex, dey, dez), abc),
                        -two_term_product(two_term_sum_of_squares(cex, cey, cez), dab),
                        two_term_product(two_term_sum_of_squares(bex, bey, bez), cda),
                        -two_term_product(two_term_sum_of_squares(aex, aey, aez), bcd));
}

/// in_ellipse's two-term stage: det [p-d, q(p-d)], q(v) = m11 vx^2 + m12x2 vx vy + m22 vy^2
/// (m12x2 = 2 M12), over the EXACT differences diff = (adx, ady, bdx, bdy, cdx, cdy), each the
/// pair (hi, lo) of two_diff, along the lift column as in_ellipse_fast: within 138.32 u^2 of its
/// permanent in the exact differences (Gappa, proofs/gappa/two_term_in_ellipse.g). Every lift
/// monomial is a product of two pairs scaled by its metric entry, every minor the sum of two
/// products of pairs.
inline TwoTerm in_ellipse_two_term(const TwoTerm* diff, double m11, double m12x2,
                                   double m22) noexcept {
    const auto lift = [&](const TwoTerm& x, const TwoTerm& y) {
        return two_term_sum(two_term_scale(two_term_product(x, x), m11),
                            two_term_scale(two_term_product(x, y), m12x2),
                            two_term_scale(two_term_product(y, y), m22));
    };
    // px qy - qx py
    const auto minor = [](const TwoTerm& px, const TwoTerm& py, const TwoTerm& qx,
                          const TwoTerm& qy) {
        return two_term_sum(two_term_product(px, qy), -two_term_product(qx, py));
    };
    const TwoTerm &adx = diff[0], &ady = diff[1], &bdx = diff[2], &bdy = diff[3];
    const TwoTerm &cdx = diff[4], &cdy = diff[5];
    return two_term_sum(two_term_product(lift(adx, ady), minor(bdx, bdy, cdx, cdy)),
                        two_term_product(lift(bdx, bdy), minor(cdx, cdy, adx, ady)),
                        two_term_product(lift(cdx, cdy), minor(adx, ady, bdx, bdy)));
}

}  // namespace exactmesh::predicates::detail
