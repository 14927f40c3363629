// SPDX-License-Identifier: MIT
// Quadtree mesh generation of a PSLG domain for a size function [Yerry-Shephard83: "A modified
// quadtree approach to finite element mesh generation", IEEE CG&A 3(1); Baehmann87: "Robust,
// geometrically based, automatic two-dimensional mesh generation", IJNME 24; Mavriplis97
// "Unstructured grid techniques" §2; seed material, issue 6 generator 1]:
//  - a quadtree over a power-of-two square around the domain (cell corners exact dyadic
//    doubles); a leaf is split while its side exceeds cell_factor times the size (smallest of
//    nine samples), boundary_factor times the shortest boundary piece near it, or while it
//    meets two boundary features (pieces of different segments sharing no vertex: the local
//    feature size); then 2:1 balanced across sides; long boundary pieces bisected to the leaves
//    beside them;
//  - kept leaves: no boundary piece meets the leaf grown by clearance times its side (exact
//    segment-box tests: bounding boxes and orient2d against the box corners) and its centre in
//    the domain (exact point location): each closed kept leaf lies inside the domain. Each is
//    triangulated by a template: two 45-45-90 triangles, or a fan of 45-45-90 triangles from its
//    centre when a neighbour across a side is split (a hanging midpoint);
//  - the band between the kept leaves' outline and the boundary: the other leaves' corners far
//    enough from the boundary join it as vertices, the nearer ones are dropped (the
//    drop-instead-of-warp step: every vertex stays where the tree put it); boundary recovery is
//    the constrained Delaunay triangulation of the band with the outline and the pieces as
//    segments, the kept region removed by flood fill from one point per kept component; then
//    its triangles with an angle below band_min_angle get their circumcenters (Ruppert's rule,
//    boundary pieces halved when encroached, the outline never split).
// Invariants (proofs/invariants/quadtree_mesh_2d.md): every triangle strictly counter-clockwise
// (exact orient2d), the union of the triangles is the domain, input vertices keep their numbers,
// every segment a chain of pieces. Cost: O(L log L + n log n) for L leaves and n band vertices.
// Predicates: orient2d (segment-box tests, template orientation, point location), incircle (SoS,
// in the band's CDT); constructions: circumcenter.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "base/counter_table.hpp"
#include "generators/boundary/mesh_domain_2d.hpp"
#include "generators/sizing/size_function.hpp"
#include "triangulation/constrained/constrained_2d.hpp"

namespace exactmesh::generators {

struct QuadtreeOptions2 {
    /// Target edge length (required: unbounded is an InputError).
    SizeFunction size;
    /// A leaf is split while its side exceeds this times the smallest size sampled at its
    /// centre, corners and side midpoints; 1/sqrt(2) makes a two-triangle template's diagonal at
    /// most the sampled size. In (0, 16].
    double cell_factor = 0.70710678118654752;
    /// A leaf that boundary pieces come near (within clearance times its side) is split while
    /// its side exceeds this times the shortest of them: small features get small leaves.
    /// In (0, 16].
    double boundary_factor = 1.0;
    /// A leaf is kept (template-triangulated) only when no piece comes within this times its
    /// side; the rest is the band the CDT triangulates. In [1/16, 4].
    double clearance = 0.5;
    /// A corner of a band leaf (one not kept) inside the domain becomes a vertex of the band
    /// when no piece comes within this (at most clearance) times the leaf's side (exact box
    /// test) nor within this times the piece's own length (a shape choice in doubles); nearer
    /// corners are dropped (the drop-or-warp step; dropping keeps every vertex exact). 0 adds
    /// none. 0 or in [1/16, 1/2].
    double corner_clearance = 0.5;
    /// A boundary piece is bisected while it is longer than this times the side of the smallest
    /// leaf a quarter of its length into the domain from its ends and midpoint; 0 turns piece
    /// splitting off. 0 or in [1, 64].
    double piece_factor = 2.0;
    /// Band triangles with an angle below this (degrees) get their circumcenter inserted; one
    /// that encroaches boundary pieces halves them instead (at most twice each, never below the
    /// triangle's shortest edge; outline edges are never split); 0 leaves the band's CDT as it
    /// is. In [0, 30].
    double band_min_angle = 28.0;
    /// InputError when the tree would have more leaves (0: automatic, 64 per triangle the size
    /// asks for (expected_triangle_count) and per boundary piece, in [2^16, 2^24]).
    std::uint64_t max_leaves = 0;
    /// A size asking for more new boundary points than this is refused (InputError) as the
    /// boundary is sampled (0: the budget above).
    std::uint64_t max_boundary_points = 0;
    /// The domain's constrained Delaunay triangulation and the band's (recovery Swap or Cavity).
    triangulation::Cdt2Options cdt;
};

struct QuadtreeCounters2 {
    std::uint64_t leaves = 0;  ///< leaves of the balanced tree
    /// the features' lower bound on the leaves, before the tree (quadtree_leaf_bound_2d)
    std::uint64_t leaf_bound = 0;
    std::uint64_t size_splits = 0;      ///< leaves split by the size criterion
    std::uint64_t boundary_splits = 0;  ///< leaves split by the piece-length criterion
    std::uint64_t feature_splits = 0;   ///< leaves split for two boundary features near them
    std::uint64_t balance_splits = 0;   ///< leaves split by 2:1 balancing
    std::uint32_t depth = 0;            ///< deepest leaf level (root 0)
    std::uint32_t depth_limit = 0;      ///< the level at which splitting stops (exact corners)
    std::uint64_t piece_splits = 0;     ///< points added by bisecting boundary pieces
    std::uint64_t box_tests = 0;        ///< exact segment-box tests
    std::uint64_t domain_queries = 0;   ///< exact point-in-domain queries (leaf centres)
    std::uint64_t kept_leaves = 0;      ///< leaves triangulated by templates
    std::uint64_t fan_leaves = 0;       ///< of those, with a hanging midpoint (centre fans)
    std::uint64_t template_triangles = 0;
    std::uint64_t kept_components = 0;  ///< side-connected components of the kept leaves
    std::uint64_t outline_edges = 0;    ///< edges between kept leaves and the band
    std::uint64_t band_corners = 0;     ///< band leaves' corners added as band vertices
    std::uint64_t dropped_corners =
        0;  ///< band leaves' corners in the domain but too near the boundary
    std::uint64_t band_vertices = 0;       ///< vertices of the band's CDT
    std::uint64_t band_triangles = 0;      ///< triangles of the band
    std::uint64_t band_flips = 0;          ///< Lawson flips of the band's CDT
    std::uint64_t band_circumcenters = 0;  ///< circumcenters inserted into the band
    std::uint64_t band_rejected = 0;       ///< circumcenters not inserted (they encroached)
    std::uint64_t band_piece_splits = 0;   ///< boundary pieces halved for encroaching circumcenters
};

/// The counters' names as `exactmesh mesh --stats` prints them, in this order (one row
/// per field: counter_table_complete).
inline constexpr std::array kQuadtreeCounterNames =
    EM_COUNTER_TABLE(QuadtreeCounters2, leaves, leaf_bound, size_splits, boundary_splits,
                     feature_splits, balance_splits, depth, depth_limit, piece_splits, box_tests,
                     domain_queries, kept_leaves, fan_leaves, template_triangles, kept_components,
                     outline_edges, band_corners, dropped_corners, band_vertices, band_triangles,
                     band_flips, band_circumcenters, band_rejected, band_piece_splits);
static_assert(counter_table_complete(kQuadtreeCounterNames));

struct QuadtreeResult2 {
    /// The mesh in the caller's numbering: input vertices first, then the boundary's points,
    /// then the quadtree's; pieces with their input segment; the domain CDT's warnings.
    triangulation::Cdt2Result mesh;
    QuadtreeCounters2 counters;
};

/// Meshes the domain the PSLG's segments enclose (holes and exterior removed as
/// constrained_delaunay_2d removes them).
/// @throws InputError on bad input (as constrained_delaunay_2d), an unbounded size ("quadtree
///         needs a size"), options out of range, segments enclosing no region, or more leaves
///         than max_leaves.
/// @throws GeometryError when the band cannot be triangulated without new vertices (boundary
///         pieces that cross after rounding their split points).
QuadtreeResult2 quadtree_mesh_2d(const triangulation::Pslg& pslg, const QuadtreeOptions2& options);
/// The same over the domain built once (its options replace options.cdt for the domain).
QuadtreeResult2 quadtree_mesh_2d(const MeshDomain2& domain, const QuadtreeOptions2& options);

/// The counters named as `exactmesh mesh --stats` prints them.
std::vector<std::pair<std::string, std::uint64_t>> counter_list(const QuadtreeCounters2& c);

}  // namespace exactmesh::generators
