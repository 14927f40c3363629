// SPDX-License-Identifier: MIT
// Plain data exchanged with 3D mesh files: a point set with its per-vertex attributes and
// markers (TetGen's .node), and a tetrahedron list (.ele). Indices are 0-based in memory; the
// file's own numbering base is kept so that outputs number things as the input did.
#pragma once

#include <cstdint>
#include <vector>

#include "triangulation/mesh3.hpp"

namespace exactmesh::io {

using triangulation::TetIdx;
using triangulation::VertIdx;

/// The content of a TetGen .node file.
struct NodeFile3 {
    std::vector<double> xyz;            ///< 3·#V coordinates x0 y0 z0 x1 ..., in file order
    std::uint32_t first_index = 0;      ///< number of the first vertex in the file: 0 or 1
    std::uint32_t attribute_count = 0;  ///< attributes per vertex
    std::vector<double> attributes;     ///< attribute_count·#V, vertex after vertex
    bool has_markers = false;           ///< whether each vertex carries a boundary marker
    std::vector<std::int32_t> markers;  ///< #V boundary markers when has_markers, else empty

    std::uint32_t vertex_count() const { return static_cast<std::uint32_t>(xyz.size() / 3); }
};

/// The content of a TetGen .ele file: corners 0-based and reordered to triangulation/'s
/// orientation (see tetgen_format.hpp).
struct TetFile {
    std::vector<VertIdx> tets;          ///< 4·#T 0-based vertex indices (the corners)
    std::uint32_t first_index = 0;      ///< number of the first tetrahedron in the file: 0 or 1
    std::uint32_t attribute_count = 0;  ///< region attributes per tetrahedron (0 or 1)
    std::vector<double> attributes;     ///< attribute_count·#T

    std::uint32_t tet_count() const { return static_cast<std::uint32_t>(tets.size() / 4); }
};

}  // namespace exactmesh::io
