// SPDX-License-Identifier: MIT
// The local rewrites of a TetMesh3: conversions, replace_tets, the planned flips and the star of
// a point (see flip_3d.hpp).
#include "triangulation/mesh/flip_3d.hpp"

#include "triangulation/mesh/vertex_keys_3d.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>

#include "base/errors.hpp"
#include "predicates/orient3d.hpp"
#include "predicates/sos.hpp"

namespace exactmesh::triangulation {

namespace {

using predicates::Sign;

/// A face rotated so that its smallest vertex comes first; the cyclic order (orientation) kept.
using OrientedFace = std::array<VertIdx, 3>;

OrientedFace rotated(VertIdx a, VertIdx b, VertIdx c) {
    if (a < b && a < c) return {a, b, c};
    if (b < a && b < c) return {b, c, a};
    return {c, a, b};
}

OrientedFace reversed(const OrientedFace& f) {
    return {f[0], f[2], f[1]};
}

OrientedFace outward_face(const Tet& t, unsigned k) {
    const unsigned* lf = kFaceVertex[k];
    return rotated(t[lf[0]], t[lf[1]], t[lf[2]]);
}

std::string tet_text(std::size_t t, const VertIdx* v, const Check3Numbering& numbering) {
    auto name = [&](unsigned k) {
        return std::to_string(std::uint64_t{v[numbering.corner_order[k]]} + numbering.first_vertex);
    };
    return "tetrahedron " + std::to_string(t + numbering.first_tet) + " (" + name(0) + ", " +
           name(1) + ", " + name(2) + ", " + name(3) + ")";
}

/// Range, distinct vertices, finite coordinates and strictly positive orientation of every
/// tetrahedron; throws InputError naming the first offender.
void validate_tets(const std::vector<double>& xyz, const std::vector<VertIdx>& tets,
                   const Check3Numbering& numbering) {
    const std::uint32_t first_vertex = numbering.first_vertex;
    if (xyz.size() % 3 != 0) throw InputError("coordinate array length is not a multiple of 3");
    if (tets.size() % 4 != 0) throw InputError("tetrahedron list length is not a multiple of 4");
    const std::size_t n = xyz.size() / 3;
    for (std::size_t i = 0; i < xyz.size(); ++i) {
        if (!std::isfinite(xyz[i])) {
            throw NonFiniteCoordinate(
                "vertex " + std::to_string(i / 3 + first_vertex) + " has a non-finite coordinate",
                static_cast<std::uint32_t>(i / 3));
        }
    }
    for (std::size_t t = 0; 4 * t < tets.size(); ++t) {
        const VertIdx* v = &tets[4 * t];
        for (unsigned k = 0; k < 4; ++k) {
            if (v[k] >= n) {
                throw InputError(tet_text(t, v, numbering) + ": vertex " +
                                 std::to_string(std::uint64_t{v[k]} + first_vertex) +
                                 " out of range (" + std::to_string(n) + " vertices)");
            }
            for (unsigned j = 0; j < k; ++j) {
                if (v[j] == v[k]) {
                    throw InputError(tet_text(t, v, numbering) + " repeats a vertex");
                }
            }
        }
        const Sign s =
            predicates::orient3d(&xyz[3 * std::size_t{v[0]}], &xyz[3 * std::size_t{v[1]}],
                                 &xyz[3 * std::size_t{v[2]}], &xyz[3 * std::size_t{v[3]}]);
        if (s != Sign::Positive) {
            throw InputError(tet_text(t, v, numbering) +
                             (s == Sign::Zero ? " is flat (its vertices are coplanar)"
                                              : " is negatively oriented"));
        }
    }
}

/// adj from the vertex lists: facets sorted by their face's vertex set.
std::vector<FaceIdx> link_facets(const std::vector<VertIdx>& tets, std::uint32_t first_vertex,
                                 std::uint32_t first_tet) {
    const std::vector<KeyedFace3> entries = sorted_faces_3d(tets);
    std::vector<FaceIdx> adj(tets.size(), kNone);
    for (std::size_t i = 0; i < entries.size();) {
        std::size_t j = i + 1;
        while (j < entries.size() && entries[j].key == entries[i].key) ++j;
        if (j - i > 2) {
            const auto& k = entries[i].key;
            throw InputError("face (" + std::to_string(std::uint64_t{k[0]} + first_vertex) + ", " +
                             std::to_string(std::uint64_t{k[1]} + first_vertex) + ", " +
                             std::to_string(std::uint64_t{k[2]} + first_vertex) +
                             ") is shared by " + std::to_string(j - i) + " tetrahedra (" +
                             std::to_string(entries[i].face / 4 + first_tet) + ", " +
                             std::to_string(entries[i + 1].face / 4 + first_tet) + ", " +
                             std::to_string(entries[i + 2].face / 4 + first_tet) +
                             "): overlapping tetrahedra");
        }
        if (j - i == 2) {
            adj[entries[i].face] = entries[i + 1].face;
            adj[entries[i + 1].face] = entries[i].face;
        }
        i = j;
    }
    return adj;
}

}  // namespace

void link_neighbors_3d(Tetrahedralization3& mesh, const Check3Numbering& numbering) {
    validate_tets(mesh.xyz, mesh.tets, numbering);
    const std::vector<FaceIdx> adj =
        link_facets(mesh.tets, numbering.first_vertex, numbering.first_tet);
    mesh.neighbors.assign(mesh.tets.size(), kNone);
    for (std::size_t f = 0; f < adj.size(); ++f) {
        if (adj[f] != kNone) mesh.neighbors[f] = adj[f] / 4;
    }
}

TetMesh3 make_tet_mesh_3d(const Tetrahedralization3& mesh) {
    return make_tet_mesh_3d(Tetrahedralization3(mesh));
}

TetMesh3 make_tet_mesh_3d(Tetrahedralization3&& mesh) {
    validate_tets(mesh.xyz, mesh.tets, Check3Numbering{});
    TetMesh3 out;
    out.xyz = std::move(mesh.xyz);
    out.tv = std::move(mesh.tets);
    if (mesh.neighbors.empty()) {
        out.adj = link_facets(out.tv, 0, 0);
    } else {
        if (mesh.neighbors.size() != out.tv.size()) {
            throw InputError("neighbor array: " + std::to_string(mesh.neighbors.size()) +
                             " entries for " + std::to_string(out.tv.size() / 4) + " tetrahedra");
        }
        const std::size_t count = out.tv.size() / 4;
        out.adj.assign(out.tv.size(), kNone);
        // Each link is checked once, from its lower tetrahedron, which sets both sides; the
        // higher one's side must then be set already (it points back at a face that pointed at
        // it). Checking from both sides read every neighbour's corners twice, in random order:
        // a sixth of sliver removal's time at 7 10^5 tetrahedra.
        // The neighbours lie anywhere in the arrays (refinement numbers its tetrahedra in the
        // order it makes them): a later one's links, corners and adj entries are fetched a few
        // faces ahead.
        constexpr std::size_t kAhead = 32;
        for (std::size_t f = 0; f < out.tv.size(); ++f) {
            if (f + kAhead < out.tv.size()) {
                const std::size_t ahead = mesh.neighbors[f + kAhead];
                if (ahead < count && ahead > (f + kAhead) / 4) {
                    __builtin_prefetch(&mesh.neighbors[4 * ahead]);
                    __builtin_prefetch(&out.tv[4 * ahead]);
                    __builtin_prefetch(&out.adj[4 * ahead], 1);
                }
            }
            const TetIdx u = mesh.neighbors[f];
            if (u == kNone) continue;
            const std::size_t t = f / 4;
            if (u >= count || u == t) {
                throw InputError("tetrahedron " + std::to_string(t) + ": neighbor " +
                                 std::to_string(u) + " across face " + std::to_string(f % 4) +
                                 " is not another tetrahedron");
            }
            bool found = u < t && out.adj[f] != kNone && out.adj[f] / 4 == u;
            if (u > t) {
                const OrientedFace mine = outward_face(out.tet(static_cast<TetIdx>(t)), f % 4);
                for (unsigned j = 0; j < 4 && !found; ++j) {
                    const std::size_t g = 4 * std::size_t{u} + j;
                    if (mesh.neighbors[g] == t && outward_face(out.tet(u), j) == reversed(mine)) {
                        out.adj[f] = static_cast<FaceIdx>(g);
                        out.adj[g] = static_cast<FaceIdx>(f);
                        found = true;
                    }
                }
            }
            if (!found) {
                throw InputError("tetrahedron " + std::to_string(t) + ": neighbor " +
                                 std::to_string(u) + " across face " + std::to_string(f % 4) +
                                 " does not share that face back (inconsistent neighbors)");
            }
        }
        // A face shared without a neighbor link: two boundary faces that coincide, or a
        // boundary face on a linked pair's face. The boundary faces' keys, sorted, find the
        // first; each linked pair whose three vertices are all on boundary faces is looked up
        // among them for the second. (Sorting every face, as link_facets does, was a quarter of
        // sliver removal's time at 680,000 tetrahedra; two linked pairs on one face, four
        // overlapping tetrahedra, are not looked for.)
        std::vector<std::pair<Key3, FaceIdx>> boundary;
        std::vector<std::uint8_t> on_boundary(out.vertex_count(), 0);
        const auto key_of = [&](std::size_t f) {
            const unsigned* lf = kFaceVertex[f % 4];
            const VertIdx* v = &out.tv[f - f % 4];
            return sorted3(v[lf[0]], v[lf[1]], v[lf[2]]);
        };
        for (std::size_t f = 0; f < out.adj.size(); ++f) {
            if (out.adj[f] != kNone) continue;
            const Key3 key = key_of(f);
            boundary.push_back({key, static_cast<FaceIdx>(f)});
            for (const VertIdx v : key) on_boundary[v] = 1;
        }
        std::sort(boundary.begin(), boundary.end());
        const auto shared = [](std::size_t f) {
            return InputError(
                "tetrahedron " + std::to_string(f / 4) + ": face " + std::to_string(f % 4) +
                " is shared with another tetrahedron but the neighbors say otherwise");
        };
        for (std::size_t i = 1; i < boundary.size(); ++i) {
            if (boundary[i].first == boundary[i - 1].first) throw shared(boundary[i - 1].second);
        }
        for (std::size_t f = 0; f < out.adj.size(); ++f) {
            if (out.adj[f] == kNone || out.adj[f] < f) continue;
            const Key3 key = key_of(f);
            if (!on_boundary[key[0]] || !on_boundary[key[1]] || !on_boundary[key[2]]) continue;
            const auto at = std::lower_bound(boundary.begin(), boundary.end(), key,
                                             [](const std::pair<Key3, FaceIdx>& entry,
                                                const Key3& k) { return entry.first < k; });
            if (at != boundary.end() && at->first == key) throw shared(at->second);
        }
    }
    out.vertex_tet.assign(out.vertex_count(), kNone);
    for (std::size_t i = 0; i < out.tv.size(); ++i)
        out.vertex_tet[out.tv[i]] = static_cast<TetIdx>(i / 4);
    return out;
}

Tetrahedralization3 to_tetrahedralization_3d(const TetMesh3& mesh) {
    return to_tetrahedralization_3d(TetMesh3(mesh));
}

Tetrahedralization3 to_tetrahedralization_3d(TetMesh3&& mesh) {
    // Compacted in place: a live slot's new index is at most its own, so each tetrahedron is
    // read before anything is written over it (fresh arrays were a twentieth of sliver
    // removal's time at 7 10^5 tetrahedra, most of it first touches of their pages).
    std::vector<TetIdx> index(mesh.tet_slots(), kNone);
    TetIdx next = 0;
    for (TetIdx t = 0; t < mesh.tet_slots(); ++t) {
        if (!mesh.is_dead(t)) index[t] = next++;
    }
    for (TetIdx t = 0; t < mesh.tet_slots(); ++t) {
        if (index[t] == kNone) continue;
        const std::size_t from = 4 * std::size_t{t}, to = 4 * std::size_t{index[t]};
        for (unsigned k = 0; k < 4; ++k) {
            mesh.tv[to + k] = mesh.tv[from + k];
            const FaceIdx twin = mesh.adj[from + k];
            mesh.adj[to + k] = twin == kNone ? kNone : index[twin / 4];
        }
    }
    mesh.tv.resize(4 * std::size_t{next});
    mesh.adj.resize(4 * std::size_t{next});
    Tetrahedralization3 out;
    out.xyz = std::move(mesh.xyz);
    out.tets = std::move(mesh.tv);
    out.neighbors = std::move(mesh.adj);
    return out;
}

bool replace_tets(TetMesh3& mesh, std::span<const TetIdx> old_tets, std::span<const Tet> new_tets,
                  std::vector<TetIdx>* created, bool retriangulate_domain_boundary) {
    auto in_old = [&](TetIdx t) {
        return std::find(old_tets.begin(), old_tets.end(), t) != old_tets.end();
    };
    struct Boundary {
        OrientedFace face;  ///< outward from the old region
        FaceIdx twin;       ///< the facet outside, or kNone
        bool used;
    };
    std::vector<Boundary> boundary;
    boundary.reserve(2 * old_tets.size() + 4);
    for (const TetIdx t : old_tets) {
        EM_ASSERT(!mesh.is_dead(t));
        for (unsigned k = 0; k < 4; ++k) {
            const FaceIdx twin = mesh.adj[4 * std::size_t{t} + k];
            if (twin == kNone || !in_old(twin / 4)) {
                boundary.push_back({outward_face(mesh.tet(t), k), twin, false});
            }
        }
    }
    // For every new facet: the boundary entry it takes, or the new facet it faces.
    constexpr std::uint32_t kBoundaryFlag = 0x80000000u;
    constexpr std::uint32_t kDomainBoundary = 0x7FFFFFFFu;  // a new face on the domain boundary
    const std::size_t facets = 4 * new_tets.size();
    std::vector<std::uint32_t> match(facets, kNone);
    std::vector<OrientedFace> faces(facets);
    for (std::size_t i = 0; i < new_tets.size(); ++i) {
        for (unsigned k = 0; k < 4; ++k) faces[4 * i + k] = outward_face(new_tets[i], k);
    }
    for (std::size_t f = 0; f < facets; ++f) {
        if (match[f] != kNone) continue;
        const OrientedFace back = reversed(faces[f]);
        for (std::size_t g = f + 1; g < facets && match[f] == kNone; ++g) {
            if (match[g] == kNone && faces[g] == back) {
                match[f] = static_cast<std::uint32_t>(g);
                match[g] = static_cast<std::uint32_t>(f);
            }
        }
        if (match[f] != kNone) continue;
        for (std::size_t b = 0; b < boundary.size(); ++b) {
            if (!boundary[b].used && boundary[b].face == faces[f]) {
                boundary[b].used = true;
                match[f] = kBoundaryFlag | static_cast<std::uint32_t>(b);
                break;
            }
        }
        if (match[f] == kNone) {
            if (!retriangulate_domain_boundary) return false;
            match[f] = kBoundaryFlag | kDomainBoundary;
        }
    }
    for (const Boundary& b : boundary) {
        if (!b.used && !(retriangulate_domain_boundary && b.twin == kNone)) return false;
    }

    // Slots: the old ones first, then recycled or fresh ones.
    std::vector<TetIdx> slots;
    slots.reserve(new_tets.size());
    for (std::size_t i = 0; i < new_tets.size(); ++i) {
        // new_tet hands out the last freed slot, else the lowest fresh one: the slots an
        // append per tetrahedron would give.
        slots.push_back(i < old_tets.size() ? old_tets[i] : mesh.new_tet());
    }
    // Vertices that may lose their last tetrahedron (the removed vertex of a 4-1 flip).
    std::vector<VertIdx> old_vertices;
    for (const TetIdx t : old_tets) {
        for (unsigned k = 0; k < 4; ++k) old_vertices.push_back(mesh.vertex(t, k));
    }
    for (std::size_t i = new_tets.size(); i < old_tets.size(); ++i) {
        const std::size_t s = 4 * std::size_t{old_tets[i]};
        for (unsigned k = 0; k < 4; ++k) {
            mesh.tv[s + k] = kNone;
            mesh.adj[s + k] = kNone;
        }
        mesh.free_tets.push_back(old_tets[i]);
    }
    for (std::size_t i = 0; i < new_tets.size(); ++i) {
        const std::size_t s = 4 * std::size_t{slots[i]};
        for (unsigned k = 0; k < 4; ++k) mesh.tv[s + k] = new_tets[i][k];
    }
    for (VertIdx v : old_vertices) mesh.vertex_tet[v] = kNone;
    for (std::size_t i = 0; i < new_tets.size(); ++i) {
        for (unsigned k = 0; k < 4; ++k) mesh.vertex_tet[new_tets[i][k]] = slots[i];
    }
    for (std::size_t f = 0; f < facets; ++f) {
        const FaceIdx mine = 4 * slots[f / 4] + static_cast<FaceIdx>(f % 4);
        if ((match[f] & kBoundaryFlag) != 0) {
            const std::uint32_t b = match[f] & ~kBoundaryFlag;
            const FaceIdx twin = b == kDomainBoundary ? kNone : boundary[b].twin;
            mesh.adj[mine] = twin;
            if (twin != kNone) mesh.adj[twin] = mine;
        } else {
            mesh.adj[mine] = 4 * slots[match[f] / 4] + match[f] % 4;
        }
    }
    if (created != nullptr) *created = std::move(slots);
    return true;
}

EdgeRing edge_ring(const TetMesh3& mesh, TetIdx t, VertIdx a, VertIdx b) {
    EdgeRing ring;
    const unsigned la = mesh.slot_of(t, a), lb = mesh.slot_of(t, b);
    EM_ASSERT(la < 4 && lb < 4 && la != lb);
    unsigned others[2], n = 0;
    for (unsigned k = 0; k < 4; ++k) {
        if (k != la && k != lb) others[n++] = k;
    }
    // Walk leaving through the face opposite `stay`'s partner: enter a tetrahedron through the
    // face (a, b, w) and leave through the face (a, b, u) of its other apex u.
    auto walk = [&](VertIdx first_exit_opposite, std::vector<TetIdx>& out) -> bool {
        TetIdx current = t;
        VertIdx opposite = first_exit_opposite;  // leave `current` through the face opposite it
        for (;;) {
            const unsigned k = mesh.slot_of(current, opposite);
            const FaceIdx twin = mesh.adj[4 * std::size_t{current} + k];
            if (twin == kNone) return false;
            const TetIdx next = twin / 4;
            if (next == t) return true;
            out.push_back(next);
            // The apex of `next` across the entry face is the new vertex; leave through the face
            // opposite the entry face's third vertex (the one `current` and `next` share).
            VertIdx shared = kNone;
            for (unsigned j = 0; j < 4; ++j) {
                const VertIdx v = mesh.vertex(current, j);
                if (v != a && v != b && v != opposite) shared = v;
            }
            EM_ASSERT(shared != kNone && out.size() <= mesh.tet_slots());
            current = next;
            opposite = shared;
        }
    };
    ring.tets.push_back(t);
    std::vector<TetIdx> forward;
    if (walk(mesh.vertex(t, others[1]), forward)) {
        ring.closed = true;
        ring.tets.insert(ring.tets.end(), forward.begin(), forward.end());
        return ring;
    }
    std::vector<TetIdx> backward;
    walk(mesh.vertex(t, others[0]), backward);
    std::reverse(backward.begin(), backward.end());
    backward.push_back(t);
    backward.insert(backward.end(), forward.begin(), forward.end());
    ring.tets = std::move(backward);
    return ring;
}

std::vector<TetIdx> vertex_star(const TetMesh3& mesh, VertIdx v) {
    std::vector<TetIdx> star;
    const TetIdx start = mesh.vertex_tet[v];
    if (start == kNone) return star;
    star.push_back(start);
    for (std::size_t i = 0; i < star.size(); ++i) {
        const TetIdx t = star[i];
        const unsigned lv = mesh.slot_of(t, v);
        EM_ASSERT(lv < 4);
        for (unsigned k = 0; k < 4; ++k) {
            if (k == lv) continue;
            const FaceIdx twin = mesh.adj[4 * std::size_t{t} + k];
            if (twin == kNone) continue;
            const TetIdx u = twin / 4;
            if (std::find(star.begin(), star.end(), u) == star.end()) star.push_back(u);
        }
    }
    return star;
}

// ---- Planned flips ----
//
// Each new tetrahedron is accepted only when exact orient3d says it is positively oriented;
// replace_tets then checks combinatorially that the new set has the old one's boundary. Both
// together make each flip a retetrahedralization of the same region (positive tetrahedra with
// matching faces and boundary cover the region once).

namespace {

Sign orient(const TetMesh3& mesh, const Tet& t) {
    return predicates::orient3d(mesh.point(t[0]), mesh.point(t[1]), mesh.point(t[2]),
                                mesh.point(t[3]));
}

bool all_positive(const TetMesh3& mesh, const FlipPlan3& plan) {
    for (unsigned i = 0; i < plan.made_count; ++i) {
        if (orient(mesh, plan.made[i]) != Sign::Positive) return false;
    }
    return true;
}

/// The vertices around the face f (face outward from t1, apexes d in t1 and e in t2).
struct FaceConfig {
    TetIdx t1, t2;
    VertIdx a, b, c, d, e;
};

FaceConfig face_config(const TetMesh3& mesh, FaceIdx f) {
    FaceConfig q{};
    q.t1 = f / 4;
    const FaceIdx g = mesh.adj[f];
    q.t2 = g / 4;
    const auto face = mesh.face(f);
    q.a = face[0];
    q.b = face[1];
    q.c = face[2];
    q.d = mesh.vertex(q.t1, f % 4);
    q.e = mesh.vertex(q.t2, g % 4);
    return q;
}

/// The 3-2 flip of edge (x, y) of the face, z its third vertex, when the ring is the three
/// tetrahedra xyzd, xyze, xyde and both new tetrahedra are positive.
bool plan_32(const TetMesh3& mesh, const FaceConfig& q, VertIdx x, VertIdx y, VertIdx z,
             FlipPlan3& plan) {
    const EdgeRing ring = edge_ring(mesh, q.t1, x, y);
    if (!ring.closed || ring.tets.size() != 3) return false;
    TetIdx third = kNone;
    for (const TetIdx t : ring.tets) {
        if (t != q.t1 && t != q.t2) third = t;
    }
    if (third == kNone || mesh.slot_of(third, q.d) == 4 || mesh.slot_of(third, q.e) == 4)
        return false;
    plan.kind = FlipKind3::Flip32;
    plan.old = {q.t1, q.t2, third, kNone};
    plan.old_count = 3;
    plan.made[0] = {z, q.d, q.e, y};
    plan.made[1] = {z, q.e, q.d, x};
    plan.made_count = 2;
    return all_positive(mesh, plan);
}

/// The 4-4 or 2-2 flip turning edge (x, y) of the face into de (d, e, x, y coplanar).
bool plan_44(const TetMesh3& mesh, const FaceConfig& q, VertIdx x, VertIdx y, VertIdx z,
             FlipPlan3& plan) {
    const EdgeRing ring = edge_ring(mesh, q.t1, x, y);
    plan.made[0] = {y, z, q.e, q.d};
    plan.made[1] = {z, x, q.e, q.d};
    if (!ring.closed) {
        if (ring.tets.size() != 2) return false;
        plan.kind = FlipKind3::Flip22;
        plan.old = {q.t1, q.t2, kNone, kNone};
        plan.old_count = 2;
        plan.made_count = 2;
        return all_positive(mesh, plan);
    }
    if (ring.tets.size() != 4) return false;
    // The far side: the tetrahedron of the ring holding d other than t1, and its face opposite d.
    TetIdx near_d = kNone, near_e = kNone;
    for (const TetIdx t : ring.tets) {
        if (t == q.t1 || t == q.t2) continue;
        if (mesh.slot_of(t, q.d) < 4) near_d = t;
        if (mesh.slot_of(t, q.e) < 4) near_e = t;
    }
    if (near_d == kNone || near_e == kNone || near_d == near_e) return false;
    const unsigned ld = mesh.slot_of(near_d, q.d);
    const auto far = mesh.face(4 * near_d + ld);  // (x, y, w) in some rotation, outward from near_d
    unsigned made = 2;
    for (unsigned s = 0; s < 3; ++s) {
        const VertIdx p = far[s], r = far[(s + 1) % 3];
        if ((p == x && r == y) || (p == y && r == x)) continue;  // the flat one
        plan.made[made++] = {p, r, q.e, q.d};
    }
    if (made != 4) return false;
    plan.kind = FlipKind3::Flip44;
    plan.old = {q.t1, q.t2, near_d, near_e};
    plan.old_count = 4;
    plan.made_count = 4;
    return all_positive(mesh, plan);
}

/// The valid flip at the interior face f, if any (at most one exists for the five points; the
/// order of the tries does not matter).
bool plan_flip(const TetMesh3& mesh, FaceIdx f, FlipPlan3& plan, std::uint64_t* edges_examined) {
    const FaceConfig q = face_config(mesh, f);
    const Tet t23[3] = {{q.a, q.b, q.e, q.d}, {q.b, q.c, q.e, q.d}, {q.c, q.a, q.e, q.d}};
    Sign s[3];
    for (int i = 0; i < 3; ++i) s[i] = orient(mesh, t23[i]);
    if (s[0] == Sign::Positive && s[1] == Sign::Positive && s[2] == Sign::Positive) {
        plan.kind = FlipKind3::Flip23;
        plan.old = {q.t1, q.t2, kNone, kNone};
        plan.old_count = 2;
        plan.made = {t23[0], t23[1], t23[2], Tet{}};
        plan.made_count = 3;
        return true;
    }
    const VertIdx face[3] = {q.a, q.b, q.c};
    int zeros = 0;
    for (int i = 0; i < 3; ++i) zeros += s[i] == Sign::Zero ? 1 : 0;
    for (int i = 0; i < 3; ++i) {
        const VertIdx x = face[i], y = face[(i + 1) % 3], z = face[(i + 2) % 3];
        if (s[i] == Sign::Negative) {
            if (edges_examined != nullptr) ++*edges_examined;
            if (plan_32(mesh, q, x, y, z, plan)) return true;
        } else if (s[i] == Sign::Zero && zeros == 1) {
            if (edges_examined != nullptr) ++*edges_examined;
            if (plan_44(mesh, q, x, y, z, plan)) return true;
        }
    }
    plan.kind = FlipKind3::None;
    return false;
}

}  // namespace

bool plan_flip_3d(const TetMesh3& mesh, FaceIdx f, FlipPlan3& plan, std::uint64_t* edges_examined) {
    if (mesh.is_dead(f / 4) || mesh.adj[f] == kNone) return false;
    return plan_flip(mesh, f, plan, edges_examined);
}

void apply_flip_3d(TetMesh3& mesh, const FlipPlan3& plan, std::vector<TetIdx>& created) {
    const bool ok = replace_tets(mesh, std::span<const TetIdx>(plan.old.data(), plan.old_count),
                                 std::span<const Tet>(plan.made.data(), plan.made_count), &created,
                                 plan.kind == FlipKind3::Flip22);
    if (!ok) throw InternalError("flip_3d: a flip's new tetrahedra do not fit the old boundary");
}

FlipKind3 flip_face_3d(TetMesh3& mesh, FaceIdx f) {
    FlipPlan3 plan;
    if (!plan_flip_3d(mesh, f, plan)) return FlipKind3::None;
    std::vector<TetIdx> created;
    apply_flip_3d(mesh, plan, created);
    return plan.kind;
}

// ---- The star of a point ----

std::uint32_t TetStar3::next_stamp() {
    if (++stamp_counter_ == 0) {  // wrapped: forget every old mark
        std::fill(stamp.begin(), stamp.end(), 0u);
        stamp_counter_ = 1;
    }
    return stamp_counter_;
}

void TetStar3::grow_stamps(const TetMesh3& mesh) {
    if (stamp.size() < mesh.tet_slots()) stamp.resize(mesh.tet_slots() + mesh.tet_slots() / 2, 0u);
}

template <bool kBoundary>
void TetStar3::glue(std::uint64_t key, FaceIdx face) {
    TetMesh3& mesh = *mesh_;
    const std::size_t mask = edge_key_.size() - 1;
    std::size_t h = static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> 40) & mask;
    for (;; h = (h + 1) & mask) {
        if (edge_generation_[h] != generation_) {
            edge_generation_[h] = generation_;
            edge_key_[h] = key;
            edge_face_[h] = face;
            return;
        }
        if (edge_key_[h] == key) {
            if constexpr (kBoundary) {
                // A kept face through p may be the domain's boundary (kNone).
                mesh.link_or_boundary(edge_face_[h], face);
            } else {
                mesh.link(edge_face_[h], face);
            }
            return;
        }
    }
}

void TetStar3::replace_by_star(TetMesh3& mesh, std::span<const TetIdx> region,
                               std::uint32_t region_stamp, VertIdx p) {
    // Two copies: the Delaunay constructions' closed meshes pay no test for kNone twins.
    if (closed) {
        replace_by_star_in<false>(mesh, region, region_stamp, p);
    } else {
        replace_by_star_in<true>(mesh, region, region_stamp, p);
    }
}

template <bool kBoundary>
void TetStar3::replace_by_star_in(TetMesh3& mesh, std::span<const TetIdx> region,
                                  std::uint32_t region_stamp, VertIdx p) {
    mesh_ = &mesh;
    star_faces_.clear();
    p_faces_outside_.clear();
    p_faces_key_.clear();
    for (const TetIdx c : region) {
        const VertIdx* v = &mesh.tv[4 * std::size_t{c}];
        const unsigned p_slot = mesh.slot_of(c, p);
        for (unsigned k = 0; k < 4; ++k) {
            const FaceIdx outside = mesh.adj[4 * std::size_t{c} + k];
            if ((!kBoundary || outside != kNone) && stamp[tet_of(outside)] == region_stamp) {
                continue;
            }
            if (p_slot != 4 && p_slot != k) {
                // A boundary face through p stays; the new tetrahedra glue to it along the
                // edge it has besides p.
                const unsigned* f = kFaceVertex[k];
                VertIdx e[2];
                unsigned count = 0;
                for (unsigned i = 0; i < 3; ++i) {
                    if (f[i] != p_slot) e[count++] = v[f[i]];
                }
                p_faces_outside_.push_back(outside);
                p_faces_key_.push_back(edge_key(e[0], e[1]));
                continue;
            }
            StarFace face{{v[0], v[1], v[2], v[3]}, k, outside};
            face.v[k] = p;
            star_faces_.push_back(face);
        }
    }
    for (const TetIdx c : region) mesh.kill_tet(c);
    // Each edge (a, b) of the star's boundary is met exactly twice: two new faces (p, a, b), or
    // a new face and a kept boundary face through p.
    const std::size_t entries = 3 * star_faces_.size() + p_faces_outside_.size();
    if (edge_key_.size() < 2 * entries) {
        std::size_t size = 64;
        while (size < 2 * entries) size *= 2;
        edge_key_.assign(size, 0);
        edge_face_.assign(size, kNone);
        edge_generation_.assign(size, 0);
        generation_ = 0;
    }
    if (++generation_ == 0) {
        std::fill(edge_generation_.begin(), edge_generation_.end(), 0u);
        generation_ = 1;
    }
    created.clear();
    for (const StarFace& face : star_faces_) {
        const TetIdx t = mesh.new_tet();
        created.push_back(t);
        VertIdx* w = &mesh.tv[4 * std::size_t{t}];
        w[0] = face.v[0];
        w[1] = face.v[1];
        w[2] = face.v[2];
        w[3] = face.v[3];
        if constexpr (kBoundary) {
            mesh.link_or_boundary(4 * t + face.k, face.outside);
        } else {
            mesh.link(4 * t + face.k, face.outside);
        }
        for (unsigned j = 0; j < 4; ++j) {
            if (j == face.k) continue;
            // Face j holds p and the two vertices at the slots other than j and k.
            unsigned a = 0;
            while (a == j || a == face.k) ++a;
            unsigned b = a + 1;
            while (b == j || b == face.k) ++b;
            glue<kBoundary>(edge_key(face.v[a], face.v[b]), 4 * t + j);
        }
    }
    for (std::size_t i = 0; i < p_faces_outside_.size(); ++i) {
        glue<kBoundary>(p_faces_key_[i], p_faces_outside_[i]);
    }
    // Every vertex of the region but p lies on a boundary face without p (the boundary faces
    // around it close a fan, and at most two of them hold the edge to p), so it is a vertex of
    // a new tetrahedron: pointing each vertex of the new ones at them keeps vertex_tet valid.
    if (!mesh.vertex_tet.empty()) {
        mesh.vertex_tet.resize(mesh.vertex_count(), kNone);
        for (const TetIdx t : created) {
            for (unsigned k = 0; k < 4; ++k) {
                const VertIdx v = mesh.vertex(t, k);
                if (v < mesh.vertex_tet.size()) mesh.vertex_tet[v] = t;
            }
        }
    }
    grow_stamps(mesh);
}

void TetStar3::star(TetMesh3& mesh, std::span<const TetIdx> region, VertIdx p) {
    grow_stamps(mesh);
    const std::uint32_t mark = next_stamp();
    for (const TetIdx t : region) stamp[t] = mark;
    replace_by_star(mesh, region, mark, p);
}

void TetStar3::split_1_4(TetMesh3& mesh, TetIdx t, VertIdx p) {
    const TetIdx region[1] = {t};
    star(mesh, region, p);
}

void TetStar3::split_2_6(TetMesh3& mesh, TetIdx t, unsigned k, VertIdx p) {
    const FaceIdx across = mesh.adj[4 * std::size_t{t} + k];
    EM_ASSERT(across != kNone);
    const TetIdx region[2] = {t, tet_of(across)};
    star(mesh, region, p);
}

void TetStar3::split_edge(TetMesh3& mesh, TetIdx t, unsigned a_slot, unsigned b_slot, VertIdx p) {
    unsigned others[2], count = 0;
    for (unsigned k = 0; k < 4; ++k) {
        if (k != a_slot && k != b_slot) others[count++] = k;
    }
    const VertIdx a = mesh.vertex(t, a_slot), b = mesh.vertex(t, b_slot);
    // Around the edge: enter the next tetrahedron (a, b, y, w) through (a, b, y) and leave it
    // through (a, b, w), the face opposite y.
    VertIdx cross_opposite = mesh.vertex(t, others[0]);
    TetIdx current = t;
    ring_.clear();
    for (;;) {
        ring_.push_back(current);
        const FaceIdx g =
            mesh.adj[4 * std::size_t{current} + mesh.slot_of(current, cross_opposite)];
        EM_ASSERT(g != kNone);  // an interior edge: the ring closes
        const TetIdx next = tet_of(g);
        if (next == t) break;
        const VertIdx w = mesh.tv[g];
        for (unsigned k = 0; k < 4; ++k) {
            const VertIdx v = mesh.vertex(next, k);
            if (v != a && v != b && v != w) cross_opposite = v;
        }
        current = next;
    }
    star(mesh, ring_, p);
}

void TetStar3::flip_2_3(TetMesh3& mesh, TetIdx t, unsigned k) {
    const TetIdx region[2] = {t, tet_of(mesh.adj[4 * std::size_t{t} + k])};
    star(mesh, region, mesh.vertex(t, k));
}

void TetStar3::flip_3_2(TetMesh3& mesh, TetIdx t, unsigned k, unsigned j) {
    const TetIdx region[3] = {t, tet_of(mesh.adj[4 * std::size_t{t} + k]),
                              tet_of(mesh.adj[4 * std::size_t{t} + j])};
    star(mesh, region, mesh.vertex(t, k));
}

void TetStar3::flip_4_4(TetMesh3& mesh, TetIdx t, unsigned k, unsigned j) {
    const TetIdx t2 = tet_of(mesh.adj[4 * std::size_t{t} + k]);
    const TetIdx t3 = tet_of(mesh.adj[4 * std::size_t{t} + j]);
    const unsigned j_in_t2 = mesh.slot_of(t2, mesh.vertex(t, j));
    const TetIdx region[4] = {t, t2, t3, tet_of(mesh.adj[4 * std::size_t{t2} + j_in_t2])};
    star(mesh, region, mesh.vertex(t, k));
}

}  // namespace exactmesh::triangulation
