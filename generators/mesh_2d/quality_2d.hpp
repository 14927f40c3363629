// SPDX-License-Identifier: MIT
// The quality report shared by the 2D mesh generators [issue 6; Shewchuk97 "Delaunay
// refinement mesh generation" §1.2 for the measures]: element count, minimum and maximum angle,
// the histogram of all corner angles in 10-degree bins, the mean of the triangles' smallest
// angles, the radius-edge ratio R / l_min (1/sqrt(3) = 0.577 for an equilateral triangle,
// 1 / (2 sin theta_min) in general), and size conformity: each edge's length over the target
// size at its midpoint. Measured in double precision (a report, not a decision).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>

#include "generators/sizing/size_function.hpp"
#include "triangulation/mesh/mesh2.hpp"

namespace exactmesh::generators {

struct QualityReport2 {
    std::uint64_t triangles = 0;
    std::uint64_t vertices = 0;  ///< vertices used by a triangle
    double min_angle = 0;        ///< degrees, over every corner
    double max_angle = 0;
    double mean_min_angle = 0;  ///< mean over triangles of their smallest angle
    std::array<std::uint64_t, 18> angle_histogram{};  ///< corners in [10k, 10k + 10) degrees
    double radius_edge_min = 0, radius_edge_median = 0, radius_edge_max = 0;
    bool has_size = false;  ///< a bounded size function was given
    std::uint64_t edges = 0;
    double size_ratio_min = 0, size_ratio_median = 0, size_ratio_max = 0;  ///< length / s(midpoint)
    double seconds = 0;  ///< the generator's time (set by the caller)
};

/// The report of the triangles (3·#T indices into xy, 2·#V coordinates, counter-clockwise);
/// size conformity when `size` is bounded. An empty mesh gives zeros.
QualityReport2 quality_report_2d(std::span<const double> xy,
                                 std::span<const triangulation::VertIdx> triangles,
                                 const SizeFunction& size = {});

/// One "quality.<name>: value" line per measure (the CLI's --quality output).
std::string quality_report_text(const QualityReport2& report);

}  // namespace exactmesh::generators
