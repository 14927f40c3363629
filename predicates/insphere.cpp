// SPDX-License-Identifier: MIT
// Exact stages of insphere [Shewchuk97 §4.6]: B the exact determinant of the rounded
// differences (1152 components; exact when they are, else certified by an error bound), then
// the raw-coordinate det [x y z w 1] (5760 components), and GMP out of range.
#include "predicates/insphere.hpp"

#include "predicates/adaptive_bounds.hpp"
#include "predicates/exact_range.hpp"
#include "predicates/expansion.hpp"
#include "predicates/gmp_fallback.hpp"

namespace exactmesh::predicates {

namespace {

/// px * qy - qx * py exactly.
Expansion<4> minor_xy(const double* p, const double* q) noexcept {
    return exact_product(p[0], q[1]) - exact_product(q[0], p[1]);
}

/// det [p; q; r] of xyz rows, expanded along z; compressed, since it is multiplied next.
Expansion<24> det3_xyz(const double* p, const double* q, const double* r) noexcept {
    return compressed(scale(minor_xy(q, r), p[2]) - scale(minor_xy(p, r), q[2]) +
                      scale(minor_xy(p, q), r[2]));
}

/// px^2 + py^2 + pz^2 exactly, compressed (usually 2 components).
Expansion<6> lift(const double* p) noexcept {
    return compressed(exact_product(p[0], p[0]) + exact_product(p[1], p[1]) +
                      exact_product(p[2], p[2]));
}

/// (px^2 + py^2 + pz^2) * m exactly, as a product of two short compressed expansions.
template <int N>
Expansion<12 * N> lift_times(const double* p, const Expansion<N>& m) noexcept {
    return product(lift(p), compressed(m));
}

/// Raw det [x y z 1] over rows p, q, r, s, given their four xyz minors.
Expansion<96> det4_xyz1(const Expansion<24>& pqr, const Expansion<24>& pqs,
                        const Expansion<24>& prs, const Expansion<24>& qrs) noexcept {
    return compressed((pqr - pqs) + (prs - qrs));
}

}  // namespace

Sign insphere_exact(const double* a, const double* b, const double* c, const double* d,
                    const double* e) {
    const auto coordinates = {a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1],
                              c[2], d[0], d[1], d[2], e[0], e[1], e[2]};
    detail::require_finite("insphere", coordinates);
    if (!detail::expansion_safe(5, coordinates)) {
        EM_STAT(insphere, gmp);
        return insphere_gmp(a, b, c, d, e);
    }
    double diff[12], tail[12];
    const double* rows[4] = {a, b, c, d};
    bool exact = true;
    for (int r = 0; r < 4; ++r) {
        for (int k = 0; k < 3; ++k) {
            two_diff(rows[r][k], e[k], diff[3 * r + k], tail[3 * r + k]);
            exact = exact && tail[3 * r + k] == 0.0;
        }
    }
    // Stage B: det [p-e, |p-e|^2] of the rounded differences, exactly, along the lift column.
    const double* ae = diff;
    const double* be = diff + 3;
    const double* ce = diff + 6;
    const double* de = diff + 9;
    const auto det_b = (lift_times(be, det3_xyz(ae, ce, de)) - lift_times(ae, det3_xyz(be, ce, de))) +
                       (lift_times(de, det3_xyz(ae, be, ce)) - lift_times(ce, det3_xyz(ae, be, de)));
    if (exact) {
        EM_STAT(insphere, exact_differences);
        return det_b.sign();
    }
    // The permanent: each lift times the permanent of the other rows' xyz minor.
    auto lift = [](const double* p) { return p[0] * p[0] + p[1] * p[1] + p[2] * p[2]; };
    auto permanent3 = [](const double* p, const double* q, const double* r) {
        return (std::fabs(p[0] * q[1]) + std::fabs(q[0] * p[1])) * std::fabs(r[2]) +
               (std::fabs(q[0] * r[1]) + std::fabs(r[0] * q[1])) * std::fabs(p[2]) +
               (std::fabs(r[0] * p[1]) + std::fabs(p[0] * r[1])) * std::fabs(q[2]);
    };
    const double permanent = lift(ae) * permanent3(be, ce, de) + lift(be) * permanent3(ae, ce, de) +
                             lift(ce) * permanent3(ae, be, de) + lift(de) * permanent3(ae, be, ce);
    const double det = det_b.approximate();
    if (adaptive::certified(det, adaptive::isp_errbound_b * permanent)) {
        EM_STAT(insphere, adaptive);
        return sign_of(det);
    }
    // det [x y z w 1] over rows a..e, expanded along the lift column w:
    // -w_a O(bcde) + w_b O(acde) - w_c O(abde) + w_d O(abce) - w_e O(abcd).
    EM_STAT(insphere, expansion);
    const auto abc = det3_xyz(a, b, c), abd = det3_xyz(a, b, d), abe = det3_xyz(a, b, e);
    const auto acd = det3_xyz(a, c, d), ace = det3_xyz(a, c, e), ade = det3_xyz(a, d, e);
    const auto bcd = det3_xyz(b, c, d), bce = det3_xyz(b, c, e), bde = det3_xyz(b, d, e);
    const auto cde = det3_xyz(c, d, e);
    const auto o_bcde = det4_xyz1(bcd, bce, bde, cde);
    const auto o_acde = det4_xyz1(acd, ace, ade, cde);
    const auto o_abde = det4_xyz1(abd, abe, ade, bde);
    const auto o_abce = det4_xyz1(abc, abe, ace, bce);
    const auto o_abcd = det4_xyz1(abc, abd, acd, bcd);
    const auto sum = ((lift_times(b, o_acde) - lift_times(a, o_bcde)) +
                      (lift_times(d, o_abce) - lift_times(c, o_abde))) -
                     lift_times(e, o_abcd);
    return sum.sign();
}

}  // namespace exactmesh::predicates
