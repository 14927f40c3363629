// SPDX-License-Identifier: MIT
// Solution-adaptive h-refinement in 2D (issue 13): HRefinedMesh2 (red-green refinement with
// history, h_refinement_2d.hpp) driven by an edge indicator, as h_adaptation_3d does in 3D. A
// cycle marks the leaf edges whose indicator exceeds threshold × mean (the refinement's closure
// makes the rest conforming), refines, and puts the field on the new leaves (the analytic field
// sampled, or injection at old vertices and edge midpoints' averages at new ones). Under a vertex
// budget the largest indicators are marked, halving their number until the refinement (tried on
// a copy) stays within it. A derefinement pass flags every leaf whose three edges are all below
// derefine_threshold × mean and coarsens one generation by the history.
#pragma once

#include <cstdint>
#include <vector>

#include "generators/adaptation/h_adaptation_common.hpp"
#include "generators/adaptation/h_refinement_2d.hpp"
#include "generators/adaptation/insertion_adaptation_2d.hpp"

namespace exactmesh::generators {

struct HAdaptiveMesh2 {
    HRefinedMesh2 hierarchy;
    std::vector<double> values;  ///< the field at hierarchy.leaf_mesh()'s vertices
};

using HAdaptationCounters2 = HAdaptationCounters;
inline constexpr const auto& kHAdaptationCounterNames2 = kHAdaptationCounterNames;

/// One refinement cycle; false when nothing was marked or the budget leaves no room.
bool h_refinement_cycle_2d(HAdaptiveMesh2& state, const AdaptationOptions& options,
                           const FieldSource& field, HAdaptationCounters2& counters);

/// One derefinement pass (thresholds relative to reference_mean, or (0) to the current mean);
/// returns the vertices removed.
std::uint64_t h_derefinement_pass_2d(HAdaptiveMesh2& state, EdgeIndicator indicator,
                                     double threshold, double reference_mean,
                                     const FieldSource& field, HAdaptationCounters2& counters);

}  // namespace exactmesh::generators
