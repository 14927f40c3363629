// SPDX-License-Identifier: MIT
// The 2D flip kernel on TriMesh2 half-edges: the 1-3 split (a point inside a triangle), the
// edge split (2-4 on an interior edge, 1-2 on a boundary edge) and the 2-2 flip [Lawson77;
// GreenSibson78 §3; seed material §2.2], written once for every 2D insertion and swap
// (green_sibson_2d, edge_swap_2d and the constrained builder's cdt_insertion_2d).
// Invariants kept: twins mutual (an outer twin of kNone, the boundary of a mesh without the
// infinite vertex, stays kNone), every triangle counter-clockwise when the caller's geometric
// precondition holds, and mesh.flags (when not empty) kept per edge: an outer edge keeps its
// marks, both halves of a split edge keep the split edge's, a new edge starts at 0.
// Cost: O(1) each. Predicates: none (the callers decide; the kernel only rewrites topology).
// Inline by design: Green-Sibson's insertion calls them in its hot loop.
//
// Pictures, with the labels of the code (counter-clockwise; p the new vertex):
//
//   split_triangle_2d           split_edge_2d (2-4)            flip_2d (e = u -> v)
//          c                          c                            x              x
//         /|\                        /|\                          / \            /|\      .
//        / | \                      / | \                        /   \          / | \     .
//       /  p  \                    a--p--b   (e = a -> b)       u --- v  ==>   u  |  v
//      / /   \ \                    \ | /                        \   /          \ | /     .
//     a ------- b                    \|/                          \ /            \|/      .
//                                     d                            y              y
//
// Each split writes the triangles around p counter-clockwise with p at local index 0, so their
// half-edge 3t+1 is the side opposite p (the edges Lawson's flips test next). A flip writes the
// new diagonal at the local indices the caller asks for (k1 in the triangle of e, k2 in the
// other), so that every caller keeps its own layout and its output stays what it was.
#pragma once

#include <array>
#include <cstdint>

#include "triangulation/mesh/mesh2.hpp"
#include "triangulation/mesh/triangulation_2d.hpp"

namespace exactmesh::triangulation {

/// Whether the mesh may have half-edges without a twin. Closed: closed by the infinite vertex,
/// every twin exists, and no flags (the Delaunay and constrained builders, which keep their
/// constraints in arrays of their own); the kernel then writes outer twins without a test and
/// never looks at flags, which Green-Sibson's hot loop measures. Open: boundary half-edges have
/// twin kNone and flags may be set (a HalfEdgeEdit of a Triangulation2), the safe default.
enum class MeshBoundary { Open, Closed };

/// The triangles a split made, counter-clockwise around the new vertex p, each with p at local
/// index 0: 3t+1 is the side opposite p, 3t+2 runs into p, 3t out of p.
struct SplitTriangles {
    std::array<TriIdx, 4> triangles{};
    unsigned count = 0;  ///< 3 (1-3), 4 (2-4) or 2 (1-2 on a boundary edge)
    EdgeIdx side(unsigned i) const { return 3 * triangles[i] + 1; }
};

/// The half-edges of a flipped quadrilateral u, y, v, x (e was u -> v, x its apex, y the apex
/// across it).
struct FlipEdges {
    EdgeIdx diagonal;  ///< y -> x in the triangle that held e; its twin x -> y is in the other
    /// x -> u, u -> y (in the triangle of e), y -> v, v -> x (in the other): the four sides,
    /// counter-clockwise from x.
    std::array<EdgeIdx, 4> sides;
};

namespace flip_detail {

/// Whether the kernel keeps flags: a Closed mesh has none (a compile-time false for its callers).
inline bool keeps_flags(const TriMesh2& mesh, MeshBoundary boundary) {
    return boundary == MeshBoundary::Open && !mesh.flags.empty();
}

/// e faces the surviving half-edge `outer` (kNone on the boundary of an open mesh).
inline void link_side(TriMesh2& mesh, EdgeIdx e, EdgeIdx outer, MeshBoundary boundary) {
    mesh.twin[e] = outer;
    if (boundary == MeshBoundary::Closed || outer != kNone) mesh.twin[outer] = e;
}

/// Writes the fan of made.count triangles around p: triangle i = (p, rim[i], rim[i + 1]) in slot
/// made.triangles[i], its side rim[i] -> rim[i + 1] facing outer[i] with the flags side_flags[i],
/// its spoke into p facing the next triangle's spoke out of p; the last spoke links to the first
/// when the fan closes around p, else both end spokes are boundary (kNone). Spokes start at 0.
inline void write_fan(TriMesh2& mesh, VertIdx p, const SplitTriangles& made, const VertIdx* rim,
                      const EdgeIdx* outer, const std::uint8_t* side_flags, bool closes,
                      MeshBoundary boundary) {
    const unsigned n = made.count;
    for (unsigned i = 0; i < n; ++i) {
        const TriIdx t = made.triangles[i];
        mesh.tv[3 * t] = p;
        mesh.tv[3 * t + 1] = rim[i];
        mesh.tv[3 * t + 2] = rim[i + 1];
        link_side(mesh, 3 * t + 1, outer[i], boundary);
    }
    for (unsigned i = 0; i + 1 < n; ++i) {
        mesh.link(3 * made.triangles[i] + 2, 3 * made.triangles[i + 1]);
    }
    if (closes) {
        mesh.link(3 * made.triangles[n - 1] + 2, 3 * made.triangles[0]);
    } else {
        mesh.twin[3 * made.triangles[0]] = kNone;
        mesh.twin[3 * made.triangles[n - 1] + 2] = kNone;
    }
    if (keeps_flags(mesh, boundary)) {
        for (unsigned i = 0; i < n; ++i) {
            const TriIdx t = made.triangles[i];
            mesh.flags[3 * t] = 0;
            mesh.flags[3 * t + 1] = side_flags[i];
            mesh.flags[3 * t + 2] = 0;
        }
    }
}

}  // namespace flip_detail

/// 1 -> 3: p inside t = (a, b, c) (strictly: the caller's orient2d says so) gives (p, a, b) in
/// slot t, then (p, b, c) and (p, c, a) in two new slots, in that order.
inline SplitTriangles split_triangle_2d(TriMesh2& mesh, TriIdx t, VertIdx p,
                                        MeshBoundary boundary = MeshBoundary::Open) {
    const VertIdx rim[4] = {mesh.tv[3 * t], mesh.tv[3 * t + 1], mesh.tv[3 * t + 2], mesh.tv[3 * t]};
    const EdgeIdx outer[3] = {mesh.twin[3 * t], mesh.twin[3 * t + 1], mesh.twin[3 * t + 2]};
    std::uint8_t side_flags[3] = {0, 0, 0};
    if (flip_detail::keeps_flags(mesh, boundary)) {
        for (unsigned k = 0; k < 3; ++k) side_flags[k] = mesh.flags[3 * t + k];
    }
    SplitTriangles made;
    made.triangles[0] = t;
    made.triangles[1] = mesh.new_triangle();
    made.triangles[2] = mesh.new_triangle();
    made.triangles[3] = kNone;
    made.count = 3;
    flip_detail::write_fan(mesh, p, made, rim, outer, side_flags, true, boundary);
    return made;
}

/// p on the edge e = a -> b of (a, b, c) (exactly: orient2d(a, b, p) == 0, strictly between).
/// Interior edge, twin in (b, a, d): 2 -> 4, giving (p, b, c) in e's slot, (p, c, a) in the
/// twin's, then (p, a, d) and (p, d, b) in two new slots. Boundary edge (twin kNone): 1 -> 2,
/// giving (p, b, c) in e's slot and (p, c, a) in a new one. Both halves a - p and p - b keep e's
/// flags.
inline SplitTriangles split_edge_2d(TriMesh2& mesh, EdgeIdx e, VertIdx p,
                                    MeshBoundary boundary = MeshBoundary::Open) {
    const EdgeIdx f = mesh.twin[e];
    const bool open = boundary == MeshBoundary::Open && f == kNone;
    const VertIdx a = mesh.origin(e), b = mesh.destination(e), c = mesh.tv[prev_edge(e)];
    const VertIdx d = open ? kNone : mesh.tv[prev_edge(f)];
    const VertIdx rim[5] = {b, c, a, d, b};
    const EdgeIdx outer[4] = {mesh.twin[next_edge(e)], mesh.twin[prev_edge(e)],
                              open ? kNone : mesh.twin[next_edge(f)],
                              open ? kNone : mesh.twin[prev_edge(f)]};
    const bool flagged = flip_detail::keeps_flags(mesh, boundary);
    std::uint8_t side_flags[4] = {0, 0, 0, 0};
    std::uint8_t split = 0;
    if (flagged) {
        split = mesh.flags[e];
        side_flags[0] = mesh.flags[next_edge(e)];
        side_flags[1] = mesh.flags[prev_edge(e)];
        if (!open) {
            side_flags[2] = mesh.flags[next_edge(f)];
            side_flags[3] = mesh.flags[prev_edge(f)];
        }
    }
    SplitTriangles made;
    made.triangles[0] = triangle_of(e);
    if (open) {
        made.triangles[1] = mesh.new_triangle();
        made.triangles[2] = made.triangles[3] = kNone;
        made.count = 2;
    } else {
        made.triangles[1] = triangle_of(f);
        made.triangles[2] = mesh.new_triangle();
        made.triangles[3] = mesh.new_triangle();
        made.count = 4;
    }
    flip_detail::write_fan(mesh, p, made, rim, outer, side_flags, !open, boundary);
    if (flagged) {
        // The halves: p -> b and a -> p, then (interior) p -> a and b -> p.
        mesh.flags[3 * made.triangles[0]] = split;
        mesh.flags[3 * made.triangles[1] + 2] = split;
        if (!open) {
            mesh.flags[3 * made.triangles[2]] = split;
            mesh.flags[3 * made.triangles[3] + 2] = split;
        }
    }
    return made;
}

/// 2 -> 2: the edge of e (u -> v in (u, v, x), twin in (v, u, y)) becomes x - y. The triangle of
/// e becomes (y, x, u) rotated so that y -> x sits at local index k1; the other becomes
/// (x, y, v) rotated so that x -> y sits at local index k2. The caller guarantees that u, y, v, x
/// is strictly convex (both new triangles counter-clockwise) and that e carries no constraint;
/// the new diagonal's flags are 0.
inline FlipEdges flip_2d(TriMesh2& mesh, EdgeIdx e, unsigned k1, unsigned k2,
                         MeshBoundary boundary = MeshBoundary::Open) {
    using namespace flip_detail;
    const EdgeIdx f = mesh.twin[e];
    const TriIdx t1 = triangle_of(e), t2 = triangle_of(f);
    const VertIdx u = mesh.origin(e), v = mesh.destination(e);
    const VertIdx x = mesh.tv[prev_edge(e)], y = mesh.tv[prev_edge(f)];
    const EdgeIdx vx = mesh.twin[next_edge(e)], xu = mesh.twin[prev_edge(e)];
    const EdgeIdx uy = mesh.twin[next_edge(f)], yv = mesh.twin[prev_edge(f)];
    const bool flagged = flip_detail::keeps_flags(mesh, boundary);
    std::uint8_t fvx = 0, fxu = 0, fuy = 0, fyv = 0;
    if (flagged) {
        fvx = mesh.flags[next_edge(e)];
        fxu = mesh.flags[prev_edge(e)];
        fuy = mesh.flags[next_edge(f)];
        fyv = mesh.flags[prev_edge(f)];
    }
    const EdgeIdx d1 = 3 * t1 + k1, x_u = 3 * t1 + (k1 + 1) % 3, u_y = 3 * t1 + (k1 + 2) % 3;
    const EdgeIdx d2 = 3 * t2 + k2, y_v = 3 * t2 + (k2 + 1) % 3, v_x = 3 * t2 + (k2 + 2) % 3;
    mesh.tv[d1] = y;
    mesh.tv[x_u] = x;
    mesh.tv[u_y] = u;
    mesh.tv[d2] = x;
    mesh.tv[y_v] = y;
    mesh.tv[v_x] = v;
    if (x_u != prev_edge(e)) link_side(mesh, x_u, xu, boundary);  // else x -> u kept its slot
    link_side(mesh, u_y, uy, boundary);
    link_side(mesh, y_v, yv, boundary);
    link_side(mesh, v_x, vx, boundary);
    mesh.link(d1, d2);
    if (flagged) {
        mesh.flags[d1] = mesh.flags[d2] = 0;
        mesh.flags[x_u] = fxu;
        mesh.flags[u_y] = fuy;
        mesh.flags[y_v] = fyv;
        mesh.flags[v_x] = fvx;
    }
    return {d1, {x_u, u_y, y_v, v_x}};
}

/// A Triangulation2 lent to an edit as a TriMesh2 (the one working topology of 2D edits): the
/// arrays are moved, not copied; twins are found from the neighbour ids once, here (the only
/// "which side am I on" search), flags taken from `constrained`. When the edit ends (also by an
/// exception) triangles, neighbours and constraint flags are written back. Edits that add
/// triangles are fine (neighbours grow); dead triangles are not compacted.
class HalfEdgeEdit {
  public:
    /// @pre mesh.neighbors consistent (link_neighbors_2d) and mesh.constrained empty or 3·#T.
    /// @throws InternalError (before moving anything) when a neighbour does not share the edge.
    explicit HalfEdgeEdit(Triangulation2& mesh);
    ~HalfEdgeEdit();
    HalfEdgeEdit(const HalfEdgeEdit&) = delete;
    HalfEdgeEdit& operator=(const HalfEdgeEdit&) = delete;

    TriMesh2& mesh() { return work_; }

  private:
    Triangulation2& target_;
    TriMesh2 work_;
};

}  // namespace exactmesh::triangulation
