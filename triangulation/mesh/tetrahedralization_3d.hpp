// SPDX-License-Identifier: MIT
// Tetrahedralization3: a finite 3D tetrahedralization in flat arrays (no infinite vertex). The
// common currency of the 3D layer: what delaunay_3d (Bowyer-Watson, Green-Sibson) returns, what
// the edge-face swapping framework, vertex removal, the checks, the quality statistics and the
// writers (TetGen .ele/.face, Gmsh .msh, VTK .vtu) take.
//
// Conventions:
//  - tetrahedron t is (v0, v1, v2, v3) = tets[4t .. 4t+3], positively oriented:
//    orient3d(v0, v1, v2, v3) > 0 in predicates/orient3d.hpp's sign convention [Shewchuk97], so
//    that insphere(v0, v1, v2, v3, p) > 0 exactly when p lies inside its circumsphere. Writers
//    convert to a file format's own orientation where it differs;
//  - face k of t is the triangle opposite vertex k (TetGen's numbering); neighbors[4t + k] is
//    the tetrahedron across it, or kNone on the boundary (the convex hull of a Delaunay
//    tetrahedralization).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "triangulation/mesh/mesh2.hpp"

namespace exactmesh::triangulation {

using TetIdx = std::uint32_t;

struct Tetrahedralization3 {
    /// 3·#V coordinates. Input vertices keep their input index; vertices added by an algorithm
    /// are appended after them. Duplicate input points stay in xyz, used by no tetrahedron.
    std::vector<double> xyz;
    /// 4·#T vertex indices, each tetrahedron positively oriented (see above).
    std::vector<VertIdx> tets;
    /// 4·#T: the tetrahedron across the face opposite vertex k of tetrahedron t, or kNone.
    std::vector<TetIdx> neighbors;

    std::uint32_t vertex_count() const { return static_cast<std::uint32_t>(xyz.size() / 3); }
    std::uint32_t tet_count() const { return static_cast<std::uint32_t>(tets.size() / 4); }
    const double* point(VertIdx v) const { return xyz.data() + 3 * static_cast<std::size_t>(v); }
};

/// How a report's words number vertices and tetrahedra: the caller's own bases (a 1-based
/// TetGen file passes {1, 1}). Only the message changes; indices in the report are 0-based.
struct Check3Numbering {
    std::uint32_t first_vertex = 0;
    std::uint32_t first_tet = 0;
    /// The order a message lists a tetrahedron's corners in, the caller's: its corner k is
    /// tets[4t + corner_order[k]] (a TetGen .ele, whose reader swaps the last two corners for
    /// exactmesh's orientation, passes {0, 1, 3, 2}: io::kTetgenFileCorners).
    std::array<std::uint8_t, 4> corner_order{0, 1, 2, 3};
};

}  // namespace exactmesh::triangulation
