// SPDX-License-Identifier: MIT
// Exact validation of a 2D triangulation given as flat arrays (any producer: ours, CGAL, a file).
// Topology: positive orientation, each directed edge once, one boundary loop, Euler, every
// distinct point a vertex, convex boundary (the convex hull). Delaunay: every interior edge
// locally Delaunay by the exact incircle (cocircular accepted), which implies global Delaunay
// [Delaunay34 lemma]. All decisions use exact predicates.
#pragma once

#include <cstdint>
#include <span>
#include <string>

#include "triangulation/mesh2.hpp"

namespace exactmesh::triangulation {

struct CheckReport {
    bool ok = true;
    std::string problem;         ///< the first problem found, in words, empty when ok
    TriIdx triangle = kNone;     ///< the first offending triangle, when one is to blame
};

/// Topology and convex-hull checks of `triangles` (3·#T vertex indices into xy).
CheckReport check_topology_2d(std::span<const double> xy, std::span<const VertIdx> triangles);

/// check_topology_2d, then every interior edge locally Delaunay.
CheckReport check_delaunay_2d(std::span<const double> xy, std::span<const VertIdx> triangles);

}  // namespace exactmesh::triangulation
