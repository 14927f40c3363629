// SPDX-License-Identifier: MIT
// What h_adaptation_2d and h_adaptation_3d share: their counters, and the refinement step: the
// indicator on the leaf
// edges, the edges above threshold × mean marked, the hierarchy refined; under a vertex budget
// the refinement is tried on a copy (the rules add vertices beyond the marks) and redone with
// the largest indicators, half as many each time, until it stays within the budget.
#pragma once

#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

#include "base/counter_table.hpp"
#include "generators/adaptation/edge_indicators.hpp"
#include "generators/adaptation/insertion_adaptation_2d.hpp"
#include "generators/topology/mesh_edges.hpp"

namespace exactmesh::generators {

/// The counters of h-adaptation in 2D and in 3D (HAdaptationCounters2, HAdaptationCounters3).
struct HAdaptationCounters {
    std::uint64_t cycles = 0;
    std::uint64_t marked_edges = 0;
    std::uint64_t budget_retries = 0;  ///< refinements tried again with half the marks
    std::uint64_t derefinement_passes = 0;
    std::uint64_t derefine_flagged = 0;  ///< leaves flagged for derefinement
};

inline constexpr std::array kHAdaptationCounterNames =
    EM_COUNTER_TABLE(HAdaptationCounters, cycles, marked_edges, budget_retries, derefinement_passes,
                     derefine_flagged);
static_assert(counter_table_complete(kHAdaptationCounterNames));

}  // namespace exactmesh::generators

namespace exactmesh::generators::detail {

/// Refines `hierarchy`, whose leaf mesh is `coordinates` (dim per vertex) and `elements`
/// (triangles for dim 2, tetrahedra for dim 3) carrying `values`. marks_of(flags, edges) turns
/// the flags per edge into the hierarchy's marks; vertex_count(h) counts h's leaf vertices.
/// Returns the edges marked, or 0 (hierarchy unchanged) when none is flagged or the budget
/// leaves no room; budget_retries counts the refinements redone with half the marks.
template <class Hierarchy, class MarksOf, class VertexCount>
std::size_t refine_marked_edges(Hierarchy& hierarchy, const AdaptationOptions& options,
                                std::span<const double> coordinates, unsigned dim,
                                std::span<const triangulation::VertIdx> elements,
                                std::span<const double> values, MarksOf marks_of,
                                VertexCount vertex_count, std::uint64_t& budget_retries) {
    const bool budget = options.max_vertices > 0;
    if (budget && coordinates.size() / dim >= options.max_vertices) return 0;
    const std::vector<triangulation::VertIdx> edges =
        dim == 2 ? mesh_edges_2d(elements) : mesh_edges_3d(elements);
    const std::vector<double> indicator =
        mesh_edge_indicator(options.indicator, coordinates, dim, elements, edges, values);
    std::vector<std::uint8_t> flags =
        flag_above_mean(indicator, options.threshold, options.reference_mean);
    std::size_t count = static_cast<std::size_t>(std::count(flags.begin(), flags.end(), 1));
    if (count == 0) return 0;
    if (!budget) {
        hierarchy.refine(marks_of(flags, edges));
        return count;
    }
    for (;;) {
        Hierarchy trial = hierarchy;
        trial.refine(marks_of(flags, edges));
        if (vertex_count(trial) <= options.max_vertices) {
            hierarchy = std::move(trial);
            return count;
        }
        ++budget_retries;
        count /= 2;
        if (count == 0) return 0;
        flags = flag_largest(indicator, count);
    }
}

}  // namespace exactmesh::generators::detail
