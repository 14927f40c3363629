// SPDX-License-Identifier: MIT
// Multicore Bowyer-Watson 3D (issue 17): for 1..4 threads the same tetrahedra as the sequential
// construction (canonical comparison), exactly Delaunay, mutual neighbours, on uniform, Gaussian,
// cubic-grid (massively cospherical), cospherical-sphere, duplicate and near-coplanar inputs, at
// 2^+-600, and below the sequential prefix.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "generators/inputs/inputs_3d.hpp"
#include "tests/support/phase_times.hpp"
#include "tests/support/test_scale.hpp"
#include "triangulation/checks/check_3d.hpp"
#include "triangulation/checks/compare_tetrahedralizations_3d.hpp"
#include "triangulation/delaunay/bowyer_watson_3d.hpp"
#include "triangulation/delaunay/parallel_bowyer_watson_3d.hpp"
#include "triangulation/mesh/spatial_sort.hpp"

namespace tri = exactmesh::triangulation;
namespace gen = exactmesh::generators;

namespace {

using exactmesh::testing::test_scale;

tri::Delaunay3Result build(const std::vector<double>& xyz, unsigned threads,
                           std::uint32_t round_minimum = 2048) {
    tri::Delaunay3Options options;
    options.threads = threads;
    options.parallel_round_minimum = round_minimum;
    return tri::bowyer_watson_3d(xyz, options);
}

/// Neighbours are mutual: t names u across a face and u names t back.
void expect_mutual_neighbours(const tri::Delaunay3Result& r, const std::string& label) {
    const std::vector<tri::VertIdx>& tets = r.mesh.tets;
    const std::vector<tri::TetIdx>& neighbors = r.mesh.neighbors;
    for (std::size_t t = 0; t < tets.size() / 4; ++t) {
        for (unsigned k = 0; k < 4; ++k) {
            const tri::TetIdx u = neighbors[4 * t + k];
            if (u == tri::kNone) continue;
            const bool back = std::count(&neighbors[4 * std::size_t{u}],
                                         &neighbors[4 * std::size_t{u}] + 4, t) == 1;
            ASSERT_TRUE(back) << label << ": tetrahedron " << t << " face " << k;
        }
    }
}

/// The sequential result (checked exactly) against 2, 3 and 4 threads (each with the default
/// and with tiny parallel rounds): same tetrahedra, same merged_into, mutual neighbours.
void expect_same_for_every_thread_count(const std::vector<double>& xyz, const std::string& label,
                                        bool check_each = true) {
    const tri::Delaunay3Result sequential = build(xyz, 1);
    EXPECT_EQ(sequential.counters.threads, 1u);
    const tri::Check3Report checked = tri::check_delaunay_3d(sequential.mesh);
    ASSERT_TRUE(checked.ok) << label << ": " << checked.problem;
    const auto expected = tri::canonical_tetrahedra_3d(sequential.mesh.tets);
    for (unsigned threads = 2; threads <= 4; ++threads) {
        for (const std::uint32_t minimum : {2048u, 16u}) {
            const std::string where = label + ", " + std::to_string(threads) +
                                      " threads, rounds from " + std::to_string(minimum);
            const tri::Delaunay3Result r = build(xyz, threads, minimum);
            EXPECT_EQ(r.counters.threads, threads) << where;
            EXPECT_EQ(r.coplanar, sequential.coplanar) << where;
            EXPECT_EQ(r.merged_into, sequential.merged_into) << where;
            ASSERT_EQ(tri::canonical_tetrahedra_3d(r.mesh.tets), expected) << where;
            // Equal to the checked sequential tetrahedra, so exactly Delaunay too; checked
            // again directly (with the neighbours) where asked.
            if (check_each) {
                const tri::Check3Report report = tri::check_delaunay_3d(r.mesh);
                ASSERT_TRUE(report.ok) << where << ": " << report.problem;
            }
            expect_mutual_neighbours(r, where);
            // Every point is inserted (or merged) exactly once, by one of the three phases.
            const std::uint64_t phases = r.counters.sequential_prefix + r.counters.parallel_points +
                                         r.counters.sequential_tail;
            EXPECT_LE(phases, xyz.size() / 3) << where;
            EXPECT_GE(phases + 4 + r.counters.duplicates, xyz.size() / 3) << where;
        }
    }
}

std::uint32_t scaled(double n) {
    return static_cast<std::uint32_t>(std::max(200.0, n * std::min(1.0, test_scale())));
}

}  // namespace

TEST(Triangulation_ParallelBowyerWatson3d, PhaseTimesAreDisjointPartsOfTheCall) {
    // As in 2D: the phases --stats prints fit inside the call's wall time together.
    const auto n = static_cast<std::uint32_t>(std::max(20000.0, 5e4 * std::min(1.0, test_scale())));
    const std::vector<double> xyz = gen::generate_points_3d(gen::Distribution3::Uniform, n, 5);
    EXPECT_TRUE(exactmesh::testing::phases_fit_in_call([&] { return build(xyz, 2); }));
}

TEST(Triangulation_ParallelBowyerWatson3d, SameTetrahedraAsSequentialOnEveryDistribution) {
    struct Case {
        gen::Distribution3 distribution;
        double largest;
    };
    const Case cases[] = {
        {gen::Distribution3::Uniform, 5e4},    {gen::Distribution3::Gaussian, 5e4},
        {gen::Distribution3::Grid, 3e4},       {gen::Distribution3::Cospherical, 7e3},
        {gen::Distribution3::Duplicates, 3e4}, {gen::Distribution3::NearCoplanar, 5e3}};
    for (const Case& c : cases) {
        for (const double n : {1e3, 5e3, 3e4, 5e4}) {
            if (n > c.largest) continue;
            const std::uint32_t count = scaled(n);
            const std::vector<double> xyz = gen::generate_points_3d(c.distribution, count, 5);
            expect_same_for_every_thread_count(
                xyz,
                std::string(gen::distribution_name(c.distribution)) + " n=" + std::to_string(count),
                count <= 5000);
        }
    }
}

TEST(Triangulation_ParallelBowyerWatson3d, RunsInParallelAndDefersFew) {
    // 10^5 uniform points on 2 threads: most points go through the threads, and the
    // sequential tail is a small fraction (the deferral rule is deterministic). At least
    // 2 x 10^4 at every EXACTMESH_TEST_SCALE, so that some rounds go to the threads.
    const std::uint32_t n = std::max<std::uint32_t>(scaled(1e5), 20000);
    const std::vector<double> xyz = gen::generate_points_3d(gen::Distribution3::Uniform, n, 3);
    const tri::Delaunay3Result r = build(xyz, 2);
    EXPECT_GT(r.counters.parallel_points, n / 2);
    EXPECT_LT(r.counters.sequential_tail, n / 10);
    EXPECT_GE(r.counters.parallel_rounds, 2u);
    EXPECT_EQ(tri::canonical_tetrahedra_3d(r.mesh.tets),
              tri::canonical_tetrahedra_3d(build(xyz, 1).mesh.tets));
}

TEST(Triangulation_ParallelBowyerWatson3d, ParallelOrderIsTheSequentialOne) {
    // The BRIO order and both curves' keys computed on every thread: the same as one thread's
    // (more points than one chunk of keys, so that several threads take part).
    const std::uint32_t n = std::max<std::uint32_t>(scaled(1e5), 70000);
    const std::vector<double> xyz = gen::generate_points_3d(gen::Distribution3::Gaussian, n, 11);
    EXPECT_EQ(tri::insertion_order_3d(xyz, tri::InsertionOrder::Brio, 5, true),
              tri::insertion_order_3d(xyz, tri::InsertionOrder::Brio, 5, false));
    EXPECT_EQ(tri::hilbert_keys_3d(xyz, 391, true), tri::hilbert_keys_3d(xyz, 391, false));
}

TEST(Triangulation_ParallelBowyerWatson3d, DeterministicForAThreadCount) {
    // Each thread's work depends only on its partition and the frozen mixed tetrahedra, so
    // two runs number the tetrahedra identically.
    const std::vector<double> xyz =
        gen::generate_points_3d(gen::Distribution3::Gaussian, scaled(3e4), 11);
    for (const std::uint32_t minimum : {2048u, 16u}) {
        const tri::Delaunay3Result a = build(xyz, 3, minimum);
        const tri::Delaunay3Result b = build(xyz, 3, minimum);
        EXPECT_EQ(a.mesh.tets, b.mesh.tets);
        EXPECT_EQ(a.mesh.neighbors, b.mesh.neighbors);
    }
}

TEST(Triangulation_ParallelBowyerWatson3d, ScaledByPowersOfTwo) {
    // The same input times 2^600 and 2^-600: the same tetrahedra (predicates rescale exactly;
    // the Hilbert keys read the bounding box by halves, so they are scale-free too).
    const std::vector<double> xyz =
        gen::generate_points_3d(gen::Distribution3::Uniform, scaled(2e4), 9);
    const auto expected = tri::canonical_tetrahedra_3d(build(xyz, 1).mesh.tets);
    for (const int e : {600, -600}) {
        std::vector<double> s(xyz);
        for (double& c : s) c = std::ldexp(c, e);
        for (unsigned threads = 2; threads <= 4; ++threads) {
            const tri::Delaunay3Result r = build(s, threads, 64);
            EXPECT_EQ(tri::canonical_tetrahedra_3d(r.mesh.tets), expected)
                << "2^" << e << ", " << threads << " threads";
            const tri::Check3Report report = tri::check_delaunay_3d(r.mesh);
            EXPECT_TRUE(report.ok) << "2^" << e << ": " << report.problem;
        }
    }
}

TEST(Triangulation_ParallelBowyerWatson3d, SmallAndCoplanarInputs) {
    // Fewer points than a parallel round (all in the sequential prefix), and coplanar or
    // repeated points (no tetrahedron): the parallel entry gives the same answers.
    const std::vector<std::vector<double>> inputs = {
        {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1},
        {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 0, 0, 0, 0, 0},
        {0, 0, 0, 0, 0, 0, 0, 0, 0},
        {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 2, 3, 0},
        {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0, 0, 1, 1, 0, 1, 0, 1, 1, 1, 1, 1},
    };
    for (const std::vector<double>& xyz : inputs) {
        const tri::Delaunay3Result sequential = build(xyz, 1);
        const tri::Delaunay3Result parallel = tri::parallel_bowyer_watson_3d(xyz, {}, 3);
        EXPECT_EQ(tri::canonical_tetrahedra_3d(parallel.mesh.tets),
                  tri::canonical_tetrahedra_3d(sequential.mesh.tets));
        EXPECT_EQ(parallel.merged_into, sequential.merged_into);
        EXPECT_EQ(parallel.coplanar, sequential.coplanar);
    }
}

TEST(Triangulation_ParallelBowyerWatson3d, ThreadCountZeroMeansEveryHardwareThread) {
    const std::vector<double> xyz =
        gen::generate_points_3d(gen::Distribution3::Uniform, scaled(1e4), 2);
    const tri::Delaunay3Result r = build(xyz, 0);
    EXPECT_EQ(r.counters.threads, tri::resolve_thread_count(0));
    EXPECT_EQ(tri::canonical_tetrahedra_3d(r.mesh.tets),
              tri::canonical_tetrahedra_3d(build(xyz, 1).mesh.tets));
}

TEST(Triangulation_ParallelBowyerWatson3d, OtherOrdersRunSequentially) {
    const std::vector<double> xyz = gen::generate_points_3d(gen::Distribution3::Uniform, 2000, 4);
    tri::Delaunay3Options options;
    options.threads = 4;
    options.order = tri::InsertionOrder::Random;
    EXPECT_EQ(tri::bowyer_watson_3d(xyz, options).counters.threads, 1u);
}

TEST(Triangulation_ParallelBowyerWatson3d, TinyRoundsOnSmallInputs) {
    // Parallel rounds from 4 points per thread: most cavities meet a border or the hull, so
    // deferral, the second curve and the tail all run, on every distribution and sizes 5..600.
    const int seeds = std::max(2, static_cast<int>(8 * test_scale()));
    for (const gen::Distribution3 d : gen::kAllDistributions3) {
        for (int seed = 0; seed < seeds; ++seed) {
            const auto n = static_cast<std::uint32_t>(5 + seed * 997 % 600);
            const std::vector<double> xyz =
                gen::generate_points_3d(d, n, static_cast<std::uint64_t>(seed));
            tri::Delaunay3Options options;
            options.seed = static_cast<std::uint64_t>(seed);
            const tri::Delaunay3Result sequential = tri::bowyer_watson_3d(xyz, options);
            const auto expected = tri::canonical_tetrahedra_3d(sequential.mesh.tets);
            for (unsigned threads = 2; threads <= 4; ++threads) {
                options.threads = threads;
                options.parallel_round_minimum = 4;
                const tri::Delaunay3Result r = tri::bowyer_watson_3d(xyz, options);
                const std::string where =
                    std::string(gen::distribution_name(d)) + " n=" + std::to_string(n) + " seed " +
                    std::to_string(seed) + ", " + std::to_string(threads) + " threads";
                ASSERT_EQ(tri::canonical_tetrahedra_3d(r.mesh.tets), expected) << where;
                ASSERT_EQ(r.merged_into, sequential.merged_into) << where;
                const tri::Check3Report report = tri::check_delaunay_3d(r.mesh);
                ASSERT_TRUE(report.ok) << where << ": " << report.problem;
                expect_mutual_neighbours(r, where);
            }
        }
    }
}
