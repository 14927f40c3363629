// SPDX-License-Identifier: MIT
// TetMesh3: the one working tetrahedral mesh of the 3D layer, in flat index arrays. The 3D
// Delaunay constructions (delaunay_3d_core, bowyer_watson_3d, green_sibson_3d) close it by one
// infinite vertex so that every face has a twin; the flip algorithms on a given domain
// (edge_face_swap_3d, vertex_removal_3d) leave the domain's boundary faces without one (kNone).
// The local rewrites (splits, flips, the general replacement) are in flip_3d.*;
// Tetrahedralization3 is the exchange type both sides start from and return.
//
// Local indices of tetrahedron t: vertices v0..v3 = tv[4t .. 4t+3], positively oriented
// (orient3d(v0, v1, v2, v3) > 0). Face slot f = 4t + k is the triangle opposite vk; its
// vertices in the order kFaceVertex[k] (counter-clockwise seen from outside t) see vk on their
// positive side:
//
//                 v3                 face 0 = (v1, v3, v2)   opposite v0
//                /|\                 face 1 = (v0, v2, v3)   opposite v1
//               / | \                face 2 = (v0, v3, v1)   opposite v2
//              /  |  \               face 3 = (v0, v1, v2)   opposite v3
//            v0 --|-- v2             orient3d(face k, vk) > 0 for each k
//              \  |  /
//               \ | /                adj[4t + k] = 4t' + k': the same face seen from the
//                 v1                 tetrahedron t' across it (twin face slots), or kNone on
//                                    the boundary of a domain that is not closed
//
// Replacing vertex k of a tetrahedron by a point q gives orient3d(face k, q): positive when q
// lies on vk's side of face k. An infinite tetrahedron has kInfinite as its vertex v3 (always
// slot 3: the constructions only ever replace one vertex of a tetrahedron by a new point, and
// a tetrahedron whose slot 3 is replaced becomes finite); its finite face 3 is a convex-hull
// face, oriented so that orient3d of the tetrahedron with kInfinite replaced by q is positive
// exactly when q lies strictly outside the hull across that face. Dead tetrahedra (recycled)
// have tv[4t] == kNone.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "base/errors.hpp"
#include "triangulation/mesh/mesh2.hpp"

namespace exactmesh::triangulation {

using TetIdx = std::uint32_t;
using FaceIdx = std::uint32_t;

/// A tetrahedron as 4 vertex indices, positively oriented.
using Tet = std::array<VertIdx, 4>;

/// Largest number of input points of the 3D constructions: about 6.7 tetrahedra per point, and
/// 4 face slots per tetrahedron must fit in 32 bits (with room for degenerate inputs).
inline constexpr std::uint32_t kMaxPoints3 = 0x04000000u;
/// Largest number of tetrahedron slots: 4 face slots each, below kNone.
inline constexpr std::uint32_t kMaxTetSlots = 0x3FFFFFFFu;

/// The vertices of face k (opposite vertex k) in the order that sees vertex k positively
/// (counter-clockwise seen from outside the tetrahedron).
inline constexpr unsigned kFaceVertex[4][3] = {{1, 3, 2}, {0, 2, 3}, {0, 3, 1}, {0, 1, 2}};

/// Bowyer-Watson's cavity search marks tetrahedra in the high bits of vertex slot 1 (see
/// bowyer_watson_3d.cpp); a vertex read from another tetrahedron meanwhile is masked with this.
inline constexpr std::uint32_t kVertexBits = 0x3FFFFFFFu;

/// The slot of kInfinite in an infinite tetrahedron.
inline constexpr unsigned kInfiniteSlot = 3;

inline constexpr TetIdx tet_of(FaceIdx f) {
    return f >> 2;
}
inline constexpr unsigned local_of(FaceIdx f) {
    return f & 3u;
}

struct TetMesh3 {
    std::vector<double> xyz;        ///< 3·#V coordinates, x0 y0 z0 x1 ...
    std::vector<VertIdx> tv;        ///< 4·#T vertices, positively oriented; kNone for dead tets
    std::vector<FaceIdx> adj;       ///< 4·#T twin face slots (kNone: domain boundary)
    std::vector<TetIdx> free_tets;  ///< dead slots to recycle
    /// Per vertex: one live tetrahedron holding it, or kNone. Kept by every rewrite of flip_3d
    /// when it is filled (make_tet_mesh_3d fills it); empty in the Delaunay constructions,
    /// which do not need it.
    std::vector<TetIdx> vertex_tet;

    std::uint32_t vertex_count() const { return static_cast<std::uint32_t>(xyz.size() / 3); }
    std::uint32_t tet_slots() const { return static_cast<std::uint32_t>(tv.size() / 4); }
    std::uint32_t live_tet_count() const {
        return tet_slots() - static_cast<std::uint32_t>(free_tets.size());
    }
    const double* point(VertIdx v) const { return xyz.data() + 3 * static_cast<std::size_t>(v); }

    bool is_dead(TetIdx t) const { return tv[4 * std::size_t{t}] == kNone; }
    bool is_infinite(TetIdx t) const { return tv[4 * std::size_t{t} + 3] == kInfinite; }
    VertIdx vertex(TetIdx t, unsigned k) const { return tv[4 * std::size_t{t} + k]; }
    Tet tet(TetIdx t) const {
        const std::size_t s = 4 * std::size_t{t};
        return {tv[s], tv[s + 1], tv[s + 2], tv[s + 3]};
    }
    /// Face slot f as 3 vertices, counter-clockwise seen from outside its tetrahedron.
    std::array<VertIdx, 3> face(FaceIdx f) const {
        const TetIdx t = tet_of(f);
        const unsigned* lf = kFaceVertex[local_of(f)];
        return {vertex(t, lf[0]), vertex(t, lf[1]), vertex(t, lf[2])};
    }
    /// The slot of vertex v in tetrahedron t, or 4 when t does not hold v.
    unsigned slot_of(TetIdx t, VertIdx v) const {
        const VertIdx* w = &tv[4 * std::size_t{t}];
        return w[0] == v ? 0u : w[1] == v ? 1u : w[2] == v ? 2u : w[3] == v ? 3u : 4u;
    }

    /// A slot for a new tetrahedron (recycled when possible); the caller fills tv and adj.
    TetIdx new_tet() {
        if (free_tets.empty()) add_slots();
        const TetIdx t = free_tets.back();
        free_tets.pop_back();
        return t;
    }

    /// Appends a batch of dead slots to the free list, lowest first to be handed out, so that
    /// slots are used in order and no per-tetrahedron resize runs in the hot loop.
    void add_slots() {
        const TetIdx first = tet_slots();
        // Within the reserved capacity when there is room: a reallocation would copy both
        // arrays (and lose the huge-page advice of delaunay_3d_core).
        const std::size_t room = (tv.capacity() - tv.size()) / 4;
        std::uint32_t batch = std::max<std::uint32_t>(64, first / 16);
        if (room >= 64 && room < batch) batch = static_cast<std::uint32_t>(room);
        if (std::uint64_t{first} + batch > kMaxTetSlots) {
            throw InputError("tetrahedralization: more than " + std::to_string(kMaxTetSlots) +
                             " tetrahedra (32-bit face slots)");
        }
        tv.resize(tv.size() + 4 * std::size_t{batch}, kNone);
        adj.resize(adj.size() + 4 * std::size_t{batch}, kNone);
        for (std::uint32_t i = batch; i-- > 0;) free_tets.push_back(first + i);
    }

    void kill_tet(TetIdx t) {
        tv[4 * std::size_t{t}] = kNone;
        free_tets.push_back(t);
    }

    void link(FaceIdx f, FaceIdx g) {
        adj[f] = g;
        adj[g] = f;
    }
    /// link, where either side may be kNone (the domain's boundary: nothing to point back).
    void link_or_boundary(FaceIdx f, FaceIdx g) {
        if (f != kNone) adj[f] = g;
        if (g != kNone) adj[g] = f;
    }
};

}  // namespace exactmesh::triangulation
