// SPDX-License-Identifier: MIT
// Exact refinement decisions in scaled GMP integers (see tet_quality_3d.hpp).
#include "predicates/tet_quality_3d.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>

namespace exactmesh::predicates {

namespace {

using Vec = std::array<mpz_class, 3>;

/// The lowest exponent k with x an integer multiple of 2^k (x finite, non-zero).
int low_exponent(double x) {
    return std::ilogb(x) - 52;
}

/// x / 2^k as an exact integer (x an integer multiple of 2^k).
mpz_class scaled_integer(double x, int k) {
    if (x == 0) return 0;
    const int e = low_exponent(x);
    mpz_class z(std::ldexp(x, -e));  // |z| < 2^53: exact
    mpz_mul_2exp(z.get_mpz_t(), z.get_mpz_t(), static_cast<unsigned long>(e - k));
    return z;
}

/// The points as integer vectors on one common scale 2^k (k returned).
template <std::size_t N>
std::array<Vec, N> to_integers(const std::array<const double*, N>& points, int& k) {
    k = INT_MAX;
    for (const double* p : points)
        for (int i = 0; i < 3; ++i)
            if (p[i] != 0) k = std::min(k, low_exponent(p[i]));
    if (k == INT_MAX) k = 0;
    std::array<Vec, N> out;
    for (std::size_t j = 0; j < N; ++j)
        for (int i = 0; i < 3; ++i) out[j][i] = scaled_integer(points[j][i], k);
    return out;
}

Vec sub(const Vec& a, const Vec& b) {
    return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
mpz_class dot(const Vec& a, const Vec& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
Vec cross(const Vec& a, const Vec& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Vec scale(const mpz_class& s, const Vec& a) {
    return {s * a[0], s * a[1], s * a[2]};
}
Vec add(const Vec& a, const Vec& b) {
    return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}

Sign sign_of(const mpz_class& x) {
    const int s = sgn(x);
    return s > 0 ? Sign::Positive : s < 0 ? Sign::Negative : Sign::Zero;
}

/// x = m 2^e with m an integer (|m| < 2^53): splits a non-zero finite double.
void split_double(double x, mpz_class& m, int& e) {
    e = low_exponent(x);
    m = mpz_class(std::ldexp(x, -e));
}

/// Multiplies `right` by 2^s when s >= 0, else `left` by 2^-s: compares left with right 2^s.
void shift_pair(mpz_class& left, mpz_class& right, long s) {
    if (s >= 0) {
        mpz_mul_2exp(right.get_mpz_t(), right.get_mpz_t(), static_cast<unsigned long>(s));
    } else {
        mpz_mul_2exp(left.get_mpz_t(), left.get_mpz_t(), static_cast<unsigned long>(-s));
    }
}

}  // namespace

Sign compare_radius_edge_3d(const double* a, const double* b, const double* c, const double* d,
                            double bound) {
    int k = 0;
    const auto p = to_integers<4>({a, b, c, d}, k);
    const Vec u = sub(p[1], p[0]), v = sub(p[2], p[0]), w = sub(p[3], p[0]);
    const Vec vw = cross(v, w), wu = cross(w, u), uv = cross(u, v);
    const mpz_class det = dot(u, vw);
    // Circumcentre - a = (|u|^2 (v x w) + |v|^2 (w x u) + |w|^2 (u x v)) / (2 det).
    const Vec num = add(add(scale(dot(u, u), vw), scale(dot(v, v), wu)), scale(dot(w, w), uv));
    mpz_class shortest = dot(u, u);
    for (const Vec& e : {v, w, sub(p[2], p[1]), sub(p[3], p[1]), sub(p[3], p[2])})
        shortest = std::min<mpz_class>(shortest, dot(e, e));
    // R^2 > B^2 l^2  <=>  |num|^2 > 4 det^2 B^2 l^2, with B = m 2^e.
    mpz_class m;
    int e = 0;
    split_double(bound, m, e);
    mpz_class left = dot(num, num);
    mpz_class right = 4 * det * det * m * m * shortest;
    shift_pair(left, right, 2L * e);
    return sign_of(left - right);
}

Sign compare_tet_volume_3d(const double* a, const double* b, const double* c, const double* d,
                           double max_volume) {
    int k = 0;
    const auto p = to_integers<4>({a, b, c, d}, k);
    const Vec u = sub(p[1], p[0]), v = sub(p[2], p[0]), w = sub(p[3], p[0]);
    mpz_class det = dot(u, cross(v, w));
    det = abs(det);
    // |det| 2^(3k) / 6 > V = m 2^e  <=>  |det| 2^(3k - e) > 6 m.
    mpz_class m;
    int e = 0;
    split_double(max_volume, m, e);
    mpz_class right = 6 * m;
    shift_pair(right, det, 3L * k - e);
    return sign_of(det - right);
}

Sign in_equatorial_sphere_3d(const double* p, const double* a, const double* b, const double* c) {
    int k = 0;
    const auto x = to_integers<4>({p, a, b, c}, k);
    const Vec u = sub(x[2], x[1]), v = sub(x[3], x[1]), q = sub(x[0], x[1]);
    const Vec n = cross(u, v);
    // Centre - a = X / (2 |n|^2), X = |u|^2 (v x n) + |v|^2 (n x u); p strictly inside iff
    // |q|^2 - 2 q . (centre - a) < 0  <=>  |n|^2 |q|^2 - q . X < 0.
    const Vec big = add(scale(dot(u, u), cross(v, n)), scale(dot(v, v), cross(n, u)));
    return sign_of(dot(q, big) - dot(n, n) * dot(q, q));
}

Sign compare_angle_60_3d(const double* apex, const double* p, const double* q) {
    int k = 0;
    const auto x = to_integers<3>({apex, p, q}, k);
    const Vec u = sub(x[1], x[0]), v = sub(x[2], x[0]);
    const mpz_class uv = dot(u, v);
    if (sgn(uv) <= 0) return Sign::Negative;  // at least 90 degrees
    // cos > 1/2  <=>  4 (u.v)^2 > |u|^2 |v|^2 (u.v > 0).
    return sign_of(4 * uv * uv - dot(u, u) * dot(v, v));
}

Sign compare_lengths_3d(const double* a, const double* b, const double* c, const double* d) {
    int k = 0;
    const auto x = to_integers<4>({a, b, c, d}, k);
    const Vec u = sub(x[1], x[0]), v = sub(x[3], x[2]);
    return sign_of(dot(u, u) - dot(v, v));
}

}  // namespace exactmesh::predicates
