// SPDX-License-Identifier: MIT
// Stretched Delaunay point insertion for airfoil domains (issue 14, the seed's seven steps)
// [Mavriplis90 "Adaptive mesh generation for viscous flows using Delaunay triangulation",
// J. Comput. Phys. 90; Mavriplis95 "Unstructured mesh generation and adaptivity", VKI LS §2.3]:
//  1. a structured O-mesh about each component (each closed loop of the domain's boundary with
//     the domain outside it): every wall vertex offset along its smoothed wall normal at the
//     heights first_height (growth^k - 1) / (growth - 1), k = 1..max_layers, each point rounded
//     once from the wall vertex (fma), a normal stopped when its layer's thickness reaches the
//     wall's tangential spacing there (cells of aspect ratio about 1) or its point leaves the
//     domain; staggered (an option), the odd layers sit on the sides' midpoints along the
//     mean of the two normals, half a spacing along the wall from the even ones, and a normal
//     stops at sqrt 3 / 2 of the spacing: the cells' triangles are equilateral in step 3's
//     metric;
//  2. filtering: O-mesh points not strictly inside the domain (exact orient2d on the domain's
//     CDT) go, as do points with a finer point of another component's O-mesh inside either
//     one's unit stretching ellipse (overlapping O-meshes: the finer kept); far-field points
//     (the centres of a quadtree's leaves refined to the far-field size) are kept only strictly
//     inside the domain and farther than `far_field_spacing` sizes from every O-mesh and
//     boundary point (and wake point). With wake_length > 0, a wake behind each trailing edge
//     (a wall's rearmost vertex when it is a convex corner sharper than 90 degrees, exact
//     orient2d and compare_angles): stations along the corner's bisector, each growth times
//     farther apart, with a centre point and staggered layers on both sides whose first height
//     grows by growth^2 per station (the stretching falls by growth per station), ending where
//     it turns isotropic, after wake_length chords or outside the domain; its points give way
//     to the boundary, the wall vertices, other components' O-meshes and finer points of other
//     wakes, and its own component's O-mesh points near it give way to it (the trailing edge's
//     fan of normals, stretched across the wake);
//  3. a metric per point: an O-mesh point's stretching (sizes its structured cell's spacing
//     along the wall, the mean distance to the same layer's points on the neighbouring normals,
//     and its layer's thickness times sqrt(growth) across it, the geometric mean
//     of its distances to the points below and above it, times 2 / sqrt 3 when staggered:
//     metric_from_stretching), the wall's own at the wall vertices (first_height across, times
//     2 / sqrt 3 when staggered), a far-field point's from its quadtree leaf (isotropic,
//     (1 + sqrt 2) / 2 times the leaf's side: the leaf grid's sides and diagonals both unit),
//     the far-field size's isotropic metric at the other boundary vertices;
//  4. the Euclidean constrained Delaunay triangulation of every point with the boundary's
//     pieces (constrained_delaunay_2d, holes and exterior removed);
//  5. the metrics smoothed over that triangulation (smooth_vertex_metrics), progressively:
//     weight 0 at the wall, growing with the layer, 1/2 in the far field;
//  6. Lawson swapping by the exact in-ellipse test under the mean metric of each quadrilateral
//     (swap_edges_2d with MetricInEllipse);
//  7. point smoothing: each O-mesh and far-field point moved towards the centroid of its
//     neighbours weighted by the edges' metric lengths (relaxed by its smoothing weight, at most
//     point_move_limit times its smallest size), a move kept only when every incident triangle
//     stays strictly counter-clockwise (exact orient2d); then swapping again;
//     `point_smoothing_passes` rounds;
//  8. (not in the seed) a cleanup of the flat triangles the in-ellipse swaps can leave where
//     the stretching turns quickly between neighbouring normals (a trailing edge's fan: the
//     mean of four matrices there is much less stretched than any of them): a triangle above
//     150 degrees gets the side opposite that angle swapped when the quadrilateral's largest
//     angle strictly decreases (exact compare_angles; measured: 5 swaps on the three-element
//     domain, 22 on a NACA 0012 at wall aspect ratio 1000, none left above 150 degrees).
// Every input vertex and segment survives (segments as chains of boundary pieces). Lengths are
// scale-free (predicates::scale_free_norm, metric_length) and points are built by exact power-
// of-two-scalable operations, so a domain scaled by 2^k with first_height and the far-field
// size scaled alike gives the same mesh scaled. Predicates: orient2d, in_ellipse_sos (through
// swap_edges_2d), compare_angles. Cost: the filters scan windows of the points sorted by x,
// O(P log P + P W) for P points and W in a window of the local spacing's width; the CDT
// O(P log P); the smoothing O(passes E). The swaps from the Euclidean triangulation dominate
// when the layers are many and thin: from the Euclidean CDT of long columns of points each
// point's stretched cell must be rebuilt (measured on the NACA 0012 with 1000 uniform layers of
// 1e-7: 4.7 10^6 swaps for 1.6 10^5 points, 1.7 10^6 for half as many layers).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "base/counter_table.hpp"
#include "generators/boundary/mesh_domain_2d.hpp"
#include "generators/sizing/size_function.hpp"
#include "generators/stretched/metric_2d.hpp"
#include "triangulation/constrained/constrained_2d.hpp"

namespace exactmesh::generators {

struct StretchedDelaunayOptions2 {
    /// The first layer's height at every wall (finite > 0).
    double first_height = 1e-3;
    /// The ratio of consecutive layers' thicknesses (finite >= 1).
    double growth = 1.2;
    /// The most layers per wall normal (>= 0).
    int max_layers = 40;
    /// Staggered layers: the odd layers' points on the midpoints of the wall's sides (along the
    /// mean of the two normals), half a spacing along the wall from the even layers', and the
    /// metric's size across 2 / sqrt 3 of the layer spacing, so that each structured cell's
    /// triangles are equilateral in it; the layers end at a thickness of sqrt 3 / 2 of the
    /// spacing (equilateral triangles). False: every layer on the wall vertices' normals, the
    /// cells split by their diagonals (79% unit edges on the NACA 0012).
    bool staggered_layers = false;
    /// Passes of averaging the wall normals with their neighbours' along each wall (>= 0).
    int normal_smoothing_passes = 2;
    /// Passes of smooth_vertex_metrics (step 5, >= 0).
    int metric_smoothing_passes = 3;
    /// Rounds of point smoothing and re-swapping (step 7, >= 0).
    int point_smoothing_passes = 2;
    /// The largest move of a point in one smoothing pass, in units of its metric's smallest
    /// size (in [0, 1]): a fraction of its layer's thickness in the layers, in any direction
    /// (a shift along the wall by more than that shears a stretched cell).
    double point_move_limit = 0.1;
    /// The far field's isotropic size; unbounded (the default): graded_size_from_boundary of
    /// the domain (its boundary spacing, graded).
    SizeFunction far_field_size;
    /// A far-field point is dropped when an O-mesh or boundary point lies closer than this many
    /// far-field sizes (finite in (0, 1]).
    double far_field_spacing = 0.7;
    /// The wake behind each trailing edge (a wall's rearmost vertex, largest x, when it is a
    /// convex corner sharper than 90 degrees): its length in chords of its component (finite
    /// >= 0; 0, the default: no wake). A strip of stretched points along the corner's bisector,
    /// ending sooner where it turns isotropic or leaves the domain (wake_points).
    double wake_length = 0;
    /// The most points of the O-meshes, and of the far field, each (0: kStretchedPointBudget);
    /// counted before the points are made (an InputError beyond it).
    std::uint64_t max_points = 0;
};

struct StretchedDelaunayCounters2 {
    std::uint64_t components = 0;            ///< walls with an O-mesh
    std::uint64_t wall_vertices = 0;         ///< vertices of those walls
    std::uint64_t omesh_points = 0;          ///< O-mesh points computed
    std::uint64_t outside_domain = 0;        ///< of those, not strictly inside the domain
    std::uint64_t overlap_dropped = 0;       ///< of those, by a finer point of another O-mesh
    std::uint64_t far_field_candidates = 0;  ///< quadtree leaf centres
    std::uint64_t far_field_dropped = 0;     ///< of those, outside or too near another point
    std::uint64_t duplicates = 0;            ///< points equal to an earlier point, dropped
    std::uint64_t points = 0;                ///< vertices of the triangulation
    std::uint64_t swaps = 0;                 ///< in-ellipse swaps of step 6
    std::uint64_t reswaps = 0;               ///< in-ellipse swaps after point smoothing
    std::uint64_t swap_budget_hits = 0;      ///< edges whose swap budget ran out
    std::uint64_t smoothing_moves = 0;       ///< point moves kept
    std::uint64_t smoothing_refused = 0;     ///< point moves that would invert a triangle
    std::uint64_t flat_swaps = 0;            ///< min-max swaps of triangles above 150 degrees
    std::uint64_t trailing_edges = 0;        ///< walls with a wake (wake_length > 0)
    std::uint64_t wake_points = 0;           ///< wake points computed
    std::uint64_t wake_dropped = 0;          ///< of those, outside or too near another point
    std::uint64_t wake_omesh_dropped = 0;    ///< O-mesh points near their own component's wake
};

inline constexpr std::array kStretchedDelaunayCounterNames = EM_COUNTER_TABLE(
    StretchedDelaunayCounters2, components, wall_vertices, omesh_points, outside_domain,
    overlap_dropped, far_field_candidates, far_field_dropped, duplicates, points, swaps, reswaps,
    swap_budget_hits, smoothing_moves, smoothing_refused, flat_swaps, trailing_edges, wake_points,
    wake_dropped, wake_omesh_dropped);
static_assert(counter_table_complete(kStretchedDelaunayCounterNames));

struct StretchedDelaunayResult2 {
    triangulation::Cdt2Result mesh;
    /// #V: each vertex's metric after step 5 (the one the swaps used).
    std::vector<Metric2> metrics;
    StretchedDelaunayCounters2 counters;
};

/// The largest number of O-mesh points, and of far-field points: 2^24 each (an InputError
/// beyond it, the O-mesh's counted before any point is made, the far field's before the CDT).
inline constexpr std::uint64_t kStretchedPointBudget = std::uint64_t{1} << 24;

/// @throws InputError on an option out of range, as constrained_delaunay_2d, when the segments
///         enclose no region, or when the layers or the far-field size ask for more than
///         kStretchedPointBudget points.
StretchedDelaunayResult2 stretched_delaunay_2d(const MeshDomain2& domain,
                                               const StretchedDelaunayOptions2& options);

std::vector<std::pair<std::string, std::uint64_t>> counter_list(
    const StretchedDelaunayCounters2& c);

}  // namespace exactmesh::generators
