// SPDX-License-Identifier: MIT
// Sliver removal after 3D Delaunay refinement [FreitagOllivierGooch97: "Tetrahedral mesh
// improvement using swapping and smoothing", IJNME 40, 1997; Klingner-Shewchuk07 "Aggressive
// tetrahedral mesh improvement" §3-4; Si15 §4 (TetGen's mesh optimization)]. Works on the
// tetrahedra whose smallest dihedral angle is below a threshold (15 degrees by default), in a
// few rounds of:
//  1. edge-face swapping under MaxMinDihedral (edge_face_swap_3d's constrained variant), from
//     the faces of those tetrahedra: a swap is made when the smallest dihedral angle among its
//     new tetrahedra is strictly larger than among the old ones (exact), and never when it
//     removes a subface (boundary or interior facet) or an edge that is a subsegment or an edge
//     of a subface: every 2-2 swap (which trades two boundary subfaces) is refused; then
//     edge removal (edge_removal_3d: the ring of 3 to 7 tetrahedra around an unlocked edge of a
//     tetrahedron still below the threshold replaced by the best triangulation of its link,
//     when every new tetrahedron beats the worst old one), under the same rules;
//  2. smoothing of their interior Steiner vertices (VertexFeature3::Volume; input, segment and
//     facet vertices never move): a few candidate positions (the neighbours' centroid, halfway
//     to it, steps along the ascent direction of the star's smallest dihedral angle, and the
//     end of a compass search over 26 directions on that angle, which gets past the max-min
//     points where several angles are active) are computed in doubles in a frame centred
//     at the vertex and scaled by a power of two (so that the result is the same for the mesh
//     scaled by any power of two) and rounded once; the best one (exact) is taken
//     when every tetrahedron of the star stays positively oriented (exact orient3d) and the
//     star's smallest dihedral angle strictly increases (exact, angle_comparisons_3d).
// Decision on the refinement's bounds: with `keep_bounds` (the default), a swap or a move is
// also refused when it raises the number of its tetrahedra over the radius-edge bound B (or
// the volume bound: the global one and the tetrahedron's region's, the smaller, as
// delaunay_refinement_3d applies them) above the number among the ones it replaces (exact,
// tet_quality_3d). So the
// mesh's count of tetrahedra over the bounds never grows: a mesh that met the bounds still
// does. It is no longer Delaunay; the input vertices, the subfaces, the subsegments and the
// region attributes are kept. Termination: every swap and move strictly raises the sorted
// vector of smallest dihedral angles (edge_face_swap_3d.cpp's argument), and the rounds are
// bounded. Decisions: orient3d, compare_dihedral, compare_radius_edge_3d, compare_tet_volume_3d;
// the threshold only selects where to work (rounded angles, scale-free).
#pragma once

#include <array>
#include <cstdint>

#include "base/counter_table.hpp"
#include "generators/mesh_3d/small_angle_rule_3d.hpp"
#include "triangulation/mesh/conforming_mesh_3d.hpp"
#include "triangulation/mesh/mesh3.hpp"

namespace exactmesh::generators {

struct SliverRemoval3Options {
    /// Tetrahedra with a dihedral angle below this are worked on (degrees, in (0, 90)).
    double threshold_degrees = 15.0;
    /// Rounds of swapping then smoothing (each stops early when nothing changes).
    unsigned rounds = 4;
    /// Keep the count of tetrahedra over the bounds below from growing (see above).
    bool keep_bounds = true;
    double radius_edge_bound = 2.0;  ///< B (> 0)
    double max_volume = 0;           ///< <= 0: no global volume bound (region bounds still apply)
};

struct SliverRemoval3Counters {
    std::uint64_t rounds = 0;    ///< rounds run
    std::uint64_t flips_23 = 0;  ///< swaps made, by kind
    std::uint64_t flips_32 = 0;
    std::uint64_t flips_44 = 0;
    /// edges removed (triangulation/modification/edge_removal_3d: rings of 3 to 7 around an
    /// edge of a tetrahedron still below the threshold after the face swaps)
    std::uint64_t edge_removals = 0;
    std::uint64_t swaps_locked = 0;    ///< preferred swaps refused: a subface or subsegment
    std::uint64_t swaps_vetoed = 0;    ///< preferred swaps refused by the bounds
    std::uint64_t moves_accepted = 0;  ///< smoothing moves made
    std::uint64_t moves_rejected = 0;  ///< vertices tried that no candidate improved
    std::uint64_t moves_vetoed = 0;    ///< vertices whose improving candidates all broke a bound
    std::uint64_t slivers_before = 0;  ///< tetrahedra below the threshold before
    std::uint64_t slivers_after = 0;   ///< and after
    /// tetrahedra removed first as folds: flat between two subfaces of one facet (see
    /// remove_boundary_folds in sliver_removal_3d.cpp)
    std::uint64_t folds_removed = 0;
};

inline constexpr std::array kSliverRemoval3CounterNames =
    EM_COUNTER_TABLE(SliverRemoval3Counters, rounds, flips_23, flips_32, flips_44, edge_removals,
                     swaps_locked, swaps_vetoed, moves_accepted, moves_rejected, moves_vetoed,
                     slivers_before, slivers_after, folds_removed);
static_assert(counter_table_complete(kSliverRemoval3CounterNames));

struct SliverRemoval3Result {
    triangulation::ConformingMesh3 mesh;
    SliverRemoval3Counters counters;
};

/// Improves the worst dihedral angles of `mesh` (delaunay_refinement_3d's result, or any mesh
/// that passes check_boundary_conformity_3d) as above. Vertices keep their indices (only
/// Volume vertices move); tetrahedra are renumbered.
/// @throws InputError when the options are out of range or a tetrahedron is not positive.
SliverRemoval3Result sliver_removal_3d(triangulation::ConformingMesh3 mesh,
                                       const SliverRemoval3Options& options = {});

/// The same on a mesh already in working form, as delaunay_refinement_3d hands its own over
/// (DelaunayRefinement3Options::sliver_removal): `linked` holds the tetrahedra (adj and
/// vertex_tet filled, dead slots allowed; the links are trusted, not checked: building them
/// from a Tetrahedralization3 was a sixth of sliver removal's time at 7 10^5 tetrahedra),
/// `mesh.mesh` is ignored, and mesh.tet_attributes and mesh.tet_max_volume, when filled, hold
/// one value per slot of `linked`. With `sharp` (refinement's classification, built on the
/// recovered mesh), the small-input-angle rule takes those sharp facets instead of classifying
/// the subfaces again: the rule refinement spared tetrahedra by, and a 65th of the wing's
/// construction time saved.
/// @pre `linked` is a valid TetMesh3 of the domain (what make_tet_mesh_3d would build), and
/// `sharp`, when given, classifies its facets.
SliverRemoval3Result sliver_removal_3d(triangulation::ConformingMesh3 mesh,
                                       triangulation::TetMesh3 linked,
                                       const SliverRemoval3Options& options = {},
                                       const SharpFacets3* sharp = nullptr);

}  // namespace exactmesh::generators
