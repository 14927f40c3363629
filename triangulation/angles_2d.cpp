// SPDX-License-Identifier: MIT
// Exact angle and length comparisons (see angles_2d.hpp). Filter bounds, by the standard
// forward error analysis of sums of products [Higham, "Accuracy and Stability of Numerical
// Algorithms", §3.1]: with u = 2^-53 and every operation rounding to nearest with a relative
// error delta, |delta| <= u (no overflow, no underflow: see the window below), the computed value
// of a polynomial is the sum of its monomials, each multiplied by at most k factors (1 + delta),
// so |fl(E) - E| <= gamma_k * P, where P is the sum of the monomials' absolute values and
// gamma_k = k u / (1 - k u). P computed in floating point from the absolute differences has
// nonnegative terms only, so P <= fl(P) / (1 - u)^k.
//  - Angles: E = dot_b cross_a - dot_a cross_b. Each monomial is a product of four coordinate
//    differences and meets k = 10 roundings (4 differences, 1 product and 1 sum inside dot or
//    cross, the product dot * cross, the final difference): gamma_10 / (1 - u)^10 < 11u, and the
//    filter uses 16u = 2^-49.
//  - Lengths: E = |p1 - q1|^2 - |p2 - q2|^2, k = 5 (2 for the squared difference, the product,
//    the sum, the final difference): gamma_5 / (1 - u)^5 < 6u; the filter uses 8u = 2^-50.
//  - Dot products: E = (p - o) . (q - o), k = 3 (the difference, the product, the sum):
//    gamma_3 / (1 - u)^3 < 4u; the filter uses 8u = 2^-50 too.
// The window: every nonzero computed difference has magnitude in [2^-200, 2^200]. A computed
// difference of doubles is zero only when the exact one is (gradual underflow), and then every
// nonzero monomial lies in [2^-800, 2^803] and every partial sum is a nonzero multiple of an
// ulp above 2^-905 or zero, so no operation underflows or overflows. The same window keeps the
// expansion stage exact (every two_product's low part is a multiple of 2^-1012, every
// Veltkamp split far below 2^995). Outside it, or when a difference is not exact, GMP decides.
#include "triangulation/angles_2d.hpp"

#include <cmath>

#include "predicates/exact_reference.hpp"
#include "predicates/expansion.hpp"

namespace exactmesh::triangulation {

namespace {

using predicates::Sign;

constexpr double kWindowLow = 0x1p-200;
constexpr double kWindowHigh = 0x1p200;
constexpr double kAngleFilter = 0x1p-49;
constexpr double kLengthFilter = 0x1p-50;
constexpr double kDotFilter = 0x1p-50;

bool in_window(double d) {
    const double a = std::fabs(d);
    return a == 0.0 || (a >= kWindowLow && a <= kWindowHigh);
}

/// p - o per coordinate, and whether both differences are exact doubles.
struct Difference {
    double x, y;
    bool exact;
};

Difference difference(const double* p, const double* o) {
    double x, y, x_tail, y_tail;
    predicates::two_diff(p[0], o[0], x, x_tail);
    predicates::two_diff(p[1], o[1], y, y_tail);
    return {x, y, x_tail == 0.0 && y_tail == 0.0};
}

Sign compare_angles_gmp(const Corner& a, const Corner& b) {
    using predicates::reference::exact;
    auto dot_cross = [](const Corner& c, mpq_class& dot, mpq_class& cross) {
        const mpq_class ux = exact(c.p[0]) - exact(c.o[0]), uy = exact(c.p[1]) - exact(c.o[1]);
        const mpq_class vx = exact(c.q[0]) - exact(c.o[0]), vy = exact(c.q[1]) - exact(c.o[1]);
        dot = ux * vx + uy * vy;
        cross = ux * vy - uy * vx;
    };
    mpq_class dot_a, cross_a, dot_b, cross_b;
    dot_cross(a, dot_a, cross_a);
    dot_cross(b, dot_b, cross_b);
    return predicates::reference::sign_of(dot_b * cross_a - dot_a * cross_b);
}

Sign compare_lengths_gmp(const double* p1, const double* q1, const double* p2, const double* q2) {
    using predicates::reference::exact;
    const mpq_class x1 = exact(p1[0]) - exact(q1[0]), y1 = exact(p1[1]) - exact(q1[1]);
    const mpq_class x2 = exact(p2[0]) - exact(q2[0]), y2 = exact(p2[1]) - exact(q2[1]);
    return predicates::reference::sign_of(x1 * x1 + y1 * y1 - (x2 * x2 + y2 * y2));
}

Sign corner_dot_sign_gmp(const double* o, const double* p, const double* q) {
    using predicates::reference::exact;
    const mpq_class ux = exact(p[0]) - exact(o[0]), uy = exact(p[1]) - exact(o[1]);
    const mpq_class vx = exact(q[0]) - exact(o[0]), vy = exact(q[1]) - exact(o[1]);
    return predicates::reference::sign_of(ux * vx + uy * vy);
}

}  // namespace

Sign corner_dot_sign(const double* o, const double* p, const double* q) {
    const Difference u = difference(p, o), v = difference(q, o);
    if (!(in_window(u.x) && in_window(u.y) && in_window(v.x) && in_window(v.y))) {
        return corner_dot_sign_gmp(o, p, q);
    }
    const double xx = u.x * v.x, yy = u.y * v.y;
    const double e = xx + yy;
    if (std::fabs(e) > kDotFilter * (std::fabs(xx) + std::fabs(yy))) return predicates::sign_of(e);
    if (!(u.exact && v.exact)) return corner_dot_sign_gmp(o, p, q);
    using predicates::exact_product;
    return (exact_product(u.x, v.x) + exact_product(u.y, v.y)).sign();
}

Sign direction_dot_sign(const double* p, const double* q, const double* a, const double* b) {
    // The dot product's filter and exact stage with u = q - p, v = b - a (same error analysis).
    const Difference u = difference(q, p), v = difference(b, a);
    if (!(in_window(u.x) && in_window(u.y) && in_window(v.x) && in_window(v.y)) ||
        !(u.exact && v.exact)) {
        const double xx = u.x * v.x, yy = u.y * v.y;
        const double e = xx + yy;
        if (in_window(u.x) && in_window(u.y) && in_window(v.x) && in_window(v.y) &&
            std::fabs(e) > kDotFilter * (std::fabs(xx) + std::fabs(yy))) {
            return predicates::sign_of(e);
        }
        // Outside the window: long double (64-bit significand, exponents to 2^16383), where no
        // difference or product of doubles' differences overflows or underflows, and each of the
        // two products carries at most 3 roundings of 2^-64 (difference, difference, product)
        // and the sum one more: a margin of 2^-60 of |xx| + |yy| decides (spans 1e-225..1e212
        // spent a minute in GMP here in conforming bends); else GMP.
        using LD = long double;
        const LD lux = static_cast<LD>(q[0]) - p[0], luy = static_cast<LD>(q[1]) - p[1];
        const LD lvx = static_cast<LD>(b[0]) - a[0], lvy = static_cast<LD>(b[1]) - a[1];
        const LD lxx = lux * lvx, lyy = luy * lvy, le = lxx + lyy;
        if (std::fabs(le) > std::ldexp(std::fabs(lxx) + std::fabs(lyy), -60))
            return le > 0 ? Sign::Positive : Sign::Negative;
        using predicates::reference::exact;
        const mpq_class ux = exact(q[0]) - exact(p[0]), uy = exact(q[1]) - exact(p[1]);
        const mpq_class vx = exact(b[0]) - exact(a[0]), vy = exact(b[1]) - exact(a[1]);
        return predicates::reference::sign_of(ux * vx + uy * vy);
    }
    const double xx = u.x * v.x, yy = u.y * v.y;
    const double e = xx + yy;
    if (std::fabs(e) > kDotFilter * (std::fabs(xx) + std::fabs(yy))) return predicates::sign_of(e);
    using predicates::exact_product;
    return (exact_product(u.x, v.x) + exact_product(u.y, v.y)).sign();
}

Sign compare_angles(const Corner& a, const Corner& b) {
    const Difference ua = difference(a.p, a.o), va = difference(a.q, a.o);
    const Difference ub = difference(b.p, b.o), vb = difference(b.q, b.o);
    const bool window = in_window(ua.x) && in_window(ua.y) && in_window(va.x) && in_window(va.y) &&
                        in_window(ub.x) && in_window(ub.y) && in_window(vb.x) && in_window(vb.y);
    if (!window) return compare_angles_gmp(a, b);

    const double dot_a = ua.x * va.x + ua.y * va.y, cross_a = ua.x * va.y - ua.y * va.x;
    const double dot_b = ub.x * vb.x + ub.y * vb.y, cross_b = ub.x * vb.y - ub.y * vb.x;
    const double e = dot_b * cross_a - dot_a * cross_b;
    const double dot_a_abs = std::fabs(ua.x * va.x) + std::fabs(ua.y * va.y);
    const double cross_a_abs = std::fabs(ua.x * va.y) + std::fabs(ua.y * va.x);
    const double dot_b_abs = std::fabs(ub.x * vb.x) + std::fabs(ub.y * vb.y);
    const double cross_b_abs = std::fabs(ub.x * vb.y) + std::fabs(ub.y * vb.x);
    const double permanent = dot_b_abs * cross_a_abs + dot_a_abs * cross_b_abs;
    if (std::fabs(e) > kAngleFilter * permanent) return predicates::sign_of(e);

    if (!(ua.exact && va.exact && ub.exact && vb.exact)) return compare_angles_gmp(a, b);
    using predicates::exact_product;
    const auto dot_a_exact = exact_product(ua.x, va.x) + exact_product(ua.y, va.y);
    const auto cross_a_exact = exact_product(ua.x, va.y) - exact_product(ua.y, va.x);
    const auto dot_b_exact = exact_product(ub.x, vb.x) + exact_product(ub.y, vb.y);
    const auto cross_b_exact = exact_product(ub.x, vb.y) - exact_product(ub.y, vb.x);
    return (predicates::product(dot_b_exact, cross_a_exact) -
            predicates::product(dot_a_exact, cross_b_exact))
        .sign();
}

Sign compare_lengths(const double* p1, const double* q1, const double* p2, const double* q2) {
    const Difference d1 = difference(p1, q1), d2 = difference(p2, q2);
    if (!(in_window(d1.x) && in_window(d1.y) && in_window(d2.x) && in_window(d2.y))) {
        return compare_lengths_gmp(p1, q1, p2, q2);
    }
    const double s1 = d1.x * d1.x + d1.y * d1.y, s2 = d2.x * d2.x + d2.y * d2.y;
    const double e = s1 - s2;
    if (std::fabs(e) > kLengthFilter * (s1 + s2)) return predicates::sign_of(e);
    if (!(d1.exact && d2.exact)) return compare_lengths_gmp(p1, q1, p2, q2);
    using predicates::exact_product;
    return ((exact_product(d1.x, d1.x) + exact_product(d1.y, d1.y)) -
            (exact_product(d2.x, d2.x) + exact_product(d2.y, d2.y)))
        .sign();
}

namespace {

/// The corner opposite the longest side (`longer` = Positive) or the shortest (Negative): side
/// lengths order the angles of a triangle.
Corner corner_opposite_extreme_side(const double* a, const double* b, const double* c,
                                    Sign longer) {
    // Side opposite a is bc, opposite b is ca, opposite c is ab.
    Corner best{a, b, c};
    const double* best_p = b;
    const double* best_q = c;
    if (compare_lengths(c, a, best_p, best_q) == longer) {
        best = {b, c, a};
        best_p = c;
        best_q = a;
    }
    if (compare_lengths(a, b, best_p, best_q) == longer) best = {c, a, b};
    return best;
}

}  // namespace

Corner largest_corner(const double* a, const double* b, const double* c) {
    return corner_opposite_extreme_side(a, b, c, Sign::Positive);
}

Corner smallest_corner(const double* a, const double* b, const double* c) {
    return corner_opposite_extreme_side(a, b, c, Sign::Negative);
}

}  // namespace exactmesh::triangulation
