// SPDX-License-Identifier: MIT
// The local rewrites of a TetMesh3 (mesh3.hpp), in one place: every 3D algorithm that changes a
// tetrahedralization goes through these [Joe91; Shewchuk03; EdelsbrunnerShah96 for the flips].
//
//   splits (a new point p)       1-4: p inside a tetrahedron; 2-6: p on a face; n-2n: p on an
//                                edge with n tetrahedra around it
//   flips (five points or six)   2-3: a face becomes an edge; 3-2: an edge with three
//                                tetrahedra becomes a face; 4-4: an edge with four tetrahedra
//                                (its two halves flat) becomes the other diagonal edge; 2-2: as
//                                4-4 on the domain boundary (two tetrahedra)
//
// Two ways to make them, one per kind of caller, over the same mesh:
//  - TetStar3 replaces a region star-shaped from a point p by p's star (one new tetrahedron per
//    boundary face of the region not holding p), gluing the new faces by an edge table: O(size
//    of the region). Every split and every flip whose new tetrahedra all hold one vertex of the
//    old ones (2-3, 3-2, 4-4 seen from that vertex) is such a star; the Delaunay insertion
//    (green_sibson_3d) makes its splits and flips this way, from the point just inserted.
//  - plan_flip_3d / apply_flip_3d find the one valid flip at an arbitrary face and make it
//    through replace_tets, which matches the given new tetrahedra to the old boundary
//    combinatorially; the criterion of a swap (edge_face_swap_3d) or a removal
//    (vertex_removal_3d) looks at the planned tetrahedra before any change. replace_tets also
//    makes any other retetrahedralization (the 4-1 flip, a removal's cavity, an undo).
// Both make the same tetrahedra for a flip; they differ in the order of the new tetrahedra and
// of their vertices (region by region for the star, the plan's picture below otherwise), which
// the callers' later steps (the walk, the swap queue) follow, so each caller keeps its own.
// Bowyer-Watson's cavity star is this file's star specialised by hand (bowyer_watson_3d.cpp).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "triangulation/mesh/mesh3.hpp"
#include "triangulation/mesh/tetrahedralization_3d.hpp"

namespace exactmesh::triangulation {

/// Builds the working mesh of a domain (boundary faces kNone, vertex_tet filled). Uses
/// `mesh.neighbors` when it is filled (checked to be mutual and face-sharing), else links the faces
/// from the vertex lists.
/// @throws InputError when a tetrahedron is not positively oriented (exact orient3d), names a
///         vertex out of range or repeats one, a face is shared by more than two tetrahedra or
///         the given neighbors are inconsistent; messages number tetrahedra and vertices from 0.
TetMesh3 make_tet_mesh_3d(const Tetrahedralization3& mesh);
/// The same, taking over the coordinates and tetrahedra of `mesh`.
TetMesh3 make_tet_mesh_3d(Tetrahedralization3&& mesh);

/// The live tetrahedra, compacted in slot order, with their neighbors.
Tetrahedralization3 to_tetrahedralization_3d(const TetMesh3& mesh);
/// The same, compacting `mesh`'s own arrays in place (left empty).
Tetrahedralization3 to_tetrahedralization_3d(TetMesh3&& mesh);

/// Fills mesh.neighbors from mesh.tets (the face opposite vertex k of t is shared with at most
/// one other tetrahedron). Checks as make_tet_mesh_3d; `numbering` gives the bases the
/// messages number from and the order they list corners in (a file's own).
void link_neighbors_3d(Tetrahedralization3& mesh, const Check3Numbering& numbering = {});

/// Replaces the live tetrahedra `old_tets` by `new_tets` (each positively oriented, checked by
/// the caller) covering the same region: every face of a new tetrahedron is either shared with
/// exactly one other new tetrahedron (in the opposite orientation) or is a boundary face of the
/// old set (a face whose other side is not in `old_tets`), and every boundary face of the old
/// set is used exactly once. On success the new tetrahedra's slots are written to `created`
/// (in the order of new_tets) when it is given; old slots are reused first, then free ones
/// (new_tet). Keeps vertex_tet.
/// With `retriangulate_domain_boundary` (the 2-2 swap, whose two coplanar boundary faces trade
/// their diagonal), old faces on the domain boundary may go unused and unmatched new faces
/// become domain boundary faces; the caller vouches for the geometry.
/// @return false, and the mesh untouched, when the faces do not match that way.
bool replace_tets(TetMesh3& mesh, std::span<const TetIdx> old_tets, std::span<const Tet> new_tets,
                  std::vector<TetIdx>* created = nullptr,
                  bool retriangulate_domain_boundary = false);

/// The tetrahedra around edge (a, b), starting at t (which holds both) and turning through
/// the faces holding the edge. `closed` tells whether the ring closes (an interior edge); an
/// open ring lists the tetrahedra from one boundary face to the other.
struct EdgeRing {
    std::vector<TetIdx> tets;
    bool closed = false;
};
EdgeRing edge_ring(const TetMesh3& mesh, TetIdx t, VertIdx a, VertIdx b);

/// The live tetrahedra holding v (its star), by a walk over faces holding v from vertex_tet[v].
std::vector<TetIdx> vertex_star(const TetMesh3& mesh, VertIdx v);

// ---- Flips at an arbitrary face, planned then made (edge-face swapping, vertex removal) ----

enum class FlipKind3 { None, Flip23, Flip32, Flip44, Flip22, EdgeRemoval };

/// Most tetrahedra around an edge that edge removal replaces (triangulation/modification/
/// edge_removal_3d): rings of up to 7, as in Shewchuk's experiments, where larger rings rarely
/// gave a better triangulation.
inline constexpr unsigned kMaxEdgeRemovalRing = 7;

/// Adds one to the counter of `kind` in `counters`: the members flips_23, flips_32, flips_44,
/// and flips_22 and edge_removals where the counters have one (a kind without a member is not
/// counted).
template <class Counters>
void count_flip(Counters& counters, FlipKind3 kind) {
    if (kind == FlipKind3::Flip23) ++counters.flips_23;
    if (kind == FlipKind3::Flip32) ++counters.flips_32;
    if (kind == FlipKind3::Flip44) ++counters.flips_44;
    if constexpr (requires { counters.flips_22; }) {
        if (kind == FlipKind3::Flip22) ++counters.flips_22;
    }
    if constexpr (requires { counters.edge_removals; }) {
        if (kind == FlipKind3::EdgeRemoval) ++counters.edge_removals;
    }
}

/// A flip found at a face: the tetrahedra it removes and the positive ones it makes.
///
/// The face abc (outward from t1 = abcd, so orient3d(a, b, c, d) > 0) and its neighbor t2 = bace:
///
///   2-3: de crosses abc        ->  (a, b, e, d), (b, c, e, d), (c, a, e, d)   [edge de]
///   3-2: ring of xy = {xyzd, xyze, xyde}, z the third vertex of the face, (x, y, z, d) positive
///                              ->  (z, d, e, y), (z, e, d, x)                 [face zde]
///   4-4: d, e, x, y coplanar, ring of xy = {xyzd, xyze, xywe, xywd}
///                              ->  (y, z, e, d), (z, x, e, d) and the same two from the far
///                                  side's face (x, y, w) seen from xywd        [edge de]
///   2-2: as 4-4 with xy on the boundary and only xyzd, xyze around it.
///   edge removal (triangulation/modification/edge_removal_3d): the n <= kMaxEdgeRemovalRing
///   tetrahedra around an interior edge ab replaced by 2 (n - 2): a triangulation of the ring of
///   its link, each triangle joined to a and to b.
struct FlipPlan3 {
    FlipKind3 kind = FlipKind3::None;
    std::array<TetIdx, kMaxEdgeRemovalRing> old{};
    unsigned old_count = 0;
    std::array<Tet, 2 * (kMaxEdgeRemovalRing - 2)> made{};
    unsigned made_count = 0;
};

/// The valid flip at the interior face f (at most one exists for the five or six points; each
/// new tetrahedron checked positive by exact orient3d), into `plan`; false when there is none
/// (or f is dead or on the boundary). `edges_examined`, when given, counts the edge rings
/// walked (for a 3-2, 4-4 or 2-2).
bool plan_flip_3d(const TetMesh3& mesh, FaceIdx f, FlipPlan3& plan,
                  std::uint64_t* edges_examined = nullptr);

/// Makes a planned flip through replace_tets; the new tetrahedra's slots go to `created`.
void apply_flip_3d(TetMesh3& mesh, const FlipPlan3& plan, std::vector<TetIdx>& created);

/// Makes the one valid flip (2-3, 3-2, 4-4 or 2-2) at the interior face f. Returns the kind
/// made, None when the face has no valid flip.
FlipKind3 flip_face_3d(TetMesh3& mesh, FaceIdx f);

// ---- Splits and flips as the star of a point (Delaunay insertion) ----

/// Replaces a region star-shaped from a point p by p's star, and names the splits and flips
/// that are such stars. The scratch (an edge table cleared by a generation count, the region
/// marks) is kept between calls, so repeated rewrites allocate nothing.
///
/// The mesh may be closed by kInfinite (every face has a twin) or a domain with boundary faces
/// (kNone); vertex_tet is kept when the mesh has one (it is empty in the Delaunay
/// constructions, which then pay one test per star).
class TetStar3 {
  public:
    /// Per tetrahedron slot: a region mark, compared with fresh values from next_stamp().
    /// Public: the Delaunay constructions mark their own regions (the hull seen from a point)
    /// with it.
    std::vector<std::uint32_t> stamp;
    std::uint32_t next_stamp();
    /// Grows `stamp` to the mesh's slots (with room, so that it grows rarely).
    void grow_stamps(const TetMesh3& mesh);

    /// Set when every face of the mesh has a twin (closed by kInfinite, as in the Delaunay
    /// constructions): the star then never tests for the domain's boundary (kNone).
    bool closed = false;

    /// The new tetrahedra of the last rewrite, in the order they were made.
    std::vector<TetIdx> created;

    /// Replaces the tetrahedra of `region` (all marked with stamp[t] == region_stamp, forming a
    /// region star-shaped from p) by the star of p: one tetrahedron joining p to each boundary
    /// face of the region that does not contain p, made in region order and face order (slot
    /// k of region tetrahedron c gives c with vertex k replaced by p). Faces of the region's
    /// boundary that contain p (when p is already a vertex of the region, as in a flip) are
    /// glued to the new tetrahedra. Dead slots are recycled (last freed first).
    void replace_by_star(TetMesh3& mesh, std::span<const TetIdx> region, std::uint32_t region_stamp,
                         VertIdx p);
    /// replace_by_star with the region marked here.
    void star(TetMesh3& mesh, std::span<const TetIdx> region, VertIdx p);

    /// 1-4: p strictly inside tetrahedron t.
    void split_1_4(TetMesh3& mesh, TetIdx t, VertIdx p);
    /// 2-6: p inside the interior face k of t (t and the tetrahedron across it).
    void split_2_6(TetMesh3& mesh, TetIdx t, unsigned k, VertIdx p);
    /// n-2n: p inside the edge of t between slots a and b: the tetrahedra around the edge,
    /// walked from t across its face opposite the lower of the two other slots. The edge must
    /// be interior (its ring closed). The ring is left in `ring()`.
    void split_edge(TetMesh3& mesh, TetIdx t, unsigned a, unsigned b, VertIdx p);
    /// 2-3 across face k of t, from t's vertex k: {t, t2} -> three tetrahedra around the new
    /// edge from vertex k to t2's apex. The caller has checked that this edge crosses the face.
    void flip_2_3(TetMesh3& mesh, TetIdx t, unsigned k);
    /// 3-2 from t's vertex k: {t, t2 across face k, t3 across face j} -> two tetrahedra, the
    /// edge of t between its slots other than k and j removed. The caller has checked that the
    /// edge has exactly these three tetrahedra (t3 holds t2's apex) and is reflex.
    void flip_3_2(TetMesh3& mesh, TetIdx t, unsigned k, unsigned j);
    /// 4-4 from t's vertex k: {t, t2 across face k, t3 across face j, t4 across t2's face
    /// opposite t's vertex j} -> four tetrahedra, the edge of t between its slots other than k
    /// and j replaced by the edge from vertex k to t2's apex. The caller has checked that the
    /// six points are two flat halves and the edge has exactly these four tetrahedra.
    void flip_4_4(TetMesh3& mesh, TetIdx t, unsigned k, unsigned j);

    const std::vector<TetIdx>& ring() const { return ring_; }

  private:
    /// One boundary face of a region to star: the new tetrahedron's vertices, the slot of p in
    /// it (the face slot that faces outward), and the outside twin of that face.
    struct StarFace {
        VertIdx v[4];
        unsigned k;
        FaceIdx outside;
    };
    std::vector<StarFace> star_faces_;
    std::vector<FaceIdx> p_faces_outside_;    ///< outside twins of boundary faces holding p
    std::vector<std::uint64_t> p_faces_key_;  ///< their edges (the two vertices besides p)
    /// Open-addressing table: edge (a, b) -> the face slot holding p, a and b seen first.
    std::vector<std::uint64_t> edge_key_;
    std::vector<FaceIdx> edge_face_;
    std::vector<std::uint32_t> edge_generation_;
    std::uint32_t generation_ = 0;
    std::uint32_t stamp_counter_ = 0;
    std::vector<TetIdx> ring_;  ///< the last edge split's ring
    template <bool kBoundary>
    void replace_by_star_in(TetMesh3& mesh, std::span<const TetIdx> region,
                            std::uint32_t region_stamp, VertIdx p);
    /// The mesh of the rewrite in progress (glue's, so that it takes no more arguments than
    /// it needs: it runs three times per new tetrahedron).
    TetMesh3* mesh_ = nullptr;
    template <bool kBoundary>
    void glue(std::uint64_t key, FaceIdx face);
};

}  // namespace exactmesh::triangulation
