// SPDX-License-Identifier: MIT
// The numbering of a Delaunay result, shared by Delaunay2Core::take_result and
// Delaunay3Core::take_result: merged duplicate points reported by their first occurrence, the
// finite cells (triangles, tetrahedra) numbered consecutively. Internal to triangulation/delaunay.
#pragma once

#include <cstdint>
#include <vector>

#include "triangulation/mesh/mesh2.hpp"

namespace exactmesh::triangulation::detail {

/// merged_into (caller index -> caller index of the copy kept in the mesh) rewritten so that each
/// group of equal points maps to its smallest caller index ("the first occurrence"), and
/// input_index (mesh vertex -> caller index) to the same representative, so that the triangles
/// or tetrahedra name it too. Needed only when some points were merged.
inline void report_first_occurrence(std::vector<VertIdx>& merged_into,
                                    std::vector<VertIdx>& input_index) {
    std::vector<VertIdx> smallest(merged_into.size());
    for (VertIdx i = 0; i < smallest.size(); ++i) smallest[i] = i;
    for (VertIdx i = 0; i < smallest.size(); ++i) {
        const VertIdx kept = merged_into[i];
        if (i < smallest[kept]) smallest[kept] = i;
    }
    for (VertIdx i = 0; i < smallest.size(); ++i) merged_into[i] = smallest[merged_into[i]];
    for (VertIdx& v : input_index) v = merged_into[v];
}

/// Numbers the live finite cells among the first `slots` of `mesh` (a triangle or tetrahedron
/// mesh: is_dead, is_infinite) consecutively in slot order: output_index[t] is the number of cell
/// t, kNone for a dead or infinite one. Returns the count of numbered cells.
template <class Mesh>
std::uint32_t number_finite_cells(const Mesh& mesh, std::uint32_t slots,
                                  std::vector<std::uint32_t>& output_index) {
    output_index.assign(slots, kNone);
    std::uint32_t count = 0;
    for (std::uint32_t t = 0; t < slots; ++t) {
        if (!mesh.is_dead(t) && !mesh.is_infinite(t)) output_index[t] = count++;
    }
    return count;
}

}  // namespace exactmesh::triangulation::detail
