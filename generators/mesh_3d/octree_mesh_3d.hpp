// SPDX-License-Identifier: MIT
// Octree tetrahedral mesh generation [Yerry-Shephard84 (modified octree); Shephard-Georges91
// "Automatic three-dimensional mesh generation by the finite octree technique" (templates in
// the interior, a boundary band meshed apart); Frey-George "Mesh generation" §5.3] (issue 15):
//  1. Octree (octree_3d): the root is the smallest power-of-two cube aligned to half its edge that
//     holds the PLC's bounding box; a leaf that meets that box splits while its edge exceeds
//     1.8 times the size at its centre (leaf edges in (0.9 h, 1.8 h]: the cone template's edges
//     average 0.78 leaf edges, so the mesh's edges centre on h; leaves meeting the boundary,
//     which meet the box, reach the local size too: the two rules of the issue are one here);
//     then 2:1 balance across faces,
//     edges and corners. A leaf budget is refused at once from the size's estimate (the box's
//     volume over h^3, sampled on 8^3 points, in a frame scaled by h: scale-free) and enforced
//     while refining.
//  2. Core leaves: the leaf's cube grown by its own edge on every side has an open interior
//     that meets no facet's bounding box (exact comparisons of doubles), and its centre lies
//     inside the domain: located in the recovered constrained tetrahedralization of the PLC
//     (holes and the exterior removed) by exact orient3d, once per face-connected component of
//     such leaves (no facet passes between them). Deviation from the "closed": the
//     open interior lets a leaf touch a facet's box with its grown cube's side, which gives
//     the box-with-hole a core at h = 0.1 (edges 1/16 between walls 1/4 apart), and still
//     keeps a band of at least one leaf between the core and every facet.
//  3. Band: a PLC of the input facets (same vertices and order first) plus every core leaf's
//     face piece whose neighbour is not core (one square facet per piece: the leaf's face, or
//     a finer neighbour's face), each square's polygon listing every core leaf corner on its
//     perimeter (hanging corners), with a hole point at a leaf centre of each face-connected
//     core component. It is meshed by boundary_recovery_3d then frontal_delaunay_3d at the
//     size (the frontal generator aims at edges of length h, as the templates give, and its
//     boundary fitting leaves squares of edge <= h unsplit; Delaunay refinement's volume bound
//     would add points without regard to h). Every band Steiner point on a square lies in its
//     plane exactly (midpoints and circumcentres rounded once keep a coordinate all their
//     inputs share): checked, InternalError otherwise.
//  4. Templates: each core leaf is the cone from its centre over a triangulation of its
//     faces' pieces: a piece between two core leaves is fanned from its centre over every
//     vertex on its perimeter (found on exact axis lines: corners, hanging corners, band
//     points), a piece against the band takes exactly the band's subfaces on it. Both sides of
//     every face use the same triangles, so the mesh is conforming. Every template
//     tetrahedron is made positive by exact orient3d (zero is an InternalError).
//  5. Merge: the band's vertices first (so the PLC's vertices keep their indices), template
//     vertices deduplicated by exact coordinates; neighbours by shared faces (link_neighbors_3d:
//     a face in three tetrahedra or a non-positive one is an InternalError); the PLC's segments,
//     subsegments and subfaces from the band (interface ones dropped, their vertices become
//     Volume).
//  6. Regions (TetGen's region list): each region point is located in the merged mesh (exact
//     orient3d, closed) and its attribute and volume bound flood across faces that are not
//     subfaces (triangulation/recovery_3d/region_flood_3d, as boundary recovery's carve), so
//     every tetrahedron, template or band, carries its region's attribute (0 outside every
//     region; a later point in the same region overrides an earlier one). A region's volume
//     bound V caps the size there at a_V = cbrt(6 sqrt(2) V), the regular tetrahedron's edge
//     (region_volumes_3d: the region found in `recovered` by exact location), wherever the
//     size is evaluated: leaf centres, the estimate, the band's frontal insertion. The mesh
//     follows a_V as it follows h: its tetrahedra are not held to V (a core leaf of edge
//     1.8 a_V has template tetrahedra of 0.24 a_V^3 = 2.1 V); Delaunay refinement is the
//     generator that bounds every volume exactly.
// Not done: sliver removal is the caller's (the CLI runs sliver_removal_3d on the merged
// mesh). Cost: O(leaves) octree work with hash lookups, plus the band's recovery and frontal
// meshing, plus O(#T) per region point.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "base/counter_table.hpp"
#include "generators/mesh_3d/frontal_delaunay_3d.hpp"
#include "generators/mesh_3d/octree_3d.hpp"
#include "generators/sizing/size_function_3d.hpp"
#include "triangulation/mesh/conforming_mesh_3d.hpp"
#include "triangulation/mesh/plc_3d.hpp"
#include "triangulation/recovery_3d/boundary_recovery_3d.hpp"

namespace exactmesh::generators {

struct OctreeMesh3Options {
    /// The target edge length h (required: InputError when undefined).
    SizeFunction3 size;
    /// Most octree leaves; 0: 10^6. Refused at once when the estimate exceeds it.
    std::uint64_t max_leaves = 0;
    /// The band's Steiner budget (boundary recovery and frontal insertion); 0: their defaults.
    std::uint64_t max_steiner_points = 0;
    /// The band's frontal insertion grades the size down to the band PLC's local feature sizes
    /// (feature_graded_size_3d: free vertices of the input finer than the size) with this
    /// gradation; 0: the size as given. The leaves follow the size as given.
    double feature_gradation = 0.5;
};

struct OctreeMesh3Counters {
    std::uint64_t leaves = 0;             ///< octree leaves after balancing
    std::uint64_t balance_splits = 0;     ///< leaves split by the 2:1 balance
    std::uint64_t max_level = 0;          ///< deepest leaf level
    std::uint64_t core_leaves = 0;        ///< leaves meshed by templates
    std::uint64_t core_components = 0;    ///< face-connected core components (band holes)
    std::uint64_t interface_facets = 0;   ///< square facets between core and band
    std::uint64_t band_vertices = 0;      ///< vertices of the band mesh
    std::uint64_t band_tets = 0;          ///< tetrahedra of the band mesh
    std::uint64_t template_tets = 0;      ///< tetrahedra of the core templates
    std::uint64_t template_vertices = 0;  ///< vertices the templates add (centres, corners)
    std::uint64_t estimated_leaves = 0;   ///< the size's estimate (the budget's basis)
};

inline constexpr std::array kOctreeMesh3CounterNames = EM_COUNTER_TABLE(
    OctreeMesh3Counters, leaves, balance_splits, max_level, core_leaves, core_components,
    interface_facets, band_vertices, band_tets, template_tets, template_vertices, estimated_leaves);
static_assert(counter_table_complete(kOctreeMesh3CounterNames));

struct OctreeMesh3Result {
    triangulation::ConformingMesh3 mesh;
    OctreeMesh3Counters counters;
    triangulation::BoundaryRecovery3Counters band_recovery;
    FrontalDelaunay3Counters band_frontal;
    Octree3 octree;
    std::vector<std::uint8_t> core;  ///< per octree leaf: 1 when core
    /// The size followed: options.size, capped in regions with a volume bound (see above).
    SizeFunction3 size;
};

/// Meshes the domain of `plc` as above. `recovered` is boundary_recovery_3d's result for `plc`
/// (used to classify the core's components as inside). The PLC's vertices keep their indices.
/// The result's mesh carries tet_attributes (and tet_max_volume when a region has a bound) when
/// the PLC has regions; a region point outside the domain or in a hole is ignored (boundary
/// recovery, which made `recovered` of the same domain, warns of it).
/// @throws InputError when the size is undefined or not > 0 where evaluated, or a budget is
///         exceeded (the leaf budget at once when the estimate does).
OctreeMesh3Result octree_mesh_3d(const triangulation::Plc3& plc,
                                 const triangulation::ConformingMesh3& recovered,
                                 const OctreeMesh3Options& options);

}  // namespace exactmesh::generators
