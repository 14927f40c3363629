// SPDX-License-Identifier: MIT
// The truncated structured O-mesh: the hybrid mesh of Mavriplis and Weatherill (issue 14,
// "hybrid and semi-structured meshes") [Mavriplis95: "Unstructured mesh generation and
// adaptivity", VKI LS 1995-02; Weatherill-Hassan94 / Mavriplis-Jameson90 for the overlapping
// structured grids about the elements of a multi-element airfoil, truncated and merged with a
// triangulation of the rest].
//  - Rings: one O-mesh per wall loop (a closed inner boundary, as for advancing layers), one
//    normal line per wall vertex along its smoothed normal (the mean of its sides' normals
//    averaged twice with its neighbours'; no fans at corners: a structured ring), layer k at
//    height h (1 + g + ... + g^(k-1)) from the wall vertex p, the point p + t d rounded once
//    (fma). Every cell is the quadrilateral between two consecutive normal lines and two
//    consecutive layers.
//  - Truncation: a whole ring stops at one layer index K, the number of layers thinner than
//    the ring's median wall spacing (its cells become about isotropic there; at most
//    max_layers). The ring's columns (the cells between two normal lines) are then only cut
//    back, never raised: where a cell or its guard folds (not strictly convex: normal lines
//    converging at concave walls) or a cell has a corner above 160 degrees (sharp convex
//    corners, where the normals splay without a fan), where O-meshes overlap, and where a
//    step between neighbouring columns would be both more than two layers and taller than
//    the wall spacing there (so the height varies along a ring only where a cut requires it,
//    in steps the fill closes with triangles about as tall as wide).
//  - Overlaps: each cell has a guard, the quadrilateral over its bottom edge reaching one
//    more layer plus the larger of the next thickness and the cell's tangential width further
//    along its normal lines. A cell whose guard (or itself) meets a boundary segment or vertex
//    of the domain is removed; of two cells of different rings (or of one ring, columns not
//    neighbours) where the guard of one (or the cell) meets the other, the coarser (the higher
//    layer, i.e. the thicker) is removed, both when they are on the same layer; a column is
//    cut at its lowest removed cell. One pass suffices (the cells do not move, and every pair
//    that meets loses a cell): the kept cells are pairwise disjoint and their outer front
//    stays at least about a local spacing from the other rings' cells and the boundary.
//    Every decision is exact (orient2d, segments_conflict, compare_angles); lengths only
//    place the guards and the truncation (scale-free norms).
//  - Rounding: the fill's constrained triangulation bends a segment through a vertex within
//    rounding of it (2^-40 of the vertex's coordinates, the chain rule of
//    proofs/invariants/constrained_delaunay.md §4). Columns are cut until no vertex of the
//    fill's domain (a domain vertex or a layer point in use) lies within rounding of a front
//    edge or boundary piece strictly between its ends (first heights near 2^-40 of the
//    coordinates: 1e-12 beside the NACA 0012's trailing edge); the layer point on the highest
//    layer of the three goes, the steps are evened again, repeated until none is left; a
//    warning says how many cells went (omesh_removed_unresolvable).
//  - The layer cells are kept as quadrilaterals or split (layer_mesh::split_quad); the rest is
//    meshed by the fill generator from the staircase front of every ring, as for advancing
//    layers (layer_mesh::finish_layered_mesh_2d), and the mixed mesh checked exactly.
// Cost: O(C) cells C = sum of ring sizes times their K, each tested against the cells near it
// (bucket grid) once; plus the fill.
#pragma once

#include "generators/stretched/advancing_layers_2d.hpp"

namespace exactmesh::generators {

/// The truncated O-mesh variant of advancing_layers_2d (options.layers.method ==
/// LayerMethod2::TruncatedOMesh); the same result, its omesh_* counters set. stack_layers
/// holds per normal line the most layers of the two columns beside it.
/// @throws InputError on bad layer parameters or too many points; as advancing_layers_2d.
/// @throws GeometryError when the fill breaks the front or the final check fails (a bug).
AdvancingLayersResult2 truncated_omesh_2d(const MeshDomain2& domain,
                                          const AdvancingLayersOptions2& options);

}  // namespace exactmesh::generators
