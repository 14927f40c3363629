// SPDX-License-Identifier: MIT
// Comparing 2D triangulations of one point set: the triangles sorted, each rotated to start at its
// smallest vertex (orientation kept), so that two triangulations of the same points are equal
// exactly when their canonical lists are. Used by `exactmesh fuzz` and the fuzz targets and
// tests that compare algorithms with each other; and whether the points repeat (then two valid
// triangulations may differ by which copy of a point they use).
#pragma once

#include <algorithm>
#include <array>
#include <span>
#include <utility>
#include <vector>

#include "triangulation/mesh/mesh2.hpp"

namespace exactmesh::triangulation {

/// The triangle (a, b, c) rotated to start at its smallest vertex.
inline std::array<VertIdx, 3> rotated_to_smallest(std::array<VertIdx, 3> t) {
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    return t;
}

/// `triangles` (three vertices each), each rotated to start at its smallest vertex, sorted.
inline std::vector<std::array<VertIdx, 3>> canonical_triangles_2d(
    std::span<const VertIdx> triangles) {
    std::vector<std::array<VertIdx, 3>> out;
    out.reserve(triangles.size() / 3);
    for (std::size_t t = 0; t + 2 < triangles.size(); t += 3)
        out.push_back(rotated_to_smallest({triangles[t], triangles[t + 1], triangles[t + 2]}));
    std::sort(out.begin(), out.end());
    return out;
}

/// True when two of the points (x, y pairs of `xy`) are equal (0 and -0 are equal).
inline bool has_duplicate_points_2d(std::span<const double> xy) {
    std::vector<std::pair<double, double>> points;
    points.reserve(xy.size() / 2);
    for (std::size_t i = 0; i + 1 < xy.size(); i += 2) points.emplace_back(xy[i], xy[i + 1]);
    std::sort(points.begin(), points.end());
    return std::adjacent_find(points.begin(), points.end()) != points.end();
}

}  // namespace exactmesh::triangulation
