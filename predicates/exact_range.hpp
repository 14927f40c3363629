// SPDX-License-Identifier: MIT
// When expansion arithmetic is exact for a polynomial predicate of a given degree: no
// overflow and no underflow in any two_product. Internal to predicates/.
#pragma once

#include <cmath>
#include <cstdio>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <string>

#include "predicates/errors.hpp"

namespace exactmesh::predicates::detail {

/// Exponent of the lowest set bit of a nonzero finite double (x is an odd multiple of 2^k).
inline int lowest_bit_exponent(double x) noexcept {
    int exponent = 0;
    const double mantissa = std::frexp(std::fabs(x), &exponent);  // x = m * 2^e, m in [0.5, 1)
    auto integer = static_cast<std::uint64_t>(std::ldexp(mantissa, 53));  // exact: 53 bits
    int k = exponent - 53;
    while ((integer & 1u) == 0u) {
        integer >>= 1;
        ++k;
    }
    return k;
}

/// True when every expansion operation of a degree-`degree` determinant in these coordinates is
/// exact. Every intermediate value is an integer multiple of 2^(degree * q), q the lowest set bit
/// over all coordinates, so no product underflows when degree * q >= -1074; magnitudes below
/// 2^(1000/degree - 2) keep every term, and Veltkamp's split, far from overflow.
inline bool expansion_safe(int degree, std::initializer_list<double> coordinates) noexcept {
    const int max_exponent = 1000 / degree - 2;
    const double max_magnitude = std::ldexp(1.0, max_exponent);
    int lowest = std::numeric_limits<int>::max();
    for (const double x : coordinates) {
        if (x == 0.0) continue;
        if (!(std::fabs(x) <= max_magnitude)) return false;
        const int k = lowest_bit_exponent(x);
        if (k < lowest) lowest = k;
    }
    return lowest == std::numeric_limits<int>::max() || degree * lowest >= -1074;
}

/// Throws GeometryError when a coordinate is NaN or infinite; predicates have no exact answer.
inline void require_finite(const char* predicate, std::initializer_list<double> coordinates) {
    for (const double x : coordinates) {
        if (!std::isfinite(x)) {
            char value[32];
            std::snprintf(value, sizeof value, "%.17g", x);
            throw GeometryError(std::string(predicate) + ": non-finite coordinate " + value);
        }
    }
}

}  // namespace exactmesh::predicates::detail
