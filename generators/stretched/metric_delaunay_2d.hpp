// SPDX-License-Identifier: MIT
// Metric Delaunay mesh generation (issue 14): a domain meshed to a metric field M(x, y) so that
// its edges have unit length in the metric [George-Borouchaki98 "Delaunay triangulation and
// meshing" ch. 7, 10; BorouchakiGeorgeHechtLaugSaltel97 "Delaunay mesh generation governed by
// metric specifications", Finite Elem. Anal. Des. 25; the BAMG scheme of Gmsh]:
//  1. the boundary's pieces split so that each has about unit metric length (the metric's size
//     along each piece's direction: discretize_domain_boundary with a per-piece size);
//  2. their constrained Delaunay triangulation, exterior and holes removed; where a thin layer of
//     the field turns so fast that the chord of one cell sags by several layer thicknesses, its
//     points first, as structured columns across the layer from the ridge of its smallest size
//     across (turning_layer_columns_2d), inserted as the passes insert theirs;
//  3. passes over the mesh's unconstrained edges: an edge longer than sqrt 2 in the metric (its
//     length in the log-Euclidean mean of its ends' metrics, as metric_quality_report_2d measures
//     edges: measured in each end's own metric, a chord of a curved layer counts its small
//     component across both ends' directions at the layer's thickness) proposes the point halfway
//     along it in the field sampled at 8 points (a thin layer it crosses gets the point), or,
//     where the layer turns so fast that a chord of one cell sags by more than half a layer,
//     the point on the column across the layer through the edge's finer end (an edge across the
//     layer) or on the arc through its ends (an edge along it); a
//     proposal is dropped when a vertex of the triangle holding it or of that triangle's
//     neighbours lies closer than `min_spacing` (measured the same way); the others are
//     inserted, in Hilbert order, by Bowyer-Watson in the plane
//     mapped by the metric at the point (ConstrainedTriangulation2::insert_in_metric_cavity:
//     the cavity decided by the exact in_ellipse with the shared symbolic perturbation, made
//     star-shaped by exact orient2d); passes stop when no point is inserted;
//  4. Lawson swapping of the unconstrained edges by in_ellipse under the log-Euclidean mean of the
//     four vertices' metrics (the same metric for both diagonals of a quadrilateral, so each
//     decision is one exact test; the mean of the matrices would add up the large eigenvalues of
//     metrics that rotate and lose the stretching), then towards the shorter diagonal (each in
//     its own ends' mean, exact compare_metric_lengths; not when the worse new triangle is a
//     sliver), with a budget of swaps per edge because a varying metric has no global potential
//     to guarantee termination;
//  5. up to 8 rounds: each unconstrained edge still longer than sqrt 2 split in four triangles
//     (the spacing test against its two apexes, exact orient2d), one end of each edge shorter
//     than 1/sqrt 2 removed (remove_vertices_2d, an independent set; skipped when the triangles
//     carry region attributes), each followed by the swaps of step 4, until a round changes
//     fewer than 0.5% of the vertices; then passes of point smoothing and swaps
//     (metric_mesh_edits_2d.hpp);
//  6. up to 10 rounds of the final optimization: each vertex with an edge outside
//     [1/sqrt 2, sqrt 2] moved by pattern search (steps along its metric's principal directions)
//     to the place with the most unit edges (then the smallest sum of ln(l)^2), kept only when
//     its triangles stay counter-clockwise (exact orient2d); then the swaps of step 4 and the
//     splits of step 5; until a round changes fewer than 0.1% of the vertices.
// Every input vertex and segment survives (the segments as chains of pieces, the boundary's
// points within rounding of them, as for every generator here). Metric lengths are computed
// without squared lengths (metric_length: hypot in the metric's frame; log forms of sizes in
// units of one power of two taken from the domain's metric), so a domain and its metric scaled
// by 2^k give the same mesh scaled.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "base/counter_table.hpp"
#include "generators/boundary/mesh_domain_2d.hpp"
#include "generators/stretched/metric_field_2d.hpp"
#include "generators/stretched/turning_layer_columns_2d.hpp"
#include "triangulation/constrained/constrained_2d.hpp"

namespace exactmesh::generators {

struct MetricDelaunayOptions2 {
    MetricField2 metric;
    /// A proposal closer than this (metric length) to a nearby vertex is dropped. 0.7 gave the
    /// largest share of unit edges of 0.5, 0.6, 0.7, 0.8 on a rotated (aspect 100), a boundary-
    /// layer and a curved-layer metric on the unit square (2026-12-02).
    double min_spacing = 0.7;
    /// Largest number of points inserted in the interior (0: kDefaultMetricPointBudget); the
    /// estimate of the mesh's size is checked against it before any work.
    std::uint64_t max_steiner_points = 0;
    /// In-ellipse swapping after the insertion passes, then point smoothing.
    bool swap = true;
    /// Passes of smoothing the inserted points (each a move half way to the metric-weighted
    /// centroid of the neighbours, at most 0.3 in the metric, kept only when no triangle
    /// inverts, exact), each followed by swaps; 0: none.
    int smoothing_passes = 2;
    /// Where the field turns so fast that the chord of one cell along a layer sags by more than
    /// half the layer's thickness, points go on columns across the layer and on arcs along it
    /// (proposal_point in the .cpp): the only arrangement such a layer's cells fit in.
    bool turning_columns = true;
    /// Where a thin layer turns so fast that the chord of one cell sags by several layer
    /// thicknesses (TurningLayerColumnsOptions2::sag_ratio), its points are placed first as
    /// structured columns across the layer from the curve of its smallest size across
    /// (turning_layer_columns_2d), lined up from layer to layer; the insertion passes fill the
    /// rest. Fields without such a layer get no column point (the same mesh either way).
    bool layer_columns = true;
    TurningLayerColumnsOptions2 columns;
    /// Most rounds of the final optimization (vertex relocation by pattern search towards unit
    /// edges, swaps, splits of the edges still long); rounds stop when one changes fewer than
    /// 0.1% of the vertices. 0: none.
    int optimization_rounds = 10;
    triangulation::Cdt2Options cdt;
};

/// The automatic budget of interior points: 2^26.
inline constexpr std::uint64_t kDefaultMetricPointBudget = std::uint64_t{1} << 26;

struct MetricDelaunayCounters2 {
    std::uint64_t boundary_points = 0;      ///< points added on the boundary's pieces
    std::uint64_t column_points = 0;        ///< points of turning layers' columns inserted
    std::uint64_t passes = 0;               ///< insertion passes
    std::uint64_t proposals = 0;            ///< edge midpoints proposed
    std::uint64_t too_close = 0;            ///< proposals dropped by the spacing test
    std::uint64_t inserted = 0;             ///< points inserted
    std::uint64_t rejected = 0;             ///< proposals the insertion refused (on a segment, ...)
    std::uint64_t cavity_corrections = 0;   ///< cavities reduced to be star-shaped
    std::uint64_t swaps = 0;                ///< in-ellipse swaps
    std::uint64_t swap_budget_hits = 0;     ///< edges whose swap budget ran out
    std::uint64_t smoothing_moves = 0;      ///< point moves kept
    std::uint64_t late_splits = 0;          ///< long edges split after the first swaps
    std::uint64_t late_removals = 0;        ///< vertices removed at short edges after them
    std::uint64_t optimization_rounds = 0;  ///< rounds of the final optimization
    std::uint64_t relocations = 0;          ///< vertex moves of the final optimization
};

inline constexpr std::array kMetricDelaunayCounterNames =
    EM_COUNTER_TABLE(MetricDelaunayCounters2, boundary_points, column_points, passes, proposals,
                     too_close, inserted, rejected, cavity_corrections, swaps, swap_budget_hits,
                     smoothing_moves, late_splits, late_removals, optimization_rounds, relocations);
static_assert(counter_table_complete(kMetricDelaunayCounterNames));

struct MetricDelaunayResult2 {
    triangulation::Cdt2Result mesh;
    MetricDelaunayCounters2 counters;
};

/// The estimated number of triangles of a unit mesh of the domain in the metric: the metric
/// area (the integral of sqrt(det M), sampled on the domain's triangles subdivided until the
/// metric is resolved) over the area of the unit equilateral triangle, sqrt 3 / 4.
double expected_metric_triangle_count(const MeshDomain2& domain, const MetricField2& metric);

/// @throws InputError as constrained_delaunay_2d; InputError when the estimate exceeds twice
///         the point budget (naming the estimate), when the segments enclose no region.
MetricDelaunayResult2 metric_delaunay_2d(const MeshDomain2& domain,
                                         const MetricDelaunayOptions2& options);

std::vector<std::pair<std::string, std::uint64_t>> counter_list(const MetricDelaunayCounters2& c);

}  // namespace exactmesh::generators
