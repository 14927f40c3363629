// SPDX-License-Identifier: MIT
// Refinement decisions: a relative double filter, then exact in scaled GMP integers (see
// tet_quality_3d.hpp).
#include "predicates/tet_quality_3d.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <cstddef>
#include <optional>

#include "predicates/expansion.hpp"
#include "predicates/filter_constants.hpp"
#include "predicates/incircle.hpp"
#include "predicates/orient2d.hpp"
#include "predicates/power_of_two.hpp"
#include "predicates/relative_filter.hpp"
#include "predicates/scaled_integers.hpp"
#include "predicates/stats.hpp"

namespace exactmesh::predicates {

namespace {

using Vec = std::array<mpz_class, 3>;

using detail::least_set_bit_exponent;

/// x / 2^k as an exact integer (x an integer multiple of 2^k).
mpz_class scaled_integer(double x, int k) {
    mpz_class z;
    detail::set_scaled_integer(z.get_mpz_t(), x, k);
    return z;
}

/// The points as integer vectors on one common scale 2^k (k returned).
template <std::size_t N>
std::array<Vec, N> to_integers(const std::array<const double*, N>& points, int& k) {
    k = INT_MAX;
    for (const double* p : points)
        for (int i = 0; i < 3; ++i)
            if (p[i] != 0) k = std::min(k, least_set_bit_exponent(p[i]));
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
    e = least_set_bit_exponent(x);
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

Sign compare_radius_edge_3d_exact(const double* a, const double* b, const double* c,
                                  const double* d, double bound) {
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

Sign compare_tet_volume_3d_exact(const double* a, const double* b, const double* c, const double* d,
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

/// The GMP integers of in_equatorial_sphere_3d_exact, kept between calls (one set per thread):
/// written with mpz_class, each call made and freed about 40 temporaries, and the allocator took
/// most of its 26,000 instructions (20,700 calls on the wing at V = 4.46e-4, 14% of its
/// refinement: the rectangles of its extruded strips are cocircular, so every facet cavity
/// across a strip's diagonal is an exact tie).
struct EquatorialIntegers {
    mpz_t x[4][3];  // p, a, b, c scaled to integers
    mpz_t u[3], v[3], q[3], n[3], vn[3], nu[3], big[3];
    mpz_t uu, vv, nn, qq, value, product;
    EquatorialIntegers() {
        for (auto& row : x)
            for (auto& z : row) mpz_init2(z, 128);
        for (mpz_t* vec : {u, v, q, n, vn, nu, big})
            for (int i = 0; i < 3; ++i) mpz_init2(vec[i], 512);
        for (mpz_t* z : {&uu, &vv, &nn, &qq, &value, &product}) mpz_init2(*z, 512);
    }
    ~EquatorialIntegers() {
        for (auto& row : x)
            for (auto& z : row) mpz_clear(z);
        for (mpz_t* vec : {u, v, q, n, vn, nu, big})
            for (int i = 0; i < 3; ++i) mpz_clear(vec[i]);
        for (mpz_t* z : {&uu, &vv, &nn, &qq, &value, &product}) mpz_clear(*z);
    }
    EquatorialIntegers(const EquatorialIntegers&) = delete;
    EquatorialIntegers& operator=(const EquatorialIntegers&) = delete;
};

/// out = a x b.
void cross_into(mpz_t* out, const mpz_t* a, const mpz_t* b) {
    for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3, k = (i + 2) % 3;
        mpz_mul(out[i], a[j], b[k]);
        mpz_submul(out[i], a[k], b[j]);
    }
}

/// out = a . b.
void dot_into(mpz_t out, const mpz_t* a, const mpz_t* b) {
    mpz_mul(out, a[0], b[0]);
    mpz_addmul(out, a[1], b[1]);
    mpz_addmul(out, a[2], b[2]);
}

Sign in_equatorial_sphere_3d_exact(const double* p, const double* a, const double* b,
                                   const double* c) {
    thread_local EquatorialIntegers z;
    const double* points[4] = {p, a, b, c};
    // One common scale 2^k, k the least exponent of a set bit (as to_integers).
    int k = INT_MAX;
    for (const double* point : points)
        for (int i = 0; i < 3; ++i)
            if (point[i] != 0) k = std::min(k, least_set_bit_exponent(point[i]));
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 3; ++i) detail::set_scaled_integer(z.x[j][i], points[j][i], k);
    for (int i = 0; i < 3; ++i) {
        mpz_sub(z.u[i], z.x[2][i], z.x[1][i]);
        mpz_sub(z.v[i], z.x[3][i], z.x[1][i]);
        mpz_sub(z.q[i], z.x[0][i], z.x[1][i]);
    }
    cross_into(z.n, z.u, z.v);
    // Centre - a = X / (2 |n|^2), X = |u|^2 (v x n) + |v|^2 (n x u); p strictly inside iff
    // |q|^2 - 2 q . (centre - a) < 0  <=>  |n|^2 |q|^2 - q . X < 0.
    cross_into(z.vn, z.v, z.n);
    cross_into(z.nu, z.n, z.u);
    dot_into(z.uu, z.u, z.u);
    dot_into(z.vv, z.v, z.v);
    for (int i = 0; i < 3; ++i) {
        mpz_mul(z.big[i], z.uu, z.vn[i]);
        mpz_addmul(z.big[i], z.vv, z.nu[i]);
    }
    dot_into(z.value, z.q, z.big);
    dot_into(z.nn, z.n, z.n);
    dot_into(z.qq, z.q, z.q);
    mpz_mul(z.product, z.nn, z.qq);
    mpz_sub(z.value, z.value, z.product);
    const int s = mpz_sgn(z.value);
    return s > 0 ? Sign::Positive : s < 0 ? Sign::Negative : Sign::Zero;
}

/// in_equatorial_sphere_3d_exact's polynomial when the nine differences b - a, c - a, p - a
/// are exact doubles and integers below 2^7 times one power of two (lattice points: the ties
/// of refined boxes off their facets' planes). Scaled by that power of two (exact, checked),
/// every intermediate is an integer below 2^53 (n < 2^15, v x n and n x u < 2^23, |u|^2 < 2^16,
/// big < 2^40, q . big < 2^49, |n|^2 |q|^2 < 2^48, the difference < 2^50), so plain doubles
/// evaluate it exactly at any scale. nullopt otherwise.
std::optional<Sign> in_equatorial_sphere_3d_small_integers(const double* p, const double* a,
                                                           const double* b, const double* c) {
    double d[9];
    const double* rows[3] = {b, c, p};
    double largest = 0;
    for (int r = 0; r < 3; ++r) {
        for (int k = 0; k < 3; ++k) {
            double tail = 0;
            two_diff(rows[r][k], a[k], d[3 * r + k], tail);
            if (tail != 0 || !std::isfinite(d[3 * r + k])) return std::nullopt;
            largest = std::max(largest, std::fabs(d[3 * r + k]));
        }
    }
    if (largest == 0) return Sign::Zero;
    const int shift = 6 - std::ilogb(largest);  // largest scaled into [2^6, 2^7)
    for (double& x : d) {
        const double y = std::ldexp(x, shift);
        if (y != std::trunc(y) || (y == 0) != (x == 0)) return std::nullopt;
        x = y;
    }
    using V = std::array<double, 3>;
    const auto cross = [](const V& x, const V& y) {
        return V{x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]};
    };
    const auto dot = [](const V& x, const V& y) { return x[0] * y[0] + x[1] * y[1] + x[2] * y[2]; };
    const V u{d[0], d[1], d[2]}, v{d[3], d[4], d[5]}, q{d[6], d[7], d[8]};
    const V n = cross(u, v), vn = cross(v, n), nu = cross(n, u);
    const double uu = dot(u, u), vv = dot(v, v);
    const V big{uu * vn[0] + vv * nu[0], uu * vn[1] + vv * nu[1], uu * vn[2] + vv * nu[2]};
    const double value = dot(q, big) - dot(n, n) * dot(q, q);
    return value > 0 ? Sign::Positive : value < 0 ? Sign::Negative : Sign::Zero;
}

/// in_equatorial_sphere_3d for four points with one coordinate exactly equal (a facet in a
/// coordinate plane, as on boxes): the sphere's trace on that plane is the triangle's
/// circumcircle and p lies in the plane, so p is inside the sphere exactly when it is inside the
/// circle: the 2D incircle of the other two coordinates, times the triangle's 2D orientation
/// (both exact, on expansions: most exact calls are such ties, and GMP took 20,000
/// instructions each). nullopt when no coordinate is shared.
std::optional<Sign> in_equatorial_sphere_3d_planar(const double* p, const double* a,
                                                   const double* b, const double* c) {
    for (int k = 0; k < 3; ++k) {
        if (p[k] != a[k] || b[k] != a[k] || c[k] != a[k]) continue;
        const int i = k == 0 ? 1 : 0, j = k == 2 ? 1 : 2;
        const double pp[2] = {p[i], p[j]}, aa[2] = {a[i], a[j]}, bb[2] = {b[i], b[j]},
                     cc[2] = {c[i], c[j]};
        const int orientation = static_cast<int>(orient2d(aa, bb, cc));
        const int inside = static_cast<int>(incircle(aa, bb, cc, pp));
        const int s = orientation * inside;
        return s > 0 ? Sign::Positive : s < 0 ? Sign::Negative : Sign::Zero;
    }
    return std::nullopt;
}

Sign compare_angle_60_3d_exact(const double* apex, const double* p, const double* q) {
    int k = 0;
    const auto x = to_integers<3>({apex, p, q}, k);
    const Vec u = sub(x[1], x[0]), v = sub(x[2], x[0]);
    const mpz_class uv = dot(u, v);
    if (sgn(uv) <= 0) return Sign::Negative;  // at least 90 degrees
    // cos > 1/2  <=>  4 (u.v)^2 > |u|^2 |v|^2 (u.v > 0).
    return sign_of(4 * uv * uv - dot(u, u) * dot(v, v));
}

Sign compare_lengths_3d_exact(const double* a, const double* b, const double* c, const double* d) {
    int k = 0;
    const auto x = to_integers<4>({a, b, c, d}, k);
    const Vec u = sub(x[1], x[0]), v = sub(x[3], x[2]);
    return sign_of(dot(u, u) - dot(v, v));
}

// The filters (relative_filter.hpp): differences rounded once and scaled by one power of two,
// each decision a Term whose rounding count the type carries and whose eps Gappa proves
// (proofs/gappa/tet_quality_3d_*_filter.g). Every filtered polynomial has degree at most 9 in
// the scaled differences (counting the bound's m^2 as one: a multiple of 2^-52 in [1, 4)), and
// 9 (50 + 52) + 48 <= 1022 with the window 2^-50: nothing underflows, eps P is normal.

template <int R>
using Vec3 = std::array<detail::Term<R>, 3>;

template <int R, int S>
auto cross_terms(const Vec3<R>& a, const Vec3<S>& b) {
    using Out = Vec3<R + S + 2>;
    return Out{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
template <int R, int S>
auto dot_terms(const Vec3<R>& a, const Vec3<S>& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
/// Differences d[3 i .. 3 i + 2] as the i-th vector.
template <std::size_t N>
Vec3<1> vector_at(const double (&d)[N], std::size_t i) {
    return {detail::difference(d[3 * i]), detail::difference(d[3 * i + 1]),
            detail::difference(d[3 * i + 2])};
}
/// The rounded differences x - y, three per pair, into `out` from position 3 i.
template <std::size_t N>
void put_difference(double (&out)[N], std::size_t i, const double* x, const double* y) {
    for (std::size_t k = 0; k < 3; ++k) out[3 * i + k] = x[k] - y[k];
}

}  // namespace

std::optional<Sign> compare_radius_edge_3d_filter(const double* a, const double* b, const double* c,
                                                  const double* d, double bound) {
    // B = m 2^e with m in [1, 2); |e| <= 64 keeps 2^(2|e|) far from overflow (beyond: GMP).
    if (!(bound > 0) || !std::isfinite(bound)) return std::nullopt;
    const int e = binary_exponent(bound);
    if (e < -64 || e > 64) return std::nullopt;
    const double m = PowerOfTwo(-e)(bound);
    double diff[18];
    put_difference(diff, 0, b, a);
    put_difference(diff, 1, c, a);
    put_difference(diff, 2, d, a);
    put_difference(diff, 3, c, b);
    put_difference(diff, 4, d, b);
    put_difference(diff, 5, d, c);
    if (!detail::scale_differences(diff, tet_quality_3d_filter_window_min)) return std::nullopt;
    const Vec3<1> u = vector_at(diff, 0), v = vector_at(diff, 1), w = vector_at(diff, 2);
    const auto vw = cross_terms(v, w), wu = cross_terms(w, u), uv = cross_terms(u, v);
    const auto det = dot_terms(u, vw);
    const auto uu = dot_terms(u, u), vv = dot_terms(v, v), ww = dot_terms(w, w);
    using Num = decltype(uu * vw[0] + vv * wu[0] + ww * uv[0]);
    const std::array<Num, 3> num{uu * vw[0] + vv * wu[0] + ww * uv[0],
                                 uu * vw[1] + vv * wu[1] + ww * uv[1],
                                 uu * vw[2] + vv * wu[2] + ww * uv[2]};
    // R^2 > B^2 l^2  <=>  |num|^2 > 4 det^2 m^2 2^(2e) l^2: the power of two goes to the side
    // it enlarges, so nothing shrinks towards underflow.
    const double left_power = PowerOfTwo(e < 0 ? -2 * e : 0)(1.0);
    const double right_power = PowerOfTwo(e > 0 ? 2 * e : 0)(1.0);
    const auto left =
        detail::scaled(num[0] * num[0] + num[1] * num[1] + num[2] * num[2], left_power);
    const auto det_bound = detail::scaled(det * det, 4.0) * detail::rounded_constant(m * m);
    // sign(R - B l_min) = sign(max over the edges of F_e), F_e = left - det_bound l_e^2: Positive
    // as soon as one F_e is certified positive, Negative when all six are certified negative.
    bool all_negative = true;
    for (std::size_t i = 0; i < 6; ++i) {
        const Vec3<1> edge = vector_at(diff, i);
        const auto value = left - detail::scaled(det_bound * dot_terms(edge, edge), right_power);
        const auto s = detail::certified<tet_quality_3d_radius_edge_filter_roundings>(
            value, tet_quality_3d_radius_edge_filter_eps);
        if (s == Sign::Positive) return Sign::Positive;
        all_negative = all_negative && s == Sign::Negative;
    }
    if (all_negative) return Sign::Negative;
    return std::nullopt;
}

std::optional<Sign> compare_tet_volume_3d_filter(const double* a, const double* b, const double* c,
                                                 const double* d, double max_volume) {
    if (!(max_volume > 0) || !std::isfinite(max_volume)) return std::nullopt;
    double diff[9];
    put_difference(diff, 0, b, a);
    put_difference(diff, 1, c, a);
    put_difference(diff, 2, d, a);
    const auto shift = detail::scale_differences(diff, tet_quality_3d_filter_window_min);
    if (!shift) return std::nullopt;
    const Vec3<1> u = vector_at(diff, 0), v = vector_at(diff, 1), w = vector_at(diff, 2);
    // Scaled units: det' = det 2^(3 shift) and V' = V 2^(3 shift); |det'| <= |u| |v| |w| < 42
    // (scaled differences below 2, the exact ones below 2 (1 + 2^-53)).
    const auto det = dot_terms(u, cross_terms(v, w));
    const int volume_exponent = binary_exponent(max_volume) + 3 * *shift;
    if (volume_exponent >= 3) return Sign::Negative;  // 6 V' >= 48 > |det'|
    const auto det_sign = detail::certified<tet_quality_3d_volume_det_roundings>(
        det, tet_quality_3d_volume_filter_eps);
    if (!det_sign) return std::nullopt;
    if (volume_exponent < -900) {
        // 6 V' < 6 2^-899; |det'| >= |det| - eps P > |det| / 2 >= 2^-801 when certified so.
        const double magnitude = std::fabs(det.value());
        if (magnitude >= 0x1p-800 &&
            magnitude > 2 * tet_quality_3d_volume_filter_eps * det.permanent())
            return Sign::Positive;
        return std::nullopt;
    }
    const double volume = std::ldexp(max_volume, 3 * *shift);  // normal: exact
    const auto value =
        detail::signed_by(det, *det_sign == Sign::Negative) - detail::rounded_constant(6 * volume);
    return detail::certified<tet_quality_3d_volume_filter_roundings>(
        value, tet_quality_3d_volume_filter_eps);
}

std::optional<Sign> in_equatorial_sphere_3d_filter(const double* p, const double* a,
                                                   const double* b, const double* c) {
    double diff[9];
    put_difference(diff, 0, b, a);
    put_difference(diff, 1, c, a);
    put_difference(diff, 2, p, a);
    if (!detail::scale_differences(diff, tet_quality_3d_filter_window_min)) return std::nullopt;
    const Vec3<1> u = vector_at(diff, 0), v = vector_at(diff, 1), q = vector_at(diff, 2);
    const auto n = cross_terms(u, v);
    const auto vn = cross_terms(v, n), nu = cross_terms(n, u);
    const auto uu = dot_terms(u, u), vv = dot_terms(v, v);
    using Big = decltype(uu * vn[0] + vv * nu[0]);
    const std::array<Big, 3> big{uu * vn[0] + vv * nu[0], uu * vn[1] + vv * nu[1],
                                 uu * vn[2] + vv * nu[2]};
    const auto value = dot_terms(q, big) - dot_terms(n, n) * dot_terms(q, q);
    return detail::certified<tet_quality_3d_equatorial_filter_roundings>(
        value, tet_quality_3d_equatorial_filter_eps);
}

std::optional<Sign> compare_angle_60_3d_filter(const double* apex, const double* p,
                                               const double* q) {
    double diff[6];
    put_difference(diff, 0, p, apex);
    put_difference(diff, 1, q, apex);
    if (!detail::scale_differences(diff, tet_quality_3d_filter_window_min)) return std::nullopt;
    const Vec3<1> u = vector_at(diff, 0), v = vector_at(diff, 1);
    const auto uv = dot_terms(u, v);
    const auto uv_sign =
        detail::certified<tet_quality_3d_angle_dot_roundings>(uv, tet_quality_3d_angle_filter_eps);
    if (uv_sign != Sign::Positive) return uv_sign;  // Negative: at least 90 degrees; or unsure
    const auto value = detail::scaled(uv * uv, 4.0) - dot_terms(u, u) * dot_terms(v, v);
    return detail::certified<tet_quality_3d_angle_filter_roundings>(
        value, tet_quality_3d_angle_filter_eps);
}

std::optional<Sign> compare_lengths_3d_filter(const double* a, const double* b, const double* c,
                                              const double* d) {
    double diff[6];
    put_difference(diff, 0, b, a);
    put_difference(diff, 1, d, c);
    if (!detail::scale_differences(diff, tet_quality_3d_filter_window_min)) return std::nullopt;
    const Vec3<1> u = vector_at(diff, 0), v = vector_at(diff, 1);
    return detail::certified<tet_quality_3d_lengths_filter_roundings>(
        dot_terms(u, u) - dot_terms(v, v), tet_quality_3d_lengths_filter_eps);
}

Sign compare_radius_edge_3d(const double* a, const double* b, const double* c, const double* d,
                            double bound) {
    EM_STAT(compare_radius_edge_3d, calls);
    if (const auto s = compare_radius_edge_3d_filter(a, b, c, d, bound)) {
        EM_STAT(compare_radius_edge_3d, filter);
        return *s;
    }
    EM_STAT(compare_radius_edge_3d, gmp);
    return compare_radius_edge_3d_exact(a, b, c, d, bound);
}

Sign compare_tet_volume_3d(const double* a, const double* b, const double* c, const double* d,
                           double max_volume) {
    EM_STAT(compare_tet_volume_3d, calls);
    if (const auto s = compare_tet_volume_3d_filter(a, b, c, d, max_volume)) {
        EM_STAT(compare_tet_volume_3d, filter);
        return *s;
    }
    EM_STAT(compare_tet_volume_3d, gmp);
    return compare_tet_volume_3d_exact(a, b, c, d, max_volume);
}

Sign in_equatorial_sphere_3d(const double* p, const double* a, const double* b, const double* c) {
    EM_STAT(in_equatorial_sphere_3d, calls);
    if (const auto s = in_equatorial_sphere_3d_filter(p, a, b, c)) {
        EM_STAT(in_equatorial_sphere_3d, filter);
        return *s;
    }
    if (const auto s = in_equatorial_sphere_3d_planar(p, a, b, c)) {
        EM_STAT(in_equatorial_sphere_3d, expansion);
        return *s;
    }
    if (const auto s = in_equatorial_sphere_3d_small_integers(p, a, b, c)) {
        EM_STAT(in_equatorial_sphere_3d, exact_differences);
        return *s;
    }
    EM_STAT(in_equatorial_sphere_3d, gmp);
    return in_equatorial_sphere_3d_exact(p, a, b, c);
}

Sign compare_angle_60_3d(const double* apex, const double* p, const double* q) {
    EM_STAT(compare_angle_60_3d, calls);
    if (const auto s = compare_angle_60_3d_filter(apex, p, q)) {
        EM_STAT(compare_angle_60_3d, filter);
        return *s;
    }
    EM_STAT(compare_angle_60_3d, gmp);
    return compare_angle_60_3d_exact(apex, p, q);
}

Sign compare_lengths_3d(const double* a, const double* b, const double* c, const double* d) {
    EM_STAT(compare_lengths_3d, calls);
    if (const auto s = compare_lengths_3d_filter(a, b, c, d)) {
        EM_STAT(compare_lengths_3d, filter);
        return *s;
    }
    EM_STAT(compare_lengths_3d, gmp);
    return compare_lengths_3d_exact(a, b, c, d);
}

}  // namespace exactmesh::predicates
