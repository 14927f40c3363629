// SPDX-License-Identifier: MIT
// Tests of predicates/dot_sign_3d (against GMP rationals) and of the constructions boundary
// recovery adds to predicates/constructions: triangle_circumcenter_3d (against the existing 2D
// exact path on triangles in coordinate planes, and the equidistance of the exact value),
// triangle_circumcenter_on_plane_3d (against the triangle's own circumcentre on the plane and an
// independent exact formula off it) and point_on_segment_3d.
#include "predicates/dot_sign_3d.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>

#include "base/errors.hpp"
#include "predicates/constructions.hpp"
#include "predicates/orient3d.hpp"

namespace exactmesh::predicates {
namespace {

Sign reference_dot(const double* p, const double* a, const double* b) {
    mpq_class sum = 0;
    for (int k = 0; k < 3; ++k) sum += (mpq_class(a[k]) - p[k]) * (mpq_class(b[k]) - p[k]);
    return sgn(sum) > 0 ? Sign::Positive : sgn(sum) < 0 ? Sign::Negative : Sign::Zero;
}

/// dot_sign_3d on the points scaled by 2^600 and 2^-600 gives `expected` (case `i`).
void expect_sign_at_extreme_scales(const double* p, const double* a, const double* b, Sign expected,
                                   int i) {
    for (const int e : {600, -600}) {
        double ps[3], as[3], bs[3];
        for (int k = 0; k < 3; ++k) {
            ps[k] = std::ldexp(p[k], e);
            as[k] = std::ldexp(a[k], e);
            bs[k] = std::ldexp(b[k], e);
        }
        ASSERT_EQ(dot_sign_3d(ps, as, bs), expected) << i << " 2^" << e;
    }
}

TEST(Predicates_DotSign3d, AgreesWithRationalsOnRandomAndNearSphericalPoints) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-1, 1);
    int zeros = 0;
    for (int i = 0; i < 20000; ++i) {
        double p[3], a[3], b[3];
        for (int k = 0; k < 3; ++k) {
            a[k] = u(rng);
            b[k] = u(rng);
            p[k] = u(rng);
        }
        if (i % 2 == 1) {
            // p on (or an ulp off) the diametral sphere: the point a + (b - a) rotated about
            // the midpoint in the plane z = const, built from integers so it is exact.
            const int m = i % 7 + 1;
            const double aa[3] = {double(-m), 0, 1}, bb[3] = {double(m), 0, 1};
            const double pp[3] = {0, std::nextafter(double(m), i % 4 == 1 ? 0.0 : 1e9), 1};
            std::copy(aa, aa + 3, a);
            std::copy(bb, bb + 3, b);
            std::copy(pp, pp + 3, p);
            if (i % 4 == 3) p[1] = double(m);
        }
        const Sign expected = reference_dot(p, a, b);
        zeros += expected == Sign::Zero;
        ASSERT_EQ(dot_sign_3d(p, a, b), expected) << i;
        expect_sign_at_extreme_scales(p, a, b, expected, i);
        if (::testing::Test::HasFatalFailure()) return;
    }
    EXPECT_GT(zeros, 0);
}

TEST(Predicates_DotSign3d, NearRightAnglesWithInexactDifferencesAgreeWithRationals) {
    // b - p nearly perpendicular to a - p, the differences rounded (p far from a and b in
    // magnitude, or a tiny offset): the filter abstains and the expansion stage decides; then
    // the same inputs at 2^600 and 2^-600 (GMP).
    std::mt19937_64 rng(9);
    std::uniform_real_distribution<double> u(-1, 1);
    int undecided = 0;
    for (int i = 0; i < 4000; ++i) {
        double p[3], a[3], b[3];
        for (int k = 0; k < 3; ++k) {
            p[k] = u(rng) * (i % 3 == 0 ? 0x1p-40 : 1.0);
            a[k] = u(rng);
        }
        const double r[3] = {u(rng), u(rng), u(rng)};
        const double d[3] = {a[0] - p[0], a[1] - p[1], a[2] - p[2]};
        const double v[3] = {d[1] * r[2] - d[2] * r[1], d[2] * r[0] - d[0] * r[2],
                             d[0] * r[1] - d[1] * r[0]};
        for (int k = 0; k < 3; ++k) b[k] = p[k] + v[k];
        if (i % 2 == 1) b[i % 3] = std::nextafter(b[i % 3], i % 4 == 1 ? -2.0 : 2.0);
        const Sign expected = reference_dot(p, a, b);
        undecided += !dot_sign_3d_filter(p, a, b).has_value();
        ASSERT_EQ(dot_sign_3d(p, a, b), expected) << i;
        expect_sign_at_extreme_scales(p, a, b, expected, i);
        if (::testing::Test::HasFatalFailure()) return;
    }
    EXPECT_GT(undecided, 100);  // the cases reach the exact stages
}

TEST(Predicates_DotSign3d, TheFilterAgreesWithRationalsAndDecidesMostRandomInputs) {
    std::mt19937_64 rng(8);
    std::uniform_real_distribution<double> u(-1, 1);
    const int n = 4000;
    int decided = 0;
    for (int i = 0; i < n; ++i) {
        double p[3], a[3], b[3];
        for (int k = 0; k < 3; ++k) {
            p[k] = u(rng);
            a[k] = u(rng);
            b[k] = u(rng);
        }
        const Sign expected = reference_dot(p, a, b);
        for (const int e : {0, 600, -600}) {
            double ps[3], as[3], bs[3];
            for (int k = 0; k < 3; ++k) {
                ps[k] = std::ldexp(p[k], e);
                as[k] = std::ldexp(a[k], e);
                bs[k] = std::ldexp(b[k], e);
            }
            const auto f = dot_sign_3d_filter(ps, as, bs);
            if (f) {
                ASSERT_EQ(*f, expected) << i << " 2^" << e;
            }
            if (f && e == 0) ++decided;
        }
    }
    EXPECT_GE(decided, n * 95 / 100);
    // Outside the window (a nonzero difference below 2^-400 of the largest) the filter abstains
    // and the rationals decide; an exact tie (Thales) is never the filter's.
    const double p[3] = {0, 0, 0}, a[3] = {1, 0, 0}, b[3] = {0x1p-450, 1, 0};
    EXPECT_FALSE(dot_sign_3d_filter(p, a, b));
    EXPECT_EQ(dot_sign_3d(p, a, b), Sign::Positive);
    const double q[3] = {0, 4, 0}, l[3] = {-5, 0, 0}, r[3] = {5, 0, 0};
    const double on[3] = {3, 4, 0};
    EXPECT_FALSE(dot_sign_3d_filter(on, l, r));
    EXPECT_EQ(dot_sign_3d(on, l, r), Sign::Zero);
    EXPECT_EQ(dot_sign_3d(q, l, r), Sign::Negative);
}

TEST(Predicates_TriangleCircumcenter3d, MatchesTheExact2dCircumcenterInCoordinatePlanes) {
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(-10, 10);
    for (int i = 0; i < 300; ++i) {
        const double a2[2] = {u(rng), u(rng)}, b2[2] = {u(rng), u(rng)}, c2[2] = {u(rng), u(rng)};
        const double level = u(rng);
        const std::array<double, 2> expected = circumcenter_exact(a2, b2, c2);
        for (int drop = 0; drop < 3; ++drop) {
            // The triangle in the plane (coordinate drop) = level, with the 2D coordinates in
            // the two others: the same exact circumcenter, so the same rounded one.
            double a[3], b[3], c[3];
            const int i1 = (drop + 1) % 3, i2 = (drop + 2) % 3;
            a[drop] = b[drop] = c[drop] = level;
            a[i1] = a2[0], a[i2] = a2[1], b[i1] = b2[0], b[i2] = b2[1], c[i1] = c2[0],
            c[i2] = c2[1];
            const std::array<double, 3> center = triangle_circumcenter_3d(a, b, c);
            EXPECT_EQ(center[static_cast<unsigned>(i1)], expected[0]) << i;
            EXPECT_EQ(center[static_cast<unsigned>(i2)], expected[1]) << i;
            EXPECT_EQ(center[static_cast<unsigned>(drop)], level) << i;
            for (const int e : {600, -600}) {  // the same point scaled by 2^e
                double as[3], bs[3], cs[3];
                for (int k = 0; k < 3; ++k) {
                    as[k] = std::ldexp(a[k], e);
                    bs[k] = std::ldexp(b[k], e);
                    cs[k] = std::ldexp(c[k], e);
                }
                const std::array<double, 3> scaled = triangle_circumcenter_3d(as, bs, cs);
                for (unsigned k = 0; k < 3; ++k) EXPECT_EQ(scaled[k], std::ldexp(center[k], e));
            }
        }
    }
    // A plane through -0: the coordinate comes back as +0, like every exact zero.
    const double a[3] = {1, -0.0, 0}, b[3] = {3, -0.0, 1}, c[3] = {1, -0.0, 4};
    const std::array<double, 3> center = triangle_circumcenter_3d(a, b, c);
    EXPECT_FALSE(std::signbit(center[1]));
    EXPECT_EQ(center[1], 0.0);
    EXPECT_EQ(center[0], 1.25);  // equidistant from (1, 0), (3, 1), (1, 4) in (x, z): (5/4, 2)
    EXPECT_EQ(center[2], 2.0);
    const double d[3] = {2, 5, 2}, e[3] = {4, 5, 4}, f[3] = {7, 5, 7};
    EXPECT_THROW(triangle_circumcenter_3d(d, e, f), GeometryError);  // collinear in the plane
}

TEST(Predicates_TriangleCircumcenter3d, ExactOnATiltedTriangleAndScalesByPowersOfTwo) {
    // (0,0,0), (2,0,2), (0,2,2): in the plane z = x + y, at squared distance 24/9 from all
    // three, the circumcenter is (2/3, 2/3, 4/3), each coordinate rounded once.
    const double a[3] = {0, 0, 0}, b[3] = {2, 0, 2}, c[3] = {0, 2, 2};
    const auto center = triangle_circumcenter_3d(a, b, c);
    EXPECT_EQ(center[0], 2.0 / 3.0);
    EXPECT_EQ(center[1], 2.0 / 3.0);
    EXPECT_EQ(center[2], 4.0 / 3.0);
    for (const int e : {600, -600}) {
        double as[3], bs[3], cs[3];
        for (int k = 0; k < 3; ++k) {
            as[k] = std::ldexp(a[k], e);
            bs[k] = std::ldexp(b[k], e);
            cs[k] = std::ldexp(c[k], e);
        }
        const auto scaled = triangle_circumcenter_3d(as, bs, cs);
        for (unsigned k = 0; k < 3; ++k) EXPECT_EQ(scaled[k], std::ldexp(center[k], e));
    }
    const double d[3] = {1, 1, 1};
    EXPECT_THROW(triangle_circumcenter_3d(a, d, d), GeometryError);
}

/// Whether r is the double nearest to x (no neighbour of r is nearer).
bool nearest_double(double r, const mpq_class& x) {
    const mpq_class error = abs(mpq_class(r) - x);
    return error <= abs(mpq_class(std::nextafter(r, -INFINITY)) - x) &&
           error <= abs(mpq_class(std::nextafter(r, INFINITY)) - x);
}

/// The point of the plane p + s (q - p) + t (r - p) equidistant from a, b, c, exactly: a 2x2
/// system in (s, t), independent of the construction's 3x3 one.
std::array<mpq_class, 3> reference_on_plane(const double* a, const double* b, const double* c,
                                            const double* p, const double* q, const double* r) {
    mpq_class u[3], v[3], e[3], f[3], pc[3];
    for (int k = 0; k < 3; ++k) {
        u[k] = mpq_class(a[k]) - c[k];
        v[k] = mpq_class(b[k]) - c[k];
        e[k] = mpq_class(q[k]) - p[k];
        f[k] = mpq_class(r[k]) - p[k];
        pc[k] = mpq_class(p[k]) - c[k];
    }
    const auto dot = [](const mpq_class* x, const mpq_class* y) -> mpq_class {
        return x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
    };
    // 2 (pc + s e + t f) . u = u . u, and the same with v.
    const mpq_class m00 = 2 * dot(e, u), m01 = 2 * dot(f, u), m10 = 2 * dot(e, v),
                    m11 = 2 * dot(f, v);
    const mpq_class r0 = dot(u, u) - 2 * dot(pc, u), r1 = dot(v, v) - 2 * dot(pc, v);
    const mpq_class det = m00 * m11 - m01 * m10;
    const mpq_class s = (r0 * m11 - m01 * r1) / det, t = (m00 * r1 - r0 * m10) / det;
    return {mpq_class(p[0] + s * e[0] + t * f[0]), mpq_class(p[1] + s * e[1] + t * f[1]),
            mpq_class(p[2] + s * e[2] + t * f[2])};
}

TEST(Predicates_TriangleCircumcenterOnPlane3d, CircumcentreOnThePlaneAndCorrectlyRoundedOffIt) {
    std::mt19937_64 rng(11);
    std::uniform_int_distribution<int> grid(-1 << 20, 1 << 20);
    // Points of the plane z = x + y on a grid of 2^-16 (every sum exact).
    const auto on_plane = [&](double* x) {
        x[0] = std::ldexp(grid(rng), -16);
        x[1] = std::ldexp(grid(rng), -16);
        x[2] = x[0] + x[1];
    };
    for (int i = 0; i < 200; ++i) {
        double a[3], b[3], c[3], p[3], q[3], r[3];
        for (double* x : {a, b, c, p, q, r}) on_plane(x);
        if (orient3d(a, b, c, p) != Sign::Zero) ADD_FAILURE() << "not coplanar";
        // On the plane: the triangle's own circumcentre, rounded the same.
        const auto center = triangle_circumcenter_on_plane_3d(a, b, c, p, q, r);
        EXPECT_EQ(center, triangle_circumcenter_3d(a, b, c)) << i;
        // Corners rounded off the plane by an ulp or a few: the exact point of the plane,
        // rounded once (against an independent formula), and scaled by 2^+-600 exactly.
        for (double* x : {a, b, c}) {
            x[2] = std::nextafter(x[2], (i & 1) ? INFINITY : -INFINITY);
            x[0] = std::nextafter(std::nextafter(x[0], INFINITY), INFINITY);
        }
        const auto moved = triangle_circumcenter_on_plane_3d(a, b, c, p, q, r);
        const auto exact = reference_on_plane(a, b, c, p, q, r);
        for (unsigned k = 0; k < 3; ++k) EXPECT_TRUE(nearest_double(moved[k], exact[k])) << i;
        for (const int e : {600, -600}) {
            double s[6][3];
            const double* in[6] = {a, b, c, p, q, r};
            for (int j = 0; j < 6; ++j)
                for (int k = 0; k < 3; ++k) s[j][k] = std::ldexp(in[j][k], e);
            const auto scaled =
                triangle_circumcenter_on_plane_3d(s[0], s[1], s[2], s[3], s[4], s[5]);
            for (unsigned k = 0; k < 3; ++k) EXPECT_EQ(scaled[k], std::ldexp(moved[k], e)) << i;
        }
    }
    // Collinear plane points, a triangle standing on the plane (flat projection), non-finite.
    const double o[3] = {0, 0, 0}, x1[3] = {1, 0, 0}, x2[3] = {2, 0, 0}, y1[3] = {0, 1, 0},
                 z1[3] = {0, 0, 1}, nan[3] = {NAN, 0, 0};
    EXPECT_THROW(triangle_circumcenter_on_plane_3d(o, y1, z1, o, x1, x2), GeometryError);
    EXPECT_THROW(triangle_circumcenter_on_plane_3d(o, x1, z1, o, x1, y1), GeometryError);
    EXPECT_THROW(triangle_circumcenter_on_plane_3d(nan, x1, z1, o, x1, y1), GeometryError);
    const auto flat = triangle_circumcenter_on_plane_3d(o, x1, y1, o, x1, y1);
    EXPECT_EQ(flat, (std::array<double, 3>{0.5, 0.5, 0}));
}

TEST(Predicates_PointOnSegment3d, CorrectlyRoundedAndScaleInvariant) {
    const double p[3] = {1, 0, -3}, q[3] = {2, 0x1p-60, 5};
    const auto m = point_on_segment_3d(p, q, 0.5);
    EXPECT_EQ(m[0], 1.5);
    EXPECT_EQ(m[1], 0x1p-61);
    EXPECT_EQ(m[2], 1.0);
    // 1/3 of the way: the rational 1 + t (2 - 1) rounded once.
    const double t = 1.0 / 3.0;
    const auto r = point_on_segment_3d(p, q, t);
    const mpq_class exact = mpq_class(1) + mpq_class(t);
    const mpq_class error = abs(mpq_class(r[0]) - exact);
    EXPECT_LE(error, abs(mpq_class(std::nextafter(r[0], 0.0)) - exact));
    EXPECT_LE(error, abs(mpq_class(std::nextafter(r[0], 9.0)) - exact));
    EXPECT_EQ(r[1], 0x1p-60 * t);  // exact: a power of two times t
    for (const int e : {600, -600}) {
        double ps[3], qs[3];
        for (int k = 0; k < 3; ++k) {
            ps[k] = std::ldexp(p[k], e);
            qs[k] = std::ldexp(q[k], e);
        }
        const auto s = point_on_segment_3d(ps, qs, t);
        for (unsigned k = 0; k < 3; ++k) EXPECT_EQ(s[k], std::ldexp(r[k], e));
    }
}

/// Split points certified exact by error-free transformations (an axis-parallel coordinate,
/// dyadic ends and parameters) and ones that need the rational path, near the fast path's range
/// guards (2^-450, 2^500) too: each coordinate the correct rounding of p + t (q - p), 0 as +0.
TEST(Predicates_PointOnSegment3d, ExactShortcutAgreesWithRationalRounding) {
    std::mt19937_64 random(15);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::uniform_int_distribution<int> pick(0, 5);
    const auto check = [](const double* p, const double* q, double t) {
        const auto r = point_on_segment_3d(p, q, t);
        for (unsigned k = 0; k < 3; ++k) {
            const mpq_class exact = mpq_class(p[k]) + mpq_class(t) * (mpq_class(q[k]) - p[k]);
            const mpq_class error = abs(mpq_class(r[k]) - exact);
            EXPECT_LE(error, abs(mpq_class(std::nextafter(r[k], -INFINITY)) - exact));
            EXPECT_LE(error, abs(mpq_class(std::nextafter(r[k], INFINITY)) - exact));
            if (r[k] == 0) {
                EXPECT_FALSE(std::signbit(r[k]));
            }
        }
    };
    for (int i = 0; i < 20000; ++i) {
        double p[3], q[3];
        const int scale = std::array<int, 6>{0, -449, -451, 499, 501, -40}[pick(random) % 6];
        for (int k = 0; k < 3; ++k) {
            p[k] = std::ldexp(unit(random), scale);
            switch (pick(random)) {
                case 0:
                    q[k] = p[k];
                    break;  // parallel
                case 1:
                    q[k] = std::ldexp(std::round(unit(random) * 64), scale - 6);
                    break;
                case 2:
                    q[k] = -p[k];
                    break;  // through 0
                default:
                    q[k] = std::ldexp(unit(random), scale);
                    break;
            }
            if (pick(random) == 0) p[k] = std::ldexp(std::round(unit(random) * 64), scale - 6);
        }
        const double t =
            std::array<double, 6>{0.5, 0.25, 0.75, 1.0 / 3.0, 0.0, unit(random)}[pick(random) % 6];
        check(p, q, std::fabs(t));
    }
    const double zero[3] = {-0.0, 0.0, -0.0}, minus[3] = {-1.0, -0.0, 0x1p-1074};
    check(zero, zero, 0.5);
    check(minus, zero, 1.0);
    check(zero, minus, 0.5);
}

}  // namespace
}  // namespace exactmesh::predicates
