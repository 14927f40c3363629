// SPDX-License-Identifier: MIT
// Expansion arithmetic with zero elimination [Shewchuk97 §2.5-2.8].
#include "predicates/expansion.hpp"

namespace exactmesh::predicates {

namespace {
inline double at(const double* p, int i) noexcept { return p[i]; }
}  // namespace

int expansion_sum(int elen, const double* e, int flen, const double* f, double* h) noexcept {
    // Merge e and f by magnitude, then accumulate with two_sum. The merged order makes
    // fast_two_sum valid for the first step; round-to-even makes the result nonoverlapping
    // [Shewchuk97 Theorem 13].
    if (elen == 0) {
        for (int i = 0; i < flen; ++i) h[i] = f[i];
        return flen;
    }
    if (flen == 0) {
        for (int i = 0; i < elen; ++i) h[i] = e[i];
        return elen;
    }
    int ei = 0, fi = 0, hi = 0;
    double enow = at(e, 0), fnow = at(f, 0);
    double q, qnew, hh;
    if ((fnow > enow) == (fnow > -enow)) {
        q = enow;
        ++ei;
    } else {
        q = fnow;
        ++fi;
    }
    if (ei < elen && fi < flen) {
        enow = e[ei];
        fnow = f[fi];
        if ((fnow > enow) == (fnow > -enow)) {
            fast_two_sum(enow, q, qnew, hh);
            ++ei;
        } else {
            fast_two_sum(fnow, q, qnew, hh);
            ++fi;
        }
        q = qnew;
        if (hh != 0.0) h[hi++] = hh;
        while (ei < elen && fi < flen) {
            enow = e[ei];
            fnow = f[fi];
            if ((fnow > enow) == (fnow > -enow)) {
                two_sum(q, enow, qnew, hh);
                ++ei;
            } else {
                two_sum(q, fnow, qnew, hh);
                ++fi;
            }
            q = qnew;
            if (hh != 0.0) h[hi++] = hh;
        }
    }
    while (ei < elen) {
        two_sum(q, e[ei++], qnew, hh);
        q = qnew;
        if (hh != 0.0) h[hi++] = hh;
    }
    while (fi < flen) {
        two_sum(q, f[fi++], qnew, hh);
        q = qnew;
        if (hh != 0.0) h[hi++] = hh;
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
    if (hh != 0.0) h[hi++] = hh;
    for (int i = 1; i < elen; ++i) {
        two_product(e[i], b, product1, product0);
        two_sum(q, product0, sum, hh);
        if (hh != 0.0) h[hi++] = hh;
        fast_two_sum(product1, sum, q, hh);
        if (hh != 0.0) h[hi++] = hh;
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
