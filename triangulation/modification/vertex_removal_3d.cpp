// SPDX-License-Identifier: MIT
// Vertex removal by flips (see vertex_removal_3d.hpp).
//
// Why the flips keep the result Delaunay. Let C be p's original star (a polyhedron, star-shaped
// from p) and L the vertices of its link. The Delaunay tetrahedralization D of the points
// without p keeps every tetrahedron outside C, and inside C it is DT(L) restricted to C: a
// tetrahedron of D inside C has its vertices in L and an empty sphere, so it is in DT(L), and
// these tile C. A flip among p's tetrahedra only changes tetrahedra inside C; a tetrahedron it
// creates without p lies in C, and when its sphere holds no vertex of L (SoS) it belongs to
// DT(L), hence to D. So every created tetrahedron is final, and when p's last four go by the 4-1
// flip the whole of C is tiled by tetrahedra of D.
#include "triangulation/modification/vertex_removal_3d.hpp"

#include <algorithm>
#include <array>
#include <vector>

#include "predicates/orient3d.hpp"
#include "predicates/sos.hpp"
#include "triangulation/modification/edge_face_swap_3d.hpp"

namespace exactmesh::triangulation {

namespace {

using predicates::Sign;

bool holds(const Tet& t, VertIdx v) {
    return std::find(t.begin(), t.end(), v) != t.end();
}

/// Whether the circumsphere of positive tetrahedron t holds no vertex of `link` (SoS).
bool empty_of(const TetMesh3& mesh, const Tet& t, const std::vector<VertIdx>& link,
              VertexRemovalCounters& counters) {
    for (const VertIdx x : link) {
        if (holds(t, x)) continue;
        ++counters.insphere_tests;
        if (predicates::insphere_sos(mesh.point(t[0]), mesh.point(t[1]), mesh.point(t[2]),
                                     mesh.point(t[3]), mesh.point(x), t[0], t[1], t[2], t[3],
                                     x) == Sign::Positive) {
            return false;
        }
    }
    return true;
}

std::vector<VertIdx> link_vertices(const TetMesh3& mesh, const std::vector<TetIdx>& star,
                                   VertIdx v) {
    std::vector<VertIdx> link;
    for (const TetIdx t : star) {
        for (unsigned k = 0; k < 4; ++k) {
            const VertIdx x = mesh.vertex(t, k);
            if (x != v && std::find(link.begin(), link.end(), x) == link.end()) link.push_back(x);
        }
    }
    return link;
}

/// One flip among v's tetrahedra whose new tetrahedra without v are empty of `link`'s vertices.
bool find_flip(const TetMesh3& mesh, VertIdx v, const std::vector<TetIdx>& star,
               const std::vector<VertIdx>& link, FlipPlan3& plan, VertexRemovalCounters& counters) {
    for (const TetIdx t : star) {
        const unsigned lv = mesh.slot_of(t, v);
        for (unsigned k = 0; k < 4; ++k) {
            if (k == lv) continue;
            const FaceIdx f = 4 * t + k;
            const FaceIdx twin = mesh.adj[f];
            if (twin == kNone || twin / 4 < t) continue;  // each face holding v once
            if (!plan_flip_3d(mesh, f, plan)) continue;
            if (plan.kind == FlipKind3::Flip22) continue;
            bool inside = true;
            for (unsigned i = 0; i < plan.old_count; ++i)
                inside = inside && mesh.slot_of(plan.old[i], v) < 4;
            if (!inside) continue;  // would change tetrahedra outside the star
            bool delaunay = true;
            for (unsigned i = 0; i < plan.made_count && delaunay; ++i) {
                if (!holds(plan.made[i], v))
                    delaunay = empty_of(mesh, plan.made[i], link, counters);
            }
            if (delaunay) return true;
        }
    }
    return false;
}

/// The Delaunay tetrahedra of the link vertices inside the region of `star`, by gift wrapping
/// from its boundary faces; empty when the front cannot be closed.
std::vector<Tet> wrap_cavity(const TetMesh3& mesh, VertIdx v, const std::vector<TetIdx>& star,
                             const std::vector<VertIdx>& link, VertexRemovalCounters& counters) {
    // Front faces, oriented so that the part still to fill lies on their positive side.
    std::vector<std::array<VertIdx, 3>> front;
    for (const TetIdx t : star) front.push_back(mesh.face(4 * t + mesh.slot_of(t, v)));
    auto same = [](const std::array<VertIdx, 3>& x, const std::array<VertIdx, 3>& y) {
        return (x[0] == y[0] && x[1] == y[1] && x[2] == y[2]) ||
               (x[0] == y[1] && x[1] == y[2] && x[2] == y[0]) ||
               (x[0] == y[2] && x[1] == y[0] && x[2] == y[1]);
    };
    std::vector<Tet> made;
    const std::size_t limit = 4 * link.size() * link.size() + 16;
    while (!front.empty()) {
        if (made.size() > limit) return {};
        const auto face = front.back();
        front.pop_back();
        const double* a = mesh.point(face[0]);
        const double* b = mesh.point(face[1]);
        const double* c = mesh.point(face[2]);
        VertIdx best = kNone;
        for (const VertIdx x : link) {
            if (x == face[0] || x == face[1] || x == face[2]) continue;
            if (predicates::orient3d(a, b, c, mesh.point(x)) != Sign::Positive) continue;
            if (best == kNone) {
                best = x;
                continue;
            }
            ++counters.insphere_tests;
            if (predicates::insphere_sos(a, b, c, mesh.point(best), mesh.point(x), face[0], face[1],
                                         face[2], best, x) == Sign::Positive) {
                best = x;
            }
        }
        if (best == kNone) return {};
        const Tet t{face[0], face[1], face[2], best};
        made.push_back(t);
        // The three other faces: each closes a front face it meets, or joins the front.
        for (unsigned k = 0; k < 3; ++k) {
            const unsigned* lf = kFaceVertex[k];
            const std::array<VertIdx, 3> outward{t[lf[0]], t[lf[1]],
                                                 t[lf[2]]};  // t on its positive side
            const auto it = std::find_if(front.begin(), front.end(),
                                         [&](const auto& g) { return same(g, outward); });
            if (it != front.end()) {
                front.erase(it);
            } else {
                front.push_back({outward[0], outward[2], outward[1]});
            }
        }
    }
    return made;
}

void remove_one(TetMesh3& mesh, VertIdx v, VertexRemovalCounters& counters) {
    if (v >= mesh.vertex_count()) {
        throw VertexRemovalError(
            v, "out of range (" + std::to_string(mesh.vertex_count()) + " vertices)");
    }
    if (mesh.vertex_tet[v] == kNone)
        throw VertexRemovalError(v, "it is a vertex of no tetrahedron");
    const std::vector<TetIdx> original = vertex_star(mesh, v);
    for (const TetIdx t : original) {
        const unsigned lv = mesh.slot_of(t, v);
        for (unsigned k = 0; k < 4; ++k) {
            if (k != lv && mesh.adj[4 * std::size_t{t} + k] == kNone) {
                throw VertexRemovalError(
                    v,
                    "it lies on the boundary of the domain (removing it would change the domain)");
            }
        }
    }
    std::vector<Tet> original_tets;
    for (const TetIdx t : original) original_tets.push_back(mesh.tet(t));
    const std::vector<VertIdx> link = link_vertices(mesh, original, v);
    // Every tetrahedron made inside the star so far (for the undo).
    std::vector<Tet> made_outside_star;
    std::vector<TetIdx> star = original;
    std::vector<TetIdx> created;
    FlipPlan3 plan;
    VertexRemovalCounters local;
    auto undo_and_fail = [&](const std::string& reason) {
        std::vector<TetIdx> region = vertex_star(mesh, v);
        for (const Tet& t : made_outside_star) {
            // Find the live slot of each made tetrahedron through a vertex's star.
            for (const TetIdx u : vertex_star(mesh, t[0])) {
                if (mesh.tet(u) == t && std::find(region.begin(), region.end(), u) == region.end())
                    region.push_back(u);
            }
        }
        if (!replace_tets(mesh, region, original_tets)) {
            throw InternalError("vertex_removal_3d: could not restore the star of vertex " +
                                std::to_string(v));
        }
        throw VertexRemovalError(v, reason);
    };
    while (star.size() > 4) {
        if (!find_flip(mesh, v, star, link, plan, local)) break;
        apply_flip_3d(mesh, plan, created);
        for (unsigned i = 0; i < plan.made_count; ++i) {
            if (!holds(plan.made[i], v)) made_outside_star.push_back(plan.made[i]);
        }
        count_flip(local, plan.kind);
        star = vertex_star(mesh, v);
    }
    std::vector<Tet> closing;
    if (star.size() == 4) {
        // The 4-1 flip: the link is a tetrahedron holding v; any star tetrahedron with v
        // replaced by the fourth link vertex has the same orientation.
        const std::vector<VertIdx> last = link_vertices(mesh, star, v);
        Tet t = mesh.tet(star[0]);
        for (const VertIdx x : last) {
            if (!holds(t, x)) std::replace(t.begin(), t.end(), v, x);
        }
        if (last.size() == 4 &&
            predicates::orient3d(mesh.point(t[0]), mesh.point(t[1]), mesh.point(t[2]),
                                 mesh.point(t[3])) == Sign::Positive) {
            closing.push_back(t);
        }
    }
    if (closing.empty()) {
        closing = wrap_cavity(mesh, v, star, link_vertices(mesh, star, v), local);
        if (closing.empty()) {
            undo_and_fail(
                "no flip sequence empties its star, and the Delaunay tetrahedra of its link do not "
                "fill the star "
                "(the tetrahedralization is not Delaunay around it)");
        }
        ++local.cavity_fallbacks;
    } else {
        ++local.flips_41;
    }
    if (!replace_tets(mesh, star, closing)) {
        undo_and_fail(
            "the Delaunay tetrahedra of its link do not fit its star (the tetrahedralization is "
            "not Delaunay "
            "around it)");
    }
    counters.removed += 1;
    counters.star_tets += original.size();
    counters.flips_23 += local.flips_23;
    counters.flips_32 += local.flips_32;
    counters.flips_44 += local.flips_44;
    counters.flips_41 += local.flips_41;
    counters.cavity_fallbacks += local.cavity_fallbacks;
    counters.insphere_tests += local.insphere_tests;
}

}  // namespace

void remove_vertex_3d(TetMesh3& mesh, VertIdx v, VertexRemovalCounters* counters) {
    VertexRemovalCounters local;
    remove_one(mesh, v, counters != nullptr ? *counters : local);
}

void remove_vertices_3d(TetMesh3& mesh, std::span<const VertIdx> vertices,
                        VertexRemovalCounters* counters) {
    VertexRemovalCounters local;
    for (const VertIdx v : vertices) remove_one(mesh, v, counters != nullptr ? *counters : local);
}

void remove_vertices_3d(Tetrahedralization3& mesh, std::span<const VertIdx> vertices,
                        VertexRemovalCounters* counters) {
    TetMesh3 work = make_tet_mesh_3d(mesh);
    remove_vertices_3d(work, vertices, counters);
    mesh = to_tetrahedralization_3d(work);
}

}  // namespace exactmesh::triangulation
