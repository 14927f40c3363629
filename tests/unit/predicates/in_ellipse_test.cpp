// SPDX-License-Identifier: MIT
// in_ellipse and compare_metric_lengths against the GMP reference (predicates/exact_reference.*):
// random points under random metrics with condition numbers up to 10^12, points on an ellipse
// rounded to doubles (the near-degenerate cases stretched meshes produce), exact ties and their
// symbolic perturbation, the identity metric against incircle and compare_lengths, and extreme
// magnitudes of the coordinates and of the metric. The two-term stage (on the exact differences)
// against its proven bound, and the stage counters where the build has them.
#include <gtest/gtest.h>

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "base/errors.hpp"
#include "predicates/angle_comparisons_2d.hpp"
#include "predicates/exact_reference.hpp"
#include "predicates/filter_constants.hpp"
#include "predicates/in_ellipse.hpp"
#include "predicates/incircle.hpp"
#include "predicates/metric_lengths.hpp"
#include "predicates/sos.hpp"
#include "predicates/stats.hpp"
#include "predicates/two_term.hpp"
#include "tests/support/test_scale.hpp"

namespace pr = exactmesh::predicates;
using pr::Sign;

namespace {

long scaled(long count) {
    return std::max(1L, static_cast<long>(std::ceil(static_cast<double>(count) *
                                                    exactmesh::testing::test_scale())));
}

using Point = std::array<double, 2>;
using Metric = std::array<double, 3>;  // M11, M12, M22

/// R(theta) diag(1 / h1^2, 1 / h2^2) R(theta)^T, rounded entry by entry.
Metric metric_of(double theta, double h1, double h2) {
    const double c = std::cos(theta), s = std::sin(theta);
    const double l1 = 1.0 / (h1 * h1), l2 = 1.0 / (h2 * h2);
    return {c * c * l1 + s * s * l2, c * s * (l1 - l2), s * s * l1 + c * c * l2};
}

/// A random SPD metric: random direction, sizes 1 and 10^-k, k uniform in [0, 6] (condition
/// number up to 10^12).
Metric random_metric(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> angle(0.0, 2.0 * std::acos(-1.0));
    std::uniform_real_distribution<double> exponent(0.0, 6.0);
    return metric_of(angle(rng), 1.0, std::pow(10.0, -exponent(rng)));
}

Sign full(const Point& a, const Point& b, const Point& c, const Point& d, const Metric& m) {
    return pr::in_ellipse(a.data(), b.data(), c.data(), d.data(), m.data());
}

Sign reference(const Point& a, const Point& b, const Point& c, const Point& d, const Metric& m) {
    return pr::reference::in_ellipse(a.data(), b.data(), c.data(), d.data(), m.data());
}

/// The adaptive predicate, its exact stages and the filter (when it answers) all agree with the
/// reference; returns the reference sign.
Sign expect_agreement(const Point& a, const Point& b, const Point& c, const Point& d,
                      const Metric& m) {
    const Sign want = reference(a, b, c, d, m);
    EXPECT_EQ(full(a, b, c, d, m), want);
    EXPECT_EQ(pr::in_ellipse_exact(a.data(), b.data(), c.data(), d.data(), m.data()), want);
    if (const auto s = pr::in_ellipse_filter(a.data(), b.data(), c.data(), d.data(), m.data())) {
        EXPECT_EQ(*s, want);
    }
    return want;
}

TEST(InEllipse, SignConventionAndTheMetricDecides) {
    // a, b, c counter-clockwise on the ellipse x^2 + 4 y^2 = 16 (M = diag(1, 4)).
    const Point a{4, 0}, b{0, 2}, c{-4, 0};
    const Metric m{1, 0, 4};
    EXPECT_EQ(full(a, b, c, Point{0, 0}, m), Sign::Positive);     // the centre: inside
    EXPECT_EQ(full(a, b, c, Point{0, -2.4}, m), Sign::Negative);  // outside the ellipse ...
    const Point d{0, -2.4};
    // ... but inside the circle through a, b, c (centre (0, -3), radius 5).
    EXPECT_EQ(pr::incircle(a.data(), b.data(), c.data(), d.data()), Sign::Positive);
    EXPECT_EQ(full(a, b, c, Point{0, -2}, m), Sign::Zero);     // on the ellipse
    EXPECT_EQ(full(c, b, a, Point{0, 0}, m), Sign::Negative);  // clockwise: the sign flips
}

TEST(InEllipse, RandomPointsUnderIllConditionedMetricsMatchTheReference) {
    std::mt19937_64 rng(20261202);
    std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
    auto point = [&] { return Point{coordinate(rng), coordinate(rng)}; };
    std::array<long, 3> signs{};
    for (long i = 0; i < scaled(20000); ++i) {
        const Metric m = random_metric(rng);
        const Sign s = expect_agreement(point(), point(), point(), point(), m);
        ++signs[static_cast<std::size_t>(static_cast<int>(s) + 1)];
    }
    EXPECT_GT(signs[0], 0);
    EXPECT_GT(signs[2], 0);
}

TEST(InEllipse, PointsOnAnEllipseRoundedToDoublesMatchTheReference) {
    // Four points on one ellipse (centre, direction, sizes random; aspect up to 10^6), each
    // coordinate rounded once: determinants a few ulps from zero, where the filter must abstain.
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const double pi = std::acos(-1.0);
    long abstained = 0, cases = scaled(20000);
    for (long i = 0; i < cases; ++i) {
        const double theta = 2.0 * pi * unit(rng), h1 = 1.0 + unit(rng);
        const double h2 = h1 * std::pow(10.0, -6.0 * unit(rng));
        const Point o{unit(rng) * 100.0, unit(rng) * 100.0};
        const double c = std::cos(theta), s = std::sin(theta);
        auto on_ellipse = [&](double t) {
            const double u = h1 * std::cos(t), v = h2 * std::sin(t);
            return Point{o[0] + c * u - s * v, o[1] + s * u + c * v};
        };
        std::array<double, 4> t{};
        for (double& x : t) x = 2.0 * pi * unit(rng);
        std::sort(t.begin(), t.end());
        const Metric m = metric_of(theta, h1, h2);
        const Point a = on_ellipse(t[0]), b = on_ellipse(t[1]), cc = on_ellipse(t[2]);
        const Point d = on_ellipse(t[3]);
        expect_agreement(a, b, cc, d, m);
        if (!pr::in_ellipse_filter(a.data(), b.data(), cc.data(), d.data(), m.data())) {
            ++abstained;
        }
    }
    EXPECT_GT(abstained, 0);  // the exact stages were exercised
}

/// Four points on one ellipse (centre in [0, 100)^2, random direction, sizes h1 in [1, 2) and
/// h1 10^-k, k in [0, 6]: condition numbers up to 10^12), each coordinate rounded once, and the
/// ellipse's metric rounded entry by entry; then d moved by `ulps` representable doubles in x.
std::array<Point, 4> points_on_an_ellipse(std::mt19937_64& rng, Metric& m, int ulps) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const double pi = std::acos(-1.0);
    const double theta = 2.0 * pi * unit(rng), h1 = 1.0 + unit(rng);
    const double h2 = h1 * std::pow(10.0, -6.0 * unit(rng));
    const Point o{unit(rng) * 100.0, unit(rng) * 100.0};
    const double c = std::cos(theta), s = std::sin(theta);
    std::array<double, 4> t{};
    for (double& x : t) x = 2.0 * pi * unit(rng);
    std::sort(t.begin(), t.end());
    std::array<Point, 4> p{};
    for (int k = 0; k < 4; ++k) {
        const double u = h1 * std::cos(t[k]), v = h2 * std::sin(t[k]);
        p[k] = {o[0] + c * u - s * v, o[1] + s * u + c * v};
    }
    for (int k = 0; k < std::abs(ulps); ++k) {
        p[3][0] = std::nextafter(p[3][0], ulps > 0 ? 1e300 : -1e300);
    }
    m = metric_of(theta, h1, h2);
    return p;
}

TEST(InEllipse, TwoTermStageIsWithinItsProvenBound) {
    // |hi + lo - Det| <= 138.3125 u^2 P over the exact differences (proofs/gappa/
    // two_term_in_ellipse.g), P the permanent: on random points (differences mostly inexact, so
    // the tails matter), rounded ellipse points and integer ties (Det = 0), under metrics with
    // condition numbers up to 10^12.
    using pr::reference::exact;
    std::mt19937_64 rng(141);
    std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
    std::uniform_int_distribution<int> small(-3, 3);
    const mpq_class bound_units = mpq_class(138.3125) * mpq_class(0x1p-53) * mpq_class(0x1p-53);
    double worst = 0.0;  // observed |hi + lo - Det| / (u^2 P)
    for (long i = 0; i < scaled(20000); ++i) {
        Metric m{};
        std::array<Point, 4> p{};
        switch (i % 3) {
            case 0:
                m = random_metric(rng);
                for (Point& x : p) x = {coordinate(rng), coordinate(rng) * 1e-3};
                break;
            case 1:
                p = points_on_an_ellipse(rng, m, 0);
                break;
            default:
                m = {1, 0, 4};
                for (Point& x : p) x = {double(small(rng)), double(small(rng))};
                break;
        }
        pr::detail::TwoTerm pairs[6];
        mpq_class x[6];
        for (int r = 0; r < 3; ++r) {
            for (int k = 0; k < 2; ++k) {
                pr::two_diff(p[r][k], p[3][k], pairs[2 * r + k].hi, pairs[2 * r + k].lo);
                x[2 * r + k] = exact(p[r][k]) - exact(p[3][k]);
            }
        }
        const pr::detail::TwoTerm t =
            pr::detail::in_ellipse_two_term(pairs, m[0], 2.0 * m[1], m[2]);
        const mpq_class m11 = exact(m[0]), m12x2 = 2 * exact(m[1]), m22 = exact(m[2]);
        mpq_class det = 0, permanent = 0;
        for (int r = 0; r < 3; ++r) {
            const mpq_class &vx = x[2 * r], &vy = x[2 * r + 1];
            const mpq_class &px = x[(2 * r + 2) % 6], &py = x[(2 * r + 3) % 6];
            const mpq_class &qx = x[(2 * r + 4) % 6], &qy = x[(2 * r + 5) % 6];
            det += (m11 * vx * vx + m12x2 * vx * vy + m22 * vy * vy) * (px * qy - qx * py);
            permanent += (abs(m11 * vx * vx) + abs(m12x2 * vx * vy) + abs(m22 * vy * vy)) *
                         (abs(px * qy) + abs(qx * py));
        }
        const mpq_class error = abs(exact(t.hi) + exact(t.lo) - det);
        ASSERT_LE(error, bound_units * permanent) << "case " << i;
        if (permanent > 0) {
            const mpq_class ratio = error / (permanent * mpq_class(0x1p-53) * mpq_class(0x1p-53));
            worst = std::max(worst, ratio.get_d());
        }
    }
    EXPECT_LT(worst, 138.3125);
    RecordProperty("worst_error_in_u2_permanent", std::to_string(worst));
}

TEST(InEllipse, TheTwoTermStageDecidesRoundedEllipsePointsAtEveryScale) {
    // Rounded ellipse points, and the same with d moved by up to 4 ulps (random near-degenerate
    // inputs), at 2^0 and with the points scaled by 2^+-600 and the metric by 2^+-500 (the
    // rescaled copy): every sign matches the reference. With stage counters, the two-term stage
    // decides nearly every call the filter leaves, at every scale; no call reaches GMP.
    std::mt19937_64 rng(2027);
    std::uniform_int_distribution<int> ulps(-4, 4);
    const std::array<std::array<int, 2>, 5> scales = {
        {{0, 0}, {-600, -500}, {600, 500}, {-600, 500}, {600, -500}}};
    pr::reset_thread_stats();
    long calls = 0;
    for (long i = 0; i < scaled(4000); ++i) {
        Metric m{};
        const std::array<Point, 4> p = points_on_an_ellipse(rng, m, i % 2 == 0 ? 0 : ulps(rng));
        const Sign want = reference(p[0], p[1], p[2], p[3], m);
        for (const auto& [k, j] : scales) {
            std::array<Point, 4> q = p;
            for (Point& x : q) x = {std::ldexp(x[0], k), std::ldexp(x[1], k)};
            const Metric n{std::ldexp(m[0], j), std::ldexp(m[1], j), std::ldexp(m[2], j)};
            EXPECT_EQ(full(q[0], q[1], q[2], q[3], n), want) << "2^" << k << ", M 2^" << j;
            ++calls;
        }
    }
    const pr::StageCounts c = pr::thread_stats().in_ellipse;
    if (pr::stats_enabled()) {
        EXPECT_EQ(c.calls, static_cast<std::uint64_t>(calls));
        EXPECT_EQ(c.calls, c.filter + c.exact_differences + c.adaptive + c.expansion + c.gmp);
        EXPECT_EQ(c.gmp, 0u);
        EXPECT_GT(c.rescaled, 0u);
        const std::uint64_t left = c.calls - c.filter;
        EXPECT_GT(left, c.calls / 4) << "the filter must abstain on most of these";
        EXPECT_GE(c.adaptive * 1000, left * 999) << "adaptive " << c.adaptive << " of " << left;
        RecordProperty("calls_filter_adaptive_exact_differences_expansion",
                       std::to_string(c.calls) + " " + std::to_string(c.filter) + " " +
                           std::to_string(c.adaptive) + " " + std::to_string(c.exact_differences) +
                           " " + std::to_string(c.expansion));
    } else {
        EXPECT_EQ(c.calls, 0u);
    }
}

TEST(InEllipse, TheTwoTermStageLeavesTiesAndTinyBoundsToTheExpansions) {
    // Integer ties (Det = 0) can never be certified; and where the stage's bound would fall
    // below the normal range (differences 2^-210 and a metric of 2^-100, all of few bits, so
    // expansion-safe without rescaling), it must stand aside rather than trust a rounded bound.
    pr::reset_thread_stats();
    const Metric m{1, 0, 4};
    EXPECT_EQ(expect_agreement({10, 0}, {6, 4}, {-6, 4}, {0, -5}, m), Sign::Zero);
    const pr::StageCounts ties = pr::thread_stats().in_ellipse;
    const double t = 0x1p-210;
    const Metric tiny_metric{0x1p-100, 0x1p-102, 0x1p-101};
    const Point a{t, 0}, b{0, t}, c{-t, 0}, d{0, -t / 2};
    const Sign want = reference(a, b, c, d, tiny_metric);
    EXPECT_NE(want, Sign::Zero);
    EXPECT_EQ(full(a, b, c, d, tiny_metric), want);
    const pr::StageCounts after = pr::thread_stats().in_ellipse;
    if (pr::stats_enabled()) {
        EXPECT_EQ(ties.adaptive, 0u);
        EXPECT_GT(ties.exact_differences, 0u);
        EXPECT_EQ(after.adaptive, 0u);
        EXPECT_EQ(after.rescaled, 0u);
        EXPECT_GT(after.exact_differences, ties.exact_differences);
    }
}

TEST(InEllipse, TheIdentityMetricIsIncircleOnRandomAndDegenerateInputs) {
    std::mt19937_64 rng(11);
    std::uniform_int_distribution<int> small(-3, 3);
    std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
    const Metric identity{1, 0, 1};
    for (long i = 0; i < scaled(20000); ++i) {
        const bool grid = i % 2 == 0;  // a 7 x 7 grid: exact cocircularities and collinearities
        auto point = [&] {
            return grid ? Point{double(small(rng)), double(small(rng))}
                        : Point{coordinate(rng), coordinate(rng)};
        };
        const Point a = point(), b = point(), c = point(), d = point();
        EXPECT_EQ(full(a, b, c, d, identity), pr::incircle(a.data(), b.data(), c.data(), d.data()));
        const std::uint32_t ia = 3, ib = 0, ic = 7, id = 5;
        EXPECT_EQ(pr::in_ellipse_sos(a.data(), b.data(), c.data(), d.data(), identity.data(), ia,
                                     ib, ic, id),
                  pr::incircle_sos(a.data(), b.data(), c.data(), d.data(), ia, ib, ic, id));
    }
}

TEST(InEllipse, ExactTiesOnAnIntegerEllipseAndTheirPerturbation) {
    // x^2 + 4 y^2 = 100 through eight integer points: every four of them are ellipse-cocircular.
    const std::vector<Point> ring = {{10, 0}, {8, 3},   {6, 4},  {0, 5},
                                     {-6, 4}, {-8, -3}, {0, -5}, {6, -4}};
    const Metric m{1, 0, 4};
    std::uint32_t ties = 0;
    for (std::size_t i = 0; i < ring.size(); ++i) {
        for (std::size_t j = 0; j < ring.size(); ++j) {
            for (std::size_t k = 0; k < ring.size(); ++k) {
                for (std::size_t l = 0; l < ring.size(); ++l) {
                    if (i == j || i == k || i == l || j == k || j == l || k == l) continue;
                    const Point &a = ring[i], &b = ring[j], &c = ring[k], &d = ring[l];
                    ASSERT_EQ(expect_agreement(a, b, c, d, m), Sign::Zero);
                    ++ties;
                    const auto ia = static_cast<std::uint32_t>(i),
                               ib = static_cast<std::uint32_t>(j);
                    const auto ic = static_cast<std::uint32_t>(k),
                               id = static_cast<std::uint32_t>(l);
                    const Sign perturbed = pr::in_ellipse_sos(a.data(), b.data(), c.data(),
                                                              d.data(), m.data(), ia, ib, ic, id);
                    EXPECT_NE(perturbed, Sign::Zero);
                    EXPECT_EQ(perturbed,
                              pr::reference::in_ellipse_sos(a.data(), b.data(), c.data(), d.data(),
                                                            m.data(), ia, ib, ic, id));
                }
            }
        }
    }
    EXPECT_EQ(ties, 8u * 7u * 6u * 5u);
}

TEST(InEllipse, PowerOfTwoScalingsOfPointsAndMetricKeepTheSign) {
    // Coordinates scaled by 2^k and the metric by 2^j, far outside the filter's and the
    // expansions' ranges: the same sign (rescaled exactly or decided by GMP), as the reference
    // says.
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
    const int point_scales[] = {-600, -300, 0, 300, 600};
    const int metric_scales[] = {-500, -200, 0, 200, 500};
    for (long i = 0; i < scaled(300); ++i) {
        const Metric m = random_metric(rng);
        std::array<Point, 4> p{};
        for (Point& x : p) x = {coordinate(rng), coordinate(rng)};
        if (i % 3 == 0) p[3] = p[0];  // a repeated point: Zero at every scale
        const Sign want = reference(p[0], p[1], p[2], p[3], m);
        for (const int k : point_scales) {
            for (const int j : metric_scales) {
                std::array<Point, 4> q = p;
                for (Point& x : q) x = {std::ldexp(x[0], k), std::ldexp(x[1], k)};
                const Metric n{std::ldexp(m[0], j), std::ldexp(m[1], j), std::ldexp(m[2], j)};
                EXPECT_EQ(full(q[0], q[1], q[2], q[3], n), want) << "2^" << k << ", M 2^" << j;
            }
        }
    }
}

TEST(InEllipse, SubnormalAndMixedMagnitudesGoToExactArithmetic) {
    const double tiny = std::numeric_limits<double>::denorm_min();
    const Metric m{3, -1, 0x1p-40};
    const std::vector<std::array<Point, 4>> cases = {
        {{{tiny, 0}, {0, tiny}, {-tiny, 2 * tiny}, {3 * tiny, -tiny}}},
        {{{1, 0}, {0, tiny}, {-1e300, 2}, {3 * tiny, -1}}},
        {{{0x1p-1000, 1}, {0x1p+900, -1}, {5, 0x1p-1070}, {0, 0}}},
    };
    for (const auto& p : cases) expect_agreement(p[0], p[1], p[2], p[3], m);
    const Metric subnormal_metric{tiny, 0, 1};
    for (const auto& p : cases) expect_agreement(p[0], p[1], p[2], p[3], subnormal_metric);
}

TEST(InEllipse, TheFilterRespectsItsRangeGuards) {
    // Largest difference exactly at the guards: certified inside, abstains just outside.
    const Metric m{1, 0, 1};
    for (const double scale : {pr::in_ellipse_filter_min, pr::in_ellipse_filter_max}) {
        const Point a{scale, 0}, b{0, scale}, c{-scale, 0}, d{0, 0};
        EXPECT_EQ(pr::in_ellipse_filter(a.data(), b.data(), c.data(), d.data(), m.data()),
                  std::optional<Sign>(Sign::Positive));
        const double out = scale == pr::in_ellipse_filter_min ? scale / 2 : scale * 2;
        const Point a2{out, 0}, b2{0, out}, c2{-out, 0};
        EXPECT_FALSE(pr::in_ellipse_filter(a2.data(), b2.data(), c2.data(), d.data(), m.data()));
        EXPECT_EQ(full(a2, b2, c2, d, m), Sign::Positive);
    }
    const Point a{1, 0}, b{0, 1}, c{-1, 0}, d{0, 0};
    const Metric small{pr::in_ellipse_filter_min / 2, 0, pr::in_ellipse_filter_min / 2};
    EXPECT_FALSE(pr::in_ellipse_filter(a.data(), b.data(), c.data(), d.data(), small.data()));
    EXPECT_EQ(full(a, b, c, d, small), Sign::Positive);
}

TEST(InEllipse, NonFiniteInputIsAnError) {
    const Point a{1, 0}, b{0, 1}, c{-1, 0}, d{0, 0};
    const Metric bad{std::numeric_limits<double>::quiet_NaN(), 0, 1};
    EXPECT_THROW(pr::in_ellipse(a.data(), b.data(), c.data(), d.data(), bad.data()),
                 exactmesh::GeometryError);
    const Point inf{std::numeric_limits<double>::infinity(), 0};
    const Metric m{1, 0, 1};
    EXPECT_THROW(pr::in_ellipse(a.data(), b.data(), c.data(), inf.data(), m.data()),
                 exactmesh::GeometryError);
}

// ---------------------------------------------------------------------------------------------
// compare_metric_lengths

Sign reference_lengths(const Point& p1, const Point& q1, const Metric& m1, const Point& p2,
                       const Point& q2, const Metric& m2) {
    using pr::reference::exact;
    auto square = [](const Point& p, const Point& q, const Metric& m) {
        const mpq_class x = exact(q[0]) - exact(p[0]), y = exact(q[1]) - exact(p[1]);
        return mpq_class(exact(m[0]) * x * x + 2 * exact(m[1]) * x * y + exact(m[2]) * y * y);
    };
    return pr::reference::sign_of(square(p1, q1, m1) - square(p2, q2, m2));
}

Sign lengths(const Point& p1, const Point& q1, const Metric& m1, const Point& p2, const Point& q2,
             const Metric& m2) {
    const Sign s = pr::compare_metric_lengths(p1.data(), q1.data(), m1.data(), p2.data(), q2.data(),
                                              m2.data());
    if (const auto f = pr::compare_metric_lengths_filter(p1.data(), q1.data(), m1.data(), p2.data(),
                                                         q2.data(), m2.data())) {
        EXPECT_EQ(*f, s);
    }
    return s;
}

TEST(CompareMetricLengths, RandomEdgesAndMetricsMatchTheReference) {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
    auto point = [&] { return Point{coordinate(rng), coordinate(rng)}; };
    for (long i = 0; i < scaled(20000); ++i) {
        const Metric m1 = random_metric(rng);
        const Metric m2 = i % 2 == 0 ? m1 : random_metric(rng);
        const Point p1 = point(), q1 = point(), p2 = point();
        // Every fourth case the second edge is the first one mirrored (close lengths when the
        // metrics are close; equal when they are the same and M12 = 0).
        const Point q2 =
            i % 4 == 1 ? Point{p2[0] + (q1[0] - p1[0]), p2[1] - (q1[1] - p1[1])} : point();
        EXPECT_EQ(lengths(p1, q1, m1, p2, q2, m2), reference_lengths(p1, q1, m1, p2, q2, m2));
    }
}

TEST(CompareMetricLengths, TiesTheIdentityAndExtremeScales) {
    const Metric identity{1, 0, 1}, m{1, 0, 4};
    // (0,0)-(3,4) and (0,0)-(5,0) have the same Euclidean length; in x^2 + 4 y^2, 9 + 64 > 25.
    const Point o{0, 0}, p{3, 4}, q{5, 0};
    EXPECT_EQ(lengths(o, p, identity, o, q, identity), Sign::Zero);
    EXPECT_EQ(lengths(o, p, m, o, q, m), Sign::Positive);
    EXPECT_EQ(lengths(o, q, m, o, p, m), Sign::Negative);
    // (0,0)-(10,0) and (0,0)-(0,5) are both 10 long in M = diag(1, 4).
    EXPECT_EQ(lengths(o, Point{10, 0}, m, o, Point{0, 5}, m), Sign::Zero);
    std::mt19937_64 rng(9);
    std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
    for (long i = 0; i < scaled(2000); ++i) {
        const Point p1{coordinate(rng), coordinate(rng)}, q1{coordinate(rng), coordinate(rng)};
        const Point p2{coordinate(rng), coordinate(rng)}, q2{coordinate(rng), coordinate(rng)};
        EXPECT_EQ(lengths(p1, q1, identity, p2, q2, identity),
                  pr::compare_lengths(p1.data(), q1.data(), p2.data(), q2.data()));
        const Metric m1 = random_metric(rng), m2 = random_metric(rng);
        const Sign want = reference_lengths(p1, q1, m1, p2, q2, m2);
        for (const int k : {-600, -250, 250, 600}) {
            for (const int j : {-400, 0, 400}) {
                auto s = [k](const Point& x) {
                    return Point{std::ldexp(x[0], k), std::ldexp(x[1], k)};
                };
                auto t = [j](const Metric& x) {
                    return Metric{std::ldexp(x[0], j), std::ldexp(x[1], j), std::ldexp(x[2], j)};
                };
                EXPECT_EQ(lengths(s(p1), s(q1), t(m1), s(p2), s(q2), t(m2)), want);
            }
        }
    }
    const double tiny = std::numeric_limits<double>::denorm_min();
    const Point a{tiny, 1}, b{0, 1 + 0x1p-52}, c{1e300, 0}, d{1e300, 1e-300};
    EXPECT_EQ(lengths(a, b, m, c, d, m), reference_lengths(a, b, m, c, d, m));
    const Metric nan{std::numeric_limits<double>::quiet_NaN(), 0, 1};
    EXPECT_THROW(lengths(a, b, nan, c, d, m), exactmesh::GeometryError);
}

}  // namespace
