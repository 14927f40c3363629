// SPDX-License-Identifier: MIT
// Indicator-driven 2D h-refinement and derefinement (see h_adaptation_2d.hpp).
#include "generators/adaptation/h_adaptation_2d.hpp"

#include <algorithm>

#include "generators/adaptation/edge_indicators.hpp"
#include "generators/adaptation/h_adaptation_common.hpp"
#include "generators/topology/mesh_edges.hpp"

namespace exactmesh::generators {

using triangulation::VertIdx;

bool h_refinement_cycle_2d(HAdaptiveMesh2& state, const AdaptationOptions& options,
                           const FieldSource& field, HAdaptationCounters2& counters) {
    const triangulation::Triangulation2& mesh = state.hierarchy.leaf_mesh();
    const std::uint32_t before = mesh.vertex_count();
    const auto marks_of = [](const std::vector<std::uint8_t>& flags,
                             const std::vector<VertIdx>& edges) {
        std::vector<VertIdx> marks;
        for (std::size_t e = 0; e < flags.size(); ++e)
            if (flags[e]) marks.insert(marks.end(), {edges[2 * e], edges[2 * e + 1]});
        return marks;
    };
    const std::size_t count = detail::refine_marked_edges(
        state.hierarchy, options, mesh.xy, 2, mesh.triangles, state.values, marks_of,
        [](const HRefinedMesh2& h) { return h.leaf_mesh().vertex_count(); },
        counters.budget_retries);
    if (count == 0) return false;
    counters.marked_edges += count;
    ++counters.cycles;
    const triangulation::Triangulation2& leaves = state.hierarchy.leaf_mesh();
    if (field.analytic != nullptr) {
        state.values = sample_field(*field.analytic, leaves.xy, 2, field.t);
    } else {
        state.values.resize(before);
        state.values = state.hierarchy.transfer_field(state.values);
    }
    return true;
}

std::uint64_t h_derefinement_pass_2d(HAdaptiveMesh2& state, EdgeIndicator indicator,
                                     double threshold, double reference_mean,
                                     const FieldSource& field, HAdaptationCounters2& counters) {
    const triangulation::Triangulation2& mesh = state.hierarchy.leaf_mesh();
    const std::vector<VertIdx> edges = mesh_edges_2d(mesh.triangles);
    if (edges.empty()) return 0;
    const std::vector<double> ind =
        mesh_edge_indicator(indicator, mesh.xy, 2, mesh.triangles, edges, state.values);
    const double mean = reference_mean > 0 ? reference_mean : mean_indicator(ind);
    const MeshEdgeIndex index(edges);
    std::vector<triangulation::TriIdx> flagged;
    for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
        bool low = true;
        for (unsigned k = 0; k < 3 && low; ++k)
            low = ind[index.find(mesh.triangles[3 * t + k], mesh.triangles[3 * t + (k + 1) % 3])] <
                  threshold * mean;
        if (low) flagged.push_back(static_cast<triangulation::TriIdx>(t));
    }
    ++counters.derefinement_passes;
    counters.derefine_flagged += flagged.size();
    const std::uint32_t before = mesh.vertex_count();
    const std::vector<VertIdx> map = state.hierarchy.derefine(flagged);
    const triangulation::Triangulation2& leaves = state.hierarchy.leaf_mesh();
    if (field.analytic != nullptr)
        state.values = sample_field(*field.analytic, leaves.xy, 2, field.t);
    else
        state.values = restrict_field(state.values, map);
    return before - leaves.vertex_count();
}

}  // namespace exactmesh::generators
