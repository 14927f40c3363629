// SPDX-License-Identifier: MIT
// Internal to triangulation/: the builder behind constrained_delaunay_2d (constrained_2d.cpp)
// and ConstrainedTriangulation2 (constrained_triangulation_2d.cpp, the incremental edits).
//
// State: the Delaunay2Core mesh (infinite vertex, twin half-edges) plus, per half-edge, the
// input segment it carries (kNone when unconstrained; both halves of an edge agree), and per
// vertex one half-edge leaving it, so a segment's walk starts in O(degree). Every operation
// that rewrites triangles writes all of its vertices again, which keeps vertex_edge_ exact.
// After build(), removed_ (exterior and holes) and attribute_ (regions) are kept per slot
// through every edit: a new triangle takes the side of the triangle it replaces.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "triangulation/constrained_2d.hpp"
#include "triangulation/constrained_triangulation_2d.hpp"
#include "triangulation/delaunay_2d_core.hpp"

namespace exactmesh::triangulation::detail {

using predicates::Sign;

struct Piece {
    VertIdx a, b;           // mesh vertices
    std::uint32_t segment;  // input segment
};

class CdtBuilder {
  public:
    /// pslg's spans must outlive the builder (constrained_delaunay_2d: the call; the
    /// ConstrainedTriangulation2: its own copies).
    /// enclose_in_box: after recovering the segments, insert four corners of a box around
    /// every vertex, so that no segment lies on the convex hull (ConstrainedTriangulation2:
    /// splitting a hull segment at a rounded point could leave the hull non-convex); the
    /// corners never reach the output.
    CdtBuilder(const Pslg& pslg, const Cdt2Options& options, bool enclose_in_box = false)
        : pslg_(pslg),
          options_(options),
          enclose_in_box_(enclose_in_box),
          core_(pslg.xy, delaunay_options(options)),
          mesh_(core_.mesh) {}
    CdtBuilder(const CdtBuilder&) = delete;
    CdtBuilder& operator=(const CdtBuilder&) = delete;

    /// Triangulates, recovers the segments (and conforms), marks exterior, holes and regions.
    /// Returns false when the points are collinear (then finish() reports the pieces alone).
    bool build();
    /// The result in the caller's numbering; consumes the builder.
    Cdt2Result finish();

    // ---- incremental editing after build() (constrained_triangulation_2d.cpp) --------------
    const TriMesh2& mesh() const { return mesh_; }
    std::uint32_t segment_of(EdgeIdx e) const { return segment_of_[e]; }
    bool in_domain(TriIdx t) const {
        return !mesh_.is_dead(t) && !mesh_.is_infinite(t) && (removed_.empty() || removed_[t] == 0);
    }
    double attribute_of(TriIdx t) const { return attribute_.empty() ? 0.0 : attribute_[t]; }
    bool collinear() const { return collinear_; }
    std::uint32_t input_vertex_count() const { return input_count_; }
    std::span<const VertIdx> input_index() const { return core_.input_index; }
    std::array<VertIdx, 2> segment_ends(std::uint32_t s) const { return segment_ends_[s]; }
    EdgeIdx edge_between(VertIdx u, VertIdx v) const { return find_edge(u, v); }
    TriIdx locate(double x, double y) { return locate_point(x, y); }
    CavityInsertion insert_in_cavity(TriIdx t, double x, double y);
    std::span<const EdgeIdx> encroached_edges() const { return encroached_edges_; }
    VertIdx split_constrained_edge(EdgeIdx e, double x, double y);
    std::span<const TriIdx> touched() const { return touched_; }
    void clear_touched() { touched_.clear(); }
    const ConstrainedTriangulation2Counters& edit_counters() const { return edit_counters_; }
    void reserve(std::uint32_t vertices);

  private:
    Pslg pslg_;
    Cdt2Options options_;
    bool enclose_in_box_ = false;
    VertIdx box_first_ = kNone;  // the box's four corners, when enclosed
    void enclose_in_box();
    detail::Delaunay2Core core_;
    TriMesh2& mesh_;
    std::vector<std::uint32_t> segment_of_;  // per half-edge
    std::vector<EdgeIdx> vertex_edge_;       // per mesh vertex
    std::vector<TriIdx> flip_stack_;
    std::vector<std::uint8_t> in_cavity_;  // per triangle slot, scratch of recover_by_cavity
    std::vector<Piece> work_;
    std::vector<std::array<VertIdx, 2>> segment_ends_;  // per input segment: its mesh vertices
    Cdt2Result result_;
    std::uint32_t input_count_ = 0;
    std::uint64_t work_done_ = 0;

    static Delaunay2Options delaunay_options(const Cdt2Options& o) {
        Delaunay2Options d;
        d.order = o.order;
        d.seed = o.seed;
        return d;
    }

    // ---- mesh editing -------------------------------------------------------------------
    TriIdx new_triangle() {
        const TriIdx t = mesh_.new_triangle();
        if (segment_of_.size() < mesh_.tv.size()) segment_of_.resize(mesh_.tv.size(), kNone);
        if (domain_marked_ && removed_.size() < mesh_.triangle_slots()) {
            removed_.resize(mesh_.triangle_slots(), 0);
            if (!attribute_.empty()) attribute_.resize(mesh_.triangle_slots(), 0.0);
        }
        return t;
    }
    void set(TriIdx t, VertIdx a, VertIdx b, VertIdx c) {
        const VertIdx v[3] = {a, b, c};
        for (unsigned k = 0; k < 3; ++k) {
            mesh_.tv[3 * t + k] = v[k];
            if (v[k] != kInfinite) vertex_edge_[v[k]] = 3 * t + k;
        }
        if (domain_marked_) touched_.push_back(t);
    }
    /// Once the domain is marked: triangle t lies on the same side of every constraint as the
    /// triangle whose marks are `side` (removed flag, attribute).
    struct Side {
        std::uint8_t removed = 0;
        double attribute = 0.0;
    };
    Side side_of(TriIdx t) const {
        if (!domain_marked_) return {};
        return {removed_[t], attribute_.empty() ? 0.0 : attribute_[t]};
    }
    void put_on_side(TriIdx t, const Side& side) {
        if (!domain_marked_) return;
        removed_[t] = side.removed;
        if (!attribute_.empty()) attribute_[t] = side.attribute;
    }
    /// Links a new half-edge to a surviving outer one, keeping its constraint.
    void link_outer(EdgeIdx e, EdgeIdx outer, std::uint32_t segment) {
        mesh_.link(e, outer);
        segment_of_[e] = segment;
    }
    void link_inner(EdgeIdx e, EdgeIdx f, std::uint32_t segment = kNone) {
        mesh_.link(e, f);
        segment_of_[e] = segment_of_[f] = segment;
    }
    void mark(EdgeIdx e, std::uint32_t segment) {
        const std::uint32_t old = segment_of_[e];
        if (old != kNone && old != segment) {
            // One edge, pieces of two segments (overlapping, or one bent through the other's
            // vertex): segment_of_ keeps the smallest, shared_ every other one, so that a later
            // bend or split of the piece answers to each segment's chain (issue 11: a unit
            // segment's piece shared with a 1e-320 segment was bent by the unit one's rule alone).
            auto& others = shared_[edge_key(mesh_.origin(e), mesh_.destination(e))];
            const std::uint32_t extra = std::max(old, segment);
            if (std::find(others.begin(), others.end(), extra) == others.end())
                others.push_back(extra);
        }
        const std::uint32_t s = std::min(old, segment);
        segment_of_[e] = segment_of_[mesh_.twin[e]] = s;
    }
    static std::uint64_t edge_key(VertIdx u, VertIdx v) {
        return (std::uint64_t{std::min(u, v)} << 32) | std::max(u, v);
    }
    /// The segments other than segment_of_ whose chains use the edge u - v (usually none).
    std::vector<std::uint32_t> shared_segments(VertIdx u, VertIdx v) const {
        const auto it = shared_.find(edge_key(u, v));
        return it == shared_.end() ? std::vector<std::uint32_t>{} : it->second;
    }
    /// The edge u - v stops being a piece: forget its other segments (returned).
    std::vector<std::uint32_t> release_shared(VertIdx u, VertIdx v) {
        const auto it = shared_.find(edge_key(u, v));
        if (it == shared_.end()) return {};
        std::vector<std::uint32_t> others = std::move(it->second);
        shared_.erase(it);
        return others;
    }
    std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> shared_;
    VertIdx apex(EdgeIdx e) const { return mesh_.tv[prev_edge(e)]; }

    /// The half-edge u -> v, or kNone. Walks the stars of u and v in step, so the cost is
    /// O(min(degree u, degree v)): refinement between nested squares 1e-5 apart builds fans of
    /// thousands of slivers at one vertex, and a lookup of each fan edge from its centre made
    /// restoring Delaunay after a boundary split quadratic (issue 11: minutes for 12 vertices).
    EdgeIdx find_edge(VertIdx u, VertIdx v) const {
        const EdgeIdx first_u = vertex_edge_[u], first_v = vertex_edge_[v];
        EdgeIdx e = first_u, f = first_v;
        bool u_done = false, v_done = false;
        while (!u_done || !v_done) {
            if (!u_done) {
                if (mesh_.destination(e) == v) return e;
                e = mesh_.twin[prev_edge(e)];
                u_done = e == first_u;
            }
            if (!v_done) {
                if (mesh_.destination(f) == u) return mesh_.twin[f];
                f = mesh_.twin[prev_edge(f)];
                v_done = f == first_v;
            }
        }
        return kNone;
    }

    VertIdx add_vertex(double x, double y) {
        mesh_.xy.push_back(x);
        mesh_.xy.push_back(y);
        const VertIdx v = mesh_.vertex_count() - 1;
        core_.input_index.push_back(v);  // added vertices follow the inputs in the output
        core_.merged_into.push_back(static_cast<VertIdx>(core_.merged_into.size()));
        vertex_edge_.push_back(kNone);
        return v;
    }

    /// Undoes add_vertex for a probe that no triangle uses (a located point, or a rounded
    /// point equal to an existing vertex).
    void remove_last_vertex() {
        mesh_.xy.resize(mesh_.xy.size() - 2);
        core_.input_index.pop_back();
        core_.merged_into.pop_back();
        vertex_edge_.pop_back();
    }

    // ---- insertion with Lawson flips that never cross a constraint --------------------
    void insert_vertex(VertIdx p, TriIdx t);
    void split_triangle(TriIdx t, VertIdx p);
    void split_edge(EdgeIdx e, VertIdx p);
    void flip_if_needed(TriIdx t1);  // t1 = (p, u, v), tests edge u -> v
    /// Flips the edge of e (u -> v, apexes x and y) to x - y; returns the half-edge y -> x.
    EdgeIdx flip(EdgeIdx e);
    /// Lawson flips from the given edges until every unconstrained one is locally Delaunay.
    void restore_delaunay(std::vector<std::pair<VertIdx, VertIdx>>& edges);
    bool locally_delaunay(EdgeIdx e);

    // ---- segments ----------------------------------------------------------------------
    void prepare_segments();
    /// How the segment a -> b leaves vertex a: the half-edge a -> b itself, else a neighbour
    /// exactly on the ray a -> b, else the edge (of the triangle whose angle at a the segment
    /// enters) that it crosses first; each kNone when absent.
    struct StarExit {
        EdgeIdx edge = kNone;
        VertIdx on_ray = kNone;
        EdgeIdx entry = kNone;
    };
    StarExit star_exit(VertIdx a, VertIdx b);
    void insert_piece(const Piece& piece);
    /// The piece passes exactly through vertex v: recover its two parts instead (a warning).
    void split_piece_at_vertex(const Piece& piece, VertIdx v) {
        ++result_.counters.vertices_on_segments;
        result_.warnings.push_back("segment " + segment_name(piece.segment) + " passes through " +
                                   vertex_name(v) + "; split there");
        work_.push_back({v, piece.b, piece.segment});
        work_.push_back({piece.a, v, piece.segment});
    }
    void split_at_intersection(const Piece& piece, EdgeIdx h);
    /// Where piece (of one segment) and the constrained edge u - v (of segment other) are split.
    std::array<double, 2> crossing_point(const Piece& piece, VertIdx u, VertIdx v,
                                         std::uint32_t other);
    void recover_by_swaps(const Piece& piece, const std::vector<EdgeIdx>& crossed);
    void recover_by_cavity(const Piece& piece, const std::vector<EdgeIdx>& crossed);
    void triangulate_pseudo_polygon(VertIdx u, VertIdx v, std::span<const VertIdx> chain,
                                    std::vector<std::array<VertIdx, 3>>& out);
    /// A conforming piece to check (present: mark it) or, when encroached, to split.
    struct SplitTask {
        Piece piece;
        bool encroached;
    };
    void conform();
    /// Splits a missing piece (concentric shell or midpoint), inserts the point, queues both
    /// halves and every marked piece the insertion encroached.
    void split_piece(const Piece& piece, std::vector<SplitTask>& tasks);
    /// A vertex that a missing piece crosses exactly on it, or within rounding of its input
    /// segment's line and between its ends (the nearest), or kNone.
    VertIdx vertex_near_segment(const Piece& piece);
    /// w may bend the chain of `segment` between its vertices a and b (the check's chain rule).
    bool bend_candidate(std::uint32_t segment, VertIdx a, VertIdx b, VertIdx w) const;
    bool conforming_ = false;
    VertIdx first_split_vertex_ = 0;             // vertices from here on are conforming splits
    std::vector<std::uint32_t> segment_degree_;  // pieces at each earlier vertex
    std::vector<Piece> encroached_;
    bool on_ray(VertIdx a, VertIdx b, VertIdx x) const;
    void guard();

    // ---- domain --------------------------------------------------------------------------
    std::vector<std::uint8_t> removed_;  // per triangle slot
    std::vector<double> attribute_;      // per triangle slot
    TriIdx locate_point(double x, double y);
    /// Marks `value` on every triangle reached from start without crossing a constraint (or
    /// into the infinite vertex); calls reached(t) for each one marked.
    template <class Mark, class Reached>
    void flood(TriIdx start, std::vector<Mark>& mark_value, Mark value, Reached reached);
    /// Throws AmbiguousMarkPoint when hole or region `index` at (x, y), located in triangle t,
    /// lies on a segment or a vertex (which side it marks would be the walk's choice).
    void require_off_boundary(AmbiguousMarkPoint::Kind kind, std::size_t index, double x, double y,
                              TriIdx t);
    void remove_exterior_and_holes();
    void assign_regions();
    void collect_output();
    void collinear_output();
    bool collinear_ = false;

    // ---- incremental editing state ----------------------------------------------------------
    bool domain_marked_ = false;               // removed_ (and attribute_) follow every edit
    std::vector<TriIdx> touched_;              // slots written since clear_touched()
    std::vector<std::uint32_t> cavity_stamp_;  // per slot: == stamp_ when in the current cavity
    std::uint32_t stamp_ = 0;
    std::vector<TriIdx> cavity_;
    std::vector<EdgeIdx> boundary_;  // cavity boundary, half-edges inside the cavity
    std::vector<EdgeIdx> cycle_;     // the same, in order around the cavity
    std::vector<EdgeIdx> encroached_edges_;
    struct FanEdge {
        VertIdx u, v;
        EdgeIdx outer;
        std::uint32_t segment;
    };
    std::vector<FanEdge> fan_;  // the cavity's new triangles, in order
    std::vector<TriIdx> fan_slots_;
    ConstrainedTriangulation2Counters edit_counters_;
    /// Lawson flips from flip_stack_ (after split_triangle or split_edge).
    void drain_flip_stack();
    /// One attempt of split_constrained_edge at (x, y): true (and the new vertex) when the point
    /// lies on e or inside the quadrilateral of e's two triangles; the edges to check for
    /// Lawson flips are appended to `check`. Else nothing changes.
    bool try_split_at(EdgeIdx e, double x, double y,
                      std::vector<std::pair<VertIdx, VertIdx>>& check, VertIdx& vertex);
    /// The exact fan test of split_constrained_edge: p strictly inside both triangles' star.
    bool star_contains(VertIdx p, VertIdx a, VertIdx b, VertIdx c, VertIdx d);
    /// The half-edge (e or its twin) whose apex lies within rounding of e's segment, strictly
    /// between e's ends; kNone if neither.
    EdgeIdx near_apex(EdgeIdx e) const;
    /// The chain u - w - v replaces u - v = g, w the apex of g's triangle; returns w.
    VertIdx bend_through_apex(EdgeIdx g);
    /// bend_through_apex(near_apex(e)), or GeometryError when there is no such apex.
    VertIdx bend_at_apex(EdgeIdx e);
    /// Before refinement: every vertex within rounding of a segment becomes a vertex of it.
    void bend_through_near_vertices();

    std::string vertex_name(VertIdx v) const {
        return "vertex " + std::to_string(core_.input_index[v] + options_.first_index);
    }
    std::string segment_name(std::uint32_t s) const {
        return std::to_string(s + options_.first_index);
    }
};

}  // namespace exactmesh::triangulation::detail
