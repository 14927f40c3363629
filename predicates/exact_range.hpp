// SPDX-License-Identifier: MIT
// When expansion arithmetic is exact for a polynomial predicate of a given degree: no
// overflow and no underflow in any two_product. Internal to predicates/.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <initializer_list>
#include <limits>
#include <string>

#include "base/errors.hpp"
#include "base/number_text.hpp"
#include "predicates/sign.hpp"
#include "predicates/stats.hpp"

namespace exactmesh::predicates::detail {

/// Exponent of the lowest set bit of a nonzero finite double (x is an odd multiple of 2^k),
/// read from the bits: no libm call, no loop.
inline int lowest_bit_exponent(double x) noexcept {
    const auto bits = std::bit_cast<std::uint64_t>(x);
    const auto biased = static_cast<int>((bits >> 52) & 0x7FFu);
    std::uint64_t mantissa = bits & ((std::uint64_t{1} << 52) - 1);
    if (biased != 0) mantissa |= std::uint64_t{1} << 52;  // normal: implicit leading bit
    const int unit = (biased == 0 ? 1 : biased) - 1075;   // exponent of the mantissa's last bit
    return unit + std::countr_zero(mantissa);
}

/// 2^e for a normal exponent e, without a libm call.
constexpr double power_of_two(int e) noexcept {
    return std::bit_cast<double>(static_cast<std::uint64_t>(e + 1023) << 52);
}

/// True when every expansion operation of a degree-`degree` determinant in these coordinates is
/// exact. Every intermediate value is an integer multiple of 2^(degree * q), q the lowest set bit
/// over all coordinates, so no product underflows when degree * q >= -1074; magnitudes below
/// 2^(1000/degree - 2) keep every term, and Veltkamp's split, far from overflow.
/// A coordinate of magnitude >= 2^(53 - 1074/degree) has q >= -1074/degree already, so only
/// smaller ones need their lowest bit read.
inline bool expansion_safe(int degree, std::initializer_list<double> coordinates) noexcept {
    const double max_magnitude = power_of_two(1000 / degree - 2);
    const double surely_fine = power_of_two(53 - 1074 / degree);
    const int lowest_allowed = -(1074 / degree);
    for (const double x : coordinates) {
        const double a = std::fabs(x);
        if (!(a <= max_magnitude)) return false;
        if (a < surely_fine && a != 0.0 && lowest_bit_exponent(x) < lowest_allowed) return false;
    }
    return true;
}

/// Coordinates outside the expansion-safe range brought into it by one power of two, when
/// that is exact: out[i] = 2^k coordinates[i] with k = -ilogb(max |x|), so the largest
/// magnitude lands in [1, 2). Every predicate here is a homogeneous polynomial in the
/// coordinates (degree `degree`: the sign of det(2^k p) is the sign of 2^(k degree) det(p)),
/// so the scaled coordinates give the same sign, through the filter and stages B-C, whenever
/// the scaling is exact and the result is expansion_safe: both hold exactly when every nonzero
/// coordinate's lowest set bit, shifted by k, is at least -1074 / degree (then no bit is lost,
/// and the bound on the largest magnitude holds since 2 <= 2^(1000 / degree - 2)). False (out
/// unspecified) for inputs that span too wide a range (a subnormal beside a coordinate near 1):
/// those stay with GMP. The scaled copy makes domains scaled by 2^-600 or 2^600 as fast as
/// at 2^0, where every call used to go to GMP.
inline bool rescale_into_safe_range(int degree, std::initializer_list<double> coordinates,
                                    double* out) noexcept {
    double largest = 0.0;
    for (const double x : coordinates) largest = std::max(largest, std::fabs(x));
    if (largest == 0.0) return false;  // all zero: expansion_safe already holds
    const int k = -std::ilogb(largest);
    const int lowest_allowed = -(1074 / degree);
    for (const double x : coordinates) {
        if (x != 0.0 && lowest_bit_exponent(x) + k < lowest_allowed) return false;
    }
    // 2^k in one or two normal factors (|k| <= 1074 + 1023); each product is exact (no bit
    // falls below 2^-1074, checked above, and none overflows: the largest ends below 2).
    const int first = std::clamp(k, -1022, 1023), second = k - first;
    const double f1 = power_of_two(first), f2 = power_of_two(second);
    std::size_t i = 0;
    for (const double x : coordinates) out[i++] = second == 0 ? x * f1 : x * f1 * f2;
    return true;
}

/// EM_STAT for a predicate chosen by the caller: one more call of `predicate` ended in `stage`.
inline void count_stage([[maybe_unused]] StageCounts PredicateStats::*predicate,
                        [[maybe_unused]] std::uint64_t StageCounts::*stage) noexcept {
#if defined(EXACTMESH_PREDICATE_STATS)
    ++((thread_stats().*predicate).*stage);
#endif
}

/// The sign of a predicate whose `N` coordinates are outside the expansion-safe range: scaled
/// into it when that is exact (rescale_into_safe_range), then decided by the predicate's own
/// filter and exact stages on the scaled copy (`scaled_filter(s)`, `scaled_exact(s)`, s the N
/// scaled coordinates in the order given); else `gmp()` on the original points. Counts the
/// stages in `predicate`'s counters as the predicate itself does (rescaled, filter, gmp).
template <std::size_t N, class Filter, class Exact, class Gmp>
Sign out_of_range_sign(StageCounts PredicateStats::*predicate, int degree,
                       std::initializer_list<double> coordinates, Filter scaled_filter,
                       Exact scaled_exact, Gmp gmp) {
    double s[N];
    if (rescale_into_safe_range(degree, coordinates, s)) {
        count_stage(predicate, &StageCounts::rescaled);
        if (const auto sign = scaled_filter(static_cast<const double*>(s))) {
            count_stage(predicate, &StageCounts::filter);
            return *sign;
        }
        return scaled_exact(static_cast<const double*>(s));  // expansion-safe now
    }
    count_stage(predicate, &StageCounts::gmp);
    return gmp();
}

/// Throws GeometryError when a coordinate is NaN or infinite; predicates have no exact answer.
inline void require_finite(const char* predicate, std::initializer_list<double> coordinates) {
    for (const double x : coordinates) {
        if (!std::isfinite(x)) {
            throw GeometryError(std::string(predicate) + ": non-finite coordinate " +
                                format_number(x));
        }
    }
}

}  // namespace exactmesh::predicates::detail
