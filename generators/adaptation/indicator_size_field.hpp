// SPDX-License-Identifier: MIT
// The indicator turned into a size field on the current mesh (issue 13: the background mesh of
// Steiner restart and adaptive remeshing; the seed material's "error equidistribution"). An
// edge of length h whose indicator is I_e asks for the length
//     h_e = h (target / I_e)^(1 / p),   target = threshold × mean(I),
// (or target = threshold × a fixed reference mean) where p is the order in h of the indicator on a
// smooth field: 1 for first-difference
// (|Δu| ~ |u'| h), 2 for second-difference (|u''| h²), length-weighted (|u'| h²) and loehner
// (treated as second order, as Löhner's refinement levels are); so every edge at the target
// keeps its length, an edge above it shrinks, one below grows. A vertex takes the smallest
// length its edges ask for, clamped to [h_v / max_factor, h_v × max_factor] (h_v: its shortest
// edge), so one cycle never asks for a jump the indicator (measured on this mesh) cannot see.
// An edge with indicator 0 asks for max_factor × h. Lengths are scale-free
// (predicates::scale_free_norm): ×2^k gives sizes ×2^k exactly, no overflow at 2^±600.
#pragma once

#include <span>
#include <vector>

#include "generators/adaptation/edge_indicators.hpp"
#include "generators/sizing/size_function.hpp"

namespace exactmesh::generators {

/// The order p above.
double indicator_order(EdgeIndicator indicator);

/// #V sizes at the vertices (dim 2 or 3; edges from mesh_edges_2d/3d, indicator per edge);
/// vertices of no edge get +infinity. reference_mean > 0 replaces the mean of `indicator` in the
/// target (a transient run's fixed target, AdaptationOptions::reference_mean): the sizes then
/// no longer depend on how fine the rest of the mesh is, which a steady vertex count needs.
std::vector<double> indicator_vertex_sizes(std::span<const double> coordinates, unsigned dim,
                                           std::span<const triangulation::VertIdx> edges,
                                           std::span<const double> indicator, EdgeIndicator kind,
                                           double threshold, double max_factor = 4.0,
                                           double reference_mean = 0);

/// The 2D size function: the sizes linear over the mesh's triangles
/// (SizeFunction::background_mesh); the vertices of no triangle take the largest finite size.
SizeFunction indicator_size_function_2d(std::span<const double> xy,
                                        std::span<const triangulation::VertIdx> triangles,
                                        std::vector<double> vertex_sizes);

}  // namespace exactmesh::generators
