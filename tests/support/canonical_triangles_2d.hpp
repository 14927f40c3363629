// SPDX-License-Identifier: MIT
// Order-free comparison of 2D triangulations for the tests: the triangles as a set, each rotated
// to start at its smallest vertex (the orientation is kept). Test support.
#pragma once

#include <algorithm>
#include <array>
#include <set>
#include <span>

#include "triangulation/mesh/mesh2.hpp"

namespace exactmesh::testing {

using CanonicalTriangles = std::set<std::array<triangulation::VertIdx, 3>>;

/// `triangles` (three vertices each) as a set, each rotated to start at its smallest vertex.
inline CanonicalTriangles canonical_triangles(std::span<const triangulation::VertIdx> triangles) {
    CanonicalTriangles s;
    for (std::size_t t = 0; t + 2 < triangles.size(); t += 3) {
        std::array<triangulation::VertIdx, 3> a{triangles[t], triangles[t + 1], triangles[t + 2]};
        std::rotate(a.begin(), std::min_element(a.begin(), a.end()), a.end());
        s.insert(a);
    }
    return s;
}

}  // namespace exactmesh::testing
