// SPDX-License-Identifier: MIT
// compare_metric_lengths (metric_lengths.hpp). The filter follows the relative-filter model of
// proofs/invariants/filters.md ("Relative filters"): E = s1 - s2 with s = (M11 x) x + (2 M12 x) y
// + (M22 y) y over the computed differences; every monomial of E (a metric entry times two exact
// differences) carries 7 roundings (its two differences, two products, at most two sums inside s,
// the final difference), and so does the bound (the same over absolute values, then b1 + b2):
// compare_metric_lengths_filter_eps = 2^-50 (proofs/gappa/compare_metric_lengths_filter.g).
// The window: every nonzero computed difference and every nonzero metric entry has magnitude in
// [2^-200, 2^200]; every nonzero monomial then lies in [2^-600, 2^602], every partial sum is a
// nonzero multiple of 2^-756 or zero, so no operation underflows or overflows, and the
// expansions are exact (every two_product's low part is a multiple of 2^-756, every Veltkamp
// split far below 2^995). Outside the window, the coordinates (one power of two for all eight)
// and the metrics (one for all six) are scaled into it when that is exact, else GMP decides, as
// it does when a difference is not exact.
#include "predicates/metric_lengths.hpp"

#include <cmath>

#include "predicates/exact_range.hpp"
#include "predicates/exact_reference.hpp"
#include "predicates/expansion.hpp"
#include "predicates/filter_constants.hpp"
#include "predicates/stats.hpp"

namespace exactmesh::predicates {

namespace {

constexpr double kWindowLow = 0x1p-200;
constexpr double kWindowHigh = 0x1p+200;

bool in_window(double x) {
    const double a = std::fabs(x);
    return a == 0.0 || (a >= kWindowLow && a <= kWindowHigh);
}

bool in_window(const double* m) {
    return in_window(m[0]) && in_window(m[1]) && in_window(m[2]);
}

/// q - p per coordinate, and whether both differences are exact doubles.
struct Difference {
    double x, y;
    bool exact;
};

Difference difference(const double* q, const double* p) {
    double x, y, x_tail, y_tail;
    two_diff(q[0], p[0], x, x_tail);
    two_diff(q[1], p[1], y, y_tail);
    return {x, y, x_tail == 0.0 && y_tail == 0.0};
}

/// The filter over computed differences, in the order proofs/gappa models.
std::optional<Sign> length_filter(const Difference& d1, const double* m1, const Difference& d2,
                                  const double* m2) {
    if (!(in_window(d1.x) && in_window(d1.y) && in_window(d2.x) && in_window(d2.y) &&
          in_window(m1) && in_window(m2))) {
        return std::nullopt;
    }
    const double s1 = (m1[0] * d1.x) * d1.x + ((2.0 * m1[1]) * d1.x) * d1.y + (m1[2] * d1.y) * d1.y;
    const double s2 = (m2[0] * d2.x) * d2.x + ((2.0 * m2[1]) * d2.x) * d2.y + (m2[2] * d2.y) * d2.y;
    const double b1 = (std::fabs(m1[0]) * std::fabs(d1.x)) * std::fabs(d1.x) +
                      (std::fabs(2.0 * m1[1]) * std::fabs(d1.x)) * std::fabs(d1.y) +
                      (std::fabs(m1[2]) * std::fabs(d1.y)) * std::fabs(d1.y);
    const double b2 = (std::fabs(m2[0]) * std::fabs(d2.x)) * std::fabs(d2.x) +
                      (std::fabs(2.0 * m2[1]) * std::fabs(d2.x)) * std::fabs(d2.y) +
                      (std::fabs(m2[2]) * std::fabs(d2.y)) * std::fabs(d2.y);
    const double e = s1 - s2;
    if (std::fabs(e) > compare_metric_lengths_filter_eps * (b1 + b2)) return sign_of(e);
    return std::nullopt;
}

/// v^T M v exactly for an exact difference v.
Expansion<12> metric_square(const Difference& v, const double* m) noexcept {
    return (scale(exact_product(v.x, v.x), m[0]) + scale(exact_product(v.x, v.y), 2.0 * m[1])) +
           scale(exact_product(v.y, v.y), m[2]);
}

Sign compare_metric_lengths_gmp(const double* p1, const double* q1, const double* m1,
                                const double* p2, const double* q2, const double* m2) {
    using reference::exact;
    auto square = [](const double* p, const double* q, const double* m) {
        const mpq_class x = exact(q[0]) - exact(p[0]), y = exact(q[1]) - exact(p[1]);
        return mpq_class(exact(m[0]) * x * x + 2 * exact(m[1]) * x * y + exact(m[2]) * y * y);
    };
    return reference::sign_of(square(p1, q1, m1) - square(p2, q2, m2));
}

Sign staged(const double* p1, const double* q1, const double* m1, const double* p2,
            const double* q2, const double* m2, bool may_rescale) {
    const Difference d1 = difference(q1, p1), d2 = difference(q2, p2);
    if (const auto s = length_filter(d1, m1, d2, m2)) {
        EM_STAT(compare_metric_lengths, filter);
        return *s;
    }
    const bool window = in_window(d1.x) && in_window(d1.y) && in_window(d2.x) && in_window(d2.y) &&
                        in_window(m1) && in_window(m2);
    if (!window && may_rescale) {
        // Homogeneous of degree 2 in the coordinates and 1 in the metrics (both metrics share
        // one factor, so their ratio is kept).
        double c[8], m[6];
        if (detail::rescale_into_safe_range(
                3, {p1[0], p1[1], q1[0], q1[1], p2[0], p2[1], q2[0], q2[1]}, c) &&
            detail::rescale_into_safe_range(3, {m1[0], m1[1], m1[2], m2[0], m2[1], m2[2]}, m)) {
            EM_STAT(compare_metric_lengths, rescaled);
            return staged(c, c + 2, m, c + 4, c + 6, m + 3, false);
        }
    }
    if (!(window && d1.exact && d2.exact)) {
        EM_STAT(compare_metric_lengths, gmp);
        return compare_metric_lengths_gmp(p1, q1, m1, p2, q2, m2);
    }
    EM_STAT(compare_metric_lengths, exact_differences);
    return (metric_square(d1, m1) - metric_square(d2, m2)).sign();
}

}  // namespace

std::optional<Sign> compare_metric_lengths_filter(const double* p1, const double* q1,
                                                  const double* m1, const double* p2,
                                                  const double* q2, const double* m2) {
    return length_filter(difference(q1, p1), m1, difference(q2, p2), m2);
}

Sign compare_metric_lengths(const double* p1, const double* q1, const double* m1, const double* p2,
                            const double* q2, const double* m2) {
    detail::require_finite("compare_metric_lengths",
                           {p1[0], p1[1], q1[0], q1[1], p2[0], p2[1], q2[0], q2[1], m1[0], m1[1],
                            m1[2], m2[0], m2[1], m2[2]});
    EM_STAT(compare_metric_lengths, calls);
    return staged(p1, q1, m1, p2, q2, m2, true);
}

}  // namespace exactmesh::predicates
