// SPDX-License-Identifier: MIT
// Exact stages of orient2d [Shewchuk97 §4.3]: B when the coordinate differences are exact
// (a 4-component expansion), C over raw coordinates (12 components), D in GMP.
#include "predicates/orient2d.hpp"

#include "predicates/exact_range.hpp"
#include "predicates/expansion.hpp"
#include "predicates/gmp_fallback.hpp"

namespace exactmesh::predicates {

namespace {

/// px * qy - qx * py exactly.
Expansion<4> minor_xy(const double* p, const double* q) noexcept {
    return exact_product(p[0], q[1]) - exact_product(q[0], p[1]);
}

}  // namespace

Sign orient2d_exact(const double* a, const double* b, const double* c) {
    detail::require_finite("orient2d", {a[0], a[1], b[0], b[1], c[0], c[1]});
    if (!detail::expansion_safe(2, {a[0], a[1], b[0], b[1], c[0], c[1]})) {
        EM_STAT(orient2d, gmp);
        return orient2d_gmp(a, b, c);
    }
    double adx, bdx, ady, bdy, adx_tail, bdx_tail, ady_tail, bdy_tail;
    two_diff(a[0], c[0], adx, adx_tail);
    two_diff(b[0], c[0], bdx, bdx_tail);
    two_diff(a[1], c[1], ady, ady_tail);
    two_diff(b[1], c[1], bdy, bdy_tail);
    if (adx_tail == 0.0 && bdx_tail == 0.0 && ady_tail == 0.0 && bdy_tail == 0.0) {
        EM_STAT(orient2d, exact_differences);
        return (exact_product(adx, bdy) - exact_product(ady, bdx)).sign();
    }
    // det [x y 1] over rows a, b, c = m(a,b) + m(b,c) + m(c,a): no differences, no tails.
    EM_STAT(orient2d, expansion);
    return (minor_xy(a, b) + minor_xy(b, c) + minor_xy(c, a)).sign();
}

}  // namespace exactmesh::predicates
