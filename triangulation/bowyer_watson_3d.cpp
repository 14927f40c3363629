// SPDX-License-Identifier: MIT
// Bowyer-Watson 3D (see bowyer_watson_3d.hpp).
#include "triangulation/bowyer_watson_3d.hpp"

#include <vector>

#include "triangulation/delaunay_3d_core.hpp"

namespace exactmesh::triangulation {

namespace {

/// Grows the cavity of p from `seed` (in conflict) breadth first: the conflict region of a
/// point is connected [Watson81], so every tetrahedron in it is reached. A tetrahedron tested
/// and found outside keeps its own mark, so it is tested once even when several cavity faces
/// touch it.
void grow_cavity(detail::Delaunay3Core& core, std::vector<TetIdx>& cavity, TetIdx seed, VertIdx p,
                 std::uint32_t inside, std::uint32_t outside) {
    TetMesh3& mesh = core.mesh;
    cavity.clear();
    cavity.push_back(seed);
    core.stamp[seed] = inside;
    for (std::size_t i = 0; i < cavity.size(); ++i) {
        const TetIdx c = cavity[i];
        for (unsigned k = 0; k < 4; ++k) {
            const TetIdx u = tet_of(mesh.adj[4 * std::size_t{c} + k]);
            const std::uint32_t mark = core.stamp[u];
            if (mark == inside || mark == outside) continue;
            if (core.conflict(u, p)) {
                core.stamp[u] = inside;
                cavity.push_back(u);
            } else {
                core.stamp[u] = outside;
            }
        }
    }
}

}  // namespace

Delaunay3Result bowyer_watson_3d(std::span<const double> xyz, const Delaunay3Options& options) {
    detail::Delaunay3Core core(xyz, options);
    std::vector<bool> skip;
    // Fewer than four non-coplanar points: no tetrahedron, duplicates still merged.
    if (!core.make_first_tet(skip)) return core.coplanar_result(xyz);
    std::vector<TetIdx> cavity;
    for (VertIdx p = 0; p < core.mesh.vertex_count(); ++p) {
        if (skip[p]) continue;
        const detail::Delaunay3Core::Location where = core.locate(p);
        if (where.tet == kNone) continue;  // duplicate, merged
        const std::uint32_t inside = core.next_stamp();
        const std::uint32_t outside = core.next_stamp();
        grow_cavity(core, cavity, where.tet, p, inside, outside);
        core.counters.cavity_tets += cavity.size();
        core.replace_by_star(cavity, inside, p);
    }
    return core.take_result(xyz);
}

}  // namespace exactmesh::triangulation
