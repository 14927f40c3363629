// SPDX-License-Identifier: MIT
// The exact sign of (a - p) . (b - p) (see dot_sign_3d.hpp).
#include "predicates/dot_sign_3d.hpp"

#include <gmpxx.h>

#include <cmath>

namespace exactmesh::predicates {

std::optional<Sign> dot_sign_3d_filter(const double* p, const double* a, const double* b) {
    // Scale by the power of two that brings the largest coordinate near 1: exact, and the
    // sign of the dot product does not change. Each difference then carries a relative error
    // of at most 2^-53, each product 2^-52 more, the sum of three 3 * 2^-53 of the sum of the
    // absolute values of the products: the bound below (8 * 2^-53 of that sum) is ample.
    double largest = 0;
    for (const double* q : {p, a, b}) {
        for (int k = 0; k < 3; ++k) largest = std::fmax(largest, std::fabs(q[k]));
    }
    if (largest == 0) return Sign::Zero;
    const int e = std::ilogb(largest);
    double sum = 0, magnitude = 0;
    for (int k = 0; k < 3; ++k) {
        const double u = std::ldexp(a[k], -e) - std::ldexp(p[k], -e);
        const double v = std::ldexp(b[k], -e) - std::ldexp(p[k], -e);
        sum += u * v;
        magnitude += std::fabs(u * v);
    }
    // Below this the products may be subnormal (lost bits): leave it to the exact stage.
    if (magnitude < 0x1p-900) return std::nullopt;
    const double bound = 0x1p-50 * magnitude;
    if (sum > bound) return Sign::Positive;
    if (sum < -bound) return Sign::Negative;
    return std::nullopt;
}

Sign dot_sign_3d(const double* p, const double* a, const double* b) {
    if (const auto s = dot_sign_3d_filter(p, a, b)) return *s;
    mpq_class sum = 0;
    for (int k = 0; k < 3; ++k) sum += (mpq_class(a[k]) - p[k]) * (mpq_class(b[k]) - p[k]);
    const int s = sgn(sum);
    return s > 0 ? Sign::Positive : s < 0 ? Sign::Negative : Sign::Zero;
}

}  // namespace exactmesh::predicates
