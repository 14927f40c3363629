// SPDX-License-Identifier: MIT
// Plc3: a piecewise linear complex, the input of 3D mesh generation [Si15 §1.2.1; the TetGen
// 1.5 manual §5.1.1], as plain data. A mesh type like mesh3.hpp, so that io/'s readers
// (io/plc_format) return it and triangulation/recovery_3d checks and triangulates it.
//
// Conventions:
//  - Indices are 0-based in memory. Plc3::first_index (0 or 1) is the numbering of the file the
//    PLC came from; every message names vertices and facets in that numbering (facets are
//    numbered in order from first_index, as TetGen's .face markers count them).
//  - A facet is TetGen's: one or more polygons in one plane. A polygon of n >= 3 corners is a
//    closed loop (corner n-1 joins corner 0); of 2 corners a segment inside the facet; of 1 an
//    isolated point. Facet hole points (3 each) mark the polygons' holes.
//  - Region3::max_volume <= 0 means "no volume bound"; volume hole points are 3 per hole.
#pragma once

#include <cstdint>
#include <vector>

#include "triangulation/mesh/mesh2.hpp"

namespace exactmesh::triangulation {

/// One facet: polygons (corner lists), hole points in the facet, a boundary marker.
struct Facet3 {
    std::vector<std::vector<VertIdx>> polygons;  ///< each: n >= 1 corner indices into Plc3::xyz
    std::vector<double> holes;                   ///< 3·#H points inside the facet's holes
    int marker = 0;                              ///< boundary marker (TetGen's facet marker)
};

/// A region point with its attribute and volume bound (TetGen's region list).
struct Region3 {
    double x = 0, y = 0, z = 0;
    double attribute = 0;
    double max_volume = -1;  ///< <= 0: no bound
};

/// A piecewise linear complex.
struct Plc3 {
    std::vector<double> xyz;        ///< 3·#V coordinates
    std::vector<Facet3> facets;     ///< #F facets
    std::vector<double> holes;      ///< 3·#H points inside volume holes
    std::vector<Region3> regions;   ///< #R region points
    std::uint32_t first_index = 0;  ///< numbering of vertices and facets in messages: 0 or 1
    /// Where each facet came from, for messages (empty: nowhere to point to): its line in the
    /// file, or its triangle number in a binary STL file (facet_origin_kind "triangle").
    std::vector<std::uint64_t> facet_origin;
    const char* facet_origin_kind = "line";

    /// When vertices at one point were merged (merge_duplicate_vertices_3d, as TetGen merges
    /// them): per vertex, the input's vertex it stands for (the first at its point), and per
    /// input vertex, the vertex that stands for it. Both empty otherwise.
    std::vector<VertIdx> input_vertex;
    std::vector<VertIdx> merged_vertex;

    std::uint32_t vertex_count() const { return static_cast<std::uint32_t>(xyz.size() / 3); }
    const double* point(VertIdx v) const { return xyz.data() + 3 * static_cast<std::size_t>(v); }
    /// A mesh vertex of this PLC (its Steiner points after its vertices) in the input's
    /// numbering, where the Steiner points follow every input vertex, merged ones included.
    VertIdx to_input_vertex(VertIdx v) const {
        if (input_vertex.empty()) return v;
        if (v < input_vertex.size()) return input_vertex[v];
        return static_cast<VertIdx>(v - input_vertex.size() + merged_vertex.size());
    }
    /// The inverse on mesh vertices: an input-numbered mesh vertex as this PLC numbers it (a
    /// merged input vertex as the vertex that stands for it).
    VertIdx from_input_vertex(VertIdx v) const {
        if (merged_vertex.empty()) return v;
        if (v < merged_vertex.size()) return merged_vertex[v];
        return static_cast<VertIdx>(v - merged_vertex.size() + input_vertex.size());
    }
    /// Vertex v's number in messages: its input vertex's, counted from first_index.
    std::uint64_t vertex_number(VertIdx v) const {
        return std::uint64_t{to_input_vertex(v)} + first_index;
    }
};

}  // namespace exactmesh::triangulation
