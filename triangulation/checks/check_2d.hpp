// SPDX-License-Identifier: MIT
// Exact validation of a 2D triangulation given as flat arrays (any producer: ours, CGAL, a file).
// Topology: positive orientation, each directed edge once, one boundary loop that is convex and
// winds once (the convex hull), Euler, every distinct point a vertex; no triangle at all only
// when the points are collinear. Delaunay: every interior edge locally Delaunay by the exact
// incircle (cocircular accepted), which implies global Delaunay [Delaunay34 lemma]. All
// decisions use exact predicates.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "triangulation/mesh/mesh2.hpp"

namespace exactmesh::triangulation {

/// How a report's words number vertices and triangles: the caller's own bases (a 1-based
/// Triangle file passes {1, 1}). Only the message changes: `triangles` holds 0-based indices
/// into xy, and CheckReport::triangle and CheckReport::vertices are 0-based too.
struct CheckNumbering {
    std::uint32_t first_vertex = 0;
    std::uint32_t first_triangle = 0;
};

struct CheckReport {
    bool ok = true;
    std::string problem;      ///< the first problem found, in words, empty when ok
    TriIdx triangle = kNone;  ///< the first offending triangle (0-based), when one is to blame
    std::vector<VertIdx> vertices;  ///< the vertices the problem names (0-based), in its order
};

/// Topology and convex-hull checks of `triangles` (3·#T vertex indices into xy).
/// With no triangle, passes only when all distinct points are collinear (or fewer than 3).
CheckReport check_topology_2d(std::span<const double> xy, std::span<const VertIdx> triangles,
                              CheckNumbering numbering = {});

/// check_topology_2d, then every interior edge locally Delaunay.
CheckReport check_delaunay_2d(std::span<const double> xy, std::span<const VertIdx> triangles,
                              CheckNumbering numbering = {});

}  // namespace exactmesh::triangulation
