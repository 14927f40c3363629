// SPDX-License-Identifier: MIT
// Error-free transformations and nonoverlapping expansion arithmetic [Shewchuk97 §2].
// Invariant of every Expansion: components sorted by increasing magnitude, nonoverlapping,
// no zero components, so the sign of the sum is the sign of the last component.
// Exact only when no operation overflows or underflows: predicates check that range first.
#pragma once

#include <array>
#include <cfloat>
#include <cmath>
#include <limits>
#include <utility>

#include "predicates/sign.hpp"

static_assert(std::numeric_limits<double>::is_iec559, "exactmesh needs IEEE 754 binary64");
static_assert(FLT_EVAL_METHOD == 0, "exactmesh needs double evaluation without extended precision");

namespace exactmesh::predicates {

/// x + y == a + b exactly, x = fl(a + b); requires |a| >= |b| or a == 0 [Dekker71].
inline void fast_two_sum(double a, double b, double& x, double& y) noexcept {
    x = a + b;
    y = b - (x - a);
}

/// x + y == a + b exactly, x = fl(a + b), for any a, b [Knuth, Møller].
inline void two_sum(double a, double b, double& x, double& y) noexcept {
    x = a + b;
    const double b_virtual = x - a;
    const double a_virtual = x - b_virtual;
    y = (a - a_virtual) + (b - b_virtual);
}

/// x + y == a - b exactly, x = fl(a - b).
inline void two_diff(double a, double b, double& x, double& y) noexcept {
    x = a - b;
    const double b_virtual = a - x;
    const double a_virtual = x + b_virtual;
    y = (a - a_virtual) + (b_virtual - b);
}

/// Veltkamp splitting: a == hi + lo, each with at most 26 significant bits.
/// Requires |a| < 2^995 so that the scaled value cannot overflow.
inline void split(double a, double& hi, double& lo) noexcept {
    constexpr double kSplitter = 134217729.0;  // 2^27 + 1
    const double c = kSplitter * a;
    const double a_big = c - a;
    hi = c - a_big;
    lo = a - hi;
}

/// x + y == a * b exactly, x = fl(a * b) (Dekker's product, or one FMA when configured).
inline void two_product(double a, double b, double& x, double& y) noexcept {
    x = a * b;
#if defined(EXACTMESH_USE_FMA_TWO_PRODUCT)
    y = std::fma(a, b, -x);
#else
    double a_hi, a_lo, b_hi, b_lo;
    split(a, a_hi, a_lo);
    split(b, b_hi, b_lo);
    const double err1 = x - (a_hi * b_hi);
    const double err2 = err1 - (a_lo * b_hi);
    const double err3 = err2 - (a_hi * b_lo);
    y = (a_lo * b_lo) - err3;
#endif
}

/// h = e + f with zero elimination [Shewchuk97 Fig. 8, fast_expansion_sum_zeroelim].
/// h must have room for elen + flen components; returns its length.
int expansion_sum(int elen, const double* e, int flen, const double* f, double* h) noexcept;

/// h = e * b with zero elimination [Shewchuk97 Fig. 11]; h needs room for 2 * elen.
int scale_expansion(int elen, const double* e, double b, double* h) noexcept;

/// Rewrites e into h with the largest component nearly containing the whole value
/// [Shewchuk97 §2.8, compress]; h needs room for elen; returns its length.
int compress(int elen, const double* e, double* h) noexcept;

/// A double approximation of the expansion's value (sum of components).
double estimate(int elen, const double* e) noexcept;

/// An expansion with capacity N fixed at compile time, so that the exact stages of the
/// predicates live on the stack and their worst-case sizes are visible in the types.
template <int N>
struct Expansion {
    static constexpr int kCapacity = N;
    int length = 0;
    std::array<double, N> components;  // deliberately not value-initialised: filled by writers

    Sign sign() const noexcept {
        return length == 0 ? Sign::Zero : sign_of(components[static_cast<unsigned>(length - 1)]);
    }
    double approximate() const noexcept { return estimate(length, components.data()); }
};

/// The exact value of one double.
inline Expansion<1> expansion_of(double a) noexcept {
    Expansion<1> r;
    r.components[0] = a;
    r.length = a != 0.0 ? 1 : 0;
    return r;
}

/// The exact product a * b as an expansion of at most 2 components.
inline Expansion<2> exact_product(double a, double b) noexcept {
    Expansion<2> r;
    double x, y;
    two_product(a, b, x, y);
    int n = 0;
    if (y != 0.0) r.components[static_cast<unsigned>(n++)] = y;
    if (x != 0.0) r.components[static_cast<unsigned>(n++)] = x;
    r.length = n;
    return r;
}

/// The exact difference a - b as an expansion of at most 2 components.
inline Expansion<2> exact_difference(double a, double b) noexcept {
    Expansion<2> r;
    double x, y;
    two_diff(a, b, x, y);
    int n = 0;
    if (y != 0.0) r.components[static_cast<unsigned>(n++)] = y;
    if (x != 0.0) r.components[static_cast<unsigned>(n++)] = x;
    r.length = n;
    return r;
}

template <int A, int B>
Expansion<A + B> operator+(const Expansion<A>& e, const Expansion<B>& f) noexcept {
    Expansion<A + B> h;
    h.length = expansion_sum(e.length, e.components.data(), f.length, f.components.data(),
                             h.components.data());
    return h;
}

template <int A>
Expansion<A> operator-(const Expansion<A>& e) noexcept {
    Expansion<A> h;
    h.length = e.length;
    for (int i = 0; i < e.length; ++i) {
        h.components[static_cast<unsigned>(i)] = -e.components[static_cast<unsigned>(i)];
    }
    return h;
}

template <int A, int B>
Expansion<A + B> operator-(const Expansion<A>& e, const Expansion<B>& f) noexcept {
    return e + (-f);
}

/// The same value with fewer components (the largest one nearly the whole value): worth it
/// before an expansion is multiplied, since products cost in proportion to length.
template <int A>
Expansion<A> compressed(const Expansion<A>& e) noexcept {
    Expansion<A> h;
    h.length = compress(e.length, e.components.data(), h.components.data());
    return h;
}

/// e * b exactly.
template <int A>
Expansion<2 * A> scale(const Expansion<A>& e, double b) noexcept {
    Expansion<2 * A> h;
    h.length = scale_expansion(e.length, e.components.data(), b, h.components.data());
    return h;
}

/// e * f exactly: the sum of e scaled by each component of f. Compress both first: the cost is
/// proportional to the product of their lengths.
template <int A, int B>
Expansion<2 * A * B> product(const Expansion<A>& e, const Expansion<B>& f) noexcept {
    // Accumulate alternately into the result and a scratch buffer (no whole-array swaps).
    Expansion<2 * A * B> result, scratch;
    Expansion<2 * A> term;
    double* sum = result.components.data();
    double* next = scratch.components.data();
    int length = 0;
    for (int i = 0; i < f.length; ++i) {
        term.length =
            scale_expansion(e.length, e.components.data(), f.components[static_cast<unsigned>(i)],
                            term.components.data());
        length = expansion_sum(length, sum, term.length, term.components.data(), next);
        std::swap(sum, next);
    }
    if (sum != result.components.data()) {
        for (int i = 0; i < length; ++i) result.components[static_cast<unsigned>(i)] = sum[i];
    }
    result.length = length;
    return result;
}

/// e * b * b exactly (b squared without forming b^2 as a double).
template <int A>
Expansion<4 * A> scale_twice(const Expansion<A>& e, double b) noexcept {
    return scale(scale(e, b), b);
}

}  // namespace exactmesh::predicates
