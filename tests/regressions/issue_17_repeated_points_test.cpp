// SPDX-License-Identifier: MIT
// Issue 17, the multicore Bowyer-Watson constructions on degenerate inputs with repeated points:
// 3,000 points rounded to an integer lattice (13^3 nodes in 3D, 41^2 in 2D: every point repeats,
// every cell is cospherical or cocircular). The parallel constructions gave other tetrahedra
// (other triangles) than one thread on every such input, 2D included: of two copies of a point
// the threads could insert the later one in the BRIO order first (a walk starting elsewhere, the
// way back from a thread's start taking its list backwards), and the copy inserted is the one
// whose input index the symbolic perturbation reads. The threads now try copies in the
// sequential order (detail::sweep_partition), so the copy kept, and the result, are the
// sequential ones.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "triangulation/checks/check_2d.hpp"
#include "triangulation/checks/check_3d.hpp"
#include "triangulation/checks/compare_tetrahedralizations_3d.hpp"
#include "triangulation/checks/compare_triangulations_2d.hpp"
#include "triangulation/delaunay/bowyer_watson_2d.hpp"
#include "triangulation/delaunay/bowyer_watson_3d.hpp"

namespace {

namespace tri = exactmesh::triangulation;

/// `count` coordinates uniform in [0, 1), times `scale`, rounded to integers.
std::vector<double> lattice_coordinates(std::size_t count, double scale, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<double> out(count);
    for (double& c : out) c = std::round(u(rng) * scale);
    return out;
}

}  // namespace

TEST(Regression_Issue17, RepeatedLatticePointsKeepTheSequentialCopies) {
    for (std::uint64_t seed = 0; seed < 6; ++seed) {
        const std::vector<double> xyz = lattice_coordinates(3 * 3000, 12, seed);
        const std::vector<double> xy = lattice_coordinates(2 * 3000, 40, seed);
        tri::Delaunay3Options options_3d;
        options_3d.seed = seed;
        const tri::Delaunay3Result one_3d = tri::bowyer_watson_3d(xyz, options_3d);
        ASSERT_TRUE(tri::check_delaunay_3d(one_3d.mesh).ok);
        tri::Delaunay2Options options_2d;
        options_2d.seed = seed;
        const tri::Delaunay2Result one_2d = tri::bowyer_watson_2d(xy, options_2d);
        ASSERT_TRUE(tri::check_delaunay_2d(xy, one_2d.triangles).ok);
        for (unsigned threads = 2; threads <= 3; ++threads) {
            for (const std::uint32_t minimum : {16u, 2048u}) {
                const std::string where = "seed " + std::to_string(seed) + ", " +
                                          std::to_string(threads) + " threads, rounds from " +
                                          std::to_string(minimum);
                options_3d.threads = options_2d.threads = threads;
                options_3d.parallel_round_minimum = options_2d.parallel_round_minimum = minimum;
                const tri::Delaunay3Result r3 = tri::bowyer_watson_3d(xyz, options_3d);
                EXPECT_EQ(tri::canonical_tetrahedra_3d(r3.mesh.tets),
                          tri::canonical_tetrahedra_3d(one_3d.mesh.tets))
                    << "3D, " << where;
                EXPECT_EQ(r3.merged_into, one_3d.merged_into) << "3D, " << where;
                const tri::Delaunay2Result r2 = tri::bowyer_watson_2d(xy, options_2d);
                EXPECT_EQ(tri::canonical_triangles_2d(r2.triangles),
                          tri::canonical_triangles_2d(one_2d.triangles))
                    << "2D, " << where;
                EXPECT_EQ(r2.merged_into, one_2d.merged_into) << "2D, " << where;
            }
        }
    }
}
