// SPDX-License-Identifier: MIT
// Region flood in 3D: the tetrahedra reached from a seed without crossing a subface, and the
// region attributes and volume bounds of a PLC's region list (TetGen's .poly regions) spread that
// way [Si15 §2.1 (TetGen's region attributes); the 3D analogue of Triangle's regional
// attributes, Shewchuk96 §4]. Shared by boundary recovery (its carve removes the exterior and
// the holes with the flood, then assigns regions) and by generators that build their mesh
// otherwise (the octree's merged templates and band): a region point is located in the mesh
// given, so the assignment holds for the final mesh, however it was made.
// Invariants: a flood never crosses a face of `barrier`; a later region point in the same region
// overrides an earlier one (TetGen's order). Cost: O(#T) per region point (a linear closed
// locate, then the flood). Predicates: orient3d.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <unordered_set>
#include <vector>

#include "triangulation/mesh/conforming_mesh_3d.hpp"
#include "triangulation/mesh/plc_3d.hpp"
#include "triangulation/mesh/vertex_keys_3d.hpp"

namespace exactmesh::triangulation {

/// Faces by their sorted vertices (sorted3): the faces a flood does not cross.
using FaceSet3 = std::unordered_set<Key3, Key3Hash>;

/// The set of `faces` (3·#F vertex indices).
FaceSet3 face_set_3d(std::span<const VertIdx> faces);

/// The first tetrahedron of `mesh` whose closed interior holds p (exact orient3d against each
/// face), or kNone. A linear scan: meant for the few points of a PLC's hole and region lists.
TetIdx locate_closed_tetrahedron_3d(const Tetrahedralization3& mesh, const double* p);

/// Sets mark[t] = value for every tetrahedron reached from `seeds` through faces not in
/// `barrier` (neighbors across them), stopping at tetrahedra already marked `value`.
/// @pre mark.size() == mesh.tet_count().
void flood_tetrahedra_3d(const Tetrahedralization3& mesh, const FaceSet3& barrier,
                         std::vector<TetIdx> seeds, std::vector<std::uint8_t>& mark,
                         std::uint8_t value);

/// Per tetrahedron region values and the region points that name no tetrahedron.
struct RegionAssignment3 {
    /// #T attributes (0 outside every region); empty when the PLC has no region.
    std::vector<double> attributes;
    /// #T volume bounds (-1 where none); empty when no region has a bound (max_volume > 0).
    std::vector<double> max_volumes;
    /// One line per region point outside the domain or in a hole (TetGen ignores it silently).
    std::vector<std::string> warnings;
};

/// The regions of `plc` in `mesh`: each region point is located (closed; a point on a subface
/// was refused by boundary recovery) and its attribute and bound flood across faces that are
/// not in `subfaces`, in the order of plc.regions. `removed` (#T or empty): tetrahedra that are
/// not in the domain (boundary recovery's exterior and holes); a region point found only there
/// is ignored with a warning, as is one in no tetrahedron.
RegionAssignment3 assign_regions_3d(const Plc3& plc, const Tetrahedralization3& mesh,
                                    const FaceSet3& subfaces,
                                    std::span<const std::uint8_t> removed = {});

/// assign_regions_3d on a finished conforming mesh of `plc`'s domain (its subfaces are the
/// barrier): sets mesh.tet_attributes and mesh.tet_max_volume (both cleared without regions)
/// and returns the warnings. For generators whose output is not boundary recovery's carve.
std::vector<std::string> assign_regions_3d(const Plc3& plc, ConformingMesh3& mesh);

}  // namespace exactmesh::triangulation
