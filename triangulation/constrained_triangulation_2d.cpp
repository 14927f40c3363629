// SPDX-License-Identifier: MIT
// ConstrainedTriangulation2 (see constrained_triangulation_2d.hpp): the incremental edits of
// the constrained Delaunay builder, Bowyer-Watson cavity insertion and constrained edge splits.
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
#include "triangulation/constrained_triangulation_2d.hpp"

#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <utility>

#include "predicates/angle_comparisons_2d.hpp"
#include "predicates/errors.hpp"
#include "triangulation/constrained_2d_builder.hpp"

namespace exactmesh::triangulation {

namespace detail {

namespace {

std::string point_text(const double* p) {
    char text[80];
    std::snprintf(text, sizeof text, "(%.17g, %.17g)", p[0], p[1]);
    return text;
}

}  // namespace

void CdtBuilder::reserve(std::uint32_t vertices) {
    const std::size_t v = vertices, slots = 2 * v + 8;  // triangles (finite and infinite) ~ 2 V
    mesh_.xy.reserve(2 * v);
    mesh_.tv.reserve(3 * slots);
    mesh_.twin.reserve(3 * slots);
    segment_of_.reserve(3 * slots);
    vertex_edge_.reserve(v);
    core_.input_index.reserve(v);
    core_.merged_into.reserve(v);
    removed_.reserve(slots);
    if (!attribute_.empty()) attribute_.reserve(slots);
    cavity_stamp_.reserve(slots);
}

void CdtBuilder::drain_flip_stack() {
    const std::uint64_t before = result_.counters.delaunay_flips;
    while (!flip_stack_.empty()) {
        const TriIdx t1 = flip_stack_.back();
        flip_stack_.pop_back();
        flip_if_needed(t1);
    }
    edit_counters_.split_flips += result_.counters.delaunay_flips - before;
}

CavityInsertion CdtBuilder::insert_in_cavity(TriIdx t, double x, double y) {
    EM_ASSERT(domain_marked_ && !mesh_.is_dead(t) && !mesh_.is_infinite(t));
    encroached_edges_.clear();
    const VertIdx p = add_vertex(x, y);
    auto reject = [&](CavityInsertion why) {
        remove_last_vertex();
        ++edit_counters_.rejected_insertions;
        return why;
    };
    if (!core_.conflict(t, p)) return reject(CavityInsertion::NotInConflict);

    // The conflict zone, grown across unconstrained edges only.
    if (cavity_stamp_.size() < mesh_.triangle_slots())
        cavity_stamp_.resize(mesh_.triangle_slots(), 0);
    if (++stamp_ == 0) {
        std::fill(cavity_stamp_.begin(), cavity_stamp_.end(), 0u);
        stamp_ = 1;
    }
    cavity_.clear();
    boundary_.clear();
    cavity_.push_back(t);
    cavity_stamp_[t] = stamp_;
    bool beyond_hull = false;
    for (std::size_t i = 0; i < cavity_.size(); ++i) {
        const TriIdx c = cavity_[i];
        for (unsigned k = 0; k < 3; ++k) {
            const EdgeIdx e = 3 * c + k;
            const TriIdx u = triangle_of(mesh_.twin[e]);
            if (cavity_stamp_[u] == stamp_) continue;
            if (segment_of_[e] != kNone) {
                boundary_.push_back(e);
                continue;
            }
            if (core_.conflict(u, p)) {
                if (mesh_.is_infinite(u)) {
                    beyond_hull = true;  // outside the convex hull (exterior kept)
                    boundary_.push_back(e);
                    continue;
                }
                cavity_stamp_[u] = stamp_;
                cavity_.push_back(u);
            } else {
                boundary_.push_back(e);
            }
        }
    }
    if (beyond_hull) return reject(CavityInsertion::Outside);
    for (const EdgeIdx e : boundary_) {
        if (core_.same_point(mesh_.origin(e), p)) return reject(CavityInsertion::Duplicate);
    }
    for (const EdgeIdx e : boundary_) {
        const VertIdx u = mesh_.origin(e), v = mesh_.destination(e);
        const Sign side = core_.orient(u, v, p);
        if (segment_of_[e] != kNone) {
            if (side != Sign::Positive ||
                predicates::corner_dot_sign(mesh_.point(p), mesh_.point(u), mesh_.point(v)) !=
                    Sign::Positive) {
                encroached_edges_.push_back(e);
            }
        } else if (side != Sign::Positive) {
            // Only on the line of a hull edge beyond its ends (exterior kept): the Delaunay lemma
            // puts p strictly inside every other unconstrained boundary edge.
            EM_ASSERT(mesh_.is_infinite(triangle_of(mesh_.twin[e])));
            return reject(CavityInsertion::Outside);
        }
    }
    if (!encroached_edges_.empty()) return reject(CavityInsertion::Encroaches);

    // The boundary in order: from each boundary edge u -> v, turn about v through the cavity to
    // the next boundary edge leaving v. A cavity with an interior vertex or pinched at a vertex
    // would not close after boundary_.size() edges (never seen: the Delaunay lemma excludes it).
    auto on_boundary = [&](EdgeIdx g) {
        return segment_of_[g] != kNone || cavity_stamp_[triangle_of(mesh_.twin[g])] != stamp_;
    };
    cycle_.clear();
    EdgeIdx current = boundary_.front();
    do {
        cycle_.push_back(current);
        EM_ASSERT(cycle_.size() <= boundary_.size());
        EdgeIdx g = next_edge(current);
        std::size_t turns = 0;
        while (!on_boundary(g)) {
            g = next_edge(mesh_.twin[g]);
            EM_ASSERT(++turns <= cavity_.size());
        }
        current = g;
    } while (current != boundary_.front());
    EM_ASSERT(cycle_.size() == boundary_.size());
    EM_ASSERT(cycle_.size() == cavity_.size() + 2);

    std::vector<FanEdge>& fan = fan_;
    fan.clear();
    for (const EdgeIdx e : cycle_) {
        fan.push_back({mesh_.origin(e), mesh_.destination(e), mesh_.twin[e], segment_of_[e]});
    }
    const Side side = side_of(t);
    const std::size_t n = fan.size();
    std::vector<TriIdx>& slots = fan_slots_;
    slots.assign(cavity_.begin(), cavity_.end());
    while (slots.size() < n) slots.push_back(new_triangle());
    for (std::size_t i = 0; i < n; ++i) {
        const TriIdx s = slots[i];
        set(s, fan[i].u, fan[i].v, p);
        link_outer(3 * s, fan[i].outer, fan[i].segment);
        put_on_side(s, side);
    }
    for (std::size_t i = 0; i < n; ++i) {
        // (v_i -> p) of triangle i meets (p -> u_{i+1}) of the next, u_{i+1} = v_i.
        link_inner(3 * slots[i] + 1, 3 * slots[(i + 1) % n] + 2);
    }
    core_.last_triangle = slots[0];
    ++edit_counters_.cavity_insertions;
    edit_counters_.cavity_triangles += cavity_.size();
    return CavityInsertion::Inserted;
}

bool CdtBuilder::star_contains(VertIdx p, VertIdx a, VertIdx b, VertIdx c, VertIdx d) {
    return core_.orient(b, c, p) == Sign::Positive && core_.orient(c, a, p) == Sign::Positive &&
           core_.orient(a, d, p) == Sign::Positive && core_.orient(d, b, p) == Sign::Positive;
}

bool CdtBuilder::try_split_at(EdgeIdx e, double x, double y,
                              std::vector<std::pair<VertIdx, VertIdx>>& check, VertIdx& vertex) {
    const EdgeIdx f = mesh_.twin[e];
    const VertIdx a = mesh_.origin(e), b = mesh_.destination(e), c = apex(e), d = apex(f);
    const VertIdx p = add_vertex(x, y);
    if (core_.same_point(p, a) || core_.same_point(p, b)) {
        remove_last_vertex();
        return false;
    }
    const Sign s = core_.orient(a, b, p);
    if (s == Sign::Zero && core_.strictly_between(a, b, p)) {
        // On the line: the four triangles (p, b, c), (p, c, a), (p, a, d), (p, d, b), then
        // Lawson's flips of the edges opposite p (the spokes are locally Delaunay).
        split_edge(e, p);
        flip_stack_.clear();
        check.insert(check.end(), {{b, c}, {c, a}, {a, d}, {d, b}});
        vertex = p;
        return true;
    }
    if (s != Sign::Zero && star_contains(p, a, b, c, d)) {
        // Off the line, inside the quadrilateral a, d, b, c and seeing its four sides: the same
        // four triangles, the pieces a - p - b bent by the rounding of p. p lies inside one of
        // the two old triangles only, so the spokes p - c and p - d are checked too.
        split_edge(e, p);
        flip_stack_.clear();
        check.insert(check.end(), {{b, c}, {c, a}, {a, d}, {d, b}, {p, c}, {p, d}});
        vertex = p;
        return true;
    }
    remove_last_vertex();
    return false;
}

VertIdx CdtBuilder::split_constrained_edge(EdgeIdx e, double x, double y) {
    EM_ASSERT(domain_marked_ && segment_of_[e] != kNone);
    const VertIdx a = mesh_.origin(e), b = mesh_.destination(e);
    const std::uint32_t segment = segment_of_[e];
    {
        const double* pa = mesh_.point(a);
        const double* pb = mesh_.point(b);
        if ((x == pa[0] && y == pa[1]) || (x == pb[0] && y == pb[1])) {
            throw GeometryError("segment " + std::to_string(segment + options_.first_index) +
                                ": its piece " + point_text(pa) + " - " + point_text(pb) +
                                " is too short to split (adjacent doubles)");
        }
    }
    const double nx = mesh_.point(a)[1] - mesh_.point(b)[1],
                 ny = mesh_.point(b)[0] - mesh_.point(a)[0];  // left normal
    std::vector<std::pair<VertIdx, VertIdx>> check;
    const std::uint64_t flips_before = result_.counters.delaunay_flips;
    // A neighbouring triangle may be a sliver: its apex within ulps of the line of a - b (the next
    // vertex of the same bent segment, on the exterior side where nothing breaks up such slivers).
    // Then the point, moved 1, 1, 2, 2, 3, 3 ulps per coordinate to either side of the line, may
    // fit; else the sliver's free edge that the point lies beyond is flipped away (a temporary
    // flip: Lawson's flips from every edge involved restore the constrained Delaunay property).
    for (int round = 0; round < 8; ++round) {
        e = find_edge(a, b);
        for (int attempt = 0; attempt < 7; ++attempt) {
            double px = x, py = y;
            const double side = attempt % 2 == 1 ? 1.0 : -1.0;
            for (int step = 0; step < (attempt + 1) / 2; ++step) {
                if (nx != 0) px = std::nextafter(px, side * nx > 0 ? INFINITY : -INFINITY);
                if (ny != 0) py = std::nextafter(py, side * ny > 0 ? INFINITY : -INFINITY);
            }
            VertIdx vertex = kNone;
            if (try_split_at(e, px, py, check, vertex)) {
                restore_delaunay(check);
                edit_counters_.split_flips += result_.counters.delaunay_flips - flips_before;
                ++edit_counters_.edge_splits;
                return vertex;
            }
        }
        // The free edge of a side triangle (not a - b) that the point lies beyond, if flippable.
        const VertIdx p = add_vertex(x, y);
        EdgeIdx blocking = kNone;
        for (const EdgeIdx g :
             {next_edge(e), prev_edge(e), next_edge(mesh_.twin[e]), prev_edge(mesh_.twin[e])}) {
            if (segment_of_[g] != kNone ||
                core_.orient(mesh_.origin(g), mesh_.destination(g), p) == Sign::Positive) {
                continue;
            }
            const VertIdx u = mesh_.origin(g), v = mesh_.destination(g), w1 = apex(g),
                          w2 = apex(mesh_.twin[g]);
            if (w1 == kInfinite || w2 == kInfinite) continue;
            const Sign su = core_.orient(w1, w2, u), sv = core_.orient(w1, w2, v);
            if (su != Sign::Zero && sv != Sign::Zero && su != sv) {
                blocking = g;
                break;
            }
        }
        remove_last_vertex();
        if (blocking == kNone) break;
        const VertIdx u = mesh_.origin(blocking), v = mesh_.destination(blocking);
        const VertIdx w1 = apex(blocking), w2 = apex(mesh_.twin[blocking]);
        ++result_.counters.delaunay_flips;
        flip(blocking);
        check.insert(check.end(), {{w1, w2}, {u, w2}, {w2, v}, {v, w1}, {w1, u}});
    }
    restore_delaunay(check);
    return bend_at_apex(find_edge(a, b));
}

EdgeIdx CdtBuilder::near_apex(EdgeIdx e) const {
    // The apex (of e's triangle, else of its twin's) that may bend e's segment between e's ends:
    // bend_candidate, the chain rule that check_constrained_delaunay_2d applies.
    const std::uint32_t segment = segment_of_[e];
    const VertIdx a = mesh_.origin(e), b = mesh_.destination(e);
    for (const EdgeIdx side : {e, mesh_.twin[e]}) {
        if (bend_candidate(segment, a, b, apex(side))) return side;
    }
    return kNone;
}

VertIdx CdtBuilder::bend_through_apex(EdgeIdx g) {
    // Triangle (u, v, w) of g: the chain u - w - v replaces u - v, and the triangle moves to the
    // other side of the constraint.
    const std::uint32_t segment = segment_of_[g];
    const EdgeIdx h = mesh_.twin[g];
    const VertIdx u = mesh_.origin(g), v = mesh_.destination(g), w = apex(g);
    const TriIdx t = triangle_of(g);
    mark(next_edge(g), segment);
    mark(prev_edge(g), segment);
    for (const std::uint32_t other : release_shared(u, v)) {
        mark(next_edge(g), other);
        mark(prev_edge(g), other);
    }
    segment_of_[g] = segment_of_[h] = kNone;
    put_on_side(t, side_of(triangle_of(h)));
    if (domain_marked_) touched_.push_back(t);
    std::vector<std::pair<VertIdx, VertIdx>> released{{u, v}};
    restore_delaunay(released);
    return w;
}

VertIdx CdtBuilder::bend_at_apex(EdgeIdx e) {
    const EdgeIdx best = near_apex(e);
    if (best == kNone) {
        throw GeometryError(
            "segment " + std::to_string(segment_of_[e] + options_.first_index) + ": its piece " +
            point_text(mesh_.point(mesh_.origin(e))) + " - " +
            point_text(mesh_.point(mesh_.destination(e))) +
            " cannot be split: features within rounding of it (finer than double precision "
            "resolves)");
    }
    ++edit_counters_.edge_bends;
    return bend_through_apex(best);
}

void CdtBuilder::bend_through_near_vertices() {
    // Every piece whose neighbouring triangle has its apex within rounding of the segment (a
    // vertex a few ulps off it) bends through that vertex, as the conforming recovery bends:
    // else refinement would have to resolve the ulp-wide gap between them.
    std::vector<std::pair<VertIdx, VertIdx>> pieces;
    for (EdgeIdx e = 0; e < segment_of_.size(); ++e) {
        if (segment_of_[e] == kNone || mesh_.is_dead(triangle_of(e))) continue;
        if (mesh_.origin(e) < mesh_.destination(e))
            pieces.emplace_back(mesh_.origin(e), mesh_.destination(e));
    }
    while (!pieces.empty()) {
        const auto [a, b] = pieces.back();
        pieces.pop_back();
        const EdgeIdx e = find_edge(a, b);
        if (e == kNone || segment_of_[e] == kNone) continue;
        const EdgeIdx side = near_apex(e);
        if (side == kNone) continue;
        const std::uint32_t segment = segment_of_[e];
        const VertIdx w = bend_through_apex(side);
        ++result_.counters.conforming_bends;
        result_.warnings.push_back(
            "vertex " + std::to_string(core_.input_index[w] + options_.first_index) +
            " lies within rounding of segment " + std::to_string(segment + options_.first_index) +
            "; the segment bends through it");
        pieces.emplace_back(a, w);
        pieces.emplace_back(w, b);
    }
}

}  // namespace detail

// ---------------------------------------------------------------------------------------------

struct ConstrainedTriangulation2::Owned {
    std::vector<double> xy, holes, regions;
    std::vector<VertIdx> segments;
    Cdt2Options options;
    std::optional<detail::CdtBuilder> builder;
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
    o.options = options;
    o.builder.emplace(Pslg{o.xy, o.segments, o.holes, o.regions}, o.options, true);
    builder_ = &*o.builder;
    builder_->build();
}

ConstrainedTriangulation2::~ConstrainedTriangulation2() = default;
ConstrainedTriangulation2::ConstrainedTriangulation2(ConstrainedTriangulation2&&) noexcept =
    default;
ConstrainedTriangulation2& ConstrainedTriangulation2::operator=(
    ConstrainedTriangulation2&&) noexcept = default;

const TriMesh2& ConstrainedTriangulation2::mesh() const {
    return builder_->mesh();
}
std::uint32_t ConstrainedTriangulation2::segment_of(EdgeIdx e) const {
    return builder_->segment_of(e);
}
bool ConstrainedTriangulation2::in_domain(TriIdx t) const {
    return builder_->in_domain(t);
}
double ConstrainedTriangulation2::attribute(TriIdx t) const {
    return builder_->attribute_of(t);
}
bool ConstrainedTriangulation2::collinear() const {
    return builder_->collinear();
}
std::uint32_t ConstrainedTriangulation2::input_vertex_count() const {
    return builder_->input_vertex_count();
}
std::span<const VertIdx> ConstrainedTriangulation2::input_index() const {
    return builder_->input_index();
}
std::array<VertIdx, 2> ConstrainedTriangulation2::segment_ends(std::uint32_t s) const {
    return builder_->segment_ends(s);
}
EdgeIdx ConstrainedTriangulation2::find_edge(VertIdx u, VertIdx v) const {
    return builder_->edge_between(u, v);
}
TriIdx ConstrainedTriangulation2::locate(double x, double y) {
    return builder_->locate(x, y);
}

CavityInsertion ConstrainedTriangulation2::insert_in_cavity(TriIdx t, double x, double y) {
    return builder_->insert_in_cavity(t, x, y);
}
std::span<const EdgeIdx> ConstrainedTriangulation2::encroached_edges() const {
    return builder_->encroached_edges();
}
VertIdx ConstrainedTriangulation2::split_constrained_edge(EdgeIdx e, double x, double y) {
    return builder_->split_constrained_edge(e, x, y);
}
std::span<const TriIdx> ConstrainedTriangulation2::touched() const {
    return builder_->touched();
}
void ConstrainedTriangulation2::clear_touched() {
    builder_->clear_touched();
}
void ConstrainedTriangulation2::reserve(std::uint32_t vertices) {
    builder_->reserve(vertices);
}
const ConstrainedTriangulation2Counters& ConstrainedTriangulation2::counters() const {
    return builder_->edit_counters();
}

Cdt2Result ConstrainedTriangulation2::take_result() && {
    Cdt2Result result = builder_->finish();
    owned_.reset();
    builder_ = nullptr;
    return result;
}

}  // namespace exactmesh::triangulation
