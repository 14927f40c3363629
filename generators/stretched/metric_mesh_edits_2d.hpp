// SPDX-License-Identifier: MIT
// Edits of a finished triangle mesh towards a metric, shared by the stretched generators
// (metric_delaunay_2d, stretched_delaunay_2d; issue 14):
//  - metric_swaps_2d: Lawson swaps by the exact in-ellipse under each quadrilateral's mean metric
//    (swap_edges_2d with MetricInEllipse), the vertices' matrices in one common scale;
//  - smooth_metric_points_2d: one Gauss-Seidel pass moving each movable vertex towards the
//    centroid of its neighbours weighted by the edges' metric lengths, a move kept only when
//    every triangle at the vertex stays strictly counter-clockwise (exact orient2d).
// Sizes are never squared: the common scale divides by the smallest size first, and steps are
// measured with metric_length or scale_free_norm, so a mesh and its metrics scaled by 2^k give
// the same edits scaled.
#pragma once

#include <cstdint>
#include <span>

#include "generators/stretched/metric_2d.hpp"
#include "triangulation/mesh/triangulation_2d.hpp"
#include "triangulation/modification/edge_swap_2d.hpp"

namespace exactmesh::generators {

/// swap_edges_2d(mesh, MetricInEllipse) with metrics[v] (one per vertex) as matrices scaled by
/// the square of the smallest size of all.
/// With log_euclidean, each quadrilateral's metric is instead the log-Euclidean mean of its four
/// vertices' metrics (log_euclidean_mean): where the metric rotates from vertex to vertex (a
/// curved boundary layer) the mean of the matrices adds up their large eigenvalues in every
/// direction and loses the stretching (aspect ratio 100 turned about 12 over one cell), while the
/// log-Euclidean mean keeps it and measures as metric_quality_report_2d does.
/// `memo` (optional) takes the means' exponentials (the same swaps, fewer exponentials when the
/// caller keeps it across calls).
/// `verdicts` (optional, log_euclidean only): the verdicts of earlier calls on the same mesh
/// (triangulation::SwapVerdicts2), whose owner resets their stamps whenever a vertex's metric
/// or the binary exponent of the smallest size of all the metrics changes (the log forms'
/// unit): the same swaps, fewer decisions.
triangulation::EdgeSwapCounters metric_swaps_2d(triangulation::Triangulation2& mesh,
                                                std::span<const Metric2> metrics,
                                                bool log_euclidean = false,
                                                MetricFromLogFormMemo* memo = nullptr,
                                                triangulation::SwapVerdicts2* verdicts = nullptr);

/// Swaps each strictly convex quadrilateral whose other diagonal is strictly shorter, each
/// diagonal measured in the log-Euclidean mean of its own two ends' metrics (as
/// metric_quality_report_2d measures edges), compared exactly (compare_metric_lengths, the two
/// matrices in one scale). Where the metric rotates faster than a cell's in-ellipse can follow
/// (a curved layer of aspect ratio 1000: the ring of a cell's neighbours sags by tens of layer
/// thicknesses in any single metric), this keeps the edges the report counts.
/// `memo` and `verdicts` as for metric_swaps_2d.
triangulation::EdgeSwapCounters shorter_diagonal_swaps_2d(
    triangulation::Triangulation2& mesh, std::span<const Metric2> metrics,
    MetricFromLogFormMemo* memo = nullptr, triangulation::SwapVerdicts2* verdicts = nullptr);

/// The same two on a mesh already lent as half-edges (a triangulation::HalfEdgeEdit's): the same
/// swaps, the half-edges built once for both.
triangulation::EdgeSwapCounters metric_swaps_2d(triangulation::TriMesh2& mesh,
                                                std::span<const Metric2> metrics,
                                                bool log_euclidean, MetricFromLogFormMemo* memo,
                                                triangulation::SwapVerdicts2* verdicts);
triangulation::EdgeSwapCounters shorter_diagonal_swaps_2d(triangulation::TriMesh2& mesh,
                                                          std::span<const Metric2> metrics,
                                                          MetricFromLogFormMemo* memo,
                                                          triangulation::SwapVerdicts2* verdicts);

/// How far one smoothing move may go.
enum class MoveLimit {
    /// At most `limit` times the vertex metric's smallest size, in every direction (a stretched
    /// layer cell sheared along the wall by more than a fraction of its thickness turns obtuse).
    SmallestSize,
    /// At most `limit` in the vertex's metric (a unit mesh in the metric).
    MetricLength,
};

struct PointSmoothingCounters2 {
    std::uint64_t moves = 0;    ///< moves kept
    std::uint64_t refused = 0;  ///< moves that would have inverted or flattened a triangle
};

/// One pass over the vertices from `first_movable` on (in order), each moved by relax[v] (0: not
/// moved) times the way to the centroid of its neighbours weighted by the edges' metric lengths
/// (the mean of the lengths in both ends' metrics), limited as `limit_kind` says; with
/// keep_unit_edges, a move that leaves fewer of the vertex's edges with metric length in
/// [1/sqrt 2, sqrt 2] is refused too. With log_euclidean_lengths, an edge's metric length (the
/// weights and the unit test) is its length in the log-Euclidean mean of its ends' metrics (as
/// metric_quality_report_2d measures), instead of the mean of its lengths in both; `memo` as for
/// metric_swaps_2d.
/// @pre metrics and relax hold one value per vertex; the mesh's triangles are counter-clockwise.
PointSmoothingCounters2 smooth_metric_points_2d(
    triangulation::Triangulation2& mesh, std::span<const Metric2> metrics,
    std::span<const double> relax, double limit, MoveLimit limit_kind,
    triangulation::VertIdx first_movable, bool keep_unit_edges = false,
    bool log_euclidean_lengths = false, MetricFromLogFormMemo* memo = nullptr);

}  // namespace exactmesh::generators
