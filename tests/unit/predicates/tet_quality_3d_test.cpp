// SPDX-License-Identifier: MIT
// Tests of predicates/tet_quality_3d: known values, exact ties, and the same signs for the
// points scaled by 2^600 and 2^-600 (the bounds scaled with them); the double filters against
// GMP rationals on random, near-tie and scaled inputs, and how often they decide.
#include "predicates/tet_quality_3d.hpp"

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <functional>
#include <optional>
#include <random>
#include <vector>

#include "predicates/dot_sign_3d.hpp"
#include "predicates/relative_filter.hpp"
#include "predicates/stats.hpp"
#include "tests/support/test_scale.hpp"

namespace exactmesh::predicates {
namespace {

using P = std::array<double, 3>;

P scaled(P p, int e) {
    for (double& x : p) x = std::ldexp(x, e);
    return p;
}

TEST(Predicates_TetQuality3d, RadiusEdgeOfTheCornerTetrahedron) {
    // (0,0,0), (1,0,0), (0,1,0), (0,0,1): R = sqrt(3)/2, shortest edge 1.
    for (const int e : {0, 600, -600}) {
        const P a = scaled({0, 0, 0}, e), b = scaled({1, 0, 0}, e), c = scaled({0, 1, 0}, e),
                d = scaled({0, 0, 1}, e);
        EXPECT_EQ(compare_radius_edge_3d(a.data(), b.data(), c.data(), d.data(), 0.866),
                  Sign::Positive);
        EXPECT_EQ(compare_radius_edge_3d(a.data(), b.data(), c.data(), d.data(), 0.8661),
                  Sign::Negative);
        EXPECT_EQ(compare_radius_edge_3d(b.data(), a.data(), c.data(), d.data(), 0.866),
                  Sign::Positive);  // either orientation
    }
}

TEST(Predicates_TetQuality3d, RadiusEdgeTie) {
    // (0,0,0), (2,0,0), (0,2,0), (0,0,1)... a box corner 2 x 2 x 1: R^2 = (4 + 4 + 1) / 4 =
    // 9/4, shortest edge 1: the ratio is exactly 1.5.
    for (const int e : {0, 600, -600}) {
        const P a = scaled({0, 0, 0}, e), b = scaled({2, 0, 0}, e), c = scaled({0, 2, 0}, e),
                d = scaled({0, 0, 1}, e);
        EXPECT_EQ(compare_radius_edge_3d(a.data(), b.data(), c.data(), d.data(), 1.5), Sign::Zero);
        EXPECT_EQ(compare_radius_edge_3d(a.data(), b.data(), c.data(), d.data(),
                                         std::nextafter(1.5, 2.0)),
                  Sign::Negative);
    }
}

TEST(Predicates_TetQuality3d, VolumeTie) {
    const P a{0, 0, 0}, b{3, 0, 0}, c{0, 2, 0}, d{0, 0, 1};  // volume exactly 1
    EXPECT_EQ(compare_tet_volume_3d(a.data(), b.data(), c.data(), d.data(), 1.0), Sign::Zero);
    EXPECT_EQ(compare_tet_volume_3d(a.data(), c.data(), b.data(), d.data(), 1.0), Sign::Zero);
    EXPECT_EQ(compare_tet_volume_3d(a.data(), b.data(), c.data(), d.data(), 0.999), Sign::Positive);
    for (const int e : {300, -300}) {  // the volume scales by 2^(3e)
        const P sa = scaled(a, e), sb = scaled(b, e), sc = scaled(c, e), sd = scaled(d, e);
        EXPECT_EQ(compare_tet_volume_3d(sa.data(), sb.data(), sc.data(), sd.data(),
                                        std::ldexp(1.0, 3 * e)),
                  Sign::Zero);
    }
}

TEST(Predicates_TetQuality3d, EquatorialSphere) {
    // Triangle (0,0,0), (2,0,0), (0,2,0): centre (1,1,0), radius^2 2.
    for (const int e : {0, 600, -600}) {
        const P a = scaled({0, 0, 0}, e), b = scaled({2, 0, 0}, e), c = scaled({0, 2, 0}, e);
        auto at = [&](P p) {
            const P q = scaled(p, e);
            return in_equatorial_sphere_3d(q.data(), a.data(), b.data(), c.data());
        };
        EXPECT_EQ(at({1, 1, 1}), Sign::Positive);
        EXPECT_EQ(at({1, 1, 1.41421356}), Sign::Positive);
        EXPECT_EQ(at({1, 2, 1}), Sign::Zero);
        EXPECT_EQ(at({2, 2, 0}), Sign::Zero);
        EXPECT_EQ(at({1, 1, 1.5}), Sign::Negative);
        EXPECT_EQ(at({-0.5, 0, 0}), Sign::Negative);
    }
}

TEST(Predicates_TetQuality3d, AngleBelowSixtyDegreesAndLengths) {
    const P o{0, 0, 0}, x{1, 0, 0};
    const P q45{1, 1, 0}, q90{0, 1, 0}, q63{1, 2, 0}, q120{-1, 2, 0};
    EXPECT_EQ(compare_angle_60_3d(o.data(), x.data(), q45.data()), Sign::Positive);
    EXPECT_EQ(compare_angle_60_3d(o.data(), x.data(), q90.data()), Sign::Negative);
    EXPECT_EQ(compare_angle_60_3d(o.data(), x.data(), q63.data()), Sign::Negative);
    EXPECT_EQ(compare_angle_60_3d(o.data(), x.data(), q120.data()), Sign::Negative);
    const P a{0, 0, 0}, b{3, 4, 0}, c{1, 1, 1}, d{1, 1, 6};
    EXPECT_EQ(compare_lengths_3d(a.data(), b.data(), c.data(), d.data()), Sign::Zero);
    const P tiny_b = scaled(b, -600), tiny_d = scaled({1, 1, 1.0000000001}, -600);
    EXPECT_EQ(compare_lengths_3d(a.data(), tiny_b.data(), a.data(), tiny_d.data()), Sign::Positive);
}

// GMP-rational references, written from the definitions (independent of the library's code).
using Q3 = std::array<mpq_class, 3>;

Q3 rational(const P& p) {
    return {mpq_class(p[0]), mpq_class(p[1]), mpq_class(p[2])};
}
Q3 minus(const Q3& a, const Q3& b) {
    return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
mpq_class dot(const Q3& a, const Q3& b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
Q3 cross(const Q3& a, const Q3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Sign sign_q(const mpq_class& x) {
    return sgn(x) > 0 ? Sign::Positive : sgn(x) < 0 ? Sign::Negative : Sign::Zero;
}

Sign reference_radius_edge(const P& a, const P& b, const P& c, const P& d, double bound) {
    const Q3 qa = rational(a), qb = rational(b), qc = rational(c), qd = rational(d);
    const Q3 u = minus(qb, qa), v = minus(qc, qa), w = minus(qd, qa);
    // The circumcentre o - a solves 2 (u, v, w) . x = (|u|^2, |v|^2, |w|^2); by Cramer's rule
    // x = (|u|^2 v x w + |v|^2 w x u + |w|^2 u x v) / (2 det).
    const mpq_class det = dot(u, cross(v, w));
    const Q3 vw = cross(v, w), wu = cross(w, u), uv = cross(u, v);
    Q3 x;
    for (int k = 0; k < 3; ++k)
        x[k] = (dot(u, u) * vw[k] + dot(v, v) * wu[k] + dot(w, w) * uv[k]) / (2 * det);
    const mpq_class r2 = dot(x, x);
    mpq_class l2 = dot(u, u);
    for (const Q3& e : {v, w, minus(qc, qb), minus(qd, qb), minus(qd, qc)})
        l2 = std::min(l2, dot(e, e));
    const mpq_class b2 = mpq_class(bound) * mpq_class(bound);
    return sign_q(r2 - b2 * l2);
}

Sign reference_volume(const P& a, const P& b, const P& c, const P& d, double max_volume) {
    const Q3 qa = rational(a);
    const mpq_class det =
        dot(minus(rational(b), qa), cross(minus(rational(c), qa), minus(rational(d), qa)));
    return sign_q(abs(det) / 6 - mpq_class(max_volume));
}

Sign reference_equatorial(const P& p, const P& a, const P& b, const P& c) {
    // The centre o = a + s u + t v with (o - a) . u = |u|^2 / 2, (o - a) . v = |v|^2 / 2.
    const Q3 qa = rational(a), u = minus(rational(b), qa), v = minus(rational(c), qa);
    const mpq_class uu = dot(u, u), uv = dot(u, v), vv = dot(v, v);
    const mpq_class den = 2 * (uu * vv - uv * uv);
    const mpq_class s = (uu * vv - vv * uv) / den, t = (uu * vv - uu * uv) / den;
    Q3 o;
    for (int k = 0; k < 3; ++k) o[k] = qa[k] + s * u[k] + t * v[k];
    const Q3 ra = minus(qa, o), rp = minus(rational(p), o);
    return sign_q(dot(ra, ra) - dot(rp, rp));
}

Sign reference_angle_60(const P& apex, const P& p, const P& q) {
    const Q3 o = rational(apex), u = minus(rational(p), o), v = minus(rational(q), o);
    const mpq_class uv = dot(u, v);
    if (sgn(uv) <= 0) return Sign::Negative;
    return sign_q(4 * uv * uv - dot(u, u) * dot(v, v));
}

Sign reference_lengths(const P& a, const P& b, const P& c, const P& d) {
    const Q3 u = minus(rational(b), rational(a)), v = minus(rational(d), rational(c));
    return sign_q(dot(u, u) - dot(v, v));
}

/// One test case of each kind: its points, its bound, and how the bound scales with 2^e.
struct Case {
    enum Kind { RadiusEdge, Volume, Equatorial, Angle60, Lengths, DotSign } kind;
    std::array<P, 4> points;
    double bound = 0;
};

Sign reference(const Case& c) {
    const auto& x = c.points;
    switch (c.kind) {
        case Case::RadiusEdge:
            return reference_radius_edge(x[0], x[1], x[2], x[3], c.bound);
        case Case::Volume:
            return reference_volume(x[0], x[1], x[2], x[3], c.bound);
        case Case::Equatorial:
            return reference_equatorial(x[0], x[1], x[2], x[3]);
        case Case::Angle60:
            return reference_angle_60(x[0], x[1], x[2]);
        case Case::Lengths:
            return reference_lengths(x[0], x[1], x[2], x[3]);
        case Case::DotSign: {
            const Q3 p = rational(x[0]);
            return sign_q(dot(minus(rational(x[1]), p), minus(rational(x[2]), p)));
        }
    }
    return Sign::Zero;
}

Sign evaluate(const Case& c) {
    const auto& x = c.points;
    switch (c.kind) {
        case Case::RadiusEdge:
            return compare_radius_edge_3d(x[0].data(), x[1].data(), x[2].data(), x[3].data(),
                                          c.bound);
        case Case::Volume:
            return compare_tet_volume_3d(x[0].data(), x[1].data(), x[2].data(), x[3].data(),
                                         c.bound);
        case Case::Equatorial:
            return in_equatorial_sphere_3d(x[0].data(), x[1].data(), x[2].data(), x[3].data());
        case Case::Angle60:
            return compare_angle_60_3d(x[0].data(), x[1].data(), x[2].data());
        case Case::Lengths:
            return compare_lengths_3d(x[0].data(), x[1].data(), x[2].data(), x[3].data());
        case Case::DotSign:
            return dot_sign_3d(x[0].data(), x[1].data(), x[2].data());
    }
    return Sign::Zero;
}

std::optional<Sign> filter(const Case& c) {
    const auto& x = c.points;
    switch (c.kind) {
        case Case::RadiusEdge:
            return compare_radius_edge_3d_filter(x[0].data(), x[1].data(), x[2].data(), x[3].data(),
                                                 c.bound);
        case Case::Volume:
            return compare_tet_volume_3d_filter(x[0].data(), x[1].data(), x[2].data(), x[3].data(),
                                                c.bound);
        case Case::Equatorial:
            return in_equatorial_sphere_3d_filter(x[0].data(), x[1].data(), x[2].data(),
                                                  x[3].data());
        case Case::Angle60:
            return compare_angle_60_3d_filter(x[0].data(), x[1].data(), x[2].data());
        case Case::Lengths:
            return compare_lengths_3d_filter(x[0].data(), x[1].data(), x[2].data(), x[3].data());
        case Case::DotSign:
            return dot_sign_3d_filter(x[0].data(), x[1].data(), x[2].data());
    }
    return std::nullopt;
}

/// The case scaled by 2^e: points by 2^e, a volume bound by 2^(3e), a radius-edge bound not.
Case scaled_case(Case c, int e) {
    for (P& p : c.points) p = scaled(p, e);
    if (c.kind == Case::Volume) c.bound = std::ldexp(c.bound, 3 * e);
    return c;
}

constexpr const char* kKindNames[] = {"radius-edge", "volume",  "equatorial",
                                      "angle-60",    "lengths", "dot-sign"};

/// Every case and its scalings by 2^e, e in {-600, -300, -7, 0, 5, 300, 600} (volumes to
/// 2^(+-300)): the public test and
/// (when it decides) the filter against the reference; returns how many unscaled cases the
/// filter decided.
int check_cases(const std::vector<Case>& cases) {
    int decided = 0;
    for (std::size_t i = 0; i < cases.size(); ++i) {
        const Sign expected = reference(cases[i]);
        for (const int e : {0, -600, -300, -7, 5, 300, 600}) {
            // A volume scales by 2^(3e): 2^(+-1800) is no double, so volumes go to 2^(+-300).
            if (cases[i].kind == Case::Volume && std::abs(e) > 300) continue;
            const Case c = scaled_case(cases[i], e);
            const auto f = filter(c);
            if (f) {
                EXPECT_EQ(*f, expected) << kKindNames[c.kind] << " case " << i << " at 2^" << e;
            }
            if (f && e == 0) ++decided;
            EXPECT_EQ(evaluate(c), expected)
                << kKindNames[c.kind] << " case " << i << " at 2^" << e;
            if (::testing::Test::HasFailure()) return decided;
        }
    }
    return decided;
}

int case_count(int base) {
    return std::max(20, static_cast<int>(base * exactmesh::testing::test_scale()));
}

P random_point(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> unit(-1, 1);
    return {unit(rng), unit(rng), unit(rng)};
}

TEST(Predicates_TetQuality3d, FiltersAgreeWithRationalsAndDecideMostRandomInputs) {
    std::mt19937_64 rng(15);
    std::uniform_real_distribution<double> ratio(0.6, 3.0), volume(0.0, 0.4);
    const int n = case_count(400);
    for (int kind = Case::RadiusEdge; kind <= Case::DotSign; ++kind) {
        std::vector<Case> cases;
        for (int i = 0; i < n; ++i) {
            Case c{static_cast<Case::Kind>(kind),
                   {random_point(rng), random_point(rng), random_point(rng), random_point(rng)},
                   0};
            if (kind == Case::RadiusEdge) c.bound = ratio(rng);
            if (kind == Case::Volume) c.bound = volume(rng) * 0.1 + 1e-9;
            cases.push_back(c);
        }
        const int decided = check_cases(cases);
        ASSERT_FALSE(HasFailure());
        // Generic inputs: the filter decides the large majority (ties and near ties are rare).
        EXPECT_GE(decided, n * 95 / 100) << kKindNames[kind] << ": " << decided << " of " << n;
    }
}

/// x rounded to a neighbour: -1 the next double down, 0 itself, +1 the next up.
double nudged(double x, int direction) {
    if (direction == 0) return x;
    return std::nextafter(x, direction > 0 ? INFINITY : -INFINITY);
}

TEST(Predicates_TetQuality3d, FiltersAgreeWithRationalsOnExactTiesAndTheirNeighbours) {
    std::mt19937_64 rng(16);
    std::uniform_int_distribution<int> offset(-1000, 1000), nudge(-1, 1), coordinate(0, 2),
        vertex(0, 3);
    std::vector<Case> cases;
    auto translate = [&](std::array<P, 4> points, double unit) {
        // A random translation and unit (exact: small integers times a power of two), then one
        // coordinate of one point moved by an ulp or not at all.
        const P shift{double(offset(rng)), double(offset(rng)), double(offset(rng))};
        for (P& p : points)
            for (int k = 0; k < 3; ++k)
                p[static_cast<unsigned>(k)] =
                    (p[static_cast<unsigned>(k)] + shift[static_cast<unsigned>(k)]) * unit;
        double& x =
            points[static_cast<unsigned>(vertex(rng))][static_cast<unsigned>(coordinate(rng))];
        x = nudged(x, nudge(rng));
        return points;
    };
    const int n = case_count(60);
    // Radius-edge ties: the box-corner tetrahedron with edges a, b, c on the axes has R =
    // sqrt(a^2 + b^2 + c^2) / 2, l = min(a, b, c): Pythagorean quadruples give dyadic ratios.
    const std::array<std::array<double, 4>, 5> quadruples{
        {{1, 2, 2, 1.5}, {2, 3, 6, 1.75}, {1, 4, 8, 4.5}, {4, 4, 7, 1.125}, {2, 6, 9, 2.75}}};
    for (int i = 0; i < n; ++i) {
        const auto& q = quadruples[static_cast<unsigned>(i) % quadruples.size()];
        std::array<P, 4> corner{P{0, 0, 0}, P{q[0], 0, 0}, P{0, q[1], 0}, P{0, 0, q[2]}};
        std::shuffle(corner.begin(), corner.end(), rng);
        cases.push_back({Case::RadiusEdge, translate(corner, 0.25), nudged(q[3], nudge(rng))});
    }
    // Volume ties: integer tetrahedra with det divisible by 3, so that |det| / 6 is a double.
    std::uniform_int_distribution<int> small(-9, 9);
    while (cases.size() < static_cast<std::size_t>(2 * n)) {
        std::array<P, 4> t;
        for (P& p : t) p = {double(small(rng)), double(small(rng)), double(small(rng))};
        const Q3 u = minus(rational(t[1]), rational(t[0])),
                 v = minus(rational(t[2]), rational(t[0])),
                 w = minus(rational(t[3]), rational(t[0]));
        const mpq_class det = abs(dot(u, cross(v, w)));
        if (sgn(det) == 0 || det.get_num() % 3 != 0) continue;
        const double bound = mpq_class(det / 6).get_d();
        cases.push_back({Case::Volume, translate(t, 0.5), nudged(bound * 0.125, nudge(rng))});
    }
    // Equatorial sphere: right triangle a = 0, b = (2x, 0, 0), c = (0, 2y, 0) (centre (x, y, 0),
    // radius^2 x^2 + y^2) and p = centre + (i, j, k) with i^2 + j^2 + k^2 = x^2 + y^2.
    while (cases.size() < static_cast<std::size_t>(3 * n)) {
        const int x = small(rng), y = small(rng), i = small(rng), j = small(rng), k = small(rng);
        if (x == 0 || y == 0 || x * x + y * y != i * i + j * j + k * k) continue;
        std::array<P, 4> t{P{double(x + i), double(y + j), double(k)}, P{0, 0, 0}, P{2.0 * x, 0, 0},
                           P{0, 2.0 * y, 0}};
        std::shuffle(t.begin() + 1, t.end(), rng);
        cases.push_back({Case::Equatorial, translate(t, 1.0 / 1024), 0});
    }
    // 60 degrees: the equilateral triangle (s, 0, 0), (0, s, 0), (0, 0, s) and the regular
    // tetrahedron (0,0,0), (s,s,0), (s,0,s), (0,s,s), seen from any vertex.
    for (int i = 0; i < n; ++i) {
        const double s = double(1 + i % 7);
        std::array<P, 4> t = i % 2 == 0
                                 ? std::array<P, 4>{P{s, 0, 0}, P{0, s, 0}, P{0, 0, s}, P{0, 0, 0}}
                                 : std::array<P, 4>{P{0, 0, 0}, P{s, s, 0}, P{s, 0, s}, P{0, s, s}};
        std::shuffle(t.begin(), t.begin() + 3, rng);
        cases.push_back({Case::Angle60, translate(t, 0.75), 0});
    }
    // Equal lengths: Pythagorean triples against an axis segment.
    const std::array<std::array<double, 3>, 4> triples{
        {{3, 4, 5}, {5, 12, 13}, {8, 15, 17}, {20, 21, 29}}};
    for (int i = 0; i < n; ++i) {
        const auto& t = triples[static_cast<unsigned>(i) % triples.size()];
        cases.push_back(
            {Case::Lengths,
             translate({P{0, 0, 0}, P{t[0], t[1], 0}, P{1, 1, 1}, P{1, 1, 1 + t[2]}}, 0.125), 0});
        // Thales: p on the sphere with diameter ab.
        cases.push_back(
            {Case::DotSign,
             translate({P{t[0], t[1], 0}, P{-t[2], 0, 0}, P{t[2], 0, 0}, P{0, 0, 0}}, 0.5), 0});
    }
    int zeros = 0;
    for (const Case& c : cases) zeros += reference(c) == Sign::Zero;
    check_cases(cases);
    EXPECT_GT(zeros, n) << "the exact ties are kept by about a third of the cases";
}

TEST(Predicates_TetQuality3d, EquatorialSphereInACoordinatePlaneAgreesWithRationals) {
    // Four points with one coordinate equal go to the 2D incircle (not GMP): cocircular
    // lattice points (exact ties), their ulp neighbours and random points, in each coordinate
    // plane, translated, and scaled by 2^600 and 2^-600.
    std::mt19937_64 rng(18);
    std::uniform_int_distribution<int> small(-9, 9), nudge(-1, 1), which(0, 3);
    std::uniform_real_distribution<double> unit(-1, 1);
    const int n = case_count(200);
    int ties = 0, checked = 0;
    for (int i = 0; i < n; ++i) {
        std::array<std::array<double, 2>, 4> flat;  // p, a, b, c in the plane
        if (i % 2 == 0) {
            const int x = small(rng), y = small(rng);
            // Every fourth case an exact tie by construction (p = (2x, 2y), the antipode of a):
            // at the sanitizer run's small case counts random lattice points found none.
            const bool tie = i % 4 == 0;
            const int u = tie ? x : small(rng), v = tie ? y : small(rng);
            const int w = small(rng);
            if (x == 0 || y == 0) continue;
            // a = 0, b = (2x, 0), c = (0, 2y): centre (x, y); p = centre + (u, v) when on the
            // circle, else a random lattice point.
            const bool on = x * x + y * y == u * u + v * v;
            flat = {{{double(x + u), on ? double(y + v) : double(w)},
                     {0, 0},
                     {2.0 * x, 0},
                     {0, 2.0 * y}}};
            auto& coordinate =
                flat[static_cast<unsigned>(which(rng))][static_cast<unsigned>(which(rng) % 2)];
            const int step = nudge(rng);
            if (!tie) coordinate = nudged(coordinate, step);
        } else {
            for (auto& q : flat) q = {unit(rng), unit(rng)};
        }
        const int k = i % 3;
        const double level = double(small(rng)) / 8;
        for (const int e : {0, 600, -600}) {
            std::array<P, 4> t;
            for (unsigned j = 0; j < 4; ++j) {
                P q;
                q[static_cast<unsigned>(k)] = level;
                q[static_cast<unsigned>((k + 1) % 3)] = flat[j][0] + 3;
                q[static_cast<unsigned>((k + 2) % 3)] = flat[j][1] - 5;
                t[j] = scaled(q, e);
            }
            const P& a = t[1];
            const P& b = t[2];
            const P& c = t[3];
            const double* pa = a.data();
            const double* pb = b.data();
            const double* pc = c.data();
            const Sign expected = reference_equatorial(t[0], a, b, c);
            ties += expected == Sign::Zero;
            ++checked;
            EXPECT_EQ(in_equatorial_sphere_3d(t[0].data(), pa, pb, pc), expected)
                << "case " << i << " plane " << k << " scale 2^" << e;
            EXPECT_EQ(in_equatorial_sphere_3d(t[0].data(), pb, pc, pa), expected);
            EXPECT_EQ(in_equatorial_sphere_3d(t[0].data(), pb, pa, pc), expected);
        }
    }
    EXPECT_GT(checked, n);
    EXPECT_GT(ties, 0) << "some lattice points lie on their circle";
}

TEST(Predicates_TetQuality3d, EquatorialSphereOnLatticeTiesAgreesWithRationals) {
    // Lattice points on a right triangle's equatorial sphere, off its plane, with differences up
    // to the bound of the small-integer stage (2^7) and beyond it, ulp neighbours, any scale.
    std::mt19937_64 rng(19);
    std::uniform_int_distribution<int> half(1, 60), offset(-60, 60), nudge(-1, 1), which(0, 3);
    const int n = case_count(300);
    int ties = 0;
    for (int found = 0; found < n;) {
        const int x = half(rng), y = half(rng), i = offset(rng), j = offset(rng);
        const int rest = x * x + y * y - i * i - j * j;
        if (rest < 0) continue;
        const int k = static_cast<int>(std::lround(std::sqrt(double(rest))));
        if (k * k != rest) continue;
        ++found;
        // a = 0, b = (2x, 0, 0), c = (0, 2y, 0), p = (x + i, y + j, k); a shifted to (3, -5, 7).
        std::array<P, 4> t{P{double(x + i) + 3, double(y + j) - 5, double(k) + 7}, P{3, -5, 7},
                           P{2.0 * x + 3, -5, 7}, P{3, 2.0 * y - 5, 7}};
        if (found % 3 == 1) {
            auto& coordinate =
                t[static_cast<unsigned>(which(rng))][static_cast<unsigned>(which(rng) % 3)];
            coordinate = nudged(coordinate, nudge(rng));
        }
        const Sign expected = reference_equatorial(t[0], t[1], t[2], t[3]);
        ties += expected == Sign::Zero;
        for (const int e : {0, 600, -600}) {
            std::array<P, 4> s;
            for (unsigned m = 0; m < 4; ++m) s[m] = scaled(t[m], e);
            EXPECT_EQ(in_equatorial_sphere_3d(s[0].data(), s[1].data(), s[2].data(), s[3].data()),
                      expected)
                << "x " << x << " y " << y << " at 2^" << e;
            EXPECT_EQ(in_equatorial_sphere_3d(s[0].data(), s[3].data(), s[1].data(), s[2].data()),
                      expected);
        }
    }
    EXPECT_GT(ties, n / 2);
}

TEST(Predicates_TetQuality3d, FiltersAbstainOnTiesAndOutsideTheirWindow) {
    // An exact tie is never decided by a filter (it would have to answer Zero).
    const P a{0, 0, 0}, b{3, 0, 0}, c{0, 2, 0}, d{0, 0, 1};
    EXPECT_FALSE(compare_tet_volume_3d_filter(a.data(), b.data(), c.data(), d.data(), 1.0));
    const P e{2, 0, 0}, f{0, 2, 0};
    EXPECT_FALSE(compare_radius_edge_3d_filter(a.data(), e.data(), f.data(), d.data(), 1.5));
    // A difference below 2^-50 of the largest: GMP decides, rightly.
    const P near{1, 0x1p-60, 0}, far{1, 0, 0}, g{0, 0, 0}, h{0, 1, 0};
    EXPECT_FALSE(compare_lengths_3d_filter(g.data(), near.data(), g.data(), far.data()));
    EXPECT_EQ(compare_lengths_3d(g.data(), near.data(), g.data(), far.data()), Sign::Positive);
    EXPECT_FALSE(compare_angle_60_3d_filter(g.data(), near.data(), h.data()));
    // Radius-edge bounds beyond [2^-64, 2^65): GMP.
    const P t0{0, 0, 0}, t1{1, 0, 0}, t2{0, 1, 0}, t3{0, 0, 1};
    EXPECT_FALSE(
        compare_radius_edge_3d_filter(t0.data(), t1.data(), t2.data(), t3.data(), 0x1p100));
    EXPECT_EQ(compare_radius_edge_3d(t0.data(), t1.data(), t2.data(), t3.data(), 0x1p100),
              Sign::Negative);
    EXPECT_EQ(compare_radius_edge_3d(t0.data(), t1.data(), t2.data(), t3.data(), 0x1p-100),
              Sign::Positive);
    // Huge and tiny volume bounds are decided at once (or certified) without overflow.
    EXPECT_EQ(compare_tet_volume_3d_filter(t0.data(), t1.data(), t2.data(), t3.data(), 1e300),
              Sign::Negative);
    EXPECT_EQ(compare_tet_volume_3d_filter(t0.data(), t1.data(), t2.data(), t3.data(), 1e-300),
              Sign::Positive);
    EXPECT_EQ(compare_tet_volume_3d(t0.data(), t1.data(), t2.data(), t3.data(), 0x1p-1074),
              Sign::Positive);
}

/// detail::scale_differences as its scalar loops wrote it (the reference for its SSE2 form).
template <std::size_t N>
std::optional<int> scale_differences_scalar(double (&d)[N], double window_min) {
    double largest = 0;
    for (const double x : d) largest = std::max(largest, std::fabs(x));
    if (largest == 0 || !std::isfinite(largest)) return std::nullopt;
    const int shift = -std::ilogb(largest);
    for (double& x : d) {
        x = std::ldexp(x, shift);
        if (x != 0 && std::fabs(x) < window_min) return std::nullopt;
    }
    return shift;
}

template <std::size_t N>
void expect_scaled_alike(const std::array<double, N>& input, double window_min) {
    double fast[N], reference[N];
    std::copy(input.begin(), input.end(), fast);
    std::copy(input.begin(), input.end(), reference);
    const auto shift = detail::scale_differences(fast, window_min);
    const auto expected = scale_differences_scalar(reference, window_min);
    ASSERT_EQ(shift, expected);
    if (!shift) return;  // the callers drop the differences then
    for (std::size_t i = 0; i < N; ++i)
        EXPECT_EQ(std::bit_cast<std::uint64_t>(fast[i]),
                  std::bit_cast<std::uint64_t>(reference[i]));
}

template <std::size_t N>
void check_scaling_alike(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::uniform_int_distribution<int> exponent(-1074, 1023), pick(0, 11);
    const double specials[] = {0.0,      -0.0,     0x1p-1074, -0x1p-1074, 0x1p-1022,
                               0x1p1023, INFINITY, -INFINITY, NAN,        1.0};
    for (int round = 0; round < 20000; ++round) {
        std::array<double, N> d{};
        const int e = exponent(rng);
        for (double& x : d) {
            const int kind = pick(rng);
            if (kind < 8) {
                x = std::ldexp(unit(rng), std::clamp(e - kind * 8, -1074, 1023));
            } else if (kind < 10) {
                x = specials[static_cast<std::size_t>(pick(rng)) % std::size(specials)];
            } else {
                x = 0;
            }
        }
        for (const double window : {0x1p-50, 0x1p-10, 0.5}) expect_scaled_alike(d, window);
    }
}

TEST(Predicates_TetQuality3d, ScaledDifferencesMatchTheScalarLoopsBitForBit) {
    // Every filter of tet_quality_3d and dot_sign_3d starts here: the same shift, the same bits
    // (NaN skipped by the largest, infinities and windows refused alike), for the sizes in use.
    std::mt19937_64 rng(2026);
    check_scaling_alike<6>(rng);
    check_scaling_alike<9>(rng);
    check_scaling_alike<18>(rng);
    check_scaling_alike<5>(rng);
    check_scaling_alike<1>(rng);
}

TEST(Predicates_TetQuality3d, TermOperationsRoundAsTwoScalarOperations) {
    // A Term's value and permanent, however stored, are the scalar roundings: difference (d, |d|),
    // sum and product lane by lane, difference (a - b, |a| + |b| as permanents add), exact
    // scalings and negations; checked bit for bit, signed zeros and infinities included.
    std::mt19937_64 rng(77);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::uniform_int_distribution<int> exponent(-60, 60), pick(0, 15);
    const double specials[] = {0.0, -0.0, INFINITY, -INFINITY, NAN, 0x1p-1074};
    const auto draw = [&] {
        const int k = pick(rng);
        return k < 10 ? std::ldexp(unit(rng), exponent(rng)) : specials[k % 6];
    };
    // The bits, except that every NaN is one (x + (-y) carries a NaN y's sign flipped, x - y
    // not: no comparison and so no filter's answer can tell).
    const auto bits = [](double x) {
        return std::isnan(x) ? std::uint64_t{1} : std::bit_cast<std::uint64_t>(x);
    };
    for (int n = 0; n < 100000; ++n) {
        const double x = draw(), y = draw(), z = draw();
        const auto a = detail::difference(x), b = detail::difference(y);
        const auto c = detail::rounded_constant(std::fabs(z));
        ASSERT_EQ(bits(a.value()), bits(x));
        ASSERT_EQ(bits(a.permanent()), bits(std::fabs(x)));
        ASSERT_EQ(bits(c.permanent()), bits(std::fabs(z)));
        const auto sum = a + b;
        const auto difference = a - b;
        const auto product = a * b;
        const auto mixed = (a - b) * c;
        ASSERT_EQ(bits(sum.value()), bits(x + y));
        ASSERT_EQ(bits(sum.permanent()), bits(std::fabs(x) + std::fabs(y)));
        ASSERT_EQ(bits(difference.value()), bits(x - y));
        ASSERT_EQ(bits(difference.permanent()), bits(std::fabs(x) + std::fabs(y)));
        ASSERT_EQ(bits(product.value()), bits(x * y));
        ASSERT_EQ(bits(product.permanent()), bits(std::fabs(x) * std::fabs(y)));
        ASSERT_EQ(bits(mixed.value()), bits((x - y) * std::fabs(z)));
        ASSERT_EQ(bits(mixed.permanent()), bits((std::fabs(x) + std::fabs(y)) * std::fabs(z)));
        const auto four = detail::scaled(difference, 4.0);
        ASSERT_EQ(bits(four.value()), bits((x - y) * 4.0));
        ASSERT_EQ(bits(detail::signed_by(a, true).value()), bits(-x));
        ASSERT_EQ(bits(detail::signed_by(a, true).permanent()), bits(std::fabs(x)));
        ASSERT_EQ(bits(detail::signed_by(a, false).value()), bits(x));
    }
}

#if defined(EXACTMESH_PREDICATE_STATS)
TEST(Predicates_TetQuality3d, StatsCountTheFilterAndTheExactStage) {
    reset_thread_stats();
    std::mt19937_64 rng(17);
    for (int i = 0; i < 100; ++i) {
        const P a = random_point(rng), b = random_point(rng), c = random_point(rng),
                d = random_point(rng);
        compare_radius_edge_3d(a.data(), b.data(), c.data(), d.data(), 1.5);
        compare_lengths_3d(a.data(), b.data(), c.data(), d.data());
    }
    const P o{0, 0, 0}, x{3, 0, 0}, y{0, 2, 0}, z{0, 0, 1};
    compare_tet_volume_3d(o.data(), x.data(), y.data(), z.data(), 1.0);  // a tie: GMP
    const PredicateStats& s = thread_stats();
    EXPECT_EQ(s.compare_radius_edge_3d.calls, 100u);
    EXPECT_EQ(s.compare_radius_edge_3d.calls,
              s.compare_radius_edge_3d.filter + s.compare_radius_edge_3d.gmp);
    EXPECT_GE(s.compare_radius_edge_3d.filter, 95u);
    EXPECT_EQ(s.compare_lengths_3d.calls, s.compare_lengths_3d.filter + s.compare_lengths_3d.gmp);
    EXPECT_EQ(s.compare_tet_volume_3d.gmp, 1u);
}
#endif

}  // namespace
}  // namespace exactmesh::predicates
