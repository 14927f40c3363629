// SPDX-License-Identifier: MIT
// Stage D: the difference-form determinants in GMP integers. Every finite double is M·2^E with
// an integer |M| < 2^53 and E >= -1074. Each determinant is a homogeneous polynomial of the
// coordinates (degree 2, 3, 4, 5), so scaling every input of one call by 2^-Emin, Emin the least
// E among them, multiplies it by a positive power of two and keeps its sign, while making every
// coordinate an integer. Integers never overflow in GMP, so the sign is exact; and unlike
// rationals (mpq, the previous version) they need no gcd after each operation: 3-4x fewer
// cycles on a conforming run whose coordinates span 1e-322..1e231 (perf, 2026-11-23).
#include "predicates/gmp_fallback.hpp"

#include "predicates/scaled_integers.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <cstddef>
#include <cstdint>

namespace exactmesh::predicates {

namespace {

using detail::scaled_integers;

Sign sign_of(const mpz_class& x) {
    const int s = sgn(x);
    return s > 0 ? Sign::Positive : (s < 0 ? Sign::Negative : Sign::Zero);
}

}  // namespace

Sign orient2d_gmp(const double* a, const double* b, const double* c) {
    const auto v = scaled_integers<6>({a[0], a[1], b[0], b[1], c[0], c[1]});
    const mpz_class adx = v[0] - v[4], ady = v[1] - v[5];
    const mpz_class bdx = v[2] - v[4], bdy = v[3] - v[5];
    return sign_of(adx * bdy - ady * bdx);
}

Sign orient3d_gmp(const double* a, const double* b, const double* c, const double* d) {
    const auto v = scaled_integers<12>(
        {a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2], d[0], d[1], d[2]});
    mpz_class m[3][3];
    for (int r = 0; r < 3; ++r) {
        for (int k = 0; k < 3; ++k) m[r][k] = v[3 * r + k] - v[9 + k];
    }
    const mpz_class det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                          m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                          m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    return sign_of(det);
}

Sign incircle_gmp(const double* a, const double* b, const double* c, const double* d) {
    const auto v = scaled_integers<8>({a[0], a[1], b[0], b[1], c[0], c[1], d[0], d[1]});
    mpz_class m[3][3];
    for (int r = 0; r < 3; ++r) {
        m[r][0] = v[2 * r] - v[6];
        m[r][1] = v[2 * r + 1] - v[7];
        m[r][2] = m[r][0] * m[r][0] + m[r][1] * m[r][1];
    }
    const mpz_class det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                          m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                          m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    return sign_of(det);
}

Sign in_ellipse_gmp(const double* a, const double* b, const double* c, const double* d,
                    const double* m) {
    // Coordinates and M scaled by their own powers of two: the determinant is homogeneous in each
    // group (degree 4 and 1), so both scalings keep its sign.
    const auto v = scaled_integers<8>({a[0], a[1], b[0], b[1], c[0], c[1], d[0], d[1]});
    const auto metric = scaled_integers<3>({m[0], m[1], m[2]});
    mpz_class r[3][3];
    for (int i = 0; i < 3; ++i) {
        r[i][0] = v[2 * i] - v[6];
        r[i][1] = v[2 * i + 1] - v[7];
        r[i][2] = metric[0] * r[i][0] * r[i][0] + 2 * metric[1] * r[i][0] * r[i][1] +
                  metric[2] * r[i][1] * r[i][1];
    }
    const mpz_class det = r[0][0] * (r[1][1] * r[2][2] - r[1][2] * r[2][1]) -
                          r[0][1] * (r[1][0] * r[2][2] - r[1][2] * r[2][0]) +
                          r[0][2] * (r[1][0] * r[2][1] - r[1][1] * r[2][0]);
    return sign_of(det);
}

Sign insphere_gmp(const double* a, const double* b, const double* c, const double* d,
                  const double* e) {
    const auto v = scaled_integers<15>(
        {a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2], d[0], d[1], d[2], e[0], e[1], e[2]});
    mpz_class m[4][4];
    for (int r = 0; r < 4; ++r) {
        for (int k = 0; k < 3; ++k) m[r][k] = v[3 * r + k] - v[12 + k];
        m[r][3] = m[r][0] * m[r][0] + m[r][1] * m[r][1] + m[r][2] * m[r][2];
    }
    // Laplace expansion along the first row with 3x3 minors.
    auto minor3 = [&](int skip) {
        int cols[3], n = 0;
        for (int k = 0; k < 4; ++k) {
            if (k != skip) cols[n++] = k;
        }
        return mpz_class(
            m[1][cols[0]] * (m[2][cols[1]] * m[3][cols[2]] - m[2][cols[2]] * m[3][cols[1]]) -
            m[1][cols[1]] * (m[2][cols[0]] * m[3][cols[2]] - m[2][cols[2]] * m[3][cols[0]]) +
            m[1][cols[2]] * (m[2][cols[0]] * m[3][cols[1]] - m[2][cols[1]] * m[3][cols[0]]));
    };
    const mpz_class det =
        m[0][0] * minor3(0) - m[0][1] * minor3(1) + m[0][2] * minor3(2) - m[0][3] * minor3(3);
    return sign_of(det);
}

Sign triangle_area_gmp(const double* a, const double* b, const double* c, double area) {
    // Not homogeneous: the determinant has degree 2 in the coordinates, the area degree 0. With
    // the coordinates scaled to integers by 2^-least, det = D 2^(2 least) for the integer D;
    // area = M 2^E (frexp); compare D 2^(2 least) with M 2^(E + 1) after dividing both by
    // 2^min(2 least, E + 1), which leaves two integers.
    int least = 0;
    const auto v = scaled_integers<6>({a[0], a[1], b[0], b[1], c[0], c[1]}, &least);
    const mpz_class det = (v[0] - v[4]) * (v[3] - v[5]) - (v[1] - v[5]) * (v[2] - v[4]);
    if (area == 0.0) return sign_of(det);
    if (least == INT_MAX) return area > 0 ? Sign::Negative : Sign::Positive;
    int e = 0;
    const double f = std::frexp(area, &e);
    mpz_class twice_area = static_cast<long>(std::ldexp(f, 53));
    e -= 53;
    const long det_exponent = 2L * least, area_exponent = e + 1L;
    const long common = std::min(det_exponent, area_exponent);
    mpz_class scaled_det = det;
    mpz_mul_2exp(scaled_det.get_mpz_t(), scaled_det.get_mpz_t(),
                 static_cast<mp_bitcnt_t>(det_exponent - common));
    mpz_mul_2exp(twice_area.get_mpz_t(), twice_area.get_mpz_t(),
                 static_cast<mp_bitcnt_t>(area_exponent - common));
    return sign_of(mpz_class(scaled_det - twice_area));
}

}  // namespace exactmesh::predicates
