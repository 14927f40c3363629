// SPDX-License-Identifier: MIT
// Exact scaling by powers of two, the tool of scale invariance: a measure computed on vectors
// first scaled by 2^k (k from the data) neither overflows nor underflows, and the same input
// scaled by 2^j gives the same bits. Multiplying by 2^k is correctly rounded exactly like
// std::ldexp, so the product is used wherever 2^k is a normal double (std::ldexp and
// std::ilogb are library calls: three per coordinate tripled the cost of a size evaluation).
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>

namespace exactmesh::predicates {

/// floor(log2 |value|) for finite nonzero value (std::ilogb), from the bits for normal numbers.
inline int binary_exponent(double value) noexcept {
    const int biased = static_cast<int>((std::bit_cast<std::uint64_t>(value) >> 52) & 0x7ff);
    return biased != 0 ? biased - 1023 : std::ilogb(value);
}

/// The shift that brings |largest| to [1, 2): -binary_exponent(largest), or 0 when largest is
/// zero, infinite or NaN (nothing to scale).
inline int unit_shift(double largest) noexcept {
    return largest != 0 && std::isfinite(largest) ? -binary_exponent(largest) : 0;
}

/// value * 2^shift, correctly rounded (identical to std::ldexp(value, shift)).
class PowerOfTwo {
  public:
    explicit PowerOfTwo(int shift) noexcept
        : shift_(shift), multiply_(shift >= -1022 && shift <= 1023) {
        if (multiply_)
            unit_ = std::bit_cast<double>(static_cast<std::uint64_t>(shift + 1023) << 52);
    }
    double operator()(double value) const noexcept {
        return multiply_ ? value * unit_ : std::ldexp(value, shift_);
    }
    int shift() const noexcept { return shift_; }
    /// Whether operator() is one multiplication, by factor() (2^shift a normal double).
    bool is_multiplication() const noexcept { return multiply_; }
    double factor() const noexcept { return unit_; }

  private:
    int shift_;
    bool multiply_;
    double unit_ = 1.0;
};

/// |(dx, dy)| computed on the vector scaled to a largest coordinate in [1, 2): no square
/// overflows or underflows, and scaling the vector by 2^k scales the result by 2^k exactly
/// (while it stays a normal double).
inline double scale_free_norm(double dx, double dy) noexcept {
    dx = std::fabs(dx);
    dy = std::fabs(dy);
    const double larger = dx > dy ? dx : dy;
    if (larger == 0) return 0;
    const int e = binary_exponent(larger);
    const PowerOfTwo down(-e);
    const double a = down(dx), b = down(dy);
    return PowerOfTwo(e)(std::sqrt(a * a + b * b));
}

}  // namespace exactmesh::predicates
