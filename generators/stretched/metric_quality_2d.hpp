// SPDX-License-Identifier: MIT
// The quality report of stretched (anisotropic) meshes [issue 14; Frey-George08 §10.7 for the
// metric measures; Babuska-Aziz76 and Shewchuk02 "What is a good linear element?" for why the
// maximum angle, not the minimum, matters in stretched triangles]:
//  - metric edge lengths: each edge's length in the log-Euclidean mean of its two end points'
//    metrics (the midpoint rule of the log-Euclidean interpolation, not an integral along the
//    edge), their minimum, median, maximum and the share in [1/sqrt 2, sqrt 2] (a unit mesh);
//  - metric shape quality per triangle: the mean ratio q = 4 sqrt(3) area_M / sum of the squared
//    metric edge lengths, in the log-Euclidean mean of the three corners' metrics (1 for a
//    triangle equilateral in that metric, 0 for a flat one), computed on the edges mapped to the
//    metric's unit frame and scaled by a power of two (no square overflows);
//  - Euclidean maximum angles: each triangle's largest angle in a histogram of 10-degree bins,
//    and the count above 150 degrees;
//  - Euclidean aspect ratios: longest edge over the smallest altitude, L_max^2 / (2 area)
//    (2 / sqrt(3) = 1.1547 for an equilateral triangle), on the edge vectors scaled by a power of
//    two.
// Measured in double precision (a report, not a decision). A mesh and its metric field scaled
// together by 2^k report the same values (bit for bit where the field itself is scale-free).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>

#include "generators/stretched/metric_field_2d.hpp"
#include "triangulation/mesh/mesh2.hpp"

namespace exactmesh::generators {

struct MetricQualityReport2 {
    std::uint64_t triangles = 0;
    std::uint64_t edges = 0;
    double length_min = 0, length_median = 0, length_max = 0;  ///< metric edge lengths
    /// share of edges with metric length in [1/sqrt 2, sqrt 2] (to a relative 1e-12: rounding)
    double unit_length_share = 0;
    double shape_min = 0, shape_median = 0, shape_mean = 0;  ///< mean ratio in the metric
    std::array<std::uint64_t, 18> max_angle_histogram{};     ///< triangles by largest angle
    std::uint64_t above_150_degrees = 0;  ///< triangles with an angle > 150 degrees
    double max_angle = 0;                 ///< degrees, over every triangle
    double aspect_min = 0, aspect_median = 0, aspect_max = 0;  ///< longest edge / min altitude
};

/// The report of the triangles (3·#T indices into xy, 2·#V coordinates, counter-clockwise)
/// against `metric` (evaluated once at each vertex a triangle uses). An empty mesh gives zeros.
MetricQualityReport2 metric_quality_report_2d(std::span<const double> xy,
                                              std::span<const triangulation::VertIdx> triangles,
                                              const MetricField2& metric);

/// One "quality.metric_<name>: value" line per measure, in the style of quality_report_text.
std::string metric_quality_report_text(const MetricQualityReport2& report);

}  // namespace exactmesh::generators
