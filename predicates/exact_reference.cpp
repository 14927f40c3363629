// SPDX-License-Identifier: MIT
// Exact rational reference predicates (see exact_reference.hpp): generic Gaussian elimination on
// the raw determinants, explicit cofactor expansions of the difference forms, and the symbolic
// perturbations evaluated from their definitions [EdelsbrunnerMücke90; DevillersTeillaud11].
#include "predicates/exact_reference.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <utility>

#include "base/errors.hpp"
#include "base/number_text.hpp"

namespace exactmesh::predicates::reference {

namespace {

std::size_t at(int row, int column, int n) {
    return static_cast<std::size_t>(row) * static_cast<std::size_t>(n) +
           static_cast<std::size_t>(column);
}

/// The lifted coordinate x^2 + y^2 (+ z^2) of a point with `dims` coordinates, exactly.
mpq_class lift(const double* p, int dims) {
    mpq_class w = 0;
    for (int k = 0; k < dims; ++k) {
        const mpq_class x = exact(p[k]);
        w += x * x;
    }
    return w;
}

/// The rows [p, |p|^2 (when lifted), 1] of the raw determinant, one point per row.
std::vector<mpq_class> raw_matrix(std::initializer_list<const double*> points, int dims,
                                  bool lifted) {
    std::vector<mpq_class> m;
    m.reserve(points.size() * points.size());
    for (const double* p : points) {
        for (int k = 0; k < dims; ++k) m.push_back(exact(p[k]));
        if (lifted) m.push_back(lift(p, dims));
        m.emplace_back(1);
    }
    return m;
}

/// The rows [x y q(p) 1], q(p) = p^T M p exactly, one point per row.
std::vector<mpq_class> metric_raw_matrix(std::initializer_list<const double*> points,
                                         const double* m) {
    const mpq_class m11 = exact(m[0]), m12 = exact(m[1]), m22 = exact(m[2]);
    std::vector<mpq_class> rows;
    rows.reserve(points.size() * points.size());
    for (const double* p : points) {
        const mpq_class x = exact(p[0]), y = exact(p[1]);
        rows.push_back(x);
        rows.push_back(y);
        rows.push_back(m11 * x * x + 2 * m12 * x * y + m22 * y * y);
        rows.emplace_back(1);
    }
    return rows;
}

Sign integer_sign(const mpz_class& x) {
    const int s = sgn(x);
    return s > 0 ? Sign::Positive : (s < 0 ? Sign::Negative : Sign::Zero);
}

/// det [[a b], [c d]] over integers.
mpz_class det2(const mpz_class& a, const mpz_class& b, const mpz_class& c, const mpz_class& d) {
    return a * d - b * c;
}

/// det [[m0 m1 m2], [m3 m4 m5], [m6 m7 m8]] along the first row.
mpz_class det3(const mpz_class* m) {
    return m[0] * det2(m[4], m[5], m[7], m[8]) - m[1] * det2(m[3], m[5], m[6], m[8]) +
           m[2] * det2(m[3], m[4], m[6], m[7]);
}

/// The coordinates as integers x * 2^-q, with 2^q the largest power of two dividing all of them.
/// Every finite double is an integer times a power of two, so this is exact; and scaling every
/// coordinate by 2^-q multiplies a homogeneous determinant of degree n by 2^(-qn) > 0, which
/// leaves its sign alone. Integer arithmetic needs no gcd, so this is much faster than mpq.
std::vector<mpz_class> scaled_integers(std::initializer_list<double> coordinates) {
    std::vector<std::int64_t> mantissa;
    std::vector<int> exponent;
    int lowest = 0;
    bool any = false;
    for (const double x : coordinates) {
        (void)exact(x);  // throws on NaN and infinity
        int e = 0;
        // x = m * 2^(e-53) with m an integer of at most 53 bits (exact for subnormals too).
        auto m = static_cast<std::int64_t>(std::ldexp(std::frexp(x, &e), 53));
        e -= 53;
        if (m != 0) {
            while (m % 2 == 0) {
                m /= 2;
                ++e;
            }
            lowest = any ? std::min(lowest, e) : e;
            any = true;
        }
        mantissa.push_back(m);
        exponent.push_back(e);
    }
    std::vector<mpz_class> v(mantissa.size());
    for (std::size_t i = 0; i < v.size(); ++i) {
        v[i] = static_cast<long>(mantissa[i]);
        if (mantissa[i] != 0) {
            mpz_mul_2exp(v[i].get_mpz_t(), v[i].get_mpz_t(),
                         static_cast<mp_bitcnt_t>(exponent[i] - lowest));
        }
    }
    return v;
}

/// The ranks of the indices: 0 for the largest. Throws when two indices are equal.
std::vector<int> ranks_by_decreasing_index(std::initializer_list<std::uint32_t> indices) {
    const std::vector<std::uint32_t> v(indices);
    std::vector<int> rank(v.size(), 0);
    for (std::size_t i = 0; i < v.size(); ++i) {
        for (std::size_t j = 0; j < v.size(); ++j) {
            if (i == j) continue;
            if (v[i] == v[j]) {
                throw std::invalid_argument("reference sos: two points share the index " +
                                            std::to_string(v[i]));
            }
            if (v[j] > v[i]) ++rank[i];
        }
    }
    return rank;
}

// The eps of the lifted perturbations. With integer coordinates |x| <= 2^20 the unperturbed
// determinant is an integer (so |Δ| >= 1 when nonzero) and every cofactor C_p is an integer with
// |C_p| <= 4! * (2^20)^3 < 2^65. The perturbed determinant is Δ + Σ eps^(r_p+1) C_p (linear: all
// perturbations sit in one column), so any eps < 2^-67 makes each term dominate everything after
// it; 2^-200 leaves a wide margin.
constexpr int kLiftPerturbationBits = 200;
constexpr double kLiftPerturbationMaxCoordinate = 1048576.0;  // 2^20

void require_small_integers(const char* predicate, std::initializer_list<double> coordinates) {
    for (const double x : coordinates) {
        if (!(std::fabs(x) <= kLiftPerturbationMaxCoordinate) || std::trunc(x) != x) {
            throw std::invalid_argument(std::string(predicate) +
                                        ": needs integer coordinates |x| <= 2^20, got " +
                                        format_number(x));
        }
    }
}

/// eps^power with eps = 2^-kLiftPerturbationBits, exactly.
mpq_class lift_perturbation(int power) {
    mpq_class p = 1;
    mpq_div_2exp(p.get_mpq_t(), p.get_mpq_t(),
                 static_cast<mp_bitcnt_t>(kLiftPerturbationBits * power));
    return p;
}

/// Sign of the raw lifted determinant m (rows [p, w_p, 1]) with w_p += eps^(rank_p + 1).
Sign perturbed_lifted_sign(std::vector<mpq_class> m, int dims, const std::vector<int>& rank) {
    const int n = dims + 2;
    for (int r = 0; r < n; ++r) {
        m[at(r, dims, n)] += lift_perturbation(rank[static_cast<std::size_t>(r)] + 1);
    }
    return determinant_sign(std::move(m), n);
}

// Polynomials in eps with rational coefficients (coefficient k multiplies eps^k), for the
// symbolic evaluation of orient2d_sos.
using Poly = std::vector<mpq_class>;

Poly poly_constant(const mpq_class& c) {
    return Poly{c};
}

Poly poly_plus_monomial(const mpq_class& c, int power) {
    Poly p(static_cast<std::size_t>(power) + 1, mpq_class(0));
    p[0] = c;
    p[static_cast<std::size_t>(power)] += 1;
    return p;
}

Poly poly_add(const Poly& p, const Poly& q, int sign_of_q) {
    Poly r(std::max(p.size(), q.size()), mpq_class(0));
    for (std::size_t i = 0; i < p.size(); ++i) r[i] += p[i];
    for (std::size_t i = 0; i < q.size(); ++i) {
        if (sign_of_q > 0) {
            r[i] += q[i];
        } else {
            r[i] -= q[i];
        }
    }
    return r;
}

Poly poly_multiply(const Poly& p, const Poly& q) {
    Poly r(p.size() + q.size() - 1, mpq_class(0));
    for (std::size_t i = 0; i < p.size(); ++i) {
        if (sgn(p[i]) == 0) continue;
        for (std::size_t j = 0; j < q.size(); ++j) r[i + j] += p[i] * q[j];
    }
    return r;
}

/// Determinant of an n x n matrix of polynomials by Laplace expansion along the first row.
Poly poly_determinant(const std::vector<Poly>& m, int n) {
    if (n == 1) return m[0];
    Poly det = poly_constant(0);
    for (int skip = 0; skip < n; ++skip) {
        std::vector<Poly> minor;
        minor.reserve(static_cast<std::size_t>((n - 1) * (n - 1)));
        for (int r = 1; r < n; ++r) {
            for (int c = 0; c < n; ++c) {
                if (c != skip) minor.push_back(m[at(r, c, n)]);
            }
        }
        const Poly term = poly_multiply(m[at(0, skip, n)], poly_determinant(minor, n - 1));
        det = poly_add(det, term, skip % 2 == 0 ? 1 : -1);
    }
    return det;
}

}  // namespace

Sign sign_of(const mpq_class& x) {
    const int s = sgn(x);
    return s > 0 ? Sign::Positive : (s < 0 ? Sign::Negative : Sign::Zero);
}

mpq_class exact(double x) {
    if (!std::isfinite(x)) {
        throw GeometryError("exact reference: non-finite coordinate " + format_number(x));
    }
    return mpq_class(x);  // mpq_set_d is exact for every finite double, subnormals included
}

Sign determinant_sign(std::vector<mpq_class> matrix, int n) {
    if (n <= 0 || matrix.size() != static_cast<std::size_t>(n) * static_cast<std::size_t>(n)) {
        throw std::invalid_argument("determinant_sign: matrix is not n x n");
    }
    // det = (parity of the row swaps) * product of the pivots; only their signs matter.
    int sign = 1;
    for (int col = 0; col < n; ++col) {
        int pivot = col;
        while (pivot < n && sgn(matrix[at(pivot, col, n)]) == 0) ++pivot;
        if (pivot == n) return Sign::Zero;
        if (pivot != col) {
            for (int k = col; k < n; ++k) std::swap(matrix[at(pivot, k, n)], matrix[at(col, k, n)]);
            sign = -sign;
        }
        const mpq_class& p = matrix[at(col, col, n)];
        if (sgn(p) < 0) sign = -sign;
        for (int r = col + 1; r < n; ++r) {
            if (sgn(matrix[at(r, col, n)]) == 0) continue;
            const mpq_class factor = matrix[at(r, col, n)] / p;
            for (int k = col + 1; k < n; ++k) matrix[at(r, k, n)] -= factor * matrix[at(col, k, n)];
        }
    }
    return sign > 0 ? Sign::Positive : Sign::Negative;
}

Sign orient2d(const double* a, const double* b, const double* c) {
    return determinant_sign(raw_matrix({a, b, c}, 2, false), 3);
}

Sign orient3d(const double* a, const double* b, const double* c, const double* d) {
    return determinant_sign(raw_matrix({a, b, c, d}, 3, false), 4);
}

Sign incircle(const double* a, const double* b, const double* c, const double* d) {
    return determinant_sign(raw_matrix({a, b, c, d}, 2, true), 4);
}

Sign in_ellipse(const double* a, const double* b, const double* c, const double* d,
                const double* m) {
    return determinant_sign(metric_raw_matrix({a, b, c, d}, m), 4);
}

Sign insphere(const double* a, const double* b, const double* c, const double* d, const double* e) {
    return determinant_sign(raw_matrix({a, b, c, d, e}, 3, true), 5);
}

Sign orient2d_differences(const double* a, const double* b, const double* c) {
    const std::vector<mpz_class> v = scaled_integers({a[0], a[1], b[0], b[1], c[0], c[1]});
    return integer_sign(det2(v[0] - v[4], v[1] - v[5], v[2] - v[4], v[3] - v[5]));
}

Sign orient3d_differences(const double* a, const double* b, const double* c, const double* d) {
    const std::vector<mpz_class> v =
        scaled_integers({a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2], d[0], d[1], d[2]});
    mpz_class m[9];
    for (std::size_t i = 0; i < 9; ++i) m[i] = v[i] - v[9 + i % 3];
    return integer_sign(det3(m));
}

Sign incircle_differences(const double* a, const double* b, const double* c, const double* d) {
    const std::vector<mpz_class> v =
        scaled_integers({a[0], a[1], b[0], b[1], c[0], c[1], d[0], d[1]});
    mpz_class m[9];
    for (std::size_t r = 0; r < 3; ++r) {
        m[3 * r] = v[2 * r] - v[6];
        m[3 * r + 1] = v[2 * r + 1] - v[7];
        m[3 * r + 2] = m[3 * r] * m[3 * r] + m[3 * r + 1] * m[3 * r + 1];
    }
    return integer_sign(det3(m));
}

Sign insphere_differences(const double* a, const double* b, const double* c, const double* d,
                          const double* e) {
    const std::vector<mpz_class> v = scaled_integers(
        {a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2], d[0], d[1], d[2], e[0], e[1], e[2]});
    // Rows [p-e, |p-e|^2] for p = a, b, c, d, expanded along the lift column:
    // det = -w_a M_a + w_b M_b - w_c M_c + w_d M_d, M_p the 3x3 minor without p's row.
    mpz_class xyz[4][3], w[4];
    for (std::size_t r = 0; r < 4; ++r) {
        for (std::size_t k = 0; k < 3; ++k) xyz[r][k] = v[3 * r + k] - v[12 + k];
        w[r] = xyz[r][0] * xyz[r][0] + xyz[r][1] * xyz[r][1] + xyz[r][2] * xyz[r][2];
    }
    mpz_class det = 0;
    for (std::size_t skip = 0; skip < 4; ++skip) {
        mpz_class minor[9];
        std::size_t n = 0;
        for (std::size_t r = 0; r < 4; ++r) {
            if (r == skip) continue;
            for (std::size_t k = 0; k < 3; ++k) minor[n++] = xyz[r][k];
        }
        // Entry (skip, 3) has cofactor sign (-1)^(skip + 3).
        if (skip % 2 == 0) {
            det -= w[skip] * det3(minor);
        } else {
            det += w[skip] * det3(minor);
        }
    }
    return integer_sign(det);
}

Sign orient2d_sos(const double* a, const double* b, const double* c, std::uint32_t ia,
                  std::uint32_t ib, std::uint32_t ic) {
    const std::vector<int> rank = ranks_by_decreasing_index({ia, ib, ic});
    const double* points[3] = {a, b, c};
    std::vector<Poly> m;
    for (int r = 0; r < 3; ++r) {
        const int rk = rank[static_cast<std::size_t>(r)];
        // x_p += eps^(2^(2r+1)), y_p += eps^(2^(2r)): y moves more than x, and a larger index
        // more than a smaller one.
        m.push_back(poly_plus_monomial(exact(points[r][0]), 1 << (2 * rk + 1)));
        m.push_back(poly_plus_monomial(exact(points[r][1]), 1 << (2 * rk)));
        m.push_back(poly_constant(1));
    }
    // As eps -> 0+, the sign is that of the lowest-order nonzero coefficient.
    for (const mpq_class& coefficient : poly_determinant(m, 3)) {
        if (sgn(coefficient) != 0) return sign_of(coefficient);
    }
    return Sign::Zero;
}

Sign incircle_sos(const double* a, const double* b, const double* c, const double* d,
                  std::uint32_t ia, std::uint32_t ib, std::uint32_t ic, std::uint32_t id) {
    require_small_integers("reference::incircle_sos",
                           {a[0], a[1], b[0], b[1], c[0], c[1], d[0], d[1]});
    return perturbed_lifted_sign(raw_matrix({a, b, c, d}, 2, true), 2,
                                 ranks_by_decreasing_index({ia, ib, ic, id}));
}

Sign in_ellipse_sos(const double* a, const double* b, const double* c, const double* d,
                    const double* m, std::uint32_t ia, std::uint32_t ib, std::uint32_t ic,
                    std::uint32_t id) {
    require_small_integers("reference::in_ellipse_sos",
                           {a[0], a[1], b[0], b[1], c[0], c[1], d[0], d[1], m[0], m[1], m[2]});
    return perturbed_lifted_sign(metric_raw_matrix({a, b, c, d}, m), 2,
                                 ranks_by_decreasing_index({ia, ib, ic, id}));
}

Sign insphere_sos(const double* a, const double* b, const double* c, const double* d,
                  const double* e, std::uint32_t ia, std::uint32_t ib, std::uint32_t ic,
                  std::uint32_t id, std::uint32_t ie) {
    require_small_integers(
        "reference::insphere_sos",
        {a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2], d[0], d[1], d[2], e[0], e[1], e[2]});
    return perturbed_lifted_sign(raw_matrix({a, b, c, d, e}, 3, true), 3,
                                 ranks_by_decreasing_index({ia, ib, ic, id, ie}));
}

namespace {

struct Vec3 {
    mpq_class x, y, z;
};
Vec3 minus3(const double* p, const double* o) {
    return {exact(p[0]) - exact(o[0]), exact(p[1]) - exact(o[1]), exact(p[2]) - exact(o[2])};
}
Vec3 cross3(const Vec3& a, const Vec3& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
mpq_class dot3(const Vec3& a, const Vec3& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

/// cot of the corner at o of (o, p, q), counter-clockwise.
mpq_class cotangent(const double* o, const double* p, const double* q) {
    const mpq_class ux = exact(p[0]) - exact(o[0]), uy = exact(p[1]) - exact(o[1]);
    const mpq_class vx = exact(q[0]) - exact(o[0]), vy = exact(q[1]) - exact(o[1]);
    const mpq_class cross = ux * vy - uy * vx;
    if (sgn(cross) <= 0)
        throw std::invalid_argument("compare_angles: corner not counter-clockwise");
    return (ux * vx + uy * vy) / cross;
}

/// Sign and square of the cosine of the dihedral angle at edge (t[i], t[j]).
std::pair<int, mpq_class> dihedral_cosine(const double* const* t, unsigned i, unsigned j) {
    unsigned other[2], n = 0;
    for (unsigned k = 0; k < 4; ++k) {
        if (k != i && k != j) other[n++] = k;
    }
    const Vec3 e = minus3(t[j], t[i]);
    const Vec3 n1 = cross3(e, minus3(t[other[0]], t[i]));
    const Vec3 n2 = cross3(e, minus3(t[other[1]], t[i]));
    const mpq_class d = dot3(n1, n2);
    return {sgn(d), d * d / (dot3(n1, n1) * dot3(n2, n2))};
}

}  // namespace

Sign compare_angles(const double* o1, const double* p1, const double* q1, const double* o2,
                    const double* p2, const double* q2) {
    // The angle decreases as its cotangent increases on (0, pi).
    return sign_of(cotangent(o2, p2, q2) - cotangent(o1, p1, q1));
}

Sign compare_lengths(const double* p1, const double* q1, const double* p2, const double* q2) {
    const mpq_class x1 = exact(p1[0]) - exact(q1[0]), y1 = exact(p1[1]) - exact(q1[1]);
    const mpq_class x2 = exact(p2[0]) - exact(q2[0]), y2 = exact(p2[1]) - exact(q2[1]);
    return sign_of(x1 * x1 + y1 * y1 - x2 * x2 - y2 * y2);
}

Sign dot_sign(const double* p, const double* q, const double* a, const double* b) {
    return sign_of((exact(q[0]) - exact(p[0])) * (exact(b[0]) - exact(a[0])) +
                   (exact(q[1]) - exact(p[1])) * (exact(b[1]) - exact(a[1])));
}

bool within_rounding_of_segment(const double* w, const double* s0, const double* s1) {
    const double m = std::max(std::fabs(w[0]), std::fabs(w[1]));
    const mpq_class t = exact(std::max(std::ldexp(m, -40), 0x1p-1074));
    // Points s0 + r (s1 - s0), r in [lo, hi], inside the square: clip r coordinate by coordinate.
    mpq_class lo = 0, hi = 1;
    for (int k = 0; k < 2; ++k) {
        const mpq_class a = exact(s0[k]), d = exact(s1[k]) - exact(s0[k]);
        const mpq_class low = exact(w[k]) - t, high = exact(w[k]) + t;
        if (sgn(d) == 0) {
            if (a < low || a > high) return false;
            continue;
        }
        mpq_class r0 = (low - a) / d, r1 = (high - a) / d;
        if (r0 > r1) std::swap(r0, r1);
        if (r0 > lo) lo = r0;
        if (r1 < hi) hi = r1;
    }
    return lo <= hi;
}

Sign compare_dihedral(const double* const* a, unsigned i, unsigned j, const double* const* b,
                      unsigned k, unsigned l) {
    // angle(a) - angle(b) has the sign of cos(b) - cos(a).
    const auto [sa, ca2] = dihedral_cosine(a, i, j);
    const auto [sb, cb2] = dihedral_cosine(b, k, l);
    if (sa != sb) return sb > sa ? Sign::Positive : Sign::Negative;
    if (sa == 0) return Sign::Zero;
    const Sign squares = sign_of(cb2 - ca2);  // |cos b| - |cos a|
    return sa > 0 ? squares : -squares;
}

Sign compare_volume_edge(const double* const* a, const double* const* b) {
    auto measure = [](const double* const* t) {
        const mpq_class v6 =
            dot3(cross3(minus3(t[2], t[0]), minus3(t[3], t[0])), minus3(t[1], t[0]));
        mpq_class lengths = 0;
        for (int p = 0; p < 4; ++p) {
            for (int q = p + 1; q < 4; ++q) {
                const Vec3 e = minus3(t[q], t[p]);
                lengths += dot3(e, e);
            }
        }
        return std::pair<mpq_class, mpq_class>{v6, lengths};
    };
    const auto [va, la] = measure(a);
    const auto [vb, lb] = measure(b);
    return sign_of(va * va / (la * la * la) - vb * vb / (lb * lb * lb));
}

Sign triangle_area_sign(const double* a, const double* b, const double* c, double area) {
    const mpq_class det = (exact(a[0]) - exact(c[0])) * (exact(b[1]) - exact(c[1])) -
                          (exact(a[1]) - exact(c[1])) * (exact(b[0]) - exact(c[0]));
    return sign_of(det / 2 - exact(area));
}

}  // namespace exactmesh::predicates::reference
