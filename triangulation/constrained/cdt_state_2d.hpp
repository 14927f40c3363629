// SPDX-License-Identifier: MIT
// Internal to triangulation/: CdtState, the one state of the constrained Delaunay builder, which
// its phases (cdt_phases_2d.hpp) work on and ConstrainedTriangulation2 owns; with the primitives
// every phase edits it through.
//
// State: the Delaunay2Core mesh (infinite vertex, twin half-edges) plus, per half-edge, the
// input segment it carries (kNone when unconstrained; both halves of an edge agree), and per
// vertex one half-edge leaving it, so a segment's walk starts in O(degree). Every operation
// that rewrites triangles writes all of its vertices again, which keeps vertex_edge exact.
// Once the domain is marked (removed non-empty: exterior and holes; attribute: regions), both
// are kept per slot through every edit: a new triangle takes the side of the triangle it
// replaces.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "triangulation/constrained/constrained_2d.hpp"
#include "triangulation/constrained/constrained_triangulation_2d.hpp"
#include "triangulation/delaunay/delaunay_2d_core.hpp"

namespace exactmesh::triangulation::detail {

struct Piece {
    VertIdx a, b;           // mesh vertices
    std::uint32_t segment;  // input segment
};

/// One crossed edge kept for ConstrainedTriangulation2's cavity fan.
struct FanEdge {
    VertIdx u, v;
    EdgeIdx outer;
    std::uint32_t segment;
};

/// The scratch of ordering a cavity's boundary into its fan (one per thread that writes fans).
struct FanScratch {
    std::vector<FanEdge> fan;            // the cavity's new triangles, in order
    std::vector<std::uint32_t> leaving;  // per vertex: the boundary edge leaving it
};

struct CdtState {
    /// pslg's spans must outlive the state (constrained_delaunay_2d: the call; the
    /// ConstrainedTriangulation2: its own copies).
    CdtState(const Pslg& pslg_in, const Cdt2Options& options_in)
        : pslg(pslg_in),
          options(options_in),
          core(pslg_in.xy, delaunay_options(options_in)),
          mesh(core.mesh) {}
    CdtState(const CdtState&) = delete;
    CdtState& operator=(const CdtState&) = delete;

    // ---- input and the mesh ------------------------------------------------------------------
    Pslg pslg;
    Cdt2Options options;
    detail::Delaunay2Core core;
    TriMesh2& mesh;
    std::vector<std::uint32_t> segment_of;  // per half-edge
    std::vector<EdgeIdx> vertex_edge;       // per mesh vertex
    std::uint32_t input_count = 0;
    bool collinear = false;     // every input point on one line: no triangle (build stopped)
    VertIdx box_first = kNone;  // the enclosing box's four corners, when enclosed

    // ---- segment recovery ----------------------------------------------------------------------
    std::vector<Piece> work;                           // pieces still to recover (a stack)
    std::vector<std::array<VertIdx, 2>> segment_ends;  // per input segment: its mesh vertices
    std::vector<std::array<VertIdx, 2>> segment_line;  // per input segment: its chain rule's line
    /// Per edge key: the segments other than segment_of whose chains use the edge (see mark).
    std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> shared;
    std::vector<TriIdx> flip_stack;
    std::vector<std::uint8_t> in_cavity;  // per triangle slot, scratch of recover_by_cavity
    std::uint64_t work_done = 0;          // steps counted by guard()

    // ---- the result: counters, warnings, later the output ------------------------------------
    Cdt2Result result;

    // ---- domain --------------------------------------------------------------------------------
    std::vector<std::uint8_t> removed;  // per triangle slot; empty until the domain is marked
    std::vector<double> attribute;      // per triangle slot; empty without regions

    // ---- incremental editing (ConstrainedTriangulation2) -------------------------------------
    std::vector<TriIdx> touched;              // slots written since clear_touched()
    std::vector<std::uint32_t> cavity_stamp;  // per slot: == stamp when in the current cavity
    std::uint32_t stamp = 0;
    std::vector<TriIdx> cavity;
    std::vector<EdgeIdx> boundary;  // cavity boundary, half-edges inside the cavity
    std::vector<EdgeIdx> encroached_edges;
    FanScratch fan_scratch;  // write_fan's
    std::vector<TriIdx> fan_slots;
    std::vector<std::size_t> apart_slot_begin;  // insert_probed_apart: each fan's first slot
    std::vector<FanScratch> apart_scratch;      // insert_probed_apart: one per chunk
    CavityProbe probe;  // insert_in_cavity's: its cavity, boundary and encroached edges
    ConstrainedTriangulation2Counters edit_counters;

    static Delaunay2Options delaunay_options(const Cdt2Options& o) {
        Delaunay2Options d;
        d.order = o.order;
        d.seed = o.seed;
        d.progress = o.progress;
        return d;
    }

    /// After mark_domain: removed (and attribute) follow every edit.
    bool domain_marked() const { return !removed.empty(); }
    bool in_domain(TriIdx t) const {
        return !mesh.is_dead(t) && !mesh.is_infinite(t) && (removed.empty() || removed[t] == 0);
    }

    // ---- mesh editing -------------------------------------------------------------------
    TriIdx new_triangle() {
        const TriIdx t = mesh.new_triangle();
        grow_slots();
        return t;
    }
    /// new_triangle `count` times, into `slots` (one growth of each array).
    void new_triangles(std::size_t count, std::vector<TriIdx>& slots) {
        mesh.new_triangles(count, slots);
        grow_slots();
    }
    /// The per-slot arrays follow mesh's slots (after mesh.new_triangle, also the flip kernel's).
    void grow_slots() {
        if (segment_of.size() < mesh.tv.size()) segment_of.resize(mesh.tv.size(), kNone);
        if (domain_marked() && removed.size() < mesh.triangle_slots()) {
            removed.resize(mesh.triangle_slots(), 0);
            if (!attribute.empty()) attribute.resize(mesh.triangle_slots(), 0.0);
        }
    }
    void set(TriIdx t, VertIdx a, VertIdx b, VertIdx c) {
        mesh.tv[3 * t] = a;
        mesh.tv[3 * t + 1] = b;
        mesh.tv[3 * t + 2] = c;
        rewritten(t);
    }
    /// Triangle t's vertices were just written (by set or the flip kernel): vertex_edge points
    /// into it, and an edit after marking the domain records it.
    void rewritten(TriIdx t) {
        for (unsigned k = 0; k < 3; ++k) {
            const VertIdx v = mesh.tv[3 * t + k];
            if (v != kInfinite) vertex_edge[v] = 3 * t + k;
        }
        if (domain_marked()) touched.push_back(t);
    }
    /// Once the domain is marked: triangle t lies on the same side of every constraint as the
    /// triangle whose marks are `side` (removed flag, attribute).
    struct Side {
        std::uint8_t removed = 0;
        double attribute = 0.0;
    };
    Side side_of(TriIdx t) const {
        if (!domain_marked()) return {};
        return {removed[t], attribute.empty() ? 0.0 : attribute[t]};
    }
    void put_on_side(TriIdx t, const Side& side) {
        if (!domain_marked()) return;
        removed[t] = side.removed;
        if (!attribute.empty()) attribute[t] = side.attribute;
    }
    /// Links a new half-edge to a surviving outer one, keeping its constraint.
    void link_outer(EdgeIdx e, EdgeIdx outer, std::uint32_t segment) {
        mesh.link(e, outer);
        segment_of[e] = segment;
    }
    void link_inner(EdgeIdx e, EdgeIdx f, std::uint32_t segment = kNone) {
        mesh.link(e, f);
        segment_of[e] = segment_of[f] = segment;
    }
    void mark(EdgeIdx e, std::uint32_t segment) {
        const std::uint32_t old = segment_of[e];
        if (old != kNone && old != segment) {
            // One edge, pieces of two segments (overlapping, or one bent through the other's
            // vertex): segment_of keeps the smallest, shared every other one, so that a later
            // bend or split of the piece answers to each segment's chain (issue 11: a unit
            // segment's piece shared with a 1e-320 segment was bent by the unit one's rule alone).
            auto& others = shared[edge_key(mesh.origin(e), mesh.destination(e))];
            const std::uint32_t extra = std::max(old, segment);
            if (std::find(others.begin(), others.end(), extra) == others.end())
                others.push_back(extra);
        }
        const std::uint32_t s = std::min(old, segment);
        segment_of[e] = segment_of[mesh.twin[e]] = s;
    }
    static std::uint64_t edge_key(VertIdx u, VertIdx v) {
        return (std::uint64_t{std::min(u, v)} << 32) | std::max(u, v);
    }
    /// The segments other than segment_of whose chains use the edge u - v (usually none).
    std::vector<std::uint32_t> shared_segments(VertIdx u, VertIdx v) const {
        const auto it = shared.find(edge_key(u, v));
        return it == shared.end() ? std::vector<std::uint32_t>{} : it->second;
    }
    /// The edge u - v stops being a piece: forget its other segments (returned).
    std::vector<std::uint32_t> release_shared(VertIdx u, VertIdx v) {
        const auto it = shared.find(edge_key(u, v));
        if (it == shared.end()) return {};
        std::vector<std::uint32_t> others = std::move(it->second);
        shared.erase(it);
        return others;
    }
    VertIdx apex(EdgeIdx e) const { return mesh.tv[prev_edge(e)]; }

    /// The half-edge u -> v, or kNone. Walks the stars of u and v in step, so the cost is
    /// O(min(degree u, degree v)): refinement between nested squares 1e-5 apart builds fans of
    /// thousands of slivers at one vertex, and a lookup of each fan edge from its centre made
    /// restoring Delaunay after a boundary split quadratic (issue 11: minutes for 12 vertices).
    EdgeIdx find_edge(VertIdx u, VertIdx v) const {
        const EdgeIdx first_u = vertex_edge[u], first_v = vertex_edge[v];
        EdgeIdx e = first_u, f = first_v;
        bool u_done = false, v_done = false;
        while (!u_done || !v_done) {
            if (!u_done) {
                if (mesh.destination(e) == v) return e;
                e = mesh.twin[prev_edge(e)];
                u_done = e == first_u;
            }
            if (!v_done) {
                if (mesh.destination(f) == u) return mesh.twin[f];
                f = mesh.twin[prev_edge(f)];
                v_done = f == first_v;
            }
        }
        return kNone;
    }

    VertIdx add_vertex(double x, double y) {
        mesh.xy.push_back(x);
        mesh.xy.push_back(y);
        const VertIdx v = mesh.vertex_count() - 1;
        core.input_index.push_back(v);  // added vertices follow the inputs in the output
        core.merged_into.push_back(static_cast<VertIdx>(core.merged_into.size()));
        vertex_edge.push_back(kNone);
        return v;
    }

    /// Undoes add_vertex for a probe that no triangle uses (a located point, or a rounded
    /// point equal to an existing vertex).
    void remove_last_vertex() {
        mesh.xy.resize(mesh.xy.size() - 2);
        core.input_index.pop_back();
        core.merged_into.pop_back();
        vertex_edge.pop_back();
    }

    std::string vertex_name(VertIdx v) const {
        return "vertex " + std::to_string(core.input_index[v] + options.first_index);
    }
    std::string segment_name(std::uint32_t s) const {
        return std::to_string(s + options.first_index);
    }
};

}  // namespace exactmesh::triangulation::detail
