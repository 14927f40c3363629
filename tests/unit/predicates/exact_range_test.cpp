// SPDX-License-Identifier: MIT
// detail::out_of_range_sign (predicates/exact_range.hpp), the out-of-range stage orient2d,
// orient3d, incircle and insphere share: an exact power-of-two rescale handed to the
// predicate's filter, then its exact stages, else GMP; with the stage counters as before.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <vector>

#include "predicates/exact_range.hpp"
#include "predicates/orient2d.hpp"
#include "predicates/stats.hpp"

namespace pr = exactmesh::predicates;
using pr::Sign;

namespace {

/// What each callback of out_of_range_sign saw.
struct Calls {
    std::vector<double> filter_input, exact_input;
    int filters = 0, exacts = 0, gmps = 0;
};

Sign run(Calls& calls, std::optional<Sign> filter_answer, std::initializer_list<double> xs) {
    return pr::detail::out_of_range_sign<6>(
        &pr::PredicateStats::orient2d, 2, xs,
        [&](const double* s) {
            ++calls.filters;
            calls.filter_input.assign(s, s + 6);
            return filter_answer;
        },
        [&](const double* s) {
            ++calls.exacts;
            calls.exact_input.assign(s, s + 6);
            return Sign::Positive;
        },
        [&] {
            ++calls.gmps;
            return Sign::Zero;
        });
}

}  // namespace

TEST(Predicates_ExactRange, OutOfRangeSignHandsTheExactlyRescaledCopyToFilterThenExact) {
    const double k = 0x1p600;
    const std::vector<double> xs = {3 * k, 5 * k, -k, 7 * k, 0.0, 2 * k};
    Calls calls;
    pr::reset_thread_stats();
    EXPECT_EQ(run(calls, std::nullopt, {xs[0], xs[1], xs[2], xs[3], xs[4], xs[5]}), Sign::Positive);
    EXPECT_EQ(calls.filters, 1);
    EXPECT_EQ(calls.exacts, 1);
    EXPECT_EQ(calls.gmps, 0);
    // The largest magnitude, 7 * 2^600, lands in [1, 2): every coordinate times 2^-602, exactly.
    ASSERT_EQ(calls.filter_input.size(), 6u);
    for (std::size_t i = 0; i < 6; ++i) {
        EXPECT_EQ(calls.filter_input[i], std::ldexp(xs[i], -602)) << i;
        EXPECT_EQ(calls.exact_input[i], calls.filter_input[i]) << i;
    }
    const pr::StageCounts& counts = pr::thread_stats().orient2d;
    EXPECT_EQ(counts.rescaled, pr::stats_enabled() ? 1u : 0u);
    EXPECT_EQ(counts.filter, 0u);
    EXPECT_EQ(counts.gmp, 0u);
}

TEST(Predicates_ExactRange, OutOfRangeSignReturnsTheFilterSignWithoutTheExactStages) {
    Calls calls;
    pr::reset_thread_stats();
    EXPECT_EQ(run(calls, Sign::Negative, {0x1p-700, 0x1p-699, 0.0, 0x1p-698, -0x1p-700, 0.0}),
              Sign::Negative);
    EXPECT_EQ(calls.filters, 1);
    EXPECT_EQ(calls.exacts, 0);
    EXPECT_EQ(calls.gmps, 0);
    EXPECT_EQ(calls.filter_input[3], 1.0);  // 2^-698 scaled by 2^698
    const pr::StageCounts& counts = pr::thread_stats().orient2d;
    EXPECT_EQ(counts.rescaled, pr::stats_enabled() ? 1u : 0u);
    EXPECT_EQ(counts.filter, pr::stats_enabled() ? 1u : 0u);
}

TEST(Predicates_ExactRange, OutOfRangeSignGoesToGmpWhenNoRescaleIsExact) {
    // A subnormal beside 1: scaling by 2^0 leaves its lowest bit below 2^-537 (degree 2).
    Calls calls;
    pr::reset_thread_stats();
    EXPECT_EQ(run(calls, Sign::Positive, {1.0, 0x1p-1074, 0.0, 1.0, 0.5, 0.0}), Sign::Zero);
    EXPECT_EQ(calls.filters, 0);
    EXPECT_EQ(calls.exacts, 0);
    EXPECT_EQ(calls.gmps, 1);
    const pr::StageCounts& counts = pr::thread_stats().orient2d;
    EXPECT_EQ(counts.rescaled, 0u);
    EXPECT_EQ(counts.gmp, pr::stats_enabled() ? 1u : 0u);
}

TEST(Predicates_ExactRange, Orient2dOutOfRangeKeepsTheSignOfTheUnscaledPoints) {
    // Through the real predicate: at 2^600 (rescaled) and with a subnormal (GMP).
    const double a[2] = {0.0, 0.0}, b[2] = {1.0, 0.0}, c[2] = {0.25, 0x1p-60};
    for (const double scale : {0x1p600, 0x1p-600}) {
        const double as[2] = {a[0] * scale, a[1] * scale}, bs[2] = {b[0] * scale, b[1] * scale};
        const double cs[2] = {c[0] * scale, c[1] * scale};
        EXPECT_EQ(pr::orient2d(as, bs, cs), Sign::Positive) << scale;
        EXPECT_EQ(pr::orient2d(bs, as, cs), Sign::Negative) << scale;
    }
    const double p[2] = {1.0, 0.0}, q[2] = {0x1p-1074, 0.0}, r[2] = {0.5, 0x1p-1074};
    EXPECT_EQ(pr::orient2d(p, q, r), Sign::Negative);
}
