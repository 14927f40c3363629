// SPDX-License-Identifier: MIT
// Constant 2x2 metrics (see metric_2d.hpp). Every eigendecomposition here is the closed form of
// a symmetric 2x2 matrix [a b; b d] scaled by a power of two to entries of order 1: the larger
// eigenvalue mean + radius (mean = (a + d) / 2, radius = hypot((a - d) / 2, b)) has no
// cancellation when the matrix is positive definite, the smaller one is det / larger with the
// determinant from Kahan's fma algorithm (accurate to a few ulps even when it cancels), and the
// direction of the larger one is half the angle atan2(b, (a - d) / 2). A nearly isotropic matrix
// thus keeps full relative accuracy in both eigenvalues (its direction is then arbitrary, which
// does not matter when the sizes are equal), and a matrix of aspect ratio r loses only about
// log2(r) bits in the smaller one, never all of them.
#include "generators/stretched/metric_2d.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <string>

#include "base/errors.hpp"
#include "base/number_text.hpp"
#include "predicates/power_of_two.hpp"

namespace exactmesh::generators {

namespace {

using predicates::binary_exponent;
using predicates::PowerOfTwo;

/// a d - b c, accurate to about 1.5 ulp whatever the cancellation [Kahan, "Further analysis of
/// Kahan's algorithm for the accurate computation of 2x2 determinants", Jeannerod et al. 2013].
double kahan_determinant(double a, double b, double c, double d) {
    const double w = b * c;
    const double error = std::fma(-b, c, w);  // w - b c, exactly
    const double f = std::fma(a, d, -w);
    return f + error;
}

/// The eigenvalues (larger, smaller) and the unit direction of the larger of [a b; b d].
struct Eigen2 {
    double larger = 0, smaller = 0, c = 1, s = 0;
};

/// The direction of the larger eigenvalue: half the angle of (a - d) / 2 + i b. For an exactly
/// isotropic matrix atan2(0, 0) = 0 gives (1, 0).
void principal_direction(double a, double b, double d, Eigen2& eigen) {
    const double angle = 0.5 * std::atan2(b, 0.5 * a - 0.5 * d);
    eigen.c = std::cos(angle);
    eigen.s = std::sin(angle);
}

/// Eigenvalues of a positive definite [a b; b d] with entries of order 1 and its determinant
/// `det` > 0 computed accurately by the caller.
Eigen2 positive_definite_eigen(double a, double b, double d, double det) {
    Eigen2 eigen;
    const double mean = 0.5 * a + 0.5 * d;
    const double radius = std::hypot(0.5 * a - 0.5 * d, b);
    eigen.larger = mean + radius;
    eigen.smaller = det / eigen.larger;
    principal_direction(a, b, d, eigen);
    return eigen;
}

std::string triple(double a, double b, double c) {
    std::string text = "(";
    text += format_number(a);
    text += ", ";
    text += format_number(b);
    text += ", ";
    text += format_number(c);
    text += ")";
    return text;
}

/// Refuses sizes that are not finite > 0 or whose ratio exceeds kMaxAspectRatio.
/// `what` names the metric in a message: a string, or a callable returning one (built only
/// when a message is: formatting numbers costs more than the metric itself).
std::string named(const std::string& what) {
    return what;
}
std::string named(const char* what) {
    return what;
}
template <class What>
std::string named(const What& what) {
    return what();
}

template <class What>
void check_sizes(double h1, double h2, const What& what) {
    if (!(std::isfinite(h1) && h1 > 0 && std::isfinite(h2) && h2 > 0)) {
        throw InputError(named(what) + ": its sizes " + format_number(h1) + " and " +
                         format_number(h2) +
                         " are not finite numbers > 0 (beyond the range of doubles)");
    }
    const double ratio = h1 > h2 ? h1 / h2 : h2 / h1;
    if (!(ratio <= kMaxAspectRatio)) {
        throw InputError(named(what) + ": its aspect ratio " + format_number(ratio) +
                         " exceeds 2^250 (sizes " + format_number(h1) + " and " +
                         format_number(h2) + ")");
    }
}

/// The metric C^T C of the factor C = [c11 c12; c21 c22] (column j: the mapped components of
/// the image of e_j), C first scaled by a power of two to entries below 2: no square
/// overflows, and det(C^T C) = det(C)^2 keeps its accuracy (det(C) cancels only by C's condition
/// number, the square root of M's).
Metric2 metric_from_factor(double c11, double c12, double c21, double c22, const char* what) {
    const double largest =
        std::max({std::fabs(c11), std::fabs(c12), std::fabs(c21), std::fabs(c22)});
    const int shift = predicates::unit_shift(largest);
    const PowerOfTwo scale(shift);
    c11 = scale(c11), c12 = scale(c12), c21 = scale(c21), c22 = scale(c22);
    const double det = kahan_determinant(c11, c12, c21, c22);
    const double g11 = c11 * c11 + c21 * c21, g12 = c11 * c12 + c21 * c22,
                 g22 = c12 * c12 + c22 * c22;
    if (!(std::isfinite(det) && det != 0)) {
        throw InputError(std::string(what) + ": the result is singular in double precision " +
                         "(an aspect ratio far beyond 2^250)");
    }
    const Eigen2 eigen = positive_definite_eigen(g11, g12, g22, det * det);
    // C = 2^-shift C_scaled, so lambda = 2^(-2 shift) lambda_scaled and h = 2^shift / sqrt(.).
    const PowerOfTwo back(shift);
    Metric2 metric{back(1.0 / std::sqrt(eigen.larger)), back(1.0 / std::sqrt(eigen.smaller)),
                   eigen.c, eigen.s};
    check_sizes(metric.h1, metric.h2, what);
    return metric;
}

}  // namespace

Metric2 metric_from_matrix(double m11, double m12, double m22) {
    const auto what = [&] { return "metric (M11, M12, M22) = " + triple(m11, m12, m22); };
    if (!(std::isfinite(m11) && std::isfinite(m12) && std::isfinite(m22)))
        throw InputError(what() + " is not finite");
    const double largest = std::max({std::fabs(m11), std::fabs(m12), std::fabs(m22)});
    if (largest == 0 || !(m11 > 0 && m22 > 0))
        throw InputError(what() + " is not positive definite (a diagonal entry is not > 0)");
    // An even power of two, so that the sizes scale back by an exact power of two as well.
    int even = binary_exponent(largest);
    even -= even & 1;  // floor to even (two's complement: also for negative exponents)
    const PowerOfTwo down(-even);
    const double a = down(m11), b = down(m12), d = down(m22);
    const double det = kahan_determinant(a, b, b, d);
    if (!(det > 0)) {
        throw InputError(what() + " is not positive definite (M11 M22 - M12^2 = " +
                         format_number(std::ldexp(det, 2 * even)) + (det == 0 ? ", singular" : "") +
                         ")");
    }
    const Eigen2 eigen = positive_definite_eigen(a, b, d, det);
    const PowerOfTwo back(-even / 2);
    Metric2 metric{back(1.0 / std::sqrt(eigen.larger)), back(1.0 / std::sqrt(eigen.smaller)),
                   eigen.c, eigen.s};
    check_sizes(metric.h1, metric.h2, what);
    return metric;
}

Metric2 metric_from_stretching(double dir_x, double dir_y, double size_along, double aspect_ratio) {
    const std::string what = "stretching vector (" + format_number(dir_x) + ", " +
                             format_number(dir_y) + "), size " + format_number(size_along) +
                             ", aspect ratio " + format_number(aspect_ratio);
    const double norm = predicates::scale_free_norm(dir_x, dir_y);
    if (!(std::isfinite(norm) && norm > 0))
        throw InputError(what + ": the direction is zero or not finite");
    if (!(std::isfinite(size_along) && size_along > 0))
        throw InputError(what + ": the size is not a finite number > 0");
    if (!(std::isfinite(aspect_ratio) && aspect_ratio > 0))
        throw InputError(what + ": the aspect ratio is not a finite number > 0");
    Metric2 metric{size_along, size_along / aspect_ratio, dir_x / norm, dir_y / norm};
    check_sizes(metric.h1, metric.h2, what);
    return metric;
}

Metric2 isotropic(double h) {
    if (!(std::isfinite(h) && h > 0))
        throw InputError("isotropic metric: size " + format_number(h) +
                         " is not a finite number > 0");
    return Metric2{h, h, 1, 0};
}

void check_metric(const Metric2& metric) {
    const std::string what = "metric with sizes " + format_number(metric.h1) + ", " +
                             format_number(metric.h2) + " along (" + format_number(metric.c) +
                             ", " + format_number(metric.s) + ")";
    check_sizes(metric.h1, metric.h2, what);
    const double norm2 = metric.c * metric.c + metric.s * metric.s;
    if (!(std::fabs(norm2 - 1) <= 1e-12))
        throw InputError(what + ": the direction is not a unit vector");
}

LogMetric2 log_form(const Metric2& metric) {
    const double a1 = -2 * std::log(metric.h1), a2 = -2 * std::log(metric.h2);
    const double cc = metric.c * metric.c, ss = metric.s * metric.s, cs = metric.c * metric.s;
    return {a1 * cc + a2 * ss, (a1 - a2) * cs, a1 * ss + a2 * cc};
}

Metric2 metric_from_log_form(double l11, double l12, double l22) {
    const auto what = [&] {
        return "log-Euclidean metric (L11, L12, L22) = " + triple(l11, l12, l22);
    };
    if (!(std::isfinite(l11) && std::isfinite(l12) && std::isfinite(l22)))
        throw InputError(what() + " is not finite");
    // Logarithms need absolute, not relative, accuracy (an absolute error e in mu is a relative
    // error e / 2 in the size), so mean -+ radius serves for both eigenvalues.
    Eigen2 eigen;
    const double mean = 0.5 * l11 + 0.5 * l22;
    const double radius = std::hypot(0.5 * l11 - 0.5 * l22, l12);
    eigen.larger = mean + radius;
    eigen.smaller = mean - radius;
    principal_direction(l11, l12, l22, eigen);
    Metric2 metric{std::exp(-0.5 * eigen.larger), std::exp(-0.5 * eigen.smaller), eigen.c, eigen.s};
    check_sizes(metric.h1, metric.h2, what);
    return metric;
}

MetricFromLogFormMemo::MetricFromLogFormMemo(std::size_t slots) {
    int bits = 10;
    while (bits < 20 && (std::size_t{1} << bits) < slots) ++bits;
    shift_ = 64 - bits;
}

Metric2 MetricFromLogFormMemo::operator()(double l11, double l12, double l22) {
    if (slots_.empty()) {
        // Allocated at the first use: a run in a constant metric never takes a mean.
        // A NaN key: no finite argument matches it (non-finite ones throw before being stored).
        const auto empty = std::bit_cast<std::uint64_t>(std::numeric_limits<double>::quiet_NaN());
        slots_.assign(std::size_t{1} << (64 - shift_), Slot{{empty, empty, empty}, Metric2{}});
    }
    const auto k0 = std::bit_cast<std::uint64_t>(l11);
    const auto k1 = std::bit_cast<std::uint64_t>(l12);
    const auto k2 = std::bit_cast<std::uint64_t>(l22);
    std::uint64_t h = k0 * 0x9e3779b97f4a7c15ULL;
    h = (h ^ (h >> 29) ^ k1) * 0xbf58476d1ce4e5b9ULL;
    h = (h ^ (h >> 31) ^ k2) * 0x94d049bb133111ebULL;
    h ^= h >> 32;
    Slot& slot = slots_[static_cast<std::size_t>(h >> shift_)];
    if (slot.key[0] == k0 && slot.key[1] == k1 && slot.key[2] == k2) {
        ++hits_;
        return slot.value;
    }
    ++misses_;
    const Metric2 value = metric_from_log_form(l11, l12, l22);
    slot = Slot{{k0, k1, k2}, value};
    return value;
}

Metric2 log_euclidean_mean(std::span<const Metric2> metrics, std::span<const double> weights,
                           MetricFromLogFormMemo* memo) {
    if (metrics.size() != weights.size()) {
        throw InputError("log-Euclidean mean: " + std::to_string(metrics.size()) + " metrics but " +
                         std::to_string(weights.size()) + " weights");
    }
    double total = 0;
    std::size_t first = metrics.size(), used = 0;
    for (std::size_t i = 0; i < weights.size(); ++i) {
        if (!(std::isfinite(weights[i]) && weights[i] >= 0)) {
            throw InputError("log-Euclidean mean: weight " + std::to_string(i) + " is " +
                             format_number(weights[i]) + ", not a finite number >= 0");
        }
        if (weights[i] > 0) {
            first = std::min(first, i);
            total += weights[i];
            ++used;
        }
    }
    if (used == 0 || !std::isfinite(total))
        throw InputError("log-Euclidean mean: the weights sum to " + format_number(total));
    if (used == 1) return metrics[first];
    // Logarithms of the sizes in units of 2^e: metrics scaled together by 2^k give the same
    // logarithms, and the mean is scaled back exactly.
    const int e = binary_exponent(metrics[first].h1);
    const PowerOfTwo down(-e);
    double l11 = 0, l12 = 0, l22 = 0;
    for (std::size_t i = 0; i < metrics.size(); ++i) {
        if (weights[i] == 0) continue;
        Metric2 scaled = metrics[i];
        scaled.h1 = down(scaled.h1);
        scaled.h2 = down(scaled.h2);
        const LogMetric2 form = log_form(scaled);
        const double w = weights[i] / total;
        l11 += w * form.l11;
        l12 += w * form.l12;
        l22 += w * form.l22;
    }
    Metric2 mean = memo != nullptr ? (*memo)(l11, l12, l22) : metric_from_log_form(l11, l12, l22);
    const PowerOfTwo up(e);
    mean.h1 = up(mean.h1);
    mean.h2 = up(mean.h2);
    return mean;
}

void metric_map(const Metric2& metric, double vx, double vy, double& a, double& b) {
    a = (metric.c * vx + metric.s * vy) / metric.h1;
    b = (metric.c * vy - metric.s * vx) / metric.h2;
}

double metric_length(const Metric2& metric, double vx, double vy) {
    double a = 0, b = 0;
    metric_map(metric, vx, vy, a, b);
    return std::hypot(a, b);
}

void matrix_for_predicate(const Metric2& metric, double out[3]) {
    const double smallest = std::min(metric.h1, metric.h2);
    const double r1 = smallest / metric.h1, r2 = smallest / metric.h2;  // in [2^-250, 1]
    const double e1 = r1 * r1, e2 = r2 * r2;
    const double cc = metric.c * metric.c, ss = metric.s * metric.s, cs = metric.c * metric.s;
    out[0] = e1 * cc + e2 * ss;
    out[1] = (e1 - e2) * cs;
    out[2] = e1 * ss + e2 * cc;
    // Rounded to doubles, a rotated metric keeps its small eigenvalue only to within about
    // 2^-53 of the large one: beyond an aspect ratio of about 2^26 the rounded matrix may be
    // singular or indefinite. The exact predicate would then decide on a degenerate quadric, so
    // M22 is raised by ulps until M11 M22 - M12^2 > 0 (Kahan's determinant has a relative error
    // of at most 2 ulps, so its sign is exact): each ulp adds at least M11 * 2^-105 > 0 to the
    // determinant, a step or two suffice.
    for (int step = 0; step < 64 && !(kahan_determinant(out[0], out[1], out[1], out[2]) > 0);
         ++step)
        out[2] = std::nextafter(out[2], 2.0);
}

Metric2 metric_intersection(const Metric2& a, const Metric2& b, double tolerance) {
    // Sizes in units of 2^k, k the exponent of the smallest: every scaled size is >= 1, the
    // reciprocals below are <= 1, and metrics scaled together by 2^j intersect the same.
    const int k = binary_exponent(std::min({a.h1, a.h2, b.h1, b.h2}));
    const PowerOfTwo down(-k);
    const Metric2 as{down(a.h1), down(a.h2), a.c, a.s};
    const Metric2 bs{down(b.h1), down(b.h2), b.c, b.s};
    const double cc = as.c * as.c, ss = as.s * as.s, cs = as.c * as.s;
    // x = A y with A = M_a^(-1/2) = R diag(h1, h2) R^T maps a's unit circle onto its ellipse: in
    // y, a is the identity and b is B^T B, B's column j = the b-mapped components of A e_j.
    const double a11 = as.h1 * cc + as.h2 * ss, a12 = (as.h1 - as.h2) * cs,
                 a22 = as.h1 * ss + as.h2 * cc;
    double b11 = 0, b21 = 0, b12 = 0, b22 = 0;
    metric_map(bs, a11, a12, b11, b21);
    metric_map(bs, a12, a22, b12, b22);
    const Metric2 in_a_frame = metric_from_factor(b11, b12, b21, b22, "metric intersection");
    // In y the intersection keeps b's principal directions and cuts its sizes to at most 1 (the
    // unit circle, a's ellipse) [Frey-George08 §10.2.3, simultaneous reduction].
    if (in_a_frame.h1 >= 1 - tolerance && in_a_frame.h2 >= 1 - tolerance) return a;
    const Metric2 cut{std::min(1.0, in_a_frame.h1), std::min(1.0, in_a_frame.h2), in_a_frame.c,
                      in_a_frame.s};
    // Back to x: y = A^-1 x, A^-1 = R diag(1 / h1, 1 / h2) R^T; C's column j = the cut-mapped
    // components of A^-1 e_j, and the intersection is C^T C.
    const double i1 = 1 / as.h1, i2 = 1 / as.h2;
    const double p11 = i1 * cc + i2 * ss, p12 = (i1 - i2) * cs, p22 = i1 * ss + i2 * cc;
    double c11 = 0, c21 = 0, c12 = 0, c22 = 0;
    metric_map(cut, p11, p12, c11, c21);
    metric_map(cut, p12, p22, c12, c22);
    Metric2 result = metric_from_factor(c11, c12, c21, c22, "metric intersection");
    const PowerOfTwo up(k);
    result.h1 = up(result.h1);
    result.h2 = up(result.h2);
    return result;
}

}  // namespace exactmesh::generators
