// SPDX-License-Identifier: MIT
// FlipMesh3 construction, compaction and the one local rewrite every 3D flip goes through
// (see flip_mesh_3d.hpp).
#include "triangulation/flip_mesh_3d.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "predicates/errors.hpp"
#include "predicates/orient3d.hpp"

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

OrientedFace reversed(const OrientedFace& f) { return {f[0], f[2], f[1]}; }

OrientedFace outward_face(const Tet& t, unsigned k) {
    const auto& lf = kOutwardFace[k];
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
            throw NonFiniteCoordinate("vertex " + std::to_string(i / 3 + first_vertex) +
                                          " has a non-finite coordinate",
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
        const Sign s = predicates::orient3d(&xyz[3 * std::size_t{v[0]}], &xyz[3 * std::size_t{v[1]}],
                                            &xyz[3 * std::size_t{v[2]}], &xyz[3 * std::size_t{v[3]}]);
        if (s != Sign::Positive) {
            throw InputError(tet_text(t, v, numbering) +
                             (s == Sign::Zero ? " is flat (its vertices are coplanar)"
                                              : " is negatively oriented"));
        }
    }
}

/// adj from the vertex lists: facets sorted by their face's vertex set.
std::vector<FacetIdx> link_facets(const std::vector<VertIdx>& tets, std::uint32_t first_vertex,
                                  std::uint32_t first_tet) {
    struct Entry {
        std::array<VertIdx, 3> key;
        FacetIdx facet;
    };
    std::vector<Entry> entries;
    entries.reserve(tets.size());
    for (std::size_t f = 0; f < tets.size(); ++f) {
        const std::size_t t = f / 4;
        const auto& lf = kOutwardFace[f % 4];
        std::array<VertIdx, 3> key{tets[4 * t + lf[0]], tets[4 * t + lf[1]], tets[4 * t + lf[2]]};
        std::sort(key.begin(), key.end());
        entries.push_back({key, static_cast<FacetIdx>(f)});
    }
    std::sort(entries.begin(), entries.end(), [](const Entry& x, const Entry& y) {
        return x.key != y.key ? x.key < y.key : x.facet < y.facet;
    });
    std::vector<FacetIdx> adj(tets.size(), kNone);
    for (std::size_t i = 0; i < entries.size();) {
        std::size_t j = i + 1;
        while (j < entries.size() && entries[j].key == entries[i].key) ++j;
        if (j - i > 2) {
            const auto& k = entries[i].key;
            throw InputError("face (" + std::to_string(std::uint64_t{k[0]} + first_vertex) + ", " +
                             std::to_string(std::uint64_t{k[1]} + first_vertex) + ", " +
                             std::to_string(std::uint64_t{k[2]} + first_vertex) + ") is shared by " +
                             std::to_string(j - i) + " tetrahedra (" +
                             std::to_string(entries[i].facet / 4 + first_tet) + ", " +
                             std::to_string(entries[i + 1].facet / 4 + first_tet) + ", " +
                             std::to_string(entries[i + 2].facet / 4 + first_tet) +
                             "): overlapping tetrahedra");
        }
        if (j - i == 2) {
            adj[entries[i].facet] = entries[i + 1].facet;
            adj[entries[i + 1].facet] = entries[i].facet;
        }
        i = j;
    }
    return adj;
}

}  // namespace

void link_neighbors_3d(Tetrahedralization3& mesh, const Check3Numbering& numbering) {
    validate_tets(mesh.xyz, mesh.tets, numbering);
    const std::vector<FacetIdx> adj =
        link_facets(mesh.tets, numbering.first_vertex, numbering.first_tet);
    mesh.neighbors.assign(mesh.tets.size(), kNone);
    for (std::size_t f = 0; f < adj.size(); ++f) {
        if (adj[f] != kNone) mesh.neighbors[f] = adj[f] / 4;
    }
}

FlipMesh3 make_flip_mesh_3d(const Tetrahedralization3& mesh) {
    validate_tets(mesh.xyz, mesh.tets, Check3Numbering{});
    FlipMesh3 out;
    out.xyz = mesh.xyz;
    out.tets = mesh.tets;
    if (mesh.neighbors.empty()) {
        out.adj = link_facets(mesh.tets, 0, 0);
    } else {
        if (mesh.neighbors.size() != mesh.tets.size()) {
            throw InputError("neighbor array: " + std::to_string(mesh.neighbors.size()) +
                             " entries for " + std::to_string(mesh.tets.size() / 4) + " tetrahedra");
        }
        const std::size_t count = mesh.tets.size() / 4;
        out.adj.assign(mesh.tets.size(), kNone);
        for (std::size_t f = 0; f < mesh.tets.size(); ++f) {
            const TetIdx u = mesh.neighbors[f];
            if (u == kNone) continue;
            const std::size_t t = f / 4;
            if (u >= count || u == t) {
                throw InputError("tetrahedron " + std::to_string(t) + ": neighbor " +
                                 std::to_string(u) + " across face " + std::to_string(f % 4) +
                                 " is not another tetrahedron");
            }
            const OrientedFace mine = outward_face(out.tet(static_cast<TetIdx>(t)), f % 4);
            bool found = false;
            for (unsigned j = 0; j < 4 && !found; ++j) {
                if (mesh.neighbors[4 * std::size_t{u} + j] == t &&
                    outward_face(out.tet(u), j) == reversed(mine)) {
                    out.adj[f] = 4 * u + j;
                    found = true;
                }
            }
            if (!found) {
                throw InputError("tetrahedron " + std::to_string(t) + ": neighbor " +
                                 std::to_string(u) + " across face " + std::to_string(f % 4) +
                                 " does not share that face back (inconsistent neighbors)");
            }
        }
        // Faces shared without a neighbor link would make two boundary faces coincide.
        const std::vector<FacetIdx> linked = link_facets(mesh.tets, 0, 0);
        for (std::size_t f = 0; f < linked.size(); ++f) {
            if (linked[f] != out.adj[f]) {
                throw InputError("tetrahedron " + std::to_string(f / 4) + ": face " +
                                 std::to_string(f % 4) +
                                 " is shared with another tetrahedron but the neighbors say otherwise");
            }
        }
    }
    out.vertex_tet.assign(out.vertex_count(), kNone);
    for (std::size_t i = 0; i < out.tets.size(); ++i) out.vertex_tet[out.tets[i]] = static_cast<TetIdx>(i / 4);
    return out;
}

Tetrahedralization3 to_tetrahedralization_3d(const FlipMesh3& mesh) {
    Tetrahedralization3 out;
    out.xyz = mesh.xyz;
    std::vector<TetIdx> index(mesh.slot_count(), kNone);
    TetIdx next = 0;
    for (TetIdx t = 0; t < mesh.slot_count(); ++t) {
        if (!mesh.is_dead(t)) index[t] = next++;
    }
    out.tets.reserve(4 * std::size_t{next});
    out.neighbors.reserve(4 * std::size_t{next});
    for (TetIdx t = 0; t < mesh.slot_count(); ++t) {
        if (mesh.is_dead(t)) continue;
        for (unsigned k = 0; k < 4; ++k) {
            out.tets.push_back(mesh.vertex(t, k));
            const FacetIdx twin = mesh.adj[4 * std::size_t{t} + k];
            out.neighbors.push_back(twin == kNone ? kNone : index[twin / 4]);
        }
    }
    return out;
}

bool replace_tets(FlipMesh3& mesh, std::span<const TetIdx> old_tets, std::span<const Tet> new_tets,
                  std::vector<TetIdx>* created, bool retriangulate_domain_boundary) {
    auto in_old = [&](TetIdx t) {
        return std::find(old_tets.begin(), old_tets.end(), t) != old_tets.end();
    };
    struct Boundary {
        OrientedFace face;  ///< outward from the old region
        FacetIdx twin;      ///< the facet outside, or kNone
        bool used;
    };
    std::vector<Boundary> boundary;
    boundary.reserve(2 * old_tets.size() + 4);
    for (const TetIdx t : old_tets) {
        EM_ASSERT(!mesh.is_dead(t));
        for (unsigned k = 0; k < 4; ++k) {
            const FacetIdx twin = mesh.adj[4 * std::size_t{t} + k];
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
        if (i < old_tets.size()) {
            slots.push_back(old_tets[i]);
        } else if (!mesh.free_tets.empty()) {
            slots.push_back(mesh.free_tets.back());
            mesh.free_tets.pop_back();
        } else {
            slots.push_back(mesh.slot_count());
            mesh.tets.resize(mesh.tets.size() + 4, kNone);
            mesh.adj.resize(mesh.adj.size() + 4, kNone);
        }
    }
    // Vertices that may lose their last tetrahedron (the removed vertex of a 4-1 flip).
    std::vector<VertIdx> old_vertices;
    for (const TetIdx t : old_tets) {
        for (unsigned k = 0; k < 4; ++k) old_vertices.push_back(mesh.vertex(t, k));
    }
    for (std::size_t i = new_tets.size(); i < old_tets.size(); ++i) {
        const std::size_t s = 4 * std::size_t{old_tets[i]};
        for (unsigned k = 0; k < 4; ++k) {
            mesh.tets[s + k] = kNone;
            mesh.adj[s + k] = kNone;
        }
        mesh.free_tets.push_back(old_tets[i]);
    }
    for (std::size_t i = 0; i < new_tets.size(); ++i) {
        const std::size_t s = 4 * std::size_t{slots[i]};
        for (unsigned k = 0; k < 4; ++k) mesh.tets[s + k] = new_tets[i][k];
    }
    for (VertIdx v : old_vertices) mesh.vertex_tet[v] = kNone;
    for (std::size_t i = 0; i < new_tets.size(); ++i) {
        for (unsigned k = 0; k < 4; ++k) mesh.vertex_tet[new_tets[i][k]] = slots[i];
    }
    for (std::size_t f = 0; f < facets; ++f) {
        const FacetIdx mine = 4 * slots[f / 4] + static_cast<FacetIdx>(f % 4);
        if ((match[f] & kBoundaryFlag) != 0) {
            const std::uint32_t b = match[f] & ~kBoundaryFlag;
            const FacetIdx twin = b == kDomainBoundary ? kNone : boundary[b].twin;
            mesh.adj[mine] = twin;
            if (twin != kNone) mesh.adj[twin] = mine;
        } else {
            mesh.adj[mine] = 4 * slots[match[f] / 4] + match[f] % 4;
        }
    }
    if (created != nullptr) *created = std::move(slots);
    return true;
}

EdgeRing edge_ring(const FlipMesh3& mesh, TetIdx t, VertIdx a, VertIdx b) {
    EdgeRing ring;
    const unsigned la = mesh.local_index(t, a), lb = mesh.local_index(t, b);
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
            const unsigned k = mesh.local_index(current, opposite);
            const FacetIdx twin = mesh.adj[4 * std::size_t{current} + k];
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
            EM_ASSERT(shared != kNone && out.size() <= mesh.slot_count());
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

std::vector<TetIdx> vertex_star(const FlipMesh3& mesh, VertIdx v) {
    std::vector<TetIdx> star;
    const TetIdx start = mesh.vertex_tet[v];
    if (start == kNone) return star;
    star.push_back(start);
    for (std::size_t i = 0; i < star.size(); ++i) {
        const TetIdx t = star[i];
        const unsigned lv = mesh.local_index(t, v);
        EM_ASSERT(lv < 4);
        for (unsigned k = 0; k < 4; ++k) {
            if (k == lv) continue;
            const FacetIdx twin = mesh.adj[4 * std::size_t{t} + k];
            if (twin == kNone) continue;
            const TetIdx u = twin / 4;
            if (std::find(star.begin(), star.end(), u) == star.end()) star.push_back(u);
        }
    }
    return star;
}

}  // namespace exactmesh::triangulation
