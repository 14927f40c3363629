// SPDX-License-Identifier: MIT
// The exact sign of (a - p) . (b - p) (see dot_sign_3d.hpp).
#include "predicates/dot_sign_3d.hpp"

#include <gmpxx.h>

#include <cmath>

#include "predicates/exact_range.hpp"
#include "predicates/expansion.hpp"
#include "predicates/filter_constants.hpp"
#include "predicates/relative_filter.hpp"
#include "predicates/stats.hpp"

namespace exactmesh::predicates {

std::optional<Sign> dot_sign_3d_filter(const double* p, const double* a, const double* b) {
    // The differences are rounded once from the input, then scaled by the power of two that
    // brings the largest to [1, 2) (exact inside the window; the sign does not change). Each
    // monomial of the computed sum goes through 5 roundings (two differences, the product, two
    // sums), and so does its permanent; Gappa proves dot_sign_3d_filter_eps for that count
    // (proofs/gappa/dot_sign_3d_filter.g, proofs/invariants/filters.md). Every nonzero scaled
    // difference is at least the window 2^-400, so no product underflows (degree 2 and the
    // bound: 2 (400 + 52) + 50 <= 1022, relative_filter.hpp).
    using detail::difference;
    double d[6] = {a[0] - p[0], a[1] - p[1], a[2] - p[2], b[0] - p[0], b[1] - p[1], b[2] - p[2]};
    if (!detail::scale_differences(d, dot_sign_3d_filter_window_min)) return std::nullopt;
    const auto sum = difference(d[0]) * difference(d[3]) + difference(d[1]) * difference(d[4]) +
                     difference(d[2]) * difference(d[5]);
    return detail::certified<dot_sign_3d_filter_roundings>(sum, dot_sign_3d_filter_eps);
}

Sign dot_sign_3d(const double* p, const double* a, const double* b) {
    EM_STAT(dot_sign_3d, calls);
    if (const auto s = dot_sign_3d_filter(p, a, b)) {
        EM_STAT(dot_sign_3d, filter);
        return *s;
    }
    if (detail::expansion_safe(2, {p[0], p[1], p[2], a[0], a[1], a[2], b[0], b[1], b[2]})) {
        // The exact sum of the products of the exact differences (ties, such as the right
        // angles of lattice points in 3D refinement on boxes, went to GMP at ~3,600
        // instructions each: a third of the encroachment checks' time). expansion_safe for
        // degree 2: no product's error term underflows, nothing overflows.
        EM_STAT(dot_sign_3d, expansion);
        const auto term = [&](int k) {
            return product(exact_difference(a[k], p[k]), exact_difference(b[k], p[k]));
        };
        return (term(0) + term(1) + term(2)).sign();
    }
    EM_STAT(dot_sign_3d, gmp);
    mpq_class sum = 0;
    for (int k = 0; k < 3; ++k) sum += (mpq_class(a[k]) - p[k]) * (mpq_class(b[k]) - p[k]);
    const int s = sgn(sum);
    return s > 0 ? Sign::Positive : s < 0 ? Sign::Negative : Sign::Zero;
}

}  // namespace exactmesh::predicates
