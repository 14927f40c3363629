// SPDX-License-Identifier: MIT
// An SVG picture of a triangulation: triangles as one path, points as round dots, fitted into
// a viewBox with y pointing up. Line widths follow the triangle density, so the picture stays
// readable from a handful of triangles to ~10^5.
#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "io/point_set_2d.hpp"

namespace exactmesh::io {

struct SvgOptions {
    double width = 1000.0;    ///< length of the picture's longer side, in SVG user units
    bool draw_points = true;  ///< dots at the points (all of them, vertices or not)
    std::string title;        ///< shown by viewers as the picture's title; empty for none
    std::vector<VertIdx> segments;  ///< 2·#S constrained edges, drawn thick above the triangles
};

/// The SVG text. `xy`: 2·#V finite coordinates; `triangles`: 3·#T 0-based vertex indices.
std::string format_svg(std::span<const double> xy, std::span<const VertIdx> triangles,
                       const SvgOptions& options = {});
void write_svg(const std::filesystem::path& path, std::span<const double> xy,
               std::span<const VertIdx> triangles, const SvgOptions& options = {});

}  // namespace exactmesh::io
