// SPDX-License-Identifier: MIT
// Plain data exchanged with mesh files: a 2D point set with its per-vertex attributes and
// markers (Triangle's .node), and a triangle list (.ele). Indices are 0-based in memory; the
// file's own numbering base is kept so that outputs number things as the input did.
#pragma once

#include <cstdint>
#include <vector>

#include "triangulation/mesh/mesh2.hpp"

namespace exactmesh::io {

using triangulation::TriIdx;
using triangulation::VertIdx;

/// The content of a Triangle .node file.
struct NodeFile {
    std::vector<double> xy;             ///< 2·#V coordinates x0 y0 x1 y1 ..., in file order
    std::uint32_t first_index = 0;      ///< number of the first vertex in the file: 0 or 1
    std::uint32_t attribute_count = 0;  ///< attributes per vertex
    std::vector<double> attributes;     ///< attribute_count·#V, vertex after vertex
    bool has_markers = false;           ///< whether each vertex carries a boundary marker
    std::vector<std::int32_t> markers;  ///< #V boundary markers when has_markers, else empty
    std::vector<std::uint64_t> lines;   ///< #V: each vertex's line in the file read (for messages)

    std::uint32_t vertex_count() const { return static_cast<std::uint32_t>(xy.size() / 2); }
};

/// The content of a Triangle .poly file: a planar straight-line graph. Vertex and segment
/// numbers are 0-based in memory; `vertices.first_index` is the file's base for both.
struct PolyFile {
    NodeFile vertices;                     ///< the vertex section (or the .node file it names)
    bool vertices_from_node_file = false;  ///< the .poly announced 0 vertices: read from .node
    std::vector<VertIdx> segments;         ///< 2·#S endpoint indices, 0-based
    bool has_segment_markers = false;
    std::vector<std::int32_t> segment_markers;  ///< #S when has_segment_markers
    std::vector<double> holes;                  ///< 2·#H points inside holes
    std::vector<double> regions;                ///< 4·#R: x, y, attribute, maximum area (-1: none)
    std::vector<std::uint64_t> hole_lines;      ///< #H: the line of each hole (for messages)
    std::vector<std::uint64_t> region_lines;    ///< #R: the line of each region

    std::uint32_t segment_count() const { return static_cast<std::uint32_t>(segments.size() / 2); }
};

/// The content of a Triangle .ele file, vertex numbers made 0-based.
struct EleFile {
    std::vector<VertIdx> triangles;     ///< 3·#T 0-based vertex indices (the corners)
    std::uint32_t first_index = 0;      ///< number of the first triangle in the file: 0 or 1
    std::uint32_t attribute_count = 0;  ///< attributes per triangle
    std::vector<double> attributes;     ///< attribute_count·#T

    std::uint32_t triangle_count() const {
        return static_cast<std::uint32_t>(triangles.size() / 3);
    }
};

}  // namespace exactmesh::io
