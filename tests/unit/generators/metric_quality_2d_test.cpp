// SPDX-License-Identifier: MIT
// The stretched-mesh quality report (generators/stretched/metric_quality_2d.hpp) on
// hand-computed meshes: an equilateral triangle in the identity metric (quality 1, unit edges,
// largest angle 60, aspect ratio 2 / sqrt 3), a needle triangle matched to its metric (quality
// 1, unit metric edges, one angle above 150 degrees), a mesh twice too fine, bit-for-bit scale
// invariance at 2^+-600, and the text form.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "generators/stretched/metric_quality_2d.hpp"

namespace gen = exactmesh::generators;

namespace {

const double kSqrt3 = std::sqrt(3.0);

/// The unit equilateral triangle mapped by x = R diag(h1, h2) y (so that it is equilateral with
/// unit edges in the metric (h1, h2, c, s)).
std::vector<double> matched_triangle(const gen::Metric2& m) {
    const double y[6] = {0, 0, 1, 0, 0.5, kSqrt3 / 2};
    std::vector<double> xy;
    for (int k = 0; k < 3; ++k) {
        const double a = m.h1 * y[2 * k], b = m.h2 * y[2 * k + 1];
        xy.push_back(m.c * a - m.s * b);
        xy.push_back(m.s * a + m.c * b);
    }
    return xy;
}

}  // namespace

TEST(Generators_MetricQuality2d, EquilateralInTheIdentityMetric) {
    const std::vector<double> xy = {0, 0, 1, 0, 0.5, kSqrt3 / 2};
    const std::vector<std::uint32_t> triangles = {0, 1, 2};
    const gen::MetricQualityReport2 r = gen::metric_quality_report_2d(xy, triangles, {});
    EXPECT_EQ(r.triangles, 1u);
    EXPECT_EQ(r.edges, 3u);
    EXPECT_NEAR(r.shape_min, 1, 1e-15);
    EXPECT_NEAR(r.length_min, 1, 1e-15);
    EXPECT_NEAR(r.length_max, 1, 1e-15);
    EXPECT_EQ(r.unit_length_share, 1);
    EXPECT_NEAR(r.max_angle, 60, 1e-12);
    EXPECT_EQ(r.max_angle_histogram[5] + r.max_angle_histogram[6], 1u);
    EXPECT_EQ(r.above_150_degrees, 0u);
    EXPECT_NEAR(r.aspect_min, 2 / kSqrt3, 1e-15);
}

TEST(Generators_MetricQuality2d, NeedleMatchedToItsMetric) {
    const gen::Metric2 m{1, 1e-3, std::cos(0.4), std::sin(0.4)};
    const std::vector<double> xy = matched_triangle(m);
    const std::vector<std::uint32_t> triangles = {0, 1, 2};
    const gen::MetricField2 field = gen::MetricField2::uniform(m);
    const gen::MetricQualityReport2 r = gen::metric_quality_report_2d(xy, triangles, field);
    EXPECT_NEAR(r.shape_min, 1, 1e-12);
    EXPECT_NEAR(r.length_min, 1, 1e-12);
    EXPECT_NEAR(r.length_max, 1, 1e-12);
    EXPECT_EQ(r.unit_length_share, 1);
    // In Euclidean terms it is a needle with its apex nearly on its base: angle ~ 179.8 degrees.
    EXPECT_GT(r.max_angle, 179);
    EXPECT_EQ(r.above_150_degrees, 1u);
    EXPECT_EQ(r.max_angle_histogram[17], 1u);
    // Longest edge 1 (the base), area h2 * sqrt 3 / 4: aspect 1 / (2 area) = 2 / (sqrt 3 h2).
    EXPECT_NEAR(r.aspect_max, 2 / (kSqrt3 * 1e-3), 1e-6);
    // In the identity metric the same triangle is flat: 4 sqrt 3 (sqrt 3 h2 / 4) / (about 2).
    const gen::MetricQualityReport2 flat = gen::metric_quality_report_2d(xy, triangles, {});
    EXPECT_LT(flat.shape_min, 0.01);
    EXPECT_GT(flat.shape_min, 0);
}

TEST(Generators_MetricQuality2d, TooFineMeshAndShares) {
    // Two right triangles of the unit square in the isotropic metric of size 2: edges of metric
    // length 1/2 (four sides) and sqrt(2)/2 (the diagonal, inside [1/sqrt 2, sqrt 2]).
    const std::vector<double> xy = {0, 0, 1, 0, 1, 1, 0, 1};
    const std::vector<std::uint32_t> triangles = {0, 1, 2, 0, 2, 3};
    const gen::MetricQualityReport2 r =
        gen::metric_quality_report_2d(xy, triangles, gen::MetricField2::uniform(gen::isotropic(2)));
    EXPECT_EQ(r.edges, 5u);
    EXPECT_NEAR(r.length_min, 0.5, 1e-15);
    EXPECT_NEAR(r.length_median, 0.5, 1e-15);
    EXPECT_NEAR(r.length_max, std::sqrt(0.5), 1e-15);
    EXPECT_NEAR(r.unit_length_share, 0.2, 1e-15);
    // Right isosceles: mean ratio 4 sqrt 3 (1/2) / 4 = sqrt 3 / 2; aspect 2 / 1 = 2 (longest
    // edge sqrt 2, altitude to it sqrt 2 / 2); largest angle 90.
    EXPECT_NEAR(r.shape_min, kSqrt3 / 2, 1e-15);
    EXPECT_NEAR(r.shape_mean, kSqrt3 / 2, 1e-15);
    EXPECT_NEAR(r.aspect_max, 2, 1e-15);
    EXPECT_NEAR(r.max_angle, 90, 1e-12);
}

TEST(Generators_MetricQuality2d, ScaleInvarianceAndText) {
    const gen::Metric2 m{0.3, 0.002, 0.6, 0.8};
    std::vector<double> xy = matched_triangle(m);
    xy.insert(xy.end(), {1, -1});
    const std::vector<std::uint32_t> triangles = {0, 1, 2, 0, 3, 1};
    const gen::MetricQualityReport2 r =
        gen::metric_quality_report_2d(xy, triangles, gen::MetricField2::uniform(m));
    for (const int k : {600, -600}) {
        std::vector<double> scaled = xy;
        for (double& x : scaled) x = std::ldexp(x, k);
        const gen::Metric2 mk{std::ldexp(m.h1, k), std::ldexp(m.h2, k), m.c, m.s};
        const gen::MetricQualityReport2 s =
            gen::metric_quality_report_2d(scaled, triangles, gen::MetricField2::uniform(mk));
        EXPECT_EQ(s.length_min, r.length_min) << k;
        EXPECT_EQ(s.length_max, r.length_max) << k;
        EXPECT_EQ(s.shape_min, r.shape_min) << k;
        EXPECT_EQ(s.shape_mean, r.shape_mean) << k;
        EXPECT_EQ(s.max_angle, r.max_angle) << k;
        EXPECT_EQ(s.aspect_min, r.aspect_min) << k;
        EXPECT_EQ(s.aspect_max, r.aspect_max) << k;
        EXPECT_EQ(s.max_angle_histogram, r.max_angle_histogram) << k;
    }
    const std::string text = gen::metric_quality_report_text(r);
    EXPECT_NE(text.find("quality.metric_edge_length: min "), std::string::npos) << text;
    EXPECT_NE(text.find("(5 edges, "), std::string::npos) << text;
    EXPECT_NE(text.find("quality.metric_shape: min "), std::string::npos) << text;
    EXPECT_NE(text.find("quality.max_angle_histogram: 0-10:0 "), std::string::npos) << text;
    EXPECT_NE(text.find("quality.above_150_degrees: "), std::string::npos) << text;
    EXPECT_NE(text.find("quality.aspect_ratio: min "), std::string::npos) << text;
    const gen::MetricQualityReport2 empty = gen::metric_quality_report_2d({}, {}, {});
    EXPECT_EQ(empty.triangles, 0u);
    EXPECT_EQ(empty.edges, 0u);
}
