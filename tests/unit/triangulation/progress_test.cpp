// SPDX-License-Identifier: MIT
// The progress hook of the constructions (base/progress.hpp, issue 16 "Long runs"): called every
// 2^14 points inserted with increasing counts and the point count as total, and without any
// effect on the result.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "base/progress.hpp"
#include "tests/support/test_scale.hpp"
#include "tests/support/uniform_draws.hpp"
#include "triangulation/constrained/constrained_2d.hpp"
#include "triangulation/delaunay/bowyer_watson_2d.hpp"
#include "triangulation/delaunay/bowyer_watson_3d.hpp"
#include "triangulation/delaunay/green_sibson_2d.hpp"
#include "triangulation/delaunay/green_sibson_3d.hpp"

namespace em = exactmesh;
namespace tri = exactmesh::triangulation;

namespace {

constexpr std::uint64_t kStep = std::uint64_t{1} << em::ProgressCounter::kProgressShift;

struct Call {
    std::uint64_t done, total;
    std::string what;
};

/// A hook recording every call into `calls`.
em::Progress recorder(std::vector<Call>& calls) {
    em::Progress progress;
    progress.report = [&calls](std::uint64_t done, std::uint64_t total, const char* what) {
        calls.push_back({done, total, what});
    };
    return progress;
}

/// n points uniform in the unit square (dimension 2) or cube (3), distinct with probability 1.
std::vector<double> uniform_points(std::size_t n, unsigned dimension, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::vector<double> points(dimension * n);
    for (double& x : points) x = em::testing::uniform(rng, 0, 1);
    return points;
}

/// At least 2^15 points (two calls), 2^17 at the default scale.
std::size_t point_count(double full) {
    return static_cast<std::size_t>(std::max(double{1 << 15}, full * em::testing::test_scale()));
}

/// Every call: the next multiple of 2^14, the total `total`, the unit `what`; as many calls as
/// `inserted` points make.
void expect_calls(const std::vector<Call>& calls, std::uint64_t inserted, std::uint64_t total,
                  const std::string& what) {
    ASSERT_EQ(calls.size(), inserted / kStep);
    for (std::size_t k = 0; k < calls.size(); ++k) {
        EXPECT_EQ(calls[k].done, (k + 1) * kStep) << k;
        EXPECT_EQ(calls[k].total, total) << k;
        EXPECT_EQ(calls[k].what, what) << k;
    }
}

}  // namespace

TEST(Base_ProgressCounter, CallsEveryStepAndNeverWithoutHook) {
    std::vector<Call> calls;
    em::ProgressCounter counter(recorder(calls), 7, "units");
    em::ProgressCounter silent;
    em::ProgressCounter empty(em::Progress{}, 7, "units");
    for (std::uint64_t k = 0; k < 3 * kStep + 5; ++k) {
        counter.tick();
        silent.tick();
        empty.tick();
    }
    expect_calls(calls, 3 * kStep + 5, 7, "units");
    EXPECT_EQ(silent.done(), 3 * kStep + 5);
    EXPECT_EQ(empty.done(), 3 * kStep + 5);
}

TEST(Triangulation_Progress, Delaunay2DReportsPointsAndKeepsTheResult) {
    const std::size_t n = point_count(1 << 17);
    const std::vector<double> xy = uniform_points(n, 2, 16);
    for (const auto build : {&tri::bowyer_watson_2d, &tri::green_sibson_2d}) {
        std::vector<Call> calls;
        tri::Delaunay2Options with_hook;
        with_hook.progress = recorder(calls);
        const tri::Delaunay2Result plain = build(xy, tri::Delaunay2Options{});
        const tri::Delaunay2Result hooked = build(xy, with_hook);
        EXPECT_EQ(plain.triangles, hooked.triangles);
        EXPECT_EQ(plain.neighbors, hooked.neighbors);
        // The first triangle's three points are not counted: they are not inserted.
        expect_calls(calls, n - 3, n, "points inserted");
    }
}

TEST(Triangulation_Progress, Delaunay3DReportsPointsAndKeepsTheResult) {
    const std::size_t n = point_count(1 << 16);
    const std::vector<double> xyz = uniform_points(n, 3, 17);
    for (const auto build : {&tri::bowyer_watson_3d, &tri::green_sibson_3d}) {
        std::vector<Call> calls;
        tri::Delaunay3Options with_hook;
        with_hook.progress = recorder(calls);
        const tri::Delaunay3Result plain = build(xyz, tri::Delaunay3Options{});
        const tri::Delaunay3Result hooked = build(xyz, with_hook);
        EXPECT_EQ(plain.mesh.tets, hooked.mesh.tets);
        EXPECT_EQ(plain.mesh.neighbors, hooked.mesh.neighbors);
        expect_calls(calls, n - 4, n, "points inserted");
    }
}

TEST(Triangulation_Progress, ConstrainedReportsVerticesAndKeepsTheResult) {
    const std::size_t n = point_count(1 << 16);
    std::vector<double> xy = uniform_points(n, 2, 18);
    // A square around the points, its sides the segments.
    const auto first = static_cast<tri::VertIdx>(n);
    xy.insert(xy.end(), {-1, -1, 2, -1, 2, 2, -1, 2});
    const std::vector<tri::VertIdx> segments = {first,     first + 1, first + 1, first + 2,
                                                first + 2, first + 3, first + 3, first};
    const tri::Pslg pslg{xy, segments, {}, {}};
    std::vector<Call> calls;
    tri::Cdt2Options with_hook;
    with_hook.progress = recorder(calls);
    const tri::Cdt2Result plain = tri::constrained_delaunay_2d(pslg);
    const tri::Cdt2Result hooked = tri::constrained_delaunay_2d(pslg, with_hook);
    EXPECT_EQ(plain.mesh.triangles, hooked.mesh.triangles);
    EXPECT_EQ(plain.mesh.xy, hooked.mesh.xy);
    expect_calls(calls, n + 4 - 3, n + 4, "points inserted");
}
