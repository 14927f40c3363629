// SPDX-License-Identifier: MIT
// Correctly rounded circumcenters and segment intersections: an expansion fast path certified by
// exact midpoint sign tests [Shewchuk97 §2, Ziv91], and a GMP + MPFR exact path (see the header).
// Every quotient num / den below comes from Cramer's rule on the bisector equations
// 2 (p - q) . X = |p|^2 - |q|^2 (circumcenters) or from X = a + t (b - a) with orient2d(c, d, X)
// = 0 (intersections), written in the raw doubles or in exact differences, so it is the exact
// construction. Expansion safety of the translated forms: an exact difference p - p0 has no set
// bit below those of p and p0 and is at most 2^332 (2D) or 2^249 (3D) in magnitude, which keeps
// every sum and product below 2^1002, far from overflow, as in the raw forms.
#include "predicates/constructions.hpp"

#include <gmpxx.h>
#include <mpfr.h>

#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <initializer_list>
#include <limits>
#include <optional>
#include <string>

#include "base/errors.hpp"
#include "base/number_text.hpp"
#include "predicates/exact_range.hpp"
#include "predicates/expansion.hpp"
#include "predicates/orient2d.hpp"
#include "predicates/orient3d.hpp"

namespace exactmesh::predicates {

namespace {

thread_local ConstructionStats this_thread_stats;

// ---------------------------------------------------------------------------------------------
// Errors: every message names the construction, the problem and the points (format_point:
// shortest round trip).

std::string format_points(std::initializer_list<const double*> points, int dimension) {
    std::string text;
    for (const double* p : points) text += (text.empty() ? "" : ", ") + format_point(p, dimension);
    return text;
}

[[noreturn]] void fail(const char* construction, const char* problem,
                       std::initializer_list<const double*> points, int dimension,
                       SourceLocation where = SourceLocation::current()) {
    throw GeometryError(
        std::string(construction) + ": " + problem + ": " + format_points(points, dimension),
        where);
}

void require_finite_points(const char* construction, std::initializer_list<const double*> points,
                           int dimension) {
    for (const double* p : points) {
        for (int k = 0; k < dimension; ++k) {
            if (!std::isfinite(p[k])) {
                fail(construction, "non-finite coordinate", points, dimension);
            }
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Exact path: GMP rationals, one rounding by MPFR.

/// Narrows MPFR's exponent range to binary64's for the lifetime of the object and restores the
/// caller's range afterwards (exceptions included). MPFR mantissas lie in [1/2, 1), so
/// DBL_MAX = (1 - 2^-53) 2^1024 gives emax = 1024 and 2^-1074 = 2^-1 2^-1073 gives emin = -1073.
/// Debian's MPFR is built with thread-local state, so other threads are not affected.
class DoubleExponentRange {
  public:
    DoubleExponentRange() noexcept : emin_(mpfr_get_emin()), emax_(mpfr_get_emax()) {
        mpfr_set_emin(-1073);
        mpfr_set_emax(1024);
    }
    ~DoubleExponentRange() {
        mpfr_set_emin(emin_);
        mpfr_set_emax(emax_);
    }
    DoubleExponentRange(const DoubleExponentRange&) = delete;
    DoubleExponentRange& operator=(const DoubleExponentRange&) = delete;

  private:
    mpfr_exp_t emin_;
    mpfr_exp_t emax_;
};

/// v rounded to the nearest double, ties to even, subnormals rounded once (mpfr_subnormalize
/// re-rounds with the ternary value of the first rounding, so there is no double rounding).
/// Returns false when the rounded value is infinite (|v| >= DBL_MAX + ulp(DBL_MAX) / 2).
bool round_to_double(const mpq_class& v, double& result) {
    if (sgn(v) == 0) {
        result = 0.0;
        return true;
    }
    const DoubleExponentRange range;
    mpfr_t x;
    mpfr_init2(x, 53);
    int ternary = mpfr_set_q(x, v.get_mpq_t(), MPFR_RNDN);
    ternary = mpfr_subnormalize(x, ternary, MPFR_RNDN);
    static_cast<void>(ternary);
    const bool overflow = mpfr_inf_p(x) != 0;
    result = mpfr_get_d(x, MPFR_RNDN);  // exact: x is a binary64 value now
    mpfr_clear(x);
    return !overflow;
}

mpq_class det3(const mpq_class m[3][3]) {
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
           m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

/// Finite, non-collinear input. Origin at c: 2 (p - c) . u = |p - c|^2 for p = a, b.
std::array<double, 2> circumcenter2_rational(const double* a, const double* b, const double* c) {
    const mpq_class ax = mpq_class(a[0]) - c[0], ay = mpq_class(a[1]) - c[1];
    const mpq_class bx = mpq_class(b[0]) - c[0], by = mpq_class(b[1]) - c[1];
    const mpq_class wa = ax * ax + ay * ay, wb = bx * bx + by * by;
    const mpq_class twice_det = 2 * (ax * by - ay * bx);
    const mpq_class x = c[0] + (wa * by - wb * ay) / twice_det;
    const mpq_class y = c[1] + (ax * wb - bx * wa) / twice_det;
    std::array<double, 2> result;
    if (!round_to_double(x, result[0]) || !round_to_double(y, result[1])) {
        fail("circumcenter", "the circumcenter overflows the double range", {a, b, c}, 2);
    }
    return result;
}

/// origin + the solution of M x = w by Cramer's rule (det = det3(M), nonzero), each coordinate
/// rounded once; false when one overflows the double range.
bool cramer_rounded(const mpq_class m[3][3], const mpq_class w[3], const mpq_class& det,
                    const double* origin, std::array<double, 3>& result) {
    for (int k = 0; k < 3; ++k) {
        mpq_class mk[3][3];
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) mk[i][j] = j == k ? w[i] : m[i][j];
        }
        const mpq_class coordinate = origin[k] + det3(mk) / det;
        if (!round_to_double(coordinate, result[static_cast<unsigned>(k)])) return false;
    }
    return true;
}

/// Finite, non-coplanar input. Origin at d; Cramer's rule on 2 P u = w, P's rows p - d.
std::array<double, 3> circumcenter3_rational(const double* a, const double* b, const double* c,
                                             const double* d) {
    const double* rows[3] = {a, b, c};
    mpq_class p[3][3], w[3];
    for (int r = 0; r < 3; ++r) {
        for (int k = 0; k < 3; ++k) p[r][k] = mpq_class(rows[r][k]) - d[k];
        w[r] = p[r][0] * p[r][0] + p[r][1] * p[r][1] + p[r][2] * p[r][2];
    }
    const mpq_class twice_det = 2 * det3(p);
    std::array<double, 3> result;
    if (!cramer_rounded(p, w, twice_det, d, result))
        fail("circumcenter", "the circumcenter overflows the double range", {a, b, c, d}, 3);
    return result;
}

/// Finite input, u x v != 0 (checked by the caller).
std::array<double, 3> triangle_circumcenter3_rational(const double* a, const double* b,
                                                      const double* c) {
    mpq_class u[3], v[3];
    for (int k = 0; k < 3; ++k) {
        u[k] = mpq_class(a[k]) - c[k];
        v[k] = mpq_class(b[k]) - c[k];
    }
    const mpq_class w[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                            u[0] * v[1] - u[1] * v[0]};
    const mpq_class uu = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
    const mpq_class vv = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
    const mpq_class ww = w[0] * w[0] + w[1] * w[1] + w[2] * w[2];
    if (sgn(ww) == 0) fail("circumcenter", "the points are collinear", {a, b, c}, 3);
    mpq_class s[3];
    for (int k = 0; k < 3; ++k) s[k] = uu * v[k] - vv * u[k];
    const mpq_class n[3] = {s[1] * w[2] - s[2] * w[1], s[2] * w[0] - s[0] * w[2],
                            s[0] * w[1] - s[1] * w[0]};
    const mpq_class twice_ww = 2 * ww;
    std::array<double, 3> result;
    for (int k = 0; k < 3; ++k) {
        const mpq_class coordinate = c[k] + n[k] / twice_ww;
        if (!round_to_double(coordinate, result[static_cast<unsigned>(k)])) {
            fail("circumcenter", "the circumcenter overflows the double range", {a, b, c}, 3);
        }
    }
    return result;
}

/// orient2d(p, q, r) in rationals: (q - p) x (r - p).
mpq_class orient2d_rational(const double* p, const double* q, const double* r) {
    return (mpq_class(q[0]) - p[0]) * (mpq_class(r[1]) - p[1]) -
           (mpq_class(q[1]) - p[1]) * (mpq_class(r[0]) - p[0]);
}

/// Non-parallel lines: X = a + t (b - a) with orient(c, d, X) = 0, which is affine in X, so
/// t = o_a / (o_a - o_b) and X = (o_a b - o_b a) / (o_a - o_b), o_p = orient2d(c, d, p).
std::array<double, 2> segment_intersection_rational(const double* a, const double* b,
                                                    const double* c, const double* d) {
    const mpq_class oa = orient2d_rational(c, d, a), ob = orient2d_rational(c, d, b);
    const mpq_class den = oa - ob;
    std::array<double, 2> result;
    for (unsigned k = 0; k < 2; ++k) {
        const mpq_class coordinate = (oa * b[k] - ob * a[k]) / den;
        if (!round_to_double(coordinate, result[k])) {
            // Unreachable for a point on [a, b]; kept so that no path can return infinity.
            fail("segment_intersection", "the intersection overflows the double range",
                 {a, b, c, d}, 2);
        }
    }
    return result;
}

// ---------------------------------------------------------------------------------------------
// Fast path: exact expansions for num and den, a double candidate, exact midpoint certification.

/// e * 2, exact (no overflow in the expansion-safe range).
template <int N>
Expansion<N> twice(Expansion<N> e) noexcept {
    for (int i = 0; i < e.length; ++i) e.components[static_cast<unsigned>(i)] *= 2.0;
    return e;
}

/// p_u q_v - q_u p_v exactly.
Expansion<4> minor_uv(const double* p, const double* q, int u, int v) noexcept {
    return exact_product(p[u], q[v]) - exact_product(q[u], p[v]);
}

/// det [u v 1] over rows p, q, r, expanded along the column of ones.
Expansion<12> det_uv1(const double* p, const double* q, const double* r, int u, int v) noexcept {
    return minor_uv(p, q, u, v) + minor_uv(q, r, u, v) + minor_uv(r, p, u, v);
}

/// det [x y z] of rows p, q, r, expanded along z.
Expansion<24> det_xyz(const double* p, const double* q, const double* r) noexcept {
    return scale(minor_uv(q, r, 0, 1), p[2]) - scale(minor_uv(p, r, 0, 1), q[2]) +
           scale(minor_uv(p, q, 0, 1), r[2]);
}

/// |p|^2 * e exactly in 2D, as p_x^2 e + p_y^2 e (no rounded square is ever formed).
template <int A>
Expansion<8 * A> times_norm2(const Expansion<A>& e, const double* p) noexcept {
    return scale_twice(e, p[0]) + scale_twice(e, p[1]);
}

/// |p|^2 * e exactly in 3D.
template <int A>
Expansion<12 * A> times_norm3(const Expansion<A>& e, const double* p) noexcept {
    return scale_twice(e, p[0]) + scale_twice(e, p[1]) + scale_twice(e, p[2]);
}

/// det [w u] over rows p, q (already translated) with w = |p|^2.
Expansion<16> det_w_u(const double* p, const double* q, int u) noexcept {
    return times_norm2(expansion_of(q[u]), p) - times_norm2(expansion_of(p[u]), q);
}

/// det [w u 1] over rows a, b, c with w = |p|^2, expanded along w.
Expansion<48> det_w_u1(const double* a, const double* b, const double* c, int u) noexcept {
    return times_norm2(exact_difference(b[u], c[u]), a) -
           times_norm2(exact_difference(a[u], c[u]), b) +
           times_norm2(exact_difference(a[u], b[u]), c);
}

/// det [w u v 1] over rows a, b, c, d with w = |p|^2, expanded along w.
Expansion<576> det_w_uv1(const double* a, const double* b, const double* c, const double* d, int u,
                         int v) noexcept {
    return (times_norm3(det_uv1(b, c, d, u, v), a) - times_norm3(det_uv1(a, c, d, u, v), b)) +
           (times_norm3(det_uv1(a, b, d, u, v), c) - times_norm3(det_uv1(a, b, c, u, v), d));
}

/// det [w u v] over rows p, q, r (already translated) with w = |p|^2, expanded along w.
Expansion<144> det_w_uv(const double* p, const double* q, const double* r, int u, int v) noexcept {
    return times_norm3(minor_uv(q, r, u, v), p) - times_norm3(minor_uv(p, r, u, v), q) +
           times_norm3(minor_uv(p, q, u, v), r);
}

/// How a fast-path coordinate ended.
enum class Certification { Certified, OutOfRange, Uncertified };

struct Quotient {
    Certification status = Certification::Uncertified;
    double value = 0.0;
    bool neighbour = false;  ///< certified at the neighbour of the first candidate
};

/// Below this magnitude the candidate's half-ulps are left to the exact path; far above the
/// subnormal range, so halving an ulp is exact and never yields zero.
constexpr double kMinCandidate = 0x1p-500;

/// detail::expansion_safe's condition (|x| <= 2^(1000/degree - 2), degree * lowest set bit
/// >= -1074) for the doubles the fast path derives itself, read from the bits instead of by
/// exact_range.hpp's bit-by-bit loop, which runs 52 times on the powers of two (half-ulps)
/// checked here. Subnormals are refused. Together with expansion_safe over the inputs this is
/// expansion_safe over all values, since both bounds are checked value by value.
bool derived_values_safe(int degree, std::initializer_list<double> values) noexcept {
    const double max_magnitude = std::ldexp(1.0, 1000 / degree - 2);
    for (const double x : values) {
        if (x == 0.0) continue;
        if (!(std::fabs(x) <= max_magnitude)) return false;  // NaN and infinity too
        const auto bits = std::bit_cast<std::uint64_t>(x);
        const int biased_exponent = static_cast<int>((bits >> 52) & 0x7ffu);
        if (biased_exponent == 0) return false;
        const std::uint64_t significand = (bits & ((std::uint64_t{1} << 52) - 1)) |
                                          (std::uint64_t{1} << 52);  // x = significand 2^(e-1075)
        const int lowest = biased_exponent - 1075 + std::countr_zero(significand);
        if (degree * lowest < -1074) return false;
    }
    return true;
}

/// The double with the even significand among two adjacent doubles (one of them always is:
/// adjacent significands are consecutive integers, or 2^53 - 1 and 2^52 across a binade).
double even_of(double x, double y) noexcept {
    return (std::bit_cast<std::uint64_t>(x) & 1u) == 0u ? x : y;
}

/// The exact quotient v = num / den, kept as q0 + residual / den with residual = num - q0 den
/// exact, so that comparisons near q0 work on the small residual (one short expansion per test)
/// rather than on num.
template <int N, int D>
struct ExactQuotient {
    const Expansion<N>& num;
    const Expansion<D>& den;
    int den_sign;
    int degree;
    double q0;
    Expansion<N + 2 * D> residual;

    /// sign(v - (q + half)) exactly; q and half are expansion-safe (checked by the caller).
    int side_of_midpoint(double q, double half) const noexcept {
        // m - q0 = (q - q0) + half is usually one double (q is within a few ulps of q0);
        // then v - m = (residual - (m - q0) den) / den.
        double step, step_tail, offset, offset_tail;
        two_diff(q, q0, step, step_tail);
        two_sum(step, half, offset, offset_tail);
        if (step_tail == 0.0 && offset_tail == 0.0 && derived_values_safe(degree, {offset})) {
            return to_int((residual - scale(den, offset)).sign()) * den_sign;
        }
        return to_int((num - (scale(den, q) + scale(den, half))).sign()) * den_sign;
    }
};

/// The double nearest to num / den (ties to even), certified, or the reason it is not.
/// `degree` is the degree of num (and of den * candidate) in the inputs, whose expansion
/// safety the caller has checked; every double that multiplies den here is checked too, which
/// together with the inputs is exactly detail::expansion_safe over all of them.
/// q is correct iff m_below < v < m_above, or v is a midpoint and q the even neighbour.
template <int N, int D>
Quotient certified_quotient(const Expansion<N>& num, const Expansion<D>& den, int degree) noexcept {
    if (num.length == 0) return {Certification::Certified, 0.0, false};
    const double q0 = num.approximate() / den.approximate();
    // NaN and infinity fail both tests.
    if (!(std::fabs(q0) >= kMinCandidate) || !derived_values_safe(degree, {q0})) {
        return {Certification::OutOfRange, 0.0, false};
    }
    const ExactQuotient<N, D> v{num, den, to_int(den.sign()), degree, q0, num - scale(den, q0)};
    if (v.residual.length == 0) return {Certification::Certified, q0, false};  // v == q0
    // q0 carries up to about two ulps of error from the three roundings; the residual turns
    // it into a double-double q0 + delta accurate to ~2^-100, whose rounding q is the nearest
    // double unless v lies within that distance of a midpoint [Shewchuk97 §2.8, Ziv91].
    double q = q0 + v.residual.approximate() / den.approximate();
    // After a step to a neighbour, the midpoint between it and the previous candidate is
    // already known to be on the right side, so only the far midpoint is tested.
    bool below_known = false, above_known = false;
    for (int attempt = 0; attempt < 2; ++attempt) {
        const bool neighbour = attempt > 0;
        if (!(std::fabs(q) >= kMinCandidate)) return {Certification::OutOfRange, 0.0, false};
        const double below = std::nextafter(q, -std::numeric_limits<double>::infinity());
        const double above = std::nextafter(q, std::numeric_limits<double>::infinity());
        // Adjacent doubles differ by an exactly representable ulp; at a binade boundary the
        // ulp below is half the ulp above, which these differences capture on their own.
        const double half_below = (below - q) * 0.5, half_above = (above - q) * 0.5;
        if (!derived_values_safe(degree, {q, half_below, half_above})) {
            return {Certification::OutOfRange, 0.0, false};
        }
        if (!below_known) {
            const int side = v.side_of_midpoint(q, half_below);
            if (side == 0) return {Certification::Certified, even_of(below, q), neighbour};
            if (side < 0) {
                q = below;
                above_known = true;
                continue;
            }
        }
        if (!above_known) {
            const int side = v.side_of_midpoint(q, half_above);
            if (side == 0) return {Certification::Certified, even_of(q, above), neighbour};
            if (side > 0) {
                q = above;
                below_known = true;
                continue;
            }
        }
        return {Certification::Certified, q, neighbour};
    }
    return {Certification::Uncertified, 0.0, false};
}

/// Runs the fast path for each coordinate in turn and records the outcome. Returns true when
/// every coordinate was certified; otherwise the caller takes the exact path.
class FastPath {
  public:
    template <int N, int D>
    bool certify(const Expansion<N>& num, const Expansion<D>& den, int degree, double& result) {
        const Quotient quotient = certified_quotient(num, den, degree);
        if (quotient.status == Certification::OutOfRange) status_ = Certification::OutOfRange;
        if (quotient.status == Certification::Uncertified) status_ = Certification::Uncertified;
        if (quotient.status != Certification::Certified) return false;
        neighbour_steps_ += quotient.neighbour ? 1u : 0u;
        result = quotient.value;
        return true;
    }
    /// Counts a call whose coordinates were all certified.
    void count_fast() const noexcept {
        ++this_thread_stats.calls;
        ++this_thread_stats.fast;
        this_thread_stats.neighbour_steps += neighbour_steps_;
    }
    /// Counts a call that went to the exact path after a fast-path attempt.
    void count_exact() const noexcept { count_exact_path(status_); }

    static void count_exact_path(Certification reason) noexcept {
        ++this_thread_stats.calls;
        if (reason == Certification::Uncertified) {
            ++this_thread_stats.exact_uncertified;
        } else {
            ++this_thread_stats.exact_range;
        }
    }

  private:
    Certification status_ = Certification::Certified;
    std::uint64_t neighbour_steps_ = 0;
};

// ---------------------------------------------------------------------------------------------
// Stage 0 of the 2D circumcenter (exact differences only): double-double arithmetic with a
// proven error bound, certified when the exact value cannot lie beyond either midpoint of the
// candidate; else the expansion fast path decides. With u = 2^-53, for the differences
// p = a - c, q = b - c (exact doubles), H = (p_x q_y - p_y q_x) and N = |p|^2 q_y - |q|^2 p_y
// (x; y alike with N = |q|^2 p_x - |p|^2 q_x), every product is split exactly (two_product)
// and every sum of the exact parts is rounded at most twice, which bounds
//  - |H~ - H| <= 3.1 u^2 P_H,  P_H = |p_x q_y| + |p_y q_x|           (three roundings of tails)
//  - |N~ - N| <= 11 u^2 P_N,   P_N = |p|^2 |q_y| + |q|^2 |p_y|       (norms 3.1, products 3.2,
//                                                                     difference 4.3)
//  - the dd quotient Q~ of N~ / H~: |Q~ - N~/H~| <= 25 u^2 |Q|        (one remainder step)
//  - x~ = c + Q~ / 2: one more rounding, u^2 (|x| + |Q| / 2),
// so |x~ - x| <= u^2 (13 |Q| + (5.5 P_N + 1.6 |Q| P_H) / |H| + 2 |x|) to first order; the
// filter uses E = 2^-100 (|Q| + (P_N + |Q| P_H) / |H| + |x|), over four times that, which also
// covers the second-order terms and the rounding of E itself. x~ = x_hi + x_lo with x_lo at
// most half an ulp of x_hi; x_hi is the correctly rounded x when |x_lo| + E stays below both
// half-ulps about x_hi. Range: every nonzero difference in [2^-300, 2^300] (no product or
// error term underflows or overflows), |H| >= 2^-500 and > 2^-40 P_H, |Q| and |x_hi| in
// [2^-400, 2^400] (so |N| >= 2^-900: every error term above stays normal); else no filter.

namespace {

struct DoubleDouble {
    double hi, lo;
};

/// v is 0 or its magnitude is within [1 / limit, limit] (limit a power of two).
bool in_filter_range(double v, double limit = 0x1p300) noexcept {
    const double m = std::fabs(v);
    return m == 0.0 || (m >= 1 / limit && m <= limit);
}

/// x + y == a * b exactly, x = fl(a * b): two_product (Dekker's), or with kFma one fused
/// multiply-add, exact in the same range (the tail a b - x is a double whenever it does not
/// underflow, which the stages' range guards ensure), so both give the same bits. kFma only in
/// functions compiled for FMA (circumcenter2_double_double_fma), chosen at run time.
template <bool kFma>
[[gnu::always_inline]] inline void exact_product(double a, double b, double& x,
                                                 double& y) noexcept {
    if constexpr (kFma) {
        x = a * b;
        y = __builtin_fma(a, b, -x);
    } else {
        two_product(a, b, x, y);
    }
}

/// a b + c d (sign +1) or a b - c d (sign -1), as hi + lo within 3.1 u^2 (|ab| + |cd|).
template <bool kFma = false>
DoubleDouble sum_of_products(double a, double b, double c, double d, double sign) noexcept {
    double p, pe, q, qe, s, se;
    exact_product<kFma>(a, b, p, pe);
    exact_product<kFma>(c, d, q, qe);
    two_sum(p, sign * q, s, se);
    const double tail = se + (pe + sign * qe);
    DoubleDouble r;
    two_sum(s, tail, r.hi, r.lo);
    return r;
}

/// (A_hi + A_lo) b, within 3.2 u^2 |A b| beyond A's own error times |b|.
template <bool kFma = false>
DoubleDouble times(const DoubleDouble& a, double b) noexcept {
    double m, me;
    exact_product<kFma>(a.hi, b, m, me);
    DoubleDouble r;
    two_sum(m, me + a.lo * b, r.hi, r.lo);
    return r;
}

/// x + y, within 3.1 u^2 (|x| + |y|) beyond the operands' errors.
DoubleDouble plus(const DoubleDouble& x, const DoubleDouble& y) noexcept {
    double s, se;
    two_sum(x.hi, y.hi, s, se);
    DoubleDouble r;
    two_sum(s, se + (x.lo + y.lo), r.hi, r.lo);
    return r;
}

/// x - y: plus with y negated (the same roundings as subtracting each part).
DoubleDouble minus(const DoubleDouble& x, const DoubleDouble& y) noexcept {
    return plus(x, DoubleDouble{-y.hi, -y.lo});
}

/// One coordinate: c + N / (2 H); false when not certified (then nothing is known).
template <bool kFma = false>
bool certify_dd(double c, const DoubleDouble& n, double pn, const DoubleDouble& h, double ph,
                double& result) noexcept {
    // Q = N / H: q1 from the high parts, one exact-ish remainder step.
    const double q1 = n.hi / h.hi;
    if (!(std::fabs(q1) >= 0x1p-400 && std::fabs(q1) <= 0x1p400)) return false;
    double p, pe;
    exact_product<kFma>(q1, h.hi, p, pe);
    const double remainder = ((n.hi - p) - pe) + (n.lo - q1 * h.lo);
    const double q2 = remainder / h.hi;
    double q_hi, q_lo;
    two_sum(q1, q2, q_hi, q_lo);
    // x = c + Q / 2 (halving is exact in range).
    double s, se;
    two_sum(c, 0.5 * q_hi, s, se);
    double x_hi, x_lo;
    two_sum(s, se + 0.5 * q_lo, x_hi, x_lo);
    if (!(std::fabs(x_hi) >= 0x1p-400 && std::fabs(x_hi) <= 0x1p400)) return false;
    const double abs_q = std::fabs(q_hi), abs_h = std::fabs(h.hi);
    const double bound = 0x1p-100 * (abs_q + (pn + abs_q * ph) / abs_h + std::fabs(x_hi));
    // The half-ulps about x_hi to its two neighbours (x_hi is normal here: |x_hi| in
    // [2^-400, 2^400]), from the bits: the neighbour away from zero is the next bit pattern,
    // the one towards zero the previous (the same doubles as std::nextafter, a library call
    // that was an eighth of a refinement's circumcenter cost). Both differences are exact.
    const auto bits = std::bit_cast<std::uint64_t>(x_hi);
    const double away = std::bit_cast<double>(bits + 1), toward = std::bit_cast<double>(bits - 1);
    const double half_away = 0.5 * std::fabs(away - x_hi);
    const double half_toward = 0.5 * std::fabs(x_hi - toward);
    if (!(std::fabs(x_lo) + bound < 0.999 * std::min(half_away, half_toward))) return false;
    result = x_hi;
    return true;
}

/// Stage 0 for exact differences p = a - c, q = b - c; true with both coordinates certified.
template <bool kFma = false>
bool circumcenter2_double_double(const double* p, const double* q, const double* c,
                                 std::array<double, 2>& result) noexcept {
    for (const double v : {p[0], p[1], q[0], q[1]}) {
        if (!in_filter_range(v)) return false;
    }
    const DoubleDouble h = sum_of_products<kFma>(p[0], q[1], p[1], q[0], -1.0);
    const double ph = std::fabs(p[0] * q[1]) + std::fabs(p[1] * q[0]);
    // Nearly collinear (the bound's 1 / |H| grows) or |H| small enough that |N| = |Q H| could
    // leave the normal range: the exact stages decide.
    if (!(std::fabs(h.hi) > 0x1p-40 * ph) || !(std::fabs(h.hi) >= 0x1p-500)) return false;
    const DoubleDouble p_norm = sum_of_products<kFma>(p[0], p[0], p[1], p[1], 1.0);
    const DoubleDouble q_norm = sum_of_products<kFma>(q[0], q[0], q[1], q[1], 1.0);
    const DoubleDouble nx = minus(times<kFma>(p_norm, q[1]), times<kFma>(q_norm, p[1]));
    const double pnx = p_norm.hi * std::fabs(q[1]) + q_norm.hi * std::fabs(p[1]);
    const DoubleDouble ny = minus(times<kFma>(q_norm, p[0]), times<kFma>(p_norm, q[0]));
    const double pny = q_norm.hi * std::fabs(p[0]) + p_norm.hi * std::fabs(q[0]);
    return certify_dd<kFma>(c[0], nx, pnx, h, ph, result[0]) &&
           certify_dd<kFma>(c[1], ny, pny, h, ph, result[1]);
}

/// The stage with Dekker's products, its helpers inlined (flatten): without the calls of its
/// five helpers a circumcenter takes about 1,010 instructions instead of 1,060.
[[gnu::flatten]] bool circumcenter2_double_double_dekker(const double* p, const double* q,
                                                         const double* c,
                                                         std::array<double, 2>& result) noexcept {
    return circumcenter2_double_double<false>(p, q, c, result);
}

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
// Runtime dispatch (the build targets every x86-64, so FMA is not assumed): the stage with its
// twelve exact products as fused multiply-adds, everything else the same double operations (the
// predicates keep -ffp-contract=off, so nothing else is fused), compiled for FMA here alone and
// called only where the CPU has it. Dekker's product costs about 17 instructions, the FMA 2: a
// circumcenter takes about 540 instructions instead of 1,010 (random small triangles; 564
// instead of 1,083 in a refinement, where the stage certifies 99%).
[[gnu::target("fma"), gnu::flatten]] bool circumcenter2_double_double_fma(
    const double* p, const double* q, const double* c, std::array<double, 2>& result) noexcept {
    return circumcenter2_double_double<true>(p, q, c, result);
}

bool cpu_has_fma() noexcept {
    static const bool has_fma = __builtin_cpu_supports("fma") != 0;
    return has_fma;
}
#else
bool circumcenter2_double_double_fma(const double* p, const double* q, const double* c,
                                     std::array<double, 2>& result) noexcept {
    return circumcenter2_double_double_dekker(p, q, c, result);
}

bool cpu_has_fma() noexcept {
    return false;
}
#endif

// ---------------------------------------------------------------------------------------------
// Stage 0 of the 3D circumcenter (exact differences p = a - d, q = b - d, r = c - d): the same
// double-double scheme. X = d + N / (2 H), H = p . (q x r), N = |p|^2 (q x r) + |q|^2 (r x p) +
// |r|^2 (p x q) (Cramer's rule: the adjugate's columns are the three cross products). With
// u = 2^-53 and the helpers' bounds (sum_of_products 3.1 u^2 (|ab| + |cd|); times 3.2 u^2 |A b|;
// plus 3.1 u^2 (|x| + |y|); times_dd 8.1 u^2 |A B|; norm3 6.3 u^2 |p|^2; each beyond the
// operands' own errors carried through), to first order:
//  - each cross product's coordinate C_k within 3.1 u^2 P_Ck, P_Ck = |q_y r_z| + |q_z r_y| (etc.);
//  - |H~ - H| <= 12.5 u^2 P_H, P_H = sum |p_k| P_Ck (products 6.3, two sums 6.2);
//  - |N~_k - N_k| <= 23.7 u^2 P_Nk, P_Nk = |p|^2 P_Ck + |q|^2 P_Dk + |r|^2 P_Ek (products
//    8.1 + 6.3 + 3.1, two sums 6.2);
// so with certify_dd's quotient (25 u^2 |Q|, halved) and final rounding (2 u^2 |x|),
// |x~ - x| <= u^2 (13 |Q| + (11.9 P_N + 6.3 |Q| P_H) / |H| + 2 |x|): certify_dd's
// E = 2^-100 (|Q| + (P_N + |Q| P_H) / |H| + |x|) is over 4.9 times every term. Range: every
// nonzero difference in [2^-150, 2^150]: they are multiples of 2^-202, so every nonzero product
// of two and every cross product is a multiple of 2^-404 and every product the scheme forms is
// 0 or above 2^-808 (normal: every two_product exact, every rounding relative), none above
// 2^610; |H| >= 2^-500 and > 2^-40 P_H (second-order terms negligible); certify_dd's ranges.

/// A B for double-doubles, within 8.1 u^2 |A B| beyond the operands' errors.
DoubleDouble times_dd(const DoubleDouble& a, const DoubleDouble& b) noexcept {
    double m, me;
    two_product(a.hi, b.hi, m, me);
    DoubleDouble r;
    two_sum(m, me + (a.hi * b.lo + a.lo * b.hi), r.hi, r.lo);
    return r;
}

/// |p|^2 within 6.3 u^2 |p|^2.
DoubleDouble norm3(const double* p) noexcept {
    double z, ze;
    two_product(p[2], p[2], z, ze);
    return plus(sum_of_products(p[0], p[0], p[1], p[1], 1.0), DoubleDouble{z, ze});
}

/// x cross y, each coordinate within 3.1 u^2 of its permanent (`permanent`).
void cross_dd(const double* x, const double* y, DoubleDouble* out, double* permanent) noexcept {
    for (int k = 0; k < 3; ++k) {
        const int i = (k + 1) % 3, j = (k + 2) % 3;
        out[k] = sum_of_products(x[i], y[j], x[j], y[i], -1.0);
        permanent[k] = std::fabs(x[i] * y[j]) + std::fabs(x[j] * y[i]);
    }
}

/// Cramer's rule's pieces for X = d + N / (2 H) (see above): the cross products q x r, r x p,
/// p x q with their permanents, |p|^2, |q|^2, |r|^2, and H with its permanent.
struct Cramer3 {
    DoubleDouble c[3], e[3], f[3];
    double pc[3], pe[3], pf[3];
    DoubleDouble np, nq, nr;
    DoubleDouble h;
    double ph;
};

/// The three coordinates of d + N / (2 H), each by certify_dd; false unless H is far enough
/// from 0 (the ranges above) and every coordinate is certified.
bool certify_cramer3(const double* d, const Cramer3& m, std::array<double, 3>& result) noexcept {
    if (!(std::fabs(m.h.hi) > 0x1p-40 * m.ph) || !(std::fabs(m.h.hi) >= 0x1p-500)) return false;
    for (int k = 0; k < 3; ++k) {
        const DoubleDouble n =
            plus(plus(times_dd(m.np, m.c[k]), times_dd(m.nq, m.e[k])), times_dd(m.nr, m.f[k]));
        const double pn = m.np.hi * m.pc[k] + m.nq.hi * m.pe[k] + m.nr.hi * m.pf[k];
        if (!certify_dd(d[k], n, pn, m.h, m.ph, result[static_cast<std::size_t>(k)])) return false;
    }
    return true;
}

/// Stage 0 for exact differences p = a - d, q = b - d, r = c - d; true with all three
/// coordinates certified.
bool circumcenter3_double_double(const double* p, const double* q, const double* r, const double* d,
                                 std::array<double, 3>& result) noexcept {
    for (const double* v : {p, q, r}) {
        for (int k = 0; k < 3; ++k) {
            if (!in_filter_range(v[k], 0x1p150)) return false;
        }
    }
    Cramer3 m;
    cross_dd(q, r, m.c, m.pc);
    cross_dd(r, p, m.e, m.pe);
    cross_dd(p, q, m.f, m.pf);
    m.h = plus(plus(times(m.c[0], p[0]), times(m.c[1], p[1])), times(m.c[2], p[2]));
    m.ph = std::fabs(p[0]) * m.pc[0] + std::fabs(p[1]) * m.pc[1] + std::fabs(p[2]) * m.pc[2];
    m.np = norm3(p);
    m.nq = norm3(q);
    m.nr = norm3(r);
    return certify_cramer3(d, m, result);
}

// ---------------------------------------------------------------------------------------------
// Stage 0 for differences that are not exact doubles (coordinates of one sign change, or of
// magnitudes more than a factor 2 apart: tetrahedra beside a coordinate plane, a third of the
// wing's circumcentres took the 576-term raw path for that alone). Each difference is kept
// exactly as a double-double p = p_hi + p_lo (two_diff), and the same scheme runs on them with
// double-double products throughout. With the helpers' bounds (times_dd 8.1 u^2 |A B|, plus
// 3.1 u^2 (|x| + |y|), each beyond the operands' own errors carried through), to first order:
//  - C_k = x_i y_j - x_j y_i: two times_dd and one plus, within 11.2 u^2 P_Ck;
//  - |p|^2: three times_dd and two plus, within 14.3 u^2 |p|^2;
//  - H = sum p_k C_k: each product within (8.1 + 11.2) u^2 |p_k| P_Ck, two sums 6.2: 25.5 u^2 P_H;
//  - N_k: each product within (8.1 + 14.3 + 11.2) u^2 |p|^2 P_Ck, two sums 6.2: 39.8 u^2 P_Nk;
// so with certify_dd's quotient (25 u^2 |Q|, halved) and final rounding (2 u^2 |x|),
// |x~ - x| <= u^2 (12.5 |Q| + (19.9 P_N + 12.8 |Q| P_H) / |H| + 2 |x|): certify_dd's
// E = 2^-100 (|Q| + (P_N + |Q| P_H) / |H| + |x|) is over 3.2 times every term (the permanents
// are taken on the high parts, within a factor 1 + 4u of the exact ones). Range: every input
// coordinate 0 or of magnitude in [2^-150, 2^150]: each is a multiple of 2^-202, so are both
// parts of every difference (two_diff's error is exact), and every value the scheme forms is a
// sum of products of at most four of them: 0 or above 2^-808 (normal: every two_product exact,
// every rounding relative), none above 2^610; certify_dd's ranges as before.

/// A double-double difference a - b, exact.
DoubleDouble exact_difference(double a, double b) noexcept {
    DoubleDouble r;
    two_diff(a, b, r.hi, r.lo);
    return r;
}

/// x cross y for double-double vectors, each coordinate within 11.2 u^2 of its permanent.
void cross_dd2(const DoubleDouble* x, const DoubleDouble* y, DoubleDouble* out,
               double* permanent) noexcept {
    for (int k = 0; k < 3; ++k) {
        const int i = (k + 1) % 3, j = (k + 2) % 3;
        out[k] = minus(times_dd(x[i], y[j]), times_dd(x[j], y[i]));
        permanent[k] = std::fabs(x[i].hi * y[j].hi) + std::fabs(x[j].hi * y[i].hi);
    }
}

/// |p|^2 of a double-double vector, within 14.3 u^2 |p|^2.
DoubleDouble norm3_dd(const DoubleDouble* p) noexcept {
    return plus(plus(times_dd(p[0], p[0]), times_dd(p[1], p[1])), times_dd(p[2], p[2]));
}

/// Stage 0 on the inputs themselves (see above); true with all three coordinates certified.
bool circumcenter3_double_double_inexact(const double* a, const double* b, const double* c,
                                         const double* d, std::array<double, 3>& result) noexcept {
    for (const double* v : {a, b, c, d}) {
        for (int k = 0; k < 3; ++k) {
            if (!in_filter_range(v[k], 0x1p150)) return false;
        }
    }
    DoubleDouble p[3], q[3], r[3];
    for (int k = 0; k < 3; ++k) {
        p[k] = exact_difference(a[k], d[k]);
        q[k] = exact_difference(b[k], d[k]);
        r[k] = exact_difference(c[k], d[k]);
    }
    Cramer3 m;
    cross_dd2(q, r, m.c, m.pc);
    cross_dd2(r, p, m.e, m.pe);
    cross_dd2(p, q, m.f, m.pf);
    m.h = plus(plus(times_dd(m.c[0], p[0]), times_dd(m.c[1], p[1])), times_dd(m.c[2], p[2]));
    m.ph =
        std::fabs(p[0].hi) * m.pc[0] + std::fabs(p[1].hi) * m.pc[1] + std::fabs(p[2].hi) * m.pc[2];
    m.np = norm3_dd(p);
    m.nq = norm3_dd(q);
    m.nr = norm3_dd(r);
    return certify_cramer3(d, m, result);
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Input checks shared by the public functions and their _exact variants.

void check_triangle(const double* a, const double* b, const double* c) {
    require_finite_points("circumcenter", {a, b, c}, 2);
    if (orient2d(a, b, c) == Sign::Zero) {
        fail("circumcenter", "the points are collinear", {a, b, c}, 2);
    }
}

void check_tetrahedron(const double* a, const double* b, const double* c, const double* d) {
    require_finite_points("circumcenter", {a, b, c, d}, 3);
    if (orient3d(a, b, c, d) == Sign::Zero) {
        fail("circumcenter", "the points are coplanar", {a, b, c, d}, 3);
    }
}

/// Accepts exactly the configurations documented in the header: the segments share one point
/// and the lines are not parallel. With s_p = orient2d(c, d, p) and t_p = orient2d(a, b, p),
/// that is s_a s_b <= 0 and t_c t_d <= 0, not both s_a and s_b zero.
void check_segments(const double* a, const double* b, const double* c, const double* d) {
    constexpr const char* kName = "segment_intersection";
    require_finite_points(kName, {a, b, c, d}, 2);
    if ((a[0] == b[0] && a[1] == b[1]) || (c[0] == d[0] && c[1] == d[1])) {
        fail(kName, "a segment has zero length", {a, b, c, d}, 2);
    }
    const Sign sa = orient2d(c, d, a), sb = orient2d(c, d, b);
    if (sa == Sign::Zero && sb == Sign::Zero) {
        fail(kName, "the segments are collinear (parallel lines)", {a, b, c, d}, 2);
    }
    if (sa == sb) {
        // Both endpoints strictly on one side of line cd: say whether that is because the
        // lines are parallel ((b - a) x (d - c) == 0, exactly) or because they meet elsewhere.
        const mpq_class cross = (mpq_class(b[0]) - a[0]) * (mpq_class(d[1]) - c[1]) -
                                (mpq_class(b[1]) - a[1]) * (mpq_class(d[0]) - c[0]);
        if (sgn(cross) == 0) fail(kName, "the lines are parallel", {a, b, c, d}, 2);
        fail(kName, "the segments do not intersect", {a, b, c, d}, 2);
    }
    const Sign sc = orient2d(a, b, c), sd = orient2d(a, b, d);
    if (sc != Sign::Zero && sc == sd) {
        fail(kName, "the segments do not intersect", {a, b, c, d}, 2);
    }
}

}  // namespace

// ---------------------------------------------------------------------------------------------

namespace {

/// circumcenter (2D), its double-double stage's products by FMA when use_fma.
std::array<double, 2> circumcenter2(const double* a, const double* b, const double* c,
                                    bool use_fma) {
    std::array<double, 2> result;
    double pa[2], pb[2], tails[4];
    two_diff(a[0], c[0], pa[0], tails[0]);
    two_diff(a[1], c[1], pa[1], tails[1]);
    two_diff(b[0], c[0], pb[0], tails[2]);
    two_diff(b[1], c[1], pb[1], tails[3]);
    const bool exact_differences =
        tails[0] == 0.0 && tails[1] == 0.0 && tails[2] == 0.0 && tails[3] == 0.0;
    // Exact differences (Sterbenz: nearby points): X = c + (det [w' y], det [x w']) / 2D' over
    // the translated rows a - c, b - c, with D' = det [x y] of those rows. The double-double
    // stage goes first, before the input checks: it keeps to its own range (finite differences
    // within [2^-300, 2^300], so finite points, and s = c + Q / 2 within [2^-400, 2^400]) and
    // certifies only when |D'~| > 2^-40 P_H, beyond its error bound 3.1 u^2 P_H, so D' != 0 and
    // the points are not collinear: everything check_triangle and expansion_safe would establish
    // (77 of the 1,160 instructions a refinement's circumcentre cost, orient2d most of them).
    if (exact_differences && (use_fma ? circumcenter2_double_double_fma(pa, pb, c, result)
                                      : circumcenter2_double_double_dekker(pa, pb, c, result))) {
        ++this_thread_stats.calls;
        ++this_thread_stats.fast;
        ++this_thread_stats.double_double;
        return result;
    }
    check_triangle(a, b, c);
    if (!detail::expansion_safe(3, {a[0], a[1], b[0], b[1], c[0], c[1]})) {
        FastPath::count_exact_path(Certification::OutOfRange);
        return circumcenter2_rational(a, b, c);
    }
    FastPath fast;
    if (exact_differences) {
        const Expansion<4> den = twice(minor_uv(pa, pb, 0, 1));
        if (fast.certify(scale(den, c[0]) + det_w_u(pa, pb, 1), den, 3, result[0]) &&
            fast.certify(scale(den, c[1]) - det_w_u(pa, pb, 0), den, 3, result[1])) {
            fast.count_fast();
            return result;
        }
    } else {
        // x = det [w y 1] / (2 det [x y 1]), y = det [x w 1] / (2 det [x y 1]), w = |p|^2.
        const Expansion<12> den = twice(det_uv1(a, b, c, 0, 1));
        if (fast.certify(det_w_u1(a, b, c, 1), den, 3, result[0]) &&
            fast.certify(-det_w_u1(a, b, c, 0), den, 3, result[1])) {
            fast.count_fast();
            return result;
        }
    }
    fast.count_exact();
    return circumcenter2_rational(a, b, c);
}

}  // namespace

std::array<double, 2> circumcenter(const double* a, const double* b, const double* c) {
    return circumcenter2(a, b, c, cpu_has_fma());
}

namespace detail {

std::array<double, 2> circumcenter_without_fma(const double* a, const double* b, const double* c) {
    return circumcenter2(a, b, c, false);
}

bool circumcenter_uses_fma() noexcept {
    return cpu_has_fma();
}

}  // namespace detail

std::array<double, 3> circumcenter(const double* a, const double* b, const double* c,
                                   const double* d) {
    check_tetrahedron(a, b, c, d);
    if (!detail::expansion_safe(
            4, {a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2], d[0], d[1], d[2]})) {
        FastPath::count_exact_path(Certification::OutOfRange);
        return circumcenter3_rational(a, b, c, d);
    }
    FastPath fast;
    std::array<double, 3> result;
    // When every p - d is an exact double (Sterbenz: common for nearby points), the translated
    // form X = d + det [w' u v] / (2 det P') is about four times shorter than the raw 4x4 form.
    double translated[3][3];
    bool exact_differences = true;
    const double* rows[3] = {a, b, c};
    for (unsigned r = 0; r < 3; ++r) {
        for (unsigned k = 0; k < 3; ++k) {
            double tail;
            two_diff(rows[r][k], d[k], translated[r][k], tail);
            exact_differences = exact_differences && tail == 0.0;
        }
    }
    if (exact_differences) {
        const double* pa = translated[0];
        const double* pb = translated[1];
        const double* pc = translated[2];
        if (circumcenter3_double_double(pa, pb, pc, d, result)) {
            ++this_thread_stats.calls;
            ++this_thread_stats.fast;
            ++this_thread_stats.double_double;
            return result;
        }
        const Expansion<24> den = twice(det_xyz(pa, pb, pc));
        if (fast.certify(scale(den, d[0]) + det_w_uv(pa, pb, pc, 1, 2), den, 4, result[0]) &&
            fast.certify(scale(den, d[1]) - det_w_uv(pa, pb, pc, 0, 2), den, 4, result[1]) &&
            fast.certify(scale(den, d[2]) + det_w_uv(pa, pb, pc, 0, 1), den, 4, result[2])) {
            fast.count_fast();
            return result;
        }
    } else {
        if (circumcenter3_double_double_inexact(a, b, c, d, result)) {
            ++this_thread_stats.calls;
            ++this_thread_stats.fast;
            ++this_thread_stats.double_double;
            return result;
        }
        // det [x y z 1] expanded along the column of ones (as in orient3d's stage C).
        const Expansion<96> den =
            twice((det_xyz(a, b, c) - det_xyz(a, b, d)) + (det_xyz(a, c, d) - det_xyz(b, c, d)));
        if (fast.certify(det_w_uv1(a, b, c, d, 1, 2), den, 4, result[0]) &&
            fast.certify(-det_w_uv1(a, b, c, d, 0, 2), den, 4, result[1]) &&
            fast.certify(det_w_uv1(a, b, c, d, 0, 1), den, 4, result[2])) {
            fast.count_fast();
            return result;
        }
    }
    fast.count_exact();
    return circumcenter3_rational(a, b, c, d);
}

std::array<double, 2> segment_intersection(const double* a, const double* b, const double* c,
                                           const double* d) {
    check_segments(a, b, c, d);
    if (!detail::expansion_safe(3, {a[0], a[1], b[0], b[1], c[0], c[1], d[0], d[1]})) {
        FastPath::count_exact_path(Certification::OutOfRange);
        return segment_intersection_rational(a, b, c, d);
    }
    FastPath fast;
    std::array<double, 2> result;
    // X = (o_a b - o_b a) / (o_a - o_b), o_p = orient2d(c, d, p) = det [x y 1] over c, d, p.
    double pb[2], pc[2], pd[2];
    bool exact_differences = true;
    for (unsigned k = 0; k < 2; ++k) {
        double tail_b, tail_c, tail_d;
        two_diff(b[k], a[k], pb[k], tail_b);
        two_diff(c[k], a[k], pc[k], tail_c);
        two_diff(d[k], a[k], pd[k], tail_d);
        exact_differences = exact_differences && tail_b == 0.0 && tail_c == 0.0 && tail_d == 0.0;
    }
    if (exact_differences) {
        // Origin at a (p' = p - a exact): o_a = c' x d', o_a - o_b = b' x d' + c' x b', and
        // X = a + o_a b' / (o_a - o_b).
        const Expansion<4> oa = minor_uv(pc, pd, 0, 1);
        const Expansion<8> den = minor_uv(pb, pd, 0, 1) + minor_uv(pc, pb, 0, 1);
        if (fast.certify(scale(den, a[0]) + scale(oa, pb[0]), den, 3, result[0]) &&
            fast.certify(scale(den, a[1]) + scale(oa, pb[1]), den, 3, result[1])) {
            fast.count_fast();
            return result;
        }
    } else {
        const Expansion<12> oa = det_uv1(c, d, a, 0, 1), ob = det_uv1(c, d, b, 0, 1);
        const Expansion<24> den = oa - ob;
        if (fast.certify(scale(oa, b[0]) - scale(ob, a[0]), den, 3, result[0]) &&
            fast.certify(scale(oa, b[1]) - scale(ob, a[1]), den, 3, result[1])) {
            fast.count_fast();
            return result;
        }
    }
    fast.count_exact();
    return segment_intersection_rational(a, b, c, d);
}

std::array<double, 2> circumcenter_exact(const double* a, const double* b, const double* c) {
    check_triangle(a, b, c);
    return circumcenter2_rational(a, b, c);
}

std::array<double, 3> circumcenter_exact(const double* a, const double* b, const double* c,
                                         const double* d) {
    check_tetrahedron(a, b, c, d);
    return circumcenter3_rational(a, b, c, d);
}

std::array<double, 3> triangle_circumcenter_3d(const double* a, const double* b, const double* c) {
    require_finite_points("circumcenter", {a, b, c}, 3);
    for (unsigned k = 0; k < 3; ++k) {
        if (a[k] != b[k] || b[k] != c[k]) continue;
        // In a coordinate plane (facets of boxes): the circumcentre lies in that plane and is
        // the 2D circumcentre of the other two coordinates, exactly, so its correctly rounded
        // coordinates are the 2D construction's, whose fast paths avoid the rationals (50,000
        // instructions a call). The plane's coordinate is exact; -0 becomes +0 as above.
        const unsigned i = k == 0 ? 1 : 0, j = k == 2 ? 1 : 2;
        const double a2[2] = {a[i], a[j]}, b2[2] = {b[i], b[j]}, c2[2] = {c[i], c[j]};
        const std::array<double, 2> center = circumcenter(a2, b2, c2);
        std::array<double, 3> result;
        result[i] = center[0];
        result[j] = center[1];
        result[k] = a[k] == 0 ? 0.0 : a[k];
        return result;
    }
    return triangle_circumcenter3_rational(a, b, c);
}

std::array<double, 3> triangle_circumcenter_on_plane_3d(const double* a, const double* b,
                                                        const double* c, const double* p,
                                                        const double* q, const double* r) {
    require_finite_points("circumcenter on a plane", {a, b, c, p, q, r}, 3);
    // Origin at c, unknown y = x - c: 2 y . u = |u|^2, 2 y . v = |v|^2, n . y = n . (p - c).
    mpq_class u[3], v[3], e[3], f[3];
    for (int k = 0; k < 3; ++k) {
        u[k] = mpq_class(a[k]) - c[k];
        v[k] = mpq_class(b[k]) - c[k];
        e[k] = mpq_class(q[k]) - p[k];
        f[k] = mpq_class(r[k]) - p[k];
    }
    const mpq_class n[3] = {e[1] * f[2] - e[2] * f[1], e[2] * f[0] - e[0] * f[2],
                            e[0] * f[1] - e[1] * f[0]};
    if (sgn(n[0]) == 0 && sgn(n[1]) == 0 && sgn(n[2]) == 0)
        fail("circumcenter on a plane", "the plane's points are collinear", {p, q, r}, 3);
    mpq_class m[3][3], w[3];
    for (int k = 0; k < 3; ++k) {
        m[0][k] = 2 * u[k];
        m[1][k] = 2 * v[k];
        m[2][k] = n[k];
    }
    w[0] = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
    w[1] = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
    w[2] = n[0] * (mpq_class(p[0]) - c[0]) + n[1] * (mpq_class(p[1]) - c[1]) +
           n[2] * (mpq_class(p[2]) - c[2]);
    const mpq_class det = det3(m);
    if (sgn(det) == 0) {
        fail("circumcenter on a plane",
             "the triangle's projection onto the plane is flat (no point of the plane is "
             "equidistant from its corners)",
             {a, b, c, p, q, r}, 3);
    }
    std::array<double, 3> result;
    if (!cramer_rounded(m, w, det, c, result))
        fail("circumcenter on a plane", "the point overflows the double range", {a, b, c, p, q, r},
             3);
    return result;
}

namespace {

/// Whether |x| is 0 or within [2^-450, 2^500]: two such doubles have an error-free Dekker (or
/// FMA) product, since the partial products stay above 2^-1022 (the exponents sum to at least
/// -900, the low halves' product at least 2^-900-106) and below 2^1000 (the splitting needs
/// |x| < 2^995).
bool product_safe(double x) {
    const double a = std::fabs(x);
    return a == 0.0 || (a >= 0x1p-450 && a <= 0x1p500);
}

/// p + t (q - p) when it is a double, shown by error-free transformations (each tail zero: the
/// difference, the product and the sum are then the exact values), which is then its own
/// correct rounding (0 as +0, as the rational path rounds it); nullopt otherwise. Split points
/// of 3D refinement are mostly such (a segment parallel to an axis keeps two coordinates,
/// midpoints of dyadic ends are exact): each spared an MPFR rounding of three rationals.
std::optional<double> exact_point_on_segment_coordinate(double p, double q, double t) {
    if (q == p) return p == 0.0 ? 0.0 : p;
    double d = 0, d_tail = 0;
    two_diff(q, p, d, d_tail);
    if (d_tail != 0.0 || !product_safe(d) || !product_safe(t)) return std::nullopt;
    double m = 0, m_tail = 0;
    two_product(t, d, m, m_tail);
    if (m_tail != 0.0) return std::nullopt;
    double s = 0, s_tail = 0;
    two_sum(p, m, s, s_tail);
    if (s_tail != 0.0 || !std::isfinite(s)) return std::nullopt;
    return s == 0.0 ? 0.0 : s;
}

}  // namespace

std::array<double, 3> point_on_segment_3d(const double* p, const double* q, double t) {
    require_finite_points("point_on_segment", {p, q}, 3);
    if (!std::isfinite(t)) {
        fail("point_on_segment", "the parameter is not finite", {p, q}, 3);
    }
    std::array<double, 3> result;
    std::optional<mpq_class> s;  // t as a rational, made only when a coordinate needs it
    for (unsigned k = 0; k < 3; ++k) {
        if (const auto coordinate = exact_point_on_segment_coordinate(p[k], q[k], t)) {
            result[k] = *coordinate;
            continue;
        }
        if (!s) s.emplace(t);
        const mpq_class coordinate = p[k] + *s * (mpq_class(q[k]) - p[k]);
        if (!round_to_double(coordinate, result[k])) {
            fail("point_on_segment", "the point overflows the double range", {p, q}, 3);
        }
    }
    return result;
}

std::array<double, 2> segment_intersection_exact(const double* a, const double* b, const double* c,
                                                 const double* d) {
    check_segments(a, b, c, d);
    return segment_intersection_rational(a, b, c, d);
}

std::array<double, 2> point_on_line_at(const double* s0, const double* s1, int axis, double value) {
    require_finite_points("point_on_line_at", {s0, s1}, 2);
    if (!std::isfinite(value) || s0[axis] == s1[axis]) {
        fail("point_on_line_at", "the line does not cross that coordinate once", {s0, s1}, 2);
    }
    const int other = 1 - axis;
    const mpq_class t = (mpq_class(value) - s0[axis]) / (mpq_class(s1[axis]) - s0[axis]);
    std::array<double, 2> result;
    result[axis] = value;
    if (!round_to_double(mpq_class(s0[other]) + t * (mpq_class(s1[other]) - s0[other]),
                         result[other])) {
        fail("point_on_line_at", "the point overflows the double range", {s0, s1}, 2);
    }
    return result;
}

ConstructionStats& construction_stats() noexcept {
    return this_thread_stats;
}

void reset_construction_stats() noexcept {
    this_thread_stats = ConstructionStats{};
}

}  // namespace exactmesh::predicates
