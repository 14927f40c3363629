// SPDX-License-Identifier: MIT
// The conversion between the exchange type Triangulation2 and the working half-edge mesh
// TriMesh2 (see flip_2d.hpp); the flip kernel itself is inline in the header.
#include "triangulation/mesh/flip_2d.hpp"

#include <cstddef>
#include <utility>

#include "base/errors.hpp"

namespace exactmesh::triangulation {

HalfEdgeEdit::HalfEdgeEdit(Triangulation2& mesh) : target_(mesh) {
    const std::size_t slots = mesh.triangles.size();
    EM_ASSERT(mesh.neighbors.size() == slots);
    EM_ASSERT(mesh.constrained.empty() || mesh.constrained.size() == slots);
    work_.twin.assign(slots, kNone);
    for (std::size_t e = 0; e < slots; ++e) {
        const TriIdx w = mesh.neighbors[e];
        if (w == kNone) continue;
        // The neighbour holds the edge reversed: b -> a where e is a -> b.
        const VertIdx a = mesh.triangles[e];
        const VertIdx b = mesh.triangles[3 * (e / 3) + (e % 3 + 1) % 3];
        EdgeIdx found = kNone;
        const std::size_t base = 3 * static_cast<std::size_t>(w);
        for (unsigned j = 0; j < 3 && base + 2 < slots; ++j) {
            if (mesh.triangles[base + j] == b && mesh.triangles[base + (j + 1) % 3] == a) {
                found = static_cast<EdgeIdx>(base + j);
                break;
            }
        }
        if (found == kNone) {
            throw InternalError(
                "2D edit: neighbor does not share the edge (inconsistent neighbors)");
        }
        work_.twin[e] = found;
    }
    work_.xy = std::move(mesh.xy);
    work_.tv = std::move(mesh.triangles);
    work_.flags = std::move(mesh.constrained);
}

HalfEdgeEdit::~HalfEdgeEdit() {
    target_.xy = std::move(work_.xy);
    target_.triangles = std::move(work_.tv);
    target_.constrained = std::move(work_.flags);
    const std::size_t slots = work_.twin.size();
    target_.neighbors.resize(slots);
    for (std::size_t e = 0; e < slots; ++e) {
        target_.neighbors[e] = work_.twin[e] == kNone ? kNone : triangle_of(work_.twin[e]);
    }
}

}  // namespace exactmesh::triangulation
