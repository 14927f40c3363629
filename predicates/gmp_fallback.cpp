// SPDX-License-Identifier: MIT
// Stage D: the difference-form determinants in GMP rationals. mpq_class(double) is exact for
// every finite double, subnormals included, and rationals cannot overflow, so the sign is exact.
#include "predicates/gmp_fallback.hpp"

#include <gmpxx.h>

namespace exactmesh::predicates {

namespace {

Sign sign_of(const mpq_class& x) {
    const int s = sgn(x);
    return s > 0 ? Sign::Positive : (s < 0 ? Sign::Negative : Sign::Zero);
}

}  // namespace

Sign orient2d_gmp(const double* a, const double* b, const double* c) {
    const mpq_class adx = mpq_class(a[0]) - c[0], ady = mpq_class(a[1]) - c[1];
    const mpq_class bdx = mpq_class(b[0]) - c[0], bdy = mpq_class(b[1]) - c[1];
    return sign_of(adx * bdy - ady * bdx);
}

Sign orient3d_gmp(const double* a, const double* b, const double* c, const double* d) {
    mpq_class m[3][3];
    const double* rows[3] = {a, b, c};
    for (int r = 0; r < 3; ++r) {
        for (int k = 0; k < 3; ++k) m[r][k] = mpq_class(rows[r][k]) - d[k];
    }
    const mpq_class det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                          m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                          m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    return sign_of(det);
}

Sign incircle_gmp(const double* a, const double* b, const double* c, const double* d) {
    mpq_class m[3][3];
    const double* rows[3] = {a, b, c};
    for (int r = 0; r < 3; ++r) {
        m[r][0] = mpq_class(rows[r][0]) - d[0];
        m[r][1] = mpq_class(rows[r][1]) - d[1];
        m[r][2] = m[r][0] * m[r][0] + m[r][1] * m[r][1];
    }
    const mpq_class det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                          m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                          m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    return sign_of(det);
}

Sign insphere_gmp(const double* a, const double* b, const double* c, const double* d,
                  const double* e) {
    mpq_class m[4][4];
    const double* rows[4] = {a, b, c, d};
    for (int r = 0; r < 4; ++r) {
        for (int k = 0; k < 3; ++k) m[r][k] = mpq_class(rows[r][k]) - e[k];
        m[r][3] = m[r][0] * m[r][0] + m[r][1] * m[r][1] + m[r][2] * m[r][2];
    }
    // Laplace expansion along the first row with 3x3 minors.
    auto minor3 = [&](int skip) {
        int cols[3], n = 0;
        for (int k = 0; k < 4; ++k) {
            if (k != skip) cols[n++] = k;
        }
        return mpq_class(m[1][cols[0]] * (m[2][cols[1]] * m[3][cols[2]] - m[2][cols[2]] * m[3][cols[1]]) -
                         m[1][cols[1]] * (m[2][cols[0]] * m[3][cols[2]] - m[2][cols[2]] * m[3][cols[0]]) +
                         m[1][cols[2]] * (m[2][cols[0]] * m[3][cols[1]] - m[2][cols[1]] * m[3][cols[0]]));
    };
    const mpq_class det =
        m[0][0] * minor3(0) - m[0][1] * minor3(1) + m[0][2] * minor3(2) - m[0][3] * minor3(3);
    return sign_of(det);
}

}  // namespace exactmesh::predicates
