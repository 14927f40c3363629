// SPDX-License-Identifier: MIT
// Exact angle and length comparisons (see angle_comparisons_2d.hpp). Filters: by the standard
// forward error analysis of sums of products [Higham, "Accuracy and Stability of Numerical
// Algorithms", §3.1], with every operation rounding to nearest with a relative error delta,
// |delta| <= u = 2^-53 (no overflow, no underflow: see the window below), the computed value of
// a polynomial is the sum of its monomials (products of exact coordinate differences), each
// multiplied by one factor (1 + delta) per rounding on its path, and so is the computed
// permanent (the same expression on absolute values). The filter constants of
// filter_constants.hpp are the least powers of two for which Gappa proves |prod (1 + d) - 1| <=
// eps prod (1 + e) at these rounding counts (proofs/invariants/filters.md, "Relative filters"):
//  - Angles: E = dot_b cross_a - dot_a cross_b; 10 roundings per monomial (4 differences, a
//    product and a sum inside dot or cross, the product dot * cross, the final difference), 10
//    in the permanent (the same differences, a product and a sum inside |dot| or |cross|, the
//    outer product and sum): compare_angles_filter_eps = 2^-49
//    (proofs/gappa/compare_angles_filter.g).
//  - Lengths: E = |p1 - q1|^2 - |p2 - q2|^2; 5 and 5: compare_lengths_filter_eps = 2^-50
//    (proofs/gappa/compare_lengths_filter.g).
//  - Dot products: E = (p - o) . (q - o); 4 and 4 (two differences, the product, the sum):
//    dot_sign_filter_eps = 2^-50 (proofs/gappa/dot_sign_filter.g).
// The window: every nonzero computed difference has magnitude in [2^-200, 2^200]
// (angle_comparisons_2d_window_min/max). A computed
// difference of doubles is zero only when the exact one is (gradual underflow), and then every
// nonzero monomial lies in [2^-800, 2^803] and every partial sum is a nonzero multiple of an
// ulp above 2^-905 or zero, so no operation underflows or overflows. The same window keeps the
// expansion stage exact (every two_product's low part is a multiple of 2^-1012, every
// Veltkamp split far below 2^995). Outside it, the coordinates are scaled into it by a power
// of two when that is exact (each comparison is homogeneous), else GMP decides, as it does when a
// difference is not exact.
#include "predicates/angle_comparisons_2d.hpp"

#include <cmath>
#include <limits>
#include <optional>

#include "predicates/exact_range.hpp"
#include "predicates/exact_reference.hpp"
#include "predicates/expansion.hpp"
#include "predicates/filter_constants.hpp"
#include "predicates/stats.hpp"

namespace exactmesh::predicates {

namespace {

constexpr double kWindowLow = angle_comparisons_2d_window_min;
constexpr double kWindowHigh = angle_comparisons_2d_window_max;
constexpr double kAngleFilter = compare_angles_filter_eps;
constexpr double kLengthFilter = compare_lengths_filter_eps;
constexpr double kDotFilter = dot_sign_filter_eps;
// direction_dot_sign's long double stage needs a format where no difference or product of two
// doubles' differences overflows or underflows (x86-64's 80-bit, or binary128); elsewhere GMP.
constexpr bool kWideLongDouble = std::numeric_limits<long double>::digits >= 64 &&
                                 std::numeric_limits<long double>::max_exponent >= 16384;

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
    two_diff(p[0], o[0], x, x_tail);
    two_diff(p[1], o[1], y, y_tail);
    return {x, y, x_tail == 0.0 && y_tail == 0.0};
}

Sign compare_angles_gmp(const Corner& a, const Corner& b) {
    using reference::exact;
    auto dot_cross = [](const Corner& c, mpq_class& dot, mpq_class& cross) {
        const mpq_class ux = exact(c.p[0]) - exact(c.o[0]), uy = exact(c.p[1]) - exact(c.o[1]);
        const mpq_class vx = exact(c.q[0]) - exact(c.o[0]), vy = exact(c.q[1]) - exact(c.o[1]);
        dot = ux * vx + uy * vy;
        cross = ux * vy - uy * vx;
    };
    mpq_class dot_a, cross_a, dot_b, cross_b;
    dot_cross(a, dot_a, cross_a);
    dot_cross(b, dot_b, cross_b);
    return reference::sign_of(dot_b * cross_a - dot_a * cross_b);
}

Sign compare_lengths_gmp(const double* p1, const double* q1, const double* p2, const double* q2) {
    using reference::exact;
    const mpq_class x1 = exact(p1[0]) - exact(q1[0]), y1 = exact(p1[1]) - exact(q1[1]);
    const mpq_class x2 = exact(p2[0]) - exact(q2[0]), y2 = exact(p2[1]) - exact(q2[1]);
    return reference::sign_of(x1 * x1 + y1 * y1 - (x2 * x2 + y2 * y2));
}

Sign corner_dot_sign_gmp(const double* o, const double* p, const double* q) {
    using reference::exact;
    const mpq_class ux = exact(p[0]) - exact(o[0]), uy = exact(p[1]) - exact(o[1]);
    const mpq_class vx = exact(q[0]) - exact(o[0]), vy = exact(q[1]) - exact(o[1]);
    return reference::sign_of(ux * vx + uy * vy);
}

bool in_window(const Difference& d) {
    return in_window(d.x) && in_window(d.y);
}

/// The dot product's filter over u and v (proofs/gappa/dot_sign_filter.g).
std::optional<Sign> dot_filter(const Difference& u, const Difference& v) {
    if (!(in_window(u) && in_window(v))) return std::nullopt;
    const double xx = u.x * v.x, yy = u.y * v.y;
    const double e = xx + yy;
    if (std::fabs(e) > kDotFilter * (std::fabs(xx) + std::fabs(yy))) return sign_of(e);
    return std::nullopt;
}

/// compare_angles' filter over the corners' differences (proofs/gappa/compare_angles_filter.g).
std::optional<Sign> angle_filter(const Difference& ua, const Difference& va, const Difference& ub,
                                 const Difference& vb) {
    if (!(in_window(ua) && in_window(va) && in_window(ub) && in_window(vb))) return std::nullopt;
    const double dot_a = ua.x * va.x + ua.y * va.y, cross_a = ua.x * va.y - ua.y * va.x;
    const double dot_b = ub.x * vb.x + ub.y * vb.y, cross_b = ub.x * vb.y - ub.y * vb.x;
    const double e = dot_b * cross_a - dot_a * cross_b;
    const double dot_a_abs = std::fabs(ua.x * va.x) + std::fabs(ua.y * va.y);
    const double cross_a_abs = std::fabs(ua.x * va.y) + std::fabs(ua.y * va.x);
    const double dot_b_abs = std::fabs(ub.x * vb.x) + std::fabs(ub.y * vb.y);
    const double cross_b_abs = std::fabs(ub.x * vb.y) + std::fabs(ub.y * vb.x);
    const double permanent = dot_b_abs * cross_a_abs + dot_a_abs * cross_b_abs;
    if (std::fabs(e) > kAngleFilter * permanent) return sign_of(e);
    return std::nullopt;
}

/// compare_lengths' filter (proofs/gappa/compare_lengths_filter.g).
std::optional<Sign> length_filter(const Difference& d1, const Difference& d2) {
    if (!(in_window(d1) && in_window(d2))) return std::nullopt;
    const double s1 = d1.x * d1.x + d1.y * d1.y, s2 = d2.x * d2.x + d2.y * d2.y;
    const double e = s1 - s2;
    if (std::fabs(e) > kLengthFilter * (s1 + s2)) return sign_of(e);
    return std::nullopt;
}

}  // namespace

std::optional<Sign> corner_dot_sign_filter(const double* o, const double* p, const double* q) {
    return dot_filter(difference(p, o), difference(q, o));
}

std::optional<Sign> direction_dot_sign_filter(const double* p, const double* q, const double* a,
                                              const double* b) {
    return dot_filter(difference(q, p), difference(b, a));
}

std::optional<Sign> compare_angles_filter(const Corner& a, const Corner& b) {
    return angle_filter(difference(a.p, a.o), difference(a.q, a.o), difference(b.p, b.o),
                        difference(b.q, b.o));
}

std::optional<Sign> compare_lengths_filter(const double* p1, const double* q1, const double* p2,
                                           const double* q2) {
    return length_filter(difference(p1, q1), difference(p2, q2));
}

namespace {

// The staged evaluations. Every comparison here is a homogeneous polynomial in the coordinates,
// so when a difference leaves the window (coordinates near 2^+-600, say) the coordinates are
// scaled by one power of two into [1, 2) when that is exact (detail::rescale_into_safe_range)
// and the stages run again on the copy, once (may_rescale false); else GMP.

Sign corner_dot_sign_staged(const double* o, const double* p, const double* q, bool may_rescale) {
    const Difference u = difference(p, o), v = difference(q, o);
    if (const auto s = dot_filter(u, v)) {
        EM_STAT(corner_dot_sign, filter);
        return *s;
    }
    const bool window = in_window(u) && in_window(v);
    if (!window && may_rescale) {
        double c[6];
        if (detail::rescale_into_safe_range(2, {o[0], o[1], p[0], p[1], q[0], q[1]}, c)) {
            EM_STAT(corner_dot_sign, rescaled);
            return corner_dot_sign_staged(c, c + 2, c + 4, false);
        }
    }
    if (!(window && u.exact && v.exact)) {
        EM_STAT(corner_dot_sign, gmp);
        return corner_dot_sign_gmp(o, p, q);
    }
    EM_STAT(corner_dot_sign, exact_differences);
    return (exact_product(u.x, v.x) + exact_product(u.y, v.y)).sign();
}

Sign direction_dot_sign_staged(const double* p, const double* q, const double* a, const double* b,
                               bool may_rescale) {
    // The dot product's filter and exact stage with u = q - p, v = b - a.
    const Difference u = difference(q, p), v = difference(b, a);
    if (const auto s = dot_filter(u, v)) {
        EM_STAT(direction_dot_sign, filter);
        return *s;
    }
    const bool window = in_window(u) && in_window(v);
    if (window && u.exact && v.exact) {
        EM_STAT(direction_dot_sign, exact_differences);
        return (exact_product(u.x, v.x) + exact_product(u.y, v.y)).sign();
    }
    if (!window && may_rescale) {
        double c[8];
        if (detail::rescale_into_safe_range(2, {p[0], p[1], q[0], q[1], a[0], a[1], b[0], b[1]},
                                            c)) {
            EM_STAT(direction_dot_sign, rescaled);
            return direction_dot_sign_staged(c, c + 2, c + 4, c + 6, false);
        }
    }
    if constexpr (kWideLongDouble) {
        // Outside the window, or inexact differences: long double, where no difference or
        // product of doubles' differences overflows or underflows; each monomial carries 4
        // roundings of 2^-64 (two differences, the product, the sum), and so does the bound: a
        // margin of dot_sign_long_double_filter_eps of |xx| + |yy| decides (proofs/gappa/
        // dot_sign_long_double_filter.g; spans 1e-225..1e212 spent a minute in GMP here in
        // conforming bends); else GMP.
        using LD = long double;
        const LD lux = static_cast<LD>(q[0]) - p[0], luy = static_cast<LD>(q[1]) - p[1];
        const LD lvx = static_cast<LD>(b[0]) - a[0], lvy = static_cast<LD>(b[1]) - a[1];
        const LD lxx = lux * lvx, lyy = luy * lvy, le = lxx + lyy;
        if (std::fabs(le) > dot_sign_long_double_filter_eps * (std::fabs(lxx) + std::fabs(lyy))) {
            EM_STAT(direction_dot_sign, adaptive);
            return le > 0 ? Sign::Positive : Sign::Negative;
        }
    }
    EM_STAT(direction_dot_sign, gmp);
    using reference::exact;
    const mpq_class ux = exact(q[0]) - exact(p[0]), uy = exact(q[1]) - exact(p[1]);
    const mpq_class vx = exact(b[0]) - exact(a[0]), vy = exact(b[1]) - exact(a[1]);
    return reference::sign_of(ux * vx + uy * vy);
}

Sign compare_angles_staged(const Corner& a, const Corner& b, bool may_rescale) {
    const Difference ua = difference(a.p, a.o), va = difference(a.q, a.o);
    const Difference ub = difference(b.p, b.o), vb = difference(b.q, b.o);
    if (const auto s = angle_filter(ua, va, ub, vb)) {
        EM_STAT(compare_angles, filter);
        return *s;
    }
    const bool window = in_window(ua) && in_window(va) && in_window(ub) && in_window(vb);
    if (!window && may_rescale) {
        double c[12];
        if (detail::rescale_into_safe_range(4,
                                            {a.o[0], a.o[1], a.p[0], a.p[1], a.q[0], a.q[1], b.o[0],
                                             b.o[1], b.p[0], b.p[1], b.q[0], b.q[1]},
                                            c)) {
            EM_STAT(compare_angles, rescaled);
            return compare_angles_staged({c, c + 2, c + 4}, {c + 6, c + 8, c + 10}, false);
        }
    }
    if (!(window && ua.exact && va.exact && ub.exact && vb.exact)) {
        EM_STAT(compare_angles, gmp);
        return compare_angles_gmp(a, b);
    }
    EM_STAT(compare_angles, exact_differences);
    const auto dot_a_exact = exact_product(ua.x, va.x) + exact_product(ua.y, va.y);
    const auto cross_a_exact = exact_product(ua.x, va.y) - exact_product(ua.y, va.x);
    const auto dot_b_exact = exact_product(ub.x, vb.x) + exact_product(ub.y, vb.y);
    const auto cross_b_exact = exact_product(ub.x, vb.y) - exact_product(ub.y, vb.x);
    return (product(dot_b_exact, cross_a_exact) - product(dot_a_exact, cross_b_exact)).sign();
}

Sign compare_lengths_staged(const double* p1, const double* q1, const double* p2, const double* q2,
                            bool may_rescale) {
    const Difference d1 = difference(p1, q1), d2 = difference(p2, q2);
    if (const auto s = length_filter(d1, d2)) {
        EM_STAT(compare_lengths, filter);
        return *s;
    }
    const bool window = in_window(d1) && in_window(d2);
    if (!window && may_rescale) {
        double c[8];
        if (detail::rescale_into_safe_range(
                2, {p1[0], p1[1], q1[0], q1[1], p2[0], p2[1], q2[0], q2[1]}, c)) {
            EM_STAT(compare_lengths, rescaled);
            return compare_lengths_staged(c, c + 2, c + 4, c + 6, false);
        }
    }
    if (!(window && d1.exact && d2.exact)) {
        EM_STAT(compare_lengths, gmp);
        return compare_lengths_gmp(p1, q1, p2, q2);
    }
    EM_STAT(compare_lengths, exact_differences);
    return ((exact_product(d1.x, d1.x) + exact_product(d1.y, d1.y)) -
            (exact_product(d2.x, d2.x) + exact_product(d2.y, d2.y)))
        .sign();
}

}  // namespace

Sign corner_dot_sign(const double* o, const double* p, const double* q) {
    EM_STAT(corner_dot_sign, calls);
    return corner_dot_sign_staged(o, p, q, true);
}

Sign direction_dot_sign(const double* p, const double* q, const double* a, const double* b) {
    EM_STAT(direction_dot_sign, calls);
    return direction_dot_sign_staged(p, q, a, b, true);
}

Sign compare_angles(const Corner& a, const Corner& b) {
    EM_STAT(compare_angles, calls);
    return compare_angles_staged(a, b, true);
}

Sign compare_lengths(const double* p1, const double* q1, const double* p2, const double* q2) {
    EM_STAT(compare_lengths, calls);
    return compare_lengths_staged(p1, q1, p2, q2, true);
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

}  // namespace exactmesh::predicates
