// SPDX-License-Identifier: MIT
// An SVG picture of a triangulation: triangles as one path, points as round dots, fitted into
// a viewBox with y pointing up. Line widths follow the density of the triangles drawn, so the
// picture stays readable from a handful of triangles to ~10^5. Optionally a window (a zoom:
// the viewBox is the window, triangles outside it dropped, the rest clipped) and triangles
// shaded by their smallest angle with a colour bar.
#pragma once

#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "io/point_set_2d.hpp"

namespace exactmesh::io {

/// A window in data coordinates: x0 < x1, y0 < y1, all finite (svg_window_problem).
struct SvgWindow {
    double x0 = 0, y0 = 0, x1 = 1, y1 = 1;
};

/// How triangles are filled: one flat colour, or by their smallest angle (5-degree classes
/// from 0 to 60, red for small angles to blue for equilateral, with a colour bar below; no
/// dots at the points then, which would read as the red of small angles).
enum class SvgShade { None, MinAngle };

struct SvgOptions {
    double width = 1000.0;          ///< length of the picture's longer side, in SVG user units
    bool draw_points = true;        ///< dots at the points (all of them, vertices or not)
    std::string title;              ///< shown by viewers as the picture's title; empty for none
    std::vector<VertIdx> segments;  ///< 2·#S constrained edges, drawn thick above the triangles
    /// The part of the plane drawn: the viewBox is this window (plus the colour bar); triangles,
    /// segments and points entirely outside it are left out, the others clipped to it. Line
    /// widths follow the triangles that are (partly) inside. Empty: the bounding box of `xy`.
    std::optional<SvgWindow> view;
    SvgShade shade = SvgShade::None;
};

/// "" when `window` is usable (finite, x0 < x1, y0 < y1), else the reason, for a message.
std::string svg_window_problem(const SvgWindow& window);

/// The smallest angle of triangle a, b, c in degrees, in [0, 60] (0 when degenerate). For
/// drawing only (not exact), but scale-free: the corners are scaled by a power of two to the
/// unit range, then the edge vectors again, so 2^±600 coordinates give the same angle.
double triangle_min_angle_degrees(const double* a, const double* b, const double* c);

/// The SVG text. `xy`: 2·#V finite coordinates; `triangles`: 3·#T 0-based vertex indices.
/// @throws InputError when options.view is not a usable window (svg_window_problem).
std::string format_svg(std::span<const double> xy, std::span<const VertIdx> triangles,
                       const SvgOptions& options = {});
void write_svg(const std::filesystem::path& path, std::span<const double> xy,
               std::span<const VertIdx> triangles, const SvgOptions& options = {});

}  // namespace exactmesh::io
