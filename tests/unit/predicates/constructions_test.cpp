// SPDX-License-Identifier: MIT
// Tests of predicates/constructions: every result is checked against an independent oracle in
// GMP rationals (its own formulas: Cramer around a, Gaussian elimination, segment parameters)
// for being the double nearest to the exact value, ties to even; plus exact cases, errors, the
// MPFR exponent range being restored, and the fast-path certification rate.
#include "predicates/constructions.hpp"
#include "predicates/orient2d.hpp"
#include "predicates/orient3d.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>
#include <mpfr.h>

#include <array>
#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <optional>
#include <random>
#include <string>

#include "base/errors.hpp"
#include "tests/support/error_message.hpp"

namespace em = exactmesh;
namespace pr = exactmesh::predicates;

namespace {

using P2 = std::array<double, 2>;
using P3 = std::array<double, 3>;
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

mpq_class q(double x) {
    return mpq_class(x);
}

mpq_class power_of_two(int e) {
    mpq_class r(1);
    if (e >= 0) {
        mpq_mul_2exp(r.get_mpq_t(), r.get_mpq_t(), static_cast<mp_bitcnt_t>(e));
    } else {
        mpq_div_2exp(r.get_mpq_t(), r.get_mpq_t(), static_cast<mp_bitcnt_t>(-e));
    }
    return r;
}

/// The smallest magnitude that rounds to infinity: DBL_MAX + ulp(DBL_MAX) / 2.
const mpq_class& overflow_threshold() {
    static const mpq_class threshold = q(DBL_MAX) + power_of_two(970);
    return threshold;
}

bool even_significand(double x) {
    return (std::bit_cast<std::uint64_t>(x) & 1u) == 0u;
}

template <std::size_t N>
std::string describe(std::initializer_list<std::array<double, N>> points) {
    std::string text;
    char value[40];
    for (const auto& p : points) {
        text += "(";
        for (std::size_t k = 0; k < N; ++k) {
            std::snprintf(value, sizeof value, k == 0 ? "%a" : ", %a", p[k]);
            text += value;
        }
        text += ") ";
    }
    return text;
}

/// r is the double nearest to `exact`, ties to even: no neighbour of r is closer, and at an
/// equal distance r has the even significand. Infinity counts as the even neighbour 2^1024.
::testing::AssertionResult correctly_rounded(const mpq_class& exact, double r) {
    if (!std::isfinite(r)) return ::testing::AssertionFailure() << "result " << r;
    const mpq_class error = abs(exact - q(r));
    for (const double direction : {-kInf, kInf}) {
        const double neighbour = std::nextafter(r, direction);
        const mpq_class nq = std::isfinite(neighbour)
                                 ? q(neighbour)
                                 : (direction > 0 ? power_of_two(1024) : -power_of_two(1024));
        const mpq_class neighbour_error = abs(exact - nq);
        if (error > neighbour_error) {
            return ::testing::AssertionFailure()
                   << "result " << std::hexfloat << r << " but its neighbour " << neighbour
                   << " is nearer to the exact value " << exact.get_d();
        }
        if (error == neighbour_error && !even_significand(r)) {
            return ::testing::AssertionFailure()
                   << "tie not rounded to even: " << std::hexfloat << r << " vs " << neighbour;
        }
    }
    return ::testing::AssertionSuccess();
}

// ---------------------------------------------------------------------------------------------
// Oracles: exact rationals, nullopt when the construction is undefined.

/// Circumcenter by Cramer's rule on 2 (p - a) . X = |p|^2 - |a|^2, p = b, c (origin untouched).
std::optional<std::array<mpq_class, 2>> oracle_circumcenter(const P2& a, const P2& b, const P2& c) {
    const mpq_class m00 = 2 * (q(b[0]) - a[0]), m01 = 2 * (q(b[1]) - a[1]);
    const mpq_class m10 = 2 * (q(c[0]) - a[0]), m11 = 2 * (q(c[1]) - a[1]);
    const mpq_class na = q(a[0]) * a[0] + q(a[1]) * a[1];
    const mpq_class r0 = q(b[0]) * b[0] + q(b[1]) * b[1] - na;
    const mpq_class r1 = q(c[0]) * c[0] + q(c[1]) * c[1] - na;
    const mpq_class det = m00 * m11 - m01 * m10;
    if (sgn(det) == 0) return std::nullopt;
    std::array<mpq_class, 2> x = {(r0 * m11 - m01 * r1) / det, (m00 * r1 - r0 * m10) / det};
    // Self-check of the oracle: equidistant from the three points.
    auto distance2 = [&](const P2& p) {
        const mpq_class dx = x[0] - p[0], dy = x[1] - p[1];
        return mpq_class(dx * dx + dy * dy);
    };
    EXPECT_EQ(distance2(a), distance2(b));
    EXPECT_EQ(distance2(a), distance2(c));
    return x;
}

/// Circumcenter in 3D by Gaussian elimination on the same bisector system.
std::optional<std::array<mpq_class, 3>> oracle_circumcenter(const P3& a, const P3& b, const P3& c,
                                                            const P3& d) {
    mpq_class m[3][4];
    const P3* rows[3] = {&b, &c, &d};
    const mpq_class na = q(a[0]) * a[0] + q(a[1]) * a[1] + q(a[2]) * a[2];
    for (int r = 0; r < 3; ++r) {
        const P3& p = *rows[r];
        for (unsigned k = 0; k < 3; ++k) m[r][k] = 2 * (q(p[k]) - a[k]);
        m[r][3] = q(p[0]) * p[0] + q(p[1]) * p[1] + q(p[2]) * p[2] - na;
    }
    for (int col = 0; col < 3; ++col) {
        int pivot = col;
        while (pivot < 3 && sgn(m[pivot][col]) == 0) ++pivot;
        if (pivot == 3) return std::nullopt;
        for (int k = 0; k < 4; ++k) std::swap(m[col][k], m[pivot][k]);
        for (int r = 0; r < 3; ++r) {
            if (r == col || sgn(m[r][col]) == 0) continue;
            const mpq_class factor = m[r][col] / m[col][col];
            for (int k = col; k < 4; ++k) m[r][k] -= factor * m[col][k];
        }
    }
    std::array<mpq_class, 3> x;
    for (int k = 0; k < 3; ++k) x[static_cast<unsigned>(k)] = m[k][3] / m[k][k];
    return x;
}

/// Intersection by the parameters of a + t (b - a) = c + s (d - c); nullopt unless the
/// segments meet in exactly one point (lines not parallel, t and s in [0, 1]).
std::optional<std::array<mpq_class, 2>> oracle_intersection(const P2& a, const P2& b, const P2& c,
                                                            const P2& d) {
    const mpq_class ux = q(b[0]) - a[0], uy = q(b[1]) - a[1];
    const mpq_class vx = q(d[0]) - c[0], vy = q(d[1]) - c[1];
    const mpq_class wx = q(c[0]) - a[0], wy = q(c[1]) - a[1];
    const mpq_class det = vx * uy - ux * vy;  // det [u, -v]
    if (sgn(det) == 0) return std::nullopt;
    const mpq_class t = (vx * wy - wx * vy) / det;
    const mpq_class s = (ux * wy - wx * uy) / det;
    if (t < 0 || t > 1 || s < 0 || s > 1) return std::nullopt;
    std::array<mpq_class, 2> x = {a[0] + t * ux, a[1] + t * uy};
    EXPECT_EQ(x[0], c[0] + s * vx);
    EXPECT_EQ(x[1], c[1] + s * vy);
    return x;
}

// ---------------------------------------------------------------------------------------------
// Checks of one call against the oracle: the value, or the error when there must be one.

template <std::size_t N, class Call>
::testing::AssertionResult matches_oracle(const std::optional<std::array<mpq_class, N>>& exact,
                                          Call call, const std::string& input) {
    bool overflows = false;
    if (exact) {
        for (const mpq_class& x : *exact) overflows = overflows || abs(x) >= overflow_threshold();
    }
    if (!exact || overflows) {
        try {
            const auto r = call();
            return ::testing::AssertionFailure()
                   << "expected GeometryError, got " << r[0] << " for " << input;
        } catch (const em::GeometryError&) {
            return ::testing::AssertionSuccess();
        }
    }
    std::array<double, N> r;
    try {
        r = call();
    } catch (const std::exception& e) {
        return ::testing::AssertionFailure()
               << "unexpected exception " << e.what() << " for " << input;
    }
    for (std::size_t k = 0; k < N; ++k) {
        auto verdict = correctly_rounded((*exact)[k], r[k]);
        if (!verdict) return verdict << " (coordinate " << k << ") for " << input;
    }
    return ::testing::AssertionSuccess();
}

::testing::AssertionResult check_circumcenter(const P2& a, const P2& b, const P2& c) {
    return matches_oracle<2>(
        oracle_circumcenter(a, b, c),
        [&] { return pr::circumcenter(a.data(), b.data(), c.data()); }, describe({a, b, c}));
}

::testing::AssertionResult check_circumcenter(const P3& a, const P3& b, const P3& c, const P3& d) {
    return matches_oracle<3>(
        oracle_circumcenter(a, b, c, d),
        [&] { return pr::circumcenter(a.data(), b.data(), c.data(), d.data()); },
        describe({a, b, c, d}));
}

::testing::AssertionResult check_intersection(const P2& a, const P2& b, const P2& c, const P2& d) {
    return matches_oracle<2>(
        oracle_intersection(a, b, c, d),
        [&] { return pr::segment_intersection(a.data(), b.data(), c.data(), d.data()); },
        describe({a, b, c, d}));
}

// ---------------------------------------------------------------------------------------------
// Input distributions (fixed seeds).

class Inputs {
  public:
    explicit Inputs(std::uint64_t seed) : engine_(seed) {}

    double uniform(double lo = -1.0, double hi = 1.0) {
        return std::uniform_real_distribution<double>(lo, hi)(engine_);
    }
    double grid(int n) { return std::uniform_int_distribution<int>(-n, n)(engine_); }
    int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(engine_); }
    /// Uniform significand, exponent uniform in [lo, hi]: every binade equally often.
    double wide(int lo, int hi) { return std::ldexp(uniform(), integer(lo, hi)); }
    /// x moved by k ulps.
    static double ulps(double x, int k) {
        for (; k > 0; --k) x = std::nextafter(x, kInf);
        for (; k < 0; ++k) x = std::nextafter(x, -kInf);
        return x;
    }

    template <std::size_t N, class F>
    std::array<double, N> point(F f) {
        std::array<double, N> p;
        for (auto& x : p) x = f();
        return p;
    }

  private:
    std::mt19937_64 engine_;
};

/// The scaled families of the random tests: factor applied to uniform [-1, 1) coordinates.
constexpr double kScales[] = {1.0, 1e200, 1e-200, 1e-308, 1e100, 1e-100};

// ---------------------------------------------------------------------------------------------
// Random comparisons with the oracle (about 10^5 calls in all).

TEST(Predicates_Constructions, Circumcenter2dMatchesOracleOnRandomInputs) {
    Inputs in(20240501);
    for (int i = 0; i < 12000; ++i) {
        const auto u = [&] { return in.uniform(); };
        ASSERT_TRUE(check_circumcenter(in.point<2>(u), in.point<2>(u), in.point<2>(u)));
    }
    for (int i = 0; i < 8000; ++i) {  // integer grid: exact collinearity, cocircularity, ties
        const auto g = [&] { return in.grid(20); };
        ASSERT_TRUE(check_circumcenter(in.point<2>(g), in.point<2>(g), in.point<2>(g)));
    }
    for (int i = 0; i < 6000; ++i) {  // binades from 2^-40 to 2^40 mixed in one triangle
        const auto w = [&] { return in.wide(-40, 40); };
        ASSERT_TRUE(check_circumcenter(in.point<2>(w), in.point<2>(w), in.point<2>(w)));
    }
    for (int i = 0; i < 4000; ++i) {  // small triangles far from the origin
        const auto t = [&] { return 1e6 + in.uniform(0.0, 1e-3); };
        ASSERT_TRUE(check_circumcenter(in.point<2>(t), in.point<2>(t), in.point<2>(t)));
    }
    for (const double scale : kScales) {  // huge, tiny, subnormal (exact path and its rounding)
        for (int i = 0; i < 1500; ++i) {
            const auto s = [&] { return in.uniform() * scale; };
            ASSERT_TRUE(check_circumcenter(in.point<2>(s), in.point<2>(s), in.point<2>(s)));
        }
    }
}

TEST(Predicates_Constructions, Circumcenter2dMatchesOracleOnNearDegenerateTriangles) {
    // c on the segment ab up to rounding, then moved by a few ulps: circumcenters near 1e16,
    // some triangles exactly collinear (the oracle then expects GeometryError).
    Inputs in(7);
    for (int i = 0; i < 10000; ++i) {
        const P2 a = {in.uniform(), in.uniform()}, b = {in.uniform(), in.uniform()};
        const double t = in.uniform(0.0, 1.0);
        P2 c = {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])};
        c[1] = Inputs::ulps(c[1], in.integer(-3, 3));
        ASSERT_TRUE(check_circumcenter(a, b, c));
    }
}

TEST(Predicates_Constructions, Circumcenter3dMatchesOracleOnRandomInputs) {
    Inputs in(99);
    for (int i = 0; i < 5000; ++i) {
        const auto u = [&] { return in.uniform(); };
        ASSERT_TRUE(
            check_circumcenter(in.point<3>(u), in.point<3>(u), in.point<3>(u), in.point<3>(u)));
    }
    for (int i = 0; i < 3000; ++i) {
        const auto g = [&] { return in.grid(6); };
        ASSERT_TRUE(
            check_circumcenter(in.point<3>(g), in.point<3>(g), in.point<3>(g), in.point<3>(g)));
    }
    for (int i = 0; i < 2000; ++i) {  // exact differences p - d: the translated form
        const auto t = [&] { return 1e6 + in.uniform(0.0, 1e-3); };
        ASSERT_TRUE(
            check_circumcenter(in.point<3>(t), in.point<3>(t), in.point<3>(t), in.point<3>(t)));
    }
    for (int i = 0; i < 2000; ++i) {
        const auto w = [&] { return in.wide(-30, 30); };
        ASSERT_TRUE(
            check_circumcenter(in.point<3>(w), in.point<3>(w), in.point<3>(w), in.point<3>(w)));
    }
    for (int i = 0; i < 3000; ++i) {  // d in the plane abc up to rounding, then a few ulps off
        const auto u = [&] { return in.uniform(); };
        const P3 a = in.point<3>(u), b = in.point<3>(u), c = in.point<3>(u);
        const double s = in.uniform(0.0, 1.0), t = in.uniform(0.0, 1.0);
        P3 d;
        for (unsigned k = 0; k < 3; ++k) d[k] = a[k] + s * (b[k] - a[k]) + t * (c[k] - a[k]);
        d[2] = Inputs::ulps(d[2], in.integer(-2, 2));
        ASSERT_TRUE(check_circumcenter(a, b, c, d));
    }
    for (const double scale : kScales) {
        for (int i = 0; i < 400; ++i) {
            const auto s = [&] { return in.uniform() * scale; };
            ASSERT_TRUE(
                check_circumcenter(in.point<3>(s), in.point<3>(s), in.point<3>(s), in.point<3>(s)));
        }
    }
}

TEST(Predicates_Constructions, SegmentIntersectionMatchesOracleOnRandomInputs) {
    Inputs in(4242);
    for (int i = 0; i < 12000; ++i) {  // about one pair in six crosses; the rest must throw
        const auto u = [&] { return in.uniform(); };
        ASSERT_TRUE(
            check_intersection(in.point<2>(u), in.point<2>(u), in.point<2>(u), in.point<2>(u)));
    }
    int crossing = 0;
    for (int i = 0; i < 6000; ++i) {  // forced crossings: c, d on opposite sides of ab's midpoint
        const P2 a = {in.uniform(), in.uniform()}, b = {in.uniform(), in.uniform()};
        const P2 m = {0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])};
        const P2 dir = {in.uniform(), in.uniform()};
        const P2 c = {m[0] - dir[0], m[1] - dir[1]}, d = {m[0] + dir[0], m[1] + dir[1]};
        crossing += oracle_intersection(a, b, c, d) ? 1 : 0;
        ASSERT_TRUE(check_intersection(a, b, c, d));
    }
    EXPECT_GT(crossing, 5000);
    for (int i = 0; i < 3000; ++i) {  // crossings far from the origin: exact differences
        const auto t = [&] { return 1e6 + in.uniform(0.0, 1e-3); };
        const P2 a = in.point<2>(t), b = in.point<2>(t);
        const P2 m = {0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])};
        const P2 dir = {in.uniform(-1e-3, 1e-3), in.uniform(-1e-3, 1e-3)};
        ASSERT_TRUE(check_intersection(a, b, {m[0] - dir[0], m[1] - dir[1]},
                                       {m[0] + dir[0], m[1] + dir[1]}));
    }
    for (int i = 0; i < 6000; ++i) {  // grids: T-junctions, shared endpoints, collinear overlaps
        const auto g = [&] { return in.grid(4); };
        ASSERT_TRUE(
            check_intersection(in.point<2>(g), in.point<2>(g), in.point<2>(g), in.point<2>(g)));
    }
    for (int i = 0; i < 4000; ++i) {  // nearly parallel crossings: the point is ill-conditioned
        const P2 a = {in.uniform(), in.uniform()}, b = {in.uniform(), in.uniform()};
        const P2 c = {Inputs::ulps(a[0], in.integer(-4, 4)), Inputs::ulps(a[1], 3)};
        const P2 d = {Inputs::ulps(b[0], in.integer(-4, 4)), Inputs::ulps(b[1], -3)};
        ASSERT_TRUE(check_intersection(a, b, c, d));
    }
    for (const double scale : kScales) {
        for (int i = 0; i < 1000; ++i) {
            const P2 a = {in.uniform() * scale, in.uniform() * scale};
            const P2 b = {-a[0] + in.uniform() * scale * 0.1, -a[1]};
            const P2 c = {in.uniform() * scale, in.uniform() * scale};
            const P2 d = {-c[0], -c[1] + in.uniform() * scale * 0.1};
            ASSERT_TRUE(check_intersection(a, b, c, d));
        }
    }
}

TEST(Predicates_Constructions, ExactPathAgreesAndResultsArePermutationInvariant) {
    // Correct rounding makes the result a function of the point set: every vertex order, and
    // the always-exact path, must give the same bits.
    Inputs in(31337);
    for (int i = 0; i < 2000; ++i) {
        const auto u = [&] { return in.wide(-8, 8); };
        const P2 a = in.point<2>(u), b = in.point<2>(u), c = in.point<2>(u);
        const P2 r = pr::circumcenter(a.data(), b.data(), c.data());
        ASSERT_EQ(r, pr::circumcenter_exact(a.data(), b.data(), c.data()));
        ASSERT_EQ(r, pr::circumcenter(b.data(), c.data(), a.data()));
        ASSERT_EQ(r, pr::circumcenter(c.data(), b.data(), a.data()));
        const P3 p = in.point<3>(u), s = in.point<3>(u), t = in.point<3>(u), w = in.point<3>(u);
        const P3 r3 = pr::circumcenter(p.data(), s.data(), t.data(), w.data());
        ASSERT_EQ(r3, pr::circumcenter_exact(p.data(), s.data(), t.data(), w.data()));
        ASSERT_EQ(r3, pr::circumcenter(w.data(), t.data(), p.data(), s.data()));
        const P2 e = {-a[0], -a[1]};  // segment through a's mirror: [a, -a] vs [b, c] may cross
        if (oracle_intersection(a, e, b, c)) {
            const P2 x = pr::segment_intersection(a.data(), e.data(), b.data(), c.data());
            ASSERT_EQ(x, pr::segment_intersection_exact(a.data(), e.data(), b.data(), c.data()));
            ASSERT_EQ(x, pr::segment_intersection(c.data(), b.data(), e.data(), a.data()));
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Exact cases.

TEST(Predicates_Constructions, RightTriangleCircumcenterIsHypotenuseMidpoint) {
    const P2 a = {0, 0}, b = {7, 1}, c = {3, 4};  // (a - c) . (b - c) = 0: right angle at c
    EXPECT_EQ(pr::circumcenter(a.data(), b.data(), c.data()), (P2{3.5, 0.5}));
    const P2 p = {0.125, -3}, s = {0.125, 5}, t = {-1, 5};  // right angle at s
    EXPECT_EQ(pr::circumcenter(p.data(), s.data(), t.data()), (P2{-0.4375, 1}));
    // Huge and tiny right triangles: the exact path, midpoints still exact.
    const P2 h1 = {DBL_MAX, 0}, h2 = {0, DBL_MAX}, h3 = {0, 0};
    EXPECT_EQ(pr::circumcenter(h1.data(), h2.data(), h3.data()), (P2{DBL_MAX / 2, DBL_MAX / 2}));
    const P2 t1 = {0x1p-1000, 0}, t2 = {0, 0x1p-1010}, t3 = {0, 0};
    EXPECT_EQ(pr::circumcenter(t1.data(), t2.data(), t3.data()), (P2{0x1p-1001, 0x1p-1011}));
    // Corner tetrahedron: the center is the middle of the box.
    const P3 o = {0, 0, 0}, x = {6, 0, 0}, y = {0, 10, 0}, z = {0, 0, -0.5};
    EXPECT_EQ(pr::circumcenter(o.data(), x.data(), y.data(), z.data()), (P3{3, 5, -0.25}));
    const P3 o2 = {1e6, 1e6, 1e6}, x2 = {1e6 + 2, 1e6, 1e6}, y2 = {1e6, 1e6 + 4, 1e6},
             z2 = {1e6, 1e6, 1e6 + 8};
    EXPECT_EQ(pr::circumcenter(o2.data(), x2.data(), y2.data(), z2.data()),
              (P3{1e6 + 1, 1e6 + 2, 1e6 + 4}));
}

TEST(Predicates_Constructions, SymmetricInputsGiveSymmetricResults) {
    // Isosceles about the y axis: x is exactly 0; mirroring negates exactly (round to nearest
    // is symmetric), and y = (h^2 - 1) / (2h) needs rounding.
    const P2 a = {-1, 0}, b = {1, 0}, c = {0, 0.3};
    const P2 r = pr::circumcenter(a.data(), b.data(), c.data());
    EXPECT_EQ(r[0], 0.0);
    EXPECT_TRUE(correctly_rounded((q(0.3) * 0.3 - 1) / (2 * q(0.3)), r[1]));
    Inputs in(5);
    for (int i = 0; i < 200; ++i) {
        const P2 p = {in.uniform(), in.uniform()}, s = {in.uniform(), in.uniform()},
                 t = {in.uniform(), in.uniform()};
        const P2 mp = {-p[0], p[1]}, ms = {-s[0], s[1]}, mt = {-t[0], t[1]};
        const P2 x = pr::circumcenter(p.data(), s.data(), t.data());
        const P2 mx = pr::circumcenter(mp.data(), ms.data(), mt.data());
        EXPECT_EQ(mx[0], -x[0]);
        EXPECT_EQ(mx[1], x[1]);
    }
    // Regular tetrahedron on alternate cube corners: the center is the cube center.
    const P3 v0 = {1, 1, 1}, v1 = {1, -1, -1}, v2 = {-1, 1, -1}, v3 = {-1, -1, 1};
    const P3 center = pr::circumcenter(v0.data(), v1.data(), v2.data(), v3.data());
    EXPECT_EQ(center, (P3{0, 0, 0}));
    EXPECT_FALSE(std::signbit(center[0]) || std::signbit(center[1]) || std::signbit(center[2]));
}

TEST(Predicates_Constructions, UnrepresentableCircumcenterIsRoundedToNearest) {
    // (0,0), (2,0), (1,3): center (1, 4/3); IEEE division rounds 4/3 correctly too.
    const P2 a = {0, 0}, b = {2, 0}, c = {1, 3};
    EXPECT_EQ(pr::circumcenter(a.data(), b.data(), c.data()), (P2{1, 4.0 / 3.0}));
    const P2 d = {0.1, 0}, e = {0, 0.7}, f = {0.3, 0.5};
    const P2 r = pr::circumcenter(d.data(), e.data(), f.data());
    const auto exact = oracle_circumcenter(d, e, f);
    ASSERT_TRUE(exact);
    EXPECT_TRUE(correctly_rounded((*exact)[0], r[0]));
    EXPECT_TRUE(correctly_rounded((*exact)[1], r[1]));
    EXPECT_NE(q(r[0]), (*exact)[0]);  // really not representable
    // 3D: x = y = 1.5 from the first three; 2 (1, 1, 3) . X = 11 gives z = 5/6.
    const P3 p = {0, 0, 0}, s = {3, 0, 0}, t = {0, 3, 0}, w = {1, 1, 3};
    const P3 r3 = pr::circumcenter(p.data(), s.data(), t.data(), w.data());
    EXPECT_EQ(r3, (P3{1.5, 1.5, 5.0 / 6.0}));
}

TEST(Predicates_Constructions, ExactTiesRoundToEven) {
    // Right angle at a: center = ((p + r) / 2, s / 2), an exact midpoint between two doubles.
    struct Case {
        double p, r, expected;
    };
    const Case cases[] = {
        {0x1p53, 0x1p53 + 2, 0x1p53},          // 2^53 + 1: 2^53 is even
        {0x1p53 + 2, 0x1p53 + 4, 0x1p53 + 4},  // 2^53 + 3: 2^53 + 4 is even
        {1.0, 1.0 + 0x1p-52, 1.0},             // 1 + 2^-53
        {1.0 + 0x1p-52, 1.0 + 0x1p-51, 1.0 + 0x1p-51},
        {-(1.0 + 0x1p-52), -(1.0 + 0x1p-51), -(1.0 + 0x1p-51)},
        {0x1p-1074, 0x1p-1073, 0x1p-1073},      // 1.5 * 2^-1074: subnormal tie
        {3 * 0x1p-1074, 0x1p-1072, 0x1p-1072},  // 3.5 * 2^-1074: 4 * 2^-1074 is even
    };
    pr::reset_construction_stats();
    for (const Case& t : cases) {
        const P2 a = {t.p, 0}, b = {t.r, 0}, c = {t.p, 2};
        const P2 x = pr::circumcenter(a.data(), b.data(), c.data());
        const mpq_class exact = (q(t.p) + t.r) / 2;
        EXPECT_TRUE(correctly_rounded(exact, x[0])) << std::hexfloat << t.p << " " << t.r;
        EXPECT_EQ(x[1], 1.0);
    }
    EXPECT_EQ(pr::construction_stats().calls, std::size(cases));
    EXPECT_GE(pr::construction_stats().fast, 5u);  // the normal-range ties certify on the fast path
    // The even neighbour, spelled out.
    for (const Case& t : cases) {
        const P2 a = {t.p, 0}, b = {t.r, 0}, c = {t.p, 2};
        EXPECT_EQ(pr::circumcenter(a.data(), b.data(), c.data())[0], t.expected)
            << std::hexfloat << t.p;
    }
    // Segment intersection at an exact tie: x = 1 + 2^-53 on the line y = x.
    const P2 s0 = {1.0, 1.0}, s1 = {1.0 + 0x1p-52, 1.0 + 0x1p-52};
    const P2 s2 = {1.0, 1.0 + 0x1p-52}, s3 = {1.0 + 0x1p-52, 1.0};
    const P2 x = pr::segment_intersection(s0.data(), s1.data(), s2.data(), s3.data());
    EXPECT_EQ(x, (P2{1.0, 1.0}));
}

TEST(Predicates_Constructions, NearMidpointResultsStillRoundCorrectly) {
    // Centers within 2^-100 (relative) of a midpoint but not on it: b is raised by delta off
    // the horizontal through a, which turns the bisector and moves x = (p + r) / 2 by about
    // -delta * y / (r - p). The first candidate's refinement cannot tell the side; the exact
    // tests must, stepping to the neighbour or falling back to the exact path.
    pr::reset_construction_stats();
    int cases = 0;
    for (const double p : {1.0, 0x1p53, -3.0, 0x1.8p-20}) {
        const double r = std::nextafter(p, kInf);
        for (int k = 90; k <= 200; ++k) {
            for (const double sign : {-1.0, 1.0}) {
                const double delta = sign * std::ldexp(std::fabs(p), -k);
                const P2 a = {p, 0}, b = {r, delta}, c = {p, 1};
                ASSERT_TRUE(check_circumcenter(a, b, c)) << k;
                ++cases;
            }
        }
    }
    const pr::ConstructionStats& s = pr::construction_stats();
    std::printf(
        "[ stats    ] near-midpoint: calls %llu fast %llu neighbour steps %llu exact "
        "range %llu uncertified %llu\n",
        static_cast<unsigned long long>(s.calls), static_cast<unsigned long long>(s.fast),
        static_cast<unsigned long long>(s.neighbour_steps),
        static_cast<unsigned long long>(s.exact_range),
        static_cast<unsigned long long>(s.exact_uncertified));
    EXPECT_EQ(s.calls, static_cast<std::uint64_t>(cases));
    EXPECT_GT(s.neighbour_steps, 0u);  // the neighbour step really ran (and was right)
}

TEST(Predicates_Constructions, SubnormalResultsAreRoundedOnce) {
    // Subnormal results: the exact path rounds straight to the subnormal grid (no double
    // rounding through 53 bits).
    Inputs in(11);
    for (int i = 0; i < 2000; ++i) {
        const auto s = [&] { return in.grid(1 << 20) * 0x1p-1074; };
        ASSERT_TRUE(check_circumcenter(in.point<2>(s), in.point<2>(s), in.point<2>(s)));
    }
    // A result just below 2^-1074 / 2 rounds to zero, just above to 2^-1074.
    const P2 a = {0, 0}, b = {0x1p-1074, 0}, c = {0, 0x1p-1074};
    EXPECT_EQ(pr::circumcenter(a.data(), b.data(), c.data()), (P2{0, 0}));  // ties 2^-1075 to 0
    const P2 d = {0x1p-1073, 0}, e = {0, 3 * 0x1p-1074};  // center (2^-1074, 1.5 * 2^-1074)
    EXPECT_EQ(pr::circumcenter(a.data(), d.data(), e.data()), (P2{0x1p-1074, 0x1p-1073}));
}

// ---------------------------------------------------------------------------------------------
// Errors.

/// The GeometryError message of `call`, or "" when it throws none.
template <class Call>
std::string error_message(Call call) {
    return em::testing::error_message<em::GeometryError>(call);
}

TEST(Predicates_Constructions, CollinearTriangleIsAnError) {
    const P2 a = {0.1, 0.1}, b = {0.2, 0.2}, c = {0, 0};
    const std::string message =
        error_message([&] { pr::circumcenter(a.data(), b.data(), c.data()); });
    EXPECT_NE(message.find("collinear"), std::string::npos) << message;
    // The points as the shortest text that reads back exactly (format_point).
    EXPECT_NE(message.find("(0.1, 0.1), (0.2, 0.2), (0, 0)"), std::string::npos) << message;
    const P2 p = {1, 3}, s = {2, 5}, t = {1.5, 4};
    EXPECT_THROW(pr::circumcenter(p.data(), s.data(), t.data()), em::GeometryError);
    EXPECT_THROW(pr::circumcenter(p.data(), p.data(), t.data()), em::GeometryError);
    EXPECT_THROW(pr::circumcenter_exact(p.data(), s.data(), t.data()), em::GeometryError);
    const P2 h = {1e300, 1e300}, k = {2e300, 2e300}, o = {0, 0};  // exact path, y = x
    EXPECT_THROW(pr::circumcenter(h.data(), k.data(), o.data()), em::GeometryError);
}

TEST(Predicates_Constructions, CoplanarTetrahedronIsAnError) {
    const P3 a = {0, 0, 1}, b = {1, 0, 1}, c = {0, 1, 1}, d = {0.3, 0.7, 1};
    const std::string message =
        error_message([&] { pr::circumcenter(a.data(), b.data(), c.data(), d.data()); });
    EXPECT_NE(message.find("coplanar"), std::string::npos) << message;
    EXPECT_NE(message.find("(0.3, 0.7, 1)"), std::string::npos) << message;
    const P3 p = {1, 0, 0}, s = {0, 1, 0}, t = {0, 0, 1}, u = {0.25, 0.25, 0.5};  // x+y+z=1
    EXPECT_THROW(pr::circumcenter(p.data(), s.data(), t.data(), u.data()), em::GeometryError);
    EXPECT_THROW(pr::circumcenter_exact(p.data(), s.data(), t.data(), u.data()), em::GeometryError);
}

TEST(Predicates_Constructions, NonFiniteInputIsAnError) {
    const P2 a = {0, 0}, b = {1, 0}, c = {0, 1};
    for (const double bad : {kNaN, kInf, -kInf}) {
        const P2 x = {bad, 0.5};
        EXPECT_THROW(pr::circumcenter(x.data(), b.data(), c.data()), em::GeometryError);
        EXPECT_THROW(pr::circumcenter(a.data(), b.data(), x.data()), em::GeometryError);
        EXPECT_THROW(pr::segment_intersection(a.data(), x.data(), b.data(), c.data()),
                     em::GeometryError);
        const P3 p = {0, 0, 0}, s = {1, 0, 0}, t = {0, 1, 0}, u = {0, 0, bad};
        EXPECT_THROW(pr::circumcenter(p.data(), s.data(), t.data(), u.data()), em::GeometryError);
    }
    const P2 x = {kNaN, 0.5};
    const std::string message =
        error_message([&] { pr::circumcenter(x.data(), b.data(), c.data()); });
    EXPECT_NE(message.find("non-finite"), std::string::npos) << message;
}

TEST(Predicates_Constructions, OverflowingCircumcenterIsAnError) {
    // Nearly collinear huge points: the center lies far beyond DBL_MAX.
    const P2 a = {-1e308, 0}, b = {1e308, 0}, c = {0, 1e-300};
    const std::string message =
        error_message([&] { pr::circumcenter(a.data(), b.data(), c.data()); });
    EXPECT_NE(message.find("overflow"), std::string::npos) << message;
    const P3 p = {-1e308, 0, 0}, s = {1e308, 0, 0}, t = {0, 1e-300, 0}, u = {0, 0, 1e308};
    EXPECT_THROW(pr::circumcenter(p.data(), s.data(), t.data(), u.data()), em::GeometryError);
    // Intermediate values far beyond DBL_MAX, result in range: right angle at m0, center 0.
    const P2 m0 = {DBL_MAX, DBL_MAX}, m1 = {DBL_MAX, -DBL_MAX}, m2 = {-DBL_MAX, DBL_MAX};
    EXPECT_EQ(pr::circumcenter(m0.data(), m1.data(), m2.data()), (P2{0, 0}));
}

TEST(Predicates_Constructions, SegmentErrorsNameTheProblem) {
    auto message = [](const P2& a, const P2& b, const P2& c, const P2& d) {
        return error_message(
            [&] { pr::segment_intersection(a.data(), b.data(), c.data(), d.data()); });
    };
    // Parallel, distinct lines.
    EXPECT_NE(message({0, 0}, {1, 1}, {0, 1}, {1, 2}).find("parallel"), std::string::npos);
    // Collinear overlap, and collinear segments sharing only an endpoint.
    EXPECT_NE(message({0, 0}, {2, 2}, {1, 1}, {3, 3}).find("collinear"), std::string::npos);
    EXPECT_NE(message({0, 0}, {1, 1}, {1, 1}, {2, 2}).find("collinear"), std::string::npos);
    // Lines cross outside the segments (both orders of the test).
    EXPECT_NE(message({0, 0}, {1, 0}, {2, -1}, {2, 1}).find("do not intersect"), std::string::npos);
    EXPECT_NE(message({2, -1}, {2, 1}, {0, 0}, {1, 0}).find("do not intersect"), std::string::npos);
    EXPECT_NE(message({0, 0}, {1, 0}, {0.5, 0.25}, {0.6, 2}).find("do not intersect"),
              std::string::npos);
    // Zero-length segment.
    EXPECT_NE(message({0.5, 0.5}, {0.5, 0.5}, {0, 0}, {1, 1}).find("zero length"),
              std::string::npos);
    const P2 a = {0, 0}, b = {1, 0}, c = {0.5, 1}, d = {0.5, 2};
    EXPECT_THROW(pr::segment_intersection_exact(a.data(), b.data(), c.data(), d.data()),
                 em::GeometryError);
}

TEST(Predicates_Constructions, SegmentTouchingAtOnePointIsAccepted) {
    const P2 a = {0, 0}, b = {4, 0};
    const P2 c = {1, -1}, d = {2, 1};  // proper crossing at x = 1.5
    EXPECT_EQ(pr::segment_intersection(a.data(), b.data(), c.data(), d.data()), (P2{1.5, 0}));
    const P2 t = {0.1, 0}, u = {0.3, 5};  // T-junction: t lies inside [a, b]
    EXPECT_EQ(pr::segment_intersection(a.data(), b.data(), t.data(), u.data()), (P2{0.1, 0}));
    EXPECT_EQ(pr::segment_intersection(t.data(), u.data(), a.data(), b.data()), (P2{0.1, 0}));
    const P2 e = {0.7, 0.9};  // shared endpoint b, non-collinear
    EXPECT_EQ(pr::segment_intersection(a.data(), b.data(), b.data(), e.data()), b);
    EXPECT_EQ(pr::segment_intersection(e.data(), b.data(), a.data(), b.data()), b);
    // An endpoint of one segment on the interior of the other, with inexact coordinates.
    const P2 p = {0.1, 0.2}, s = {0.7, 0.9};
    const P2 m = {0.1 + 0.6 * 0.5, 0.2 + 0.7 * 0.5};  // on ps only up to rounding
    const P2 w = {m[0] + 1, m[1] - 3};
    ASSERT_TRUE(check_intersection(p, s, m, w));
    // Crossing point with irrational-looking coordinates: rounded to nearest.
    const P2 f = {0.1, 0.3}, g = {0.9, 0.2}, h = {0.2, -0.1}, k = {0.4, 0.8};
    ASSERT_TRUE(check_intersection(f, g, h, k));
}

// ---------------------------------------------------------------------------------------------
// Exact-path hygiene and the fast-path claim.

TEST(Predicates_Constructions, ExactPathRestoresTheMpfrExponentRange) {
    const mpfr_exp_t emin = mpfr_get_emin(), emax = mpfr_get_emax();
    const P2 a = {1e-200, 0}, b = {0, 3e-200}, c = {-2e-200, 1e-210};
    static_cast<void>(pr::circumcenter(a.data(), b.data(), c.data()));
    EXPECT_EQ(mpfr_get_emin(), emin);
    EXPECT_EQ(mpfr_get_emax(), emax);
    const P2 h = {-1e308, 0}, k = {1e308, 0}, m = {0, 1e-300};
    EXPECT_THROW(pr::circumcenter(h.data(), k.data(), m.data()), em::GeometryError);
    EXPECT_EQ(mpfr_get_emin(), emin);
    EXPECT_EQ(mpfr_get_emax(), emax);
}

TEST(Predicates_Constructions, FastPathCertifiesNearlyAllRandomInputs) {
    Inputs in(2718);
    auto rate = [](const char* what) {
        const pr::ConstructionStats& s = pr::construction_stats();
        EXPECT_EQ(s.calls, s.fast + s.exact_range + s.exact_uncertified);
        const double fast = static_cast<double>(s.fast) / static_cast<double>(s.calls);
        std::printf(
            "[ stats    ] %-28s calls %llu fast %llu (%.4f%%) neighbour steps %llu "
            "exact: range %llu uncertified %llu\n",
            what, static_cast<unsigned long long>(s.calls), static_cast<unsigned long long>(s.fast),
            100.0 * fast, static_cast<unsigned long long>(s.neighbour_steps),
            static_cast<unsigned long long>(s.exact_range),
            static_cast<unsigned long long>(s.exact_uncertified));
        return fast;
    };
    constexpr int kCalls = 10000;
    const auto u = [&] { return in.uniform(); };
    pr::reset_construction_stats();
    for (int i = 0; i < kCalls; ++i) {
        const P2 a = in.point<2>(u), b = in.point<2>(u), c = in.point<2>(u);
        static_cast<void>(pr::circumcenter(a.data(), b.data(), c.data()));
    }
    EXPECT_GE(rate("circumcenter 2D uniform"), 0.999);
    pr::reset_construction_stats();
    const auto t = [&] { return 1e6 + in.uniform(0.0, 1e-3); };
    for (int i = 0; i < kCalls; ++i) {
        const P2 a = in.point<2>(t), b = in.point<2>(t), c = in.point<2>(t);
        static_cast<void>(pr::circumcenter(a.data(), b.data(), c.data()));
    }
    EXPECT_GE(rate("circumcenter 2D translated"), 0.999);
    pr::reset_construction_stats();
    for (int i = 0; i < kCalls / 2; ++i) {
        const P3 a = in.point<3>(u), b = in.point<3>(u), c = in.point<3>(u), d = in.point<3>(u);
        static_cast<void>(pr::circumcenter(a.data(), b.data(), c.data(), d.data()));
    }
    EXPECT_GE(rate("circumcenter 3D uniform"), 0.999);
    pr::reset_construction_stats();
    for (int i = 0; i < kCalls / 2; ++i) {
        const P3 a = in.point<3>(t), b = in.point<3>(t), c = in.point<3>(t), d = in.point<3>(t);
        static_cast<void>(pr::circumcenter(a.data(), b.data(), c.data(), d.data()));
    }
    EXPECT_GE(rate("circumcenter 3D translated"), 0.999);
    pr::reset_construction_stats();
    for (int i = 0; i < kCalls; ++i) {
        const P2 a = in.point<2>(u), b = in.point<2>(u);
        const P2 m = {0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])};
        const P2 dir = {in.uniform(), in.uniform()};
        const P2 c = {m[0] - dir[0], m[1] - dir[1]}, d = {m[0] + dir[0], m[1] + dir[1]};
        try {
            static_cast<void>(pr::segment_intersection(a.data(), b.data(), c.data(), d.data()));
        } catch (const em::GeometryError&) {  // the rare pair that misses; not counted
        }
    }
    EXPECT_GE(rate("segment_intersection uniform"), 0.999);
    pr::reset_construction_stats();
    for (int i = 0; i < kCalls; ++i) {
        const P2 a = in.point<2>(t), b = in.point<2>(t);
        const P2 m = {0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])};
        const P2 dir = {in.uniform(-1e-3, 1e-3), in.uniform(-1e-3, 1e-3)};
        const P2 c = {m[0] - dir[0], m[1] - dir[1]}, d = {m[0] + dir[0], m[1] + dir[1]};
        try {
            static_cast<void>(pr::segment_intersection(a.data(), b.data(), c.data(), d.data()));
        } catch (const em::GeometryError&) {
        }
    }
    EXPECT_GE(rate("segment_intersection translated"), 0.999);
    // Out of the expansion-safe range, the exact path runs and is counted as such.
    pr::reset_construction_stats();
    const P2 a = {1e200, 0}, b = {0, 1e200}, c = {-1e200, 3e199};
    static_cast<void>(pr::circumcenter(a.data(), b.data(), c.data()));
    EXPECT_EQ(pr::construction_stats().exact_range, 1u);
    EXPECT_EQ(pr::construction_stats().fast, 0u);
}

/// Small triangles as a mesh generator makes them: `count` for each magnitude (offsets 1e-3 to
/// 1e6) and spread (1e-9 to 1e-1), every fourth skinny (c close to the segment ab), each passed
/// to visit(a, b, c), which returns false to stop.
template <class Visit>
void for_mesh_like_triangles(Inputs& in, int count, const Visit& visit) {
    for (const double offset : {1e-3, 0.5, 1.0, 3.0, 1e3, 1e6}) {
        for (const double spread : {1e-9, 1e-4, 1e-1}) {
            for (int i = 0; i < count; ++i) {
                const auto near = [&] { return offset + in.uniform() * spread; };
                P2 a = in.point<2>(near), b = in.point<2>(near), c = in.point<2>(near);
                if (i % 4 == 3) {
                    const double t = in.uniform(0.0, 1.0);
                    c = {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]) + spread * 1e-3};
                }
                if (!visit(a, b, c)) return;
            }
        }
    }
}

/// The call, coordinates in hexadecimal floating point (they round-trip).
std::string call_text(const P2& a, const P2& b, const P2& c) {
    char text[200];
    std::snprintf(text, sizeof text, "circumcenter((%a, %a), (%a, %a), (%a, %a))", a[0], a[1], b[0],
                  b[1], c[0], c[1]);
    return text;
}

/// Prints the construction counters of a mesh-like run of `calls` calls and checks that every
/// call was counted and at least `share` of them certified by the double-double stage.
void expect_double_double_share(const char* label, int calls, double share) {
    const pr::ConstructionStats& s = pr::construction_stats();
    std::printf("[ stats    ] %s: calls %llu double-double %llu fast %llu\n", label,
                static_cast<unsigned long long>(s.calls),
                static_cast<unsigned long long>(s.double_double),
                static_cast<unsigned long long>(s.fast));
    EXPECT_EQ(s.calls, static_cast<std::uint64_t>(calls));
    EXPECT_GE(static_cast<double>(s.double_double), share * calls);
}

/// A small tetrahedron of points from `near`: every fourth one flat (d close to the plane of
/// abc, 1e-3 spread above it), every fourth another with a short edge (b within 1e-3 spread of a).
template <class Near>
std::array<P3, 4> mesh_like_tetrahedron(Inputs& in, const Near& near, double spread, int i) {
    P3 a = in.point<3>(near), b = in.point<3>(near), c = in.point<3>(near), d = in.point<3>(near);
    if (i % 4 == 3) {
        const double s = in.uniform(0.0, 1.0), t = in.uniform(0.0, 1.0 - s);
        for (int k = 0; k < 3; ++k)
            d[k] = a[k] + s * (b[k] - a[k]) + t * (c[k] - a[k]) + (k == 2 ? spread * 1e-3 : 0);
    } else if (i % 4 == 2) {
        for (int k = 0; k < 3; ++k) b[k] = a[k] + (b[k] - a[k]) * 1e-3;
    }
    return {a, b, c, d};
}

/// circumcenter against circumcenter_exact on `count` mesh_like_tetrahedron tetrahedra for each
/// offset and spread, their coordinates drawn by draw(offset, spread); the calls made (coplanar
/// draws skipped). Stops the test at the first difference.
template <class Draw>
int expect_tetrahedra_correctly_rounded(Inputs& in, std::initializer_list<double> offsets,
                                        std::initializer_list<double> spreads, int count,
                                        const Draw& draw) {
    int calls = 0;
    for (const double offset : offsets) {
        for (const double spread : spreads) {
            for (int i = 0; i < count; ++i) {
                const auto near = [&] { return draw(offset, spread); };
                const auto [a, b, c, d] = mesh_like_tetrahedron(in, near, spread, i);
                if (pr::orient3d(a.data(), b.data(), c.data(), d.data()) == pr::Sign::Zero)
                    continue;
                ++calls;
                const auto fast = pr::circumcenter(a.data(), b.data(), c.data(), d.data());
                const auto exact = pr::circumcenter_exact(a.data(), b.data(), c.data(), d.data());
                EXPECT_EQ(fast, exact) << offset << " " << spread << " " << i;
                if (fast != exact) return calls;
            }
        }
    }
    return calls;
}

}  // namespace

TEST(Predicates_Constructions, DoubleDoubleStageIsCorrectlyRoundedOnMeshLikeTriangles) {
    // Small triangles (as a mesh generator makes them) at magnitudes from 1e-3 to 1e6, well
    // shaped and skinny: the double-double stage certifies nearly all and every result equals
    // the exact path's; where it cannot certify (skinny, near a midpoint) the later stages do.
    Inputs in(314159);
    pr::reset_construction_stats();
    int calls = 0;
    for_mesh_like_triangles(in, 4000, [&](const P2& a, const P2& b, const P2& c) {
        if (pr::orient2d(a.data(), b.data(), c.data()) == pr::Sign::Zero) return true;
        ++calls;
        const P2 fast = pr::circumcenter(a.data(), b.data(), c.data());
        const P2 exact = pr::circumcenter_exact(a.data(), b.data(), c.data());
        EXPECT_EQ(fast, exact) << call_text(a, b, c);
        return fast == exact;
    });
    expect_double_double_share("mesh-like", calls, 0.9);
}

TEST(Predicates_Constructions, FmaAndDekkerProductsGiveTheSameCircumcenters) {
    // The 2D double-double stage takes its exact products by FMA where the CPU has it (runtime
    // dispatch) and by Dekker's algorithm elsewhere: both products are exact, so every result,
    // and every decision to certify, must be the same bits, and the exact path's. Mesh-like
    // triangles at magnitudes 1e-3 to 1e6 (well shaped and skinny), and right triangles whose
    // circumcentre (the hypotenuse's midpoint) is a rounding midpoint or a few ulps from one.
    Inputs in(577215);
    std::printf("[ fma      ] circumcenter takes FMA products: %s\n",
                pr::detail::circumcenter_uses_fma() ? "yes" : "no (both paths are Dekker's)");
    int calls = 0;
    const auto expect_same = [&](const P2& a, const P2& b, const P2& c) {
        if (pr::orient2d(a.data(), b.data(), c.data()) == pr::Sign::Zero) return true;
        ++calls;
        const P2 dispatched = pr::circumcenter(a.data(), b.data(), c.data());
        const P2 dekker = pr::detail::circumcenter_without_fma(a.data(), b.data(), c.data());
        const P2 exact = pr::circumcenter_exact(a.data(), b.data(), c.data());
        EXPECT_EQ(std::bit_cast<std::uint64_t>(dispatched[0]),
                  std::bit_cast<std::uint64_t>(dekker[0]));
        EXPECT_EQ(std::bit_cast<std::uint64_t>(dispatched[1]),
                  std::bit_cast<std::uint64_t>(dekker[1]));
        EXPECT_EQ(dispatched, exact) << call_text(a, b, c);
        return dispatched == dekker && dispatched == exact;
    };
    pr::reset_construction_stats();
    for_mesh_like_triangles(in, 2000, expect_same);
    for (int i = 0; i < 4000; ++i) {
        // Right angle at c = (a_x, b_y): the centre is ((a_x + b_x) / 2, (a_y + b_y) / 2), a
        // midpoint between two doubles when the sum's last bit is odd; c moved by up to two ulps
        // puts the centre just beside it.
        const double ax = 0.5 + in.uniform() * 0.25, ay = 0.5 + in.uniform() * 0.25;
        const double bx = ax + std::ldexp(in.integer(1, 4096), -53);
        const double by = ay + std::ldexp(in.integer(1, 4096), -53);
        double cx = ax, cy = by;
        for (int step = 0; step < i % 3; ++step) cx = std::nextafter(cx, i % 2 == 0 ? 0.0 : 1.0);
        if (!expect_same({ax, ay}, {bx, by}, {cx, cy})) break;
    }
    expect_double_double_share("fma and dekker", 2 * calls, 0.5);
}

TEST(Predicates_Constructions, DoubleDoubleStageIsCorrectlyRoundedOnMeshLikeTetrahedra) {
    // The 3D stage on small tetrahedra at magnitudes from 1e-3 to 1e6, well shaped, flat (d
    // close to the plane of abc) and nearly degenerate in one edge: every result equals the
    // exact path's, and the stage certifies nearly all of those it may take.
    Inputs in(271828);
    pr::reset_construction_stats();
    const int calls = expect_tetrahedra_correctly_rounded(
        in, {1e-3, 0.5, 1.0, 3.0, 1e3, 1e6}, {1e-9, 1e-4, 1e-1}, 3000,
        [&](double offset, double spread) { return offset + in.uniform() * spread; });
    expect_double_double_share("mesh-like 3D", calls, 0.8);
}

TEST(Predicates_Constructions, DoubleDoubleStageIsCorrectlyRoundedWhereDifferencesRound) {
    // Small tetrahedra whose coordinate differences are not doubles: around a coordinate plane
    // (coordinates of both signs, offset 0) and beside one (offsets 1e-3 to 1 with spreads up to
    // ten times the offset), well shaped, flat and with a short edge. The double-double stage on
    // the inputs themselves must equal the exact path every time and take most of them.
    Inputs in(161803);
    pr::reset_construction_stats();
    const int calls = expect_tetrahedra_correctly_rounded(
        in, {0.0, 1e-3, 0.25, 1.0}, {1e-6, 1e-2, 1.0, 10.0}, 2500,
        [&](double offset, double spread) { return offset + in.uniform(-0.5, 0.5) * spread; });
    expect_double_double_share("rounded differences 3D", calls, 0.8);
}
