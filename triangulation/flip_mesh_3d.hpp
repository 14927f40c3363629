// SPDX-License-Identifier: MIT
// FlipMesh3: the mutable tetrahedral mesh that the 3D flip algorithms work on (edge-face
// swapping, vertex removal). Built from a Tetrahedralization3, returned to one compacted.
// Flat arrays, twin facets instead of neighbor ids (STYLE.md), a free list for dead slots and one
// live tetrahedron per vertex. Every local change goes through replace_tets, which re-links the
// new tetrahedra to the old boundary combinatorially and refuses a set that does not fit.
//
// Local indices of tetrahedron t = (v0, v1, v2, v3), orient3d(v0, v1, v2, v3) > 0: facet
// f = 4t + k is the face opposite vk, and kOutwardFace[k] lists it counter-clockwise seen from
// outside t (so orient3d(face..., vk) > 0):
//
//                v3                    facet 0: (v1, v3, v2)
//               /|\                    facet 1: (v0, v2, v3)
//              / | \                   facet 2: (v0, v3, v1)
//             /  |  \                  facet 3: (v0, v1, v2)
//            /   |   \                 adj[4t + k] = 4t' + k' (the same face seen from t',
//          v0 ---|--- v2               opposite vertex k' of t'), or kNone on the boundary.
//             \  |  /
//              \ | /
//               v1
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "triangulation/check_3d.hpp"
#include "triangulation/tetrahedralization_3d.hpp"

namespace exactmesh::triangulation {

using FacetIdx = std::uint32_t;

/// Outward face opposite local vertex k, counter-clockwise seen from outside.
inline constexpr std::array<std::array<unsigned, 3>, 4> kOutwardFace{
    {{1, 3, 2}, {0, 2, 3}, {0, 3, 1}, {0, 1, 2}}};

/// A tetrahedron as 4 vertex indices, positively oriented.
using Tet = std::array<VertIdx, 4>;

struct FlipMesh3 {
    std::vector<double> xyz;           ///< 3·#V coordinates
    std::vector<VertIdx> tets;         ///< 4 per slot; tets[4t] == kNone for a dead slot
    std::vector<FacetIdx> adj;         ///< 4 per slot: twin facet or kNone
    std::vector<TetIdx> free_tets;     ///< dead slots to recycle
    std::vector<TetIdx> vertex_tet;    ///< per vertex: one live tetrahedron holding it, or kNone

    std::uint32_t vertex_count() const { return static_cast<std::uint32_t>(xyz.size() / 3); }
    std::uint32_t slot_count() const { return static_cast<std::uint32_t>(tets.size() / 4); }
    std::uint32_t live_tet_count() const {
        return slot_count() - static_cast<std::uint32_t>(free_tets.size());
    }
    const double* point(VertIdx v) const { return xyz.data() + 3 * static_cast<std::size_t>(v); }
    bool is_dead(TetIdx t) const { return tets[4 * std::size_t{t}] == kNone; }
    VertIdx vertex(TetIdx t, unsigned k) const { return tets[4 * std::size_t{t} + k]; }
    Tet tet(TetIdx t) const {
        const std::size_t s = 4 * std::size_t{t};
        return {tets[s], tets[s + 1], tets[s + 2], tets[s + 3]};
    }
    /// The local index of v in t, or 4 when t does not hold v.
    unsigned local_index(TetIdx t, VertIdx v) const {
        for (unsigned k = 0; k < 4; ++k) {
            if (vertex(t, k) == v) return k;
        }
        return 4;
    }
    /// The outward face of facet f = 4t + k as 3 vertices.
    std::array<VertIdx, 3> face(FacetIdx f) const {
        const TetIdx t = f / 4;
        const auto& lf = kOutwardFace[f % 4];
        return {vertex(t, lf[0]), vertex(t, lf[1]), vertex(t, lf[2])};
    }
};

/// Builds the working mesh. Uses `mesh.neighbors` when it is filled (checked to be mutual
/// and face-sharing), else links the faces from the vertex lists.
/// @throws InputError when a tetrahedron is not positively oriented (exact orient3d), names a
///         vertex out of range or repeats one, a face is shared by more than two tetrahedra or
///         the given neighbors are inconsistent; messages number tetrahedra and vertices from 0.
FlipMesh3 make_flip_mesh_3d(const Tetrahedralization3& mesh);

/// The live tetrahedra, compacted in slot order, with their neighbors.
Tetrahedralization3 to_tetrahedralization_3d(const FlipMesh3& mesh);

/// Fills mesh.neighbors from mesh.tets (the face opposite vertex k of t is shared with at most
/// one other tetrahedron). Checks as make_flip_mesh_3d; `numbering` gives the bases the
/// messages number from and the order they list corners in (a file's own).
void link_neighbors_3d(Tetrahedralization3& mesh, const Check3Numbering& numbering = {});

/// Replaces the live tetrahedra `old_tets` by `new_tets` (each positively oriented, checked by
/// the caller) covering the same region: every face of a new tetrahedron is either shared with
/// exactly one other new tetrahedron (in the opposite orientation) or is a boundary face of the
/// old set (a face whose other side is not in `old_tets`), and every boundary face of the old
/// set is used exactly once. On success the new tetrahedra's slots are written to `created`
/// (in the order of new_tets) when it is given; old slots are reused first.
/// With `retriangulate_domain_boundary` (the 2-2 swap, whose two coplanar boundary faces trade
/// their diagonal), old faces on the domain boundary may go unused and unmatched new faces
/// become domain boundary faces; the caller vouches for the geometry.
/// @return false, and the mesh untouched, when the faces do not match that way.
bool replace_tets(FlipMesh3& mesh, std::span<const TetIdx> old_tets, std::span<const Tet> new_tets,
                  std::vector<TetIdx>* created = nullptr, bool retriangulate_domain_boundary = false);

/// The tetrahedra around edge (a, b), starting at t (which holds both) and turning through
/// the faces holding the edge. `closed` tells whether the ring closes (an interior edge); an
/// open ring lists the tetrahedra from one boundary face to the other.
struct EdgeRing {
    std::vector<TetIdx> tets;
    bool closed = false;
};
EdgeRing edge_ring(const FlipMesh3& mesh, TetIdx t, VertIdx a, VertIdx b);

/// The live tetrahedra holding v (its star), by a walk over faces holding v from vertex_tet[v].
std::vector<TetIdx> vertex_star(const FlipMesh3& mesh, VertIdx v);

}  // namespace exactmesh::triangulation
