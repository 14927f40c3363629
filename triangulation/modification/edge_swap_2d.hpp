// SPDX-License-Identifier: MIT
// Lawson's edge swapping [Lawson77: C. L. Lawson, "Software for C1 surface interpolation", 1977]
// over a Triangulation2, in place, for any local criterion: an interior, unconstrained edge whose
// quadrilateral is strictly convex (exact orient2d) is replaced by the other diagonal when the
// criterion strictly prefers it; a queue of edges to test is refilled with the four sides of
// every swapped quadrilateral until no edge wants swapping. Criteria are small types:
//  - Delaunay: the SoS incircle [EdelsbrunnerMücke90] (ties broken by vertex index, as in
//    delaunay_2d), so from any triangulation of a point set it reaches exactly the triangulation
//    delaunay_2d builds, cocircular points included.
//  - MaxMinAngle / MinMaxAngle: the smallest (largest) of the six angles strictly increases
//    (decreases), compared exactly (predicates/angle_comparisons_2d.hpp).
//  - MinTotalLength: the new diagonal is strictly shorter (exact).
//  - DataDependent: Dyn, Levin and Rippa's data-dependent criteria for piecewise-linear
//    interpolation [DynLevinRippa90: "Data dependent triangulations for piecewise linear
//    interpolation", IMA J. Numer. Anal. 10(1), 1990], the l1 cost of the quadrilateral's five
//    edges, with either the angle between the normals (ABN) or the jump in normal derivatives
//    (JND) as the edge cost; the sums are compared exactly.
// Termination of every criterion is proved beside swap_edges_2d in edge_swap_2d.cpp.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <string_view>
#include <vector>

#include "base/counter_table.hpp"
#include "triangulation/checks/check_2d.hpp"
#include "triangulation/mesh/mesh2.hpp"
#include "triangulation/mesh/triangulation_2d.hpp"

namespace exactmesh::triangulation {

/// Delaunay by the SoS incircle: swap when the apex across the edge lies inside the
/// circumcircle (perturbed lifts by vertex index; never a tie in a strictly convex quad).
struct Delaunay {};
/// Swap when the minimum of the six angles of the two triangles strictly increases.
struct MaxMinAngle {};
/// Swap when the maximum of the six angles strictly decreases.
struct MinMaxAngle {};
/// Swap when the new diagonal is strictly shorter than the old one.
struct MinTotalLength {};

/// The cost of an interior edge under a data-dependent criterion [DynLevinRippa90 §3].
enum class DataCost {
    /// ABN: the angle (radians, in [0, pi]) between the normals of the two planes
    /// interpolating the values over the triangles on each side.
    AngleBetweenNormals,
    /// JND: |n . (grad1 - grad2)|, the jump of the derivative along the edge's unit normal n.
    JumpInNormalDerivatives,
};

/// Swap when the l1 cost (sum over the quadrilateral's diagonal and four sides, hull sides
/// costing nothing) strictly decreases. `values`: #V doubles, one per vertex (finite).
struct DataDependent {
    std::span<const double> values;
    DataCost cost = DataCost::AngleBetweenNormals;
};

/// Stamps of a mesh's triangles, shared by the swap runs over it and by its owner's own edits
/// between them, so that a run skips the quadrilaterals an earlier one found not to swap and
/// that have not changed since (SwapVerdicts2). Each triangle's stamp is renewed whenever the
/// triangle changes: a swap renews both triangles of its quadrilateral; the owner calls touch()
/// for every triangle it rewrites or adds, and reset() after anything that moves vertices,
/// renumbers vertices or triangles, or changes what a criterion reads about a vertex. A stamp is
/// never given twice (at the wrap of the 32-bit clock the era changes, voiding every verdict).
class TriangleStamps2 {
  public:
    /// Every triangle of a mesh of `triangles` triangles new (every verdict void).
    void reset(std::size_t triangles);
    /// Triangle t was rewritten or added (the stamps grow to cover it).
    void touch(TriIdx t);
    /// The triangles were renumbered: triangle t is old_of_new[t] as it was (the same vertices
    /// in the same order, vertices renumbered in their order), or new when that is kNone.
    void renumber(std::span<const TriIdx> old_of_new);
    /// Triangle t's stamp, 0 when it has none (then no verdict is taken or kept for it).
    std::uint32_t operator[](TriIdx t) const { return t < stamps_.size() ? stamps_[t] : 0; }
    std::uint32_t era() const { return era_; }

  private:
    std::uint32_t next();
    std::vector<std::uint32_t> stamps_;
    std::uint32_t clock_ = 0;
    std::uint32_t era_ = 0;
};

/// One criterion's verdicts from earlier runs over a stamped mesh: slot e's quadrilateral was
/// found not to swap (not strictly convex, or the criterion kept the diagonal) when its two
/// triangles had the stamps kept here; while both keep them, the quadrilateral is the same four
/// vertices at the same points and a run takes the verdict instead of deciding again. Valid for
/// a criterion that is a function of the quadrilateral's vertex indices and points (and of data
/// per vertex that the owner keeps, resetting the stamps when it changes). The budget still
/// counts: a kept diagonal of a strictly convex quadrilateral met after the budget is a stop.
struct SwapVerdicts2 {
    TriangleStamps2* stamps = nullptr;
    /// Per slot: the stamps of its triangle (high half) and of its twin's (low half), 0 none.
    std::vector<std::uint64_t> kept;
    /// Per slot: whether that quadrilateral was strictly convex.
    std::vector<std::uint8_t> convex;
    std::uint32_t era = 0;
    /// The triangles were renumbered as for TriangleStamps2::renumber: the verdicts follow.
    void renumber(std::span<const TriIdx> old_of_new);
};

/// Metric Delaunay (issue 14): swap when the apex across the edge lies inside the circumscribed
/// ellipse of the triangle in the mean of the quadrilateral's four vertex metrics (the SoS
/// in_ellipse, predicates/in_ellipse.hpp): both diagonals of a quadrilateral are judged in the
/// same metric, so each decision is one exact test and a single quadrilateral never flips back.
/// With a metric that varies over the mesh there is no global potential, so the loop stops
/// after max_swaps_per_edge times the number of edges swaps (counted in EdgeSwapCounters::
/// budget_stops).
struct MetricInEllipse {
    /// 3 per vertex: {M11, M12, M22} of each vertex's metric, all scaled by one common positive
    /// factor (finite doubles, positive definite).
    std::span<const double> metrics;
    std::uint32_t max_swaps_per_edge = 8;
    /// When set, the quadrilateral's metric instead of the mean of its vertices' `metrics`:
    /// quad_metric(a, b, c, d, out) writes {M11, M12, M22} (finite, positive definite, any
    /// positive scale) for the quadrilateral of vertices a, b, c, d (e.g. a log-Euclidean
    /// mean, which keeps the stretching of metrics that rotate from vertex to vertex, where the
    /// mean of the matrices loses it).
    std::function<void(VertIdx, VertIdx, VertIdx, VertIdx, double*)> quad_metric = {};
    /// When set, the verdicts of earlier runs with the same metrics (SwapVerdicts2), renewed by
    /// this run.
    SwapVerdicts2* verdicts = nullptr;
};

/// A caller's decision per quadrilateral: swap(v, p) is true when the diagonal c - d is preferred
/// to a - b, the current one, for the vertices v = {a, b, c, d} (c the apex of the triangle left
/// of a -> b, d of the one right of it) at the points p; it must give false for {c, d, b, a}
/// whenever it gives true for {a, b, c, d} (then a single quadrilateral never flips back), e.g.
/// one exact comparison of the two diagonals. With no
/// global potential the loop stops after max_swaps_per_edge times the number of edges swaps
/// (budget_stops).
struct QuadPreference {
    std::function<bool(const std::array<VertIdx, 4>&, const std::array<const double*, 4>&)> swap =
        {};
    std::uint32_t max_swaps_per_edge = 8;
    /// When set, the verdicts of earlier runs with the same decision (SwapVerdicts2), renewed by
    /// this run.
    SwapVerdicts2* verdicts = nullptr;
};

/// The criterion names of the CLI and benches.
enum class SwapCriterion { Delaunay, MaxMinAngle, MinMaxAngle, MinTotalLength, DataDependent };
/// "delaunay", "max-min-angle", "min-max-angle", "min-length", "data-dependent"; throws
/// InputError naming the known ones otherwise.
SwapCriterion swap_criterion_from_name(std::string_view name);

/// Work counters of one swapping run.
struct EdgeSwapCounters {
    std::uint64_t edges_tested = 0;  ///< edges popped from the queue and examined
    std::uint64_t not_convex = 0;    ///< of those, skipped: quadrilateral not strictly convex
    std::uint64_t constrained = 0;   ///< of those, skipped: constrained (or on the boundary)
    std::uint64_t swaps = 0;         ///< edges swapped
    std::uint64_t budget_stops = 0;  ///< MetricInEllipse: edges left because the budget ran out
};

/// The name table of EdgeSwapCounters (base/counter_table.hpp): --stats prints it in this order.
inline constexpr std::array kEdgeSwapCounterNames =
    EM_COUNTER_TABLE(EdgeSwapCounters, edges_tested, not_convex, constrained, swaps, budget_stops);
static_assert(counter_table_complete(kEdgeSwapCounterNames));

/// Swaps edges of `mesh` until none is swappable and preferred by the criterion.
/// @pre mesh.neighbors is consistent (see link_neighbors_2d), triangles strictly counter-
///      clockwise, coordinates finite; constrained edges are never swapped or crossed.
/// Vertex indices are the SoS tie-break ranks (a larger index is perturbed more).
EdgeSwapCounters swap_edges_2d(Triangulation2& mesh, Delaunay criterion);
EdgeSwapCounters swap_edges_2d(Triangulation2& mesh, MaxMinAngle criterion);
EdgeSwapCounters swap_edges_2d(Triangulation2& mesh, MinMaxAngle criterion);
EdgeSwapCounters swap_edges_2d(Triangulation2& mesh, MinTotalLength criterion);
/// MinMaxAngle on a mesh already lent as half-edges (a HalfEdgeEdit's, open: boundary twins
/// kNone, flag bit 0 constrained), from the half-edges in `seeds` only (and the sides of every
/// swapped quadrilateral, as above): the local pass of an incremental generator after its
/// insertions (min_max_front_2d). Dead triangles' seeds are skipped. No point validation.
EdgeSwapCounters swap_edges_2d(TriMesh2& mesh, MinMaxAngle criterion,
                               std::span<const EdgeIdx> seeds);
/// @throws InputError when criterion.values does not hold one finite value per vertex.
EdgeSwapCounters swap_edges_2d(Triangulation2& mesh, DataDependent criterion);
/// @throws InputError when criterion.metrics does not hold three finite values per vertex.
EdgeSwapCounters swap_edges_2d(Triangulation2& mesh, MetricInEllipse criterion);
/// Swaps strictly convex quadrilaterals as criterion.swap says. @throws InputError when it is
/// empty.
EdgeSwapCounters swap_edges_2d(Triangulation2& mesh, QuadPreference criterion);
/// The same two on a mesh already lent as half-edges (a HalfEdgeEdit's: open, boundary twins
/// kNone, flag bit 0 constrained, no dead triangles), from every interior edge: the same swaps,
/// and runs in a row on one lending (the metric generator's two criteria) build the half-edges
/// once.
EdgeSwapCounters swap_edges_2d(TriMesh2& mesh, MetricInEllipse criterion);
EdgeSwapCounters swap_edges_2d(TriMesh2& mesh, QuadPreference criterion);

/// Fills mesh.neighbors from mesh.triangles (each undirected edge shared by at most two
/// triangles, in opposite directions) and sizes mesh.constrained to match when it is not empty.
/// @throws InputError naming the edge when a directed edge appears twice or a vertex index is
///         out of range, or when a triangle is not strictly counter-clockwise (exact orient2d);
///         messages number vertices and triangles from `numbering`'s bases (a file's own).
void link_neighbors_2d(Triangulation2& mesh, CheckNumbering numbering = {});

}  // namespace exactmesh::triangulation
