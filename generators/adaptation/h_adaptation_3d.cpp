// SPDX-License-Identifier: MIT
// Indicator-driven 3D h-refinement and derefinement (see h_adaptation_3d.hpp).
#include "generators/adaptation/h_adaptation_3d.hpp"

#include <numeric>

#include "generators/adaptation/edge_indicators.hpp"
#include "generators/adaptation/h_adaptation_common.hpp"
#include "generators/topology/mesh_edges.hpp"

namespace exactmesh::generators {

using triangulation::VertIdx;

namespace {

void set_values(HAdaptiveMesh3& state, const FieldSource& field) {
    if (field.analytic != nullptr)
        state.values = sample_field(*field.analytic, state.leaves.xyz, 3, field.t);
    else
        state.values = state.hierarchy.transfer(state.values);
}

}  // namespace

HAdaptiveMesh3 make_h_adaptive_mesh_3d(triangulation::Tetrahedralization3 root) {
    HAdaptiveMesh3 state{HRefinedMesh3(std::move(root)), {}, {}};
    state.leaves = state.hierarchy.leaf_mesh();
    return state;
}

bool h_refinement_cycle_3d(HAdaptiveMesh3& state, const AdaptationOptions& options,
                           const FieldSource& field, HAdaptationCounters3& counters) {
    const triangulation::Tetrahedralization3& mesh = state.leaves;
    const auto marks_of = [](const std::vector<std::uint8_t>& flags,
                             const std::vector<VertIdx>& edges) {
        std::vector<std::array<VertIdx, 2>> marks;
        for (std::size_t e = 0; e < flags.size(); ++e)
            if (flags[e]) marks.push_back({edges[2 * e], edges[2 * e + 1]});
        return marks;
    };
    const std::size_t count = detail::refine_marked_edges(
        state.hierarchy, options, mesh.xyz, 3, mesh.tets, state.values, marks_of,
        [](const HRefinedMesh3& h) { return h.vertex_count(); }, counters.budget_retries);
    if (count == 0) return false;
    counters.marked_edges += count;
    ++counters.cycles;
    state.leaves = state.hierarchy.leaf_mesh();
    set_values(state, field);
    return true;
}

std::uint64_t h_derefinement_pass_3d(HAdaptiveMesh3& state, EdgeIndicator indicator,
                                     double threshold, double reference_mean,
                                     const FieldSource& field, HAdaptationCounters3& counters) {
    const triangulation::Tetrahedralization3& mesh = state.leaves;
    const std::vector<VertIdx> edges = mesh_edges_3d(mesh.tets);
    if (edges.empty()) return 0;
    const std::vector<double> ind =
        mesh_edge_indicator(indicator, mesh.xyz, 3, mesh.tets, edges, state.values);
    const double mean = reference_mean > 0 ? reference_mean : mean_indicator(ind);
    const MeshEdgeIndex index(edges);
    std::vector<std::uint8_t> flags(mesh.tet_count(), 0);
    for (std::size_t t = 0; t < mesh.tet_count(); ++t) {
        bool low = true;
        for (unsigned i = 0; i < 4 && low; ++i)
            for (unsigned j = i + 1; j < 4 && low; ++j)
                low =
                    ind[index.find(mesh.tets[4 * t + i], mesh.tets[4 * t + j])] < threshold * mean;
        flags[t] = low ? 1 : 0;
    }
    ++counters.derefinement_passes;
    counters.derefine_flagged +=
        static_cast<std::uint64_t>(std::count(flags.begin(), flags.end(), 1));
    const std::uint32_t before = mesh.tet_count();
    state.hierarchy.derefine(flags);
    state.leaves = state.hierarchy.leaf_mesh();
    set_values(state, field);
    return before > state.leaves.tet_count() ? before - state.leaves.tet_count() : 0;
}

}  // namespace exactmesh::generators
