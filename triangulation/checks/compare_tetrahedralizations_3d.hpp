// SPDX-License-Identifier: MIT
// Comparing 3D tetrahedralizations of one point set: each tetrahedron as its sorted vertex
// quadruple, the list sorted, so that two tetrahedralizations of the same points are equal
// exactly when their canonical lists are (orientation is check_tetrahedralization_3d's job).
// Used by the tests and fuzz targets that compare constructions with each other.
#pragma once

#include <algorithm>
#include <array>
#include <span>
#include <vector>

#include "triangulation/mesh/mesh3.hpp"

namespace exactmesh::triangulation {

/// `tets` (four vertices each), each sorted, the list sorted.
inline std::vector<std::array<VertIdx, 4>> canonical_tetrahedra_3d(std::span<const VertIdx> tets) {
    std::vector<std::array<VertIdx, 4>> out;
    out.reserve(tets.size() / 4);
    for (std::size_t t = 0; t + 3 < tets.size(); t += 4) {
        std::array<VertIdx, 4> a{tets[t], tets[t + 1], tets[t + 2], tets[t + 3]};
        std::sort(a.begin(), a.end());
        out.push_back(a);
    }
    std::sort(out.begin(), out.end());
    return out;
}

}  // namespace exactmesh::triangulation
