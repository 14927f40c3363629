// SPDX-License-Identifier: MIT
// A given 2D triangle mesh (a Triangle .node/.ele) as the start of an adaptive run (issue 13):
// its domain as a planar straight-line graph and the mesh validated exactly.
//  - The PSLG: the mesh's vertices (all of them input vertices, in the mesh's numbering), its
//    boundary edges as segments (directed with the mesh on their left), and one point in every
//    hole: a bounded region outside the mesh but inside its outer boundary. The insertion
//    method rebuilds a constrained Delaunay triangulation of the domain each cycle and removes
//    what the hole points reach, so each must lie exactly outside the mesh.
//  - Validation: triangles strictly counter-clockwise and each directed edge once
//    (link_neighbors_2d), every vertex used, no fold at any vertex with the boundary on the
//    segments (check_conforming_mesh_2d); then the constrained Delaunay triangulation (CDT) of
//    the boundary alone must keep every boundary edge whole (no two vertices at one point, no
//    vertex on a boundary edge, no two boundary edges crossing), and the winding number of the
//    boundary, propagated across the CDT's triangles from its own boundary (0 outside; crossing
//    a segment from its right to its left adds 1), must be 0 or 1 on every triangle. A locally
//    injective mesh covers each point as often as its boundary winds around it [the argument of
//    proofs/invariants/conforming_mesh_2d.md], so this shows the mesh covers the winding-1
//    triangles once and nothing else: no second layer.
//  - Hole points: for each connected set of winding-0 triangles (across unconstrained edges),
//    the rounded centroid of one of them, verified strictly inside it by exact orient2d; when
//    rounding puts it out, the next triangle of the set is tried.
//  - The start of a run: `cdt`, the CDT of the PSLG with its holes (the same vertices; the
//    connectivity Delaunay), which the Delaunay-based methods need, or the given mesh itself
//    (given_mesh_result_2d) for methods that do not (h-refinement, local remeshing).
// Cost: O((V + T) log V) for the checks and the CDT. Predicates: orient2d (the checks, the
// hole points), incircle (the CDT).
#pragma once

#include <cstdint>
#include <vector>

#include "triangulation/checks/check_2d.hpp"
#include "triangulation/constrained/constrained_2d.hpp"
#include "triangulation/mesh/triangulation_2d.hpp"

namespace exactmesh::generators {

struct GivenMeshDomain2 {
    /// The given mesh: neighbors linked, boundary sides flagged constrained.
    triangulation::Triangulation2 mesh;
    /// 2·#S: the mesh's boundary edges, each directed with the mesh on its left, 0-based.
    std::vector<triangulation::VertIdx> segments;
    /// 2·#H: one point strictly outside the mesh in each hole.
    std::vector<double> holes;
    /// The CDT of (mesh.xy, segments, holes): the mesh's region, the mesh's vertices, each
    /// segment one piece (input vertices keep their numbers; nothing is added).
    triangulation::Cdt2Result cdt;
    /// Whether `cdt` has the given mesh's triangles (as sets of corners).
    bool mesh_is_cdt = false;
};

/// Validates the mesh (xy: 2·#V, triangles: 3·#T 0-based, as read) and builds its domain (see
/// the header comment). `numbering` numbers vertices and triangles in messages.
/// @throws InputError naming the first problem (an inverted triangle, an edge used twice in one
///         direction, an unused vertex, a fold, coinciding vertices, touching or crossing
///         boundary edges, a region covered twice); the caller adds the file.
GivenMeshDomain2 given_mesh_domain_2d(std::vector<double> xy,
                                      std::vector<triangulation::VertIdx> triangles,
                                      triangulation::CheckNumbering numbering = {});

/// The given mesh itself as a constrained result (pieces: the segments, each its own input
/// segment; every vertex an input vertex), for methods that keep it.
triangulation::Cdt2Result given_mesh_result_2d(const GivenMeshDomain2& domain);

}  // namespace exactmesh::generators
