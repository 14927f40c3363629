// SPDX-License-Identifier: MIT
// Constrained edges of a 2D triangulation for the edge-modification tests: constrain a sample of
// its interior sides, and read back the set of constrained edges, so that a test can assert that
// an algorithm kept every one. Test support.
#pragma once

#include <algorithm>
#include <cstddef>
#include <set>
#include <utility>

#include "triangulation/mesh/triangulation_2d.hpp"
#include "triangulation/modification/edge_swap_2d.hpp"

namespace exactmesh::testing {

using Edges2 = std::set<std::pair<triangulation::VertIdx, triangulation::VertIdx>>;

/// The constrained edges of `mesh`, each as (smaller vertex, larger vertex).
inline Edges2 constrained_edges(const triangulation::Triangulation2& mesh) {
    Edges2 edges;
    for (std::size_t e = 0; e < mesh.triangles.size(); ++e) {
        const triangulation::VertIdx p = mesh.triangles[e],
                                     q = mesh.triangles[3 * (e / 3) + (e % 3 + 1) % 3];
        if (mesh.constrained[e] != 0) edges.insert({std::min(p, q), std::max(p, q)});
    }
    return edges;
}

/// Constrains the interior sides 0, step, 2 step, ... of `mesh` (hull sides skipped; every
/// other constraint cleared; link_neighbors_2d marks the twin sides) and returns their edges.
inline Edges2 constrain_every_nth_side(triangulation::Triangulation2& mesh, std::size_t step) {
    mesh.constrained.assign(mesh.triangles.size(), 0);
    Edges2 constrained;
    for (std::size_t e = 0; e < mesh.triangles.size(); e += step) {
        if (mesh.neighbors[e] == triangulation::kNone) continue;
        const triangulation::VertIdx p = mesh.triangles[e],
                                     q = mesh.triangles[3 * (e / 3) + (e % 3 + 1) % 3];
        constrained.insert({std::min(p, q), std::max(p, q)});
        mesh.constrained[e] = 1;
    }
    triangulation::link_neighbors_2d(mesh);
    return constrained;
}

}  // namespace exactmesh::testing
