// SPDX-License-Identifier: MIT
// Constant metrics (generators/stretched/metric_2d.hpp): matrix <-> Metric2 round trips
// (rotated, aspect ratio 2^20 and 1e6, nearly and exactly isotropic), refusals naming the
// values, metric length against the direct formula, log-Euclidean forms and means, the
// predicate's matrix, intersection, and bit-for-bit scale invariance at 2^+-600.
#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "base/errors.hpp"
#include "generators/stretched/metric_2d.hpp"
#include "tests/support/test_scale.hpp"

namespace gen = exactmesh::generators;

namespace {

/// M = R diag(1 / h1^2, 1 / h2^2) R^T, in plain doubles (moderate sizes only).
std::array<double, 3> matrix_of(const gen::Metric2& m) {
    const double e1 = 1 / (m.h1 * m.h1), e2 = 1 / (m.h2 * m.h2);
    return {e1 * m.c * m.c + e2 * m.s * m.s, (e1 - e2) * m.c * m.s,
            e1 * m.s * m.s + e2 * m.c * m.c};
}

gen::Metric2 rotated(double h1, double h2, double angle) {
    return gen::Metric2{h1, h2, std::cos(angle), std::sin(angle)};
}

gen::Metric2 scaled(gen::Metric2 m, int k) {
    m.h1 = std::ldexp(m.h1, k);
    m.h2 = std::ldexp(m.h2, k);
    return m;
}

int cases(int base) {
    return std::max(1, static_cast<int>(base * exactmesh::testing::test_scale()));
}

std::string message_of(double m11, double m12, double m22) {
    try {
        gen::metric_from_matrix(m11, m12, m22);
    } catch (const exactmesh::InputError& error) {
        return error.what();
    }
    return "";
}

}  // namespace

TEST(Generators_Metric2d, MatrixRoundTripRotated) {
    // [2 1; 1 2]: eigenvalues 3 along (1, 1) and 1 along (-1, 1).
    const gen::Metric2 m = gen::metric_from_matrix(2, 1, 2);
    EXPECT_NEAR(m.h1, 1 / std::sqrt(3.0), 1e-15);
    EXPECT_NEAR(m.h2, 1.0, 1e-15);
    EXPECT_NEAR(std::fabs(m.c), std::sqrt(0.5), 1e-15);
    EXPECT_NEAR(m.c * m.s, 0.5, 1e-15);  // (c, s) = +-(1, 1) / sqrt 2
    std::mt19937_64 random(14);
    std::uniform_real_distribution<double> angle(-3.2, 3.2), log_size(-5, 5);
    for (int i = 0; i < cases(500); ++i) {
        const gen::Metric2 original =
            rotated(std::exp(log_size(random)), std::exp(log_size(random)), angle(random));
        const std::array<double, 3> M = matrix_of(original);
        const gen::Metric2 back = gen::metric_from_matrix(M[0], M[1], M[2]);
        const std::array<double, 3> again = matrix_of(back);
        const double norm = std::max(std::fabs(M[0]), std::fabs(M[2]));
        for (std::size_t k = 0; k < 3; ++k) EXPECT_NEAR(again[k], M[k], 1e-13 * norm) << i;
        EXPECT_LE(back.h1, back.h2);
        EXPECT_NO_THROW(gen::check_metric(back));
    }
}

TEST(Generators_Metric2d, StretchedMatrixKeepsItsSmallEigenvalue) {
    // [t+1 t-1; t-1 t+1], exact doubles for t = 2^40: eigenvalues 2t along (1, 1), 2 across:
    // aspect ratio 2^20, and the small eigenvalue exact (det by Kahan's algorithm).
    const double t = 0x1p40;
    const gen::Metric2 m = gen::metric_from_matrix(t + 1, t - 1, t + 1);
    EXPECT_DOUBLE_EQ(m.h1, 1 / std::sqrt(2 * t));
    EXPECT_NEAR(m.h2, 1 / std::sqrt(2.0), 1e-15);
    EXPECT_NEAR(m.c * m.s, 0.5, 1e-15);
    // Aspect ratio 1e6 rotated by 0.7: the large eigenvalue and direction to full accuracy; the
    // small one within what the rounded matrix entries determine (relative 1e-16 * 1e12).
    const gen::Metric2 original = rotated(1e-6, 1, 0.7);
    const std::array<double, 3> M = matrix_of(original);
    const gen::Metric2 back = gen::metric_from_matrix(M[0], M[1], M[2]);
    EXPECT_NEAR(back.h1, 1e-6, 1e-20);
    EXPECT_NEAR(back.h2, 1, 1e-3);
    EXPECT_NEAR(std::fabs(back.c * original.c + back.s * original.s), 1, 1e-15);
}

TEST(Generators_Metric2d, NearlyIsotropic) {
    const gen::Metric2 exact = gen::metric_from_matrix(4, 0, 4);
    EXPECT_EQ(exact.h1, 0.5);
    EXPECT_EQ(exact.h2, 0.5);
    EXPECT_EQ(exact.c, 1);
    EXPECT_EQ(exact.s, 0);
    // Eigenvalues 1 + 1e-14 +- hypot(1e-14, 1e-14): both sizes to full relative accuracy.
    const gen::Metric2 m = gen::metric_from_matrix(1, 1e-14, 1 + 2e-14);
    const double radius = std::hypot(1e-14, 1e-14);
    EXPECT_NEAR(m.h1, 1 / std::sqrt(1 + 1e-14 + radius), 2e-16);
    EXPECT_NEAR(m.h2, 1 / std::sqrt(1 + 1e-14 - radius), 2e-16);
    EXPECT_LT(m.h1, m.h2);
}

TEST(Generators_Metric2d, RefusalsNameTheValues) {
    std::string text = message_of(1, 2, 1);
    EXPECT_NE(text.find("(1, 2, 1) is not positive definite"), std::string::npos) << text;
    EXPECT_NE(text.find("M11 M22 - M12^2 = -3"), std::string::npos) << text;
    text = message_of(1, 1, 1);
    EXPECT_NE(text.find("singular"), std::string::npos) << text;
    text = message_of(-1, 0, 1);
    EXPECT_NE(text.find("(-1, 0, 1) is not positive definite"), std::string::npos) << text;
    text = message_of(1, NAN, 1);
    EXPECT_NE(text.find("(1, NaN, 1) is not finite"), std::string::npos) << text;
    text = message_of(1, 0, 0x1p-600);
    EXPECT_NE(text.find("aspect ratio"), std::string::npos) << text;
    EXPECT_THROW(gen::isotropic(0), exactmesh::InputError);
    EXPECT_THROW(gen::isotropic(INFINITY), exactmesh::InputError);
    EXPECT_THROW(gen::metric_from_stretching(0, 0, 1, 10), exactmesh::InputError);
    EXPECT_THROW(gen::metric_from_stretching(1, 0, 1, 0x1p251), exactmesh::InputError);
    EXPECT_NO_THROW(gen::metric_from_stretching(1, 0, 1, 0x1p250));
    EXPECT_THROW(gen::check_metric(gen::Metric2{1, 1, 1, 1}), exactmesh::InputError);
}

TEST(Generators_Metric2d, StretchingVector) {
    const gen::Metric2 m = gen::metric_from_stretching(3, 4, 2, 100);
    EXPECT_EQ(m.h1, 2);
    EXPECT_EQ(m.h2, 0.02);
    EXPECT_DOUBLE_EQ(m.c, 0.6);
    EXPECT_DOUBLE_EQ(m.s, 0.8);
    EXPECT_NEAR(gen::metric_length(m, 0.6 * 2, 0.8 * 2), 1, 1e-15);         // along: 2 long
    EXPECT_NEAR(gen::metric_length(m, -0.8 * 0.02, 0.6 * 0.02), 1, 1e-15);  // across
}

TEST(Generators_Metric2d, MetricLengthMatchesTheDirectFormula) {
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> angle(-3.2, 3.2), log_size(-2, 2), coordinate(-3, 3);
    for (int i = 0; i < cases(1000); ++i) {
        const gen::Metric2 m =
            rotated(std::exp(log_size(random)), std::exp(log_size(random)), angle(random));
        const std::array<double, 3> M = matrix_of(m);
        const double vx = coordinate(random), vy = coordinate(random);
        const double direct = std::sqrt(M[0] * vx * vx + 2 * M[1] * vx * vy + M[2] * vy * vy);
        EXPECT_NEAR(gen::metric_length(m, vx, vy), direct, 1e-12 * direct) << i;
    }
}

TEST(Generators_Metric2d, ScaleInvarianceAt2ToThe600) {
    const gen::Metric2 m = rotated(0.3, 0.001, 0.4);
    const gen::Metric2 other = rotated(0.02, 0.5, -1.1);
    const double vx = 0.123, vy = -0.0456;
    const double length = gen::metric_length(m, vx, vy);
    const std::array<gen::Metric2, 2> pair = {m, other};
    const std::array<double, 2> weights = {0.3, 0.7};
    const gen::Metric2 mean = gen::log_euclidean_mean(pair, weights);
    const gen::Metric2 both = gen::metric_intersection(m, other);
    for (const int k : {600, -600, 1, -1, 300}) {
        EXPECT_EQ(gen::metric_length(scaled(m, k), std::ldexp(vx, k), std::ldexp(vy, k)), length)
            << k;
        const std::array<gen::Metric2, 2> pair_k = {scaled(m, k), scaled(other, k)};
        const gen::Metric2 mean_k = gen::log_euclidean_mean(pair_k, weights);
        EXPECT_EQ(mean_k.h1, std::ldexp(mean.h1, k)) << k;
        EXPECT_EQ(mean_k.h2, std::ldexp(mean.h2, k)) << k;
        EXPECT_EQ(mean_k.c, mean.c) << k;
        const gen::Metric2 both_k = gen::metric_intersection(scaled(m, k), scaled(other, k));
        EXPECT_EQ(both_k.h1, std::ldexp(both.h1, k)) << k;
        EXPECT_EQ(both_k.h2, std::ldexp(both.h2, k)) << k;
        double out[3], out_k[3];
        gen::matrix_for_predicate(m, out);
        gen::matrix_for_predicate(scaled(m, k), out_k);
        for (std::size_t j = 0; j < 3; ++j) EXPECT_EQ(out_k[j], out[j]) << k;
    }
    // A matrix times 2^-1000 (sizes times 2^500) gives the sizes times 2^500 exactly.
    const gen::Metric2 base = gen::metric_from_matrix(3, 1, 2);
    const gen::Metric2 tiny = gen::metric_from_matrix(0x1p-1000 * 3, 0x1p-1000, 0x1p-1000 * 2);
    EXPECT_EQ(tiny.h1, std::ldexp(base.h1, 500));
    EXPECT_EQ(tiny.h2, std::ldexp(base.h2, 500));
}

TEST(Generators_Metric2d, LogFormRoundTripAndMeans) {
    std::mt19937_64 random(3);
    std::uniform_real_distribution<double> angle(-3.2, 3.2), log_size(-8, 8), weight(0, 1);
    for (int i = 0; i < cases(300); ++i) {
        const gen::Metric2 m =
            rotated(std::exp(log_size(random)), std::exp(log_size(random)), angle(random));
        const gen::Metric2 back = gen::metric_from_log_form(gen::log_form(m));
        const std::array<double, 3> M = matrix_of(m), again = matrix_of(back);
        const double norm = std::max(std::fabs(M[0]), std::fabs(M[2]));
        for (std::size_t k = 0; k < 3; ++k) EXPECT_NEAR(again[k], M[k], 1e-12 * norm) << i;
        // A constant field: the mean of copies is the metric itself.
        const std::array<gen::Metric2, 3> same = {m, m, m};
        const std::array<double, 3> w = {weight(random), weight(random), 0.25};
        const gen::Metric2 mean = gen::log_euclidean_mean(same, w);
        const std::array<double, 3> mean_matrix = matrix_of(mean);
        for (std::size_t k = 0; k < 3; ++k) EXPECT_NEAR(mean_matrix[k], M[k], 1e-12 * norm) << i;
        // Positive definite, and log det linear: the geometric mean of the areas h1 h2.
        const gen::Metric2 other =
            rotated(std::exp(log_size(random)), std::exp(log_size(random)), angle(random));
        const std::array<gen::Metric2, 2> pair = {m, other};
        const std::array<double, 2> pw = {0.25, 0.75};
        const gen::Metric2 between = gen::log_euclidean_mean(pair, pw);
        EXPECT_NO_THROW(gen::check_metric(between));
        const double expected = 0.25 * std::log(m.h1 * m.h2) + 0.75 * std::log(other.h1 * other.h2);
        EXPECT_NEAR(std::log(between.h1 * between.h2), expected, 1e-12 * (1 + std::fabs(expected)));
    }
    // Log entries stay of the size of ln h at 2^-1000.
    const gen::LogMetric2 deep = gen::log_form(gen::Metric2{0x1p-1000, 0x1p-990, 0.6, 0.8});
    EXPECT_TRUE(std::isfinite(deep.l11) && std::isfinite(deep.l12) && std::isfinite(deep.l22));
    EXPECT_LT(std::fabs(deep.l11), 1500);
    const std::array<gen::Metric2, 1> one = {gen::isotropic(2)};
    const std::array<double, 1> negative = {-1};
    EXPECT_THROW(gen::log_euclidean_mean(one, negative), exactmesh::InputError);
}

TEST(Generators_Metric2d, LogFormMemoGivesTheSameBits) {
    // A small memo (2^10 slots) and more keys than slots, each asked several times: hits,
    // misses and overwritten slots all return exactly what metric_from_log_form returns, and so
    // does log_euclidean_mean through the memo.
    gen::MetricFromLogFormMemo memo(1);
    std::mt19937_64 random(11);
    std::uniform_real_distribution<double> angle(-3.2, 3.2), log_size(-8, 8);
    std::vector<gen::LogMetric2> forms;
    for (int i = 0; i < cases(3000); ++i) {
        forms.push_back(gen::log_form(
            rotated(std::exp(log_size(random)), std::exp(log_size(random)), angle(random))));
    }
    // Signed zeros are different keys with (possibly) different directions.
    forms.push_back({1.0, 0.0, 1.0});
    forms.push_back({1.0, -0.0, 1.0});
    const auto same_bits = [](const gen::Metric2& a, const gen::Metric2& b) {
        return std::bit_cast<std::uint64_t>(a.h1) == std::bit_cast<std::uint64_t>(b.h1) &&
               std::bit_cast<std::uint64_t>(a.h2) == std::bit_cast<std::uint64_t>(b.h2) &&
               std::bit_cast<std::uint64_t>(a.c) == std::bit_cast<std::uint64_t>(b.c) &&
               std::bit_cast<std::uint64_t>(a.s) == std::bit_cast<std::uint64_t>(b.s);
    };
    for (int round = 0; round < 3; ++round) {
        for (std::size_t i = 0; i < forms.size(); ++i) {
            const gen::LogMetric2& f = forms[i];
            EXPECT_TRUE(same_bits(memo(f.l11, f.l12, f.l22), gen::metric_from_log_form(f)))
                << round << " " << i;
        }
    }
    EXPECT_GT(memo.hits(), 0U);
    EXPECT_GT(memo.misses(), forms.size());  // more keys than slots: some were overwritten
    EXPECT_EQ(memo.hits() + memo.misses(), 3 * forms.size());
    // Non-finite arguments throw as the function does, and are never stored.
    EXPECT_THROW(memo(std::numeric_limits<double>::quiet_NaN(), 0, 0), exactmesh::InputError);
    EXPECT_THROW(memo(std::numeric_limits<double>::quiet_NaN(), 0, 0), exactmesh::InputError);
    const std::array<double, 2> w = {0.5, 0.5};
    for (int i = 0; i + 1 < cases(200); ++i) {
        const std::array<gen::Metric2, 2> pair = {
            rotated(std::exp(log_size(random)), std::exp(log_size(random)), angle(random)),
            rotated(std::exp(log_size(random)), std::exp(log_size(random)), angle(random))};
        const gen::Metric2 direct = gen::log_euclidean_mean(pair, w);
        EXPECT_TRUE(same_bits(gen::log_euclidean_mean(pair, w, &memo), direct)) << i;
        EXPECT_TRUE(same_bits(gen::log_euclidean_mean(pair, w, &memo), direct)) << i;
    }
}

TEST(Generators_Metric2d, PredicateMatrix) {
    const gen::Metric2 m = rotated(0.01, 0.04, 0.3);
    double out[3];
    gen::matrix_for_predicate(m, out);
    const std::array<double, 3> M = matrix_of(m);
    for (std::size_t k = 0; k < 3; ++k) EXPECT_NEAR(out[k], M[k] * 1e-4, 1e-15) << k;
    // Largest eigenvalue 1, smallest (h_min / h_max)^2 = 2^-500 at the aspect ratio limit:
    // exact when aligned with the axes, and positive definite when rotated (the rounded
    // matrix cannot hold an eigenvalue 2^-500 times the other; M22 is raised to keep det > 0).
    const gen::Metric2 aligned = gen::metric_from_stretching(0, 1, 0x1p-600, 0x1p250);
    gen::matrix_for_predicate(aligned, out);
    EXPECT_EQ(out[0], 1);
    EXPECT_EQ(out[1], 0);
    EXPECT_EQ(out[2], 0x1p-500);
    for (const double angle : {0.1, 0.7, 1.3, 2.9}) {
        const gen::Metric2 limit =
            gen::metric_from_stretching(std::cos(angle), std::sin(angle), 0x1p-600, 0x1p250);
        gen::matrix_for_predicate(limit, out);
        EXPECT_GT(out[0] * out[2] - out[1] * out[1], -1e-30) << angle;
        const gen::Metric2 recovered = gen::metric_from_matrix(out[0], out[1], out[2]);
        EXPECT_NEAR(recovered.h1, 1, 1e-15) << angle;
        EXPECT_GT(recovered.h2, 0x1p20) << angle;  // strongly stretched, if not by 2^250
        EXPECT_NEAR(std::fabs(recovered.c * limit.s - recovered.s * limit.c), 1, 1e-12) << angle;
    }
}

TEST(Generators_Metric2d, Intersection) {
    const gen::Metric2 smaller = gen::metric_intersection(gen::isotropic(1), gen::isotropic(0.5));
    EXPECT_NEAR(smaller.h1, 0.5, 1e-15);
    EXPECT_NEAR(smaller.h2, 0.5, 1e-15);
    // Two crossed needles: the disk of the smaller size.
    const gen::Metric2 crossed =
        gen::metric_intersection(gen::Metric2{1, 0.1, 1, 0}, gen::Metric2{0.1, 1, 1, 0});
    EXPECT_NEAR(crossed.h1, 0.1, 1e-15);
    EXPECT_NEAR(crossed.h2, 0.1, 1e-15);
    // Containment: the result is at least as long as both in every direction (its ellipse
    // inside both).
    std::mt19937_64 random(11);
    std::uniform_real_distribution<double> angle(-3.2, 3.2), log_size(-4, 4);
    for (int i = 0; i < cases(200); ++i) {
        const gen::Metric2 a =
            rotated(std::exp(log_size(random)), std::exp(log_size(random)), angle(random));
        const gen::Metric2 b =
            rotated(std::exp(log_size(random)), std::exp(log_size(random)), angle(random));
        const gen::Metric2 r = gen::metric_intersection(a, b);
        for (int d = 0; d < 360; ++d) {
            const double vx = std::cos(d * 0.0174533), vy = std::sin(d * 0.0174533);
            const double need =
                std::max(gen::metric_length(a, vx, vy), gen::metric_length(b, vx, vy));
            const double got = gen::metric_length(r, vx, vy);
            EXPECT_GE(got, need * (1 - 1e-9)) << i << " " << d;
        }
        // With a disk between the needle's sizes: the needle cut to the disk along its length.
        const double h = std::sqrt(a.h1 * a.h2);
        const gen::Metric2 cut = gen::metric_intersection(a, gen::isotropic(h));
        const double shorter = std::min(a.h1, a.h2);
        EXPECT_NEAR(std::min(cut.h1, cut.h2), shorter, 1e-12 * shorter) << i;
        EXPECT_NEAR(std::max(cut.h1, cut.h2), h, 1e-12 * h) << i;
    }
    // A metric inside the other's ellipse comes back unchanged, bit for bit.
    const gen::Metric2 a = rotated(0.1, 0.2, 0.5);
    const gen::Metric2 r = gen::metric_intersection(a, gen::isotropic(1));
    EXPECT_EQ(r.h1, a.h1);
    EXPECT_EQ(r.h2, a.h2);
    EXPECT_EQ(r.c, a.c);
}

TEST(Generators_Metric2d, ExtremeMagnitudes) {
    // Entries near the ends of the double range: sizes 1e-150 and about 4.5e161, no overflow.
    const gen::Metric2 huge = gen::metric_from_matrix(1e300, 0, 4e300);
    EXPECT_NEAR(huge.h1, 0.5e-150, 1e-165);
    EXPECT_NEAR(huge.h2, 1e-150, 1e-165);
    EXPECT_NEAR(huge.c * huge.c, 0, 1e-30);  // the larger eigenvalue along y
    const double smallest = std::numeric_limits<double>::denorm_min();
    const gen::Metric2 subnormal = gen::metric_from_matrix(smallest, 0, smallest);
    EXPECT_NEAR(subnormal.h1 / (1 / std::sqrt(smallest)), 1, 1e-15);
    EXPECT_EQ(subnormal.h1, subnormal.h2);
    // Their lengths: a vector of length 1e-150 along y is one unit in the first.
    EXPECT_NEAR(gen::metric_length(huge, 0, 0.5e-150), 1, 1e-15);
    EXPECT_NEAR(gen::metric_length(huge, 3e-150, 4 * 0.5e-150), 5, 1e-14);  // (3, 4) in units
}
