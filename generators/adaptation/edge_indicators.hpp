// SPDX-License-Identifier: MIT
// Refinement indicators per edge and the flagging rules (issue 13; seed material's adaptation
// chapter; Löhner 1987, "An adaptive finite element scheme for transient problems in CFD",
// CMAME 61; Warren et al. 1991, "A comparison of refinement indicators for adaptive
// unstructured grid generation"). For edge (i, j) with d = x_j - x_i, field values u and
// recovered vertex gradients g (gradient_recovery below):
//  - first-difference:  |u_j - u_i|                                   (undivided Δu)
//  - second-difference: |(g_j - g_i) · d|                             (∂²u/∂s² · h²)
//  - loehner:           |(g_j - g_i)·d| / (|g_i·d| + |g_j·d| + α (|u_i| + |u_j|)), in [0, 1]
//                       (second over first differences, the noise filter α ū; 0 on a flat field)
//  - length-weighted:   |u_j - u_i| · |d|                             (Δu · Δx)
// Every length is taken in the mesh's unit scale (mesh_edges.hpp: coordinates times 2^-E), so
// the indicators are bit for bit the same on a mesh scaled by any power of two. The indicators
// only rank edges (relative to their mean or to each other); no sign of a geometric predicate
// depends on them.
// Gradient recovery: the area- (volume-) weighted mean of the linear interpolant's gradient over
// the elements at a vertex [Zienkiewicz-Zhu's simplest average], from the elements' edge
// vectors and differences without a division per element.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "triangulation/mesh/mesh2.hpp"

namespace exactmesh::generators {

enum class EdgeIndicator { FirstDifference, SecondDifference, Loehner, LengthWeighted };

inline constexpr EdgeIndicator kAllEdgeIndicators[] = {
    EdgeIndicator::FirstDifference, EdgeIndicator::SecondDifference, EdgeIndicator::Loehner,
    EdgeIndicator::LengthWeighted};

/// "first-difference", "second-difference", "loehner", "length-weighted".
std::string_view edge_indicator_name(EdgeIndicator indicator);
/// @throws InputError naming the unknown indicator and the known ones.
EdgeIndicator edge_indicator_from_name(std::string_view name);

/// Löhner's noise filter α (his ε, 0.01 to 0.2 in his papers).
inline constexpr double kLoehnerNoiseFilter = 0.05;

/// dim·#V recovered gradients in unit-scale coordinates (`unit_xy` = coordinates times 2^-E) of
/// the elements (3 vertices per triangle for dim 2, 4 per tetrahedron for dim 3, kNone slots
/// skipped); 0 at vertices in no element.
std::vector<double> recover_gradients(std::span<const double> unit_coordinates, unsigned dim,
                                      std::span<const triangulation::VertIdx> elements,
                                      std::span<const double> values);

/// The indicator on every edge (edges from mesh_edges_2d/3d); `gradients` from
/// recover_gradients (unused, may be empty, for the two first-difference forms).
std::vector<double> edge_indicator(EdgeIndicator indicator,
                                   std::span<const double> unit_coordinates, unsigned dim,
                                   std::span<const triangulation::VertIdx> edges,
                                   std::span<const double> values,
                                   std::span<const double> gradients);

/// The indicator on every edge of a mesh in its own coordinates: the unit scale
/// (mesh_edges.hpp), the gradients when the indicator needs them, then edge_indicator.
std::vector<double> mesh_edge_indicator(EdgeIndicator indicator,
                                        std::span<const double> coordinates, unsigned dim,
                                        std::span<const triangulation::VertIdx> elements,
                                        std::span<const triangulation::VertIdx> edges,
                                        std::span<const double> values);

/// Per vertex, the largest indicator of the edges at it (0 at a vertex of no edge): what
/// solution-weighted movement (weighted_movement.hpp) draws vertices towards.
std::vector<double> vertex_indicator(std::span<const triangulation::VertIdx> edges,
                                     std::span<const double> indicator, std::size_t vertex_count);

/// vertex_indicator of mesh_edge_indicator over every edge of a mesh (mesh_edges_2d for dim 2,
/// mesh_edges_3d for dim 3), one value per vertex of `coordinates`: the movement's weights.
std::vector<double> mesh_vertex_indicator(EdgeIndicator indicator,
                                          std::span<const double> coordinates, unsigned dim,
                                          std::span<const triangulation::VertIdx> elements,
                                          std::span<const double> values);

/// Edges whose indicator exceeds threshold times the mean over all edges (the seed material's
/// rule); 1 per flagged edge.
std::vector<std::uint8_t> flag_above_mean(std::span<const double> indicator, double threshold,
                                          double reference_mean = 0);

/// The mean of the indicator over all edges (0 for none): what thresholds are relative to.
double mean_indicator(std::span<const double> indicator);

/// The `count` edges with the largest indicator (ties broken by the lower edge number), for a
/// vertex budget; 0-valued edges are never flagged.
std::vector<std::uint8_t> flag_largest(std::span<const double> indicator, std::size_t count);

/// The edges to refine (one flag per edge of `edges`, mesh_edges_2d/3d of `elements`, dim + 1
/// vertices each): flagged by the indicator above threshold × mean, then the isotropic closure
/// (one pass: every element with an edge the indicator flagged gets all its edges flagged), and
/// under a budget of `room` new vertices (budget true) the largest indicators whose closure
/// fits it. *flagged and *closure (when not null) count the indicator's and the closure's edges.
std::vector<std::uint8_t> refinement_flags(std::span<const triangulation::VertIdx> elements,
                                           unsigned dim,
                                           std::span<const triangulation::VertIdx> edges,
                                           std::span<const double> indicator, double threshold,
                                           std::uint64_t room, bool budget, std::uint64_t* flagged,
                                           std::uint64_t* closure, double reference_mean = 0);

}  // namespace exactmesh::generators
