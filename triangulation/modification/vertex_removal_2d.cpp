// SPDX-License-Identifier: MIT
// Vertex removal from a 2D constrained Delaunay triangulation (see vertex_removal_2d.hpp).
//
// The star of v, counter-clockwise, with spokes e_i = v -> x_i (half-edges out of v):
//
//        x_2 ------ x_1                 interior: x_0 .. x_{k-1} close around v
//        /  \      /  \                 boundary: the fan runs from x_0 to x_m, twin(e_0) and
//       /    \    /    \                           twin(x_m -> v) are kNone, and the domain
//     x_3 ---- v ---- x_0                          lies counter-clockwise from x_0 to x_m
//       \    /   \    /
//        \  /     \  /                  straight constraint u = x_a, w = x_b: the hole splits
//        x_4 ----- x_5                  into x_a..x_b and x_b..x_{a+k}, each closed by u - w
//
// Why the result is constrained Delaunay. Let S be v's star, a closed polygon. Every triangle of
// the old mesh outside S keeps its empty circle among the vertices it sees: removing v removes a
// vertex, and replacing u - v - w by u - w changes no visibility outside S (the merged edge lies
// in S: every link vertex strictly on its side, below). So the constrained Delaunay
// triangulation (unique under SoS) of the remaining vertices agrees with the old mesh outside S,
// and inside S is some triangulation of the hole. Any triangulation of the hole followed by
// Lawson flips over its unconstrained edges reaches it: a flip replaces two lifted triangles by
// the two below them (SoS lifts, [EdelsbrunnerMücke90]), so no triangulation recurs, and when no
// unconstrained edge wants a flip every one is locally Delaunay, which by the constrained
// Delaunay lemma [Chew89] is the constrained Delaunay triangulation. The hole is triangulated
// by ear clipping with exact orient2d (an ear is a strictly convex corner whose closed triangle
// holds no other hole vertex; a simple polygon always has one [Meisters75]).
//
// Why the merged edge u - w stays in the star. When every link vertex of the chain on one side
// lies strictly on that side of the line u w (tested, exactly), a ray from v between two such
// vertices meets the line before the star edge joining them (both ends strictly beyond it), so
// u - w crosses every triangle of the star inside it and meets the link only at u and w: each
// side, closed by u - w, is a simple polygon. With u, v, w exactly collinear this always holds.
#include "triangulation/modification/vertex_removal_2d.hpp"

#include <algorithm>
#include <cstddef>
#include <string>
#include <unordered_map>
#include <utility>

#include "base/errors.hpp"
#include "predicates/incircle.hpp"
#include "predicates/orient2d.hpp"
#include "predicates/sos.hpp"
#include "predicates/within_rounding_of_segment.hpp"
#include "triangulation/mesh/flip_2d.hpp"

namespace exactmesh::triangulation {

namespace {

using predicates::Sign;

std::uint64_t edge_key(VertIdx p, VertIdx q) {
    return (std::uint64_t{p} << 32) | q;
}

/// A star as gathered around v, and the plan of its replacement.
struct Star {
    std::vector<EdgeIdx> spokes;  ///< e_i = v -> x_i, counter-clockwise
    std::vector<VertIdx> link;    ///< x_i; one more than spokes on the boundary
    bool boundary = false;
    /// The hole as one or two counter-clockwise polygons, each closed by its last vertex back to
    /// its first; the chord u - w (kNone when none) takes the flags `chord_flags`.
    std::vector<std::vector<VertIdx>> polygons;
    VertIdx chord_u = kNone, chord_w = kNone;
    std::uint8_t chord_flags = 0;
};

/// The removal machinery over the half-edges of one HalfEdgeEdit: an outgoing half-edge and the
/// number of triangles of every vertex, kept through every edit.
class Remover {
  public:
    explicit Remover(TriMesh2& mesh) : mesh_(mesh) {
        const std::uint32_t n = mesh.vertex_count();
        out_edge_.assign(n, kNone);
        triangle_count_.assign(n, 0);
        for (TriIdx t = 0; t < mesh.triangle_slots(); ++t) {
            if (mesh.is_dead(t)) continue;
            for (unsigned k = 0; k < 3; ++k) {
                const VertIdx x = mesh.tv[3 * t + k];
                EM_ASSERT(x < n);
                out_edge_[x] = 3 * t + k;
                ++triangle_count_[x];
            }
        }
    }

    RemovalStatus remove(VertIdx v, VertIdx protected_below, VertexRemoval2Counters& counters) {
        const RemovalStatus status = try_remove(v, protected_below, counters);
        if (status == RemovalStatus::Removed) {
            ++counters.removed;
        } else {
            ++counters.refused;
        }
        return status;
    }

  private:
    TriMesh2& mesh_;
    std::vector<EdgeIdx> out_edge_;
    std::vector<std::uint32_t> triangle_count_;
    Star star_;
    std::vector<EdgeIdx> queue_;

    std::uint8_t flags(EdgeIdx e) const { return mesh_.flags.empty() ? 0 : mesh_.flags[e]; }

    Sign orient(VertIdx a, VertIdx b, VertIdx c, VertexRemoval2Counters& counters) const {
        ++counters.orient_calls;
        return predicates::orient2d(mesh_.point(a), mesh_.point(b), mesh_.point(c));
    }

    /// The fan of triangles around v, counter-clockwise from the boundary spoke if there is one.
    /// False when the fan does not hold every triangle of v (pinched).
    bool gather(VertIdx v) {
        Star& s = star_;
        s.spokes.clear();
        s.link.clear();
        s.polygons.clear();
        s.chord_u = s.chord_w = kNone;
        s.chord_flags = 0;
        s.boundary = false;
        const std::uint32_t count = triangle_count_[v];
        const EdgeIdx start = out_edge_[v];
        EM_ASSERT(start != kNone && mesh_.tv[start] == v);
        // Clockwise to the boundary spoke (twin kNone), if any: cw(v -> x) = next(twin).
        EdgeIdx first = start;
        for (std::uint32_t step = 0; step <= count; ++step) {
            if (mesh_.twin[first] == kNone) {
                s.boundary = true;
                break;
            }
            first = next_edge(mesh_.twin[first]);
            if (first == start) break;
        }
        EdgeIdx e = first;
        for (std::uint32_t step = 0; step <= count; ++step) {
            EM_ASSERT(mesh_.tv[e] == v);
            s.spokes.push_back(e);
            s.link.push_back(mesh_.destination(e));
            const EdgeIdx back = prev_edge(e);  // x_{i+1} -> v
            if (mesh_.twin[back] == kNone) {
                EM_ASSERT(s.boundary);
                s.link.push_back(mesh_.origin(back));
                break;
            }
            e = mesh_.twin[back];
            if (e == first) break;
        }
        return s.spokes.size() == count;
    }

    /// Whether every vertex of `chain` strictly between its ends lies strictly left of p -> q.
    bool strictly_left(const std::vector<VertIdx>& chain, VertIdx p, VertIdx q,
                       VertexRemoval2Counters& counters) const {
        for (std::size_t i = 1; i + 1 < chain.size(); ++i) {
            if (orient(p, q, chain[i], counters) != Sign::Positive) return false;
        }
        return true;
    }

    /// u - v - w straight: collinear exactly, or v within rounding of u - w.
    bool straight(VertIdx u, VertIdx v, VertIdx w, VertexRemoval2Counters& counters) const {
        if (orient(u, v, w, counters) == Sign::Zero) return true;
        return predicates::within_rounding_of_segment(mesh_.point(v), mesh_.point(u),
                                                      mesh_.point(w));
    }

    /// The hole's polygons for the rules of the header; Removed when v can go.
    RemovalStatus plan(VertIdx v, VertexRemoval2Counters& counters) {
        Star& s = star_;
        const std::size_t m = s.spokes.size();
        std::vector<std::size_t> constrained;  // link positions of constrained spokes
        for (std::size_t i = 0; i < m; ++i) {
            if (flags(s.spokes[i]) != 0 && !(s.boundary && i == 0)) constrained.push_back(i);
        }
        if (s.boundary) {
            // The two boundary spokes are the constraints; any other one makes a junction.
            if (!constrained.empty()) return RemovalStatus::ConstraintJunction;
            const std::uint8_t first = flags(s.spokes[0]), last = flags(prev_edge(s.spokes[m - 1]));
            if ((first != 0) != (last != 0)) return RemovalStatus::ConstraintEnd;
            const VertIdx u = s.link.front(), w = s.link.back();
            if (!straight(u, v, w, counters)) return RemovalStatus::Corner;
            // The domain lies left of w -> u once v is gone: every chain vertex strictly there,
            // and v on the line or beyond it (the domain may lose the sliver u, v, w, never gain
            // one: outside the star the sliver may hold other parts of the mesh).
            if (!strictly_left(s.link, w, u, counters)) return RemovalStatus::ChordBlocked;
            if (orient(w, u, v, counters) == Sign::Positive) return RemovalStatus::ChordBlocked;
            s.polygons.push_back(s.link);
            s.chord_u = u;
            s.chord_w = w;
            s.chord_flags = first;
            return RemovalStatus::Removed;
        }
        if (constrained.empty()) {
            s.polygons.push_back(s.link);
            return RemovalStatus::Removed;
        }
        if (constrained.size() == 1) return RemovalStatus::ConstraintEnd;
        if (constrained.size() > 2) return RemovalStatus::ConstraintJunction;
        const std::size_t a = constrained[0], b = constrained[1];
        const VertIdx u = s.link[a], w = s.link[b];
        if (!straight(u, v, w, counters)) return RemovalStatus::ConstraintBend;
        std::vector<VertIdx> left(s.link.begin() + static_cast<std::ptrdiff_t>(a),
                                  s.link.begin() + static_cast<std::ptrdiff_t>(b) + 1);
        std::vector<VertIdx> right;
        for (std::size_t i = b; i <= a + m; ++i) right.push_back(s.link[i % m]);
        // left runs u .. w and closes by w -> u; right runs w .. u and closes by u -> w.
        if (!strictly_left(left, w, u, counters) || !strictly_left(right, u, w, counters))
            return RemovalStatus::ChordBlocked;
        s.polygons.push_back(std::move(left));
        s.polygons.push_back(std::move(right));
        s.chord_u = u;
        s.chord_w = w;
        s.chord_flags = flags(s.spokes[a]);
        return RemovalStatus::Removed;
    }

    /// Ear clipping of a simple counter-clockwise polygon (exact orient2d).
    void clip_ears(std::vector<VertIdx> polygon, std::vector<std::array<VertIdx, 3>>& out,
                   VertexRemoval2Counters& counters) const {
        while (polygon.size() > 3) {
            const std::size_t n = polygon.size();
            bool clipped = false;
            for (std::size_t i = 0; i < n && !clipped; ++i) {
                const VertIdx a = polygon[(i + n - 1) % n], b = polygon[i],
                              c = polygon[(i + 1) % n];
                if (orient(a, b, c, counters) != Sign::Positive) continue;
                bool empty = true;
                for (std::size_t j = 0; j < n && empty; ++j) {
                    const VertIdx x = polygon[j];
                    if (x == a || x == b || x == c) continue;
                    empty = !(orient(a, b, x, counters) != Sign::Negative &&
                              orient(b, c, x, counters) != Sign::Negative &&
                              orient(c, a, x, counters) != Sign::Negative);
                }
                if (!empty) continue;
                out.push_back({a, b, c});
                polygon.erase(polygon.begin() + static_cast<std::ptrdiff_t>(i));
                clipped = true;
            }
            if (!clipped)
                throw InternalError("vertex_removal_2d: no ear in the hole of a removed vertex");
        }
        if (polygon.size() == 3) {
            if (orient(polygon[0], polygon[1], polygon[2], counters) != Sign::Positive)
                throw InternalError("vertex_removal_2d: the hole's last triangle is degenerate");
            out.push_back({polygon[0], polygon[1], polygon[2]});
        }
    }

    void set_out_edges(TriIdx t) {
        for (unsigned k = 0; k < 3; ++k) out_edge_[mesh_.tv[3 * t + k]] = 3 * t + k;
    }

    void push(EdgeIdx e) {
        if (mesh_.twin[e] != kNone && flags(e) == 0) queue_.push_back(e);
    }

    /// Lawson flips from the queued edges, never across a constrained edge [Lawson77].
    void restore_delaunay(VertexRemoval2Counters& counters) {
        while (!queue_.empty()) {
            const EdgeIdx e = queue_.back();
            queue_.pop_back();
            const EdgeIdx f = mesh_.twin[e];
            if (f == kNone || flags(e) != 0) continue;
            const VertIdx a = mesh_.origin(e), b = mesh_.destination(e);
            const VertIdx c = mesh_.tv[prev_edge(e)], d = mesh_.tv[prev_edge(f)];
            ++counters.incircle_tests;
            if (predicates::incircle_sos(mesh_.point(a), mesh_.point(b), mesh_.point(c),
                                         mesh_.point(d), a, b, c, d) != Sign::Positive)
                continue;
            // A non-locally-Delaunay edge has a strictly convex quadrilateral (d strictly inside
            // the lifted circle of a, b, c and across a - b); checked, as edge_swap_2d does.
            if (orient(c, a, d, counters) != Sign::Positive ||
                orient(d, b, c, counters) != Sign::Positive)
                continue;
            const FlipEdges flipped = flip_2d(mesh_, e, 0, 0);
            ++counters.delaunay_flips;
            --triangle_count_[a];
            --triangle_count_[b];
            ++triangle_count_[c];
            ++triangle_count_[d];
            set_out_edges(triangle_of(e));
            set_out_edges(triangle_of(f));
            for (const EdgeIdx side : flipped.sides) push(side);
        }
    }

    /// Replaces the star by the triangles of its hole's polygons and restores the Delaunay
    /// property inside.
    void replace(VertIdx v, VertexRemoval2Counters& counters) {
        Star& s = star_;
        const std::size_t m = s.spokes.size();
        std::vector<std::array<VertIdx, 3>> made;
        for (const auto& polygon : s.polygons) clip_ears(polygon, made, counters);
        // Nothing is changed before this point: a refusal or an InternalError leaves the mesh.
        struct Outer {
            EdgeIdx twin;
            std::uint8_t flags;
            bool used;
        };
        std::unordered_map<std::uint64_t, Outer> outer;
        std::vector<TriIdx> slots;
        for (std::size_t i = 0; i < m; ++i) {
            const EdgeIdx side = next_edge(s.spokes[i]);  // x_i -> x_{i+1}
            outer[edge_key(mesh_.origin(side), mesh_.destination(side))] = {mesh_.twin[side],
                                                                            flags(side), false};
            const TriIdx t = triangle_of(side);
            for (unsigned k = 0; k < 3; ++k) --triangle_count_[mesh_.tv[3 * t + k]];
            slots.push_back(t);
        }
        EM_ASSERT(made.size() < m || (made.empty() && m == 0));
        for (std::size_t i = made.size(); i < m; ++i) mesh_.kill_triangle(slots[i]);
        out_edge_[v] = kNone;
        const bool flagged = !mesh_.flags.empty();
        auto is_chord = [&](VertIdx p, VertIdx q) {
            return s.chord_u != kNone &&
                   ((p == s.chord_u && q == s.chord_w) || (p == s.chord_w && q == s.chord_u));
        };
        std::unordered_map<std::uint64_t, EdgeIdx> open;
        for (std::size_t i = 0; i < made.size(); ++i) {
            const TriIdx t = slots[i];
            for (unsigned k = 0; k < 3; ++k) {
                mesh_.tv[3 * t + k] = made[i][k];
                ++triangle_count_[made[i][k]];
            }
            set_out_edges(t);
            for (unsigned k = 0; k < 3; ++k) {
                const VertIdx p = made[i][k], q = made[i][(k + 1) % 3];
                const EdgeIdx e = 3 * t + k;
                if (flagged) mesh_.flags[e] = 0;
                const auto o = outer.find(edge_key(p, q));
                if (o != outer.end()) {
                    mesh_.twin[e] = o->second.twin;
                    if (o->second.twin != kNone) mesh_.twin[o->second.twin] = e;
                    if (flagged) mesh_.flags[e] = o->second.flags;
                    o->second.used = true;
                    continue;
                }
                const auto w = open.find(edge_key(q, p));
                if (w != open.end()) {
                    mesh_.link(e, w->second);
                    open.erase(w);
                } else {
                    open.emplace(edge_key(p, q), e);
                    mesh_.twin[e] = kNone;
                }
            }
        }
        // Left open: only the chord on the boundary. Outer sides no new triangle took: only the
        // chord, when its side of the hole is empty (u - w was already the edge of one star
        // triangle); the triangle across it then faces the boundary, or the other side's chord.
        for (const auto& [key, e] : open) {
            EM_ASSERT(is_chord(mesh_.origin(e), mesh_.destination(e)) && s.boundary);
        }
        for (auto& [key, o] : outer) {
            if (o.used) continue;
            EM_ASSERT(is_chord(static_cast<VertIdx>(key >> 32), static_cast<VertIdx>(key)));
            if (o.twin == kNone) continue;
            const VertIdx p = mesh_.origin(o.twin), q = mesh_.destination(o.twin);
            const auto w = open.find(edge_key(q, p));
            if (w != open.end()) {
                mesh_.link(o.twin, w->second);
            } else {
                mesh_.twin[o.twin] = kNone;
            }
        }
        // The chord's halves take the merged constraint's flags.
        if (flagged && s.chord_u != kNone) {
            for (std::size_t i = 0; i < made.size(); ++i) {
                for (unsigned k = 0; k < 3; ++k) {
                    const EdgeIdx e = 3 * slots[i] + k;
                    if (!is_chord(mesh_.origin(e), mesh_.destination(e))) continue;
                    mesh_.flags[e] = s.chord_flags;
                    if (mesh_.twin[e] != kNone) mesh_.flags[mesh_.twin[e]] = s.chord_flags;
                }
            }
            for (auto& [key, o] : outer) {
                if (!o.used && o.twin != kNone) mesh_.flags[o.twin] = s.chord_flags;
            }
        }
        EM_ASSERT(triangle_count_[v] == 0);
        queue_.clear();
        for (std::size_t i = 0; i < made.size(); ++i) {
            for (unsigned k = 0; k < 3; ++k) push(3 * slots[i] + k);
        }
        restore_delaunay(counters);
    }

    RemovalStatus try_remove(VertIdx v, VertIdx protected_below, VertexRemoval2Counters& counters) {
        if (v >= mesh_.vertex_count()) return RemovalStatus::OutOfRange;
        if (v < protected_below) return RemovalStatus::Protected;
        if (triangle_count_[v] == 0) return RemovalStatus::Unused;
        if (!gather(v)) return RemovalStatus::NonManifold;
        const RemovalStatus status = plan(v, counters);
        if (status != RemovalStatus::Removed) return status;
        const std::size_t m = star_.spokes.size();
        if (star_.chord_u != kNone)
            ++(star_.boundary ? counters.boundary_merges : counters.segment_merges);
        counters.star_triangles += m;
        replace(v, counters);
        return RemovalStatus::Removed;
    }
};

/// Drops dead triangle slots (tv == kNone) left by the edit, renumbering neighbors.
void compact_triangles(Triangulation2& mesh) {
    const std::size_t slots = mesh.triangles.size() / 3;
    std::vector<TriIdx> new_index(slots, kNone);
    TriIdx live = 0;
    for (std::size_t t = 0; t < slots; ++t) {
        if (mesh.triangles[3 * t] != kNone) new_index[t] = live++;
    }
    if (live == slots) return;
    const bool flagged = !mesh.constrained.empty();
    for (std::size_t t = 0; t < slots; ++t) {
        const TriIdx to = new_index[t];
        if (to == kNone) continue;
        for (unsigned k = 0; k < 3; ++k) {
            const std::size_t from = 3 * t + k, into = 3 * std::size_t{to} + k;
            mesh.triangles[into] = mesh.triangles[from];
            const TriIdx w = mesh.neighbors[from];
            mesh.neighbors[into] = w == kNone ? kNone : new_index[w];
            if (flagged) mesh.constrained[into] = mesh.constrained[from];
        }
    }
    mesh.triangles.resize(3 * std::size_t{live});
    mesh.neighbors.resize(3 * std::size_t{live});
    if (flagged) mesh.constrained.resize(3 * std::size_t{live});
}

}  // namespace

const char* removal_status_name(RemovalStatus status) {
    switch (status) {
        case RemovalStatus::Removed:
            return "removed";
        case RemovalStatus::OutOfRange:
            return "out of range";
        case RemovalStatus::Unused:
            return "a vertex of no triangle";
        case RemovalStatus::Protected:
            return "protected (an input vertex)";
        case RemovalStatus::Corner:
            return "a corner of the domain boundary";
        case RemovalStatus::ConstraintEnd:
            return "the end of a constraint";
        case RemovalStatus::ConstraintJunction:
            return "a junction of three or more constraints";
        case RemovalStatus::ConstraintBend:
            return "a bend of a constraint";
        case RemovalStatus::ChordBlocked:
            return "the merged constraint would cross or touch another vertex of its star";
        case RemovalStatus::NonManifold:
            return "a pinch of the domain (more than one fan)";
    }
    return "unknown";
}

RemovalStatus remove_vertex_2d(Triangulation2& mesh, VertIdx v, VertexRemoval2Counters* counters) {
    VertexRemoval2Counters local;
    RemovalStatus status;
    {
        HalfEdgeEdit edit(mesh);
        Remover remover(edit.mesh());
        status = remover.remove(v, 0, counters != nullptr ? *counters : local);
    }
    compact_triangles(mesh);
    return status;
}

VertexRemoval2Result remove_vertices_2d(Triangulation2& mesh, std::span<const VertIdx> vertices,
                                        VertIdx protected_below, VertexRemoval2Counters* counters) {
    VertexRemoval2Counters local;
    VertexRemoval2Counters& sums = counters != nullptr ? *counters : local;
    VertexRemoval2Result result;
    result.status.reserve(vertices.size());
    const std::uint32_t n = mesh.vertex_count();
    std::vector<std::uint8_t> removed(n, 0);
    try {
        HalfEdgeEdit edit(mesh);
        Remover remover(edit.mesh());
        for (const VertIdx v : vertices) {
            const RemovalStatus status = remover.remove(v, protected_below, sums);
            result.status.push_back(status);
            if (status == RemovalStatus::Removed) {
                removed[v] = 1;
                ++result.removed;
            }
        }
    } catch (...) {
        // The edit has written the mesh back: the removals made so far stay, without the dead
        // triangle slots they left; the vertex numbering is not compacted.
        compact_triangles(mesh);
        throw;
    }
    compact_triangles(mesh);
    result.old_to_new.assign(n, kNone);
    VertIdx next = 0;
    for (VertIdx v = 0; v < n; ++v) {
        if (removed[v] != 0) continue;
        result.old_to_new[v] = next;
        mesh.xy[2 * std::size_t{next}] = mesh.xy[2 * std::size_t{v}];
        mesh.xy[2 * std::size_t{next} + 1] = mesh.xy[2 * std::size_t{v} + 1];
        ++next;
    }
    mesh.xy.resize(2 * std::size_t{next});
    for (VertIdx& x : mesh.triangles) x = result.old_to_new[x];
    return result;
}

}  // namespace exactmesh::triangulation
