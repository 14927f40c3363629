// SPDX-License-Identifier: MIT
// Delaunay refinement in rounds (RefinementOrder::Rounds): the same checks as the worst-first
// refinement's (constrained Delaunay with every segment a chain of pieces, exactly checked; the
// angle and size bounds; degenerate inputs), and the rounds' own promise: the same mesh, bit
// for bit, on 1, 2 and 3 threads, on the sample domains, on degenerate and cocircular inputs,
// on random PSLGs and scaled by 2^±600 (where it is the unscaled mesh, scaled). Worst-first
// asked for more than one thread is an InputError.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "base/errors.hpp"
#include "generators/boundary/sample_domains.hpp"
#include "generators/mesh_2d/delaunay_refinement_2d.hpp"
#include "tests/support/degenerate_pslgs_2d.hpp"
#include "tests/support/generated_mesh_2d.hpp"
#include "tests/support/mesh_checks_2d.hpp"
#include "tests/support/pslg_fixtures_2d.hpp"

namespace em = exactmesh;
namespace gen = exactmesh::generators;

namespace {

using exactmesh::testing::from_domain;
using exactmesh::testing::Input;
using exactmesh::testing::polygon;

using Refined = em::testing::GeneratedMesh2<gen::RefinementResult2>;

constexpr double kAngleSlack = 1e-9;  // degrees: the bad-triangle test and atan2 both round

gen::RefinementOptions2 rounds(double min_angle, const gen::SizeFunction& size = {},
                               unsigned threads = 1) {
    gen::RefinementOptions2 options;
    options.min_angle = min_angle;
    options.size = size;
    options.order = gen::RefinementOrder::Rounds;
    options.threads = threads;
    return options;
}

Refined refine(const Input& in, const gen::RefinementOptions2& options, bool closed_loops = true) {
    return em::testing::check_generated_mesh(gen::delaunay_refinement_2d(in.pslg(), options), in,
                                             options.size, closed_loops, true);
}

/// The same mesh (vertices bit for bit, triangles, pieces, warnings) and the same counters but
/// the thread count.
void expect_same_refinement(const gen::RefinementResult2& a, const gen::RefinementResult2& b,
                            const std::string& what) {
    EXPECT_EQ(a.mesh.mesh.xy, b.mesh.mesh.xy) << what;
    EXPECT_EQ(a.mesh.mesh.triangles, b.mesh.mesh.triangles) << what;
    EXPECT_EQ(a.mesh.pieces, b.mesh.pieces) << what;
    EXPECT_EQ(a.mesh.warnings, b.mesh.warnings) << what;
    gen::RefinementCounters2 ca = a.counters, cb = b.counters;
    ca.threads = cb.threads = 0;
    EXPECT_EQ(em::counters_by_name(gen::kRefinementCounterNames, ca),
              em::counters_by_name(gen::kRefinementCounterNames, cb))
        << what;
}

/// Refines `in` in rounds on 1, 2 and 3 threads: every mesh passes the exact checks and all
/// three are the same. Returns the one-thread run.
Refined refine_on_every_thread_count(const Input& in, gen::RefinementOptions2 options,
                                     const std::string& what, bool closed_loops = true) {
    options.threads = 1;
    Refined one = refine(in, options, closed_loops);
    EXPECT_TRUE(one.check.ok) << what << ": " << one.check.problem;
    EXPECT_EQ(one.result.counters.threads, 1u) << what;
    for (const unsigned threads : {2u, 3u}) {
        options.threads = threads;
        const Refined more = refine(in, options, closed_loops);
        EXPECT_TRUE(more.check.ok) << what << " on " << threads << ": " << more.check.problem;
        EXPECT_EQ(more.result.counters.threads, threads) << what;
        expect_same_refinement(one.result, more.result, what + " on " + std::to_string(threads));
    }
    return one;
}

}  // namespace

TEST(Generators_RefinementRounds, SampleDomainsMeetTheBoundsOnEveryThreadCount) {
    for (const gen::SampleDomain d : gen::kAllSampleDomains) {
        const gen::SizeFunction size = gen::sample_domain_size(d);
        const Input in = from_domain(gen::sample_domain(d, size));
        const std::string name(gen::sample_domain_name(d));
        const Refined r = refine_on_every_thread_count(in, rounds(20.7, size), name);
        EXPECT_LE(r.check.max_size_ratio, 1 + 1e-9) << name;
        EXPECT_GT(r.result.mesh.mesh.triangle_count(), 1000u) << name;
        if (d != gen::SampleDomain::Key) {
            EXPECT_GE(r.check.min_angle, 20.7 - kAngleSlack) << name;
        }
        // More than one point per round on average: the rounds do find independent cavities.
        EXPECT_GT(r.result.counters.steiner_points(), 2 * r.result.counters.rounds) << name;
    }
}

TEST(Generators_RefinementRounds, GradedSizesOfEveryKindOnEveryThreadCount) {
    // Sources and a background mesh are assessed on the fans' threads (SizeFunction::concurrent),
    // a caller's function on one thread after them: the same mesh either way, on any count.
    const Input in = from_domain(gen::sample_domain(gen::SampleDomain::SquareWithHoles));
    const gen::SizeFunction sources = gen::SizeFunction::sources(
        {{0.5, 0.5, 0.004, 0.2, 1.0}}, {{0.0, 0.0, 1.0, 0.0, 0.006, 0.3, 1.0}}, 0.05);
    const gen::SizeFunction analytic = gen::SizeFunction::analytic(
        [](double x, double y) { return 0.006 + 0.03 * std::hypot(x - 0.5, y - 0.5); },
        "0.006 + 0.03 |p - (0.5, 0.5)|");
    const gen::SizeFunction background = gen::SizeFunction::background_mesh(
        {-1, -1, 2, -1, 2, 2, -1, 2}, {0.004, 0.02, 0.05, 0.02}, {0, 1, 2, 0, 2, 3});
    EXPECT_TRUE(sources.concurrent());
    EXPECT_TRUE(background.concurrent());
    EXPECT_FALSE(analytic.concurrent());
    for (const auto& [name, size] : {std::pair{"sources", sources}, std::pair{"analytic", analytic},
                                     std::pair{"background", background}}) {
        const Refined r = refine_on_every_thread_count(in, rounds(28.0, size), name);
        EXPECT_GE(r.check.min_angle, 28.0 - kAngleSlack) << name;
        EXPECT_LE(r.check.max_size_ratio, 1 + 1e-9) << name;
        EXPECT_GT(r.result.mesh.mesh.triangle_count(), 2000u) << name;
    }
}

TEST(Generators_RefinementRounds, PhaseTimesAreDisjointPartsOfTheCall) {
    // The rounds' phases are laps of one stopwatch on the calling thread: each phase that ran
    // has time, and together they fit inside the call's own wall time (a lap that did not
    // restart the stopwatch would count a stretch twice, over about a hundred rounds here).
    // phase_list names the six in the struct's order; worst-first times none.
    const Input in = from_domain(gen::sample_domain(gen::SampleDomain::SquareWithHoles));
    gen::RefinementOptions2 options = rounds(30.0, gen::SizeFunction::uniform(0.01), 2);
    const auto begin = std::chrono::steady_clock::now();
    const gen::RefinementResult2 r = gen::delaunay_refinement_2d(in.pslg(), options);
    const double call =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    ASSERT_GT(r.counters.rounds, 10u);
    const gen::RoundPhaseSeconds2& phases = r.round_seconds;
    EXPECT_GT(phases.form, 0.0);
    EXPECT_GT(phases.probe, 0.0);
    EXPECT_GT(phases.accept, 0.0);
    EXPECT_GT(phases.fans, 0.0);
    EXPECT_GT(phases.queue, 0.0);
    const auto list = gen::phase_list(phases);
    ASSERT_EQ(list.size(), 6u);
    const double in_order[6] = {phases.form, phases.probe, phases.accept,
                                phases.fans, phases.queue, phases.steps};
    const char* names[6] = {"form", "probe", "accept", "fans", "queue", "steps"};
    double sum = 0;
    for (std::size_t i = 0; i < 6; ++i) {
        EXPECT_EQ(list[i].first, std::string("round_") + names[i] + "_seconds");
        EXPECT_EQ(list[i].second, in_order[i]);
        sum += list[i].second;
    }
    EXPECT_LE(sum, call);
    options.order = gen::RefinementOrder::WorstFirst;
    options.threads = 1;
    const gen::RefinementResult2 worst_first = gen::delaunay_refinement_2d(in.pslg(), options);
    for (const auto& [name, seconds] : gen::phase_list(worst_first.round_seconds))
        EXPECT_EQ(seconds, 0.0) << name;
}

TEST(Generators_RefinementRounds, ThirtyDegreesWithThePolishAsWorstFirst) {
    // Square with holes at 30 degrees (the polish lifts it towards 32): the same bound as the
    // worst-first refinement, within a few percent of its Steiner points.
    const Input in = from_domain(gen::sample_domain(gen::SampleDomain::SquareWithHoles));
    gen::RefinementOptions2 options = rounds(30.0, gen::SizeFunction::uniform(0.02));
    const Refined r = refine_on_every_thread_count(in, options, "square with holes at 30");
    EXPECT_GE(r.check.min_angle, 30.0 - kAngleSlack);
    EXPECT_LE(r.check.max_size_ratio, 1 + 1e-9);
    EXPECT_GT(r.result.counters.round_conflicts, 0u);
    options.order = gen::RefinementOrder::WorstFirst;
    const Refined worst_first = refine(in, options);
    ASSERT_TRUE(worst_first.check.ok) << worst_first.check.problem;
    const double ratio = static_cast<double>(r.result.counters.steiner_points()) /
                         static_cast<double>(worst_first.result.counters.steiner_points());
    EXPECT_GT(ratio, 0.95);
    EXPECT_LT(ratio, 1.05);
    EXPECT_EQ(worst_first.result.counters.rounds, 0u);
}

TEST(Generators_RefinementRounds, DegenerateAndCocircularInputs) {
    std::vector<em::testing::NamedInput> cases = em::testing::degenerate_pslgs();
    // Twelve cocircular vertices (radius 5: (±5, 0), (0, ±5), (±3, ±4), (±4, ±3)) as the
    // boundary, with a free vertex at the centre: the first cavities meet exact incircle ties
    // (the symbolic perturbation decides them, with the probed point's rank).
    cases.push_back({"cocircular ring", polygon({5,  0, 4,  3,  3,  4,  0, 5,  -3, 4,  -4, 3,
                                                 -5, 0, -4, -3, -3, -4, 0, -5, 3,  -4, 4,  -3})});
    cases.back().in.xy.insert(cases.back().in.xy.end(), {0, 0});
    for (const em::testing::NamedInput& c : cases) {
        for (const double angle : {20.7, 28.0}) {
            const std::string what = std::string(c.name) + " at " + std::to_string(angle);
            const Refined r = refine_on_every_thread_count(c.in, rounds(angle), what);
            EXPECT_GE(r.check.min_angle, angle - kAngleSlack) << what;
        }
    }
}

TEST(Generators_RefinementRounds, ScaledByPowersOfTwoGivesTheScaledMesh) {
    // Scale invariance: 2^600 and 2^-600 times the key domain (a 10-degree tooth: shell splits,
    // skipped skinny triangles) with its size give the unscaled mesh's vertices, scaled exactly.
    const gen::SizeFunction size = gen::sample_domain_size(gen::SampleDomain::Key);
    const Input in = from_domain(gen::sample_domain(gen::SampleDomain::Key, size));
    const Refined base = refine(in, rounds(25.0, size, 2));
    ASSERT_TRUE(base.check.ok) << base.check.problem;
    for (const int e : {600, -600}) {
        Input scaled = in;
        for (double& x : scaled.xy) x = std::ldexp(x, e);
        const Refined r = refine(scaled, rounds(25.0, size.scaled(std::ldexp(1.0, e)), 2));
        ASSERT_TRUE(r.check.ok) << e << ": " << r.check.problem;
        std::vector<double> back = r.result.mesh.mesh.xy;
        for (double& x : back) x = std::ldexp(x, -e);
        EXPECT_EQ(back, base.result.mesh.mesh.xy) << e;
        EXPECT_EQ(r.result.mesh.mesh.triangles, base.result.mesh.mesh.triangles) << e;
    }
}

TEST(Generators_RefinementRounds, RandomPslgsGiveValidMeshesOrAClearError) {
    em::testing::expect_random_pslgs_constrained_delaunay([](const Input& in) {
        return std::optional{gen::delaunay_refinement_2d(in.pslg(), rounds(20.7, {}, 2))};
    });
}

TEST(Generators_RefinementRounds, BudgetStopsWithTheSameError) {
    gen::RefinementOptions2 options = rounds(20.7, gen::SizeFunction::uniform(0.01), 2);
    options.max_steiner_points = 100;
    try {
        gen::delaunay_refinement_2d(polygon({0, 0, 1, 0, 1, 1, 0, 1}).pslg(), options);
        FAIL() << "no RefinementBudgetError";
    } catch (const gen::RefinementBudgetError& error) {
        EXPECT_NE(std::string(error.what()).find("more than 100 Steiner points"), std::string::npos)
            << error.what();
    }
}

TEST(Generators_RefinementRounds, WorstFirstOnMoreThreadsIsAnInputError) {
    gen::RefinementOptions2 options;
    options.threads = 2;
    EXPECT_THROW(gen::delaunay_refinement_2d(polygon({0, 0, 1, 0, 1, 1, 0, 1}).pslg(), options),
                 em::InputError);
}
