// SPDX-License-Identifier: MIT
// Structured columns across thin layers that turn (issue 14): the layer curved around a circle
// at aspect ratio 1000 gets one closed ridge on the circle and columns across it along the radii,
// each column's points on one radius, lined up from column to column layer by layer; a straight
// layer, a curved layer that sags less than the threshold, a turning field of constant thickness
// and a uniform field get none; the domain and the field scaled by 2^+-600 give the points scaled.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

#include "generators/stretched/metric_2d.hpp"
#include "generators/stretched/metric_field_2d.hpp"
#include "generators/stretched/turning_layer_columns_2d.hpp"
#include "tests/support/stretched_domains_2d.hpp"

namespace gen = exactmesh::generators;

namespace {

using exactmesh::testing::circle_layer;

std::vector<double> columns_of(const gen::MetricField2& field, double s = 1) {
    const auto inside = [s](double x, double y) { return x > 0 && x < s && y > 0 && y < s; };
    return gen::turning_layer_columns_2d(field, {0, 0, s, s}, inside, {}, 1u << 20);
}

TEST(TurningLayerColumns2d, ACurvedLayerOfAspectRatio1000GetsAlignedColumns) {
    const std::vector<double> points = columns_of(circle_layer(0.00005));
    ASSERT_GT(points.size(), 2u * 1000);
    // Group the points by bearing from the centre: sorted by bearing (measured from half a
    // column before the first point's, so that no column straddles the cut), a new column at
    // each gap above 0.01 rad (columns stand 0.05 / 0.3 = 0.17 rad apart).
    const double b0 = std::atan2(points[1] - 0.5, points[0] - 0.5) - 0.08;
    std::vector<std::pair<double, double>> polar;  // bearing, radius
    for (std::size_t i = 0; i < points.size(); i += 2) {
        const double dx = points[i] - 0.5, dy = points[i + 1] - 0.5;
        EXPECT_GT(points[i], 0);
        EXPECT_LT(points[i], 1);
        polar.emplace_back(std::fmod(std::atan2(dy, dx) - b0 + 8 * M_PI, 2 * M_PI),
                           std::hypot(dx, dy));
    }
    std::sort(polar.begin(), polar.end());
    std::vector<std::vector<double>> columns;
    for (std::size_t i = 0; i < polar.size(); ++i) {
        if (i == 0 || polar[i].first - polar[i - 1].first > 0.01) columns.emplace_back();
        columns.back().push_back(polar[i].second);
    }
    // The circle's length over the size along, 2 pi 0.3 / 0.05 = 37.7: 38 columns.
    EXPECT_EQ(columns.size(), 38u);
    const std::vector<double>* first = nullptr;
    for (std::vector<double>& radii : columns) {
        std::sort(radii.begin(), radii.end());
        // The ridge point lies on the circle, within a fiftieth of the size across there.
        const auto nearest = std::min_element(radii.begin(), radii.end(), [](double a, double b) {
            return std::fabs(a - 0.3) < std::fabs(b - 0.3);
        });
        EXPECT_NEAR(*nearest, 0.3, 0.00005 / 50 * 1.01);
        // The same layers on every column (the field is the same along the circle).
        if (first == nullptr) {
            first = &radii;
            continue;
        }
        ASSERT_EQ(radii.size(), first->size());
        for (std::size_t k = 0; k < radii.size(); ++k) {
            // A hundredth of the layer's size across there: lined up from column to column.
            EXPECT_NEAR(radii[k], (*first)[k], 0.01 * (0.00005 + 0.3 * std::fabs(radii[k] - 0.3)));
        }
    }
}

TEST(TurningLayerColumns2d, FieldsWithoutATurningThinLayerGetNone) {
    const gen::MetricField2 straight = gen::MetricField2::analytic(
        [](double, double y) {
            return gen::metric_from_stretching(1, 0, 0.05,
                                               0.05 / (0.00005 + 0.3 * std::fabs(y - 0.5)));
        },
        "straight layer");
    const gen::MetricField2 constant_thickness = gen::MetricField2::analytic(
        [](double x, double y) {
            gen::Metric2 m;
            const double dx = x - 0.5, dy = y - 0.5, r = std::hypot(dx, dy);
            m.h1 = 0.0002;
            m.h2 = 0.02;
            if (r > 0) {
                m.c = dx / r;
                m.s = dy / r;
            }
            return m;
        },
        "turning field");
    EXPECT_TRUE(columns_of(straight).empty());
    EXPECT_TRUE(columns_of(constant_thickness).empty());
    // Aspect ratio 100 on the circle: a chord sags by 2.1 sizes across, below the threshold 4.
    EXPECT_TRUE(columns_of(circle_layer(0.0005)).empty());
    EXPECT_TRUE(columns_of(gen::MetricField2::uniform(gen::isotropic(0.1))).empty());
}

TEST(TurningLayerColumns2d, AnArcLeavingTheDomainGetsColumnsOnItsOpenRidge) {
    // The same layer about (0.5, -0.05): its ridge is an arc that leaves the square through the
    // bottom side (an open ridge, traced both ways from where it is found).
    const gen::MetricField2 arc = gen::MetricField2::analytic(
        [](double x, double y) {
            const double dx = x - 0.5, dy = y + 0.05, r = std::hypot(dx, dy);
            gen::Metric2 m;
            m.h1 = 0.00005 + 0.3 * std::fabs(r - 0.3);
            m.h2 = 0.05;
            m.c = dx / r;
            m.s = dy / r;
            return m;
        },
        "arc layer");
    const std::vector<double> points = columns_of(arc);
    EXPECT_GT(points.size(), 2u * 500);
    for (std::size_t i = 0; i < points.size(); i += 2) {
        EXPECT_GT(points[i + 1], 0);
        EXPECT_LT(points[i + 1], 1);
    }
}

TEST(TurningLayerColumns2d, ALayerWhoseColumnsConvergeOnATightBendGetsNone) {
    // Along y = 0.5 + 0.05 sin(4 pi x) (radius of curvature 0.063 at the crests, aspect ratio
    // 1000): the columns converge or diverge by a quarter within a few layers, where the layer
    // still turns; a ragged edge of columns there did no better than the passes alone.
    constexpr double k = 12.566370614359172, a = 0.05;
    const gen::MetricField2 wave = gen::MetricField2::analytic(
        [](double x, double y) {
            const double slope = a * k * std::cos(k * x);
            const double across = 0.00005 + 0.3 * std::fabs(y - 0.5 - a * std::sin(k * x)) /
                                                std::sqrt(1 + slope * slope);
            return gen::metric_from_stretching(1, slope, 0.05, 0.05 / across);
        },
        "sine layer");
    EXPECT_TRUE(columns_of(wave).empty());
}

TEST(TurningLayerColumns2d, ScaledDomainAndFieldGiveThePointsScaled) {
    const std::vector<double> reference = columns_of(circle_layer(0.00005));
    for (const int k : {600, -600}) {
        const double s = std::ldexp(1.0, k);
        const std::vector<double> scaled = columns_of(circle_layer(0.00005, s), s);
        ASSERT_EQ(scaled.size(), reference.size()) << "2^" << k;
        for (std::size_t i = 0; i < scaled.size(); ++i)
            EXPECT_EQ(scaled[i], std::ldexp(reference[i], k)) << i;
    }
}

}  // namespace
