// SPDX-License-Identifier: MIT
// Removal of an interior vertex p from a tetrahedralization by flips (derefinement)
// [Shewchuk03: "Updating and constructing constrained Delaunay and constrained regular
// triangulations by flips", SoCG 2003; LedouxGoldBaciu05: "Flipping to robustly delete a vertex
// in a Delaunay tetrahedralization", ICCSA 2005]. While p has more than four tetrahedra, a 2-3,
// 3-2 or 4-4 flip among p's tetrahedra is made that creates tetrahedra without p whose
// circumspheres hold no vertex of p's original link (insphere_sos, ties by index); then the 4-1
// flip removes p. Such tetrahedra lie inside p's star and are Delaunay for the remaining points,
// so from a Delaunay tetrahedralization the result is the Delaunay tetrahedralization of the
// points without p (exactly delaunay_3d's, ties included). Any valid flip order succeeds when
// one does (proofs/invariants/edge_face_swapping_3d.md §4); when none of these flips applies (a
// degenerate star: p coplanar with link faces, e.g. a grid point), the rest of the star is
// retetrahedralized at once by the Delaunay tetrahedra of its link vertices (gift wrapping with
// insphere_sos), checked to tile the star exactly. When that fails too (a non-Delaunay input),
// every change is undone and VertexRemovalError names the vertex: never a corrupt mesh.
// Cost: O(k^2) predicates for a star with k link vertices.
#pragma once

#include <cstdint>
#include <span>
#include <string>

#include "base/errors.hpp"
#include "triangulation/mesh/flip_3d.hpp"
#include "triangulation/mesh/tetrahedralization_3d.hpp"

namespace exactmesh::triangulation {

/// A vertex that cannot be removed: out of range, in no tetrahedron, on the domain boundary, or
/// in a star that no flip sequence nor Delaunay cavity retetrahedralization can close.
class VertexRemovalError : public GeometryError {
  public:
    VertexRemovalError(VertIdx vertex, const std::string& reason,
                       SourceLocation where = SourceLocation::current())
        : GeometryError("cannot remove vertex " + std::to_string(vertex) + ": " + reason, where),
          vertex_(vertex) {}
    VertIdx vertex() const noexcept { return vertex_; }

  private:
    VertIdx vertex_;
};

struct VertexRemovalCounters {
    std::uint64_t removed = 0;
    std::uint64_t star_tets = 0;  ///< sum of the removed vertices' initial star sizes
    std::uint64_t flips_23 = 0;
    std::uint64_t flips_32 = 0;
    std::uint64_t flips_44 = 0;
    std::uint64_t flips_41 = 0;
    std::uint64_t cavity_fallbacks = 0;  ///< stars closed by the gift-wrapped Delaunay cavity
    std::uint64_t insphere_tests = 0;
};

/// Removes interior vertex v; its coordinates stay in mesh.xyz, used by no tetrahedron.
/// @throws VertexRemovalError (the mesh unchanged).
void remove_vertex_3d(TetMesh3& mesh, VertIdx v, VertexRemovalCounters* counters = nullptr);

/// Derefinement: removes each vertex of `vertices` in order.
/// @throws VertexRemovalError at the first that cannot go (the earlier removals stay made).
void remove_vertices_3d(TetMesh3& mesh, std::span<const VertIdx> vertices,
                        VertexRemovalCounters* counters = nullptr);

/// Convenience over a Tetrahedralization3 (make_tet_mesh_3d, remove, compact back); on an
/// exception `mesh` is left as it was.
void remove_vertices_3d(Tetrahedralization3& mesh, std::span<const VertIdx> vertices,
                        VertexRemovalCounters* counters = nullptr);

}  // namespace exactmesh::triangulation
