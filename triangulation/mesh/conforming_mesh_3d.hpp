// SPDX-License-Identifier: MIT
// ConformingMesh3: a tetrahedralization of a PLC's domain whose faces include every facet, cut
// into subfaces, and whose edges include every segment, cut into subsegments, with each
// Steiner vertex's feature recorded. Plain data: boundary_recovery_3d produces it and
// check_boundary_conformity_3d checks it, neither including the other.
#pragma once

#include <cstdint>
#include <vector>

#include "triangulation/mesh/tetrahedralization_3d.hpp"

namespace exactmesh::triangulation {

/// What a vertex of a ConformingMesh3 lies on.
enum class VertexFeature3 : std::uint8_t {
    Input,    ///< a PLC vertex (index below input_vertex_count)
    Segment,  ///< a Steiner point on input segment feature_index
    Facet,    ///< a Steiner point inside facet feature_index
    Volume,   ///< a Steiner point inside the domain (Delaunay refinement; feature_index kNone)
};

struct ConformingMesh3 {
    /// The domain's tetrahedra: xyz holds the PLC's vertices (same indices) then the Steiner
    /// points; exterior and hole tetrahedra are removed (neighbors kNone across the boundary).
    Tetrahedralization3 mesh;
    std::uint32_t input_vertex_count = 0;
    std::vector<VertexFeature3> vertex_feature;  ///< #V
    std::vector<std::uint32_t> feature_index;    ///< #V: segment or facet index (kNone: input)
    /// 2·#S input segments (the facets' polygon edges, each once, smaller index first).
    std::vector<VertIdx> segments;
    /// 2·#P subsegments and the input segment each lies on.
    std::vector<VertIdx> subsegments;
    std::vector<std::uint32_t> subsegment_segment;
    /// 3·#F subfaces and the facet each lies in (a facet's subfaces share its orientation in the
    /// projection that drops the coordinate of the facet's largest normal component).
    std::vector<VertIdx> subfaces;
    std::vector<std::uint32_t> subface_facet;
    /// #T region attribute per tetrahedron (0 outside every region); empty without regions.
    std::vector<double> tet_attributes;
    /// #T volume bound per tetrahedron, its region's Region3::max_volume (<= 0: none, as outside
    /// every region); empty when no region has a bound. Delaunay refinement applies it (TetGen's
    /// -a with region volume constraints), together with a global bound when one is given.
    std::vector<double> tet_max_volume;
};

}  // namespace exactmesh::triangulation
