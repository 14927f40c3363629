// SPDX-License-Identifier: MIT
// Lawson's edge swapping for any criterion (see edge_swap_2d.hpp).
//
// The quadrilateral of edge k of triangle t, before and after a swap (counter-clockwise):
//
//              c                          c
//             / \                        /|\           .
//            /   \                      / | \          .
//           /  t  \                    /  |  \         .
//          a ----- b       ==>        a t | u b
//           \  u  /                    \  |  /         .
//            \   /                      \ | /          .
//             \ /                        \|/           .
//              d                          d
//
//   t = (a, b, c), u = (b, a, d)          t = (d, c, a), u = (c, d, b)
//
// The swap is allowed only when the quadrilateral a d b c is strictly convex: orient2d(c, a, d)
// > 0 and orient2d(d, b, c) > 0 (the new triangles), exactly. Then both new triangles are
// strictly counter-clockwise, so the mesh stays a triangulation of the same domain with the same
// vertices, and only the five edges of the quadrilateral see their triangles change. The swap
// is flip_2d (flip_2d.hpp) with the new diagonal at local index 0 of both triangles, on the
// half-edges of a HalfEdgeEdit of the Triangulation2 (twins: no search for the shared edge).
//
// Termination. The loop pops an edge, and pushes four only after a swap, so it ends when the
// number of swaps is finite. The triangulations of a finite vertex set with fixed constraints are
// finitely many, so it is enough that each swap strictly improves a quantity that depends only
// on the current triangulation (then no triangulation recurs):
//  - Delaunay: the SoS incircle is the in-circle test of the lifted points (x, y, x^2 + y^2 -
//    w(v)), w infinitesimal and distinct per index [EdelsbrunnerMücke90]; a swap it asks for
//    replaces two lifted triangles by the two below them over the same quadrilateral, so the
//    lifted surface (a function on the domain, compared pointwise as polynomials in eps) goes
//    down strictly on the quadrilateral and stays elsewhere. A surface never returns above itself.
//  - MaxMinAngle: the vector of all 3T angles sorted increasingly grows strictly in lexicographic
//    order. Let m be the old minimum of the six angles: the new six are all > m, the others are
//    unchanged; below m both vectors agree, and the old one has more entries equal to m.
//  - MinMaxAngle: symmetrically, the decreasingly sorted vector of all angles strictly decreases.
//  - MinTotalLength: the total length of the edges strictly decreases (one edge, strictly shorter).
//  - DataDependent: the edge cost is a deterministic double computed from the edge and its two
//    apexes alone, in a canonical order (canonical_edge_cost), and the sum over the five edges is
//    compared exactly; so the exact real sum Phi of all interior-edge costs strictly decreases.
//    An edge with a non-finite cost blocks every swap that would change it, so the set of such
//    edges never changes and Phi over the finite ones is the decreasing quantity.
// All comparisons are exact (no tolerance), so "strictly" means strictly for real numbers.
#include "triangulation/modification/edge_swap_2d.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <deque>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "base/enum_names.hpp"
#include "base/errors.hpp"
#include "base/number_text.hpp"
#include "predicates/angle_comparisons_2d.hpp"
#include "predicates/expansion.hpp"
#include "predicates/in_ellipse.hpp"
#include "predicates/incircle.hpp"
#include "predicates/orient2d.hpp"
#include "predicates/sos.hpp"
#include "triangulation/delaunay/delaunay_2d.hpp"
#include "triangulation/mesh/flip_2d.hpp"

namespace exactmesh::triangulation {

namespace {

using predicates::compare_angles;
using predicates::compare_lengths;
using predicates::Corner;
using predicates::largest_corner;
using predicates::Sign;
using predicates::smallest_corner;

/// The quadrilateral of an interior half-edge e = a -> b of (a, b, c); its twin f lies in
/// (b, a, d).
struct Quad {
    EdgeIdx e, f;
    VertIdx a, b, c, d;
};

Quad make_quad(const TriMesh2& mesh, EdgeIdx e) {
    const EdgeIdx f = mesh.twin[e];
    return {
        e, f, mesh.origin(e), mesh.destination(e), mesh.tv[prev_edge(e)], mesh.tv[prev_edge(f)]};
}

bool strictly_convex(const TriMesh2& mesh, const Quad& q) {
    return predicates::orient2d(mesh.point(q.c), mesh.point(q.a), mesh.point(q.d)) ==
               Sign::Positive &&
           predicates::orient2d(mesh.point(q.d), mesh.point(q.b), mesh.point(q.c)) ==
               Sign::Positive;
}

bool is_constrained(const TriMesh2& mesh, EdgeIdx e) {
    return !mesh.flags.empty() && mesh.flags[e] != 0;
}

/// The queue-based loop shared by every criterion, on the half-edges of a HalfEdgeEdit of the
/// Triangulation2; `prefers(work, quad)` says whether the strictly convex quad wants its other
/// diagonal. `wide`: the decision also reads the triangles across the quad's sides (data-
/// dependent costs of the sides), so a swap re-queues the other edges of those outer triangles
/// too, not only the quad's four sides. The queue holds slots (3t + k), as it did when it ran on
/// neighbour ids: a queued slot is tested with whatever edge sits there when it is popped, so the
/// flip keeps the old layout (new diagonal at local 0 of both triangles, picture at the top) and
/// the swaps, their order and the output are unchanged.
/// The loop on a mesh already lent as half-edges, from every interior edge (`seeds` empty and
/// `all`) or from the half-edges in `seeds`. After `budget` swaps every further strictly convex
/// quadrilateral is kept (budget_stops). With `verdicts` (not for `wide` criteria, whose decision
/// reads more than the quadrilateral), a quadrilateral whose two triangles kept their stamps
/// since a run found it not to swap is not decided again: the same verdict, the same counters.
template <class Prefers>
EdgeSwapCounters swap_queue(TriMesh2& work, bool wide, std::span<const EdgeIdx> seeds, bool all,
                            std::uint64_t budget, SwapVerdicts2* verdicts, Prefers&& prefers) {
    EdgeSwapCounters counters;
    const std::size_t slots = work.tv.size();
    TriangleStamps2* stamps = verdicts != nullptr ? verdicts->stamps : nullptr;
    if (stamps != nullptr) {
        if (verdicts->era != stamps->era()) {
            verdicts->kept.assign(slots, 0);
            verdicts->convex.assign(slots, 0);
            verdicts->era = stamps->era();
        }
        // Slots of other sizes of the mesh: their stamps tell which verdicts still stand.
        verdicts->kept.resize(slots, 0);
        verdicts->convex.resize(slots, 0);
    }
    std::vector<std::uint8_t> queued(slots, 0);
    std::deque<EdgeIdx> queue;
    auto push = [&](EdgeIdx e) {
        if (work.twin[e] == kNone || queued[e] != 0 || is_constrained(work, e)) return;
        queued[e] = 1;
        queue.push_back(e);
    };
    for (std::size_t s = 0; all && s < slots; ++s) {
        // One side of each interior edge: the one in the lower-numbered triangle.
        const auto e = static_cast<EdgeIdx>(s);
        if (work.twin[e] != kNone && triangle_of(work.twin[e]) > triangle_of(e)) push(e);
    }
    for (const EdgeIdx e : seeds) {
        if (e < slots && work.tv[3 * triangle_of(e)] != kNone) push(e);
    }
    while (!queue.empty()) {
        const EdgeIdx e = queue.front();
        queue.pop_front();
        queued[e] = 0;
        if (work.twin[e] == kNone) continue;
        ++counters.edges_tested;
        if (is_constrained(work, e)) {
            ++counters.constrained;
            continue;
        }
        // The stamps of the quadrilateral's two triangles (0 when either has none).
        std::uint64_t key = 0;
        if (stamps != nullptr) {
            const std::uint64_t own = (*stamps)[triangle_of(e)];
            const std::uint64_t across = (*stamps)[triangle_of(work.twin[e])];
            if (own != 0 && across != 0) key = own << 32 | across;
            if (key != 0 && verdicts->kept[e] == key && verdicts->era == stamps->era()) {
                if (verdicts->convex[e] == 0) {
                    ++counters.not_convex;
                } else if (counters.swaps >= budget) {
                    ++counters.budget_stops;
                }
                continue;
            }
        }
        const Quad q = make_quad(work, e);
        if (!strictly_convex(work, q)) {
            ++counters.not_convex;
            if (key != 0) {
                verdicts->kept[e] = key;
                verdicts->convex[e] = 0;
            }
            continue;
        }
        if (counters.swaps >= budget) {
            ++counters.budget_stops;
            continue;
        }
        if (!prefers(work, q)) {
            if (key != 0) {
                verdicts->kept[e] = key;
                verdicts->convex[e] = 1;
            }
            continue;
        }
        const FlipEdges flipped = flip_2d(work, e, 0, 0);
        ++counters.swaps;
        if (stamps != nullptr) {
            stamps->touch(triangle_of(e));
            stamps->touch(triangle_of(q.f));
        }
        for (const EdgeIdx side : flipped.sides) push(side);
        if (wide) {
            for (const TriIdx inner : {triangle_of(e), triangle_of(q.f)}) {
                for (unsigned s = 1; s < 3; ++s) {
                    const EdgeIdx across = work.twin[3 * inner + s];
                    if (across == kNone) continue;
                    const TriIdx outer = triangle_of(across);
                    for (unsigned k = 0; k < 3; ++k) {
                        const EdgeIdx g = 3 * outer + k;
                        if (work.twin[g] == kNone || triangle_of(work.twin[g]) != inner) push(g);
                    }
                }
            }
        }
    }
    return counters;
}

constexpr std::uint64_t kNoBudget = ~std::uint64_t{0};

/// The loop over a whole Triangulation2, lent as half-edges.
template <class Prefers>
EdgeSwapCounters swap_loop(Triangulation2& mesh, bool wide, Prefers&& prefers) {
    validate_points_2d(mesh.xy);
    HalfEdgeEdit edit(mesh);
    return swap_queue(edit.mesh(), wide, {}, true, kNoBudget, nullptr,
                      std::forward<Prefers>(prefers));
}

Corner smaller(const Corner& x, const Corner& y) {
    return compare_angles(y, x) == Sign::Negative ? y : x;
}
Corner larger(const Corner& x, const Corner& y) {
    return compare_angles(y, x) == Sign::Positive ? y : x;
}

/// The plane interpolating `values` over the counter-clockwise triangle (p, q, r): its gradient,
/// with every coordinate multiplied by `unit` (a power of two) first.
std::array<double, 2> gradient(const TriMesh2& mesh, std::span<const double> values, VertIdx p,
                               VertIdx q, VertIdx r, double unit) {
    const double* a = mesh.point(p);
    const double* b = mesh.point(q);
    const double* c = mesh.point(r);
    const double ax = a[0] * unit, ay = a[1] * unit;
    const double bx = b[0] * unit - ax, by = b[1] * unit - ay;
    const double cx = c[0] * unit - ax, cy = c[1] * unit - ay;
    const double fb = values[q] - values[p], fc = values[r] - values[p];
    const double area2 = bx * cy - by * cx;
    return {(fb * cy - fc * by) / area2, (fc * bx - fb * cx) / area2};
}

/// The power of two by which data-dependent costs multiply the coordinates. JND, |n . (g1 -
/// g2)|, is homogeneous of degree -1 in the coordinates: computed on coordinates scaled by
/// 2^-e, e the exponent of the largest magnitude, the mesh scaled by 2^k gives the same doubles
/// (no area or gradient overflows or underflows at 2^+-600), and the decisions, exact sums of
/// those costs, are those of the unscaled mesh (a uniform power of two leaves every sum's sign
/// alone). ABN compares the planes' normals (-gx, -gy, 1), in which the coordinates' units
/// matter (scaling x and y but not the values turns the planes): it takes them as given.
double cost_unit(std::span<const double> xy, DataCost cost) {
    if (cost == DataCost::AngleBetweenNormals) return 1.0;
    double largest = 0;
    for (const double x : xy) largest = std::max(largest, std::fabs(x));
    if (!(largest > 0) || !std::isfinite(largest)) return 1.0;
    return std::ldexp(1.0, -std::ilogb(largest));
}

/// The cost of edge (p, q) with apex `left` on its left and `right` on its right, coordinates
/// multiplied by `unit` (cost_unit). Computed with the endpoints in increasing index order, so
/// the same edge and apexes always give the same double (the termination argument needs a
/// function of the edge, not of how it is reached).
double canonical_edge_cost(const TriMesh2& mesh, const DataDependent& criterion, VertIdx p,
                           VertIdx q, VertIdx left, VertIdx right, double unit) {
    if (p > q) {
        std::swap(p, q);
        std::swap(left, right);
    }
    const auto g1 = gradient(mesh, criterion.values, p, q, left, unit);
    const auto g2 = gradient(mesh, criterion.values, q, p, right, unit);
    if (criterion.cost == DataCost::AngleBetweenNormals) {
        // Normals (-gx, -gy, 1); the angle between them as atan2(|n1 x n2|, n1 . n2), accurate
        // for small angles too.
        const double cx = g2[1] - g1[1], cy = g1[0] - g2[0], cz = g1[0] * g2[1] - g1[1] * g2[0];
        const double dot = g1[0] * g2[0] + g1[1] * g2[1] + 1.0;
        return std::atan2(std::sqrt(cx * cx + cy * cy + cz * cz), dot);
    }
    const double* a = mesh.point(p);
    const double* b = mesh.point(q);
    const double ex = b[0] * unit - a[0] * unit, ey = b[1] * unit - a[1] * unit;
    const double length = std::sqrt(ex * ex + ey * ey);
    return std::fabs(ey * (g1[0] - g2[0]) - ex * (g1[1] - g2[1])) / length;
}

/// The apex across half-edge e from its triangle, or kNone on the boundary.
VertIdx outer_apex(const TriMesh2& mesh, EdgeIdx e) {
    const EdgeIdx across = mesh.twin[e];
    return across == kNone ? kNone : mesh.tv[prev_edge(across)];
}

/// Sign of sum(plus) - sum(minus), exact (expansion sums of the doubles).
Sign sign_of_difference(std::span<const double> plus, std::span<const double> minus) {
    std::array<double, 16> buffer_a{}, buffer_b{};
    double* sum = buffer_a.data();
    double* next = buffer_b.data();
    int length = 0;
    auto add = [&](double x) {
        length = predicates::expansion_sum(length, sum, x != 0.0 ? 1 : 0, &x, next);
        std::swap(sum, next);
    };
    for (const double x : plus) add(x);
    for (const double x : minus) add(-x);
    return length == 0 ? Sign::Zero : predicates::sign_of(sum[length - 1]);
}

constexpr std::array<EnumName<SwapCriterion>, 5> kSwapCriterionNames{{
    {"delaunay", SwapCriterion::Delaunay},
    {"max-min-angle", SwapCriterion::MaxMinAngle},
    {"min-max-angle", SwapCriterion::MinMaxAngle},
    {"min-length", SwapCriterion::MinTotalLength},
    {"data-dependent", SwapCriterion::DataDependent},
}};

}  // namespace

std::uint32_t TriangleStamps2::next() {
    if (clock_ == ~std::uint32_t{0}) {
        // The wrap: every stamp given so far may come again, so every verdict is voided.
        ++era_;
        clock_ = 0;
        std::fill(stamps_.begin(), stamps_.end(), 0u);
    }
    return ++clock_;
}

void TriangleStamps2::reset(std::size_t triangles) {
    stamps_.assign(triangles, 0);
    for (std::uint32_t& stamp : stamps_) stamp = next();
}

void TriangleStamps2::touch(TriIdx t) {
    if (t >= stamps_.size()) stamps_.resize(std::size_t{t} + 1, 0);
    stamps_[t] = next();
}

void TriangleStamps2::renumber(std::span<const TriIdx> old_of_new) {
    std::vector<std::uint32_t> renumbered(old_of_new.size(), 0);
    for (std::size_t t = 0; t < old_of_new.size(); ++t) {
        const TriIdx old = old_of_new[t];
        renumbered[t] = old != kNone && old < stamps_.size() ? stamps_[old] : 0;
    }
    stamps_ = std::move(renumbered);
    for (std::uint32_t& stamp : stamps_) {
        // After a wrap in next(), the stamps left are 0: every triangle gets a new one.
        if (stamp == 0) stamp = next();
    }
}

void SwapVerdicts2::renumber(std::span<const TriIdx> old_of_new) {
    std::vector<std::uint64_t> renumbered_kept(3 * old_of_new.size(), 0);
    std::vector<std::uint8_t> renumbered_convex(3 * old_of_new.size(), 0);
    for (std::size_t t = 0; t < old_of_new.size(); ++t) {
        const TriIdx old = old_of_new[t];
        const std::size_t from = 3 * std::size_t{old};
        if (old == kNone || from + 2 >= kept.size() || from + 2 >= convex.size()) continue;
        for (std::size_t k = 0; k < 3; ++k) {
            renumbered_kept[3 * t + k] = kept[from + k];
            renumbered_convex[3 * t + k] = convex[from + k];
        }
    }
    kept = std::move(renumbered_kept);
    convex = std::move(renumbered_convex);
}

SwapCriterion swap_criterion_from_name(std::string_view name) {
    return parse_name(kSwapCriterionNames, name, "swap criterion");
}

EdgeSwapCounters swap_edges_2d(Triangulation2& mesh, Delaunay) {
    return swap_loop(mesh, false, [&](const TriMesh2& work, const Quad& q) {
        return predicates::incircle_sos(work.point(q.a), work.point(q.b), work.point(q.c),
                                        work.point(q.d), q.a, q.b, q.c, q.d) == Sign::Positive;
    });
}

EdgeSwapCounters swap_edges_2d(Triangulation2& mesh, MaxMinAngle) {
    return swap_loop(mesh, false, [&](const TriMesh2& work, const Quad& q) {
        const double *a = work.point(q.a), *b = work.point(q.b);
        const double *c = work.point(q.c), *d = work.point(q.d);
        const Corner before = smaller(smallest_corner(a, b, c), smallest_corner(b, a, d));
        const Corner after = smaller(smallest_corner(c, a, d), smallest_corner(d, b, c));
        return compare_angles(after, before) == Sign::Positive;
    });
}

namespace {

/// MinMaxAngle's decision: the largest of the six angles strictly decreases.
bool prefers_min_max(const TriMesh2& work, const Quad& q) {
    const double *a = work.point(q.a), *b = work.point(q.b);
    const double *c = work.point(q.c), *d = work.point(q.d);
    const Corner before = larger(largest_corner(a, b, c), largest_corner(b, a, d));
    const Corner after = larger(largest_corner(c, a, d), largest_corner(d, b, c));
    return compare_angles(after, before) == Sign::Negative;
}

}  // namespace

EdgeSwapCounters swap_edges_2d(Triangulation2& mesh, MinMaxAngle) {
    return swap_loop(mesh, false, prefers_min_max);
}

EdgeSwapCounters swap_edges_2d(TriMesh2& mesh, MinMaxAngle, std::span<const EdgeIdx> seeds) {
    return swap_queue(mesh, false, seeds, false, kNoBudget, nullptr, prefers_min_max);
}

EdgeSwapCounters swap_edges_2d(Triangulation2& mesh, MinTotalLength) {
    return swap_loop(mesh, false, [&](const TriMesh2& work, const Quad& q) {
        return compare_lengths(work.point(q.c), work.point(q.d), work.point(q.a),
                               work.point(q.b)) == Sign::Negative;
    });
}

namespace {

/// The loop with a criterion that has no global potential, on a mesh lent as half-edges (no
/// dead triangles): after max_swaps_per_edge times the number of edges swaps, every further
/// quadrilateral is kept (counted in budget_stops).
template <class Prefers>
EdgeSwapCounters budgeted_swap_queue(TriMesh2& work, std::uint32_t max_swaps_per_edge,
                                     SwapVerdicts2* verdicts, Prefers&& prefers) {
    const std::uint64_t triangles = work.tv.size() / 3;
    const std::uint64_t budget = std::uint64_t{max_swaps_per_edge} * 3 * triangles;
    return swap_queue(work, false, {}, true, budget, verdicts, std::forward<Prefers>(prefers));
}

void check_metrics(std::uint32_t vertex_count, const MetricInEllipse& criterion) {
    if (criterion.metrics.size() != 3 * std::size_t{vertex_count}) {
        throw InputError("metric swapping needs three values per vertex: got " +
                         std::to_string(criterion.metrics.size()) + " values for " +
                         std::to_string(vertex_count) + " vertices");
    }
    for (const double m : criterion.metrics) {
        if (!std::isfinite(m)) {
            throw InputError("metric swapping: a metric entry is not finite (" + format_number(m) +
                             ")");
        }
    }
}

/// MetricInEllipse's loop on the lent mesh (criterion checked).
EdgeSwapCounters metric_swap_queue(TriMesh2& work, const MetricInEllipse& criterion) {
    return budgeted_swap_queue(
        work, criterion.max_swaps_per_edge, criterion.verdicts,
        [&](const TriMesh2& mesh, const Quad& q) {
            double m[3] = {0, 0, 0};
            if (criterion.quad_metric) {
                criterion.quad_metric(q.a, q.b, q.c, q.d, m);
            } else {
                for (const VertIdx v : {q.a, q.b, q.c, q.d}) {
                    for (std::size_t k = 0; k < 3; ++k)
                        m[k] += 0.25 * criterion.metrics[3 * std::size_t{v} + k];
                }
            }
            return predicates::in_ellipse_sos(mesh.point(q.a), mesh.point(q.b), mesh.point(q.c),
                                              mesh.point(q.d), m, q.a, q.b, q.c,
                                              q.d) == Sign::Positive;
        });
}

/// QuadPreference's loop on the lent mesh (criterion checked).
EdgeSwapCounters preference_swap_queue(TriMesh2& work, const QuadPreference& criterion) {
    return budgeted_swap_queue(work, criterion.max_swaps_per_edge, criterion.verdicts,
                               [&](const TriMesh2& mesh, const Quad& q) {
                                   return criterion.swap({q.a, q.b, q.c, q.d},
                                                         {mesh.point(q.a), mesh.point(q.b),
                                                          mesh.point(q.c), mesh.point(q.d)});
                               });
}

}  // namespace

EdgeSwapCounters swap_edges_2d(Triangulation2& mesh, MetricInEllipse criterion) {
    check_metrics(mesh.vertex_count(), criterion);
    validate_points_2d(mesh.xy);
    HalfEdgeEdit edit(mesh);
    return metric_swap_queue(edit.mesh(), criterion);
}

EdgeSwapCounters swap_edges_2d(TriMesh2& mesh, MetricInEllipse criterion) {
    check_metrics(mesh.vertex_count(), criterion);
    validate_points_2d(mesh.xy);
    return metric_swap_queue(mesh, criterion);
}

EdgeSwapCounters swap_edges_2d(Triangulation2& mesh, QuadPreference criterion) {
    if (!criterion.swap) throw InputError("quadrilateral swapping needs a decision");
    validate_points_2d(mesh.xy);
    HalfEdgeEdit edit(mesh);
    return preference_swap_queue(edit.mesh(), criterion);
}

EdgeSwapCounters swap_edges_2d(TriMesh2& mesh, QuadPreference criterion) {
    if (!criterion.swap) throw InputError("quadrilateral swapping needs a decision");
    validate_points_2d(mesh.xy);
    return preference_swap_queue(mesh, criterion);
}

EdgeSwapCounters swap_edges_2d(Triangulation2& mesh, DataDependent criterion) {
    if (criterion.values.size() != mesh.vertex_count()) {
        throw InputError("data-dependent swapping needs one value per vertex: got " +
                         std::to_string(criterion.values.size()) + " values for " +
                         std::to_string(mesh.vertex_count()) + " vertices");
    }
    for (std::size_t v = 0; v < criterion.values.size(); ++v) {
        if (!std::isfinite(criterion.values[v])) {
            throw InputError("data-dependent swapping: value of vertex " + std::to_string(v) +
                             " is not finite (" + format_number(criterion.values[v]) + ")");
        }
    }
    const double unit = cost_unit(mesh.xy, criterion.cost);
    return swap_loop(mesh, true, [&](const TriMesh2& work, const Quad& q) {
        // The outer apexes across the four sides, read before anything changes.
        const VertIdx o_bc = outer_apex(work, next_edge(q.e));
        const VertIdx o_ca = outer_apex(work, prev_edge(q.e));
        const VertIdx o_ad = outer_apex(work, next_edge(q.f));
        const VertIdx o_db = outer_apex(work, prev_edge(q.f));
        std::array<double, 5> before{}, after{};
        auto cost = [&](VertIdx p, VertIdx r, VertIdx left, VertIdx right) {
            return right == kNone ? 0.0
                                  : canonical_edge_cost(work, criterion, p, r, left, right, unit);
        };
        before = {cost(q.a, q.b, q.c, q.d), cost(q.b, q.c, q.a, o_bc), cost(q.c, q.a, q.b, o_ca),
                  cost(q.a, q.d, q.b, o_ad), cost(q.d, q.b, q.a, o_db)};
        after = {cost(q.c, q.d, q.b, q.a), cost(q.b, q.c, q.d, o_bc), cost(q.c, q.a, q.d, o_ca),
                 cost(q.a, q.d, q.c, o_ad), cost(q.d, q.b, q.c, o_db)};
        for (std::size_t i = 0; i < 5; ++i) {
            if (!std::isfinite(before[i]) || !std::isfinite(after[i])) return false;
        }
        return sign_of_difference(after, before) == Sign::Negative;
    });
}

void link_neighbors_2d(Triangulation2& mesh, CheckNumbering numbering) {
    const std::size_t slots = mesh.triangles.size();
    if (slots % 3 != 0) throw InputError("triangle list length is not a multiple of 3");
    if (!mesh.constrained.empty() && mesh.constrained.size() != slots) {
        throw InputError("constraint flags: " + std::to_string(mesh.constrained.size()) +
                         " entries for " + std::to_string(slots) + " triangle edges");
    }
    validate_points_2d(mesh.xy);
    const std::uint32_t n = mesh.vertex_count();
    auto vertex_name = [&](std::uint64_t v) { return std::to_string(v + numbering.first_vertex); };
    auto triangle_name = [&](std::size_t t) {
        return "triangle " + std::to_string(t + numbering.first_triangle);
    };
    std::vector<std::pair<std::uint64_t, EdgeIdx>> directed;
    directed.reserve(slots);
    for (std::size_t t = 0; 3 * t < slots; ++t) {
        const VertIdx p = mesh.triangles[3 * t], q = mesh.triangles[3 * t + 1],
                      r = mesh.triangles[3 * t + 2];
        for (const VertIdx v : {p, q, r}) {
            if (v >= n) {
                throw InputError(triangle_name(t) + ": vertex " + vertex_name(v) +
                                 " out of range (" + std::to_string(n) + " vertices)");
            }
        }
        if (predicates::orient2d(mesh.point(p), mesh.point(q), mesh.point(r)) != Sign::Positive) {
            throw InputError(triangle_name(t) + " (" + vertex_name(p) + ", " + vertex_name(q) +
                             ", " + vertex_name(r) + ") is not strictly counter-clockwise");
        }
        for (unsigned k = 0; k < 3; ++k) {
            const std::size_t e = 3 * t + k;
            directed.emplace_back(
                (std::uint64_t{mesh.triangles[e]} << 32) | mesh.triangles[3 * t + (k + 1) % 3],
                static_cast<EdgeIdx>(e));
        }
    }
    std::sort(directed.begin(), directed.end());
    for (std::size_t i = 1; i < directed.size(); ++i) {
        if (directed[i].first == directed[i - 1].first) {
            throw InputError("edge (" + vertex_name(directed[i].first >> 32) + ", " +
                             vertex_name(directed[i].first & 0xFFFFFFFFu) + ") of " +
                             triangle_name(directed[i].second / 3) +
                             " appears twice in the same direction (overlapping triangles)");
        }
    }
    mesh.neighbors.assign(slots, kNone);
    for (const auto& [key, e] : directed) {
        const std::uint64_t reverse = (key << 32) | (key >> 32);
        const auto it =
            std::lower_bound(directed.begin(), directed.end(), std::make_pair(reverse, EdgeIdx{0}));
        if (it != directed.end() && it->first == reverse) {
            mesh.neighbors[e] = it->second / 3;
            if (!mesh.constrained.empty() && mesh.constrained[it->second] != 0) {
                mesh.constrained[e] = 1;
            }
        }
    }
}

}  // namespace exactmesh::triangulation
