// SPDX-License-Identifier: MIT
// Adaptive remeshing in 2D (issue 13; Peraire-Vahdati-Morgan-Zienkiewicz87, "Adaptive remeshing
// for compressible flow computations", JCP 72; the seed material's adaptation chapter). Both
// methods start from the indicator on the current mesh turned into a size field on it
// (indicator_size_field.hpp: per-vertex sizes by error equidistribution, linear over the current
// mesh as a background mesh):
//  - global remeshing (remesh_cycle_2d): a generator of the registry (mesh_generators_2d.hpp)
//    meshes the ORIGINAL domain again (its input vertices, segments and holes: RemeshDomain2)
//    with that size; the state is rebuilt from the generator's mesh (make_adaptive_mesh_2d with
//    the domain's curves, so later insertion cycles put boundary points on the curves) and the
//    field is sampled (analytic) or transferred from the old mesh (field_transfer.hpp). Under a
//    vertex budget the size is first scaled up until the registry's estimate
//    (minimum_triangle_count, the integral of 1 / s^2) is at most max_vertices triangles (a
//    generator's mesh has about half as many vertices as triangles; the estimate is a lower
//    bound, so the factor 2 is the margin), then, should the mesh still overshoot, scaled by
//    the excess vertices / max_vertices (its square root for the first two reruns; times 1.05,
//    at least 1.1) and run again, at most 8 runs; a generator's refusal of the size for its
//    count (BoundaryBudgetError, RefinementBudgetError) ends the cycle as a budget refusal.
//    The scaled size is capped at the domain's extent (size_ceiling_2d: it cannot overflow);
//  - local remeshing (local_remesh_cycle_2d): a triangle whose size (the mean of its edge
//    lengths) and wanted size (the mean of its corners' sizes) differ by more than `factor`
//    either way is removed; each void (a set of removed triangles connected across edges that
//    are not domain pieces) is refilled by the advancing front (advancing_front_2d.hpp) from its
//    boundary with the size field. The front is the void's boundary exactly as it is: kept edges
//    and domain pieces are never split (advancing_front_from_boundary_2d), so every kept
//    triangle, every piece (with its curve parameters) and every vertex on a void's boundary
//    stays bit for bit; the input vertices inside a void are kept too (free vertices of the
//    front); the void's other vertices go. The boundary's resolution is therefore not adapted
//    by this method (insertion cycles or global remeshing do that). Under a budget, the voids
//    that remove vertices are taken first, then the others in order while the count stays
//    within max_vertices; a void that does not fit keeps its triangles.
// Invariants after a cycle (check_adaptive_mesh_2d, with delaunay == false for local remeshing
// and for generators that are not constrained Delaunay): a valid triangulation of the domain
// whose constrained edges are exactly the pieces, input vertices at their input place and number.
// Cost: global, one generator run (a few when the budget forces rescaling) plus O(#V) transfer;
// local, O(#T) to flag and collect the voids plus the advancing front over the voids.
// Predicates: those of the generators; orient2d in the transfer and in link_neighbors_2d.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "base/counter_table.hpp"
#include "generators/adaptation/adaptive_mesh_2d.hpp"
#include "generators/adaptation/insertion_adaptation_2d.hpp"
#include "generators/boundary/sample_domains.hpp"
#include "generators/mesh_2d/mesh_generators_2d.hpp"

namespace exactmesh::generators {

/// The original domain global remeshing meshes again: the PSLG the first mesh was made from (its
/// spans: the caller's arrays outlive the call), the options it was triangulated with (numbering)
/// and, per segment (#S, or empty: every side straight), the curve it was sampled from.
struct RemeshDomain2 {
    triangulation::Pslg pslg;
    triangulation::Cdt2Options cdt;
    std::span<const SegmentCurve> segment_curves;
};

/// A sample domain's PSLG as a RemeshDomain2 (it refers to `domain`'s arrays).
RemeshDomain2 remesh_domain_2d(const DomainPslg& domain);

struct RemeshCounters2 {
    std::uint64_t cycles = 0;
    std::uint64_t generator_runs = 0;
    std::uint64_t budget_scalings = 0;  ///< size scaled up before a run (estimate over budget)
    std::uint64_t budget_reruns = 0;    ///< runs redone: the mesh overshot the budget
    std::uint64_t budget_refusals = 0;  ///< cycles left undone: at the budget, or no run fitted it
    std::uint64_t outside_values = 0;   ///< transferred values taken from the nearest old vertex
};

inline constexpr std::array kRemeshCounterNames2 =
    EM_COUNTER_TABLE(RemeshCounters2, cycles, generator_runs, budget_scalings, budget_reruns,
                     budget_refusals, outside_values);
static_assert(counter_table_complete(kRemeshCounterNames2));

struct LocalRemeshCounters2 {
    std::uint64_t cycles = 0;
    std::uint64_t too_large = 0;          ///< triangles removed: larger than factor × wanted
    std::uint64_t too_small = 0;          ///< triangles removed: smaller than wanted / factor
    std::uint64_t voids = 0;              ///< voids refilled
    std::uint64_t budget_kept_voids = 0;  ///< voids left as they were: over the vertex budget
    std::uint64_t removed_vertices = 0;   ///< vertices inside refilled voids, gone
    std::uint64_t new_points = 0;         ///< points the fronts placed
    std::uint64_t new_triangles = 0;      ///< triangles the fronts made
    std::uint64_t front_closures = 0;     ///< voids whose front was closed by its CDT (budget)
    std::uint64_t inner_inputs = 0;       ///< input vertices inside refilled voids, kept
    std::uint64_t slit_pieces = 0;        ///< pieces with the same void on both sides
    std::uint64_t outside_values = 0;     ///< transferred values taken from the nearest vertex
};

inline constexpr std::array kLocalRemeshCounterNames2 = EM_COUNTER_TABLE(
    LocalRemeshCounters2, cycles, too_large, too_small, voids, budget_kept_voids, removed_vertices,
    new_points, new_triangles, front_closures, inner_inputs, slit_pieces, outside_values);
static_assert(counter_table_complete(kLocalRemeshCounterNames2));

/// The size field of both methods: indicator_vertex_sizes of options.indicator on the current
/// mesh (state.values), linear over its triangles (indicator_size_function_2d).
SizeFunction remesh_size_function_2d(const AdaptiveMesh2& state, const AdaptationOptions& options);

/// One global remeshing cycle on `state` (state.values: the field at its vertices): `generator`
/// meshes `domain` with the indicator's size (scaled under options.max_vertices); the field on
/// the new mesh comes from `field`. Only options.indicator, threshold, reference_mean and
/// max_vertices are used.
/// Returns false, the state unchanged, when no run fitted options.max_vertices.
/// @throws InputError as the generator (e.g. a boundary discretization refusing a size graded
///         over dozens of orders of magnitude) and sample_field; GeometryError as the generator
///         (a piece too short to split in double precision); InternalError on a bug.
bool remesh_cycle_2d(AdaptiveMesh2& state, const RemeshDomain2& domain,
                     const MeshGenerator2& generator, const AdaptationOptions& options,
                     const FieldSource& field, RemeshCounters2& counters);
/// The same with the generator named as the registry names it.
/// @throws InputError on an unknown generator (naming the known ones).
bool remesh_cycle_2d(AdaptiveMesh2& state, const RemeshDomain2& domain, std::string_view generator,
                     const AdaptationOptions& options, const FieldSource& field,
                     RemeshCounters2& counters);

/// Local remeshing's choice: per triangle of state.mesh, 1 when its mean edge length exceeds
/// factor times the mean of its corners' sizes (remesh_size_function_2d's vertex values), 2 when
/// it is below that mean over factor, else 0.
/// @throws InputError on a factor that is not finite and > 1.
std::vector<std::uint8_t> local_remesh_flags_2d(const AdaptiveMesh2& state,
                                                const AdaptationOptions& options, double factor);

/// One local remeshing cycle on `state` with the triangle size ratio `factor` (> 1). Returns
/// false, the state unchanged, when no triangle was removed or no void fitted the budget.
/// The vertices that stay keep their order (the input vertices their numbers), the fronts' new
/// points follow them; the kept triangles come first, in their order and rotation.
/// Only options.indicator, threshold, reference_mean and max_vertices are used.
/// @throws InputError on a factor that is not finite and > 1, and as sample_field;
///         InternalError when the filled voids do not conform (a bug).
bool local_remesh_cycle_2d(AdaptiveMesh2& state, const AdaptationOptions& options,
                           const FieldSource& field, LocalRemeshCounters2& counters,
                           double factor = 2.0);

}  // namespace exactmesh::generators
