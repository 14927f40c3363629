// SPDX-License-Identifier: MIT
// Metric fields (generators/stretched/metric_field_2d.hpp, metric_background_2d.hpp): uniform
// and analytic kinds; a background mesh reproducing a constant field, interpolating
// log-Euclidean inside (geometric means of isotropic sizes) and taking the nearest boundary
// point's value outside, bit-for-bit scale invariant; the metric file's errors naming file,
// line and value.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "base/errors.hpp"
#include "generators/stretched/metric_background_2d.hpp"
#include "generators/stretched/metric_field_2d.hpp"

namespace gen = exactmesh::generators;

namespace {

// The unit square as two counter-clockwise triangles (0 1 2) and (0 2 3).
const std::vector<double> kSquare = {0, 0, 1, 0, 1, 1, 0, 1};
const std::vector<std::uint32_t> kTriangles = {0, 1, 2, 0, 2, 3};

std::string error_of(const std::vector<double>& matrices, const std::vector<std::uint32_t>& tris) {
    const std::vector<std::uint64_t> lines = {2, 3, 5, 6};
    gen::MetricFileSource source{"m.node", "m.ele", 1, lines};
    try {
        gen::background_metric_from_file(kSquare, gen::MetricFileForm::Matrices, matrices, tris,
                                         source);
    } catch (const exactmesh::InputError& error) {
        return error.what();
    }
    return "";
}

}  // namespace

TEST(Generators_MetricField2d, UniformAndAnalytic) {
    const gen::MetricField2 identity;
    EXPECT_EQ(identity(5, 7).h1, 1);
    EXPECT_TRUE(identity.is_uniform());
    const gen::MetricField2 uniform = gen::MetricField2::uniform(gen::Metric2{0.1, 0.001, 0, 1});
    EXPECT_EQ(uniform(-3, 2).h2, 0.001);
    EXPECT_NE(uniform.describe().find("uniform: sizes 0.1, 0.001"), std::string::npos);
    EXPECT_THROW(gen::MetricField2::uniform(gen::Metric2{-1, 1, 1, 0}), exactmesh::InputError);
    const gen::MetricField2 analytic = gen::MetricField2::analytic(
        [](double x, double y) { return gen::isotropic(1 + x * x + y * y); }, "1 + r^2");
    EXPECT_EQ(analytic(1, 2).h1, 6);
    EXPECT_EQ(analytic.describe(), "1 + r^2");
}

TEST(Generators_MetricField2d, BackgroundMeshReproducesAConstantField) {
    const gen::Metric2 m{0.2, 0.002, 0.6, 0.8};
    const gen::MetricField2 field =
        gen::MetricField2::background_mesh(kSquare, std::vector<gen::Metric2>(4, m), kTriangles);
    EXPECT_EQ(field.describe(), "background mesh: 4 vertices, 2 triangles");
    for (const auto& [x, y] : std::vector<std::pair<double, double>>{
             {0.3, 0.1}, {0.9, 0.8}, {0.5, 0.5}, {1, 1}, {3, -2}, {-1, 0.5}}) {
        // The same ellipse (its sizes may come back in the other order, h1 <= h2).
        const gen::Metric2 at = field(x, y);
        for (int d = 0; d < 36; ++d) {
            const double vx = std::cos(d * 0.174533), vy = std::sin(d * 0.174533);
            const double expected = gen::metric_length(m, vx, vy);
            EXPECT_NEAR(gen::metric_length(at, vx, vy), expected, 1e-13 * expected)
                << x << " " << y << " " << d;
        }
    }
}

TEST(Generators_MetricField2d, BackgroundMeshInterpolatesLogEuclidean) {
    const std::vector<double> sizes = {1, 4, 16, 2};
    std::vector<gen::Metric2> metrics;
    for (const double h : sizes) metrics.push_back(gen::isotropic(h));
    const gen::MetricField2 field =
        gen::MetricField2::background_mesh(kSquare, metrics, kTriangles);
    // At a vertex: its own metric, exactly.
    EXPECT_EQ(field(1, 0).h1, 4);
    // At the centroid of (0 1 2): the geometric mean (1 * 4 * 16)^(1/3) = 4.
    const gen::Metric2 centroid = field(2.0 / 3, 1.0 / 3);
    EXPECT_NEAR(centroid.h1, 4, 1e-13);
    EXPECT_NEAR(centroid.h2, 4, 1e-13);
    // Outside, right of the edge (1, 0)-(1, 1) at its middle: sqrt(4 * 16) = 8.
    const gen::Metric2 outside = field(3, 0.5);
    EXPECT_NEAR(outside.h1, 8, 1e-13);
    // Outside beyond a corner: the corner's value.
    EXPECT_NEAR(field(2, -2).h1, 4, 1e-13);
    // Anisotropic corners stay positive definite in between.
    const std::vector<gen::Metric2> crossed = {gen::Metric2{1, 0.001, 1, 0},
                                               gen::Metric2{0.001, 1, 1, 0}, gen::isotropic(0.1),
                                               gen::Metric2{1, 0.01, 0.6, 0.8}};
    const gen::MetricField2 mixed =
        gen::MetricField2::background_mesh(kSquare, crossed, kTriangles);
    for (int i = 0; i <= 10; ++i) {
        for (int j = 0; j <= 10; ++j) EXPECT_NO_THROW(gen::check_metric(mixed(i / 10.0, j / 10.0)));
    }
}

TEST(Generators_MetricField2d, BackgroundMeshIsScaleInvariant) {
    const std::vector<gen::Metric2> metrics = {gen::Metric2{1, 0.001, 1, 0},
                                               gen::Metric2{0.001, 1, 1, 0}, gen::isotropic(0.1),
                                               gen::Metric2{1, 0.01, 0.6, 0.8}};
    const gen::MetricField2 field =
        gen::MetricField2::background_mesh(kSquare, metrics, kTriangles);
    for (const int k : {600, -600}) {
        std::vector<double> xy = kSquare;
        for (double& x : xy) x = std::ldexp(x, k);
        std::vector<gen::Metric2> scaled = metrics;
        for (gen::Metric2& m : scaled) m.h1 = std::ldexp(m.h1, k), m.h2 = std::ldexp(m.h2, k);
        const gen::MetricField2 big = gen::MetricField2::background_mesh(xy, scaled, kTriangles);
        for (const auto& [x, y] : std::vector<std::pair<double, double>>{
                 {0.3, 0.1}, {0.7, 0.9}, {2.5, 0.25}, {-1, -1}}) {
            const gen::Metric2 a = field(x, y), b = big(std::ldexp(x, k), std::ldexp(y, k));
            EXPECT_EQ(b.h1, std::ldexp(a.h1, k)) << k << " " << x << " " << y;
            EXPECT_EQ(b.h2, std::ldexp(a.h2, k)) << k << " " << x << " " << y;
            EXPECT_EQ(b.c, a.c);
            EXPECT_EQ(b.s, a.s);
        }
    }
}

TEST(Generators_MetricField2d, MetricFileErrorsNameFileLineAndValue) {
    std::vector<double> good = {1, 0, 1, 2, 0.5, 1, 4, 0, 4, 1, 0, 9};
    EXPECT_EQ(error_of(good, kTriangles), "");
    std::vector<double> bad = good;
    bad[6] = 1, bad[7] = 2, bad[8] = 1;  // vertex 2 (file number 3, line 5)
    std::string text = error_of(bad, kTriangles);
    EXPECT_NE(text.find("m.node:5: vertex 3: metric (M11, M12, M22) = (1, 2, 1) is not positive "
                        "definite"),
              std::string::npos)
        << text;
    bad = good;
    bad[9] = NAN;
    text = error_of(bad, kTriangles);
    EXPECT_NE(text.find("m.node:6: vertex 4: metric (M11, M12, M22) = (NaN, 0, 9) is not finite"),
              std::string::npos)
        << text;
    text = error_of(good, {0, 2, 1});
    EXPECT_NE(text.find("m.ele: background mesh: triangle 0: inverted"), std::string::npos) << text;
    text = error_of({1, 0, 1}, kTriangles);
    EXPECT_NE(text.find("m.node: 4 vertices need 12 metric values"), std::string::npos) << text;
}
