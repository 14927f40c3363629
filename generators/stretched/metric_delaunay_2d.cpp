// SPDX-License-Identifier: MIT
// Metric Delaunay mesh generation (see metric_delaunay_2d.hpp for the steps and references).
#include "generators/stretched/metric_delaunay_2d.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
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

/// The metric length of the edge from p to q when the metric varies geometrically between
/// the lengths measured in the end metrics, lp and lq [George-Borouchaki98 §10.3]:
/// (lq - lp) / ln(lq / lp), and the parameter t where half of it is reached.
struct EdgeLength {
    double length;
    double half;  ///< parameter in (0, 1) of the halfway point
};

EdgeLength edge_length(double lp, double lq) {
    if (!(lp > 0) || !(lq > 0)) return {std::max(lp, lq), 0.5};
    const double r = lq / lp;
    if (std::fabs(r - 1) < 1e-6) return {0.5 * (lp + lq), 0.5};
    const double log_r = std::log(r);
    return {(lq - lp) / log_r, std::log(0.5 * (1 + r)) / log_r};
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
        // The length of the would-be edge from the metrics at both of its ends, as the
        // insertion passes measure edges.
        return edge_length(metric_length(m, dx, dy), metric_length(metric_of(v), dx, dy)).length <
               options_.min_spacing;
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
                const EdgeLength l = edge_length(metric_length(metric_of(u), dx, dy),
                                                 metric_length(metric_of(v), dx, dy));
                if (!(l.length > kSqrt2)) continue;
                proposals.push_back(p[0] + l.half * dx);
                proposals.push_back(p[1] + l.half * dy);
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
        tri::EdgeSwapCounters swapped = metric_swaps_2d(mesh, at);
        result.counters.swaps = swapped.swaps;
        result.counters.swap_budget_hits = swapped.budget_stops;
        // Smoothing of the inserted points (the boundary's stay), each followed by swaps.
        const std::vector<double> relax(mesh.vertex_count(), 0.5);
        const auto first_inserted = static_cast<tri::VertIdx>(boundary_.xy.size() / 2);
        for (int pass = 0; pass < options_.smoothing_passes; ++pass) {
            const PointSmoothingCounters2 smoothed = smooth_metric_points_2d(
                mesh, at, relax, 0.3, MoveLimit::MetricLength, first_inserted, true);
            result.counters.smoothing_moves += smoothed.moves;
            for (tri::VertIdx v = first_inserted; v < mesh.vertex_count(); ++v)
                at[v] = options_.metric(mesh.point(v)[0], mesh.point(v)[1]);
            swapped = metric_swaps_2d(mesh, at);
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
