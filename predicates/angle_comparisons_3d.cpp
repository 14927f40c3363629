// SPDX-License-Identifier: MIT
// Exact dihedral-angle and volume-edge comparisons (see angle_comparisons_3d.hpp).
//
// Filter. Every polynomial is evaluated in long double (64-bit significand, u = 2^-64, exponent
// range to 2^16383 on x86-64) from the coordinate differences, alongside its "magnitude": the
// same expression evaluated on the absolute values with every subtraction made an addition, and
// the number k of roundings any of its monomials goes through (a difference of two doubles is
// one; a sum adds one to the larger count of its operands; a product adds the two counts and
// one). By the standard forward error analysis of sums of products [Higham, "Accuracy and
// Stability of Numerical Algorithms", §3.1], |fl(E) - E| <= gamma_k M with M the exact
// magnitude, and the computed magnitude is at least M (1 - u)^k (nonnegative terms only), so
// |fl(E) - E| <= gamma_k / (1 - u)^k fl(M); the filter certifies the sign when
// |fl(E)| > f (k + 1) u fl(M), f = angle_comparisons_3d_filter_factor, the least power of two for
// which Gappa proves the per-monomial inequality, the rounding of the bound itself included, for
// every k up to angle_comparisons_3d_filter_max_roundings = 64 (proofs/gappa/
// angle_comparisons_3d_filter.g); above it the filter abstains. The counts stay below 50 here.
// The window: every nonzero difference has magnitude in [2^-500, 2^500]. Then no operation
// overflows (degree <= 16: below 2^8100 with every term count) and none underflows: a nonzero
// sum of two long doubles is at least 2^-64 times the smaller operand, and the deepest
// expression has fewer than 30 sums on any path, so every nonzero intermediate exceeds
// 2^(-16*500 - 64*30) > 2^-10000, far above the smallest normal 2^-16382. Outside the window,
// the coordinates are scaled into it by one power of two when that is exact (both comparisons
// are homogeneous) and filtered again; when long double is not the 80-bit format, or when the
// filter is inconclusive: GMP rationals.
#include "predicates/angle_comparisons_3d.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>

#include "predicates/exact_range.hpp"
#include "predicates/exact_reference.hpp"
#include "predicates/expansion.hpp"
#include "predicates/filter_constants.hpp"
#include "predicates/scaled_integers.hpp"
#include "predicates/stats.hpp"

namespace exactmesh::predicates {

namespace {

constexpr bool kLongDoubleFilter = std::numeric_limits<long double>::digits >= 64 &&
                                   std::numeric_limits<long double>::max_exponent >= 16384;
constexpr long double kUnit = std::numeric_limits<long double>::epsilon() / 2;  // 2^-64
constexpr long double kWindowLow = 0x1p-500L;
constexpr long double kWindowHigh = 0x1p500L;

/// A value with its magnitude and rounding count (header comment).
struct Approx {
    long double value;
    long double magnitude;
    int roundings;
};

[[gnu::always_inline]] inline Approx operator+(const Approx& a, const Approx& b) {
    return {a.value + b.value, a.magnitude + b.magnitude, std::max(a.roundings, b.roundings) + 1};
}
[[gnu::always_inline]] inline Approx operator-(const Approx& a, const Approx& b) {
    return {a.value - b.value, a.magnitude + b.magnitude, std::max(a.roundings, b.roundings) + 1};
}
[[gnu::always_inline]] inline Approx operator*(const Approx& a, const Approx& b) {
    return {a.value * b.value, a.magnitude * b.magnitude, a.roundings + b.roundings + 1};
}

/// The certified sign, or Zero with `certain` false when the filter cannot tell.
Sign filtered_sign(const Approx& a, bool& certain) {
    if (a.magnitude == 0) return Sign::Zero;  // every monomial vanishes: exactly zero
    if (a.roundings > angle_comparisons_3d_filter_max_roundings) {
        certain = false;
        return Sign::Zero;
    }
    const long double bound = angle_comparisons_3d_filter_factor *
                              static_cast<long double>(a.roundings + 1) * kUnit * a.magnitude;
    if (a.value > bound) return Sign::Positive;
    if (a.value < -bound) return Sign::Negative;
    certain = false;
    return Sign::Zero;
}

struct Vector3 {
    Approx x, y, z;
};

/// p - o in long double; `in_window` turns false when a nonzero difference leaves the window.
[[gnu::always_inline]] inline Vector3 difference(const double* p, const double* o,
                                                 bool& in_window) {
    Vector3 r;
    Approx* c[3] = {&r.x, &r.y, &r.z};
    for (int i = 0; i < 3; ++i) {
        const long double d = static_cast<long double>(p[i]) - static_cast<long double>(o[i]);
        const long double m = std::fabs(d);
        if (m != 0 && (m < kWindowLow || m > kWindowHigh)) in_window = false;
        *c[i] = {d, m, 1};
    }
    return r;
}

[[gnu::always_inline]] inline Vector3 cross(const Vector3& a, const Vector3& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
[[gnu::always_inline]] inline Approx dot(const Vector3& a, const Vector3& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

constexpr unsigned kEdges[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};

/// The pieces of a dihedral angle: d = n1 . n2 and N = |n1|^2 |n2|^2.
struct DihedralTerms {
    Approx d, norms;
};

DihedralTerms dihedral_terms(const Dihedral& a, bool& in_window) {
    unsigned k = 0;
    while (k == a.i || k == a.j) ++k;
    unsigned l = k + 1;
    while (l == a.i || l == a.j) ++l;
    const double* o = a.p[a.i];
    const Vector3 e = difference(a.p[a.j], o, in_window);
    const Vector3 u = difference(a.p[k], o, in_window);
    const Vector3 w = difference(a.p[l], o, in_window);
    const Vector3 n1 = cross(e, u), n2 = cross(e, w);
    return {dot(n1, n2), dot(n1, n1) * dot(n2, n2)};
}

/// The six angles' terms of tetrahedron p, in kEdges order, from its four face area vectors:
/// with n_k = (b - a) x (c - a) over the face opposite corner k in the order (1,2,3), (0,3,2),
/// (0,1,3), (0,2,1) (consistently oriented), the angle at edge ij with the other corners k < l
/// has d = -n_k . n_l and N = |n_k|^2 |n_l|^2: the same polynomials as dihedral_terms' (its
/// e x u and e x w are n_l and n_k up to signs whose product is -1, as an expansion of both
/// shows), from 4 cross products instead of 12. The filter certifies
/// each value by its own magnitude and rounding count (header comment; the counts are the same
/// as dihedral_terms'), so the decisions are the same; `in_window` covers all five differences.
std::array<DihedralTerms, 6> tet_dihedral_terms(const TetCorners& p, bool& in_window) {
    const Vector3 e1 = difference(p[1], p[0], in_window);
    const Vector3 e2 = difference(p[2], p[0], in_window);
    const Vector3 e3 = difference(p[3], p[0], in_window);
    const Vector3 e21 = difference(p[2], p[1], in_window);
    const Vector3 e31 = difference(p[3], p[1], in_window);
    const std::array<Vector3, 4> n{cross(e21, e31), cross(e3, e2), cross(e1, e3), cross(e2, e1)};
    std::array<Approx, 4> norm;
    for (std::size_t k = 0; k < 4; ++k) norm[k] = dot(n[k], n[k]);
    std::array<DihedralTerms, 6> terms;
    for (std::size_t e = 0; e < 6; ++e) {
        std::size_t k = 0;
        while (k == kEdges[e][0] || k == kEdges[e][1]) ++k;
        std::size_t l = k + 1;
        while (l == kEdges[e][0] || l == kEdges[e][1]) ++l;
        const Approx d = dot(n[k], n[l]);
        terms[e] = {{-d.value, d.magnitude, d.roundings}, norm[k] * norm[l]};
    }
    return terms;
}

using reference::exact;

struct ExactVector {
    mpq_class x, y, z;
};
ExactVector exact_difference(const double* p, const double* o) {
    return {exact(p[0]) - exact(o[0]), exact(p[1]) - exact(o[1]), exact(p[2]) - exact(o[2])};
}
ExactVector exact_cross(const ExactVector& a, const ExactVector& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
mpq_class exact_dot(const ExactVector& a, const ExactVector& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

/// d = n1 . n2 and N = |n1|^2 |n2|^2 of the dihedral at edge (i, j), n1 and n2 the normals of
/// its two faces, on integer corners: v holds the 4 corners' 12 coordinates (scaled).
void integer_dihedral_terms(const Dihedral& a, const mpz_class* v, mpz_class& d, mpz_class& norms) {
    unsigned k = 0;
    while (k == a.i || k == a.j) ++k;
    unsigned l = k + 1;
    while (l == a.i || l == a.j) ++l;
    using IntVector = std::array<mpz_class, 3>;
    const auto diff = [&](unsigned p, unsigned o) {
        return IntVector{v[3 * p] - v[3 * o], v[3 * p + 1] - v[3 * o + 1],
                         v[3 * p + 2] - v[3 * o + 2]};
    };
    const auto cross = [](const IntVector& x, const IntVector& y) {
        return IntVector{x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2],
                         x[0] * y[1] - x[1] * y[0]};
    };
    const auto dot = [](const IntVector& x, const IntVector& y) {
        return mpz_class(x[0] * y[0] + x[1] * y[1] + x[2] * y[2]);
    };
    const IntVector e = diff(a.j, a.i);
    const IntVector n1 = cross(e, diff(k, a.i));
    const IntVector n2 = cross(e, diff(l, a.i));
    d = dot(n1, n2);
    norms = dot(n1, n1) * dot(n2, n2);
}

/// sign(cos a - cos b) from the signs of d_a, d_b and of X = d_a^2 N_b - d_b^2 N_a.
Sign cosine_order(Sign da, Sign db, Sign x) {
    if (da != db) return to_int(da) > to_int(db) ? Sign::Positive : Sign::Negative;
    if (da == Sign::Zero) return Sign::Zero;
    return da == Sign::Positive ? x : -x;
}

/// D = 6 x volume and L = sum of squared edge lengths.
struct VolumeEdgeTerms {
    Approx volume6, lengths;
};

VolumeEdgeTerms volume_edge_terms(const TetCorners& p, bool& in_window) {
    const Vector3 a = difference(p[1], p[0], in_window);
    const Vector3 b = difference(p[2], p[0], in_window);
    const Vector3 c = difference(p[3], p[0], in_window);
    const Vector3 bc = difference(p[2], p[1], in_window);
    const Vector3 bd = difference(p[3], p[1], in_window);
    const Vector3 cd = difference(p[3], p[2], in_window);
    // orient3d(p0, p1, p2, p3) = det[p0 - p3; p1 - p3; p2 - p3] = -det[a; b; c].
    const Approx det = dot(a, cross(b, c));
    const Approx volume6{-det.value, det.magnitude, det.roundings};
    return {volume6,
            ((dot(a, a) + dot(b, b)) + (dot(c, c) + dot(bc, bc))) + (dot(bd, bd) + dot(cd, cd))};
}

void exact_volume_edge_terms(const TetCorners& p, mpq_class& volume6, mpq_class& lengths) {
    const ExactVector a = exact_difference(p[1], p[0]), b = exact_difference(p[2], p[0]),
                      c = exact_difference(p[3], p[0]), bc = exact_difference(p[2], p[1]),
                      bd = exact_difference(p[3], p[1]), cd = exact_difference(p[3], p[2]);
    volume6 = -exact_dot(a, exact_cross(b, c));
    lengths = exact_dot(a, a) + exact_dot(b, b) + exact_dot(c, c) + exact_dot(bc, bc) +
              exact_dot(bd, bd) + exact_dot(cd, cd);
}

}  // namespace

namespace {

/// The filter of compare_dihedral on the two angles' terms (both in the window).
std::optional<Sign> terms_filter(const DihedralTerms& ta, const DihedralTerms& tb) {
    bool certain = true;
    const Sign da = filtered_sign(ta.d, certain);
    const Sign db = filtered_sign(tb.d, certain);
    Sign x = Sign::Zero;
    if (certain && da == db && da != Sign::Zero) {
        x = filtered_sign(ta.d * ta.d * tb.norms - tb.d * tb.d * ta.norms, certain);
    }
    if (certain) return -cosine_order(da, db, x);
    return std::nullopt;
}

/// The filter of compare_dihedral; `window` false when a difference left the window.
std::optional<Sign> dihedral_filter(const Dihedral& a, const Dihedral& b, bool& window) {
    window = true;
    if constexpr (kLongDoubleFilter) {
        const DihedralTerms ta = dihedral_terms(a, window);
        const DihedralTerms tb = dihedral_terms(b, window);
        if (window) return terms_filter(ta, tb);
    }
    return std::nullopt;
}

/// Both tetrahedra's 24 coordinates scaled by one power of two into [1, 2) (detail::
/// rescale_into_safe_range, degree `degree`), when that is exact: every comparison here is
/// homogeneous, so the copy has the same signs, and its differences may lie in the window.
bool rescaled_copy(const TetCorners& a, const TetCorners& b, int degree, double* out) {
    const TetCorners& x = a;
    const TetCorners& y = b;
    return detail::rescale_into_safe_range(
        degree, {x[0][0], x[0][1], x[0][2], x[1][0], x[1][1], x[1][2], x[2][0], x[2][1],
                 x[2][2], x[3][0], x[3][1], x[3][2], y[0][0], y[0][1], y[0][2], y[1][0],
                 y[1][1], y[1][2], y[2][0], y[2][1], y[2][2], y[3][0], y[3][1], y[3][2]},
        out);
}

__extension__ typedef __int128 Int128;  // GCC and Clang (the supported compilers)

/// d = n1 . n2 and N = |n1|^2 |n2|^2 of dihedral angle `a` (as integer_dihedral_terms) when its
/// three edge vectors from corner i are exact doubles and integers below 2^6 times one power of
/// two (lattice tetrahedra, whose angles tie: 90, 60, 45 degrees), on those integers: cos^2 =
/// d^2 / N is the same for the tetrahedron scaled by any factor, so each tetrahedron takes its
/// own. Then |n| components < 2^13, |d| < 2^28, N < 2^56, and d_a^2 N_b < 2^112: exact in
/// 64- and 128-bit integers. False otherwise.
bool small_integer_dihedral_terms(const Dihedral& a, std::int64_t& d, Int128& norms) {
    unsigned k = 0;
    while (k == a.i || k == a.j) ++k;
    unsigned l = k + 1;
    while (l == a.i || l == a.j) ++l;
    const double* o = a.p[a.i];
    const unsigned rows[3] = {a.j, k, l};
    double x[9];
    double largest = 0;
    for (unsigned r = 0; r < 3; ++r) {
        for (unsigned c = 0; c < 3; ++c) {
            double tail = 0;
            two_diff(a.p[rows[r]][c], o[c], x[3 * r + c], tail);
            if (tail != 0 || !std::isfinite(x[3 * r + c])) return false;
            largest = std::max(largest, std::fabs(x[3 * r + c]));
        }
    }
    if (largest == 0) return false;
    const int shift = 5 - std::ilogb(largest);  // largest scaled into [2^5, 2^6)
    std::int64_t v[9];
    for (unsigned i = 0; i < 9; ++i) {
        const double y = std::ldexp(x[i], shift);
        if (y != std::trunc(y) || (y == 0) != (x[i] == 0)) return false;
        v[i] = static_cast<std::int64_t>(y);
    }
    using IntVector = std::array<std::int64_t, 3>;
    const auto cross = [](const std::int64_t* p, const std::int64_t* q) {
        return IntVector{p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2],
                         p[0] * q[1] - p[1] * q[0]};
    };
    const auto dot = [](const IntVector& p, const IntVector& q) {
        return p[0] * q[0] + p[1] * q[1] + p[2] * q[2];
    };
    const IntVector n1 = cross(v, v + 3), n2 = cross(v, v + 6);
    d = dot(n1, n2);
    norms = Int128{dot(n1, n1)} * Int128{dot(n2, n2)};
    return true;
}

Sign sign_of_integer(Int128 x) {
    return x > 0 ? Sign::Positive : (x < 0 ? Sign::Negative : Sign::Zero);
}

}  // namespace

std::optional<Sign> compare_dihedral_filter(const Dihedral& a, const Dihedral& b) {
    bool window = true;
    return dihedral_filter(a, b, window);
}

Sign compare_dihedral(const Dihedral& a, const Dihedral& b) {
    EM_STAT(compare_dihedral, calls);
    bool window = true;
    if (const auto s = dihedral_filter(a, b, window)) {
        EM_STAT(compare_dihedral, filter);
        return *s;
    }
    double c[24];
    if (!window && rescaled_copy(a.p, b.p, 16, c)) {
        EM_STAT(compare_dihedral, rescaled);
        const TetCorners ca{c, c + 3, c + 6, c + 9}, cb{c + 12, c + 15, c + 18, c + 21};
        if (const auto s = dihedral_filter({ca, a.i, a.j}, {cb, b.i, b.j}, window)) {
            EM_STAT(compare_dihedral, filter);
            return *s;
        }
    }
    std::int64_t sda = 0, sdb = 0;
    Int128 sna = 0, snb = 0;
    if (small_integer_dihedral_terms(a, sda, sna) && small_integer_dihedral_terms(b, sdb, snb)) {
        EM_STAT(compare_dihedral, exact_differences);
        const Sign x = sign_of_integer(Int128{sda} * sda * snb - Int128{sdb} * sdb * sna);
        return -cosine_order(sign_of_integer(sda), sign_of_integer(sdb), x);
    }
    EM_STAT(compare_dihedral, gmp);
    // Both tetrahedra's corners as integers on one power-of-two scale (homogeneous terms of
    // degree 4 and 8: the signs below are those of the real values).
    std::array<double, 24> xyz{};
    for (unsigned k = 0; k < 4; ++k) {
        for (unsigned i = 0; i < 3; ++i) {
            xyz[3 * k + i] = a.p[k][i];
            xyz[12 + 3 * k + i] = b.p[k][i];
        }
    }
    const std::array<mpz_class, 24> v = detail::scaled_integers<24>(xyz);
    mpz_class da, na, db, nb;
    integer_dihedral_terms(a, v.data(), da, na);
    integer_dihedral_terms(b, v.data() + 12, db, nb);
    const auto sign = [](const mpz_class& x) {
        const int s = sgn(x);
        return s > 0 ? Sign::Positive : (s < 0 ? Sign::Negative : Sign::Zero);
    };
    const Sign x = sign(da * da * nb - db * db * na);
    return -cosine_order(sign(da), sign(db), x);
}

Dihedral smallest_dihedral(const TetCorners& p) {
    // compare_dihedral five times, with each angle's filter terms computed once (the best's were
    // computed again at every comparison: 10 evaluations for 6 angles, a fifth of sliver
    // removal's instructions). The filter sees the same terms, so it decides the same; where it
    // abstains (or a difference left the window), compare_dihedral decides.
    std::array<DihedralTerms, 6> terms{};
    bool window = true;
    if constexpr (kLongDoubleFilter) terms = tet_dihedral_terms(p, window);
    unsigned best = 0;
    for (unsigned e = 1; e < 6; ++e) {
        const Dihedral candidate{p, kEdges[e][0], kEdges[e][1]};
        std::optional<Sign> s;
        if (kLongDoubleFilter && window) {
            s = terms_filter(terms[e], terms[best]);
            if (s) {
                EM_STAT(compare_dihedral, calls);
                EM_STAT(compare_dihedral, filter);
            }
        }
        // (compare_dihedral counts the comparisons the cached filter left undecided.)
        if (!s) s = compare_dihedral(candidate, Dihedral{p, kEdges[best][0], kEdges[best][1]});
        if (*s == Sign::Negative) best = e;
    }
    return Dihedral{p, kEdges[best][0], kEdges[best][1]};
}

bool every_dihedral_compares(const TetCorners& p, const Dihedral& bound, Sign wanted) {
    // compare_dihedral(angle, bound) for the six angles in turn, the bound's filter terms
    // computed once; the first angle that does not compare as wanted ends it.
    DihedralTerms bound_terms{};
    std::array<DihedralTerms, 6> terms{};
    bool window = true;
    if constexpr (kLongDoubleFilter) {
        bound_terms = dihedral_terms(bound, window);
        if (window) terms = tet_dihedral_terms(p, window);
    }
    for (unsigned e = 0; e < 6; ++e) {
        const Dihedral angle{p, kEdges[e][0], kEdges[e][1]};
        std::optional<Sign> s;
        if (kLongDoubleFilter && window) {
            s = terms_filter(terms[e], bound_terms);
            if (s) {
                EM_STAT(compare_dihedral, calls);
                EM_STAT(compare_dihedral, filter);
            }
        }
        if (!s) s = compare_dihedral(angle, bound);
        if (*s != wanted) return false;
    }
    return true;
}

Dihedral largest_dihedral(const TetCorners& p) {
    Dihedral best{p, 0, 1};
    for (int e = 1; e < 6; ++e) {
        const Dihedral candidate{p, kEdges[e][0], kEdges[e][1]};
        if (compare_dihedral(candidate, best) == Sign::Positive) best = candidate;
    }
    return best;
}

namespace {

/// The filter of compare_volume_edge; `window` false when a difference left the window.
std::optional<Sign> volume_edge_filter(const TetCorners& a, const TetCorners& b, bool& window) {
    window = true;
    if constexpr (kLongDoubleFilter) {
        const VolumeEdgeTerms ta = volume_edge_terms(a, window);
        const VolumeEdgeTerms tb = volume_edge_terms(b, window);
        if (window) {
            bool certain = true;
            const Approx la3 = ta.lengths * ta.lengths * ta.lengths;
            const Approx lb3 = tb.lengths * tb.lengths * tb.lengths;
            const Sign s = filtered_sign(
                ta.volume6 * ta.volume6 * lb3 - tb.volume6 * tb.volume6 * la3, certain);
            if (certain) return s;
        }
    }
    return std::nullopt;
}

}  // namespace

std::optional<Sign> compare_volume_edge_filter(const TetCorners& a, const TetCorners& b) {
    bool window = true;
    return volume_edge_filter(a, b, window);
}

Sign compare_volume_edge(const TetCorners& a, const TetCorners& b) {
    EM_STAT(compare_volume_edge, calls);
    bool window = true;
    if (const auto s = volume_edge_filter(a, b, window)) {
        EM_STAT(compare_volume_edge, filter);
        return *s;
    }
    double c[24];
    if (!window && rescaled_copy(a, b, 12, c)) {
        EM_STAT(compare_volume_edge, rescaled);
        const TetCorners ca{c, c + 3, c + 6, c + 9}, cb{c + 12, c + 15, c + 18, c + 21};
        if (const auto s = volume_edge_filter(ca, cb, window)) {
            EM_STAT(compare_volume_edge, filter);
            return *s;
        }
    }
    EM_STAT(compare_volume_edge, gmp);
    mpq_class va, la, vb, lb;
    exact_volume_edge_terms(a, va, la);
    exact_volume_edge_terms(b, vb, lb);
    return reference::sign_of(va * va * lb * lb * lb - vb * vb * la * la * la);
}

long double dihedral_radians(const Dihedral& a) {
    unsigned k = 0;
    while (k == a.i || k == a.j) ++k;
    unsigned l = k + 1;
    while (l == a.i || l == a.j) ++l;
    auto diff = [](const double* p, const double* o) {
        return std::array<long double, 3>{static_cast<long double>(p[0]) - o[0],
                                          static_cast<long double>(p[1]) - o[1],
                                          static_cast<long double>(p[2]) - o[2]};
    };
    auto crs = [](const std::array<long double, 3>& x, const std::array<long double, 3>& y) {
        return std::array<long double, 3>{x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2],
                                          x[0] * y[1] - x[1] * y[0]};
    };
    auto dt = [](const std::array<long double, 3>& x, const std::array<long double, 3>& y) {
        return x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
    };
    const auto e = diff(a.p[a.j], a.p[a.i]), u = diff(a.p[k], a.p[a.i]), w = diff(a.p[l], a.p[a.i]);
    // |n1 x n2| = |e| |det(e, u, w)| (since (e x u) x (e x w) = det(e, u, w) e).
    const long double sine = std::sqrt(dt(e, e)) * std::fabs(dt(e, crs(u, w)));
    return std::atan2(sine, dt(crs(e, u), crs(e, w)));
}

bool dihedral_below_rounded(const Dihedral& a, long double cos_squared) {
    unsigned k = 0;
    while (k == a.i || k == a.j) ++k;
    unsigned l = k + 1;
    while (l == a.i || l == a.j) ++l;
    const double* o = a.p[a.i];
    using V = std::array<long double, 3>;
    const auto diff = [o](const double* p) {
        return V{static_cast<long double>(p[0]) - o[0], static_cast<long double>(p[1]) - o[1],
                 static_cast<long double>(p[2]) - o[2]};
    };
    const auto crs = [](const V& x, const V& y) {
        return V{x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]};
    };
    const auto dt = [](const V& x, const V& y) { return x[0] * y[0] + x[1] * y[1] + x[2] * y[2]; };
    const V e = diff(a.p[a.j]);
    const V n1 = crs(e, diff(a.p[k])), n2 = crs(e, diff(a.p[l]));
    const long double d = dt(n1, n2);
    return d > 0 && d * d > cos_squared * (dt(n1, n1) * dt(n2, n2));
}

namespace {

using RoundedVector = std::array<double, 3>;

/// The four face normals of tetrahedron p (n[k] opposite corner k, consistently oriented:
/// (1,2,3), (0,3,2), (0,1,3), (0,2,1)) and their squared lengths, in doubles on the corner
/// differences scaled by a power of two: a subnormal difference is exact and a normal one rounds
/// the same at every power-of-two scale, so every value is the same for the corners scaled by
/// 2^k. False (nothing usable) when the largest difference leaves [2^-1000, 2^1000] or a scaled
/// difference or a normal comes near the double range's bottom.
bool scaled_face_normals(const TetCorners& p, RoundedVector (&n)[4], double (&norm)[4]) {
    using V = RoundedVector;
    V e[3];
    double largest = 0;
    for (std::size_t r = 0; r < 3; ++r) {
        for (std::size_t k = 0; k < 3; ++k) {
            e[r][k] = p[r + 1][k] - p[0][k];
            largest = std::max(largest, std::fabs(e[r][k]));
        }
    }
    if (!(largest >= 0x1p-1000) || !(largest <= 0x1p1000)) return false;
    // 2^-x with largest in [2^(x-1), 2^x), from the bits (std::frexp and std::ldexp were most
    // of any_dihedral_below_rounded's time).
    const auto biased = static_cast<int>((std::bit_cast<std::uint64_t>(largest) >> 52) & 0x7ff);
    const double scale = std::bit_cast<double>(static_cast<std::uint64_t>(2045 - biased) << 52);
    for (auto& row : e) {
        for (double& x : row) {
            x *= scale;
            if (x != 0 && std::fabs(x) < 0x1p-200) return false;
        }
    }
    const auto crs = [](const V& x, const V& y) {
        return V{x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]};
    };
    const V e21{e[1][0] - e[0][0], e[1][1] - e[0][1], e[1][2] - e[0][2]};
    const V e31{e[2][0] - e[0][0], e[2][1] - e[0][1], e[2][2] - e[0][2]};
    n[0] = crs(e21, e31);
    n[1] = crs(e[2], e[1]);
    n[2] = crs(e[0], e[2]);
    n[3] = crs(e[1], e[0]);
    for (int k = 0; k < 4; ++k) {
        norm[k] = n[k][0] * n[k][0] + n[k][1] * n[k][1] + n[k][2] * n[k][2];
        if (!(norm[k] >= 0x1p-800)) return false;
    }
    return true;
}

double rounded_dot(const RoundedVector& x, const RoundedVector& y) {
    return x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
}

}  // namespace

bool any_dihedral_below_rounded(const TetCorners& p, long double cos_squared) {
    RoundedVector n[4];
    double norm[4];
    if (!scaled_face_normals(p, n, norm)) {
        for (unsigned i = 0; i < 4; ++i)
            for (unsigned j = i + 1; j < 4; ++j)
                if (dihedral_below_rounded(Dihedral{p, i, j}, cos_squared)) return true;
        return false;
    }
    const double c2 = static_cast<double>(cos_squared);
    for (int k = 0; k < 4; ++k) {
        for (int l = k + 1; l < 4; ++l) {
            const double d = -rounded_dot(n[k], n[l]);
            if (d > 0 && d * d > c2 * (norm[k] * norm[l])) return true;
        }
    }
    return false;
}

Dihedral smallest_dihedral_rounded(const TetCorners& p, double* cosine) {
    RoundedVector n[4];
    double norm[4];
    // The edge (i, j) whose faces are those opposite k and l, for (k, l) in loop order.
    constexpr unsigned kEdgeOf[4][4][2] = {
        {{}, {2, 3}, {1, 3}, {1, 2}}, {{}, {}, {0, 3}, {0, 2}}, {{}, {}, {}, {0, 1}}, {}};
    Dihedral best{p, 0, 1};
    double best_cosine = -2;
    if (cosine != nullptr) *cosine = best_cosine;
    if (!scaled_face_normals(p, n, norm)) return best;
    for (unsigned k = 0; k < 4; ++k) {
        for (unsigned l = k + 1; l < 4; ++l) {
            const double c = -rounded_dot(n[k], n[l]) / std::sqrt(norm[k] * norm[l]);
            if (c > best_cosine) {
                best_cosine = c;
                best.i = kEdgeOf[k][l][0];
                best.j = kEdgeOf[k][l][1];
            }
        }
    }
    if (cosine != nullptr) *cosine = best_cosine;
    return best;
}

long double volume_edge_quality(const TetCorners& p) {
    bool in_window = true;
    const VolumeEdgeTerms t = volume_edge_terms(p, in_window);
    const long double l = t.lengths.value;
    if (!(l > 0)) return 0;
    return 12.0L * std::sqrt(3.0L) * t.volume6.value / (l * std::sqrt(l));
}

}  // namespace exactmesh::predicates
