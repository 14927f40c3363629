// SPDX-License-Identifier: MIT
// Symbolic perturbation by vertex index (see sos.hpp and proofs/invariants/
// symbolic_perturbation.md for the derivation of each cofactor sequence).
#include "predicates/sos.hpp"

#include <algorithm>
#include <array>
#include <utility>

#include "predicates/in_ellipse.hpp"
#include "predicates/incircle.hpp"
#include "predicates/insphere.hpp"
#include "predicates/orient2d.hpp"
#include "predicates/orient3d.hpp"

namespace exactmesh::predicates {

Sign orient2d_sos(const double* a, const double* b, const double* c, std::uint32_t ia,
                  std::uint32_t ib, std::uint32_t ic) {
    const Sign unperturbed = orient2d(a, b, c);
    if (unperturbed != Sign::Zero) return unperturbed;
    // Sort by decreasing index (p0 most perturbed), tracking the permutation's parity.
    std::array<std::pair<std::uint32_t, const double*>, 3> p = {{{ia, a}, {ib, b}, {ic, c}}};
    Sign parity = Sign::Positive;
    auto order = [&](int i, int j) {
        if (p[static_cast<unsigned>(i)].first < p[static_cast<unsigned>(j)].first) {
            std::swap(p[static_cast<unsigned>(i)], p[static_cast<unsigned>(j)]);
            parity = -parity;
        }
    };
    order(0, 1);
    order(1, 2);
    order(0, 1);
    const double* pi = p[0].second;
    const double* pj = p[1].second;
    const double* pk = p[2].second;
    // Coefficients of det [x y 1] (rows pi, pj, pk) in decreasing order of significance:
    // d/dy_i = x_k - x_j, d/dx_i = y_j - y_k, d/dy_j = x_i - x_k, then d2/dx_i dy_j = +1.
    Sign s = sign_of(pk[0] - pj[0]);  // exact: the sign of a difference is a comparison
    if (pk[0] == pj[0]) s = sign_of(pj[1] - pk[1]);
    if (s == Sign::Zero)
        s = pi[0] > pk[0] ? Sign::Positive : pi[0] < pk[0] ? Sign::Negative : Sign::Positive;
    return parity * s;
}

namespace {

/// The lifted perturbation's decision once the unperturbed 2D lifted determinant is zero:
/// d det[x y w 1] / d w_p is the signed cofactor of p's row: +O(bcd), -O(acd), +O(abd), -O(abc).
/// The most perturbed point (largest index) with a nonzero cofactor decides.
Sign lifted_cofactor_sign_2d(const double* a, const double* b, const double* c, const double* d,
                             std::uint32_t ia, std::uint32_t ib, std::uint32_t ic,
                             std::uint32_t id) {
    struct Term {
        std::uint32_t index;
        int which;
    };
    std::array<Term, 4> terms = {{{ia, 0}, {ib, 1}, {ic, 2}, {id, 3}}};
    std::sort(terms.begin(), terms.end(),
              [](const Term& x, const Term& y) { return x.index > y.index; });
    for (const Term& t : terms) {
        Sign s = Sign::Zero;
        switch (t.which) {
            case 0:
                s = orient2d(b, c, d);
                break;
            case 1:
                s = -orient2d(a, c, d);
                break;
            case 2:
                s = orient2d(a, b, d);
                break;
            default:
                s = -orient2d(a, b, c);
                break;
        }
        if (s != Sign::Zero) return s;
    }
    return Sign::Zero;
}

}  // namespace

Sign incircle_sos(const double* a, const double* b, const double* c, const double* d,
                  std::uint32_t ia, std::uint32_t ib, std::uint32_t ic, std::uint32_t id) {
    const Sign unperturbed = incircle(a, b, c, d);
    if (unperturbed != Sign::Zero) return unperturbed;
    return lifted_cofactor_sign_2d(a, b, c, d, ia, ib, ic, id);
}

Sign in_ellipse_sos(const double* a, const double* b, const double* c, const double* d,
                    const double* m, std::uint32_t ia, std::uint32_t ib, std::uint32_t ic,
                    std::uint32_t id) {
    const Sign unperturbed = in_ellipse(a, b, c, d, m);
    if (unperturbed != Sign::Zero) return unperturbed;
    return lifted_cofactor_sign_2d(a, b, c, d, ia, ib, ic, id);
}

Sign insphere_sos(const double* a, const double* b, const double* c, const double* d,
                  const double* e, std::uint32_t ia, std::uint32_t ib, std::uint32_t ic,
                  std::uint32_t id, std::uint32_t ie) {
    const Sign unperturbed = insphere(a, b, c, d, e);
    if (unperturbed != Sign::Zero) return unperturbed;
    // d det[x y z w 1] / d w_p: -O(bcde), +O(acde), -O(abde), +O(abce), -O(abcd).
    struct Term {
        std::uint32_t index;
        int which;
    };
    std::array<Term, 5> terms = {{{ia, 0}, {ib, 1}, {ic, 2}, {id, 3}, {ie, 4}}};
    std::sort(terms.begin(), terms.end(),
              [](const Term& x, const Term& y) { return x.index > y.index; });
    for (const Term& t : terms) {
        Sign s = Sign::Zero;
        switch (t.which) {
            case 0:
                s = -orient3d(b, c, d, e);
                break;
            case 1:
                s = orient3d(a, c, d, e);
                break;
            case 2:
                s = -orient3d(a, b, d, e);
                break;
            case 3:
                s = orient3d(a, b, c, e);
                break;
            default:
                s = -orient3d(a, b, c, d);
                break;
        }
        if (s != Sign::Zero) return s;
    }
    return Sign::Zero;
}

}  // namespace exactmesh::predicates
