// SPDX-License-Identifier: MIT
// Dihedral and volume-edge comparisons (angle_comparisons_3d) vs GMP-free long double values on
// well-separated cases, exact ties and the GMP path outside the filter window; quality
// statistics (quality_3d) on tetrahedra with known angles: regular, cube corner, sliver, cap;
// the radius-edge histogram, and both histograms' scale invariance at 2^+-600.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "base/errors.hpp"
#include "predicates/angle_comparisons_3d.hpp"
#include "tests/support/test_scale.hpp"
#include "triangulation/checks/quality_3d.hpp"
#include "triangulation/delaunay/bowyer_watson_3d.hpp"

namespace em = exactmesh;
namespace tri = exactmesh::triangulation;
using em::predicates::Sign;

namespace {

tri::Tetrahedralization3 single(std::vector<double> xyz) {
    tri::Tetrahedralization3 mesh;
    mesh.xyz = std::move(xyz);
    mesh.tets = {0, 1, 2, 3};
    mesh.neighbors = {tri::kNone, tri::kNone, tri::kNone, tri::kNone};
    return mesh;
}

constexpr double kRad = 180.0 / 3.14159265358979323846;

}  // namespace

TEST(Triangulation_Angles3, CubeCornerTiesAreExactAndOrderIsRight) {
    // (0,0,0), (1,0,0), (0,1,0), (0,0,1) is negatively oriented; swap two to make it positive.
    const double p0[3] = {0, 0, 0}, p1[3] = {0, 1, 0}, p2[3] = {1, 0, 0}, p3[3] = {0, 0, 1};
    const em::predicates::TetCorners t{p0, p1, p2, p3};
    // The three edges at the corner meet at right angles; the other three at acos(1/sqrt 3).
    EXPECT_EQ(em::predicates::compare_dihedral({t, 0, 1}, {t, 0, 2}), Sign::Zero);
    EXPECT_EQ(em::predicates::compare_dihedral({t, 0, 2}, {t, 0, 3}), Sign::Zero);
    EXPECT_EQ(em::predicates::compare_dihedral({t, 1, 2}, {t, 0, 1}), Sign::Negative);
    EXPECT_EQ(em::predicates::compare_dihedral({t, 0, 1}, {t, 2, 3}), Sign::Positive);
    EXPECT_NEAR(static_cast<double>(em::predicates::dihedral_radians({t, 0, 1})) * kRad, 90.0,
                1e-12);
    EXPECT_NEAR(static_cast<double>(em::predicates::dihedral_radians({t, 1, 2})) * kRad,
                std::acos(1 / std::sqrt(3.0)) * kRad, 1e-12);
    const em::predicates::Dihedral smallest = em::predicates::smallest_dihedral(t);
    EXPECT_EQ(em::predicates::compare_dihedral(smallest, {t, 1, 2}), Sign::Zero);
    const em::predicates::Dihedral largest = em::predicates::largest_dihedral(t);
    EXPECT_EQ(em::predicates::compare_dihedral(largest, {t, 0, 1}), Sign::Zero);
}

TEST(Triangulation_Angles3, AgreesWithRoundedAnglesWhenWellSeparatedAndIsAntisymmetric) {
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    int checked = 0;
    for (int i = 0; i < 20000; ++i) {
        double c[8][3];
        for (auto& p : c) {
            for (double& x : p) x = unit(rng);
        }
        // Make both positively oriented by swapping two corners when needed.
        auto orient = [](double(*q)[3]) {
            double a[3], b[3], d[3];
            for (int k = 0; k < 3; ++k) {
                a[k] = q[1][k] - q[0][k];
                b[k] = q[2][k] - q[0][k];
                d[k] = q[3][k] - q[0][k];
            }
            return -(a[0] * (b[1] * d[2] - b[2] * d[1]) + a[1] * (b[2] * d[0] - b[0] * d[2]) +
                     a[2] * (b[0] * d[1] - b[1] * d[0]));
        };
        if (orient(c) < 0) std::swap(c[0], c[1]);
        if (orient(c + 4) < 0) std::swap(c[4], c[5]);
        const em::predicates::TetCorners a{c[0], c[1], c[2], c[3]}, b{c[4], c[5], c[6], c[7]};
        const em::predicates::Dihedral x{a, static_cast<unsigned>(i % 4),
                                         static_cast<unsigned>((i % 4 + 1 + i % 3) % 4)};
        const em::predicates::Dihedral y{b, 1, 3};
        if (x.i == x.j) continue;
        const double dx = static_cast<double>(em::predicates::dihedral_radians(x)),
                     dy = static_cast<double>(em::predicates::dihedral_radians(y));
        const Sign s = em::predicates::compare_dihedral(x, y);
        EXPECT_EQ(s, -em::predicates::compare_dihedral(y, x));
        if (std::fabs(dx - dy) > 1e-9) {
            EXPECT_EQ(s, dx < dy ? Sign::Negative : Sign::Positive);
            ++checked;
        }
        const long double qa = em::predicates::volume_edge_quality(a),
                          qb = em::predicates::volume_edge_quality(b);
        const Sign q = em::predicates::compare_volume_edge(a, b);
        EXPECT_EQ(q, -em::predicates::compare_volume_edge(b, a));
        if (std::fabs(static_cast<double>(qa - qb)) > 1e-9) {
            EXPECT_EQ(q, qa < qb ? Sign::Negative : Sign::Positive);
        }
    }
    EXPECT_GT(checked, 10000);
}

TEST(Triangulation_Angles3, OutsideTheFilterWindowTheExactPathDecides) {
    // Coordinates 2^600 apart in scale: the filter window rejects them, GMP answers; the result
    // is scale-invariant, so it must equal the unit-scale answer.
    const double s = std::ldexp(1.0, 600);
    const double u0[3] = {0, 0, 0}, u1[3] = {0, 1, 0}, u2[3] = {1, 0, 0}, u3[3] = {0.3, 0.2, 1};
    const double b0[3] = {0, 0, 0}, b1[3] = {0, s, 0}, b2[3] = {s, 0, 0},
                 b3[3] = {0.3 * s, 0.2 * s, s};
    const em::predicates::TetCorners unit{u0, u1, u2, u3}, big{b0, b1, b2, b3};
    for (unsigned i = 0; i < 4; ++i) {
        for (unsigned j = i + 1; j < 4; ++j) {
            EXPECT_EQ(em::predicates::compare_dihedral({unit, i, j}, {big, i, j}), Sign::Zero);
            EXPECT_EQ(em::predicates::compare_dihedral({unit, i, j}, {unit, 0, 1}),
                      em::predicates::compare_dihedral({big, i, j}, {big, 0, 1}));
        }
    }
    EXPECT_EQ(em::predicates::compare_volume_edge(unit, big), Sign::Zero);
}

TEST(Triangulation_Quality3, RegularTetrahedronCubeCornerSliverAndCap) {
    const double h = std::sqrt(2.0 / 3.0), r = 1 / std::sqrt(3.0);
    // Regular: q = 1, every dihedral acos(1/3) = 70.53 degrees (bin 7 of 10-degree bins).
    const auto regular =
        tri::quality_stats_3d(single({r, 0, 0, -r / 2, -0.5, 0, -r / 2, 0.5, 0, 0, 0, h}));
    ASSERT_EQ(regular.tets, 1u);
    EXPECT_NEAR(regular.min_volume_edge, 1.0, 1e-12);
    EXPECT_NEAR(regular.min_dihedral_degrees, std::acos(1.0 / 3) * kRad, 1e-9);
    EXPECT_NEAR(regular.max_dihedral_degrees, std::acos(1.0 / 3) * kRad, 1e-9);
    EXPECT_EQ(regular.dihedral_histogram.size(), 18u);
    EXPECT_EQ(regular.dihedral_histogram[7], 6u);
    EXPECT_NEAR(regular.max_radius_edge, std::sqrt(6.0) / 4, 1e-12);
    EXPECT_EQ(regular.slivers, 0u);
    // Sliver: a square's corners, two opposite ones lifted by 0.02: angles near 0 and 180,
    // radius-edge about 0.71, no short edge.
    const auto sliver = tri::quality_stats_3d(single({0, 0, 0, 1, 1, 0, 1, 0, 0.02, 0, 1, 0.02}));
    EXPECT_LT(sliver.min_dihedral_degrees, 5.0);
    EXPECT_GT(sliver.max_dihedral_degrees, 175.0);
    EXPECT_LT(sliver.max_radius_edge, 1.0);
    EXPECT_EQ(sliver.slivers, 1u);
    // Cap: the apex just above the base's interior: tiny angles too, but a huge radius-edge
    // ratio (the circumsphere is enormous): not a sliver.
    const auto cap = tri::quality_stats_3d(single({0, 0, 0, 0, 1, 0, 1, 0, 0, 0.3, 0.3, 0.001}));
    EXPECT_LT(cap.min_dihedral_degrees, 5.0);
    EXPECT_GT(cap.max_radius_edge, 2.0);
    EXPECT_EQ(cap.slivers, 0u);
    // 5-degree bins and a bad width.
    tri::QualityOptions options;
    options.histogram_bin_degrees = 5;
    EXPECT_EQ(
        tri::quality_stats_3d(single({r, 0, 0, -r / 2, -0.5, 0, -r / 2, 0.5, 0, 0, 0, h}), options)
            .dihedral_histogram[14],
        6u);
    options.histogram_bin_degrees = 7;
    EXPECT_THROW(tri::quality_stats_3d(single({0, 0, 0, 0, 1, 0, 1, 0, 0, 0, 0, 1}), options),
                 em::InputError);
}

TEST(Triangulation_Quality3, RadiusEdgeHistogramBinsAndBound) {
    const double h = std::sqrt(2.0 / 3.0), r = 1 / std::sqrt(3.0);
    // Regular: sqrt(6)/4 = 0.612, bin [0.6, 0.8) of the default 0.2-wide bins up to 4.
    const auto regular =
        tri::quality_stats_3d(single({r, 0, 0, -r / 2, -0.5, 0, -r / 2, 0.5, 0, 0, 0, h}));
    ASSERT_EQ(regular.radius_edge_histogram.size(), 21u);
    EXPECT_EQ(regular.radius_edge_histogram[3], 1u);
    EXPECT_EQ(regular.over_radius_edge_bound, 0u);
    // Cube corner: circumradius sqrt(3)/2, shortest edge 1: 0.866 in [0.8, 1.0).
    const auto corner = tri::quality_stats_3d(single({0, 0, 0, 0, 1, 0, 1, 0, 0, 0, 0, 1}));
    EXPECT_EQ(corner.radius_edge_histogram[4], 1u);
    EXPECT_NEAR(corner.max_radius_edge, std::sqrt(3.0) / 2, 1e-12);
    // Cap: an enormous circumsphere: the open bin [4, inf), over the bound 2.
    const auto cap = tri::quality_stats_3d(single({0, 0, 0, 0, 1, 0, 1, 0, 0, 0.3, 0.3, 0.001}));
    EXPECT_EQ(cap.radius_edge_histogram.back(), 1u);
    EXPECT_EQ(cap.over_radius_edge_bound, 1u);
    // Flat (four coplanar corners): infinite ratio, the open bin too.
    const auto flat = tri::quality_stats_3d(single({0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0}));
    EXPECT_EQ(flat.radius_edge_histogram.back(), 1u);
    // Other bins: width 0.5 up to 1 gives [0, 0.5), [0.5, 1), [1, inf).
    tri::QualityOptions options;
    options.radius_edge_bin_width = 0.5;
    options.radius_edge_histogram_max = 1;
    options.radius_edge_bound = 0.7;
    const auto coarse =
        tri::quality_stats_3d(single({0, 0, 0, 0, 1, 0, 1, 0, 0, 0, 0, 1}), options);
    EXPECT_EQ(coarse.radius_edge_histogram, (std::vector<std::uint64_t>{0, 1, 0}));
    EXPECT_EQ(coarse.over_radius_edge_bound, 1u);
    options.radius_edge_bin_width = 0.3;  // does not divide 1
    EXPECT_THROW(tri::quality_stats_3d(single({0, 0, 0, 0, 1, 0, 1, 0, 0, 0, 0, 1}), options),
                 em::InputError);
    options.radius_edge_bin_width = -0.5;
    EXPECT_THROW(tri::quality_stats_3d(single({0, 0, 0, 0, 1, 0, 1, 0, 0, 0, 0, 1}), options),
                 em::InputError);
}

TEST(Triangulation_Quality3, HistogramsAreScaleInvariantAtTwoToThePlusMinus600) {
    // The Delaunay tetrahedralization of random points (its tetrahedra include flat-ish ones at
    // the hull) and the same mesh with every coordinate times 2^600 and 2^-600 (exact): the same
    // histograms, counts and extremes, bit for bit. Squared lengths at 2^1200 or 2^-1200 would
    // overflow or underflow a double; the rescaled corners never do.
    const auto points = static_cast<std::size_t>(std::max(50.0, 2000 * em::testing::test_scale()));
    std::mt19937_64 rng(15);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::vector<double> xyz(3 * points);
    for (double& x : xyz) x = unit(rng);
    const tri::Tetrahedralization3 mesh = tri::bowyer_watson_3d(xyz).mesh;
    ASSERT_GT(mesh.tet_count(), points);
    const tri::QualityStats3 base = tri::quality_stats_3d(mesh);
    std::uint64_t total = 0;
    for (const std::uint64_t c : base.radius_edge_histogram) total += c;
    EXPECT_EQ(total, mesh.tet_count());
    EXPECT_GT(base.over_radius_edge_bound, 0u);  // random points: needles and caps
    for (const int k : {600, -600}) {
        tri::Tetrahedralization3 scaled = mesh;
        for (double& x : scaled.xyz) x = std::ldexp(x, k);
        const tri::QualityStats3 q = tri::quality_stats_3d(scaled);
        EXPECT_EQ(q.radius_edge_histogram, base.radius_edge_histogram) << "2^" << k;
        EXPECT_EQ(q.dihedral_histogram, base.dihedral_histogram) << "2^" << k;
        EXPECT_EQ(q.over_radius_edge_bound, base.over_radius_edge_bound) << "2^" << k;
        EXPECT_EQ(q.max_radius_edge, base.max_radius_edge) << "2^" << k;
        EXPECT_EQ(q.min_dihedral_degrees, base.min_dihedral_degrees) << "2^" << k;
        EXPECT_EQ(q.slivers, base.slivers) << "2^" << k;
    }
}
