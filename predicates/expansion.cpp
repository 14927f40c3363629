// SPDX-License-Identifier: MIT
// Expansion arithmetic with zero elimination [Shewchuk97 §2.5-2.8].
#include "predicates/expansion.hpp"

namespace exactmesh::predicates {

int expansion_sum(int elen, const double* e, int flen, const double* f, double* h) noexcept {
    // Merge e and f by magnitude while accumulating with two_sum; round-to-even keeps the
    // result nonoverlapping [Shewchuk97 Theorem 13]. The merge choice and the zero
    // elimination are written without branches: their outcome is data-dependent and
    // unpredictable, and mispredictions dominated the exact stages' cost.
    if (elen == 0 || flen == 0) {
        const double* g = elen == 0 ? f : e;
        const int n = elen == 0 ? flen : elen;
        for (int i = 0; i < n; ++i) h[i] = g[i];
        return n;
    }
    int ei = 0, fi = 0, hi = 0;
    auto take_next = [&]() {
        const double enow = e[ei], fnow = f[fi];
        const bool from_e = std::fabs(fnow) > std::fabs(enow);
        ei += from_e ? 1 : 0;
        fi += from_e ? 0 : 1;
        return from_e ? enow : fnow;
    };
    double q = take_next();
    double qnew, hh;
    while (ei < elen && fi < flen) {
        two_sum(q, take_next(), qnew, hh);
        q = qnew;
        h[hi] = hh;
        hi += hh != 0.0 ? 1 : 0;
    }
    for (; ei < elen; ++ei) {
        two_sum(q, e[ei], qnew, hh);
        q = qnew;
        h[hi] = hh;
        hi += hh != 0.0 ? 1 : 0;
    }
    for (; fi < flen; ++fi) {
        two_sum(q, f[fi], qnew, hh);
        q = qnew;
        h[hi] = hh;
        hi += hh != 0.0 ? 1 : 0;
    }
    if (q != 0.0 || hi == 0) h[hi++] = q;
    if (hi == 1 && h[0] == 0.0) return 0;
    return hi;
}

int scale_expansion(int elen, const double* e, double b, double* h) noexcept {
    if (elen == 0 || b == 0.0) return 0;
    int hi = 0;
    double q, hh, product1, product0, sum;
    two_product(e[0], b, q, hh);
    h[hi] = hh;
    hi += hh != 0.0 ? 1 : 0;
    for (int i = 1; i < elen; ++i) {
        two_product(e[i], b, product1, product0);
        two_sum(q, product0, sum, hh);
        h[hi] = hh;
        hi += hh != 0.0 ? 1 : 0;
        fast_two_sum(product1, sum, q, hh);
        h[hi] = hh;
        hi += hh != 0.0 ? 1 : 0;
    }
    if (q != 0.0 || hi == 0) h[hi++] = q;
    if (hi == 1 && h[0] == 0.0) return 0;
    return hi;
}

int compress(int elen, const double* e, double* h) noexcept {
    if (elen == 0) return 0;
    int bottom = elen - 1;
    double q = e[bottom];
    for (int i = elen - 2; i >= 0; --i) {
        double qnew, small;
        fast_two_sum(q, e[i], qnew, small);
        if (small != 0.0) {
            h[bottom--] = qnew;
            q = small;
        } else {
            q = qnew;
        }
    }
    int top = 0;
    for (int i = bottom + 1; i < elen; ++i) {
        double qnew, small;
        fast_two_sum(h[i], q, qnew, small);
        if (small != 0.0) h[top++] = small;
        q = qnew;
    }
    h[top++] = q;
    if (top == 1 && h[0] == 0.0) return 0;
    return top;
}

double estimate(int elen, const double* e) noexcept {
    double q = 0.0;
    for (int i = 0; i < elen; ++i) q += e[i];
    return q;
}

}  // namespace exactmesh::predicates
