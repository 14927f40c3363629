// SPDX-License-Identifier: MIT
// Solution-adaptive h-refinement in 3D (issue 13): HRefinedMesh3 (Löhner's nested refinement with
// history, h_refinement_3d.hpp) driven by an edge indicator. A cycle marks the leaf edges whose
// indicator exceeds threshold × mean (no isotropic closure: the refinement's own rules close the
// patterns), refines, and puts the field on the new leaves (the analytic field sampled, or a
// given field carried by injection at old vertices and edge averages at new ones). Under a
// vertex budget the largest indicators are marked, halving their number until the refinement
// (tried on a copy: the rules add vertices beyond the marks) stays within it. A derefinement
// pass flags every leaf whose six edges are all below derefine_threshold × mean and restores the
// parents whose children are all flagged (one level per pass, the history's rules).
#pragma once

#include <cstdint>
#include <vector>

#include "generators/adaptation/h_adaptation_common.hpp"
#include "generators/adaptation/h_refinement_3d.hpp"
#include "generators/adaptation/insertion_adaptation_2d.hpp"

namespace exactmesh::generators {

struct HAdaptiveMesh3 {
    HRefinedMesh3 hierarchy;
    triangulation::Tetrahedralization3 leaves;  ///< hierarchy.leaf_mesh(), kept current
    std::vector<double> values;                 ///< the field at the leaves' vertices
};

HAdaptiveMesh3 make_h_adaptive_mesh_3d(triangulation::Tetrahedralization3 root);

using HAdaptationCounters3 = HAdaptationCounters;
inline constexpr const auto& kHAdaptationCounterNames3 = kHAdaptationCounterNames;

/// One refinement cycle; false when nothing was marked or the budget leaves no room.
bool h_refinement_cycle_3d(HAdaptiveMesh3& state, const AdaptationOptions& options,
                           const FieldSource& field, HAdaptationCounters3& counters);

/// One derefinement pass (state.values must be current): thresholds relative to
/// reference_mean, or (0) to the current mean; returns the leaves removed.
std::uint64_t h_derefinement_pass_3d(HAdaptiveMesh3& state, EdgeIndicator indicator,
                                     double threshold, double reference_mean,
                                     const FieldSource& field, HAdaptationCounters3& counters);

}  // namespace exactmesh::generators
