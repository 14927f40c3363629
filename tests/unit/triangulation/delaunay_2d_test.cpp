// SPDX-License-Identifier: MIT
// The three 2D Delaunay constructions: exact validity, identical output (same perturbation),
// degenerate inputs and bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <set>
#include <span>
#include <string>
#include <vector>

#include "base/errors.hpp"
#include "tests/support/canonical_triangles_2d.hpp"
#include "triangulation/checks/check_2d.hpp"
#include "triangulation/delaunay/bowyer_watson_2d.hpp"
#include "triangulation/delaunay/green_sibson_2d.hpp"
#include "triangulation/delaunay/tanemura_merriam_2d.hpp"

namespace em = exactmesh;
namespace tri = exactmesh::triangulation;

namespace {

using Triangles = exactmesh::testing::CanonicalTriangles;
using exactmesh::testing::canonical_triangles;

/// Every algorithm of the registry.
const std::span<const tri::Delaunay2Algorithm> kAlgorithms = tri::delaunay_2d_algorithms();
const tri::InsertionOrder kOrders[] = {tri::InsertionOrder::Given, tri::InsertionOrder::Random,
                                       tri::InsertionOrder::Brio};

bool has_duplicates(const std::vector<double>& xy) {
    std::set<std::pair<double, double>> seen;
    for (std::size_t i = 0; i < xy.size(); i += 2) {
        if (!seen.insert({xy[i], xy[i + 1]}).second) return true;
    }
    return false;
}

/// Runs every algorithm and order on xy; all outputs must pass the exact Delaunay check and
/// have the same triangle count; without duplicates they must be the same triangles.
void expect_all_agree(const std::vector<double>& xy, const std::string& label) {
    const bool duplicates = has_duplicates(xy);
    const tri::Delaunay2Result reference =
        tri::bowyer_watson_2d(xy, {tri::InsertionOrder::Given, 1});
    const Triangles expected = canonical_triangles(reference.triangles);
    for (const tri::Delaunay2Algorithm& algorithm : kAlgorithms) {
        for (const tri::InsertionOrder order : kOrders) {
            const tri::Delaunay2Result r = algorithm.build(xy, {order, 7});
            const tri::CheckReport report = tri::check_delaunay_2d(xy, r.triangles);
            ASSERT_TRUE(report.ok) << label << " " << algorithm.name << ": " << report.problem;
            ASSERT_EQ(r.triangles.size(), reference.triangles.size())
                << label << " " << algorithm.name;
            ASSERT_EQ(r.merged_into, reference.merged_into) << label << " " << algorithm.name;
            if (!duplicates) {
                ASSERT_EQ(canonical_triangles(r.triangles), expected)
                    << label << " " << algorithm.name;
            }
            // Neighbours are mutual and share the edge.
            for (std::size_t t = 0; t < r.triangles.size() / 3; ++t) {
                for (unsigned k = 0; k < 3; ++k) {
                    const tri::TriIdx u = r.neighbors[3 * t + k];
                    if (u == tri::kNone) continue;
                    const tri::VertIdx a = r.triangles[3 * t + k],
                                       b = r.triangles[3 * t + (k + 1) % 3];
                    bool found = false;
                    for (unsigned j = 0; j < 3; ++j) {
                        found = found || (r.triangles[3 * u + j] == b &&
                                          r.triangles[3 * u + (j + 1) % 3] == a &&
                                          r.neighbors[3 * u + j] == t);
                    }
                    ASSERT_TRUE(found) << label << " " << algorithm.name << ": triangle " << t;
                }
            }
        }
    }
}

}  // namespace

TEST(Triangulation_Delaunay2, AllAlgorithmsAgreeOnRandomPoints) {
    std::mt19937_64 rng(2026);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int trial = 0; trial < 20; ++trial) {
        std::vector<double> xy;
        const int n = 3 + trial * 50;
        for (int i = 0; i < 2 * n; ++i) xy.push_back(u(rng));
        expect_all_agree(xy, "uniform trial " + std::to_string(trial));
    }
}

TEST(Triangulation_Delaunay2, AllAlgorithmsAgreeOnDegenerateFamilies) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(0, 1);
    for (int trial = 0; trial < 30; ++trial) {
        const int n = 3 + trial * 5;
        std::vector<double> grid, circle, lines;
        for (int i = 0; i < n; ++i) {  // small integer grid: cocircular quadruples, duplicates
            grid.push_back(std::floor(u(rng) * 5));
            grid.push_back(std::floor(u(rng) * 5));
        }
        // Exactly cocircular: the 12 lattice points of radius 5, and duplicates of them.
        const int px[12] = {5, -5, 3, -3, 4, -4, 0, 0, 3, -3, 4, -4};
        const int py[12] = {0, 0, 4, 4, 3, 3, 5, -5, -4, -4, -3, -3};
        for (int i = 0; i < n; ++i) {
            const int k = static_cast<int>(u(rng) * 12);
            circle.push_back(px[k]);
            circle.push_back(py[k]);
        }
        for (int i = 0; i < n; ++i) {  // points on two lines, many collinear
            const double t = std::floor(u(rng) * 7);
            lines.push_back(t);
            lines.push_back(u(rng) < 0.5 ? t : 2.0);
        }
        expect_all_agree(grid, "grid trial " + std::to_string(trial));
        expect_all_agree(circle, "circle trial " + std::to_string(trial));
        expect_all_agree(lines, "lines trial " + std::to_string(trial));
    }
}

TEST(Triangulation_Delaunay2, CocircularGridIsTheSameForEveryOrder) {
    std::vector<double> xy;
    for (int i = 0; i < 25; ++i) {
        for (int j = 0; j < 25; ++j) {
            xy.push_back(i);
            xy.push_back(j);
        }
    }
    expect_all_agree(xy, "25x25 grid");
    const tri::Delaunay2Result r = tri::green_sibson_2d(xy);
    EXPECT_EQ(r.triangles.size() / 3, 2u * 625 - 96 - 2);  // 2n - h - 2, h = 96 hull points
}

TEST(Triangulation_Delaunay2, NearCollinearByUlpsIsExact) {
    std::vector<double> xy = {0.0, 0.0, 24.0, 24.0};
    for (int i = 0; i < 16; ++i) {
        for (int j = 0; j < 16; ++j) {
            xy.push_back(0.5 + i * std::ldexp(1.0, -53));
            xy.push_back(0.5 + j * std::ldexp(1.0, -53));
        }
    }
    xy.push_back(12.0);
    xy.push_back(12.0);
    expect_all_agree(xy, "near-collinear ulp grid");
}

TEST(Triangulation_Delaunay2, CollinearPointsGiveNoTriangleAndMergeDuplicates) {
    const std::vector<double> xy = {0, 0, 2, 2, 1, 1, 2, 2, 3, 3, 0, 0};
    for (const tri::Delaunay2Algorithm& algorithm : kAlgorithms) {
        const tri::Delaunay2Result r = algorithm.build(xy, {});
        EXPECT_TRUE(r.triangles.empty()) << algorithm.name;
        const std::vector<tri::VertIdx> merged = {0, 1, 2, 1, 4, 0};
        EXPECT_EQ(r.merged_into, merged) << algorithm.name;
        EXPECT_EQ(r.counters.duplicates, 2u) << algorithm.name;
    }
}

TEST(Triangulation_Delaunay2, DuplicatesMapToFirstOccurrence) {
    const std::vector<double> xy = {0, 0, 1, 0, 0, 1, 1, 0, 1, 1, 0, 0, 1, 1};
    for (const tri::Delaunay2Algorithm& algorithm : kAlgorithms) {
        for (const tri::InsertionOrder order : kOrders) {
            const tri::Delaunay2Result r = algorithm.build(xy, {order, 3});
            const std::vector<tri::VertIdx> merged = {0, 1, 2, 1, 4, 0, 4};
            EXPECT_EQ(r.merged_into, merged) << algorithm.name;
            EXPECT_EQ(r.triangles.size(), 6u) << algorithm.name;
            for (const tri::VertIdx v : r.triangles) EXPECT_EQ(r.merged_into[v], v);
        }
    }
}

TEST(Triangulation_Delaunay2, TinyAndEmptyInputs) {
    for (const tri::Delaunay2Algorithm& algorithm : kAlgorithms) {
        EXPECT_TRUE(algorithm.build(std::vector<double>{}, {}).triangles.empty());
        EXPECT_TRUE(algorithm.build(std::vector<double>{1, 2}, {}).triangles.empty());
        EXPECT_TRUE(algorithm.build(std::vector<double>{1, 2, 3, 4}, {}).triangles.empty());
        EXPECT_EQ(algorithm.build(std::vector<double>{0, 0, 1, 0, 0, 1}, {}).triangles.size(), 3u);
    }
}

TEST(Triangulation_Delaunay2, HugeAndTinyMagnitudes) {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(-1, 1);
    for (const double scale : {1e-300, 1e-150, 1e150, 1e300}) {
        std::vector<double> xy;
        for (int i = 0; i < 200; ++i) xy.push_back(u(rng) * scale);
        expect_all_agree(xy, "scale " + std::to_string(scale));
    }
}

TEST(Triangulation_Delaunay2, RejectsNonFiniteCoordinates) {
    const double bad[] = {std::numeric_limits<double>::quiet_NaN(),
                          std::numeric_limits<double>::infinity(),
                          -std::numeric_limits<double>::infinity()};
    for (const tri::Delaunay2Algorithm& algorithm : kAlgorithms) {
        for (const double value : bad) {
            const std::vector<double> xy = {0, 0, 1, 0, 0, 1, value, 0.5};
            try {
                algorithm.build(xy, {});
                FAIL() << algorithm.name << " accepted " << value;
            } catch (const em::NonFiniteCoordinate& e) {
                EXPECT_EQ(e.vertex(), 3u);
                EXPECT_NE(std::string(e.what()).find("point 3"), std::string::npos) << e.what();
            }
        }
        EXPECT_THROW(algorithm.build(std::vector<double>{0, 0, 1}, {}), em::InputError);
    }
}

TEST(Triangulation_Delaunay2, CheckRejectsNonDelaunayAndBrokenTopology) {
    // A convex quadrilateral split by the wrong diagonal.
    const std::vector<double> xy = {0, 0, 4, 0, 4, 1, 0, 1.5};
    const std::vector<tri::VertIdx> good = tri::bowyer_watson_2d(xy).triangles;
    EXPECT_TRUE(tri::check_delaunay_2d(xy, good).ok);
    const std::vector<tri::VertIdx> diagonal02 = {0, 1, 2, 0, 2, 3};
    const std::vector<tri::VertIdx> diagonal13 = {0, 1, 3, 1, 2, 3};
    const bool first_is_delaunay = tri::check_delaunay_2d(xy, diagonal02).ok;
    EXPECT_NE(first_is_delaunay, tri::check_delaunay_2d(xy, diagonal13).ok);
    const tri::CheckReport clockwise =
        tri::check_topology_2d(xy, std::vector<tri::VertIdx>{0, 2, 1, 0, 3, 2});
    EXPECT_FALSE(clockwise.ok);
    EXPECT_EQ(clockwise.triangle, 0u);
    const tri::CheckReport missing = tri::check_topology_2d(xy, std::vector<tri::VertIdx>{0, 1, 2});
    EXPECT_FALSE(missing.ok);
    EXPECT_NE(missing.problem.find("point 3"), std::string::npos) << missing.problem;
}

TEST(Triangulation_Check2, NoTrianglesPassOnlyForCollinearPoints) {
    // Three points on y = x and one off it: a triangulation must have triangles.
    const std::vector<double> off_line = {0, 0, 1, 1, 2, 2, 3, 2};
    const std::vector<tri::VertIdx> none;
    for (const tri::CheckReport& report :
         {tri::check_topology_2d(off_line, none), tri::check_delaunay_2d(off_line, none)}) {
        EXPECT_FALSE(report.ok);
        EXPECT_EQ(report.problem, "no triangles, but points 0, 1, 3 are not collinear");
        EXPECT_EQ(report.vertices, (std::vector<tri::VertIdx>{0, 1, 3}));
        EXPECT_EQ(report.triangle, tri::kNone);
    }
    // Duplicates of the first point do not count as the second one.
    const std::vector<double> repeated_first = {5, 5, 5, 5, 6, 5, 5, 6};
    const tri::CheckReport repeated = tri::check_topology_2d(repeated_first, none);
    EXPECT_FALSE(repeated.ok);
    EXPECT_EQ(repeated.vertices, (std::vector<tri::VertIdx>{0, 2, 3})) << repeated.problem;
    // Collinear points (with duplicates), fewer than three distinct points, no points: no
    // triangle is right, and that is what every algorithm returns.
    const std::vector<std::vector<double>> degenerate = {{0, 0, 2, 2, 1, 1, 2, 2, 3, 3, 0, 0},
                                                         {0, 5, 0, 1, 0, 3},
                                                         {1, 1, 1, 1, 2, 3},
                                                         {1, 1, 1, 1},
                                                         {7, 7},
                                                         {}};
    for (const std::vector<double>& xy : degenerate) {
        EXPECT_TRUE(tri::check_delaunay_2d(xy, none).ok) << xy.size();
        for (const tri::Delaunay2Algorithm& algorithm : kAlgorithms) {
            const tri::Delaunay2Result r = algorithm.build(xy, {});
            EXPECT_TRUE(r.triangles.empty()) << algorithm.name;
            EXPECT_TRUE(tri::check_delaunay_2d(xy, r.triangles).ok) << algorithm.name;
        }
    }
    // A triangulation that lost its only triangle is caught.
    const std::vector<double> three = {0, 0, 1, 0, 0, 1};
    EXPECT_TRUE(tri::check_delaunay_2d(three, tri::bowyer_watson_2d(three).triangles).ok);
    EXPECT_FALSE(tri::check_delaunay_2d(three, none).ok);
}

TEST(Triangulation_Check2, MessagesUseTheCallersNumbering) {
    // Kite: 0 (0,0), 1 (4,0), 2 (4,1), 3 (0,1.5); 1-based names are one more.
    const std::vector<double> xy = {0, 0, 4, 0, 4, 1, 0, 1.5};
    const tri::CheckNumbering one_based{1, 1};
    const tri::CheckReport clockwise =
        tri::check_topology_2d(xy, std::vector<tri::VertIdx>{0, 1, 2, 0, 3, 2}, one_based);
    EXPECT_FALSE(clockwise.ok);
    EXPECT_EQ(clockwise.triangle, 1u);  // the index stays 0-based
    EXPECT_EQ(clockwise.problem, "triangle 2 (1, 4, 3): not counter-clockwise (orient2d <= 0)");
    const tri::CheckReport zero_based =
        tri::check_topology_2d(xy, std::vector<tri::VertIdx>{0, 1, 2, 0, 3, 2});
    EXPECT_EQ(zero_based.problem, "triangle 1 (0, 3, 2): not counter-clockwise (orient2d <= 0)");

    const tri::CheckReport missing =
        tri::check_topology_2d(xy, std::vector<tri::VertIdx>{0, 1, 2}, one_based);
    EXPECT_EQ(missing.problem, "point 4 is not a vertex of any triangle");
    EXPECT_EQ(missing.vertices, (std::vector<tri::VertIdx>{3}));

    // Vertex and triangle bases are independent.
    const tri::CheckReport none = tri::check_topology_2d(xy, std::vector<tri::VertIdx>{}, {1, 0});
    EXPECT_EQ(none.problem, "no triangles, but points 1, 2, 3 are not collinear");

    // The non-Delaunay diagonal, named 1-based: the apex across the bad edge is reported.
    const std::vector<tri::VertIdx> diagonal02 = {0, 1, 2, 0, 2, 3};
    const std::vector<tri::VertIdx> diagonal13 = {0, 1, 3, 1, 2, 3};
    const std::vector<tri::VertIdx>& bad =
        tri::check_delaunay_2d(xy, diagonal02).ok ? diagonal13 : diagonal02;
    const tri::CheckReport zero = tri::check_delaunay_2d(xy, bad);
    const tri::CheckReport one = tri::check_delaunay_2d(xy, bad, {1, 1});
    ASSERT_FALSE(zero.ok);
    ASSERT_FALSE(one.ok);
    ASSERT_EQ(zero.vertices.size(), 1u);
    EXPECT_EQ(zero.triangle, one.triangle);
    EXPECT_EQ(zero.vertices, one.vertices);
    const tri::VertIdx* corners = &bad[3 * zero.triangle];
    EXPECT_EQ(one.problem,
              "triangle " + std::to_string(zero.triangle + 1) + " (" +
                  std::to_string(corners[0] + 1) + ", " + std::to_string(corners[1] + 1) + ", " +
                  std::to_string(corners[2] + 1) + "): not Delaunay, vertex " +
                  std::to_string(zero.vertices[0] + 1) + " lies inside its circumcircle");

    // Vertex numbers past 2^32 - 1 in the caller's numbering print in full.
    const tri::CheckReport out_of_range = tri::check_topology_2d(
        xy, std::vector<tri::VertIdx>{0, 1, 4'000'000'000u}, {4'000'000'000u, 0});
    EXPECT_NE(out_of_range.problem.find("8000000000"), std::string::npos) << out_of_range.problem;
}

TEST(Triangulation_Check2, RejectsABoundaryThatWindsTwice) {
    // Five points on a circle and its centre (vertex 5); the fan around the centre along the
    // pentagram 0-2-4-1-3 covers the disk twice: every triangle is counter-clockwise, each
    // directed edge is used once, every boundary turn is a left turn, every point is a vertex
    // and V - E + F = 6 - 10 + 5 = 1, yet the angle at the centre is 4 pi.
    std::vector<double> xy;
    for (int k = 0; k < 5; ++k) {
        const double angle = 2 * 3.14159265358979323846 * k / 5;
        xy.push_back(std::cos(angle));
        xy.push_back(std::sin(angle));
    }
    xy.push_back(0);
    xy.push_back(0);
    const std::vector<tri::VertIdx> double_cover = {5, 0, 2, 5, 2, 4, 5, 4, 1, 5, 1, 3, 5, 3, 0};
    const tri::CheckReport report = tri::check_topology_2d(xy, double_cover);
    EXPECT_FALSE(report.ok);
    EXPECT_NE(report.problem.find("winds around"), std::string::npos) << report.problem;
    EXPECT_TRUE(tri::check_delaunay_2d(xy, tri::bowyer_watson_2d(xy).triangles).ok);
}

TEST(Triangulation_Delaunay2, GridLocationGivesTheSameTriangulationWithShortWalks) {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<double> uniform, grid;
    for (int i = 0; i < 4000; ++i) uniform.push_back(u(rng));
    for (int i = 0; i < 40; ++i) {
        for (int j = 0; j < 40; ++j) {
            grid.push_back(i);
            grid.push_back(j);
        }
    }
    for (const std::vector<double>* xy : {&uniform, &grid}) {
        for (const tri::InsertionOrder order : kOrders) {
            const auto walk = tri::green_sibson_2d(*xy, {order, 3, tri::PointLocation::Walk});
            const auto jump = tri::bowyer_watson_2d(*xy, {order, 3, tri::PointLocation::Grid});
            EXPECT_TRUE(tri::check_delaunay_2d(*xy, jump.triangles).ok);
            EXPECT_EQ(canonical_triangles(walk.triangles), canonical_triangles(jump.triangles));
            // Jumping keeps walks short whatever the order (a plain walk in random order
            // takes O(sqrt n) steps per point).
            EXPECT_LT(jump.counters.walk_steps, 12 * jump.counters.points);
        }
    }
}

namespace {

/// Tanemura-Merriam against Green-Sibson on xy: the exact check, then the same triangles
/// (same perturbation), and no more than 2n - 5 triangles' worth of work per point.
void expect_tanemura_merriam_matches(const std::vector<double>& xy, const std::string& label) {
    const tri::Delaunay2Result reference = tri::green_sibson_2d(xy);
    const tri::Delaunay2Result r = tri::tanemura_merriam_2d(xy);
    const tri::CheckReport report = tri::check_delaunay_2d(xy, r.triangles);
    ASSERT_TRUE(report.ok) << label << ": " << report.problem;
    EXPECT_EQ(r.merged_into, reference.merged_into) << label;
    EXPECT_EQ(canonical_triangles(r.triangles), canonical_triangles(reference.triangles)) << label;
}

}  // namespace

TEST(Triangulation_TanemuraMerriam2, WideRangeFuzzInputFromTheRevertedRewrite) {
    // tests/data/fuzz/delaunay_2d_tm_hang.bin (fuzz_delaunay_2d, raw mode: 17 points, bits
    // copied as doubles) spelled out. Edge 10 -> 13 of the grid-cell order, about 2^529 long
    // among coordinates up to 2^972, had its circle computed in grid units, where its squared
    // lengths (2^-888 and 2^-1126) underflow: radius 0, every candidate "certainly outside",
    // a wrong third vertex, and a front that went round vertex 4 forever. The circles are now
    // computed in a frame scaled to the edge.
    const std::vector<double> xy = {
        0x1.0000000000000p+2,    0x1.0000000000000p+0,    0x1.e611c0029472dp+1,
        0x1.0ab7803156ed2p+1,    0x1.9bc788585f663p+1,    0x1.82b2f9ff6123ap+1,
        0x1.2b29dd02f316dp+1,    0x1.6cb3fffffff08p-552,  0x1.0d262400d7be2p-360,
        0x1.0b85a3ff46dcbp+777,  0x1.5b1f8400fe5cap+437,  -0x1.d27773fc6e9d5p+731,
        0x1.1d52e400f1574p+201,  -0x1.38479bfe9da59p-744, -0x1.5f594400b2704p+410,
        0x1.ae622bff8cf77p-215,  0x1.f866c4004a266p-1012, 0x1.08a8abfff2ec6p-1010,
        0x1.f866e3ff8d1eap-1012, -0x1.dd614bfff2ec6p+972, -0x1.5f59c3fdcb857p+410,
        -0x1.b986cbff8cf77p+163, 0x1.1d546bfe28998p+201,  0x1.708eabfe9da59p-465,
        0x1.5b180bff64e09p+437,  -0x1.a4eea3fc6e9d5p+438, 0x1.0d250bffe2ae9p-360,
        -0x1.170b63ff46dcbp+529, -0x1.f3164bfffcb94p+259, 0x1.d961a4002b29dp-81,
        -0x1.5f65cbffaf7c4p-935, 0x1.c24844009bc78p-1,    0x1.94728bff0565fp-1021,
        0x1.ddbd0400e611cp+555};
    expect_tanemura_merriam_matches(xy, "fuzz input");
    expect_all_agree(xy, "fuzz input");
    const tri::Delaunay2Result r = tri::tanemura_merriam_2d(xy);
    EXPECT_EQ(r.triangles.size() / 3, 28u);
    // Each search looks at every point at most once: 17 points, 28 triangles.
    EXPECT_LE(r.counters.candidates, 28u * 17u);
}

TEST(Triangulation_TanemuraMerriam2, ClustersFarBelowTheLargestCoordinate) {
    // Random clusters at 2^-600, 2^-1000 (subnormal products) and at subnormal coordinates,
    // each beside a few points near 2^400 and 2^1000: in grid units (the largest coordinate
    // scaled to 1) a cluster's edges are far below the square root of the smallest double.
    std::mt19937_64 rng(17);
    std::uniform_real_distribution<double> u(-1, 1);
    for (const int small : {-600, -1000, -1070}) {
        for (const int large : {400, 1000}) {
            std::vector<double> xy;
            for (int i = 0; i < 60; ++i) {
                xy.push_back(std::ldexp(std::round(u(rng) * 64), small));
                xy.push_back(std::ldexp(std::round(u(rng) * 64), small));
            }
            for (int i = 0; i < 6; ++i) {
                xy.push_back(std::ldexp(u(rng), large));
                xy.push_back(std::ldexp(u(rng), large));
            }
            const std::string label =
                "2^" + std::to_string(small) + " and 2^" + std::to_string(large);
            expect_tanemura_merriam_matches(xy, label);
        }
    }
}

TEST(Triangulation_TanemuraMerriam2, CocircularSetsMatchGreenSibson) {
    // All integer points of x^2 + y^2 = 5^2 13^2 17^2 (one circle: every quadruple cocircular,
    // decided by the perturbation alone), with and without its centre, and shifted copies.
    const int radius = 5 * 13 * 17;
    std::vector<double> circle;
    for (int x = -radius; x <= radius; ++x) {
        const int rest = radius * radius - x * x;
        const auto y = static_cast<int>(std::lround(std::sqrt(static_cast<double>(rest))));
        if (y * y != rest) continue;
        circle.insert(circle.end(), {static_cast<double>(x), static_cast<double>(y)});
        if (y != 0) circle.insert(circle.end(), {static_cast<double>(x), -static_cast<double>(y)});
    }
    ASSERT_GT(circle.size() / 2, 100u);
    expect_tanemura_merriam_matches(circle, "one circle");
    std::vector<double> centred = circle;
    centred.insert(centred.end(), {0.0, 0.0});
    expect_tanemura_merriam_matches(centred, "one circle and its centre");
    std::vector<double> shifted;
    for (int copy = 0; copy < 4; ++copy) {
        for (std::size_t i = 0; i < circle.size(); i += 2) {
            shifted.push_back(circle[i] + copy * 1500.0);
            shifted.push_back(circle[i + 1] + (copy % 2) * 700.0);
        }
    }
    expect_tanemura_merriam_matches(shifted, "four overlapping circles");
}

TEST(Triangulation_TanemuraMerriam2, SortedParabolaMatchesGreenSibson) {
    // (t, t^2) by increasing t: the triangulation is a fan from the first point (a circle
    // through three points of a parabola meets it again at minus their sum), so every front
    // edge's third vertex is the farthest point and its lens holds the whole arc.
    for (const int n : {64, 1000}) {
        std::vector<double> xy;
        for (int i = 0; i < n; ++i) {
            const double t = static_cast<double>(i) / n;
            xy.push_back(t);
            xy.push_back(t * t);
        }
        expect_tanemura_merriam_matches(xy, "parabola n " + std::to_string(n));
        std::vector<double> reversed;
        for (int i = n - 1; i >= 0; --i)
            reversed.insert(reversed.end(), {xy[2 * i], xy[2 * i + 1]});
        expect_tanemura_merriam_matches(reversed, "reversed parabola n " + std::to_string(n));
    }
}

TEST(Triangulation_TanemuraMerriam2, DenseClusterInAWideBoundingBoxStaysLinear) {
    // 2000 points in a square 2^-40 or 2^-1000 wide beside four points about 1 or 2^600 apart:
    // the whole cluster falls in one grid cell, which gets a kd-tree. Without it every search
    // in the cluster looked at all 2000 points; with it about 30 per point. The edges from the
    // far points to the cluster have circles 2^600 times the cluster's size: the power test
    // (in double, from input coordinates) skips the cluster's points outside them, and only
    // the candidates it cannot skip reach the exact incircle. (Before issue 12 the power test
    // also took candidates, under 100 incircle calls; now incircle decides every candidate
    // taken: about 6900-7100 calls here, 1.7 per triangle.)
    std::mt19937_64 rng(23);
    std::uniform_real_distribution<double> u(0, 1);
    for (const int small : {-40, -1000}) {
        for (const int large : {0, 600}) {
            std::vector<double> xy;
            for (int i = 0; i < 2000; ++i) {
                xy.push_back(std::ldexp(u(rng), small));
                xy.push_back(std::ldexp(u(rng), small));
            }
            for (int i = 0; i < 4; ++i) {
                xy.push_back(std::ldexp(u(rng) - 0.5, large));
                xy.push_back(std::ldexp(u(rng) - 0.5, large));
            }
            const std::string label =
                "2^" + std::to_string(small) + " and 2^" + std::to_string(large);
            expect_tanemura_merriam_matches(xy, label);
            const tri::Delaunay2Result r = tri::tanemura_merriam_2d(xy);
            EXPECT_LT(r.counters.candidates, 60u * 2004u) << label;
            EXPECT_LT(r.counters.incircle_calls, 2u * (r.triangles.size() / 3)) << label;
        }
    }
}

TEST(Triangulation_TanemuraMerriam2, NearlyCocircularAtTheSlackScaleMatchesBowyerWatson) {
    // Issue 12: the circle's double bounds (slack 1e-8 r) only skip candidates; the exact
    // predicates decide the rest. Points on a few overlapping circles, each moved off its
    // circle by a relative 1e-8 .. 1e-16 (both ways) or left on it (to rounding), so that
    // circles through three of them have others within the slack: candidates that a wrong
    // bound would take or drop. At scale 1 and scaled by 2^600 and 2^-600 (exact), the same
    // triangles as Bowyer-Watson's, under the same perturbation.
    std::vector<double> base;
    const double offsets[] = {0,      1e-8,   -1e-8,  3e-9,   -3e-9, 1e-10,  -1e-10,
                              1e-11,  -1e-11, 1e-12,  -1e-12, 1e-13, -1e-13, 1e-14,
                              -1e-14, 1e-15,  -1e-15, 1e-16,  -1e-16};
    const double centres[][2] = {{0, 0}, {0.75, 0.2}, {-0.4, 0.9}};
    int k = 0;
    for (const auto& centre : centres) {
        for (int i = 0; i < 24; ++i, ++k) {
            const double angle = (i + 0.37 * (k % 5)) * (2 * M_PI / 24);
            const double radius = 1 + offsets[k % std::size(offsets)];
            base.push_back(centre[0] + radius * std::cos(angle));
            base.push_back(centre[1] + radius * std::sin(angle));
        }
        base.insert(base.end(), {centre[0], centre[1]});
    }
    // A regular 12-gon on one more circle (exactly symmetric up to rounding) with its points
    // pushed in and out by the smallest offsets.
    for (int i = 0; i < 12; ++i) {
        const double radius = 0.5 * (1 + offsets[(i % 6) + 13]);
        base.push_back(0.3 + radius * std::cos(i * (2 * M_PI / 12)));
        base.push_back(-0.6 + radius * std::sin(i * (2 * M_PI / 12)));
    }
    ASSERT_FALSE(has_duplicates(base));
    for (const int exponent : {0, 600, -600}) {
        std::vector<double> xy = base;
        for (double& v : xy) v = std::ldexp(v, exponent);
        ASSERT_FALSE(has_duplicates(xy));
        const std::string label = "scale 2^" + std::to_string(exponent);
        const tri::Delaunay2Result reference =
            tri::bowyer_watson_2d(xy, {tri::InsertionOrder::Given, 1});
        const tri::Delaunay2Result r = tri::tanemura_merriam_2d(xy);
        const tri::CheckReport report = tri::check_delaunay_2d(xy, r.triangles);
        ASSERT_TRUE(report.ok) << label << ": " << report.problem;
        // Exactly the same set, and no triangle twice.
        EXPECT_EQ(canonical_triangles(r.triangles).size(), r.triangles.size() / 3) << label;
        EXPECT_EQ(canonical_triangles(r.triangles), canonical_triangles(reference.triangles))
            << label;
        // Every candidate the bounds did not skip went to the exact incircle.
        EXPECT_GT(r.counters.incircle_calls, 0u) << label;
    }
}
