// SPDX-License-Identifier: MIT
// Order-free comparison of 2D triangulations for the tests: the triangles as a set, each rotated
// to start at its smallest vertex (the orientation is kept). Test support.
#pragma once

#include <array>
#include <set>
#include <span>

#include "triangulation/checks/compare_triangulations_2d.hpp"
#include "triangulation/mesh/mesh2.hpp"

namespace exactmesh::testing {

using CanonicalTriangles = std::set<std::array<triangulation::VertIdx, 3>>;

/// `triangles` (three vertices each) as a set, each rotated to start at its smallest vertex.
inline CanonicalTriangles canonical_triangles(std::span<const triangulation::VertIdx> triangles) {
    const auto sorted = triangulation::canonical_triangles_2d(triangles);
    return CanonicalTriangles(sorted.begin(), sorted.end());
}

}  // namespace exactmesh::testing
