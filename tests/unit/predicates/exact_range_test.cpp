// SPDX-License-Identifier: MIT
// detail::out_of_range_sign (predicates/exact_range.hpp), the out-of-range stage orient2d,
// orient3d, incircle and insphere share: an exact power-of-two rescale handed to the
// predicate's filter, then its exact stages, else GMP; with the stage counters as before.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "predicates/exact_range.hpp"
#include "predicates/exact_reference.hpp"
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

TEST(Predicates_ExactRange, Orient2dScaledPerAxisKeepsTheSignOfTheUnscaledPoints) {
    // orient2d_exact's first stage scales the differences by a power of two per axis (the
    // sign of det is unchanged, the filter's Gappa model normalises each axis so): x and y
    // moved far apart in magnitude, on and a unit off the line y = 2x - 3, against the same
    // integer points at 2^0. Every scaling is exact (small integers times powers of two).
    std::uint64_t state = 20261207;
    auto next = [&] {
        state = state * 6364136223846793005ULL + 1442695040888963407ULL;
        return static_cast<int>((state >> 33) % 2001) - 1000;
    };
    for (const auto& [kx, ky] :
         {std::pair{600, -600}, std::pair{-600, 600}, std::pair{600, 600}, std::pair{-600, -600},
          std::pair{1000, -1000}, std::pair{0, -1020}}) {
        for (int trial = 0; trial < 2000; ++trial) {
            double p[3][2];
            for (auto& q : p) {
                const int x = next();
                q[0] = x, q[1] = 2.0 * x - 3 + (trial % 3 == 0 ? 0 : next() % 2);
            }
            double s[3][2];
            for (int i = 0; i < 3; ++i)
                s[i][0] = std::ldexp(p[i][0], kx), s[i][1] = std::ldexp(p[i][1], ky);
            ASSERT_EQ(pr::orient2d(s[0], s[1], s[2]), pr::orient2d(p[0], p[1], p[2]))
                << kx << " " << ky << " trial " << trial;
        }
    }
}

TEST(Predicates_ExactRange, Orient2dOutOfTheFilterRangeMatchesTheExactSign) {
    // Out of the filter's range, orient2d_exact first filters the differences scaled per axis,
    // then rescales all six coordinates for its exact stages, or asks GMP. Points on, a unit in
    // the last place off, and far off lines through points of mixed magnitudes (differences
    // 2^-700 to 1 of the largest on an axis, around the 2^-484 past which products of scaled
    // differences underflow; exact and rounded differences), at 2^600 and 2^-600, against the
    // exact reference (GMP), in two rotations.
    std::uint64_t state = 52;
    auto next = [&] {
        state = state * 6364136223846793005ULL + 1442695040888963407ULL;
        return state >> 11;
    };
    auto unit = [&] { return static_cast<double>(next()) * 0x1p-53; };  // [0, 1), 53 bits
    const int gaps[] = {0, -10, -52, -300, -483, -484, -485, -600, -700};
    int zeros = 0;
    for (const int scale : {600, -600}) {
        for (int trial = 0; trial < 3000; ++trial) {
            const double gx = std::ldexp(1.0, gaps[next() % 9]);
            const double gy = std::ldexp(1.0, gaps[next() % 9]);
            // c, then a and b at offsets on the lattice of c's last place (exact differences)
            // or anywhere (rounded ones), then b moved onto or beside the line through a and c.
            double c[2] = {1 + unit(), 1 + unit()};
            const bool lattice = next() % 2 == 0;
            auto offset = [&](double g) {
                const double d = g * (unit() - 0.5);
                return lattice ? std::ldexp(std::round(std::ldexp(d, 52)), -52) : d;
            };
            double a[2] = {c[0] + offset(gx), c[1] + offset(gy)};
            double b[2] = {c[0] + 2 * (a[0] - c[0]), c[1] + 2 * (a[1] - c[1])};  // on the line
            switch (next() % 3) {
                case 0:
                    break;
                case 1:
                    b[1] = std::nextafter(b[1], 3.0);
                    break;
                default:
                    b[0] = c[0] + offset(gx), b[1] = c[1] + offset(gy);
                    break;
            }
            double s[3][2];
            for (int k = 0; k < 2; ++k) {
                s[0][k] = std::ldexp(a[k], scale);
                s[1][k] = std::ldexp(b[k], scale);
                s[2][k] = std::ldexp(c[k], scale);
            }
            const Sign want = pr::reference::orient2d(s[0], s[1], s[2]);
            ASSERT_EQ(pr::orient2d(s[0], s[1], s[2]), want) << scale << " trial " << trial;
            ASSERT_EQ(pr::orient2d(s[1], s[2], s[0]), want) << scale << " trial " << trial;
            zeros += want == Sign::Zero ? 1 : 0;
        }
    }
    EXPECT_GT(zeros, 300);  // exact zeros, which no filter decides, are among them
}
