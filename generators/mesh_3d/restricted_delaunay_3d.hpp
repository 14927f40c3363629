// SPDX-License-Identifier: MIT
// Internal to generators/mesh_3d: incremental Bowyer-Watson insertion restricted to a PLC's
// domain [Shewchuk98 §3; Si15 §3], shared by delaunay_refinement_3d and frontal_delaunay_3d.
// The cavity of a point grows through faces whose far tetrahedron has it strictly inside its
// circumsphere (exact insphere), never across a subface other than the ones being split; it
// is then shrunk until star-shaped from the point (exact orient3d on every kept boundary face)
// and until it keeps every subface, subsegment and vertex outside the split ones; an insertion
// whose seed would have to go is rejected (counted). Subsegments split at midpoints or
// concentric-shell points, subfaces at circumcentres with Bowyer-Watson facet cavities; the
// subsegments and subfaces a new tetrahedron's vertices encroach are queued (when enabled).
// Invariants: every subface stays a face, every subsegment an edge, every tetrahedron positive.
// Decisions: orient3d, insphere, orient2d on facet projections, dot_sign_3d,
// in_equatorial_sphere_3d. Constructions: triangle_circumcenter_3d, point_on_segment_3d.
// Not part of the installed API: the class is the generators' common machinery.
#pragma once

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <cstdint>
#include <deque>
#include <optional>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include "base/errors.hpp"
#include "generators/mesh_3d/delaunay_refinement_3d.hpp"
#include "generators/mesh_3d/edge_key_maps.hpp"
#include "generators/mesh_3d/small_angle_rule_3d.hpp"
#include "predicates/constructions.hpp"
#include "predicates/dot_sign_3d.hpp"
#include "predicates/insphere.hpp"
#include "predicates/orient3d.hpp"
#include "predicates/tet_quality_3d.hpp"
#include "predicates/within_rounding_of_segment.hpp"
#include "triangulation/mesh/facet_projection_3d.hpp"
#include "triangulation/mesh/mesh3.hpp"
#include "triangulation/mesh/plc_3d.hpp"
#include "triangulation/mesh/vertex_keys_3d.hpp"
#include "triangulation/recovery_3d/boundary_recovery_3d.hpp"
#include "triangulation/recovery_3d/plc_3d.hpp"

namespace exactmesh::generators::restricted_3d {

using predicates::Sign;
using triangulation::ConformingMesh3;
using triangulation::edge_key;
using triangulation::FaceIdx;
using triangulation::Key3;
using triangulation::Key3Hash;
using triangulation::kFaceVertex;
using triangulation::kNone;
using triangulation::Plc3;
using triangulation::sorted3;
using triangulation::TetIdx;
using triangulation::TetMesh3;
using triangulation::VertexFeature3;
using triangulation::VertIdx;

inline constexpr unsigned kEdges[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};

/// The Steiner point budget of the 3D generators: `requested` when given (not 0), else 10^6
/// plus 1,000 per input vertex. It does not grow with a size's own estimate: a size or volume
/// bound that asks for more is refused at once (with its estimate) instead of filling memory.
inline std::uint64_t steiner_budget_3d(const ConformingMesh3& recovered, std::uint64_t requested) {
    return requested != 0 ? requested
                          : 1000 * std::uint64_t{recovered.input_vertex_count} + 1000000;
}

inline bool same_point(const double* p, const double* q) {
    return p[0] == q[0] && p[1] == q[1] && p[2] == q[2];
}

/// A subface: its corners in the facet's orientation, and its facet.
struct Subface {
    Key3 oriented;
    std::uint32_t facet;
};

/// The mesh being refined, its subfaces and subsegments, and point insertion restricted to
/// the domain. Generators derive from it and receive each new tetrahedron in on_created().
class RestrictedDelaunay3 {
  public:
    /// `recovered` passes check_boundary_conformity_3d for `plc`; `budget`: most insertions
    /// before InputError; `name`: the generator named in error messages.
    RestrictedDelaunay3(const Plc3& plc, ConformingMesh3 recovered, std::uint64_t budget,
                        std::string name)
        : out_(std::move(recovered)), budget_(budget), name_(std::move(name)) {
        const std::uint32_t n = out_.mesh.vertex_count();
        // The working mesh, with twin face slots.
        m_.xyz = std::move(out_.mesh.xyz);
        const TetIdx count = out_.mesh.tet_count();
        m_.tv = out_.mesh.tets;
        m_.adj.assign(m_.tv.size(), kNone);
        for (TetIdx t = 0; t < count; ++t) {
            for (unsigned k = 0; k < 4; ++k) {
                const TetIdx u = out_.mesh.neighbors[4 * std::size_t{t} + k];
                if (u == kNone) continue;
                for (unsigned j = 0; j < 4; ++j) {
                    if (out_.mesh.neighbors[4 * std::size_t{u} + j] == t) {
                        m_.adj[4 * t + k] = 4 * u + j;
                        break;
                    }
                }
                EM_ASSERT(m_.adj[4 * t + k] != kNone);
            }
        }
        attributes_ = std::move(out_.tet_attributes);
        max_volumes_ = std::move(out_.tet_max_volume);
        vertex_tet_.assign(n, kNone);
        for (TetIdx t = 0; t < count; ++t)
            for (unsigned k = 0; k < 4; ++k) vertex_tet_[m_.vertex(t, k)] = t;
        find_non_manifold_vertices();
        for (std::size_t i = 0; i < out_.subsegments.size(); i += 2) {
            subsegments_.emplace(edge_key(out_.subsegments[i], out_.subsegments[i + 1]),
                                 out_.subsegment_segment[i / 2]);
        }
        for (std::size_t i = 0; i < out_.subfaces.size(); i += 3) {
            add_subface({{out_.subfaces[i], out_.subfaces[i + 1], out_.subfaces[i + 2]},
                         out_.subface_facet[i / 3]});
        }
        sharp_ = SharpFacets3(out_, m_.xyz);
        small_angles_.emplace(out_, m_.xyz, sharp_);
        planes_.reserve(plc.facets.size());
        for (const auto& facet : plc.facets)
            planes_.push_back(triangulation::facet_plane(plc, facet));
        // Each facet's largest input triangle: the plane its Steiner points must lie on within
        // rounding (its first corners may be within rounding of collinear).
        facet_triangle_ = triangulation::facet_largest_triangles_3d(
            plc, triangulation::triangulate_facets_3d(plc));
        vertex_segments_.resize(out_.input_vertex_count);
        for (std::uint32_t s = 0; 2 * s + 1 < out_.segments.size(); ++s) {
            vertex_segments_[out_.segments[2 * s]].push_back(s);
            vertex_segments_[out_.segments[2 * s + 1]].push_back(s);
        }
        parameter_.assign(n, 0.0);
        for (VertIdx v = out_.input_vertex_count; v < n; ++v) {
            if (out_.vertex_feature[v] == VertexFeature3::Segment)
                parameter_[v] = segment_parameter(v, out_.feature_index[v]);
        }
        // The working copies above replace these until finish() rebuilds them.
        out_.mesh = {};
        out_.subsegments = {};
        out_.subsegment_segment = {};
        out_.subfaces = {};
        out_.subface_facet = {};
    }

    DelaunayRefinement3Result run();

    virtual ~RestrictedDelaunay3() = default;
    RestrictedDelaunay3(const RestrictedDelaunay3&) = delete;
    RestrictedDelaunay3& operator=(const RestrictedDelaunay3&) = delete;

  protected:
    ConformingMesh3 out_;  ///< features and segments; the mesh itself lives in m_
    TetMesh3 m_;
    mutable std::array<std::vector<std::uint32_t>, 3> walk_mark_;  ///< StarWalk marks per walk
    mutable std::uint32_t walk_epoch_ = 0;
    std::uint64_t budget_ = 0;
    std::string name_;
    DelaunayRefinement3Counters counters_;

    std::vector<double> attributes_;
    /// Per tetrahedron slot, its region's volume bound (<= 0: none); empty when no region has
    /// one. Carried through cavities like attributes_.
    std::vector<double> max_volumes_;
    std::vector<TetIdx> vertex_tet_;
    /// Vertices whose star falls in several pieces (the domain touches itself there: two boxes
    /// sharing only an edge or a corner): a live tetrahedron of each piece but vertex_tet_'s.
    /// A walk by adjacency from one tetrahedron meets only its own piece.
    std::unordered_map<VertIdx, std::vector<TetIdx>> other_pieces_;
    std::vector<double> parameter_;
    KeyMap64<std::uint32_t> subsegments_;
    Key3Map<Subface> subfaces_;
    EdgeSubfaces edge_subfaces_;
    std::vector<triangulation::FacetPlane> planes_;
    std::vector<std::array<VertIdx, 3>> facet_triangle_;  ///< per facet, its largest input triangle

    /// Whether p lies off facet f's plane beyond rounding (beyond_rounding_of_plane with the
    /// facet's largest input triangle).
    bool off_facet_plane(const double* p, std::uint32_t f) const {
        const auto& t = facet_triangle_[f];
        if (t[0] == kNone) return false;
        // 2^-46 of the coordinates, not the exact check's 2^-40: that check measures against
        // the input triangle holding the point, whose corners may be smaller than the largest
        // triangle's (a turned cube's face: a subface circumcentre 9.3e-13 off the plane passed
        // here, 2^-40 of 1.31, and failed there, 2^-40 of 0.91: `tetmesh` stopped with an
        // internal error). A rounded point of the plane is within 2^-52 of its coordinates.
        return triangulation::beyond_rounding_of_plane(p, point(t[0]), point(t[1]), point(t[2]),
                                                       46);
    }

    /// The point of facet f's plane (through its largest input triangle) equidistant from
    /// subface `face`'s corners, correctly rounded from the corners and the facet's vertices
    /// (predicates::triangle_circumcenter_on_plane_3d). nullopt when no such point exists (the
    /// subface's projection onto the plane is flat).
    std::optional<std::array<double, 3>> circumcentre_on_facet_plane(const Subface& face) const {
        const auto& t = facet_triangle_[face.facet];
        if (t[0] == kNone) return std::nullopt;
        try {
            return predicates::triangle_circumcenter_on_plane_3d(
                point(face.oriented[0]), point(face.oriented[1]), point(face.oriented[2]),
                point(t[0]), point(t[1]), point(t[2]));
        } catch (const GeometryError&) {
            return std::nullopt;
        }
    }
    std::vector<std::vector<std::uint32_t>> vertex_segments_;
    /// Facets meeting at a segment at below 60 degrees: their encroachment of each other (and of
    /// the segment between them) splits nothing, since each split would encroach the other.
    SharpFacets3 sharp_;
    /// The small-input-angle rule on this mesh (its sharp facets sharp_): refinement's sparing
    /// (SmallInputAngleRule3::spares) and, below, segments meeting at an input vertex at below
    /// 30 degrees: a point on one does not split
    /// the other's subsegments by encroachment (SmallInputAngleRule3::narrow_angle_pair; a
    /// needle's two long edges 5e-10 radians apart ran 10^6 subsegment splits into the Steiner
    /// budget, 130 s); refinement spares the tetrahedra between them.
    std::optional<SmallInputAngleRule3> small_angles_;

    std::deque<std::uint64_t> segment_queue_;
    std::deque<Key3> subface_queue_;
    /// Whether new tetrahedra queue the subfaces and subsegments their vertices encroach.
    bool queue_encroachment_ = true;

    // Cavity scratch.
    /// Per tet slot, build_cavity's marks side by side (one cache line per tetrahedron met, not
    /// one per array): `attempt` == attempt_ while in the cavity of the current attempt,
    /// `excluded` == cavity_stamp_ when shrunk away, `sphere` == cavity_stamp_ when `inside`
    /// holds insphere(tetrahedron, p) > 0 for the current point.
    struct CavityMarks {
        std::uint32_t attempt = 0;
        std::uint32_t excluded = 0;
        std::uint32_t sphere = 0;
        std::uint32_t inside = 0;
    };
    std::vector<CavityMarks> marks_;
    std::uint32_t cavity_stamp_ = 0;
    std::vector<TetIdx> cavity_;

    const double* point(VertIdx v) const { return m_.point(v); }

    // --- subface bookkeeping -------------------------------------------------------------

    void add_subface(const Subface& s) {
        const Key3 key = sorted3(s.oriented[0], s.oriented[1], s.oriented[2]);
        subfaces_.emplace(key, s);
        for (unsigned i = 0; i < 3; ++i)
            edge_subfaces_.add(edge_key(key[i], key[(i + 1) % 3]), key[(i + 2) % 3]);
    }

    void remove_subface(const Key3& key) {
        subfaces_.erase(key);
        for (unsigned i = 0; i < 3; ++i)
            edge_subfaces_.remove(edge_key(key[i], key[(i + 1) % 3]), key[(i + 2) % 3]);
    }

    std::vector<Key3> subfaces_on_edge(VertIdx a, VertIdx b) const {
        std::vector<Key3> out;
        edge_subfaces_.for_each(edge_key(a, b),
                                [&](VertIdx c) { out.push_back(sorted3(a, b, c)); });
        return out;
    }

    Key3 face_key(TetIdx t, unsigned k) const {
        const unsigned* lf = kFaceVertex[k];
        return sorted3(m_.vertex(t, lf[0]), m_.vertex(t, lf[1]), m_.vertex(t, lf[2]));
    }

    /// Whether v can be a corner of a subface or an end of a subsegment: Volume points never
    /// are (subfaces and subsegments are split only at Segment and Facet points), and most
    /// vertices of a refined mesh are Volume points, so most lookups end here.
    bool on_boundary(VertIdx v) const { return out_.vertex_feature[v] != VertexFeature3::Volume; }

    /// Bit k set when corner k of tetrahedron t is on_boundary: a face can be a subface only
    /// with its three corners' bits, an edge a subsegment only with both ends' (one feature
    /// lookup per corner, and no sorted key, for the many faces and edges that cannot be).
    unsigned boundary_corners(TetIdx t) const {
        unsigned mask = 0;
        for (unsigned k = 0; k < 4; ++k)
            if (on_boundary(m_.vertex(t, k))) mask |= 1u << k;
        return mask;
    }
    /// The number of corners in a boundary_corners mask (a table: std::popcount is a library
    /// call without -mpopcnt).
    static unsigned corner_count(unsigned mask) {
        constexpr unsigned char kCount[16] = {0, 1, 1, 2, 1, 2, 2, 3, 1, 2, 2, 3, 2, 3, 3, 4};
        return kCount[mask & 0xfu];
    }
    /// Whether face k (opposite corner k) of a tetrahedron with boundary_corners `mask` has
    /// its three corners on the boundary.
    static bool boundary_face(unsigned mask, unsigned k) { return (mask | (1u << k)) == 0xfu; }
    /// Whether edge e (kEdges[e]) has both ends on the boundary.
    static bool boundary_edge(unsigned mask, const unsigned (&e)[2]) {
        return ((mask >> e[0]) & (mask >> e[1]) & 1u) != 0;
    }

    /// Whether the face with sorted corners `key` is a subface.
    bool is_subface_key(const Key3& key) const {
        return on_boundary(key[0]) && on_boundary(key[1]) && on_boundary(key[2]) &&
               subfaces_.count(key) != 0;
    }

    /// Whether edge a b is a subsegment.
    bool is_subsegment(VertIdx a, VertIdx b) const {
        return on_boundary(a) && on_boundary(b) && subsegments_.count(edge_key(a, b)) != 0;
    }

    bool is_subface(TetIdx t, unsigned k) const { return is_subface_key(face_key(t, k)); }

    // --- segments --------------------------------------------------------------------------

    /// The parameter of segment vertex v along segment s, from its coordinates (rounded; it
    /// only positions later split points, computed from the segment's ends). The differences
    /// are scaled by a power of two first, so no square overflows or underflows.
    double segment_parameter(VertIdx v, std::uint32_t s) const {
        const double* p = point(out_.segments[2 * s]);
        const double* q = point(out_.segments[2 * s + 1]);
        double d[3], w[3], largest = 0;
        for (int k = 0; k < 3; ++k) largest = std::max(largest, std::fabs(q[k] - p[k]));
        const int e = std::ilogb(largest);
        double dd = 0, dw = 0;
        for (int k = 0; k < 3; ++k) {
            d[k] = std::ldexp(q[k] - p[k], -e);
            w[k] = std::ldexp(point(v)[k] - p[k], -e);
            dd += d[k] * d[k];
            dw += d[k] * w[k];
        }
        return std::clamp(dw / dd, 0.0, 1.0);
    }

    double parameter_of(VertIdx v, std::uint32_t s) const {
        if (v == out_.segments[2 * s]) return 0.0;
        if (v == out_.segments[2 * s + 1]) return 1.0;
        return parameter_[v];
    }

    bool acute_apex(VertIdx apex, std::uint32_t s) const {
        const VertIdx far =
            out_.segments[2 * s] == apex ? out_.segments[2 * s + 1] : out_.segments[2 * s];
        for (const std::uint32_t other : vertex_segments_[apex]) {
            if (other == s) continue;
            const VertIdx end = out_.segments[2 * other] == apex ? out_.segments[2 * other + 1]
                                                                 : out_.segments[2 * other];
            if (predicates::dot_sign_3d(point(apex), point(far), point(end)) == Sign::Positive)
                return true;
        }
        return false;
    }

    double shell_parameter(std::uint32_t s, double t_apex, double t_far) const {
        return triangulation::concentric_shell_parameter(
            point(out_.segments[2 * s]), point(out_.segments[2 * s + 1]), t_apex, t_far);
    }

    // --- locating --------------------------------------------------------------------------

    /// A breadth-first walk over the star of one vertex (the tetrahedra holding it), by adjacency
    /// from vertex_tet_, meeting each tetrahedron once: marked with the call's epoch in its own
    /// mark array (a search of the list made star() quadratic, and a vertex beside a gap 1e-9
    /// wide gathers thousands of tetrahedra: 94% of such a run's time).
    struct StarWalk {
        VertIdx v = kNone;
        std::vector<TetIdx> met;
        std::size_t next = 0;
        bool done() const { return next == met.size(); }
    };
    mutable std::array<StarWalk, 3> tets_with_walks_;  ///< tets_with's scratch

    StarWalk start_walk(VertIdx v, unsigned which) const {
        StarWalk walk;
        restart_walk(walk, v, which);
        return walk;
    }

    /// start_walk into `walk`, whose vector keeps its capacity (tets_with's scratch walks: their
    /// allocations were a third of tets_with's instructions).
    void restart_walk(StarWalk& walk, VertIdx v, unsigned which) const {
        EM_ASSERT(vertex_tet_[v] != kNone && m_.slot_of(vertex_tet_[v], v) < 4);
        walk_mark_[which][vertex_tet_[v]] = walk_epoch_;
        walk.v = v;
        walk.met.assign(1, vertex_tet_[v]);
        walk.next = 0;
        if (other_pieces_.empty()) return;  // no star in pieces (no hash of v)
        const auto pieces = other_pieces_.find(v);
        if (pieces != other_pieces_.end()) {
            for (const TetIdx t : pieces->second) {
                if (m_.is_dead(t) || m_.slot_of(t, v) >= 4 || walk_mark_[which][t] == walk_epoch_)
                    continue;
                walk_mark_[which][t] = walk_epoch_;
                walk.met.push_back(t);
            }
        }
    }

    /// Records the pieces of v's star: vertex_tet_[v]'s, and one for each further piece met by
    /// the live tetrahedra holding v among its recorded pieces and `candidates`.
    void note_pieces(VertIdx v, const std::vector<TetIdx>& candidates) {
        new_walk_epoch();
        std::vector<TetIdx> roots;
        const auto walk_from = [&](TetIdx t) {
            if (t == kNone || m_.is_dead(t) || m_.slot_of(t, v) >= 4 ||
                walk_mark_[0][t] == walk_epoch_)
                return;
            roots.push_back(t);
            walk_mark_[0][t] = walk_epoch_;
            StarWalk walk{v, {t}, 0};
            while (!walk.done()) step(walk, 0);
        };
        walk_from(vertex_tet_[v]);
        const auto known = other_pieces_.find(v);
        if (known != other_pieces_.end()) {
            const std::vector<TetIdx> old = known->second;
            for (const TetIdx t : old) walk_from(t);
        }
        for (const TetIdx t : candidates) walk_from(t);
        if (roots.size() <= 1) {
            other_pieces_.erase(v);
        } else {
            other_pieces_[v].assign(roots.begin() + 1, roots.end());
        }
    }

    /// Finds the vertices of the starting mesh whose star is in several pieces (its
    /// tetrahedra outnumber one adjacency walk's) and records their pieces.
    void find_non_manifold_vertices() {
        std::vector<std::uint32_t> incident(vertex_tet_.size(), 0);
        for (TetIdx t = 0; t < m_.tet_slots(); ++t) {
            if (m_.is_dead(t)) continue;
            for (unsigned k = 0; k < 4; ++k) ++incident[m_.vertex(t, k)];
        }
        std::unordered_map<VertIdx, std::vector<TetIdx>> split;
        for (VertIdx v = 0; v < vertex_tet_.size(); ++v) {
            if (incident[v] != 0 && star(v).size() != incident[v]) split[v] = {};
        }
        if (split.empty()) return;
        for (TetIdx t = 0; t < m_.tet_slots(); ++t) {
            if (m_.is_dead(t)) continue;
            for (unsigned k = 0; k < 4; ++k) {
                const auto it = split.find(m_.vertex(t, k));
                if (it != split.end()) it->second.push_back(t);
            }
        }
        for (const auto& [v, tets] : split) note_pieces(v, tets);
    }

    /// Expands the next tetrahedron of the walk.
    void step(StarWalk& walk, unsigned which) const {
        const TetIdx t = walk.met[walk.next++];
        const unsigned sv = m_.slot_of(t, walk.v);
        for (unsigned k = 0; k < 4; ++k) {
            if (k == sv) continue;
            const FaceIdx g = m_.adj[4 * t + k];
            if (g == kNone) continue;
            const TetIdx u = triangulation::tet_of(g);
            if (walk_mark_[which][u] == walk_epoch_) continue;
            walk_mark_[which][u] = walk_epoch_;
            walk.met.push_back(u);
        }
    }

    /// A fresh epoch for the walks of one call.
    void new_walk_epoch() const {
        for (auto& marks : walk_mark_)
            if (marks.size() < m_.tet_slots()) marks.resize(m_.tet_slots(), 0);
        if (++walk_epoch_ == 0) {
            for (auto& marks : walk_mark_) std::fill(marks.begin(), marks.end(), 0u);
            walk_epoch_ = 1;
        }
    }

    /// The live tetrahedra holding vertex v, in the order a breadth-first walk meets them.
    std::vector<TetIdx> star(VertIdx v) const {
        new_walk_epoch();
        StarWalk walk = start_walk(v, 0);
        while (!walk.done()) step(walk, 0);
        return std::move(walk.met);
    }

    /// The live tetrahedra holding a and b (and c): the stars of the two (three) vertices are
    /// walked in turns and the first one complete is filtered, so the work is at most a few
    /// times the smallest star (a subface's corner can be a vertex with thousands).
    std::vector<TetIdx> tets_with(VertIdx a, VertIdx b, VertIdx c = kNone) const {
        std::vector<TetIdx> out;
        tets_with(out, a, b, c);
        return out;
    }

    /// tets_with into `out` (cleared first; its capacity kept by callers that loop).
    void tets_with(std::vector<TetIdx>& out, VertIdx a, VertIdx b, VertIdx c = kNone) const {
        out.clear();
        if (c != kNone) {
            face_tets(out, a, b, c);
            return;
        }
        new_walk_epoch();
        const unsigned n = c == kNone ? 2 : 3;
        const VertIdx corners[3] = {a, b, c};
        std::array<StarWalk, 3>& walks = tets_with_walks_;
        for (unsigned w = 0; w < n; ++w) restart_walk(walks[w], corners[w], w);
        unsigned finished = n;
        while (finished == n) {
            for (unsigned w = 0; w < n; ++w) {
                if (walks[w].done()) {
                    finished = w;
                    break;
                }
                step(walks[w], w);
            }
        }
        for (const TetIdx t : walks[finished].met) {
            if (m_.slot_of(t, a) < 4 && m_.slot_of(t, b) < 4 &&
                (c == kNone || m_.slot_of(t, c) < 4))
                out.push_back(t);
        }
    }

    /// The live tetrahedra holding face abc, into `out`: at most two, the face's sides. The
    /// three stars are walked in turns only until a tetrahedron holding the face is met; the
    /// other side is its neighbour across the face (walking the stars to the end, as for an
    /// edge, was most of facet_cavity's time: a boundary vertex's star holds dozens).
    void face_tets(std::vector<TetIdx>& out, VertIdx a, VertIdx b, VertIdx c) const {
        new_walk_epoch();
        const VertIdx corners[3] = {a, b, c};
        std::array<StarWalk, 3>& walks = tets_with_walks_;
        for (unsigned w = 0; w < 3; ++w) restart_walk(walks[w], corners[w], w);
        while (true) {
            for (unsigned w = 0; w < 3; ++w) {
                if (walks[w].done()) return;  // a whole star without the face: none holds it
                const TetIdx t = walks[w].met[walks[w].next];
                const unsigned sa = m_.slot_of(t, a), sb = m_.slot_of(t, b), sc = m_.slot_of(t, c);
                if (sa < 4 && sb < 4 && sc < 4) {
                    out.push_back(t);
                    const FaceIdx g = m_.adj[4 * t + (6 - sa - sb - sc)];
                    if (g != kNone) out.push_back(triangulation::tet_of(g));
                    return;
                }
                step(walks[w], w);
            }
        }
    }

    // --- cavities --------------------------------------------------------------------------

    struct Split {
        std::vector<Key3> faces;     ///< subfaces the point splits (crossed, dropped)
        std::uint64_t edge = ~0ull;  ///< the subsegment it splits, if any
        /// Edges inside the facet cavities (they may go), once per cavity subface holding one:
        /// a list, as `faces` (a node-based set here made most of facet_cavity's allocations).
        std::vector<std::uint64_t> exempt;
        /// `faces` as a set when there are many (a needle's facet cavity holds the whole facet:
        /// a scan per cavity face made first_violation quadratic); empty otherwise.
        std::unordered_set<Key3, Key3Hash> face_set;
        std::unordered_set<std::uint64_t> exempt_set;  ///< `exempt` as a set, likewise
    };
    static constexpr std::size_t kScannedFaces = 32;

    bool is_split_face(const Split& split, const Key3& key) const {
        if (!split.face_set.empty()) return split.face_set.count(key) != 0;
        return std::any_of(split.faces.begin(), split.faces.end(),
                           [&](const Key3& face) { return same_key(face, key); });
    }

    bool is_exempt(const Split& split, std::uint64_t key) const {
        if (!split.exempt_set.empty()) return split.exempt_set.count(key) != 0;
        return std::find(split.exempt.begin(), split.exempt.end(), key) != split.exempt.end();
    }

    /// Bowyer-Watson cavity of p from `seeds` that never crosses a subface outside `split`,
    /// shrunk until valid (see the header). Returns false when a seed would have to go.
    /// With `required` (not kNone): false as soon as the grown cavity misses that tetrahedron
    /// (shrinking only removes tetrahedra, so it could not come back).
    bool build_cavity(const double* p, const std::vector<TetIdx>& seeds, const Split& split,
                      TetIdx required = kNone) {
        seed_list_.assign(seeds.begin(), seeds.end());
        return grow_cavity(p, split, required);
    }

    /// build_cavity from one seed (no vector made per call).
    bool build_cavity(const double* p, TetIdx seed, const Split& split, TetIdx required = kNone) {
        seed_list_.assign(1, seed);
        return grow_cavity(p, split, required);
    }

    /// A Split of nothing: a point inside the domain.
    static const Split& no_split() {
        static const Split none;
        return none;
    }

    std::vector<TetIdx> seed_list_;  ///< build_cavity's seeds (scratch, kept for its capacity)

    /// build_cavity from the seeds in seed_list_ (which it may extend).
    bool grow_cavity(const double* p, const Split& split, TetIdx required) {
        // The mesh does not change while a cavity is built: the marks cover every slot now.
        if (marks_.size() < m_.tet_slots()) marks_.resize(m_.tet_slots());
        ++cavity_stamp_;
        std::vector<TetIdx>& seed_list = seed_list_;
        std::size_t forced = 0;  // seeds added for other seeds' faces that p does not see
        bool shrunk = false;
        while (true) {
            // Grow from the seeds (marks of this attempt in CavityMarks::attempt; the tetrahedra
            // shrunk away stay excluded under this insertion's stamp).
            cavity_.clear();
            const std::uint32_t mark = cavity_stamp_;
            ++attempt_;
            for (const TetIdx t : seed_list) {
                if (attempt_mark_(t)) continue;
                set_attempt_(t);
                cavity_.push_back(t);
            }
            for (std::size_t i = 0; i < cavity_.size(); ++i) {
                const TetIdx t = cavity_[i];
                for (unsigned k = 0; k < 4; ++k) {
                    const FaceIdx g = m_.adj[4 * t + k];
                    if (g == kNone) continue;
                    const TetIdx u = triangulation::tet_of(g);
                    if (attempt_mark_(u) || marks_[u].excluded == mark) continue;
                    // The sphere first: asked once per tetrahedron and call, while the
                    // subface lookup (a hash of the face) came once per face and round.
                    if (!inside_sphere(u, p, mark)) continue;
                    const unsigned* lf = kFaceVertex[k];
                    if (on_boundary(m_.vertex(t, lf[0])) && on_boundary(m_.vertex(t, lf[1])) &&
                        on_boundary(m_.vertex(t, lf[2]))) {
                        const Key3 key = face_key(t, k);
                        if (subfaces_.count(key) != 0 && !is_split_face(split, key)) continue;
                    }
                    set_attempt_(u);
                    cavity_.push_back(u);
                }
            }
            if (required != kNone && !in_attempt(required)) return false;
            const TetIdx bad = first_violation(p, seed_list, split);
            if (bad == kNone) {
                if (shrunk) ++counters_.shrunk_cavities;
                return true;
            }
            if (bad == kNone - 1) {
                // A seed's face that p does not see is no reason to give up while the
                // tetrahedron behind it can become a seed too: p within rounding of the face's
                // plane, rounded onto a segment or facet beside a flat tetrahedron of boundary
                // points coplanar before rounding (a thin hole's facet through the midpoints of
                // a turned cube's edges: the shell split failed every time and refinement ran
                // into its budget). A bounded number, never across a subface.
                const FaceIdx g = blind_face_ == kNone ? kNone : m_.adj[blind_face_];
                if (g == kNone || forced >= kMaxForced) return false;
                if (is_subface_key(face_key(blind_face_ / 4, blind_face_ % 4))) return false;
                const TetIdx u = triangulation::tet_of(g);
                if (std::find(seed_list.begin(), seed_list.end(), u) != seed_list.end())
                    return false;
                seed_list.push_back(u);
                marks_[u].excluded = 0;
                ++forced;
                ++counters_.forced_cavity_tets;
                continue;
            }
            marks_[bad].excluded = mark;
            for (const TetIdx u : violations_) marks_[u].excluded = mark;
            if (violations_.size() > 1) counters_.batched_removals += violations_.size() - 1;
            shrunk = true;
        }
    }

    /// insphere(u, p) > 0, asked once per tetrahedron and call of build_cavity (stamp `mark`):
    /// the shrinking loop regrows the cavity several times and a tetrahedron beside it is met
    /// from each of its faces on the cavity, and cospherical ties cost an exact evaluation.
    bool inside_sphere(TetIdx u, const double* p, std::uint32_t mark) {
        CavityMarks& marks = marks_[u];
        if (marks.sphere != mark) {
            marks.sphere = mark;
            marks.inside = predicates::insphere(point(m_.vertex(u, 0)), point(m_.vertex(u, 1)),
                                                point(m_.vertex(u, 2)), point(m_.vertex(u, 3)),
                                                p) == Sign::Positive;
        }
        return marks.inside != 0;
    }

    // Per-attempt marks (CavityMarks::attempt; build_cavity sized marks_).
    std::uint32_t attempt_ = 0;
    bool attempt_mark_(TetIdx t) const { return marks_[t].attempt == attempt_; }
    void set_attempt_(TetIdx t) { marks_[t].attempt = attempt_; }
    bool in_attempt(TetIdx t) const { return t < marks_.size() && marks_[t].attempt == attempt_; }

    /// kNone when the cavity is valid; else a non-seed cavity tetrahedron to remove, or
    /// kNone - 1 when only a seed could be removed. violations_ then holds every tetrahedron
    /// whose boundary face does not see p (all removed at once; the others found later).
    /// Removing them one per round regrew the cavity once per tetrahedron: where flat recovered
    /// tetrahedra put hundreds in one cavity, that quadratic loop was two thirds of frontal
    /// insertion's time. The batch removes the same ones: such a face stays on the boundary,
    /// facing away from p, as long as its tetrahedron stays (its far side is excluded, outside
    /// the sphere, a subface or the domain's boundary; none of which shrinking undoes), so
    /// one-per-round removal would take each of them too before any other check passes (unless
    /// cut off from the seeds first, when it is gone from the cavity either way; only which
    /// side of a crossed subface goes could differ). Measured: the same meshes bit for bit
    /// (refinement and frontal on the wing, frontal on the box with a hole).
    TetIdx first_violation(const double* p, const std::vector<TetIdx>& seeds, const Split& split) {
        auto removable = [&](TetIdx t) {
            return std::find(seeds.begin(), seeds.end(), t) == seeds.end() ? t : kNone - 1;
        };
        violations_.clear();
        blind_face_ = kNone;
        FlatKeyMap64<std::uint8_t>& boundary_edges = boundary_edges_;
        boundary_edges.clear(cavity_.size());  // edges of surface vertices only: few
        if (boundary_vertex_mark_.size() < m_.vertex_count())
            boundary_vertex_mark_.resize(m_.vertex_count(), 0);
        if (++boundary_epoch_ == 0) {
            std::fill(boundary_vertex_mark_.begin(), boundary_vertex_mark_.end(), 0u);
            boundary_epoch_ = 1;
        }
        for (const TetIdx t : cavity_) {
            for (unsigned k = 0; k < 4; ++k) {
                const FaceIdx g = m_.adj[4 * t + k];
                const unsigned* lf = kFaceVertex[k];
                if (g != kNone && attempt_mark_(triangulation::tet_of(g))) {
                    // A face inside the cavity matters only as a subface, whose corners are
                    // all on the surface: most are not, and need no sorted key.
                    if (!on_boundary(m_.vertex(t, lf[0])) || !on_boundary(m_.vertex(t, lf[1])) ||
                        !on_boundary(m_.vertex(t, lf[2])))
                        continue;
                    const Key3 key = face_key(t, k);
                    if (is_subface_key(key) && !is_split_face(split, key)) {
                        // The batch first; the crossing is met again next round if it stays.
                        if (!violations_.empty()) return violations_.front();
                        const TetIdx first = removable(t);
                        return first != kNone - 1 ? first : removable(triangulation::tet_of(g));
                    }
                    continue;
                }
                // A boundary subface being split; the sorted key only when some are.
                if (!split.faces.empty() && is_split_face(split, face_key(t, k))) continue;
                const VertIdx corner[3] = {m_.vertex(t, lf[0]), m_.vertex(t, lf[1]),
                                           m_.vertex(t, lf[2])};
                if (predicates::orient3d(point(corner[0]), point(corner[1]), point(corner[2]), p) !=
                    Sign::Positive) {
                    const TetIdx bad = removable(t);
                    if (bad == kNone - 1) {
                        blind_face_ = 4 * t + k;
                        return bad;
                    }
                    violations_.push_back(bad);
                    break;  // t goes: its other faces need no look
                }
                for (unsigned i = 0; i < 3; ++i) {
                    // Only edges of two surface vertices are looked up below (a kept edge's
                    // ends are on the surface): a cavity inside the volume hashes none. (A set
                    // of edges and one of vertices: the corners' order does not matter.)
                    const VertIdx x = corner[i], y = corner[i == 2 ? 0 : i + 1];
                    if (on_boundary(x) && on_boundary(y)) boundary_edges.emplace(edge_key(x, y), 0);
                    boundary_vertex_mark_[x] = boundary_epoch_;
                }
            }
        }
        if (!violations_.empty()) return violations_.front();
        for (const TetIdx t : cavity_) {
            for (unsigned k = 0; k < 4; ++k)
                if (boundary_vertex_mark_[m_.vertex(t, k)] != boundary_epoch_) return removable(t);
            for (const auto& e : kEdges) {
                const VertIdx a = m_.vertex(t, e[0]), b = m_.vertex(t, e[1]);
                if (!on_boundary(a) || !on_boundary(b)) continue;  // no kept edge
                const std::uint64_t key = edge_key(a, b);
                if (key == split.edge || is_exempt(split, key)) continue;
                const bool kept_edge = subsegments_.count(key) != 0 || edge_subfaces_.contains(key);
                if (kept_edge && !boundary_edges.contains(key)) return removable(t);
            }
        }
        return kNone;
    }
    std::vector<TetIdx> violations_;  ///< first_violation's batch
    /// first_violation's seed face (4 t + k) that does not see p, when that is why it gave up.
    FaceIdx blind_face_ = kNone;
    /// Most seeds build_cavity adds behind seeds' faces that p does not see.
    static constexpr std::size_t kMaxForced = 64;
    FlatKeyMap64<std::uint8_t> boundary_edges_;        ///< first_violation's scratch
    std::vector<std::uint32_t> boundary_vertex_mark_;  ///< == boundary_epoch_: on the boundary
    std::uint32_t boundary_epoch_ = 0;
    FlatKeyMap64<FaceIdx> open_edges_;  ///< commit's scratch: new faces not yet linked
    /// A face of the cavity's boundary (commit's scratch, kept for its capacity).
    struct BoundaryFace {
        std::array<VertIdx, 3> corners;
        FaceIdx outside;
        double attribute;
        double max_volume;
    };
    std::vector<BoundaryFace> commit_faces_;
    std::vector<TetIdx> commit_created_;  ///< commit's new tetrahedra (scratch)

    /// Replaces the cavity (built by build_cavity for p) by the tetrahedra joining p to its
    /// boundary, updates the subfaces and subsegments of `split`, queues what to check.
    VertIdx commit(const std::array<double, 3>& p, VertexFeature3 feature, std::uint32_t index,
                   double parameter, const Split& split, const std::vector<Subface>& new_subfaces,
                   const std::vector<std::pair<std::uint64_t, std::uint32_t>>& new_subsegments) {
        if (counters_.insertions >= budget_) {
            throw InputError(
                name_ + ": Steiner point budget of " + std::to_string(budget_) + " exceeded (" +
                std::to_string(counters_.circumcenters) + " circumcentres, " +
                std::to_string(counters_.subface_splits) + " subface and " +
                std::to_string(counters_.segment_splits + counters_.shell_splits) +
                " subsegment splits, " + std::to_string(counters_.rejected_points) +
                " rejected points): small input angles, or a bound too tight to reach");
        }
        const VertIdx v = m_.vertex_count();
        m_.xyz.insert(m_.xyz.end(), p.begin(), p.end());
        out_.vertex_feature.push_back(feature);
        out_.feature_index.push_back(index);
        parameter_.push_back(parameter);
        vertex_tet_.push_back(kNone);
        ++counters_.insertions;
        counters_.cavity_tets += cavity_.size();

        std::vector<BoundaryFace>& faces = commit_faces_;
        faces.clear();
        for (const TetIdx t : cavity_) {
            for (unsigned k = 0; k < 4; ++k) {
                const FaceIdx g = m_.adj[4 * t + k];
                if (g != kNone && attempt_mark_(triangulation::tet_of(g))) continue;
                if (!split.faces.empty() && is_split_face(split, face_key(t, k))) continue;
                const unsigned* lf = kFaceVertex[k];
                faces.push_back({{m_.vertex(t, lf[0]), m_.vertex(t, lf[1]), m_.vertex(t, lf[2])},
                                 g,
                                 attributes_.empty() ? 0.0 : attributes_[t],
                                 max_volumes_.empty() ? 0.0 : max_volumes_[t]});
            }
        }
        // m_.kill_tet on each, its free-list pushes made as one append (a push_back call each).
        for (const TetIdx t : cavity_) {
            marks_[t].attempt = 0;
            m_.tv[4 * std::size_t{t}] = kNone;
        }
        m_.free_tets.insert(m_.free_tets.end(), cavity_.begin(), cavity_.end());
        FlatKeyMap64<FaceIdx>& open = open_edges_;
        open.clear(faces.size() * 3 / 2);  // each edge of the cavity's boundary in two faces
        std::vector<TetIdx>& created = commit_created_;
        created.resize(faces.size());  // one per face, filled in order (no push_back per face)
        for (std::size_t i = 0; i < faces.size(); ++i) {
            const BoundaryFace& f = faces[i];
            const TetIdx t = m_.new_tet();
            if (attributes_.size() < m_.tet_slots() && !attributes_.empty())
                attributes_.resize(m_.tet_slots(), 0.0);
            if (!attributes_.empty()) attributes_[t] = f.attribute;
            if (max_volumes_.size() < m_.tet_slots() && !max_volumes_.empty())
                max_volumes_.resize(m_.tet_slots(), 0.0);
            if (!max_volumes_.empty()) max_volumes_[t] = f.max_volume;
            const std::size_t s = 4 * std::size_t{t};
            m_.tv[s] = f.corners[0];
            m_.tv[s + 1] = f.corners[1];
            m_.tv[s + 2] = f.corners[2];
            m_.tv[s + 3] = v;
            m_.adj[s + 3] = f.outside;
            if (f.outside != kNone) m_.adj[f.outside] = static_cast<FaceIdx>(s + 3);
            // The edge opposite corner j: the other two (a table: the loop is not unrolled, and
            // (j + 1) % 3 was two multiplications per edge).
            constexpr unsigned kOthers[3][2] = {{1, 2}, {2, 0}, {0, 1}};
            for (unsigned j = 0; j < 3; ++j) {
                m_.adj[s + j] = kNone;
                const std::uint64_t key =
                    edge_key(f.corners[kOthers[j][0]], f.corners[kOthers[j][1]]);
                const auto [slot, added] = open.emplace(key, static_cast<FaceIdx>(s + j));
                if (!added) {
                    EM_ASSERT(*slot != kNone);
                    m_.link(*slot, static_cast<FaceIdx>(s + j));
                    *slot = kNone;
                }
            }
            for (unsigned k = 0; k < 4; ++k) {
                const VertIdx w = m_.tv[s + k];
                // A star in pieces keeps the piece vertex_tet_ pointed into (note_pieces below
                // drops it again if it was this cavity's). Most meshes have none: no hash then.
                if (!other_pieces_.empty()) {
                    const auto pieces = other_pieces_.find(w);
                    if (pieces != other_pieces_.end() && vertex_tet_[w] != t)
                        pieces->second.push_back(vertex_tet_[w]);
                }
                vertex_tet_[w] = t;
            }
            created[i] = t;
        }
        // Subfaces and subsegments.
        for (const Key3& key : split.faces) remove_subface(key);
        for (const Subface& s : new_subfaces) add_subface(s);
        if (split.edge != ~0ull) subsegments_.erase(split.edge);
        for (const auto& [key, segment] : new_subsegments) subsegments_.emplace(key, segment);
        // Stars in several pieces: the corners already known to have them get the new
        // tetrahedra as candidates; the new vertex has several when its cavity had (a point on
        // an edge where the domain touches itself, whose ends are then known already: with none
        // known, no star is in pieces and this costs nothing on the insertion path).
        if (!other_pieces_.empty()) {
            std::vector<VertIdx> split_corners;
            for (const TetIdx t : created) {
                for (unsigned k = 0; k < 4; ++k) {
                    const VertIdx w = m_.vertex(t, k);
                    if (other_pieces_.count(w) != 0 &&
                        std::find(split_corners.begin(), split_corners.end(), w) ==
                            split_corners.end())
                        split_corners.push_back(w);
                }
            }
            for (const VertIdx w : split_corners) {
                std::vector<TetIdx> candidates;
                for (const TetIdx t : created)
                    if (m_.slot_of(t, w) < 4) candidates.push_back(t);
                note_pieces(w, candidates);
            }
            if (!created.empty() && star(v).size() != created.size()) note_pieces(v, created);
        }
        // Every new subface is a face, and every new subsegment an edge, of a new tetrahedron:
        // one holds all its vertices (any three vertices of a tetrahedron make a face).
        const auto created_with = [&](VertIdx a, VertIdx b, VertIdx c) {
            return std::any_of(created.begin(), created.end(), [&](TetIdx t) {
                return m_.slot_of(t, a) < 4 && m_.slot_of(t, b) < 4 && m_.slot_of(t, c) < 4;
            });
        };
        for (const Subface& s : new_subfaces)
            EM_ASSERT(created_with(s.oriented[0], s.oriented[1], s.oriented[2]));
        for (const auto& entry : new_subsegments) {
            const auto a = static_cast<VertIdx>(entry.first >> 32);
            const auto b = static_cast<VertIdx>(entry.first);
            EM_ASSERT(created_with(a, b, b));
        }
        for (const TetIdx t : created) examine(t);
        return v;
    }

    // --- queues ----------------------------------------------------------------------------

    /// A new tetrahedron: the generator's hook (after the encroachment queues).
    virtual void on_created(TetIdx t) = 0;

    /// The generator's veto on a subsegment or subface split point p whose cavity (cavity_) is
    /// built: false rejects it (counted in rejected_points).
    virtual bool boundary_point_allowed(const double* /*p*/) const { return true; }

    /// Queues the subfaces and subsegments of t its other vertices encroach (when enabled),
    /// then hands t to on_created.
    void examine(TetIdx t) {
        if (!queue_encroachment_) {
            on_created(t);
            return;
        }
        const unsigned mask = boundary_corners(t);
        if (corner_count(mask) < 2) {  // no face or edge with all its corners on the surface
            on_created(t);
            return;
        }
        const std::array<VertIdx, 4> c{m_.vertex(t, 0), m_.vertex(t, 1), m_.vertex(t, 2),
                                       m_.vertex(t, 3)};
        for (unsigned k = 0; k < 4; ++k) {
            if (!boundary_face(mask, k)) continue;
            const Key3 key = face_key(t, k);
            if (subfaces_.count(key) == 0) continue;
            if (!sharp_.empty() && sharp_.shields_subface(out_, c[k], subfaces_.at(key).facet))
                continue;
            if (predicates::in_equatorial_sphere_3d(point(c[k]), point(key[0]), point(key[1]),
                                                    point(key[2])) == Sign::Positive) {
                subface_queue_.push_back(key);
                ++counters_.encroached_subfaces;
            }
        }
        for (const auto& e : kEdges) {
            if (!boundary_edge(mask, e)) continue;
            const std::uint64_t key = edge_key(c[e[0]], c[e[1]]);
            if (subsegments_.count(key) == 0) continue;
            for (unsigned k = 0; k < 4; ++k) {
                if (k == e[0] || k == e[1]) continue;
                if (!sharp_.empty() && sharp_.shields_segment(out_, c[k], subsegments_.at(key)))
                    continue;
                if (predicates::dot_sign_3d(point(c[k]), point(c[e[0]]), point(c[e[1]])) ==
                        Sign::Negative &&
                    !small_angles_->narrow_angle_pair(c[k], c[e[0]]) &&
                    !small_angles_->narrow_angle_pair(c[k], c[e[1]])) {
                    segment_queue_.push_back(key);
                    ++counters_.encroached_segments;
                    break;
                }
            }
        }
        on_created(t);
    }

    // --- splits ----------------------------------------------------------------------------

    /// Splits subsegment `key` (if still one). Returns whether a point was inserted.
    bool split_subsegment(std::uint64_t key) {
        const std::uint32_t* found = subsegments_.find(key);
        if (found == nullptr) return false;
        const std::uint32_t s = *found;
        const VertIdx a = static_cast<VertIdx>(key >> 32), b = static_cast<VertIdx>(key);
        const double ta = parameter_of(a, s), tb = parameter_of(b, s);
        const bool apex_a = a < out_.input_vertex_count && acute_apex(a, s);
        const bool apex_b = b < out_.input_vertex_count && acute_apex(b, s);
        double t = std::nan("");
        if (apex_a != apex_b) t = apex_a ? shell_parameter(s, ta, tb) : shell_parameter(s, tb, ta);
        const bool shell = !std::isnan(t);
        if (!shell) t = 0.5 * ta + 0.5 * tb;
        const std::array<double, 3> p = predicates::point_on_segment_3d(
            point(out_.segments[2 * s]), point(out_.segments[2 * s + 1]), t);
        if (same_point(p.data(), point(a)) || same_point(p.data(), point(b))) {
            ++counters_.rejected_points;  // the subsegment is as short as doubles resolve
            return false;
        }
        Split split;
        const VertIdx v = m_.vertex_count();
        std::vector<Subface> pieces;
        const std::vector<TetIdx> around = tets_with(a, b);
        const std::vector<Key3> on_edge = subfaces_on_edge(a, b);
        std::vector<TetIdx> seeds;
        // The facet cavities first; then, when they or the tetrahedra around them fail, only
        // the subfaces on the subsegment.
        bool valid = false;
        for (const bool grow : {true, false}) {
            split = Split{};
            split.edge = key;
            pieces.clear();
            seeds = around;
            if (facet_cavity(p.data(), on_edge, v, split, pieces, seeds, grow) &&
                build_cavity(p.data(), seeds, split)) {
                valid = true;
                break;
            }
        }
        if (!valid || !boundary_point_allowed(p.data())) {
            ++counters_.rejected_points;
            return false;
        }
        commit(p, VertexFeature3::Segment, s, t, split, pieces,
               {{edge_key(a, v), s}, {edge_key(v, b), s}});
        ++(shell ? counters_.shell_splits : counters_.segment_splits);
        return true;
    }

    /// The facet cavities of a point p (to become vertex v) on a facet or segment: from the
    /// `initial` subfaces (holding p or its subsegment), every subface of the same facet reached
    /// across edges that are not subsegments whose circumcircle strictly contains p (exact
    /// in_equatorial_sphere_3d), as in 2D Bowyer-Watson. Fills split.faces, the edges
    /// inside the cavities (split.exempt), the fan of new subfaces from v to each cavity's
    /// boundary (the facet's orientation kept; the split subsegment skipped) and the seeds (the
    /// tetrahedra on both sides of each cavity subface: p lies inside their circumspheres).
    /// A grown subface whose fan piece would not have the facet's orientation (p beyond its
    /// edge in the facet's projection: the facet is not Delaunay there) is dropped from the
    /// cavity again; returns false when an initial subface would have to go.
    /// With `grow` false the cavities are the initial subfaces alone; false is also returned when
    /// a cavity's boundary is not one simple chain per facet (a vertex on it twice).
    bool facet_cavity(const double* p, const std::vector<Key3>& initial, VertIdx v, Split& split,
                      std::vector<Subface>& pieces, std::vector<TetIdx>& seeds, bool grow) const {
        std::vector<Key3> faces = initial;
        // Membership by a scan of `faces` (a facet cavity holds a few subfaces; the node-based
        // set and maps here were most of refinement's allocations), and by a hash set once it
        // holds more than kScannedFaces: on a needle's facets every subface's circumcircle holds
        // the point, the cavity takes the whole facet, and scans made each cavity quadratic
        // (frontal insertion on a needle at a size 2^20 took 359 s, nearly all in these scans).
        std::unordered_set<Key3, Key3Hash> indexed;  // faces[0, synced)
        std::size_t synced = 0;
        const auto in_set = [&](const Key3& k) {
            if (faces.size() <= kScannedFaces)
                return std::any_of(faces.begin(), faces.end(),
                                   [&](const Key3& face) { return same_key(face, k); });
            for (; synced < faces.size(); ++synced) indexed.insert(faces[synced]);
            return indexed.count(k) != 0;
        };
        for (std::size_t i = 0; grow && i < faces.size(); ++i) {
            const Subface f = subfaces_.at(faces[i]);
            for (unsigned e = 0; e < 3; ++e) {
                const VertIdx x = f.oriented[e], y = f.oriented[(e + 1) % 3];
                const std::uint64_t key = edge_key(x, y);
                if (key == split.edge || subsegments_.count(key) != 0) continue;
                edge_subfaces_.for_each(key, [&](VertIdx third) {
                    const Key3 k = sorted3(x, y, third);
                    if (in_set(k)) return;
                    const Subface& g = subfaces_.at(k);
                    if (g.facet != f.facet || !in_circumcircle(g, p)) return;
                    faces.push_back(k);
                });
            }
        }
        // The segment p splits, if it does: a subsegment of it on a cavity's boundary would make
        // a piece of three points of one line (see below).
        const std::uint32_t* split_segment =
            split.edge == ~0ull ? nullptr : subsegments_.find(split.edge);
        while (true) {
            pieces.clear();
            split.exempt.clear();
            std::size_t bad = faces.size();
            for (std::size_t i = 0; i < faces.size() && bad == faces.size(); ++i) {
                const Subface& f = subfaces_.at(faces[i]);
                const int drop = planes_[f.facet].drop;
                const Sign orientation = triangulation::projected_orient(
                    point(f.oriented[0]), point(f.oriented[1]), point(f.oriented[2]), drop);
                for (unsigned e = 0; e < 3; ++e) {
                    const VertIdx x = f.oriented[e], y = f.oriented[(e + 1) % 3];
                    const std::uint64_t key = edge_key(x, y);
                    if (key == split.edge) continue;
                    bool inner = false;
                    edge_subfaces_.for_each(key, [&](VertIdx third) {
                        const Key3 other = sorted3(x, y, third);
                        if (!same_key(other, faces[i]) && in_set(other) &&
                            subfaces_.at(other).facet == f.facet)
                            inner = true;
                    });
                    // A subsegment of the segment p splits cannot bound a piece: p on that
                    // segment's line is exactly inside no circumcircle through the two ends of
                    // another of its pieces (the line meets the circle there only), so a subface
                    // grown across it came from p's rounding off the line. Its piece would be
                    // three points of one line, rounded apart (a needle beside a subsegment
                    // 1e-12 long whose fan then left a segment vertex out of the other facet).
                    const std::uint32_t* on_segment =
                        split_segment == nullptr ? nullptr : subsegments_.find(key);
                    if (inner) {
                        split.exempt.push_back(key);
                    } else if ((on_segment != nullptr && *on_segment == *split_segment) ||
                               triangulation::projected_orient(point(x), point(y), p, drop) !=
                                   orientation) {
                        bad = i;
                        break;
                    } else {
                        pieces.push_back({{x, y, v}, f.facet});
                    }
                }
            }
            if (bad == faces.size()) break;
            if (bad < initial.size()) return false;
            if (bad < synced) {
                indexed.erase(faces[bad]);
                --synced;
            }
            faces.erase(faces.begin() + static_cast<std::ptrdiff_t>(bad));
        }
        // Each vertex starts and ends at most one boundary edge of its facet's cavity.
        std::vector<std::uint64_t>& starts = piece_starts_;
        std::vector<std::uint64_t>& ends = piece_ends_;
        starts.clear();
        ends.clear();
        for (const Subface& piece : pieces) {
            const std::uint64_t facet = std::uint64_t{piece.facet} << 32;
            starts.push_back(facet | piece.oriented[0]);
            ends.push_back(facet | piece.oriented[1]);
        }
        for (std::vector<std::uint64_t>* keys : {&starts, &ends}) {
            std::sort(keys->begin(), keys->end());
            if (std::adjacent_find(keys->begin(), keys->end()) != keys->end()) return false;
        }
        std::vector<TetIdx>& around = facet_cavity_tets_;
        for (const Key3& k : faces) {
            tets_with(around, k[0], k[1], k[2]);
            for (const TetIdx t : around)
                if (std::find(seeds.begin(), seeds.end(), t) == seeds.end()) seeds.push_back(t);
        }
        split.faces = std::move(faces);
        if (split.faces.size() > kScannedFaces)
            split.face_set.insert(split.faces.begin(), split.faces.end());
        if (split.exempt.size() > 2 * kScannedFaces)
            split.exempt_set.insert(split.exempt.begin(), split.exempt.end());
        return true;
    }

    mutable std::vector<TetIdx> facet_cavity_tets_;  ///< facet_cavity's scratch (tets_with)
    mutable std::vector<std::uint64_t> piece_starts_, piece_ends_;  ///< facet_cavity's scratch

    /// Whether p (a point of f's facet, up to rounding) lies strictly inside the circumcircle of
    /// subface f: inside its equatorial sphere, whose trace on the facet's plane is that circle
    /// (a projection to a coordinate plane would distort the circle into an ellipse).
    bool in_circumcircle(const Subface& f, const double* p) const {
        return predicates::in_equatorial_sphere_3d(p, point(f.oriented[0]), point(f.oriented[1]),
                                                   point(f.oriented[2])) == Sign::Positive;
    }

    /// The rounded centroid of subface f when it lies strictly inside f in the facet's
    /// projection `drop` (exact); nothing otherwise (a subface flat in the projection).
    std::optional<std::array<double, 3>> point_inside(const Subface& f, int drop) const {
        const double* a = point(f.oriented[0]);
        const double* b = point(f.oriented[1]);
        const double* d = point(f.oriented[2]);
        std::array<double, 3> m;
        for (int k = 0; k < 3; ++k) m[k] = (a[k] + b[k] + d[k]) / 3;
        const Sign orientation = triangulation::projected_orient(a, b, d, drop);
        if (orientation == Sign::Zero) return std::nullopt;
        const double* corner[3] = {a, b, d};
        for (int i = 0; i < 3; ++i)
            if (triangulation::projected_orient(corner[i], corner[(i + 1) % 3], m.data(), drop) !=
                orientation)
                return std::nullopt;
        return m;
    }

    /// Splits subface `key` (if still one) at its circumcentre, or the subsegments that point
    /// encroaches or lies beyond. Returns whether a point was inserted.
    bool split_subface(const Key3& key) {
        const Subface* found = subfaces_.find(key);
        if (found == nullptr) return false;
        const Subface face = *found;
        const int drop = planes_[face.facet].drop;
        std::array<double, 3> c = predicates::triangle_circumcenter_3d(
            point(face.oriented[0]), point(face.oriented[1]), point(face.oriented[2]));
        bool at_midpoint = false;  // c moved to the longest edge's midpoint (see below)
        // The subface's longest edge instead of its circumcentre: the subsegment is queued
        // (false), or c becomes the edge's midpoint, a point of the facet within rounding (true).
        const auto longest_edge_instead = [&]() {
            at_midpoint = true;
            ++counters_.longest_edge_subfaces;
            unsigned longest = 0;
            double length = -1;
            for (unsigned e = 0; e < 3; ++e) {
                const double* p = point(face.oriented[e]);
                const double* q = point(face.oriented[(e + 1) % 3]);
                double l = 0;
                for (int k = 0; k < 3; ++k) l = std::max(l, std::fabs(q[k] - p[k]));
                if (l > length) length = l, longest = e;
            }
            const VertIdx x = face.oriented[longest];
            const VertIdx y = face.oriented[(longest + 1) % 3];
            if (subsegments_.count(edge_key(x, y)) != 0) {
                segment_queue_.push_front(edge_key(x, y));
                ++counters_.encroached_segments;
                return false;
            }
            for (int k = 0; k < 3; ++k) c[k] = 0.5 * point(x)[k] + 0.5 * point(y)[k];
            return true;
        };
        // A needle subface (a side 1e-12 long beside a segment, its corners rounded off the
        // facet's plane by 1e-17) has its own plane tilted from the facet's, and its circumcentre
        // lay 2e-9 off the facet on a turned cube: a facet vertex beyond rounding of its facet
        // (the exact check of `exactmesh check` found a face on no facet). Splitting the longest
        // edge there instead split the segment beside it down to nothing (20,000 subsegment
        // splits, 77 s, on another turned cube).
        // It is replaced by the point of the facet's plane equidistant from the subface's
        // corners, constructed from the corners and the facet's vertices and rounded once (the
        // tilt moves the centre far less than the subface's size); should that still be off
        // (or not exist), the longest edge is split.
        if (off_facet_plane(c.data(), face.facet)) {
            const auto on_plane = circumcentre_on_facet_plane(face);
            ++counters_.projected_circumcentres;
            if (on_plane) c = *on_plane;
            if ((!on_plane || off_facet_plane(c.data(), face.facet)) && !longest_edge_instead())
                return false;
        }
        // Walk in the facet's projection from the subface to the one holding c, along the
        // segment from a point inside the subface (its rounded centroid, when exactly inside)
        // to c: each subface is left by the edge that segment crosses, and the subsegment it
        // meets is the one between the subface and its centre, which a vertex of the subface
        // encroaches [Shewchuk97a, the 2D lemma in each facet]. Leaving by the first edge c lies
        // beyond (as before) could meet another: on the wing's far-field side a flat subface's
        // centre 2.9 beyond the side's edge reached the piece of that edge at the box's corner
        // each time, and frontal insertion at size 0.05 halved it 15 times down to 2^-20 of
        // the size (flat tetrahedra of 0.0016 degrees there after sliver removal).
        const std::optional<std::array<double, 3>> from = point_inside(face, drop);
        const auto crosses = [&](VertIdx x, VertIdx y) {
            const Sign sx = triangulation::projected_orient(from->data(), c.data(), point(x), drop);
            const Sign sy = triangulation::projected_orient(from->data(), c.data(), point(y), drop);
            return sx != sy || sx == Sign::Zero;
        };
        Subface at = face;
        for (std::size_t steps = 0;; ++steps) {
            if (steps > subfaces_.size() + 8) {
                ++counters_.rejected_points;
                return false;
            }
            const VertIdx* o = at.oriented.data();
            const Sign orientation =
                triangulation::projected_orient(point(o[0]), point(o[1]), point(o[2]), drop);
            int outside = -1, zeros = 0, zero_edge = -1;
            for (int i = 0; i < 3; ++i) {
                const Sign s = triangulation::projected_orient(point(o[i]), point(o[(i + 1) % 3]),
                                                               c.data(), drop);
                if (s == Sign::Zero) {
                    ++zeros;
                    zero_edge = i;
                } else if (s != orientation) {
                    if (outside < 0) outside = i;  // the first such edge, without `from`
                    if (!from || crosses(o[i], o[(i + 1) % 3])) {
                        outside = i;
                        break;
                    }
                }
            }
            if (outside >= 0) {
                const VertIdx x = o[outside], y = o[(outside + 1) % 3];
                if (subsegments_.count(edge_key(x, y)) != 0) {
                    segment_queue_.push_front(edge_key(x, y));
                    ++counters_.encroached_segments;
                    return false;
                }
                const Key3 here = sorted3(o[0], o[1], o[2]);
                bool moved = false;
                for (const Key3& k : subfaces_on_edge(x, y)) {
                    const Subface& next = subfaces_.at(k);
                    if (k == here || next.facet != at.facet) continue;
                    at = next;
                    moved = true;
                    break;
                }
                if (!moved) {
                    ++counters_.rejected_points;
                    return false;
                }
                continue;
            }
            if (zeros >= 2) {  // on a vertex in projection
                // The circumcentre is a vertex already: the subface was left out of that
                // vertex's facet cavity (dropped there, the facet not Delaunay) and can never be
                // split at it. A needle rod 1e5 times longer than wide retried such subfaces
                // 53,000 times on its way into the Steiner budget. Its longest edge is split
                // instead: the subsegment, or the edge's midpoint as a facet point.
                if (!at_midpoint) {
                    if (!longest_edge_instead()) return false;
                    at = face;
                    steps = 0;
                    continue;
                }
                ++counters_.rejected_points;
                return false;
            }
            Split split;
            std::vector<TetIdx> seeds;
            const VertIdx v = m_.vertex_count();
            std::vector<Subface> pieces;
            // The facet cavity grows from the subface holding c (both subfaces at an edge c lies
            // on); when that fails, it is the starting subfaces alone. A point within rounding
            // of an edge that is not a subsegment (in the projection; the 2D chain rule's square
            // of half-width 2^-40 of the point) tries both subfaces at that edge before the one
            // alone: the centre of four cocircular points (a square's edge midpoints) rounded an
            // ulp off their diagonal went into one subface alone, and the other's centre, an ulp
            // away, made an edge of 1e-16 (a rotated cube).
            std::vector<Key3> initial{sorted3(o[0], o[1], o[2])};
            std::vector<Key3> beside;
            if (zeros == 1) {
                const VertIdx x = o[zero_edge], y = o[(zero_edge + 1) % 3];
                if (subsegments_.count(edge_key(x, y)) != 0) {
                    segment_queue_.push_front(edge_key(x, y));
                    ++counters_.encroached_segments;
                    return false;
                }
                initial = subfaces_on_edge(x, y);
            } else {
                // Within rounding of a subsegment (the 3D form the exact checks read segment
                // vertices by) is on it: the subsegment is split instead, even where the facet
                // is sharp at it. A wedge prism's subface, right-angled at a corner facing the
                // segment, had its circumcentre an ulp beside the subsegment's midpoint, where
                // the segment was later split: two vertices an ulp apart, and `exactmesh check`
                // read the facet point as the segment's.
                for (int i = 0; i < 3; ++i) {
                    const VertIdx x = o[i], y = o[(i + 1) % 3];
                    if (subsegments_.count(edge_key(x, y)) != 0 &&
                        predicates::within_rounding_of_segment_3d(c.data(), point(x), point(y))) {
                        segment_queue_.push_front(edge_key(x, y));
                        ++counters_.encroached_segments;
                        return false;
                    }
                }
                const auto cp = triangulation::project_facet_point(c.data(), drop);
                for (int i = 0; i < 3 && beside.empty(); ++i) {
                    const VertIdx x = o[i], y = o[(i + 1) % 3];
                    if (subsegments_.count(edge_key(x, y)) != 0) continue;
                    const auto xp = triangulation::project_facet_point(point(x), drop);
                    const auto yp = triangulation::project_facet_point(point(y), drop);
                    if (predicates::within_rounding_of_segment(cp.data(), xp.data(), yp.data()))
                        beside = subfaces_on_edge(x, y);
                }
            }
            const std::pair<const std::vector<Key3>*, bool> attempts[] = {
                {&initial, true}, {&beside, true}, {&beside, false}, {&initial, false}};
            bool valid = false;
            for (const auto& [start, grow] : attempts) {
                if (start->empty()) continue;
                split = Split{};
                pieces.clear();
                seeds.clear();
                if (facet_cavity(c.data(), *start, v, split, pieces, seeds, grow) &&
                    build_cavity(c.data(), seeds, split)) {
                    valid = true;
                    break;
                }
            }
            if (!valid || !boundary_point_allowed(c.data())) {
                ++counters_.rejected_points;
                return false;
            }
            // A subsegment of the cavity that c encroaches is split instead (unless the
            // facet is sharp at it: points on the facet do not split it).
            if (queue_encroached_segments(c.data(), at.facet)) return false;
            commit(c, VertexFeature3::Facet, at.facet, 0.0, split, pieces, {});
            ++counters_.subface_splits;
            return true;
        }
    }

    /// Queues (at the front) the subsegments among the cavity's edges that p encroaches
    /// (strictly inside the diametral sphere); returns whether there was one. p a point of
    /// `facet` (kNone: inside the domain) skips the subsegments it is sharp at.
    bool queue_encroached_segments(const double* p, std::uint32_t facet = kNone) {
        bool any = false;
        for (const TetIdx t : cavity_) {
            const unsigned mask = boundary_corners(t);
            if (corner_count(mask) < 2) continue;
            for (const auto& e : kEdges) {
                if (!boundary_edge(mask, e)) continue;
                const VertIdx a = m_.vertex(t, e[0]), b = m_.vertex(t, e[1]);
                const std::uint64_t key = edge_key(a, b);
                if (subsegments_.count(key) == 0) continue;
                if (facet != kNone && sharp_.shields_segment(subsegments_.at(key), facet)) continue;
                if (predicates::dot_sign_3d(p, point(a), point(b)) == Sign::Negative) {
                    segment_queue_.push_front(key);
                    ++counters_.encroached_segments;
                    any = true;
                }
            }
        }
        return any;
    }

    /// Queues (at the front) the subfaces among the cavity's faces that p encroaches (strictly
    /// inside the equatorial sphere); returns whether there was one.
    bool queue_encroached_subfaces(const double* p) {
        bool any = false;
        for (const TetIdx u : cavity_) {
            const unsigned mask = boundary_corners(u);
            if (corner_count(mask) < 3) continue;
            for (unsigned k = 0; k < 4; ++k) {
                if (!boundary_face(mask, k)) continue;
                const Key3 key = face_key(u, k);
                if (subfaces_.count(key) == 0) continue;
                if (predicates::in_equatorial_sphere_3d(p, point(key[0]), point(key[1]),
                                                        point(key[2])) == Sign::Positive) {
                    subface_queue_.push_front(key);
                    ++counters_.encroached_subfaces;
                    any = true;
                }
            }
        }
        return any;
    }

    /// Tries to split a bad tetrahedron at its circumcentre.
    /// Returns true when the split was deferred: subsegments or subfaces were queued instead.
    /// The outcome of walk_to.
    enum class Walk { Reached, Blocked, Failed };

    /// Visibility walk from tetrahedron `from` towards p (exact orient3d, rotating the first
    /// face tried so that it cannot cycle); stopped by a subface or the domain boundary
    /// (Blocked, with that face in `blocking`). Reached: p is in or on tetrahedron `at`. With
    /// `path`, every tetrahedron visited is appended to it, `from` and `at` included.
    Walk walk_to(TetIdx from, const double* p, TetIdx& at, Key3& blocking,
                 std::vector<TetIdx>* path = nullptr) const {
        TetIdx s = from;
        std::uint32_t rotation = 0;
        for (std::size_t steps = 0;; ++steps) {
            if (steps > 4 * std::size_t{m_.tet_slots()} + 16) return Walk::Failed;
            if (path != nullptr) path->push_back(s);
            int exit = -1;
            for (unsigned i = 0; i < 4; ++i) {
                const unsigned k = (i + rotation) & 3u;
                const unsigned* lf = kFaceVertex[k];
                if (predicates::orient3d(point(m_.vertex(s, lf[0])), point(m_.vertex(s, lf[1])),
                                         point(m_.vertex(s, lf[2])), p) == Sign::Negative) {
                    exit = static_cast<int>(k);
                    break;
                }
            }
            ++rotation;
            if (exit < 0) {
                at = s;
                return Walk::Reached;
            }
            const Key3 key = face_key(s, static_cast<unsigned>(exit));
            const FaceIdx g = m_.adj[4 * s + static_cast<unsigned>(exit)];
            if (g == kNone || is_subface_key(key)) {
                blocking = key;
                return Walk::Blocked;
            }
            s = triangulation::tet_of(g);
        }
    }

    /// The mesh in ConformingMesh3 form (live tetrahedra renumbered in slot order).
    ConformingMesh3 finish() const {
        ConformingMesh3 result = finish_features();
        const TetIdx slots = m_.tet_slots();
        std::vector<TetIdx> new_index(slots, kNone);
        TetIdx kept = 0;
        for (TetIdx t = 0; t < slots; ++t)
            if (!m_.is_dead(t)) new_index[t] = kept++;
        result.mesh.tets.reserve(4 * std::size_t{kept});
        result.mesh.neighbors.reserve(4 * std::size_t{kept});
        for (TetIdx t = 0; t < slots; ++t) {
            if (m_.is_dead(t)) continue;
            for (unsigned k = 0; k < 4; ++k) {
                result.mesh.tets.push_back(m_.vertex(t, k));
                const FaceIdx g = m_.adj[4 * t + k];
                result.mesh.neighbors.push_back(g == kNone ? kNone
                                                           : new_index[triangulation::tet_of(g)]);
            }
            if (!attributes_.empty()) result.tet_attributes.push_back(attributes_[t]);
            if (!max_volumes_.empty()) result.tet_max_volume.push_back(max_volumes_[t]);
        }
        result.mesh.xyz = m_.xyz;
        return result;
    }

    /// The mesh for a caller that goes on working on it (sliver removal's linked entry):
    /// finish()'s ConformingMesh3 without its tetrahedra and coordinates, whose region
    /// attributes and volume bounds are per slot of the second, the working mesh itself with
    /// vertex_tet filled (dead slots included). Building finish()'s Tetrahedralization3, only
    /// for sliver removal to link its faces again, took a fifth of sliver removal's time at
    /// 7 10^5 tetrahedra. The refinement is over: this object is left without a mesh.
    std::pair<ConformingMesh3, TetMesh3> take_linked() {
        ConformingMesh3 result = finish_features();
        for (std::vector<double>* values : {&attributes_, &max_volumes_})
            if (!values->empty()) values->resize(m_.tet_slots(), 0.0);
        result.tet_attributes = std::move(attributes_);
        result.tet_max_volume = std::move(max_volumes_);
        vertex_tet_.resize(m_.vertex_count(), kNone);
        m_.vertex_tet = std::move(vertex_tet_);
        TetMesh3 linked = std::move(m_);
        m_ = {};
        return {std::move(result), std::move(linked)};
    }

  private:
    /// finish()'s result but for the tetrahedra, their region values and the coordinates.
    ConformingMesh3 finish_features() const {
        ConformingMesh3 result;
        result.input_vertex_count = out_.input_vertex_count;
        result.vertex_feature = out_.vertex_feature;
        result.feature_index = out_.feature_index;
        result.segments = out_.segments;
        // Subsegments and subfaces in a deterministic order.
        std::vector<std::pair<std::uint64_t, std::uint32_t>> subsegments = subsegments_.entries();
        std::sort(subsegments.begin(), subsegments.end());
        for (const auto& [key, segment] : subsegments) {
            result.subsegments.insert(result.subsegments.end(),
                                      {static_cast<VertIdx>(key >> 32), static_cast<VertIdx>(key)});
            result.subsegment_segment.push_back(segment);
        }
        std::vector<std::pair<Key3, Subface>> subfaces = subfaces_.entries();
        std::sort(subfaces.begin(), subfaces.end(),
                  [](const auto& x, const auto& y) { return x.first < y.first; });
        for (const auto& [key, face] : subfaces) {
            result.subfaces.insert(result.subfaces.end(), face.oriented.begin(),
                                   face.oriented.end());
            result.subface_facet.push_back(face.facet);
        }
        return result;
    }
};

}  // namespace exactmesh::generators::restricted_3d
