// SPDX-License-Identifier: MIT
// The points a narrow gap of a PLC asks for, estimated before any 3D generator runs (issue 15).
// Two facets a distance g apart (a box-shaped hole 1e-9 from the outer wall) make every
// generator split their subfaces until they are about g wide: about area / g^2 points, 10^17 at
// g = 1e-9 on a unit box, which refinement used to chase into its Steiner budget for a minute.

// The estimate: for each triangle t of the facets' triangulation (triangulate_facets_3d), the
// nearest triangle that shares no vertex with it, if nearer than t's longest edge L_t; with
// none, t counts area_t / (4 L_t^2); with one, t is sampled at the centres of its k^2
// congruent sub-triangles (k = L_t / distance, at most 16), each counting its area / (4 f^2), f
// the distance from its centre to the nearest triangle sharing no vertex with t, capped by L_t
// and floored at 2^-44 of the coordinates' magnitude (the generators spare tetrahedra with
// edges below that fraction, so no finer feature is chased): about the surface points that
// resolve f (a disc of radius f per point). Measured on a unit box with a box-shaped hole g from
// its wall (1/2 x 1/2 facing): g = 1e-2 and 1e-3 estimate 1,350 and 125,000 points where
// refinement (radius-edge 2) makes 1,490 and 135,761 vertices.
// Scale-invariant: computed on coordinates scaled by one power of two (exact) that brings the
// largest to [1, 2), so no square overflows or underflows at 2^+-600 (a gap below 2^-511 of the
// extent floors at 2^-44 anyway). A decision of how much work to accept, not of geometry:
// computed in doubles (the distances round). The estimate stayed below every count Delaunay
// refinement made (1.1 to 7 times its points on the sample domains, box-shaped holes 1e-4 to
// 1e-2 from a wall or from each other, needles), up to 2.3 times between parallel walls, so
// every generator refuses where 2.2 times the estimate exceeds the budget (kGapMargin3: with a
// margin of 6, two holes 1e-4 apart, estimate 2e6, ran 52 s into a budget of 1.02e6; with 1, a
// slab 0.001 thick, estimate 5e5, ran 120 s into it). Frontal insertion and the octree split
// what encroaches at the size, so they resolve a gap as refinement does (a turned plate 0.001
// thick at size 0.1: 1.43e6 tetrahedra, refinement's count; a slab region, 120 s and more), but
// not between walls whose triangulations line up (two unturned box holes 1e-4 apart at size
// 0.1: 1,963 vertices, refused by the margin all the same: raise the budget there).
// Cost: nearest-triangle queries in a bounding-box tree of the T surface triangles, one per
// triangle and one per sample (at most 256 per triangle); the wing's 672 triangles, fans of
// long thin ones on its walls, take 0.17 s with the samples (1.06 s with the grid of cells of
// the median edge used before, which also missed features more than a cell away), and under
// 10 ms when a limit lets the first pass's bound (98,583 points against a budget of 1.3 10^6)
// decide alone.
#pragma once

#include <cstdint>

#include "triangulation/mesh/conforming_mesh_3d.hpp"
#include "triangulation/mesh/plc_3d.hpp"

namespace exactmesh::generators {

struct GapEstimate3 {
    double points = 0;            ///< sum over the surface triangles of area / (4 f^2)
    double smallest_feature = 0;  ///< the least f, in the input's units (0: no triangle)
    /// `points` is the upper bound of the first pass, at most `enough` (no sample taken).
    bool upper_bound_only = false;
};

/// The estimate for a PLC that passed validate_plc_3d. With `recovered` (its boundary
/// recovery), only gaps through the domain count: two facets facing each other across a hole
/// or the outside (a thin box-shaped hole's two large walls) ask for nothing, since no
/// generator splits a subface for a point it cannot see (a 0.0625 x 0.5 x 1e-4 hole was
/// refused as asking for 1.6 10^6 points; refinement meshes it with 44,210 vertices, TetGen
/// with 43,127). Without it both sides of every facet count.
/// The samples are taken only when an upper bound, from each triangle's distance to its nearest
/// triangle alone (a sample of t is no nearer to anything than t is, up to rounding), exceeds
/// `enough`: a caller that only compares the estimate with a limit passes the limit (the
/// wing's samples took 0.17 s of its refinement at 7 10^5 tetrahedra).
GapEstimate3 gap_estimate_3d(const triangulation::Plc3& plc,
                             const triangulation::ConformingMesh3* recovered = nullptr,
                             double enough = -1);

/// Every 3D generator's margin: between parallel walls refinement makes 2.0 to 2.3 times the
/// estimate (a 0.1-wide box hole 1e-4 from a wall: estimate 4.94e5, 1.01e6 points, TetGen
/// 1.02e6; a slab region 0.001 thick across a unit cube: 5.0e5, past 1.01e6 at its budget after
/// 120 s, TetGen 1.16e6 in 72 s; a plate 0.004 thick alone: 31,250, 63,021, TetGen 63,269), and
/// frontal insertion and the octree as many on turned walls, so a PLC is refused where 2.2 times
/// the estimate exceeds the budget.
inline constexpr double kGapMargin3 = 0.45;

/// Throws InputError, prefixed by `who`, when the estimate (with the recovered mesh's sides)
/// exceeds kGapMargin3 times `budget` (Steiner points), naming the estimate, the smallest
/// feature and the margin; does nothing otherwise.
void refuse_gaps_far_over_budget_3d(const triangulation::Plc3& plc,
                                    const triangulation::ConformingMesh3& recovered,
                                    std::uint64_t budget, const char* who);

}  // namespace exactmesh::generators
