// SPDX-License-Identifier: MIT
// ConstrainedTriangulation2 (see constrained_triangulation_2d.hpp): the incremental edits of
// the constrained Delaunay builder over its CdtState (cdt_state_2d.hpp), which it owns:
// Bowyer-Watson cavity insertion and constrained edge splits.
//
// Cavity insertion, local picture: the cavity (triangles whose circumcircle holds p, reached
// from the start triangle across unconstrained edges) is replaced by the fan of triangles
// (u_i, v_i, p) over its boundary edges u_i -> v_i, walked in order around the cavity.
// The fan is valid when p lies strictly left of every boundary edge; for unconstrained edges
// this is the Delaunay lemma (p is in the inner circle and not in the outer one), for
// constrained edges it is checked, and a constrained edge with p on or beyond its line has p in
// its closed diametral circle (the part of the inner circumcircle beyond the edge is the minor
// cap, inside the diametral disk) whenever the inner apex does not encroach the edge: the
// refinement only inserts when no edge is encroached, so this reports an encroachment.
#include "triangulation/constrained/constrained_triangulation_2d.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <optional>
#include <span>
#include <string>
#include <utility>

#include "base/errors.hpp"
#include "base/huge_pages.hpp"
#include "base/number_text.hpp"
#include "predicates/angle_comparisons_2d.hpp"
#include "predicates/in_ellipse.hpp"
#include "predicates/incircle.hpp"
#include "predicates/orient2d.hpp"
#include "predicates/sos.hpp"
#include "triangulation/constrained/cdt_phases_2d.hpp"
#include "triangulation/constrained/cdt_state_2d.hpp"

namespace exactmesh::triangulation {

namespace detail {

namespace {

using predicates::Sign;

/// bend_through_apex(near_apex(e)), or GeometryError when there is no such apex.
VertIdx bend_at_apex(CdtState& cdt, EdgeIdx e);

void reserve(CdtState& cdt, std::uint32_t vertices) {
    const std::size_t v = vertices, slots = 2 * v + 8;  // triangles (finite and infinite) ~ 2 V
    cdt.mesh.xy.reserve(2 * v);
    cdt.mesh.tv.reserve(3 * slots);
    cdt.mesh.twin.reserve(3 * slots);
    cdt.segment_of.reserve(3 * slots);
    cdt.vertex_edge.reserve(v);
    cdt.core.input_index.reserve(v);
    cdt.core.merged_into.reserve(v);
    cdt.removed.reserve(slots);
    if (!cdt.attribute.empty()) cdt.attribute.reserve(slots);
    cdt.cavity_stamp.reserve(slots);
    for (const auto* array : {&cdt.mesh.tv, &cdt.mesh.twin, &cdt.segment_of, &cdt.vertex_edge,
                              &cdt.core.input_index, &cdt.core.merged_into, &cdt.cavity_stamp})
        advise_huge_pages(*array);
    advise_huge_pages(cdt.mesh.xy);
    advise_huge_pages(cdt.removed);
    advise_huge_pages(cdt.attribute);
}

/// A fresh cavity stamp (cdt.stamp, returned), with a stamp slot for every triangle slot; every
/// slot is cleared when the counter wraps, so no triangle holds the new value by accident.
std::uint32_t new_cavity_stamp(CdtState& cdt) {
    if (cdt.cavity_stamp.size() < cdt.mesh.triangle_slots())
        cdt.cavity_stamp.resize(cdt.mesh.triangle_slots(), 0);
    if (++cdt.stamp == 0) {
        std::fill(cdt.cavity_stamp.begin(), cdt.cavity_stamp.end(), 0u);
        cdt.stamp = 1;
    }
    return cdt.stamp;
}

/// The cavity's boundary (half-edges inside it, p strictly left of each) in order around p, into
/// scratch.fan: what each new triangle (u_i, v_i, p) keeps of its outer edge.
void order_fan(const TriMesh2& mesh, const std::uint32_t* segment_of,
               std::span<const EdgeIdx> boundary, std::size_t cavity_size, FanScratch& scratch) {
    // The boundary in order: after each boundary edge u -> v, the boundary edge leaving v. p sees
    // every boundary edge strictly from inside, so the boundary is one simple polygon around p
    // and each vertex starts exactly one boundary edge: a per-vertex table of the edge leaving it
    // (written for every origin before it is read, so it needs no clearing) orders the edges in
    // one pass, where turning about each vertex through the cavity's triangles cost a third of
    // the fan's work. A cavity pinched at a vertex or with an interior vertex would not close
    // after boundary.size() edges, or close early (never seen: the Delaunay lemma excludes it).
    // Each edge goes straight into the fan (what the new triangle keeps of it).
    //
    // A small boundary (nearly every one: about five edges) is ordered by scanning its own
    // origins instead: the table's entries are spread over all vertices, and reading back the
    // ones just written waited on their cache lines for a third of the fan's time (perf, 1.09M
    // triangles). The scan finds the same (unique) edge, so the fan is the same.
    const std::size_t boundary_size = boundary.size();
    constexpr std::size_t kScanned = 16;
    const bool scanned = boundary_size <= kScanned;
    VertIdx origins[kScanned];
    std::vector<std::uint32_t>& leaving = scratch.leaving;
    if (scanned) {
        for (std::size_t i = 0; i < boundary_size; ++i) origins[i] = mesh.origin(boundary[i]);
    } else {
        if (leaving.size() < mesh.vertex_count()) leaving.resize(mesh.vertex_count());
        for (std::size_t i = 0; i < boundary_size; ++i) {
            leaving[mesh.origin(boundary[i])] = static_cast<std::uint32_t>(i);
        }
    }
    const auto edge_leaving = [&](VertIdx v) -> std::uint32_t {
        if (!scanned) return leaving[v];
        std::uint32_t i = 0;
        while (i < boundary_size && origins[i] != v) ++i;
        return i;  // boundary_size when none: the assertion below stops
    };
    std::vector<FanEdge>& fan = scratch.fan;
    fan.clear();
    std::uint32_t current = 0;
    do {
        EM_ASSERT(current < boundary_size && fan.size() < boundary_size);
        const EdgeIdx e = boundary[current];
        const VertIdx v = mesh.destination(e);
        fan.push_back({mesh.origin(e), v, mesh.twin[e], segment_of[e]});
        current = edge_leaving(v);
    } while (current != 0);
    EM_ASSERT(fan.size() == boundary_size && fan.size() == cavity_size + 2);
}

/// Writes the fan (ordered by order_fan) around p into `slots` (fan[i] into slots[i]), the new
/// triangles on t's side of the domain. `boundary_vertices`: vertex_edge of the fan's boundary
/// vertices too (p's always; insert_probed_apart writes the others after every fan, in order).
void write_fan_triangles(CdtState& cdt, TriIdx t, VertIdx p, std::span<const FanEdge> fan,
                         std::span<const TriIdx> slots, bool boundary_vertices) {
    // What set, link_outer, put_on_side and link_inner do, in the same order, on the arrays
    // directly (the fan is most of the writes of a refinement): each triangle (u_i, v_i, p)
    // keeps its outer edge and its constraint, takes t's side of the domain.
    const std::size_t n = fan.size();
    const std::uint8_t removed = cdt.removed[t];
    const bool attributed = !cdt.attribute.empty();
    const double attribute = attributed ? cdt.attribute[t] : 0.0;
    VertIdx* tv = cdt.mesh.tv.data();
    EdgeIdx* twin = cdt.mesh.twin.data();
    EdgeIdx* vertex_edge = cdt.vertex_edge.data();
    std::uint32_t* segments = cdt.segment_of.data();
    for (std::size_t i = 0; i < n; ++i) {
        const TriIdx s = slots[i];
        const EdgeIdx e = 3 * s;
        const FanEdge& edge = fan[i];
        tv[e] = edge.u;
        tv[e + 1] = edge.v;
        tv[e + 2] = p;
        if (boundary_vertices) {
            if (edge.u != kInfinite) vertex_edge[edge.u] = e;
            if (edge.v != kInfinite) vertex_edge[edge.v] = e + 1;
        }
        vertex_edge[p] = e + 2;
        twin[e] = edge.outer;
        twin[edge.outer] = e;
        segments[e] = edge.segment;
        cdt.removed[s] = removed;
        if (attributed) cdt.attribute[s] = attribute;
    }
    // (v_i -> p) of triangle i meets (p -> u_{i+1}) of the next, u_{i+1} = v_i; the spokes
    // are unconstrained.
    for (std::size_t i = 0; i < n; ++i) {
        const EdgeIdx e = 3 * slots[i] + 1, f = 3 * slots[i + 1 == n ? 0 : i + 1] + 2;
        twin[e] = f;
        twin[f] = e;
        segments[e] = segments[f] = kNone;
    }
}

/// Replaces the cavity (its boundary half-edges in `boundary`, p strictly left of each) by the fan
/// of triangles (u_i, v_i, p) around p, the new triangles on t's side of the domain, touched.
void write_fan(CdtState& cdt, TriIdx t, VertIdx p, std::span<const TriIdx> cavity,
               std::span<const EdgeIdx> boundary) {
    order_fan(cdt.mesh, cdt.segment_of.data(), boundary, cavity.size(), cdt.fan_scratch);
    const std::size_t n = cdt.fan_scratch.fan.size();
    std::vector<TriIdx>& slots = cdt.fan_slots;
    slots.assign(cavity.begin(), cavity.end());
    if (slots.size() < n) cdt.new_triangles(n - slots.size(), slots);
    write_fan_triangles(cdt, t, p, cdt.fan_scratch.fan, slots, true);
    cdt.touched.insert(cdt.touched.end(), slots.begin(), slots.end());
    cdt.core.last_triangle = slots[0];
    ++cdt.edit_counters.cavity_insertions;
    cdt.edit_counters.cavity_triangles += cavity.size();
}

/// Which triangles a cavity's growth has met. The sequential insertion stamps the state's
/// per-slot array; a probe (which may run beside others) searches its own list while the cavity
/// is small (nearly always: about three triangles) and moves to its thread's stamps beyond.
struct StateStamps {
    std::vector<std::uint32_t>& stamp;
    std::uint32_t value;
    void prefetch(TriIdx u) const { __builtin_prefetch(&stamp[u]); }
    bool seen(TriIdx u, const std::vector<TriIdx>&) const { return stamp[u] == value; }
    void add(TriIdx u, const std::vector<TriIdx>&) { stamp[u] = value; }
};

struct ProbeVisits {
    static constexpr std::size_t kListed = 16;  // searched in the list up to this size
    CavityProbeScratch& scratch;
    std::size_t slots;
    bool stamped = false;
    void prefetch(TriIdx u) const {
        if (stamped) __builtin_prefetch(&scratch.stamp[u]);
    }
    bool seen(TriIdx u, const std::vector<TriIdx>& cavity) const {
        if (stamped) return scratch.stamp[u] == scratch.current;
        return std::find(cavity.begin(), cavity.end(), u) != cavity.end();
    }
    /// u joins `cavity` (pushed after this call).
    void add(TriIdx u, const std::vector<TriIdx>& cavity) {
        if (!stamped && cavity.size() >= kListed) {
            if (scratch.stamp.size() < slots) scratch.stamp.resize(slots, 0);
            if (++scratch.current == 0) {
                std::fill(scratch.stamp.begin(), scratch.stamp.end(), 0u);
                scratch.current = 1;
            }
            for (const TriIdx c : cavity) scratch.stamp[c] = scratch.current;
            stamped = true;
        }
        if (stamped) scratch.stamp[u] = scratch.current;
    }
};

/// The perturbed conflict of the point q (vertex rank `index`, above every vertex's) with
/// triangle u, as Delaunay2Core::conflict decides it for a vertex, counted in the probe.
[[gnu::always_inline]] inline bool probe_conflict(const CdtState& cdt, TriIdx u, const double* q,
                                                  VertIdx index, CavityProbe& probe) {
    const TriMesh2& mesh = cdt.mesh;
    const VertIdx* v = &mesh.tv[3 * u];
    if (v[0] == kInfinite || v[1] == kInfinite || v[2] == kInfinite) {
        int k = 0;
        while (v[k] != kInfinite) ++k;
        const double* a = mesh.point(v[(k + 1) % 3]);
        const double* b = mesh.point(v[(k + 2) % 3]);
        ++probe.orient_calls;
        const Sign s = predicates::orient2d(a, b, q);
        if (s != Sign::Zero) return s == Sign::Positive;
        const int axis = a[0] != b[0] ? 0 : 1;  // strictly between a and b on their line
        return (a[axis] < q[axis] && q[axis] < b[axis]) || (b[axis] < q[axis] && q[axis] < a[axis]);
    }
    ++probe.incircle_calls;
    const double* a = mesh.point(v[0]);
    const double* b = mesh.point(v[1]);
    const double* c = mesh.point(v[2]);
    Sign s = predicates::incircle(a, b, c, q);
    if (s == Sign::Zero) {
        const auto& rank = cdt.core.input_index;
        s = predicates::incircle_sos(a, b, c, q, rank[v[0]], rank[v[1]], rank[v[2]], index);
    }
    return s == Sign::Positive;
}

/// Fills probe (its x, y set) with what inserting the point from triangle t would do: the
/// conflict zone grown across unconstrained edges, its boundary, the outcome. Reads only.
template <class Visits>
void probe_cavity(const CdtState& cdt, TriIdx t, VertIdx index, CavityProbe& probe,
                  Visits& visits) {
    EM_ASSERT(cdt.domain_marked() && !cdt.mesh.is_dead(t) && !cdt.mesh.is_infinite(t));
    const TriMesh2& mesh = cdt.mesh;
    // t's constraints are read first in the growth below (cold: cache misses, as the stamps
    // and neighbours, see there).
    __builtin_prefetch(&cdt.segment_of[3 * t]);
    const double q[2] = {probe.x, probe.y};
    probe.start = t;
    probe.cavity.clear();
    probe.boundary.clear();
    probe.encroached.clear();
    probe.incircle_calls = probe.orient_calls = 0;
    if (!probe_conflict(cdt, t, q, index, probe)) {
        probe.outcome = CavityInsertion::NotInConflict;
        return;
    }
    std::vector<TriIdx>& cavity = probe.cavity;
    std::vector<EdgeIdx>& boundary = probe.boundary;
    visits.add(t, cavity);
    cavity.push_back(t);
    bool beyond_hull = false;
    for (std::size_t i = 0; i < cavity.size(); ++i) {
        const TriIdx c = cavity[i];
        // The three neighbours' stamps and vertices are usually cold (the refinement's cavities
        // are anywhere in the arrays): asked for together, their cache misses overlap instead
        // of following one another through the tests below.
        for (unsigned k = 0; k < 3; ++k) {
            const TriIdx u = triangle_of(mesh.twin[3 * c + k]);
            visits.prefetch(u);
            __builtin_prefetch(&mesh.tv[3 * u]);
        }
        for (unsigned k = 0; k < 3; ++k) {
            const EdgeIdx e = 3 * c + k;
            const TriIdx u = triangle_of(mesh.twin[e]);
            if (visits.seen(u, cavity)) continue;
            if (cdt.segment_of[e] != kNone) {
                boundary.push_back(e);
                continue;
            }
            if (probe_conflict(cdt, u, q, index, probe)) {
                if (mesh.is_infinite(u)) {
                    beyond_hull = true;  // outside the convex hull (exterior kept)
                    boundary.push_back(e);
                    continue;
                }
                visits.add(u, cavity);
                cavity.push_back(u);
                __builtin_prefetch(&mesh.twin[3 * u]);  // both read when u's turn comes
                __builtin_prefetch(&cdt.segment_of[3 * u]);
            } else {
                boundary.push_back(e);
            }
        }
    }
    if (beyond_hull) {
        probe.outcome = CavityInsertion::Outside;
        return;
    }
    // One pass over the boundary: a duplicate vertex first (whatever else is found), then a hull
    // edge p does not see (Outside), then the encroached constrained edges. p's side of an
    // unconstrained edge between two finite triangles is not computed: the Delaunay lemma puts p
    // strictly inside it (p in the inner circle, not in the outer one; a point of the open chord
    // lies strictly inside both circles), so orient2d is asked only where it can fail.
    bool outside = false;
    for (const EdgeIdx e : boundary) {
        const double* u = mesh.point(mesh.origin(e));
        if (u[0] == q[0] && u[1] == q[1]) {
            probe.encroached.clear();
            probe.outcome = CavityInsertion::Duplicate;
            return;
        }
        const bool constrained = cdt.segment_of[e] != kNone;
        if (!constrained && !mesh.is_infinite(triangle_of(mesh.twin[e]))) continue;
        const double* v = mesh.point(mesh.destination(e));
        ++probe.orient_calls;
        const Sign side = predicates::orient2d(u, v, q);
        if (constrained) {
            if (side != Sign::Positive || predicates::corner_dot_sign(q, u, v) != Sign::Positive) {
                probe.encroached.push_back(e);
            }
        } else if (side != Sign::Positive) {
            // Only on the line of a hull edge beyond its ends (exterior kept).
            outside = true;
        }
    }
    if (outside) {
        probe.encroached.clear();
        probe.outcome = CavityInsertion::Outside;
        return;
    }
    probe.outcome =
        probe.encroached.empty() ? CavityInsertion::Inserted : CavityInsertion::Encroaches;
}

CavityInsertion insert_probed(CdtState& cdt, const CavityProbe& probe) {
    cdt.core.counters.incircle_calls += probe.incircle_calls;
    cdt.core.counters.orient_calls += probe.orient_calls;
    cdt.encroached_edges.assign(probe.encroached.begin(), probe.encroached.end());
    if (probe.outcome != CavityInsertion::Inserted) {
        ++cdt.edit_counters.rejected_insertions;
        if (probe.outcome != CavityInsertion::NotInConflict)
            cdt.edit_counters.rejected_cavity_triangles += probe.cavity.size();
        return probe.outcome;
    }
    EM_ASSERT(!cdt.mesh.is_dead(probe.start));
    const VertIdx p = cdt.add_vertex(probe.x, probe.y);
    write_fan(cdt, probe.start, p, probe.cavity, probe.boundary);
    return CavityInsertion::Inserted;
}

/// How many fans ahead insert_probed_apart asks for the slots it will write.
constexpr std::size_t kFansAhead = 4;

void insert_probed_apart(CdtState& cdt, std::span<const CavityProbe* const> probes,
                         std::size_t chunks, const ChunkRunner& run,
                         const ConstrainedTriangulation2::FanWritten& written) {
    const std::size_t n = probes.size();
    if (n == 0) return;
    // In order, as insert_probed one after another would: the vertices, then each fan's slots
    // (its cavity's, then new ones).
    const VertIdx first = cdt.mesh.vertex_count();
    std::vector<TriIdx>& slots = cdt.fan_slots;
    std::vector<std::size_t>& begin = cdt.apart_slot_begin;
    slots.clear();
    begin.assign(1, 0);
    for (const CavityProbe* probe : probes) {
        EM_ASSERT(probe->outcome == CavityInsertion::Inserted && !cdt.mesh.is_dead(probe->start));
        cdt.core.counters.incircle_calls += probe->incircle_calls;
        cdt.core.counters.orient_calls += probe->orient_calls;
        cdt.add_vertex(probe->x, probe->y);
        slots.insert(slots.end(), probe->cavity.begin(), probe->cavity.end());
        cdt.mesh.new_triangles(probe->boundary.size() - probe->cavity.size(), slots);
        begin.push_back(slots.size());
        ++cdt.edit_counters.cavity_insertions;
        cdt.edit_counters.cavity_triangles += probe->cavity.size();
    }
    cdt.grow_slots();
    cdt.encroached_edges.clear();
    // The fans, in chunks of the list (possibly at once): each writes its own cavity's and new
    // slots, the twins of the triangles beside its cavity (their own half-edges: no two cavities
    // share a boundary edge) and its own vertex's vertex_edge.
    chunks = std::max<std::size_t>(1, std::min(chunks, n));
    if (cdt.apart_scratch.size() < chunks) cdt.apart_scratch.resize(chunks);
    const auto body = [&](std::size_t c) {
        FanScratch& scratch = cdt.apart_scratch[c];
        const std::size_t end = (c + 1) * n / chunks;
        for (std::size_t i = c * n / chunks; i < end; ++i) {
            // A few fans ahead, the slots this chunk will write (their cavity's triangles and
            // the links beside it): anywhere in the arrays, and last read on the probing thread.
            if (i + kFansAhead < end) {
                const CavityProbe& ahead = *probes[i + kFansAhead];
                for (const TriIdx s : ahead.cavity) {
                    __builtin_prefetch(&cdt.mesh.tv[3 * s], 1);
                    __builtin_prefetch(&cdt.mesh.twin[3 * s], 1);
                }
                for (const TriIdx s : ahead.beside) __builtin_prefetch(&cdt.mesh.twin[3 * s], 1);
            }
            const CavityProbe& probe = *probes[i];
            order_fan(cdt.mesh, cdt.segment_of.data(), probe.boundary, probe.cavity.size(),
                      scratch);
            const std::span<const TriIdx> fan_slots =
                std::span<const TriIdx>(slots).subspan(begin[i], begin[i + 1] - begin[i]);
            write_fan_triangles(cdt, probe.start, first + static_cast<VertIdx>(i), scratch.fan,
                                fan_slots, false);
            if (written) written(c, begin[i], fan_slots);
        }
    };
    if (run && chunks > 1) {
        run(chunks, body);
    } else {
        for (std::size_t c = 0; c < chunks; ++c) body(c);
    }
    // The boundary vertices' vertex_edge as the fans one after another leave it (the last fan
    // triangle at each vertex), and the touched slots.
    EdgeIdx* vertex_edge = cdt.vertex_edge.data();
    const VertIdx* tv = cdt.mesh.tv.data();
    for (const TriIdx s : slots) {
        for (unsigned k = 0; k < 2; ++k) {
            const VertIdx v = tv[3 * s + k];
            if (v != kInfinite) vertex_edge[v] = 3 * s + k;
        }
    }
    cdt.touched.insert(cdt.touched.end(), slots.begin(), slots.end());
    cdt.core.last_triangle = slots[begin[n - 1]];
}

CavityInsertion insert_in_cavity(CdtState& cdt, TriIdx t, double x, double y) {
    CavityProbe& probe = cdt.probe;
    probe.x = x;
    probe.y = y;
    StateStamps visits{cdt.cavity_stamp, new_cavity_stamp(cdt)};
    probe_cavity(cdt, t, cdt.mesh.vertex_count(), probe, visits);
    return insert_probed(cdt, probe);
}

/// Perturbed in-ellipse conflict of p with the finite triangle u under `metric`.
bool metric_conflict(CdtState& cdt, TriIdx u, VertIdx p, const double* metric) {
    const VertIdx* w = &cdt.mesh.tv[3 * u];
    const double* a = cdt.mesh.point(w[0]);
    const double* b = cdt.mesh.point(w[1]);
    const double* c = cdt.mesh.point(w[2]);
    const double* q = cdt.mesh.point(p);
    Sign s = predicates::in_ellipse(a, b, c, q, metric);
    if (s == Sign::Zero) {
        const auto& index = cdt.core.input_index;
        s = predicates::in_ellipse_sos(a, b, c, q, metric, index[w[0]], index[w[1]], index[w[2]],
                                       index[p]);
    }
    return s == Sign::Positive;
}

/// The triangles reachable from the seeds through unconstrained edges among those stamped
/// `from`, stamped anew (cdt.stamp) into cdt.cavity.
void restamp_connected(CdtState& cdt, std::span<const TriIdx> seeds, std::uint32_t from) {
    if (++cdt.stamp == 0) {  // wrapped: no slot may hold the new value by accident
        for (std::uint32_t& v : cdt.cavity_stamp) v = v == from ? 1u : 0u;
        from = 1;
        cdt.stamp = 2;
    }
    cdt.cavity.clear();
    for (const TriIdx t : seeds) {
        cdt.cavity_stamp[t] = cdt.stamp;
        cdt.cavity.push_back(t);
    }
    for (std::size_t i = 0; i < cdt.cavity.size(); ++i) {
        const TriIdx c = cdt.cavity[i];
        for (unsigned k = 0; k < 3; ++k) {
            const EdgeIdx e = 3 * c + k;
            const TriIdx u = triangle_of(cdt.mesh.twin[e]);
            if (cdt.segment_of[e] != kNone || cdt.cavity_stamp[u] != from) continue;
            cdt.cavity_stamp[u] = cdt.stamp;
            cdt.cavity.push_back(u);
        }
    }
}

CavityInsertion insert_in_metric_cavity(CdtState& cdt, TriIdx t, double x, double y,
                                        const double* metric) {
    EM_ASSERT(cdt.domain_marked() && !cdt.mesh.is_dead(t) && !cdt.mesh.is_infinite(t));
    cdt.encroached_edges.clear();
    const VertIdx p = cdt.add_vertex(x, y);
    auto reject = [&](CavityInsertion why) {
        cdt.remove_last_vertex();
        ++cdt.edit_counters.rejected_insertions;
        return why;
    };
    // The seeds: t, which must hold p (closed), and the triangle across each edge of t that p
    // lies on (then p is in both; on a constrained edge it would split it: refused).
    std::array<TriIdx, 3> seeds{t, kNone, kNone};
    std::size_t seed_count = 1;
    for (unsigned k = 0; k < 3; ++k) {
        const EdgeIdx e = 3 * t + k;
        if (cdt.core.same_point(cdt.mesh.origin(e), p)) return reject(CavityInsertion::Duplicate);
        const Sign side = cdt.core.orient(cdt.mesh.origin(e), cdt.mesh.destination(e), p);
        if (side == Sign::Negative) return reject(CavityInsertion::NotInConflict);
        if (side == Sign::Zero) {
            if (cdt.segment_of[e] != kNone) {
                cdt.encroached_edges.push_back(e);
                return reject(CavityInsertion::Encroaches);
            }
            const TriIdx across = triangle_of(cdt.mesh.twin[e]);
            if (cdt.mesh.is_infinite(across)) return reject(CavityInsertion::Outside);
            seeds[seed_count++] = across;
        }
    }
    // The conflict zone: grown from the seeds across unconstrained edges into every finite
    // triangle whose circumscribed ellipse (in the metric) holds p.
    const std::uint32_t grown = new_cavity_stamp(cdt);
    cdt.cavity.clear();
    for (std::size_t i = 0; i < seed_count; ++i) {
        cdt.cavity_stamp[seeds[i]] = grown;
        cdt.cavity.push_back(seeds[i]);
    }
    for (std::size_t i = 0; i < cdt.cavity.size(); ++i) {
        const TriIdx c = cdt.cavity[i];
        for (unsigned k = 0; k < 3; ++k) {
            const EdgeIdx e = 3 * c + k;
            const TriIdx u = triangle_of(cdt.mesh.twin[e]);
            if (cdt.cavity_stamp[u] == grown || cdt.segment_of[e] != kNone) continue;
            if (cdt.mesh.is_infinite(u) || !metric_conflict(cdt, u, p, metric)) continue;
            cdt.cavity_stamp[u] = grown;
            cdt.cavity.push_back(u);
        }
    }
    // Star-shaped from p: in a metric that varies from point to point the mesh is not Delaunay
    // in p's metric, so the conflict zone may hold triangles p does not see. Each pass drops a
    // non-seed triangle with a boundary edge (constrained, or towards a triangle outside) that
    // p is not strictly left of, then keeps what stays connected to the seeds; at the end every
    // boundary edge sees p strictly, so the boundary is one simple loop around p (the seeds'
    // edges already see it: p is inside them) and the fan is valid [George-Borouchaki98 §7.3].
    const auto is_seed = [&](TriIdx c) { return c == seeds[0] || c == seeds[1] || c == seeds[2]; };
    for (;;) {
        bool dropped = false;
        for (const TriIdx c : cdt.cavity) {
            if (is_seed(c)) continue;
            for (unsigned k = 0; k < 3; ++k) {
                const EdgeIdx e = 3 * c + k;
                if (cdt.segment_of[e] == kNone &&
                    cdt.cavity_stamp[triangle_of(cdt.mesh.twin[e])] == cdt.stamp) {
                    continue;
                }
                if (cdt.core.orient(cdt.mesh.origin(e), cdt.mesh.destination(e), p) !=
                    Sign::Positive) {
                    cdt.cavity_stamp[c] = 0;
                    dropped = true;
                    break;
                }
            }
        }
        if (!dropped) break;
        ++cdt.edit_counters.cavity_corrections;
        restamp_connected(cdt, std::span<const TriIdx>(seeds.data(), seed_count), cdt.stamp);
    }
    cdt.boundary.clear();
    for (const TriIdx c : cdt.cavity) {
        for (unsigned k = 0; k < 3; ++k) {
            const EdgeIdx e = 3 * c + k;
            if (cdt.segment_of[e] != kNone ||
                cdt.cavity_stamp[triangle_of(cdt.mesh.twin[e])] != cdt.stamp) {
                if (cdt.core.same_point(cdt.mesh.origin(e), p)) {
                    return reject(CavityInsertion::Duplicate);
                }
                cdt.boundary.push_back(e);
            }
        }
    }
    write_fan(cdt, t, p, cdt.cavity, cdt.boundary);
    return CavityInsertion::Inserted;
}

/// The exact fan test of split_constrained_edge: p strictly inside both triangles' star.
bool star_contains(CdtState& cdt, VertIdx p, VertIdx a, VertIdx b, VertIdx c, VertIdx d) {
    return cdt.core.orient(b, c, p) == Sign::Positive &&
           cdt.core.orient(c, a, p) == Sign::Positive &&
           cdt.core.orient(a, d, p) == Sign::Positive && cdt.core.orient(d, b, p) == Sign::Positive;
}

/// One attempt of split_constrained_edge at (x, y): true (and the new vertex) when the point
/// lies on e or inside the quadrilateral of e's two triangles; the edges to check for Lawson
/// flips are appended to `check`. Else nothing changes.
bool try_split_at(CdtState& cdt, EdgeIdx e, double x, double y,
                  std::vector<std::pair<VertIdx, VertIdx>>& check, VertIdx& vertex) {
    const EdgeIdx f = cdt.mesh.twin[e];
    const VertIdx a = cdt.mesh.origin(e), b = cdt.mesh.destination(e), c = cdt.apex(e),
                  d = cdt.apex(f);
    const VertIdx p = cdt.add_vertex(x, y);
    // The pieces a - p - b must be a chain the check accepts (bend_candidate: p within rounding
    // of the input segment, strictly between a and b along it). A point moved by ulps off a piece
    // a few ulps long can land behind a or beyond b along the segment (fuzz_delaunay_refinement_2d,
    // 2026-12-07: a 45-degree segment split down to pieces of 1-3 ulps at a corner whose
    // chain then stepped back, and the check found it missing).
    if (cdt.core.same_point(p, a) || cdt.core.same_point(p, b) ||
        !bend_candidate(cdt, cdt.segment_of[e], a, b, p)) {
        cdt.remove_last_vertex();
        return false;
    }
    const Sign s = cdt.core.orient(a, b, p);
    if (s == Sign::Zero && cdt.core.strictly_between(a, b, p)) {
        // On the line: the four triangles (p, b, c), (p, c, a), (p, a, d), (p, d, b), then
        // Lawson's flips of the edges opposite p (the spokes are locally Delaunay).
        split_edge(cdt, e, p);
        cdt.flip_stack.clear();
        check.insert(check.end(), {{b, c}, {c, a}, {a, d}, {d, b}});
        vertex = p;
        return true;
    }
    if (s != Sign::Zero && star_contains(cdt, p, a, b, c, d)) {
        // Off the line, inside the quadrilateral a, d, b, c and seeing its four sides: the same
        // four triangles, the pieces a - p - b bent by the rounding of p. p lies inside one of
        // the two old triangles only, so the spokes p - c and p - d are checked too.
        split_edge(cdt, e, p);
        cdt.flip_stack.clear();
        check.insert(check.end(), {{b, c}, {c, a}, {a, d}, {d, b}, {p, c}, {p, d}});
        vertex = p;
        return true;
    }
    cdt.remove_last_vertex();
    return false;
}

VertIdx split_constrained_edge(CdtState& cdt, EdgeIdx e, double x, double y) {
    EM_ASSERT(cdt.domain_marked() && cdt.segment_of[e] != kNone);
    const VertIdx a = cdt.mesh.origin(e), b = cdt.mesh.destination(e);
    const std::uint32_t segment = cdt.segment_of[e];
    {
        const double* pa = cdt.mesh.point(a);
        const double* pb = cdt.mesh.point(b);
        if ((x == pa[0] && y == pa[1]) || (x == pb[0] && y == pb[1])) {
            throw GeometryError(
                "segment " + std::to_string(segment + cdt.options.first_index) + ": its piece " +
                format_point(pa) + " - " + format_point(pb) +
                " is too short to split: its split point rounds to one of its ends (finer "
                "than doubles resolve along the segment; a vertex or segment that "
                "close to it is a feature the mesh cannot follow)");
        }
    }
    const double nx = cdt.mesh.point(a)[1] - cdt.mesh.point(b)[1],
                 ny = cdt.mesh.point(b)[0] - cdt.mesh.point(a)[0];  // left normal
    std::vector<std::pair<VertIdx, VertIdx>> check;
    const std::uint64_t flips_before = cdt.result.counters.delaunay_flips;
    // A neighbouring triangle may be a sliver: its apex within ulps of the line of a - b (the next
    // vertex of the same bent segment, on the exterior side where nothing breaks up such slivers).
    // Then the point, moved 1, 1, 2, 2, 3, 3 ulps per coordinate to either side of the line, may
    // fit; else the sliver's free edge that the point lies beyond is flipped away (a temporary
    // flip: Lawson's flips from every edge involved restore the constrained Delaunay property).
    for (int round = 0; round < 8; ++round) {
        e = cdt.find_edge(a, b);
        for (int attempt = 0; attempt < 7; ++attempt) {
            double px = x, py = y;
            const double side = attempt % 2 == 1 ? 1.0 : -1.0;
            for (int step = 0; step < (attempt + 1) / 2; ++step) {
                if (nx != 0) px = std::nextafter(px, side * nx > 0 ? INFINITY : -INFINITY);
                if (ny != 0) py = std::nextafter(py, side * ny > 0 ? INFINITY : -INFINITY);
            }
            VertIdx vertex = kNone;
            if (try_split_at(cdt, e, px, py, check, vertex)) {
                restore_delaunay(cdt, check);
                cdt.edit_counters.split_flips += cdt.result.counters.delaunay_flips - flips_before;
                ++cdt.edit_counters.edge_splits;
                return vertex;
            }
        }
        // The free edge of a side triangle (not a - b) that the point lies beyond, if flippable.
        const VertIdx p = cdt.add_vertex(x, y);
        EdgeIdx blocking = kNone;
        for (const EdgeIdx g : {next_edge(e), prev_edge(e), next_edge(cdt.mesh.twin[e]),
                                prev_edge(cdt.mesh.twin[e])}) {
            if (cdt.segment_of[g] != kNone ||
                cdt.core.orient(cdt.mesh.origin(g), cdt.mesh.destination(g), p) == Sign::Positive) {
                continue;
            }
            const VertIdx u = cdt.mesh.origin(g), v = cdt.mesh.destination(g), w1 = cdt.apex(g),
                          w2 = cdt.apex(cdt.mesh.twin[g]);
            if (w1 == kInfinite || w2 == kInfinite) continue;
            const Sign su = cdt.core.orient(w1, w2, u), sv = cdt.core.orient(w1, w2, v);
            if (su != Sign::Zero && sv != Sign::Zero && su != sv) {
                blocking = g;
                break;
            }
        }
        cdt.remove_last_vertex();
        if (blocking == kNone) break;
        const VertIdx u = cdt.mesh.origin(blocking), v = cdt.mesh.destination(blocking);
        const VertIdx w1 = cdt.apex(blocking), w2 = cdt.apex(cdt.mesh.twin[blocking]);
        ++cdt.result.counters.delaunay_flips;
        flip(cdt, blocking);
        check.insert(check.end(), {{w1, w2}, {u, w2}, {w2, v}, {v, w1}, {w1, u}});
    }
    restore_delaunay(cdt, check);
    return bend_at_apex(cdt, cdt.find_edge(a, b));
}

VertIdx bend_at_apex(CdtState& cdt, EdgeIdx e) {
    const EdgeIdx best = near_apex(cdt, e);
    if (best == kNone) {
        throw GeometryError(
            "segment " + std::to_string(cdt.segment_of[e] + cdt.options.first_index) +
            ": its piece " + format_point(cdt.mesh.point(cdt.mesh.origin(e))) + " - " +
            format_point(cdt.mesh.point(cdt.mesh.destination(e))) +
            " cannot be split: features within rounding of it (finer than double precision "
            "resolves)");
    }
    ++cdt.edit_counters.edge_bends;
    return bend_through_apex(cdt, best);
}

}  // namespace

}  // namespace detail

// ---------------------------------------------------------------------------------------------

struct ConstrainedTriangulation2::Owned {
    std::vector<double> xy, holes, regions;
    std::vector<VertIdx> segments, segment_lines;
    Cdt2Options options;
    std::optional<detail::CdtState> state;
};

ConstrainedTriangulation2::ConstrainedTriangulation2(const Pslg& pslg, const Cdt2Options& options)
    : owned_(std::make_unique<Owned>()) {
    if (options.recovery == SegmentRecovery::Conforming) {
        throw InputError(
            "ConstrainedTriangulation2: conforming recovery keeps no constraints; use swap or "
            "cavity");
    }
    if (!options.remove_exterior) {
        throw InputError(
            "ConstrainedTriangulation2: the domain is what the segments enclose (remove_exterior)");
    }
    validate_pslg(pslg);
    Owned& o = *owned_;
    o.xy.assign(pslg.xy.begin(), pslg.xy.end());
    o.holes.assign(pslg.holes.begin(), pslg.holes.end());
    o.regions.assign(pslg.regions.begin(), pslg.regions.end());
    o.segments.assign(pslg.segments.begin(), pslg.segments.end());
    o.segment_lines.assign(pslg.segment_lines.begin(), pslg.segment_lines.end());
    o.options = options;
    o.state.emplace(Pslg{o.xy, o.segments, o.holes, o.regions, o.segment_lines}, o.options);
    state_ = &*o.state;
    detail::CdtState& cdt = *state_;
    mesh_ = &cdt.mesh;
    segment_of_ = &cdt.segment_of;
    removed_ = &cdt.removed;
    touched_ = &cdt.touched;
    if (detail::triangulate_vertices(cdt)) {
        detail::recover_segments(cdt, options.recovery == SegmentRecovery::Cavity
                                          ? detail::recover_by_cavity
                                          : detail::recover_by_swaps);
        detail::bend_through_near_vertices(cdt);
        detail::enclose_in_box(cdt);
        detail::mark_domain(cdt);
    }
}

ConstrainedTriangulation2::~ConstrainedTriangulation2() = default;
ConstrainedTriangulation2::ConstrainedTriangulation2(ConstrainedTriangulation2&&) noexcept =
    default;
ConstrainedTriangulation2& ConstrainedTriangulation2::operator=(
    ConstrainedTriangulation2&&) noexcept = default;

double ConstrainedTriangulation2::attribute(TriIdx t) const {
    return state_->attribute.empty() ? 0.0 : state_->attribute[t];
}
bool ConstrainedTriangulation2::collinear() const {
    return state_->collinear;
}
std::uint32_t ConstrainedTriangulation2::input_vertex_count() const {
    return state_->input_count;
}
std::span<const VertIdx> ConstrainedTriangulation2::input_index() const {
    return state_->core.input_index;
}
std::array<VertIdx, 2> ConstrainedTriangulation2::segment_ends(std::uint32_t s) const {
    return state_->segment_ends[s];
}
EdgeIdx ConstrainedTriangulation2::find_edge(VertIdx u, VertIdx v) const {
    return state_->find_edge(u, v);
}
TriIdx ConstrainedTriangulation2::locate(double x, double y) {
    return detail::locate_point(*state_, x, y);
}

CavityInsertion ConstrainedTriangulation2::insert_in_cavity(TriIdx t, double x, double y) {
    return detail::insert_in_cavity(*state_, t, x, y);
}
void ConstrainedTriangulation2::probe_cavity(TriIdx t, double x, double y, VertIdx index,
                                             CavityProbe& probe,
                                             CavityProbeScratch& scratch) const {
    probe.x = x;
    probe.y = y;
    detail::ProbeVisits visits{scratch, state_->mesh.triangle_slots()};
    detail::probe_cavity(*state_, t, index, probe, visits);
    probe.beside.clear();
    for (const EdgeIdx e : probe.boundary)
        probe.beside.push_back(triangle_of(state_->mesh.twin[e]));
}
CavityInsertion ConstrainedTriangulation2::insert_probed(const CavityProbe& probe) {
    return detail::insert_probed(*state_, probe);
}
void ConstrainedTriangulation2::insert_probed_apart(std::span<const CavityProbe* const> probes,
                                                    std::size_t chunks, const ChunkRunner& run,
                                                    const FanWritten& written) {
    detail::insert_probed_apart(*state_, probes, chunks, run, written);
}
CavityInsertion ConstrainedTriangulation2::insert_in_metric_cavity(TriIdx t, double x, double y,
                                                                   const double* metric) {
    return detail::insert_in_metric_cavity(*state_, t, x, y, metric);
}
std::span<const EdgeIdx> ConstrainedTriangulation2::encroached_edges() const {
    return state_->encroached_edges;
}
VertIdx ConstrainedTriangulation2::split_constrained_edge(EdgeIdx e, double x, double y) {
    return detail::split_constrained_edge(*state_, e, x, y);
}
void ConstrainedTriangulation2::reserve(std::uint32_t vertices) {
    detail::reserve(*state_, vertices);
}
const ConstrainedTriangulation2Counters& ConstrainedTriangulation2::counters() const {
    return state_->edit_counters;
}

Cdt2Result ConstrainedTriangulation2::take_result() && {
    Cdt2Result result = detail::finish(*state_);
    owned_.reset();
    state_ = nullptr;
    mesh_ = nullptr;
    segment_of_ = nullptr;
    removed_ = nullptr;
    touched_ = nullptr;
    return result;
}

}  // namespace exactmesh::triangulation
