// SPDX-License-Identifier: MIT
// The quality report on hand-checked triangles: an equilateral and a right isosceles triangle
// (angles, histogram bins, radius-edge ratios), size conformity per edge, the text form.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "generators/mesh_2d/quality_2d.hpp"

namespace gen = exactmesh::generators;

TEST(Generators_Quality2d, HandCheckedTriangles) {
    // Equilateral (0,0) (2,0) (1, sqrt 3) and right isosceles (2,0) (4,0) (2,2).
    const std::vector<double> xy = {0, 0, 2, 0, 1, std::sqrt(3.0), 4, 0, 2, 2};
    const std::vector<std::uint32_t> triangles = {0, 1, 2, 1, 3, 4};
    const gen::QualityReport2 r =
        gen::quality_report_2d(xy, triangles, gen::SizeFunction::uniform(2.0));
    EXPECT_EQ(r.triangles, 2u);
    EXPECT_EQ(r.vertices, 5u);
    EXPECT_NEAR(r.min_angle, 45, 1e-9);
    EXPECT_NEAR(r.max_angle, 90, 1e-9);
    EXPECT_NEAR(r.mean_min_angle, 52.5, 1e-9);
    // Corners: 60, 60, 60 (bin 6); 90 (bin 9), 45, 45 (bin 4); at most one ulp-level bin shift
    // for the exact 60s and 90 (atan2 rounding): count them by their neighbourhoods.
    EXPECT_EQ(r.angle_histogram[4], 2u);
    EXPECT_EQ(r.angle_histogram[5] + r.angle_histogram[6], 3u);
    EXPECT_EQ(r.angle_histogram[8] + r.angle_histogram[9], 1u);
    EXPECT_NEAR(r.radius_edge_min, 1 / std::sqrt(3.0), 1e-12);
    EXPECT_NEAR(r.radius_edge_max, 1 / std::sqrt(2.0), 1e-12);
    // Edges: 0-1, 1-2, 0-2 (length 2), 1-3 (2), 3-4 (2 sqrt 2), 1-4 (2): ratio 1 or sqrt 2.
    EXPECT_EQ(r.edges, 6u);
    EXPECT_TRUE(r.has_size);
    EXPECT_NEAR(r.size_ratio_min, 1, 1e-12);
    EXPECT_NEAR(r.size_ratio_max, std::sqrt(2.0), 1e-12);
    EXPECT_NEAR(r.size_ratio_median, 1, 1e-12);
    const std::string text = gen::quality_report_text(r);
    EXPECT_NE(text.find("quality.min_angle: 45.000000\n"), std::string::npos) << text;
    EXPECT_NE(text.find("quality.triangles: 2\n"), std::string::npos) << text;
    EXPECT_NE(text.find("quality.angle_histogram: 0-10:0 "), std::string::npos) << text;
}

TEST(Generators_Quality2d, NoSizeNoTriangles) {
    const gen::QualityReport2 empty = gen::quality_report_2d({}, {});
    EXPECT_EQ(empty.triangles, 0u);
    const std::vector<double> xy = {0, 0, 1, 0, 0, 1};
    const std::vector<std::uint32_t> triangles = {0, 1, 2};
    const gen::QualityReport2 r = gen::quality_report_2d(xy, triangles);
    EXPECT_FALSE(r.has_size);
    EXPECT_NE(gen::quality_report_text(r).find("quality.size_conformity: none"), std::string::npos);
}
