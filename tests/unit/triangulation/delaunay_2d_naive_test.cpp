// SPDX-License-Identifier: MIT
// The naive empty-circle oracle (triangulation/delaunay/delaunay_2d_naive.hpp) that `exactmesh
// fuzz` ships: it agrees with all three Delaunay algorithms on small random and cocircular sets,
// and it names the disagreement when a triangulation is not Delaunay (one edge flipped), has a
// wrong count, or a clockwise triangle.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "triangulation/delaunay/delaunay_2d.hpp"
#include "triangulation/delaunay/delaunay_2d_naive.hpp"

namespace tri = exactmesh::triangulation;

namespace {

std::vector<double> random_points(std::mt19937_64& rng, int n) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::vector<double> xy;
    for (int i = 0; i < 2 * n; ++i) xy.push_back(u(rng));
    return xy;
}

}  // namespace

TEST(Delaunay2Naive, AgreesWithEveryAlgorithmOnRandomAndCocircularSets) {
    std::mt19937_64 rng(11);
    std::vector<std::vector<double>> sets;
    for (int k = 0; k < 20; ++k) sets.push_back(random_points(rng, 5 + k * 2));
    // 12 points on the unit circle's exact 12-fold symmetry (cocircular ties) plus the centre,
    // and a duplicate.
    std::vector<double> ring{1,    0,    0,    1,    -1,   0,    0,   -1,  0.6,  0.8,
                             -0.6, 0.8,  0.6,  -0.8, -0.6, -0.8, 0.8, 0.6, -0.8, 0.6,
                             0.8,  -0.6, -0.8, -0.6, 0,    0,    0.6, 0.8};
    sets.push_back(ring);
    for (const auto& xy : sets) {
        const tri::NaiveDelaunay2 oracle = tri::delaunay_2d_naive(xy);
        EXPECT_GT(oracle.triangle_count, 0U);
        for (const tri::Delaunay2Algorithm& algorithm : tri::delaunay_2d_algorithms()) {
            const tri::Delaunay2Result r = algorithm.build(xy, {});
            EXPECT_EQ(tri::compare_with_delaunay_2d_naive(xy, r.triangles, oracle, r.merged_into),
                      "")
                << algorithm.name << ", " << xy.size() / 2 << " points";
        }
    }
    const tri::NaiveDelaunay2 o = tri::delaunay_2d_naive(ring);
    EXPECT_EQ(o.distinct, 13U);
    EXPECT_EQ(o.hull, 12U);
    EXPECT_EQ(o.triangle_count, 12U);  // 2·13 - 12 - 2
    EXPECT_EQ(o.representative[13], 4U);
}

TEST(Delaunay2Naive, NamesWhatIsWrong) {
    // A square with a point near its centre: four Delaunay triangles about it.
    const std::vector<double> xy{0, 0, 4, 0, 4, 4, 0, 4, 1.9, 2.2};
    const tri::NaiveDelaunay2 oracle = tri::delaunay_2d_naive(xy);
    ASSERT_EQ(oracle.triangle_count, 4U);
    const std::vector<std::uint32_t> good{0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4};
    EXPECT_EQ(tri::compare_with_delaunay_2d_naive(xy, good, oracle), "");
    // Edge 0-4 flipped into 1-3: triangles (1, 3, 0)... leave 3 0 1 and 1 3 4 fan: not Delaunay.
    const std::vector<std::uint32_t> flipped{3, 0, 1, 1, 2, 4, 2, 3, 4, 1, 4, 3};
    const std::string flipped_problem = tri::compare_with_delaunay_2d_naive(xy, flipped, oracle);
    EXPECT_NE(flipped_problem.find("inside its circumcircle"), std::string::npos)
        << flipped_problem;
    const std::vector<std::uint32_t> clockwise{0, 4, 1, 1, 2, 4, 2, 3, 4, 3, 0, 4};
    EXPECT_NE(
        tri::compare_with_delaunay_2d_naive(xy, clockwise, oracle).find("not counter-clockwise"),
        std::string::npos);
    const std::vector<std::uint32_t> short_by_one{0, 1, 4, 1, 2, 4, 2, 3, 4};
    EXPECT_NE(tri::compare_with_delaunay_2d_naive(xy, short_by_one, oracle).find("expected 4"),
              std::string::npos);
}
