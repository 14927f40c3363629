// SPDX-License-Identifier: MIT
// The triangle-area comparison (see triangle_area.hpp).
#include "predicates/triangle_area.hpp"

#include <algorithm>
#include <cmath>

#include "predicates/exact_range.hpp"
#include "predicates/filter_constants.hpp"
#include "predicates/gmp_fallback.hpp"
#include "predicates/power_of_two.hpp"

namespace exactmesh::predicates {

Sign triangle_area_sign(const double* a, const double* b, const double* c, double area) {
    detail::require_finite("triangle_area_sign", {a[0], a[1], b[0], b[1], c[0], c[1], area});
    double d[4] = {a[0] - c[0], a[1] - c[1], b[0] - c[0], b[1] - c[1]};
    double largest = 0;
    for (const double x : d) largest = std::max(largest, std::fabs(x));
    if (largest == 0) return -sign_of(area);  // a = b = c: the area is 0, exactly
    if (std::isfinite(largest)) {
        // Stage A. Each difference is rounded once (relative error u = 2^-53), then scaled
        // exactly by 2^shift (up to 2^-1075 absolute where it becomes subnormal). With
        // P = |d0 d3| + |d1 d2| the computed determinant is within 3.02 u P + u |det| of the
        // exact scaled one, the bound 2 area 2^(2 shift) within 2^-1075 (underflow; overflow
        // gives +-infinity, decided by its sign: |det| <= 8), and the difference r within
        // u |r| more; subnormal products add at most a few 2^-1075. The constants are proved
        // in proofs/gappa/triangle_area_filter.g (proofs/invariants/filters.md).
        const int shift = unit_shift(largest);
        const PowerOfTwo unit(shift);
        for (double& x : d) x = unit(x);
        const double p = d[0] * d[3], q = d[1] * d[2];
        const double det = p - q;
        const double bound = std::ldexp(area, 2 * shift + 1);
        if (std::isinf(bound)) return bound > 0 ? Sign::Negative : Sign::Positive;
        const double r = det - bound;
        const double error = triangle_area_filter_eps * (std::fabs(p) + std::fabs(q)) +
                             triangle_area_filter_result_eps * (std::fabs(det) + std::fabs(bound)) +
                             triangle_area_filter_floor;
        if (r > error) return Sign::Positive;
        if (-r > error) return Sign::Negative;
    }
    // Stage B: exact in GMP integers (differences that overflow, and near ties).
    return triangle_area_gmp(a, b, c, area);
}

}  // namespace exactmesh::predicates
