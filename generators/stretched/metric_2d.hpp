// SPDX-License-Identifier: MIT
// A constant 2x2 symmetric positive definite metric M, the size and stretching target of
// anisotropic meshing [issue 14; George-Borouchaki98 "Delaunay triangulation and meshing" ch.
// 10; Frey-George08 §10.2], stored scale-invariantly as principal sizes and a unit direction:
//     M = R diag(1 / h1^2, 1 / h2^2) R^T,   R = [c -s; s c],
// so an edge of unit metric length is h1 long along (c, s) and h2 long along (-s, c). The
// entries of M themselves are never stored: at the project's scales (a domain times 2^+-600)
// 1 / h^2 overflows or underflows as a double, while the sizes scale exactly.
// Operations: construction from a matrix (closed-form symmetric eigendecomposition), from a
// stretching vector, isotropic; the log-Euclidean form L = log M = R diag(-2 ln h1, -2 ln h2) R^T
// and weighted means in it [Arsigny-Fillard-Pennec-Ayache06], which keep positive definiteness
// and interpolate determinants geometrically; the metric length of a vector; the matrix handed
// to the in-ellipse predicate; and intersection by simultaneous reduction
// [Frey-George08 §10.2.3]. Every size ratio is limited to kMaxAspectRatio (2^250): a metric
// beyond it is an InputError, so that the predicate's matrix never underflows.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace exactmesh::generators {

/// The largest ratio h_max / h_min any Metric2 may have: 2^250. Then matrix_for_predicate's
/// entries (eigenvalues 1 and (h_min / h_max)^2 >= 2^-500) are normal doubles, as are their
/// products with coordinate differences scaled to [1, 2) in the predicate.
inline constexpr double kMaxAspectRatio = 0x1p250;

struct Metric2 {
    double h1 = 1;  ///< the target length along (c, s), finite > 0
    double h2 = 1;  ///< the target length along (-s, c), finite > 0
    double c = 1;   ///< the first principal direction (c, s), a unit vector
    double s = 0;
};

/// The log-Euclidean form L = log M (a symmetric matrix; its entries are of size |ln h|, so they
/// neither overflow nor underflow for any double size).
struct LogMetric2 {
    double l11 = 0, l12 = 0, l22 = 0;
};

/// The metric of the matrix [m11 m12; m12 m22] (h1 <= h2: (c, s) is the direction of the
/// largest eigenvalue). Exact eigenvalue formulas on the matrix first scaled by a power of two:
/// the larger eigenvalue as mean + radius (no cancellation), the smaller as det / larger with the
/// determinant from Kahan's fma algorithm, so a nearly isotropic or a very stretched matrix keeps
/// its relative accuracy.
/// @throws InputError naming the three values when one is not finite, the matrix is not positive
///         definite, or its sizes' ratio exceeds kMaxAspectRatio or overflows.
Metric2 metric_from_matrix(double m11, double m12, double m22);

/// A stretching vector: sizes `size_along` along the direction (dir_x, dir_y) (any length > 0)
/// and size_along / aspect_ratio across it (aspect_ratio > 1: cells long along the direction).
/// @throws InputError on a zero or non-finite direction, a size or aspect ratio not finite > 0,
///         or an aspect ratio beyond kMaxAspectRatio (or below its inverse).
Metric2 metric_from_stretching(double dir_x, double dir_y, double size_along, double aspect_ratio);

/// h1 = h2 = h along (1, 0). @throws InputError unless h is finite and > 0.
Metric2 isotropic(double h);

/// Checks a Metric2 built by hand: sizes finite > 0 within kMaxAspectRatio, (c, s) a unit vector
/// to within 1e-12. @throws InputError naming the values.
void check_metric(const Metric2& metric);

/// L = log M.
LogMetric2 log_form(const Metric2& metric);
/// exp(L) for a symmetric L (finite entries; h1 <= h2).
/// @throws InputError when an entry is not finite or the sizes exp(-mu / 2) overflow, underflow or
///         exceed kMaxAspectRatio.
Metric2 metric_from_log_form(double l11, double l12, double l22);
inline Metric2 metric_from_log_form(const LogMetric2& form) {
    return metric_from_log_form(form.l11, form.l12, form.l22);
}

/// A memo of metric_from_log_form (a pure function of its three doubles): the stretched
/// generators take the exponential of the same mean log form many times (an edge measured by
/// each swap pass, each edit round and each smoothing pass while its ends' metrics stay the
/// same), and each costs an atan2, a sincos, two exp and a hypot. Keyed by the arguments' exact
/// bits, so a hit returns the very Metric2 a call would: results are unchanged. Direct-mapped
/// (a new key overwrites the slot's old one), with a fixed number of slots: the memory stays
/// bounded whatever the mesh (allocated at the first call).
class MetricFromLogFormMemo {
  public:
    /// slots: rounded up to a power of two, at least 2^10, at most 2^20 (56 bytes each).
    explicit MetricFromLogFormMemo(std::size_t slots = std::size_t{1} << 16);
    /// metric_from_log_form(l11, l12, l22), from the memo when the same three doubles were seen.
    /// @throws InputError as metric_from_log_form (nothing is stored then).
    Metric2 operator()(double l11, double l12, double l22);
    std::uint64_t hits() const { return hits_; }
    std::uint64_t misses() const { return misses_; }

  private:
    struct Slot {
        std::uint64_t key[3];
        Metric2 value;
    };
    std::vector<Slot> slots_;
    int shift_ = 0;
    std::uint64_t hits_ = 0, misses_ = 0;
};

/// exp(sum_i w_i log M_i / sum_i w_i), the log-Euclidean weighted mean (interpolation with
/// barycentric weights, averaging). The logarithms are taken of the metrics first scaled by the
/// power of two of the first weighted metric's h1, so metrics all scaled by 2^k give the mean
/// scaled by 2^k, bit for bit. `weights`: one per metric, finite >= 0, not all 0.
/// @throws InputError on a bad weight or a size mismatch.
/// With `memo`, the exponential is taken through it (the same result).
Metric2 log_euclidean_mean(std::span<const Metric2> metrics, std::span<const double> weights,
                           MetricFromLogFormMemo* memo = nullptr);

/// The components of v in the frame where M is the identity: ((c vx + s vy) / h1,
/// (-s vx + c vy) / h2). Metrics and vectors scaled together by 2^k give the same bits.
void metric_map(const Metric2& metric, double vx, double vy, double& a, double& b);

/// sqrt(v^T M v), computed as hypot of metric_map's components: no squared length.
double metric_length(const Metric2& metric, double vx, double vy);

/// out = {M11, M12, M22} of (h_min^2) M, whose largest eigenvalue is 1 and smallest
/// (h_min / h_max)^2 >= 2^-500: no overflow or underflow at any scale. The in-ellipse predicate's
/// sign is unchanged by the positive factor h_min^2. The doubles are positive definite
/// (M11 M22 - M12^2 > 0 exactly): rounding keeps a rotated metric's small eigenvalue only to
/// within about 2^-53 of the large one, so beyond an aspect ratio of about 2^26 (not aligned
/// with the axes) M22 is raised by an ulp or two and the predicate sees a metric of aspect ratio
/// about 2^26 in that direction; axis-aligned metrics are exact up to 2^250.
void matrix_for_predicate(const Metric2& metric, double out[3]);

/// The intersection of two metrics: the metric of the largest ellipse contained in both unit
/// ellipses {v: l_a(v) <= 1} and {v: l_b(v) <= 1}, by simultaneous reduction (in the frame where
/// `a` is the identity, `b`'s principal sizes are cut to at most 1). When b's ellipse contains
/// a's to within the relative `tolerance` in every direction, returns `a` unchanged (so
/// iterations such as gradation reach an exact fixed point).
/// @throws InputError when the result's aspect ratio exceeds kMaxAspectRatio.
Metric2 metric_intersection(const Metric2& a, const Metric2& b, double tolerance = 0);

}  // namespace exactmesh::generators
