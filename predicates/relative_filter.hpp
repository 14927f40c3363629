// SPDX-License-Identifier: MIT
// Relative floating-point filters with the rounding count in the type (internal to predicates/):
// the double stages of dot_sign_3d and tet_quality_3d. The model and its proof are in
// proofs/invariants/filters.md, "Relative filters" and "dot_sign_3d and tet_quality_3d".
//
// A Term<R> holds a computed value and its computed permanent (the same expression on absolute
// values, every subtraction made an addition) of a polynomial in coordinate differences; R is
// the most roundings on any monomial's path [Higham02 §3.1]: a rounded difference 1, a sum or
// difference one more than its larger operand, a product the sum of its operands' and one, a
// scaling by a power of two none. The permanent goes through the same operations, so it carries
// the same count. With no underflow and no overflow, |fl(E) - E| <= eps fl(P) whenever
// |prod_{i<=R} (1 + d_i) - 1| <= eps prod_{j<=R} (1 + e_j) for all |d_i|, |e_j| <= 2^-53, which
// Gappa proves for each filter's eps and R (proofs/gappa/<filter>.g); `certified` asks R to be
// no more than the count proven, at compile time.
//
// No underflow: every difference is rounded from the input once (a subnormal difference is
// exact), then all are scaled by one power of two so that the largest lies in [1, 2), and the
// filter answers only when every nonzero scaled difference is at least 2^-w (the window). Such a
// difference is an integer multiple of Q = 2^(-w-52); sums and products of multiples of Q^i and
// Q^j round to multiples of Q^max(i,j) and Q^(i+j) (rounding to a coarser grid of powers of two
// keeps the multiple; on a finer one the value is representable), so a nonzero computed value of
// degree j is at least Q^j, and a product of degree j <= J is normal (no underflow error) when
// J (w + 52) <= 1022. The bound eps fl(P) must be normal too (P >= Q^J when nonzero):
// J (w + 52) - log2(eps) <= 1022. No overflow: scaled differences are below 2, so a value of
// degree 9 is far below 2^100.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "predicates/power_of_two.hpp"
#include "predicates/sign.hpp"

namespace exactmesh::predicates::detail {

#if defined(__SSE2__)
/// With SSE2 (every x86-64) a Term is one register, (value, permanent): each operation makes
/// both halves with one instruction, the same roundings of the same operands as two scalar
/// operations (a difference's value as value + (-value'): IEEE defines x - y so, bit for bit,
/// but for the sign of a NaN, which no comparison sees). These filters were a tenth of 3D
/// refinement's instructions, mostly in pairs of scalar operations.
template <int R>
struct Term {
    __m128d lanes;
    double value() const noexcept { return _mm_cvtsd_f64(lanes); }
    double permanent() const noexcept { return _mm_cvtsd_f64(_mm_unpackhi_pd(lanes, lanes)); }
};

/// (-0.0, +0.0): the sign of the value's half, xor-ed (negation is exact).
inline __m128d value_sign() noexcept {
    return _mm_set_pd(0.0, -0.0);
}

/// A rounded (and exactly scaled) coordinate difference.
inline Term<1> difference(double d) noexcept {
    return {_mm_set_pd(std::fabs(d), d)};
}
/// A nonnegative double computed with one rounding (a constant times a bound).
inline Term<1> rounded_constant(double x) noexcept {
    return {_mm_set1_pd(x)};
}

template <int R, int S>
Term<std::max(R, S) + 1> operator+(const Term<R>& a, const Term<S>& b) noexcept {
    return {_mm_add_pd(a.lanes, b.lanes)};
}
template <int R, int S>
Term<std::max(R, S) + 1> operator-(const Term<R>& a, const Term<S>& b) noexcept {
    return {_mm_add_pd(a.lanes, _mm_xor_pd(b.lanes, value_sign()))};
}
template <int R, int S>
Term<R + S + 1> operator*(const Term<R>& a, const Term<S>& b) noexcept {
    return {_mm_mul_pd(a.lanes, b.lanes)};
}
/// Times a power of two that neither overflows nor underflows: exact, no rounding.
template <int R>
Term<R> scaled(const Term<R>& a, double power) noexcept {
    return {_mm_mul_pd(a.lanes, _mm_set1_pd(power))};
}
/// The negation when `negative`: exact.
template <int R>
Term<R> signed_by(const Term<R>& a, bool negative) noexcept {
    return {negative ? _mm_xor_pd(a.lanes, value_sign()) : a.lanes};
}
#else
template <int R>
struct Term {
    double value_;
    double permanent_;
    double value() const noexcept { return value_; }
    double permanent() const noexcept { return permanent_; }
};

/// A rounded (and exactly scaled) coordinate difference.
inline Term<1> difference(double d) noexcept {
    return {d, std::fabs(d)};
}
/// A nonnegative double computed with one rounding (a constant times a bound).
inline Term<1> rounded_constant(double x) noexcept {
    return {x, x};
}

template <int R, int S>
Term<std::max(R, S) + 1> operator+(const Term<R>& a, const Term<S>& b) noexcept {
    return {a.value_ + b.value_, a.permanent_ + b.permanent_};
}
template <int R, int S>
Term<std::max(R, S) + 1> operator-(const Term<R>& a, const Term<S>& b) noexcept {
    return {a.value_ - b.value_, a.permanent_ + b.permanent_};
}
template <int R, int S>
Term<R + S + 1> operator*(const Term<R>& a, const Term<S>& b) noexcept {
    return {a.value_ * b.value_, a.permanent_ * b.permanent_};
}
/// Times a power of two that neither overflows nor underflows: exact, no rounding.
template <int R>
Term<R> scaled(const Term<R>& a, double power) noexcept {
    return {a.value_ * power, a.permanent_ * power};
}
/// The negation when `negative`: exact.
template <int R>
Term<R> signed_by(const Term<R>& a, bool negative) noexcept {
    return {negative ? -a.value_ : a.value_, a.permanent_};
}
#endif

/// sign(E) when |fl(E)| > eps fl(P), proven for at most `ProvenRoundings` roundings.
template <int ProvenRoundings, int R>
std::optional<Sign> certified(const Term<R>& t, double eps) noexcept {
    static_assert(R <= ProvenRoundings, "the Gappa proof covers fewer roundings than this term");
    const double bound = eps * t.permanent();
    const double value = t.value();
    if (value > bound) return Sign::Positive;
    if (-value > bound) return Sign::Negative;
    return std::nullopt;
}

/// Scales the N rounded differences in `d` by the power of two that brings the largest
/// magnitude to [1, 2), in place, and returns the shift; std::nullopt (nothing to filter) when
/// they are all zero, one is not finite, or a nonzero one ends below `window_min` (a power of
/// two: see the header comment).
///
/// With SSE2 (every x86-64) two differences at a time: MAXPD(|x|, m) is |x| > m ? |x| : m, the
/// scalar std::max(m, |x|) (a NaN skipped alike), MULPD by 2^shift the same exact products,
/// and the window test the same comparisons (x != 0 true for a NaN, |x| < w false), all made
/// before one answer instead of an early return (the caller drops `d` on nullopt). The same
/// bits as the scalar loops below; they were 5% of 3D refinement's instructions (1.7 10^6
/// calls on the wing at V = 4.46e-5, 16 instructions per difference).
template <std::size_t N>
[[gnu::noinline]] std::optional<int> scale_differences_by_ldexp(double (&d)[N], double window_min,
                                                                const PowerOfTwo& unit) noexcept {
    for (double& x : d) {
        x = unit(x);
        if (x != 0 && std::fabs(x) < window_min) return std::nullopt;
    }
    return unit.shift();
}

/// Inlined into each filter (a call's register saves and the returned optional's trip through
/// memory were a third of its instructions), the ldexp path out of line.
template <std::size_t N>
[[gnu::always_inline]] inline std::optional<int> scale_differences(double (&d)[N],
                                                                   double window_min) noexcept {
#if defined(__SSE2__)
    constexpr std::size_t kPairs = N / 2;
    const __m128d magnitude = _mm_castsi128_pd(_mm_set1_epi64x(0x7fffffffffffffffLL));
    __m128d pair_largest = _mm_setzero_pd();
    for (std::size_t i = 0; i < kPairs; ++i)
        pair_largest = _mm_max_pd(_mm_and_pd(_mm_loadu_pd(d + 2 * i), magnitude), pair_largest);
    double largest = std::max(_mm_cvtsd_f64(pair_largest),
                              _mm_cvtsd_f64(_mm_unpackhi_pd(pair_largest, pair_largest)));
    if constexpr (N % 2 != 0) largest = std::max(largest, std::fabs(d[N - 1]));
    if (largest == 0 || !std::isfinite(largest)) return std::nullopt;  // NaN fails both ways
    const int shift = unit_shift(largest);
    const PowerOfTwo unit(shift);
    if (unit.is_multiplication()) {
        const __m128d factor = _mm_set1_pd(unit.factor());
        const __m128d window = _mm_set1_pd(window_min);
        const __m128d zero = _mm_setzero_pd();
        __m128d below = _mm_setzero_pd();
        for (std::size_t i = 0; i < kPairs; ++i) {
            const __m128d x = _mm_mul_pd(_mm_loadu_pd(d + 2 * i), factor);
            _mm_storeu_pd(d + 2 * i, x);
            below = _mm_or_pd(below, _mm_and_pd(_mm_cmpneq_pd(x, zero),
                                                _mm_cmplt_pd(_mm_and_pd(x, magnitude), window)));
        }
        bool small = _mm_movemask_pd(below) != 0;
        if constexpr (N % 2 != 0) {
            const double x = d[N - 1] * unit.factor();
            d[N - 1] = x;
            small = small || (x != 0 && std::fabs(x) < window_min);
        }
        if (small) return std::nullopt;
        return shift;
    }
#else
    double largest = 0;
    for (const double x : d) largest = std::max(largest, std::fabs(x));
    if (largest == 0 || !std::isfinite(largest)) return std::nullopt;  // NaN fails both ways
    const int shift = unit_shift(largest);
    const PowerOfTwo unit(shift);
#endif
    return scale_differences_by_ldexp(d, window_min, unit);
}

}  // namespace exactmesh::predicates::detail
