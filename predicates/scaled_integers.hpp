// SPDX-License-Identifier: MIT
// Coordinates of one exact evaluation as GMP integers on one common power-of-two scale (internal
// to predicates/): every finite double is M·2^E with an integer |M| < 2^53, so scaling all of
// them by 2^-Emin (Emin the least E) makes each an integer and multiplies a homogeneous
// polynomial of degree n by 2^(-n Emin) > 0, keeping its sign. Integers need no gcd after each
// operation, unlike rationals (mpq): several times faster (gmp_fallback.cpp's measurement).
#pragma once

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <cstddef>
#include <cstdint>

namespace exactmesh::predicates::detail {

/// The N input coordinates of one call as integers, all scaled by the same power of two:
/// 2^-least (INT_MAX when every coordinate is 0), stored in `least_out` when given.
template <std::size_t N>
inline std::array<mpz_class, N> scaled_integers(const std::array<double, N>& x,
                                                int* least_out = nullptr) {
    std::array<std::int64_t, N> mantissa{};
    std::array<int, N> exponent{};
    int least = INT_MAX;
    for (std::size_t i = 0; i < N; ++i) {
        if (x[i] == 0.0) continue;
        int e = 0;
        const double f = std::frexp(x[i], &e);  // x = f·2^e, 0.5 <= |f| < 1: f·2^53 is an integer
        mantissa[i] = static_cast<std::int64_t>(std::ldexp(f, 53));
        exponent[i] = e - 53;
        least = std::min(least, exponent[i]);
    }
    std::array<mpz_class, N> out;
    for (std::size_t i = 0; i < N; ++i) {
        if (mantissa[i] == 0) continue;  // stays 0
        out[i] = static_cast<long>(mantissa[i]);
        mpz_mul_2exp(out[i].get_mpz_t(), out[i].get_mpz_t(),
                     static_cast<mp_bitcnt_t>(exponent[i] - least));
    }
    if (least_out != nullptr) *least_out = least;
    return out;
}

/// The least exponent k with x an integer multiple of 2^k (x finite, non-zero).
inline int least_set_bit_exponent(double x) {
    return std::ilogb(x) - 52;
}

/// z = w / 2^k exactly, in place (no allocation once z has room): w finite and an integer
/// multiple of 2^k (k at most least_set_bit_exponent(w)), or 0. For exact stages that keep
/// their integers between calls (thread-local mpz_t), where scaled_integers would allocate.
inline void set_scaled_integer(mpz_ptr z, double w, int k) {
    if (w == 0) {
        mpz_set_ui(z, 0);
        return;
    }
    const int e = least_set_bit_exponent(w);
    mpz_set_d(z, std::ldexp(w, -e));  // |w 2^-e| < 2^53: exact
    mpz_mul_2exp(z, z, static_cast<mp_bitcnt_t>(e - k));
}

}  // namespace exactmesh::predicates::detail
