// SPDX-License-Identifier: MIT
// Metric Delaunay mesh generation (see metric_delaunay_2d.hpp for the steps and references).
#include "generators/stretched/metric_delaunay_2d.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

#include "base/errors.hpp"
#include "base/number_text.hpp"
#include "generators/boundary/domain_boundary_2d.hpp"
#include "generators/sizing/size_function.hpp"
#include "generators/stretched/metric_mesh_edits_2d.hpp"
#include "predicates/orient2d.hpp"
#include "triangulation/constrained/constrained_triangulation_2d.hpp"
#include "triangulation/mesh/spatial_sort.hpp"
#include "triangulation/modification/edge_swap_2d.hpp"

namespace exactmesh::generators {

namespace tri = triangulation;

namespace {

constexpr double kSqrt2 = 1.4142135623730951;

/// (x, y) divided by its length, computed without squares: scaled by a power of two first.
std::array<double, 2> unit_vector(double x, double y) {
    const double largest = std::max(std::fabs(x), std::fabs(y));
    if (!(largest > 0) || !std::isfinite(largest)) return {1, 0};
    const int k = std::ilogb(largest);
    const double sx = std::ldexp(x, -k), sy = std::ldexp(y, -k);
    const double n = std::hypot(sx, sy);
    return {sx / n, sy / n};
}

/// The length of an edge in the metric and the parameter t in (0, 1) of its halfway point.
struct EdgeLength {
    double length;
    double half;  ///< parameter in (0, 1) of the halfway point
};

/// The metric length of the edge when the metric varies geometrically between the lengths lp and
/// lq it has at its ends [George-Borouchaki98 §10.3]: (lq - lp) / ln(lq / lp), and the parameter
/// where half of it is reached.
EdgeLength geometric_length(double lp, double lq) {
    if (!(lp > 0) || !(lq > 0)) return {std::max(lp, lq), 0.5};
    const double r = lq / lp;
    if (std::fabs(r - 1) < 1e-6) return {0.5 * (lp + lq), 0.5};
    const double log_r = std::log(r);
    return {(lq - lp) / log_r, std::log(0.5 * (1 + r)) / log_r};
}

/// The edge (dx, dy) from a vertex of metric mp to one of metric mq, with the metric interpolated
/// log-Euclidean between its ends' (as metric_quality_report_2d measures edges): its length in the
/// mean exp((log Mp + log Mq) / 2), and its halfway parameter from the lengths in the
/// interpolated metrics at 1/4 and 3/4 (extended geometrically to the ends). Measuring in each
/// end's own metric instead misjudges an edge where the metric rotates: a chord of a curved layer
/// is oblique to the direction of both ends' metrics, and its small component across them counts
/// at the layer's small size, so chords of unit length were split into pieces of a third.
EdgeLength interpolated_length(const Metric2& mp, const Metric2& mq, double dx, double dy) {
    const Metric2 ends[2] = {mp, mq};
    static constexpr double kHalf[2] = {0.5, 0.5};
    static constexpr double kQuarter[2] = {0.75, 0.25};
    static constexpr double kThreeQuarters[2] = {0.25, 0.75};
    const double length = metric_length(log_euclidean_mean(ends, kHalf), dx, dy);
    const double la = metric_length(log_euclidean_mean(ends, kQuarter), dx, dy);
    const double lb = metric_length(log_euclidean_mean(ends, kThreeQuarters), dx, dy);
    if (!(la > 0) || !(lb > 0)) return {length, 0.5};
    // l(t) = la (lb / la)^(2 t - 1/2): at the ends la sqrt(la / lb) and lb sqrt(lb / la).
    const double root = std::sqrt(lb / la);
    return {length, geometric_length(la / root, lb * root).half};
}

/// The parameter in (0, 1) of the point halfway along the edge from p by (dx, dy) in the metric
/// field itself: its length density sampled at the middles of kHalfwaySamples equal parts
/// (linear within each). Where the field has a thin layer between the ends (a boundary layer the
/// edge crosses), the point lands in it, while the interpolation of the ends' metrics sees none.
constexpr int kHalfwaySamples = 8;

double field_halfway(const MetricField2& field, const double* p, double dx, double dy) {
    std::array<double, kHalfwaySamples> density{};
    double total = 0;
    for (int i = 0; i < kHalfwaySamples; ++i) {
        const double t = (i + 0.5) / kHalfwaySamples;
        density[i] = metric_length(field(p[0] + t * dx, p[1] + t * dy), dx, dy);
        if (!(density[i] > 0) || !std::isfinite(density[i])) return 0.5;
        total += density[i];
    }
    double reached = 0;
    for (int i = 0; i < kHalfwaySamples; ++i) {
        if (reached + density[i] >= 0.5 * total) {
            const double t = (i + (0.5 * total - reached) / density[i]) / kHalfwaySamples;
            return std::clamp(t, 0.01, 0.99);
        }
        reached += density[i];
    }
    return 0.5;
}

/// sqrt(det M) times the area of the triangle (p, q, r), the metric at its centroid, summed over
/// a subdivision fine enough that the metric area of each piece is below 4 unit triangles or
/// the depth reaches 8. Areas are taken in the metric's frame (metric_map): no squared size.
double metric_area(const MetricField2& field, const double* p, const double* q, const double* r,
                   int depth) {
    const double cx = (p[0] + q[0] + r[0]) / 3, cy = (p[1] + q[1] + r[1]) / 3;
    const Metric2 m = field(cx, cy);
    double ux, uy, vx, vy;
    metric_map(m, q[0] - p[0], q[1] - p[1], ux, uy);
    metric_map(m, r[0] - p[0], r[1] - p[1], vx, vy);
    const double area = 0.5 * std::fabs(ux * vy - uy * vx);
    if (!(area > 4.0) || depth >= 8) return area;
    const double pq[2] = {0.5 * (p[0] + q[0]), 0.5 * (p[1] + q[1])};
    const double qr[2] = {0.5 * (q[0] + r[0]), 0.5 * (q[1] + r[1])};
    const double rp[2] = {0.5 * (r[0] + p[0]), 0.5 * (r[1] + p[1])};
    return metric_area(field, p, pq, rp, depth + 1) + metric_area(field, pq, q, qr, depth + 1) +
           metric_area(field, rp, qr, r, depth + 1) + metric_area(field, pq, qr, rp, depth + 1);
}

/// One pass over the finished mesh's unconstrained edges: each longer than sqrt 2
/// (interpolated_length) is split at its halfway point m into four triangles, unless m lies closer
/// than min_spacing to one of the edge's two opposite vertices, or one of the four triangles
/// would not be strictly counter-clockwise (exact orient2d), or one of its two triangles was
/// already changed in this pass. at[] (the field per vertex) and the triangles' attributes (when
/// present) follow. Returns the number of splits.
std::uint64_t split_long_edges(tri::Triangulation2& mesh, std::vector<Metric2>& at,
                               std::vector<double>& attributes, const MetricField2& field,
                               double min_spacing) {
    const tri::TriIdx count = mesh.triangle_count();
    std::vector<std::uint8_t> changed(count, 0);
    std::uint64_t splits = 0;
    for (tri::TriIdx t = 0; t < count; ++t) {
        for (unsigned k = 0; k < 3 && changed[t] == 0; ++k) {
            const tri::TriIdx u = mesh.neighbors[3 * t + k];
            if (u == tri::kNone || u < t || changed[u] != 0 || mesh.is_constrained(t, int(k))) {
                continue;
            }
            const tri::VertIdx a = mesh.triangles[3 * t + k];
            const tri::VertIdx b = mesh.triangles[3 * t + (k + 1) % 3];
            const tri::VertIdx c = mesh.triangles[3 * t + (k + 2) % 3];
            unsigned j = 0;
            while (mesh.neighbors[3 * u + j] != t) ++j;
            const tri::VertIdx d = mesh.triangles[3 * u + (j + 2) % 3];
            const double* pa = mesh.point(a);
            const double* pb = mesh.point(b);
            const double dx = pb[0] - pa[0], dy = pb[1] - pa[1];
            const EdgeLength l = interpolated_length(at[a], at[b], dx, dy);
            if (!(l.length > kSqrt2)) continue;
            const double half = field_halfway(field, pa, dx, dy);
            const double m[2] = {pa[0] + half * dx, pa[1] + half * dy};
            const Metric2 mm = field(m[0], m[1]);
            const auto close = [&](tri::VertIdx v) {
                const double* pv = mesh.point(v);
                return interpolated_length(mm, at[v], pv[0] - m[0], pv[1] - m[1]).length <
                       min_spacing;
            };
            if (close(c) || close(d)) continue;
            const double* pc = mesh.point(c);
            const double* pd = mesh.point(d);
            using predicates::Sign;
            if (predicates::orient2d(pa, m, pc) != Sign::Positive ||
                predicates::orient2d(m, pb, pc) != Sign::Positive ||
                predicates::orient2d(pb, m, pd) != Sign::Positive ||
                predicates::orient2d(m, pa, pd) != Sign::Positive) {
                continue;
            }
            // t = (a, b, c) and u = (b, a, d) become t (a, m, c), t2 (m, b, c), u (b, m, d) and
            // u2 (m, a, d).
            const tri::VertIdx mv = mesh.vertex_count();
            mesh.xy.push_back(m[0]);
            mesh.xy.push_back(m[1]);
            at.push_back(mm);
            const tri::TriIdx t2 = mesh.triangle_count(), u2 = t2 + 1;
            const tri::TriIdx n_bc = mesh.neighbors[3 * t + (k + 1) % 3];
            const tri::TriIdx n_ca = mesh.neighbors[3 * t + (k + 2) % 3];
            const tri::TriIdx n_ad = mesh.neighbors[3 * u + (j + 1) % 3];
            const tri::TriIdx n_db = mesh.neighbors[3 * u + (j + 2) % 3];
            const bool constrained = !mesh.constrained.empty();
            std::uint8_t c_bc = 0, c_ca = 0, c_ad = 0, c_db = 0;
            if (constrained) {
                c_bc = mesh.constrained[3 * t + (k + 1) % 3];
                c_ca = mesh.constrained[3 * t + (k + 2) % 3];
                c_ad = mesh.constrained[3 * u + (j + 1) % 3];
                c_db = mesh.constrained[3 * u + (j + 2) % 3];
            }
            const auto write = [&](tri::TriIdx at_slot, std::array<tri::VertIdx, 3> v,
                                   std::array<tri::TriIdx, 3> n, std::array<std::uint8_t, 3> f) {
                if (at_slot == mesh.triangle_count()) {
                    mesh.triangles.insert(mesh.triangles.end(), v.begin(), v.end());
                    mesh.neighbors.insert(mesh.neighbors.end(), n.begin(), n.end());
                    if (constrained)
                        mesh.constrained.insert(mesh.constrained.end(), f.begin(), f.end());
                } else {
                    for (unsigned i = 0; i < 3; ++i) {
                        mesh.triangles[3 * at_slot + i] = v[i];
                        mesh.neighbors[3 * at_slot + i] = n[i];
                        if (constrained) mesh.constrained[3 * at_slot + i] = f[i];
                    }
                }
            };
            write(t, {a, mv, c}, {u2, t2, n_ca}, {0, 0, c_ca});
            write(u, {b, mv, d}, {t2, u2, n_db}, {0, 0, c_db});
            write(t2, {mv, b, c}, {u, n_bc, t}, {0, c_bc, 0});
            write(u2, {mv, a, d}, {t, n_ad, u}, {0, c_ad, 0});
            const auto relink = [&](tri::TriIdx n, tri::TriIdx from, tri::TriIdx to) {
                if (n == tri::kNone) return;
                for (unsigned i = 0; i < 3; ++i) {
                    if (mesh.neighbors[3 * n + i] == from) mesh.neighbors[3 * n + i] = to;
                }
            };
            relink(n_bc, t, t2);
            relink(n_ad, u, u2);
            if (!attributes.empty()) {
                attributes.push_back(attributes[t]);
                attributes.push_back(attributes[u]);
            }
            changed[t] = changed[u] = 1;
            changed.push_back(1);  // t2
            changed.push_back(1);  // u2
            ++splits;
        }
    }
    return splits;
}

class MetricMesher {
  public:
    MetricMesher(const tri::Pslg& pslg, const MetricDelaunayOptions2& options,
                 DomainBoundary2&& boundary, const tri::Cdt2Options& cdt_options)
        : options_(options),
          boundary_(std::move(boundary)),
          cdt_(tri::Pslg{boundary_.xy, boundary_.pieces, pslg.holes, pslg.regions}, cdt_options) {}

    MetricDelaunayResult2 run(std::uint64_t budget);

  private:
    /// The metric of mesh vertex v (cached; vertices are only ever appended).
    const Metric2& metric_of(tri::VertIdx v);
    /// True when some vertex of t or of its neighbours lies closer than min_spacing to (x, y)
    /// in the metric m.
    bool too_close(tri::TriIdx t, const Metric2& m, double x, double y);
    /// One pass: proposals at the halfway points of the long edges, inserted in Hilbert order.
    std::uint64_t insertion_pass(std::uint64_t budget);

    const MetricDelaunayOptions2& options_;
    DomainBoundary2 boundary_;
    tri::ConstrainedTriangulation2 cdt_;
    std::vector<Metric2> metrics_;
    std::vector<bool> known_;
    MetricDelaunayCounters2 counters_;
};

const Metric2& MetricMesher::metric_of(tri::VertIdx v) {
    if (v >= metrics_.size()) {
        metrics_.resize(v + 1);
        known_.resize(v + 1, false);
    }
    if (!known_[v]) {
        const double* p = cdt_.mesh().point(v);
        metrics_[v] = options_.metric(p[0], p[1]);
        known_[v] = true;
    }
    return metrics_[v];
}

bool MetricMesher::too_close(tri::TriIdx t, const Metric2& m, double x, double y) {
    const tri::TriMesh2& mesh = cdt_.mesh();
    const auto close = [&](tri::VertIdx v) {
        if (v == tri::kInfinite) return false;
        const double* p = mesh.point(v);
        const double dx = p[0] - x, dy = p[1] - y;
        // The length of the would-be edge as the insertion passes measure edges.
        return interpolated_length(m, metric_of(v), dx, dy).length < options_.min_spacing;
    };
    for (unsigned k = 0; k < 3; ++k) {
        if (close(mesh.tv[3 * t + k])) return true;
        const tri::TriIdx u = tri::triangle_of(mesh.twin[3 * t + k]);
        for (unsigned j = 0; j < 3; ++j) {
            if (close(mesh.tv[3 * u + j])) return true;
        }
    }
    return false;
}

std::uint64_t MetricMesher::insertion_pass(std::uint64_t budget) {
    // The proposals of this pass: one per long unconstrained edge of the domain.
    std::vector<double> proposals;
    {
        const tri::TriMesh2& mesh = cdt_.mesh();
        for (tri::TriIdx t = 0; t < mesh.triangle_slots(); ++t) {
            if (!cdt_.in_domain(t)) continue;
            for (unsigned k = 0; k < 3; ++k) {
                const tri::EdgeIdx e = 3 * t + k;
                const tri::TriIdx across = tri::triangle_of(mesh.twin[e]);
                // Each interior edge once (from its lower-numbered triangle); constrained edges
                // (the boundary, already split to the metric) never.
                if (cdt_.segment_of(e) != tri::kNone || !cdt_.in_domain(across) || across < t) {
                    continue;
                }
                const tri::VertIdx u = mesh.origin(e), v = mesh.destination(e);
                const double* p = mesh.point(u);
                const double* q = mesh.point(v);
                const double dx = q[0] - p[0], dy = q[1] - p[1];
                // A copy: metric_of may grow the cache the other reference points into.
                const Metric2 mu = metric_of(u);
                const EdgeLength l = interpolated_length(mu, metric_of(v), dx, dy);
                if (!(l.length > kSqrt2)) continue;
                const double half = field_halfway(options_.metric, p, dx, dy);
                proposals.push_back(p[0] + half * dx);
                proposals.push_back(p[1] + half * dy);
            }
        }
    }
    counters_.proposals += proposals.size() / 2;
    std::vector<std::uint32_t> order(proposals.size() / 2);
    for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
    tri::hilbert_sort_2d(proposals, order);
    std::uint64_t inserted = 0;
    for (const std::uint32_t i : order) {
        if (counters_.inserted >= budget) break;
        const double x = proposals[2 * i], y = proposals[2 * i + 1];
        const tri::TriIdx t = cdt_.locate(x, y);
        if (cdt_.mesh().is_infinite(t) || !cdt_.in_domain(t)) {
            ++counters_.rejected;
            continue;
        }
        const Metric2 m = options_.metric(x, y);
        if (too_close(t, m, x, y)) {
            ++counters_.too_close;
            continue;
        }
        double matrix[3];
        matrix_for_predicate(m, matrix);
        if (cdt_.insert_in_metric_cavity(t, x, y, matrix) == tri::CavityInsertion::Inserted) {
            ++counters_.inserted;
            ++inserted;
            const tri::VertIdx v = cdt_.mesh().vertex_count() - 1;
            if (v >= metrics_.size()) {
                metrics_.resize(v + 1);
                known_.resize(v + 1, false);
            }
            metrics_[v] = m;  // the field's value there, already computed
            known_[v] = true;
        } else {
            ++counters_.rejected;
        }
    }
    return inserted;
}

MetricDelaunayResult2 MetricMesher::run(std::uint64_t budget) {
    // Each pass at least halves the longest edges; 64 passes reach any metric a double holds.
    for (int pass = 0; pass < 64; ++pass) {
        ++counters_.passes;
        if (insertion_pass(budget) == 0 || counters_.inserted >= budget) break;
    }
    counters_.cavity_corrections = cdt_.counters().cavity_corrections;
    MetricDelaunayResult2 result{std::move(cdt_).take_result(), counters_};
    tri::Cdt2Result& out = result.mesh;
    restore_input_terms(boundary_, out);
    tri::Triangulation2& mesh = out.mesh;
    if (options_.swap && mesh.triangle_count() > 0) {
        std::vector<Metric2> at(mesh.vertex_count());
        for (tri::VertIdx v = 0; v < mesh.vertex_count(); ++v)
            at[v] = options_.metric(mesh.point(v)[0], mesh.point(v)[1]);
        tri::EdgeSwapCounters swapped = metric_swaps_2d(mesh, at, true);
        result.counters.swaps = swapped.swaps;
        result.counters.swap_budget_hits = swapped.budget_stops;
        // The edges still long after the swaps (a varying metric leaves, after the insertion
        // passes, vertices near the middle of a long edge, which its spacing test then keeps
        // from being split; the swaps turn it into two shorter ones) are split, and swapped
        // again, until none is split.
        for (int round = 0; round < 32; ++round) {
            if (result.counters.inserted + result.counters.split_after_swaps >= budget) break;
            const std::uint64_t split = split_long_edges(mesh, at, out.triangle_attributes,
                                                         options_.metric, options_.min_spacing);
            result.counters.split_after_swaps += split;
            if (split == 0) break;
            swapped = metric_swaps_2d(mesh, at, true);
            result.counters.swaps += swapped.swaps;
            result.counters.swap_budget_hits += swapped.budget_stops;
        }
        // Smoothing of the inserted points (the boundary's stay), each followed by swaps.
        const std::vector<double> relax(mesh.vertex_count(), 0.5);
        const auto first_inserted = static_cast<tri::VertIdx>(boundary_.xy.size() / 2);
        for (int pass = 0; pass < options_.smoothing_passes; ++pass) {
            const PointSmoothingCounters2 smoothed = smooth_metric_points_2d(
                mesh, at, relax, 0.3, MoveLimit::MetricLength, first_inserted, true);
            result.counters.smoothing_moves += smoothed.moves;
            for (tri::VertIdx v = first_inserted; v < mesh.vertex_count(); ++v)
                at[v] = options_.metric(mesh.point(v)[0], mesh.point(v)[1]);
            swapped = metric_swaps_2d(mesh, at, true);
            result.counters.swaps += swapped.swaps;
            result.counters.swap_budget_hits += swapped.budget_stops;
        }
    }
    return result;
}

}  // namespace

double expected_metric_triangle_count(const MeshDomain2& domain, const MetricField2& metric) {
    const tri::Triangulation2& mesh = domain.triangulation().mesh;
    double area = 0;
    for (tri::TriIdx t = 0; t < mesh.triangle_count(); ++t) {
        area += metric_area(metric, mesh.point(mesh.triangles[3 * t]),
                            mesh.point(mesh.triangles[3 * t + 1]),
                            mesh.point(mesh.triangles[3 * t + 2]), 0);
    }
    return area / (std::sqrt(3.0) / 4);
}

MetricDelaunayResult2 metric_delaunay_2d(const MeshDomain2& domain,
                                         const MetricDelaunayOptions2& options) {
    if (!(options.min_spacing > 0 && options.min_spacing < 1)) {
        throw InputError("metric Delaunay: min_spacing " + format_number(options.min_spacing) +
                         " is outside (0, 1) (a metric length)");
    }
    const std::uint64_t budget =
        options.max_steiner_points != 0 ? options.max_steiner_points : kDefaultMetricPointBudget;
    // A triangulation of V vertices has about 2V triangles.
    const double estimate = expected_metric_triangle_count(domain, options.metric);
    if (!(estimate <= 2.0 * static_cast<double>(budget))) {
        throw InputError("the metric (" + options.metric.describe() + ") asks for " +
                         (estimate > 1e300 ? std::string("more than 1e300")
                                           : "about " + format_approximate(estimate)) +
                         " triangles over the domain, more than the budget of about " +
                         format_approximate(2.0 * static_cast<double>(budget)) +
                         " (--max-steiner raises it)");
    }
    const tri::Cdt2Options& cdt = domain.domain_options();
    const MetricField2& field = options.metric;
    // Each piece split to the metric's size along its own direction.
    DomainBoundary2 boundary =
        discretize_domain_boundary(domain, [&field](const double* a, const double* b) {
            const std::array<double, 2> u = unit_vector(b[0] - a[0], b[1] - a[1]);
            return SizeFunction::analytic(
                [&field, u](double x, double y) {
                    return 1.0 / metric_length(field(x, y), u[0], u[1]);
                },
                "the metric's size along a boundary piece");
        });
    const std::uint64_t boundary_points = boundary.xy.size() / 2 - boundary.cdt.mesh.xy.size() / 2;
    MetricMesher mesher(domain.pslg(), options, std::move(boundary), cdt);
    MetricDelaunayResult2 result = mesher.run(budget);
    result.counters.boundary_points = boundary_points;
    return result;
}

std::vector<std::pair<std::string, std::uint64_t>> counter_list(const MetricDelaunayCounters2& c) {
    return counters_by_name(kMetricDelaunayCounterNames, c);
}

}  // namespace exactmesh::generators
