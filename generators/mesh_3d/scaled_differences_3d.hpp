// SPDX-License-Identifier: MIT
// Point differences scaled by a power of two, and the vector arithmetic on them (vec3), for the
// choices the 3D generators make in doubles
// (which size, which vertex, which pair to split: never a validity decision). Halved before the
// subtraction and brought into [1, 2) by the largest, so that no difference overflows and no
// product of them overflows or underflows at 2^+-600; scaling the input by a power of two
// gives the same scaled differences.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace exactmesh::generators {

/// scaled_differences' answer when the points coincide.
inline constexpr int kCoincident = std::numeric_limits<int>::min();

/// The differences p[k] - p[0] (k = 1 .. n - 1) into d[k - 1], halved and divided by the power
/// of two that brings the largest into [1, 2); returns that scale s (a length is |d| 2^s), or
/// kCoincident when the points coincide.
inline int scaled_differences(const double* const* p, unsigned n, std::array<double, 3>* d) {
    double largest = 0;
    for (unsigned k = 1; k < n; ++k)
        for (int i = 0; i < 3; ++i)
            largest = std::max(largest, std::fabs(p[k][i] / 2 - p[0][i] / 2));
    if (!(largest > 0)) return kCoincident;
    const int exponent = std::ilogb(largest);
    for (unsigned k = 1; k < n; ++k)
        for (int i = 0; i < 3; ++i) d[k - 1][i] = std::ldexp(p[k][i] / 2 - p[0][i] / 2, -exponent);
    return exponent + 1;
}

/// Vector arithmetic in doubles on such differences (placements and selections only).
namespace vec3 {
using Vec = std::array<double, 3>;
inline Vec sub(const Vec& p, const Vec& q) {
    return {p[0] - q[0], p[1] - q[1], p[2] - q[2]};
}
inline double dot(const Vec& p, const Vec& q) {
    return p[0] * q[0] + p[1] * q[1] + p[2] * q[2];
}
inline Vec cross(const Vec& p, const Vec& q) {
    return {p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]};
}
}  // namespace vec3

}  // namespace exactmesh::generators
