// SPDX-License-Identifier: MIT
// Tests of predicates/tet_quality_3d: known values, exact ties, and the same signs for the
// points scaled by 2^600 and 2^-600 (the bounds scaled with them).
#include "predicates/tet_quality_3d.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>

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

}  // namespace
}  // namespace exactmesh::predicates
