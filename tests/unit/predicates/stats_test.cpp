// SPDX-License-Identifier: MIT
// Predicate stage counters (predicates/stats.hpp): every call ends in exactly one stage, and
// degenerate inputs reach the exact stages. Only meaningful in a build with
// EXACTMESH_PREDICATE_STATS (the `stats` preset, built and run by scripts/test); elsewhere the
// counters stay zero.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <utility>

#include "predicates/angle_comparisons_2d.hpp"
#include "predicates/angle_comparisons_3d.hpp"
#include "predicates/incircle.hpp"
#include "predicates/insphere.hpp"
#include "predicates/orient2d.hpp"
#include "predicates/orient3d.hpp"
#include "predicates/stats.hpp"
#include "predicates/within_rounding_of_segment.hpp"

namespace pr = exactmesh::predicates;

namespace {

[[maybe_unused]] std::uint64_t stage_sum(const pr::StageCounts& c) {
    return c.filter + c.exact_differences + c.adaptive + c.expansion + c.gmp;
}

/// `count` times: five points with coordinates from draw(), and each predicate on them.
template <class Draw>
void call_predicates_on_random_points(int count, Draw draw) {
    double p[5][3];
    for (int n = 0; n < count; ++n) {
        for (auto& q : p) {
            for (double& x : q) x = draw();
        }
        pr::orient2d(p[0], p[1], p[2]);
        pr::incircle(p[0], p[1], p[2], p[3]);
        pr::orient3d(p[0], p[1], p[2], p[3]);
        pr::insphere(p[0], p[1], p[2], p[3], p[4]);
    }
}

/// Runs each predicate over random points, an integer grid (exact zeros: exact differences),
/// near-degenerate points with inexact differences (expansions), huge ones (scaled into range)
/// and huge ones beside small ones (GMP).
void exercise_all_stages() {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    call_predicates_on_random_points(2000, [&] { return unit(rng); });
    std::uniform_int_distribution<int> small(-1, 1);
    call_predicates_on_random_points(2000, [&] { return small(rng); });
    for (int n = 0; n < 256; ++n) {
        // The near-collinear grid: a few ulps off the line through (12,12), (24,24); differences
        // from 0.1-ish coordinates are inexact.
        const double a[3] = {0.5 + std::ldexp(n % 16, -53), 0.5 + std::ldexp(n / 16, -53), 0.5};
        const double b[3] = {12.0, 12.0, 12.0}, c[3] = {24.0, 24.0, 24.0};
        const double d[3] = {0.1 + 0.2, 0.1 + 0.2, 0.3}, e[3] = {1.0 / 3.0, 1.0 / 3.0, 0.7};
        pr::orient2d(a, b, d);
        pr::incircle(a, b, c, d);
        pr::orient3d(a, b, c, d);
        pr::insphere(a, b, c, d, e);
        // Huge coordinates: outside the expansion-safe range, brought into it by 2^-996.
        const double h[3] = {1e300, 1e300, 1e300}, g[3] = {-1e300, -1e300, -1e300};
        const double o[3] = {0.0, 0.0, 0.0}, k[3] = {1e300, -1e300, 0.0};
        pr::orient2d(h, g, o);
        pr::incircle(h, g, o, k);
        pr::orient3d(h, g, o, k);
        pr::insphere(h, g, o, k, o);
        // 1e300 beside 0.1: no power of two brings both into range exactly, so GMP decides.
        const double w[3] = {0.1, 0.3, 0.7};
        pr::orient2d(h, g, w);
        pr::incircle(h, g, k, w);
        pr::orient3d(h, g, k, w);
        pr::insphere(h, g, o, k, w);
    }
}

[[maybe_unused]] void expect_consistent(const char* name, const pr::StageCounts& c) {
    SCOPED_TRACE(name);
    EXPECT_GT(c.calls, 0u);
    EXPECT_EQ(c.calls, stage_sum(c))
        << "filter " << c.filter << " + exact_differences " << c.exact_differences << " + adaptive "
        << c.adaptive << " + expansion " << c.expansion << " + gmp " << c.gmp;
    EXPECT_GT(c.filter, 0u);
    EXPECT_GT(c.exact_differences, 0u) << "the integer grid has exact differences";
    EXPECT_GT(c.adaptive + c.expansion, 0u)
        << "the near-collinear grid has inexact differences: stages B/C or the full expansion";
    EXPECT_GT(c.rescaled, 0u) << "1e300 coordinates are scaled into the expansion-safe range";
    EXPECT_LE(c.rescaled, c.calls);
    EXPECT_GT(c.gmp, 0u) << "1e300 beside 0.1 spans more than the expansion-safe range";
}

/// The comparisons of angle_comparisons_2d/3d and within_rounding_of_segment: random calls (the
/// filters), integer ties (exact stages), 2^-600-scaled ones (scaled back into the window) and
/// 1e-300 beside 1e300 (GMP).
[[maybe_unused]] void exercise_comparisons() {
    std::mt19937_64 rng(8);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (int n = 0; n < 400; ++n) {
        double p[8][3];
        for (auto& q : p) {
            for (double& x : q) x = unit(rng);
        }
        const int kind = n % 4;
        if (kind == 1) {
            for (auto& q : p) {
                for (double& x : q) x = static_cast<double>(static_cast<int>(4 * x));
            }
        } else if (kind == 2) {
            for (auto& q : p) {
                for (double& x : q) x *= 0x1p-600;
            }
        } else if (kind == 3) {
            p[0][0] = 1e300;
            p[1][1] = 1e-300;
        }
        const pr::Corner a{p[0], p[1], p[2]}, b{p[3], p[4], p[5]};
        pr::compare_angles(a, b);
        pr::compare_lengths(p[0], p[1], p[2], p[3]);
        pr::corner_dot_sign(p[0], p[1], p[2]);
        pr::direction_dot_sign(p[0], p[1], p[2], p[3]);
        pr::within_rounding_of_segment(p[0], p[1], p[2]);
        const pr::TetCorners s{p[0], p[1], p[2], p[3]}, t{p[4], p[5], p[6], p[7]};
        pr::compare_dihedral({s, 0, 1}, {t, 2, 3});
        pr::compare_volume_edge(s, t);
    }
}

[[maybe_unused]] void expect_sum(const char* name, const pr::StageCounts& c) {
    SCOPED_TRACE(name);
    EXPECT_EQ(c.calls, 400u);
    EXPECT_EQ(c.calls, stage_sum(c));
    EXPECT_GT(c.filter, 0u);
    // 1e300 beside 1e-300: GMP, but for direction_dot_sign, whose long double stage (counted as
    // adaptive) decides such spans.
    if (std::string(name) == "direction_dot_sign") {
        EXPECT_GT(c.adaptive, 0u);
    } else {
        EXPECT_GT(c.gmp, 0u) << "1e300 beside 1e-300";
    }
}

}  // namespace

// Each build registers the test that means something in it, so neither skips: scripts/test
// runs this one in the `stats` build (EXACTMESH_PREDICATE_STATS), the other in release.
#if defined(EXACTMESH_PREDICATE_STATS)
TEST(Predicates_Stats, CallsEqualTheSumOfStageCountsAndDegenerateInputsReachExactStages) {
    ASSERT_TRUE(pr::stats_enabled());
    pr::reset_thread_stats();
    exercise_all_stages();
    const pr::PredicateStats s = pr::thread_stats();
    expect_consistent("orient2d", s.orient2d);
    expect_consistent("incircle", s.incircle);
    expect_consistent("orient3d", s.orient3d);
    expect_consistent("insphere", s.insphere);
    pr::reset_thread_stats();
    exercise_comparisons();
    const pr::PredicateStats c = pr::thread_stats();
    const std::pair<const char*, pr::StageCounts pr::PredicateStats::*> comparisons[] = {
        {"compare_angles", &pr::PredicateStats::compare_angles},
        {"compare_lengths", &pr::PredicateStats::compare_lengths},
        {"corner_dot_sign", &pr::PredicateStats::corner_dot_sign},
        {"direction_dot_sign", &pr::PredicateStats::direction_dot_sign},
        {"compare_dihedral", &pr::PredicateStats::compare_dihedral},
        {"compare_volume_edge", &pr::PredicateStats::compare_volume_edge}};
    for (const auto& [name, counts] : comparisons) expect_sum(name, c.*counts);
    EXPECT_EQ(c.within_rounding_of_segment.calls, 400u);
    EXPECT_EQ(c.within_rounding_of_segment.calls, stage_sum(c.within_rounding_of_segment));
    EXPECT_GT(c.compare_angles.rescaled, 0u) << "2^-600 coordinates are scaled back";
    EXPECT_GT(c.corner_dot_sign.exact_differences, 0u) << "integer ties";
    pr::reset_thread_stats();
    EXPECT_EQ(pr::thread_stats().orient2d.calls, 0u);
}

#else
TEST(Predicates_Stats, CountersStayZeroWhenCompiledOut) {
    ASSERT_FALSE(pr::stats_enabled());
    pr::reset_thread_stats();
    exercise_all_stages();
    EXPECT_EQ(pr::thread_stats().orient2d.calls, 0u);
    EXPECT_EQ(pr::thread_stats().insphere.calls, 0u);
}
#endif
