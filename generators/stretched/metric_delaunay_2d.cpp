// SPDX-License-Identifier: MIT
// Metric Delaunay mesh generation (see metric_delaunay_2d.hpp for the steps and references).
#include "generators/stretched/metric_delaunay_2d.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

#include "base/errors.hpp"
#include "base/number_text.hpp"
#include "generators/boundary/domain_boundary_2d.hpp"
#include "generators/sizing/size_function.hpp"
#include "generators/stretched/metric_mesh_edits_2d.hpp"
#include "predicates/orient2d.hpp"
#include "predicates/power_of_two.hpp"
#include "triangulation/constrained/constrained_triangulation_2d.hpp"
#include "triangulation/mesh/flip_2d.hpp"
#include "triangulation/mesh/spatial_sort.hpp"
#include "triangulation/modification/edge_swap_2d.hpp"
#include "triangulation/modification/vertex_removal_2d.hpp"

namespace exactmesh::generators {

namespace tri = triangulation;

namespace {

constexpr double kSqrt2 = 1.4142135623730951;
constexpr double kUnitLow = 0.7071067811865476;
/// Most rounds of late splits and removals.
constexpr int kEditRounds = 8;

/// (x, y) divided by its length, computed without squares: scaled by a power of two first.
std::array<double, 2> unit_vector(double x, double y) {
    const double largest = std::max(std::fabs(x), std::fabs(y));
    if (!(largest > 0) || !std::isfinite(largest)) return {1, 0};
    const int k = std::ilogb(largest);
    const double sx = std::ldexp(x, -k), sy = std::ldexp(y, -k);
    const double n = std::hypot(sx, sy);
    return {sx / n, sy / n};
}

/// Log-Euclidean forms of metrics with the sizes in units of 2^unit (one power of two per mesh,
/// from the domain's metric: a domain and its metric scaled by 2^k give the same forms), so that
/// each vertex's logarithm is taken once.
LogMetric2 scaled_log_form(const Metric2& m, int unit) {
    // PowerOfTwo: the bits of std::ldexp, without its library call.
    const predicates::PowerOfTwo down(-unit);
    Metric2 scaled = m;
    scaled.h1 = down(scaled.h1);
    scaled.h2 = down(scaled.h2);
    return log_form(scaled);
}

/// The metric length of the edge (dx, dy) between vertices of log forms lp and lq (units of
/// 2^unit) in the log-Euclidean mean of their metrics, exp((log Mp + log Mq) / 2), as
/// metric_quality_report_2d measures edges. Measuring in each end's own metric instead misjudges
/// an edge where the metric rotates: a chord of a curved layer is oblique to the direction of
/// both ends' metrics, and its small component across them counts at the layer's small size, so
/// chords of unit length were split into pieces of a third.
double mean_length(const LogMetric2& lp, const LogMetric2& lq, int unit, double dx, double dy,
                   MetricFromLogFormMemo& memo) {
    Metric2 mean = memo(0.5 * (lp.l11 + lq.l11), 0.5 * (lp.l12 + lq.l12), 0.5 * (lp.l22 + lq.l22));
    const predicates::PowerOfTwo up(unit);
    mean.h1 = up(mean.h1);
    mean.h2 = up(mean.h2);
    return metric_length(mean, dx, dy);
}

/// The field's metric at each vertex of a mesh and its log form (units of 2^unit).
struct VertexMetrics {
    int unit = 0;
    std::vector<Metric2> at;
    std::vector<LogMetric2> logs;
    /// The exponentials of the means (shared by the whole run, swaps and smoothing included).
    MetricFromLogFormMemo* memo = nullptr;

    void push_back(const Metric2& m) {
        at.push_back(m);
        logs.push_back(scaled_log_form(m, unit));
    }
    /// mean_length of the edge (dx, dy) between vertices u and v.
    double length(tri::VertIdx u, tri::VertIdx v, double dx, double dy) const {
        return length_to(at[u], logs[u], v, dx, dy);
    }
    /// mean_length of the edge (dx, dy) from a point of metric m (log form lm) to vertex v; in m
    /// itself when v's metric is the same (a constant field: no exponential to take).
    double length_to(const Metric2& m, const LogMetric2& lm, tri::VertIdx v, double dx,
                     double dy) const {
        const Metric2& w = at[v];
        if (m.h1 == w.h1 && m.h2 == w.h2 && m.c == w.c && m.s == w.s) {
            return metric_length(m, dx, dy);
        }
        return mean_length(lm, logs[v], unit, dx, dy, *memo);
    }
};

/// The parameter in (0, 1) of the point halfway along the edge from p by (dx, dy) in the metric
/// field itself: its length density sampled at the middles of kHalfwaySamples equal parts
/// (linear within each). Where the field has a thin layer between the ends (a boundary layer the
/// edge crosses), the point lands in it, while the interpolation of the ends' metrics sees none.
constexpr int kHalfwaySamples = 8;

double field_halfway(const MetricField2& field, const double* p, double dx, double dy) {
    std::array<double, kHalfwaySamples> density{};
    double total = 0;
    // A uniform field has the same density at every sample: measured once (the same doubles).
    const double uniform_density =
        field.is_uniform() ? metric_length(field(p[0], p[1]), dx, dy) : 0.0;
    for (int i = 0; i < kHalfwaySamples; ++i) {
        const double t = (i + 0.5) / kHalfwaySamples;
        density[i] = field.is_uniform()
                         ? uniform_density
                         : metric_length(field(p[0] + t * dx, p[1] + t * dy), dx, dy);
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

/// The unit vector of the metric's smallest size (across a layer) and that size.
struct Across {
    double x, y, h, along;
};
Across across_of(const Metric2& m) {
    if (m.h1 <= m.h2) return {m.c, m.s, m.h1, m.h2};
    return {-m.s, m.c, m.h2, m.h1};
}

/// The point proposed on the long edge from p by (dx, dy), whose ends have metrics mp and mq: the
/// halfway point in the field (field_halfway), except, with `columns`, where the edge lies in a
/// layer that turns so fast that the chord of one cell along it sags by more than half the
/// layer's thickness (the direction across the field turns by an angle a over one size along
/// the layer, and a chord of length L sags by about L a / 8, so L a > 4 h across). There a
/// straight edge along the layer between two vertices crosses the layers below them unless their
/// vertices stand in the same columns across the layer, and a layer of vertices placed anyhow
/// can only be joined by edges across several layers (thin triangles between columns a third of
/// a size apart: 78% unit edges on the curved layer of aspect ratio 1000). So:
///  - an edge mostly across the layer (its metric component across the larger one, and the one
///    along at most sqrt 2) gets its point on the line across the layer through its finer end
///    (the end whose size across is smaller), at the halfway point's distance across: the
///    column of that end continued;
///  - an edge along the layer (or across a gap between columns wider than sqrt 2) gets its point
///    on the arc about the centre where the lines across the layer at its two ends meet, at the
///    halfway point's bearing from that centre and at the ends' mean distance from it (the finer
///    end's when the edge runs mostly across): a new column between two, in the layer of its ends
///    rather than layers below, where the chord's middle lies.
/// The arc is not used when the lines at the ends are parallel within 1e-6 or when it would move
/// the point by half the edge's length or more. Scale-free: the tests are on ratios of sizes and
/// on unit vectors, and the points are sums of the ends' coordinates and lengths.
std::array<double, 2> proposal_point(const MetricField2& field, const double* p, double dx,
                                     double dy, const Metric2& mp, const Metric2& mq,
                                     bool columns) {
    const double half = field_halfway(field, p, dx, dy);
    const std::array<double, 2> m = {p[0] + half * dx, p[1] + half * dy};
    if (!columns || field.is_uniform()) return m;
    const Across a = across_of(field(m[0], m[1]));
    if (!(a.along > 2 * a.h)) return m;
    // The turning over one size along the layer, sampled half a size on either side.
    const double sx = 0.5 * a.along * a.y, sy = 0.5 * a.along * a.x;
    const Across left = across_of(field(m[0] - sx, m[1] + sy));
    const Across right = across_of(field(m[0] + sx, m[1] - sy));
    const double turn = std::fabs(left.x * right.y - left.y * right.x);
    if (!(a.along * turn > 4 * a.h)) return m;
    const double across = std::fabs(dx * a.x + dy * a.y) / a.h;
    const double along = std::fabs(-dx * a.y + dy * a.x) / a.along;
    const Across ap = across_of(mp), aq = across_of(mq);
    const bool from_p = ap.h <= aq.h;
    const double q[2] = {p[0] + dx, p[1] + dy};
    if (across > along && !(along > kSqrt2)) {
        const Across& w = from_p ? ap : aq;
        const double* pw = from_p ? p : q;
        const double t = (m[0] - pw[0]) * w.x + (m[1] - pw[1]) * w.y;
        return {pw[0] + t * w.x, pw[1] + t * w.y};
    }
    // The centre: p + s ap = q + u aq, s = ((q - p) x aq) / (ap x aq).
    const double cross = ap.x * aq.y - ap.y * aq.x;
    if (!(std::fabs(cross) > 1e-6)) return m;
    const double s = (dx * aq.y - dy * aq.x) / cross;
    const double cx = p[0] + s * ap.x, cy = p[1] + s * ap.y;
    const double rp = std::hypot(p[0] - cx, p[1] - cy);
    const double rq = std::hypot(q[0] - cx, q[1] - cy);
    const double rm = std::hypot(m[0] - cx, m[1] - cy);
    if (!(rm > 0)) return m;
    const double radius = across > along ? (from_p ? rp : rq) : 0.5 * (rp + rq);
    const double k = radius / rm;
    if (!(std::fabs(k - 1) * rm < 0.5 * std::hypot(dx, dy))) return m;
    return {cx + k * (m[0] - cx), cy + k * (m[1] - cy)};
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

/// The metric lengths of a mesh's edges (VertexMetrics::length, from the origin of each slot
/// 3t + k) with the stamp its triangle had when measured: while the triangle keeps it, the edge
/// joins the same two vertices at the same points in the same metrics.
struct SlotLengths {
    std::vector<double> length;
    std::vector<std::uint32_t> stamp;
    std::uint32_t era = 0;

    /// The length of slot e of triangle t, measured again only when t changed since.
    template <class Measure>
    double operator()(const tri::TriangleStamps2& stamps, tri::TriIdx t, std::size_t e,
                      Measure&& measure) {
        if (era != stamps.era()) {
            // The stamps' clock wrapped: the stamps kept here may come again.
            length.clear();
            stamp.clear();
            era = stamps.era();
        }
        if (e >= stamp.size()) {
            length.resize(e + 1, 0.0);
            stamp.resize(e + 1, 0);
        }
        const std::uint32_t now = stamps[t];
        if (now != 0 && stamp[e] == now) return length[e];
        length[e] = measure();
        stamp[e] = now;
        return length[e];
    }
    /// The triangles were renumbered (as TriangleStamps2::renumber).
    void renumber(std::span<const tri::TriIdx> old_of_new) {
        std::vector<double> renumbered_length(3 * old_of_new.size(), 0.0);
        std::vector<std::uint32_t> renumbered_stamp(3 * old_of_new.size(), 0);
        for (std::size_t t = 0; t < old_of_new.size(); ++t) {
            const std::size_t old = old_of_new[t];
            if (old_of_new[t] == tri::kNone || 3 * old + 2 >= stamp.size()) continue;
            for (std::size_t k = 0; k < 3; ++k) {
                renumbered_length[3 * t + k] = length[3 * old + k];
                renumbered_stamp[3 * t + k] = stamp[3 * old + k];
            }
        }
        length = std::move(renumbered_length);
        stamp = std::move(renumbered_stamp);
    }
};

/// What the edits of one run keep from one pass to the next: the mesh's triangle stamps, each
/// swap criterion's verdicts (triangulation::SwapVerdicts2) and the long edges not split, so that
/// a pass decides again only the quadrilaterals changed since the last, and the edges' lengths.
/// Every edit of the mesh between passes renews the stamps of the triangles it changes (swaps,
/// split_long_edges, remove_short_edges, the smoothing's moves).
struct SwapMemory {
    tri::TriangleStamps2 stamps;
    tri::SwapVerdicts2 in_ellipse{&stamps, {}, {}, 0};
    tri::SwapVerdicts2 shorter{&stamps, {}, {}, 0};
    /// split_long_edges' verdicts: the slot's quadrilateral was found not to split.
    tri::SwapVerdicts2 no_split{&stamps, {}, {}, 0};
    SlotLengths lengths;
    /// The binary exponent of the smallest size at the last pass: the swaps' log forms are in
    /// its unit (a new smaller size renews every stamp).
    int unit = std::numeric_limits<int>::min();
};

/// After a renumbering of the mesh's vertices (old_to_new, in their order) and triangles (from
/// `before`, the old triangles' vertices): each triangle found among the old ones (the same
/// vertices in the same order) keeps its stamp and verdicts, the others are new.
void renumber_swap_memory(SwapMemory& memory, const std::vector<tri::VertIdx>& before,
                          const tri::Triangulation2& mesh,
                          const std::vector<tri::VertIdx>& old_to_new) {
    // The old triangles without a removed vertex, in the new numbering, grouped by their first
    // vertex (a counting sort: start[v] .. start[v + 1] for vertex v).
    const std::size_t nv = mesh.vertex_count();
    std::vector<std::uint32_t> start(nv + 2, 0);
    const auto renumbered = [&](std::size_t t, std::size_t k) {
        const tri::VertIdx v = before[3 * t + k];
        return v < old_to_new.size() ? old_to_new[v] : tri::kNone;
    };
    const auto survives = [&](std::size_t t) {
        for (std::size_t k = 0; k < 3; ++k) {
            const tri::VertIdx v = renumbered(t, k);
            if (v == tri::kNone || v >= nv) return false;
        }
        return true;
    };
    for (std::size_t t = 0; 3 * t < before.size(); ++t) {
        if (survives(t)) ++start[renumbered(t, 0) + 2];
    }
    for (std::size_t v = 2; v < start.size(); ++v) start[v] += start[v - 1];
    std::vector<std::array<std::uint32_t, 3>> old_triangles(start.back());
    for (std::size_t t = 0; 3 * t < before.size(); ++t) {
        if (!survives(t)) continue;
        old_triangles[start[renumbered(t, 0) + 1]++] = {renumbered(t, 1), renumbered(t, 2),
                                                        static_cast<std::uint32_t>(t)};
    }
    std::vector<tri::TriIdx> old_of_new(mesh.triangle_count(), tri::kNone);
    for (tri::TriIdx t = 0; t < mesh.triangle_count(); ++t) {
        const tri::VertIdx* v = &mesh.triangles[3 * std::size_t{t}];
        for (std::uint32_t i = start[v[0]]; i < start[v[0] + 1]; ++i) {
            if (old_triangles[i][0] == v[1] && old_triangles[i][1] == v[2]) {
                old_of_new[t] = old_triangles[i][2];
                break;
            }
        }
    }
    memory.stamps.renumber(old_of_new);
    memory.in_ellipse.renumber(old_of_new);
    memory.shorter.renumber(old_of_new);
    memory.no_split.renumber(old_of_new);
    memory.lengths.renumber(old_of_new);
}

/// One pass over the finished mesh's unconstrained edges: each longer than sqrt 2
/// (VertexMetrics::length) is split at its halfway point m (field_halfway) into four triangles,
/// unless m lies closer than min_spacing to one of the edge's two opposite vertices, or one of the
/// four triangles would not be strictly counter-clockwise (exact orient2d), or one of its two
/// triangles was already changed in this pass. `at` (the field per vertex) and the triangles'
/// attributes (when present) follow, and the four triangles get new stamps; an edge found not to
/// split on the same two triangles in an earlier pass (memory.no_split) is not measured again.
/// Returns the number of splits.
std::uint64_t split_long_edges(tri::Triangulation2& mesh, VertexMetrics& at,
                               std::vector<double>& attributes, const MetricField2& field,
                               double min_spacing, bool columns, SwapMemory& memory) {
    const tri::TriIdx count = mesh.triangle_count();
    std::vector<std::uint8_t> changed(count, 0);
    std::uint64_t splits = 0;
    tri::TriangleStamps2& stamps = memory.stamps;
    tri::SwapVerdicts2& no_split = memory.no_split;
    if (no_split.era != stamps.era()) {
        no_split.kept.clear();
        no_split.era = stamps.era();
    }
    no_split.kept.resize(3 * std::size_t{count}, 0);
    no_split.convex.resize(3 * std::size_t{count}, 0);  // unused, sized as kept for renumber
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
            // The verdict of an earlier pass on the same two triangles (the same quadrilateral,
            // the same points and metrics) stands; a pass that keeps the edge records it.
            const std::size_t e = 3 * std::size_t{t} + k;
            std::uint64_t key = 0;
            if (stamps[t] != 0 && stamps[u] != 0 && no_split.era == stamps.era()) {
                key = std::uint64_t{stamps[t]} << 32 | stamps[u];
            }
            if (key != 0 && no_split.kept[e] == key) continue;
            const auto keep = [&] {
                if (key != 0 && no_split.era == stamps.era()) no_split.kept[e] = key;
            };
            const double* pa = mesh.point(a);
            const double* pb = mesh.point(b);
            const double dx = pb[0] - pa[0], dy = pb[1] - pa[1];
            const double length =
                memory.lengths(stamps, t, e, [&] { return at.length(a, b, dx, dy); });
            if (!(length > kSqrt2)) {
                keep();
                continue;
            }
            const std::array<double, 2> point =
                proposal_point(field, pa, dx, dy, at.at[a], at.at[b], columns);
            const double m[2] = {point[0], point[1]};
            const Metric2 mm = field(m[0], m[1]);
            const LogMetric2 lm = scaled_log_form(mm, at.unit);
            const auto close = [&](tri::VertIdx v) {
                const double* pv = mesh.point(v);
                return at.length_to(mm, lm, v, pv[0] - m[0], pv[1] - m[1]) < min_spacing;
            };
            if (close(c) || close(d)) {
                keep();
                continue;
            }
            const double* pc = mesh.point(c);
            const double* pd = mesh.point(d);
            using predicates::Sign;
            if (predicates::orient2d(pa, m, pc) != Sign::Positive ||
                predicates::orient2d(m, pb, pc) != Sign::Positive ||
                predicates::orient2d(pb, m, pd) != Sign::Positive ||
                predicates::orient2d(m, pa, pd) != Sign::Positive) {
                keep();
                continue;
            }
            // t = (a, b, c) and u = (b, a, d) become t (a, m, c), t2 (m, b, c), u (b, m, d) and
            // u2 (m, a, d).
            const tri::VertIdx mv = mesh.vertex_count();
            mesh.xy.push_back(m[0]);
            mesh.xy.push_back(m[1]);
            at.at.push_back(mm);
            at.logs.push_back(lm);
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
            for (const tri::TriIdx changed_triangle : {t, u, t2, u2})
                stamps.touch(changed_triangle);
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

/// One pass removing an end of each unconstrained edge shorter than 1/sqrt 2
/// (VertexMetrics::length): the end numbered from `first_removable` on (the later one when both
/// are), at most one vertex of each triangle's star per pass (no two removed vertices are
/// neighbours), by remove_vertices_2d (the star retriangulated, exact); `at` is renumbered with
/// the mesh, and `memory` follows the triangles. Returns the number of vertices removed.
std::uint64_t remove_short_edges(tri::Triangulation2& mesh, VertexMetrics& at,
                                 tri::VertIdx first_removable, SwapMemory& memory) {
    const tri::VertIdx nv = mesh.vertex_count();
    // 0 untouched, 1 to remove, 2 a neighbour of one to remove.
    std::vector<std::uint8_t> mark(nv, 0);
    std::vector<tri::VertIdx> chosen;
    for (tri::TriIdx t = 0; t < mesh.triangle_count(); ++t) {
        for (unsigned k = 0; k < 3; ++k) {
            const tri::TriIdx u = mesh.neighbors[3 * t + k];
            if (u == tri::kNone || u < t || mesh.is_constrained(t, int(k))) continue;
            const tri::VertIdx a = mesh.triangles[3 * t + k];
            const tri::VertIdx b = mesh.triangles[3 * t + (k + 1) % 3];
            const tri::VertIdx v = std::max(a, b);
            if (v < first_removable || mark[a] != 0 || mark[b] != 0) continue;
            const double* pa = mesh.point(a);
            const double* pb = mesh.point(b);
            const double length = memory.lengths(memory.stamps, t, 3 * std::size_t{t} + k, [&] {
                return at.length(a, b, pb[0] - pa[0], pb[1] - pa[1]);
            });
            if (!(length < kUnitLow)) continue;
            mark[v] = 1;
            chosen.push_back(v);
            // Its neighbours (the vertices of the triangles at v) may not go in this pass.
            mark[v == a ? b : a] = 2;
        }
    }
    if (chosen.empty()) return 0;
    // The neighbours of each chosen vertex are marked from its triangles; a chosen vertex that
    // turns out to neighbour an earlier chosen one stays.
    std::vector<tri::VertIdx> removable;
    std::vector<std::uint8_t> blocked(nv, 0);
    std::vector<std::vector<tri::VertIdx>> around(nv);
    for (tri::TriIdx t = 0; t < mesh.triangle_count(); ++t) {
        for (unsigned k = 0; k < 3; ++k) {
            const tri::VertIdx v = mesh.triangles[3 * t + k];
            if (mark[v] != 1) continue;
            around[v].push_back(mesh.triangles[3 * t + (k + 1) % 3]);
            around[v].push_back(mesh.triangles[3 * t + (k + 2) % 3]);
        }
    }
    for (const tri::VertIdx v : chosen) {
        if (blocked[v] != 0) continue;
        removable.push_back(v);
        for (const tri::VertIdx w : around[v]) blocked[w] = 1;
    }
    const std::vector<tri::VertIdx> before = mesh.triangles;
    const tri::VertexRemoval2Result removed =
        tri::remove_vertices_2d(mesh, removable, first_removable);
    renumber_swap_memory(memory, before, mesh, removed.old_to_new);
    VertexMetrics renumbered{at.unit, std::vector<Metric2>(mesh.vertex_count()),
                             std::vector<LogMetric2>(mesh.vertex_count()), at.memo};
    for (tri::VertIdx v = 0; v < nv; ++v) {
        const tri::VertIdx w = removed.old_to_new[v];
        if (w == tri::kNone) continue;
        renumbered.at[w] = at.at[v];
        renumbered.logs[w] = at.logs[v];
    }
    at = std::move(renumbered);
    return removed.removed;
}

/// The generator's swaps: in-ellipse in the log-Euclidean mean of each quadrilateral's metrics,
/// then (unless the metric is the same at every vertex) towards the shorter diagonal, each in the
/// mean of its own ends' metrics.
tri::EdgeSwapCounters quad_swaps(tri::Triangulation2& mesh, const VertexMetrics& at,
                                 SwapMemory& memory) {
    double h_min = std::numeric_limits<double>::infinity();
    for (const Metric2& m : at.at) h_min = std::min({h_min, m.h1, m.h2});
    const int unit = std::isfinite(h_min) ? std::ilogb(h_min) : 0;
    if (unit != memory.unit) {
        memory.stamps.reset(mesh.triangle_count());
        memory.unit = unit;
    }
    // In a constant metric (the same at every vertex, whatever the field's kind) the in-ellipse
    // triangulation is the Delaunay one of the mapped points, the lengths' own optimum: the
    // shorter diagonal would only undo swaps the next pass redoes.
    const Metric2& first = at.at.front();
    const bool constant = std::all_of(at.at.begin(), at.at.end(), [&first](const Metric2& m) {
        return m.h1 == first.h1 && m.h2 == first.h2 && m.c == first.c && m.s == first.s;
    });
    // Both criteria on one lending of the mesh as half-edges.
    tri::HalfEdgeEdit edit(mesh);
    tri::EdgeSwapCounters c =
        metric_swaps_2d(edit.mesh(), at.at, true, at.memo, &memory.in_ellipse);
    if (constant) return c;
    const tri::EdgeSwapCounters d =
        shorter_diagonal_swaps_2d(edit.mesh(), at.at, at.memo, &memory.shorter);
    c.swaps += d.swaps;
    c.budget_stops += d.budget_stops;
    return c;
}

/// The corners of each vertex of a mesh: the slots 3 t + k holding v are
/// corner[start[v] .. start[v + 1]), in the order of their triangles.
struct Stars {
    std::vector<std::uint32_t> start;
    std::vector<std::uint32_t> corner;  ///< 3 t + k with mesh.triangles[3 t + k] == v

    explicit Stars(const tri::Triangulation2& mesh) {
        const std::size_t nv = mesh.vertex_count();
        start.assign(nv + 1, 0);
        for (const tri::VertIdx v : mesh.triangles) ++start[v + 1];
        for (std::size_t v = 0; v < nv; ++v) start[v + 1] += start[v];
        corner.resize(mesh.triangles.size());
        std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
        for (std::uint32_t i = 0; i < mesh.triangles.size(); ++i)
            corner[fill[mesh.triangles[i]]++] = i;
    }
};

/// How far an edge of metric length l is from unit length: ln(l)^2.
double length_defect(double l) {
    const double x = std::log(l);
    return x * x;
}

/// The vertices that relocate_vertices left where they were, each with a hash of its star's
/// triangle stamps then (0: none; valid in the stamps' era). A collision of two hashes can only
/// leave a vertex untried, the same way on every run.
struct RelocationMemory {
    std::vector<std::uint64_t> stars;
    std::uint32_t era = 0;
};

/// A relocation makes no edge shorter than this metric length (unless one already is): two
/// vertices pulled together would give the swaps a needle. 0.25 gave 92.7% unit edges on the
/// curved layer of aspect ratio 1000 (92.8% without the floor, edges down to 0.0002; 91.5% with
/// 1/sqrt 2; 2026-12-06).
constexpr double kShortestMove = 0.25;

/// A vertex's edges as the quality report measures them: how many have unit length, their
/// summed length_defect, the shortest.
struct StarScore {
    int unit = 0;
    double defect = 0;
    double shortest = std::numeric_limits<double>::infinity();

    /// Better for the report: more unit edges, then a smaller defect.
    bool beats(const StarScore& other) const {
        return unit > other.unit || (unit == other.unit && defect < other.defect);
    }
};

/// One Gauss-Seidel pass of pattern search over the vertices from `first_movable` on (inserted
/// points: interior) that have an edge outside [1/sqrt 2, sqrt 2]: each tries the steps of 1/2,
/// 1/4, 1/8 and 1/16 of its metric's sizes both ways along both principal directions (the field
/// evaluated at each trial point) and moves to the best (StarScore::beats) that beats its place,
/// makes no edge shorter than both kShortestMove and its shortest, and keeps every triangle of its
/// star strictly counter-clockwise (exact orient2d). Where metric-length smoothing (a weighted
/// centroid) balances lengths, this counts them as the goal does, and its moves along the layer
/// line vertices up in the columns a turning layer needs. Each trial point is the vertex's
/// coordinates plus one step (scale-free: sizes scale with the domain). The triangles of a moved
/// star get new stamps; a vertex left where it was is not tried again while its star's triangles
/// keep their stamps (`settled`). Returns the number of moves.
std::uint64_t relocate_vertices(tri::Triangulation2& mesh, VertexMetrics& at,
                                const MetricField2& field, tri::VertIdx first_movable,
                                SwapMemory& memory, RelocationMemory& settled) {
    std::uint64_t moves = 0;
    const Stars stars(mesh);
    std::vector<tri::VertIdx> ring;
    if (settled.era != memory.stamps.era()) {
        settled.stars.clear();
        settled.era = memory.stamps.era();
    }
    settled.stars.resize(mesh.vertex_count(), 0);
    for (tri::VertIdx v = first_movable; v < mesh.vertex_count(); ++v) {
        const std::uint32_t first = stars.start[v], end = stars.start[v + 1];
        if (first == end) continue;
        // A vertex that found no better place stays until a triangle of its star changes.
        std::uint64_t star_stamps = 0;
        for (std::uint32_t j = first; j < end; ++j) {
            const std::uint32_t stamp = memory.stamps[stars.corner[j] / 3];
            if (stamp == 0) {
                star_stamps = 0;
                break;
            }
            star_stamps = star_stamps * 0x9E3779B97F4A7C15u + stamp;
        }
        if (star_stamps != 0 && settled.stars[v] == star_stamps) continue;
        // The neighbours: the vertex after v in each counter-clockwise triangle of its (closed)
        // star, each once.
        ring.clear();
        for (std::uint32_t j = first; j < end; ++j) {
            const std::uint32_t t = stars.corner[j] / 3, k = stars.corner[j] % 3;
            ring.push_back(mesh.triangles[3 * t + (k + 1) % 3]);
        }
        const auto score = [&](const Metric2& m, const LogMetric2& lm, double x, double y) {
            StarScore s;
            for (const tri::VertIdx u : ring) {
                const double* pu = mesh.point(u);
                const double l = at.length_to(m, lm, u, pu[0] - x, pu[1] - y);
                if (l >= kUnitLow * (1 - 1e-12) && l <= kSqrt2 * (1 + 1e-12)) ++s.unit;
                s.defect += length_defect(l);
                s.shortest = std::min(s.shortest, l);
            }
            return s;
        };
        const double px = mesh.point(v)[0], py = mesh.point(v)[1];
        const StarScore here = score(at.at[v], at.logs[v], px, py);
        if (here.unit == static_cast<int>(ring.size())) {
            settled.stars[v] = star_stamps;
            continue;
        }
        const double floor = std::min(here.shortest, kShortestMove);
        const Metric2& mv = at.at[v];
        const double directions[4][2] = {{mv.c * mv.h1, mv.s * mv.h1},
                                         {-mv.c * mv.h1, -mv.s * mv.h1},
                                         {-mv.s * mv.h2, mv.c * mv.h2},
                                         {mv.s * mv.h2, -mv.c * mv.h2}};
        StarScore best = here;
        double best_point[2] = {px, py};
        Metric2 best_metric = mv;
        LogMetric2 best_log = at.logs[v];
        for (const double step : {0.5, 0.25, 0.125, 0.0625}) {
            for (const auto& d : directions) {
                const double q[2] = {px + step * d[0], py + step * d[1]};
                const Metric2 m = field(q[0], q[1]);
                const LogMetric2 lm = scaled_log_form(m, at.unit);
                const StarScore trial = score(m, lm, q[0], q[1]);
                if (!trial.beats(best) || !(trial.shortest >= floor)) continue;
                bool valid = true;
                for (std::uint32_t j = first; j < end && valid; ++j) {
                    const std::uint32_t t = stars.corner[j] / 3;
                    const double* corner[3];
                    for (unsigned k = 0; k < 3; ++k) {
                        const tri::VertIdx w = mesh.triangles[3 * t + k];
                        corner[k] = w == v ? q : mesh.point(w);
                    }
                    valid = predicates::orient2d(corner[0], corner[1], corner[2]) ==
                            predicates::Sign::Positive;
                }
                if (!valid) continue;
                best = trial;
                best_point[0] = q[0];
                best_point[1] = q[1];
                best_metric = m;
                best_log = lm;
            }
        }
        if (best_point[0] == px && best_point[1] == py) {
            settled.stars[v] = star_stamps;
            continue;
        }
        mesh.xy[2 * std::size_t{v}] = best_point[0];
        mesh.xy[2 * std::size_t{v} + 1] = best_point[1];
        at.at[v] = best_metric;
        at.logs[v] = best_log;
        for (std::uint32_t j = first; j < end; ++j) memory.stamps.touch(stars.corner[j] / 3);
        ++moves;
    }
    return moves;
}

class MetricMesher {
  public:
    MetricMesher(const tri::Pslg& pslg, const MetricDelaunayOptions2& options,
                 DomainBoundary2&& boundary, const tri::Cdt2Options& cdt_options,
                 std::size_t memo_slots)
        : options_(options),
          boundary_(std::move(boundary)),
          cdt_(tri::Pslg{boundary_.xy, boundary_.pieces, pslg.holes, pslg.regions,
                         piece_lines(boundary_)},
               cdt_options),
          holes_(pslg.holes),
          regions_(pslg.regions),
          cdt_options_(cdt_options),
          memo_(memo_slots) {
        // The unit of the log forms: the smallest size at the first boundary point.
        const Metric2 first = options_.metric(boundary_.xy[0], boundary_.xy[1]);
        unit_ = std::ilogb(std::min(first.h1, first.h2));
        vertices_.unit = unit_;
        vertices_.memo = &memo_;
    }

    MetricDelaunayResult2 run(std::uint64_t budget);

  private:
    /// Computes and caches the metric of mesh vertex v (vertices are only ever appended).
    void know(tri::VertIdx v);
    /// True when some vertex of t or of its neighbours lies closer than min_spacing to (x, y)
    /// (log form lm) by mean_length.
    bool too_close(tri::TriIdx t, const Metric2& m, const LogMetric2& lm, double x, double y);
    /// One pass: proposals at the halfway points of the long edges, inserted in Hilbert order.
    std::uint64_t insertion_pass(std::uint64_t budget);
    /// The columns of turning layers (turning_layer_columns_2d), inserted in Hilbert order
    /// with the spacing test, before the passes.
    void insert_columns(std::uint64_t budget);
    /// Inserts (x, y) unless it falls outside the domain or too close to a vertex; counts it.
    bool insert_point(double x, double y);

    const MetricDelaunayOptions2& options_;
    DomainBoundary2 boundary_;
    tri::ConstrainedTriangulation2 cdt_;
    /// The input's holes and regions and the triangulation's options (for insert_columns' copy
    /// of the boundary's triangulation).
    std::span<const double> holes_, regions_;
    tri::Cdt2Options cdt_options_;
    int unit_ = 0;
    MetricFromLogFormMemo memo_;
    VertexMetrics vertices_;
    std::vector<bool> known_;
    /// The edges measured so far, by their ends (u << 32 | v): whether each is longer than
    /// sqrt 2 and then the point it proposes (proposal_point).
    struct Proposal {
        std::array<double, 2> point{};
        bool is_long = false;
    };
    std::unordered_map<std::uint64_t, Proposal> proposal_;
    MetricDelaunayCounters2 counters_;
};

void MetricMesher::know(tri::VertIdx v) {
    if (v >= known_.size()) {
        vertices_.at.resize(v + 1);
        vertices_.logs.resize(v + 1);
        known_.resize(v + 1, false);
    }
    if (!known_[v]) {
        const double* p = cdt_.mesh().point(v);
        vertices_.at[v] = options_.metric(p[0], p[1]);
        vertices_.logs[v] = scaled_log_form(vertices_.at[v], unit_);
        known_[v] = true;
    }
}

bool MetricMesher::too_close(tri::TriIdx t, const Metric2& m, const LogMetric2& lm, double x,
                             double y) {
    const tri::TriMesh2& mesh = cdt_.mesh();
    const auto close = [&](tri::VertIdx v) {
        if (v == tri::kInfinite) return false;
        const double* p = mesh.point(v);
        const double dx = p[0] - x, dy = p[1] - y;
        // The length of the would-be edge as the insertion passes measure edges.
        know(v);
        return vertices_.length_to(m, lm, v, dx, dy) < options_.min_spacing;
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
                // Each edge is measured once (vertices never move here): a pass after the
                // first finds most edges as they were, and a long edge whose point was too close
                // proposes the same point again.
                const auto [slot, fresh] = proposal_.try_emplace(std::uint64_t{u} << 32 | v);
                if (fresh) {
                    know(u);
                    know(v);
                    if (vertices_.length(u, v, dx, dy) > kSqrt2) {
                        slot->second.point =
                            proposal_point(options_.metric, p, dx, dy, vertices_.at[u],
                                           vertices_.at[v], options_.turning_columns);
                        slot->second.is_long = true;
                    }
                }
                if (!slot->second.is_long) continue;
                proposals.push_back(slot->second.point[0]);
                proposals.push_back(slot->second.point[1]);
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
        if (insert_point(proposals[2 * i], proposals[2 * i + 1])) ++inserted;
    }
    return inserted;
}

bool MetricMesher::insert_point(double x, double y) {
    const tri::TriIdx t = cdt_.locate(x, y);
    if (cdt_.mesh().is_infinite(t) || !cdt_.in_domain(t)) {
        ++counters_.rejected;
        return false;
    }
    const Metric2 m = options_.metric(x, y);
    const LogMetric2 lm = scaled_log_form(m, unit_);
    if (too_close(t, m, lm, x, y)) {
        ++counters_.too_close;
        return false;
    }
    double matrix[3];
    matrix_for_predicate(m, matrix);
    if (cdt_.insert_in_metric_cavity(t, x, y, matrix) != tri::CavityInsertion::Inserted) {
        ++counters_.rejected;
        return false;
    }
    ++counters_.inserted;
    const tri::VertIdx v = cdt_.mesh().vertex_count() - 1;
    if (v >= known_.size()) {
        vertices_.at.resize(v + 1);
        vertices_.logs.resize(v + 1);
        known_.resize(v + 1, false);
    }
    vertices_.at[v] = m;  // the field's value there, already computed
    vertices_.logs[v] = lm;
    known_[v] = true;
    return true;
}

void MetricMesher::insert_columns(std::uint64_t budget) {
    if (!options_.layer_columns || options_.metric.is_uniform()) return;
    std::array<double, 4> box = {boundary_.xy[0], boundary_.xy[1], boundary_.xy[0],
                                 boundary_.xy[1]};
    for (std::size_t i = 0; i + 1 < boundary_.xy.size(); i += 2) {
        box[0] = std::min(box[0], boundary_.xy[i]);
        box[1] = std::min(box[1], boundary_.xy[i + 1]);
        box[2] = std::max(box[2], boundary_.xy[i]);
        box[3] = std::max(box[3], boundary_.xy[i + 1]);
    }
    // Whether a point lies in the domain: located in a triangulation of the boundary of its
    // own, built at the first question (only a field with a turning ridge asks). Locating in
    // cdt_ itself would move its walks' starting triangle, and with it the later insertions'
    // choices where a point lies on an edge: a field without columns would get another mesh.
    std::optional<tri::ConstrainedTriangulation2> probe;
    const std::function<bool(double, double)> inside = [&](double x, double y) {
        if (!std::isfinite(x) || !std::isfinite(y)) return false;
        if (!probe)
            probe.emplace(
                tri::Pslg{boundary_.xy, boundary_.pieces, holes_, regions_, piece_lines(boundary_)},
                cdt_options_);
        const tri::TriIdx t = probe->locate(x, y);
        return !probe->mesh().is_infinite(t) && probe->in_domain(t);
    };
    std::vector<double> points =
        turning_layer_columns_2d(options_.metric, box, inside, options_.columns, budget);
    if (points.empty()) return;
    std::vector<std::uint32_t> order(points.size() / 2);
    for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
    tri::hilbert_sort_2d(points, order);
    for (const std::uint32_t i : order) {
        if (counters_.inserted >= budget) break;
        if (insert_point(points[2 * i], points[2 * i + 1])) ++counters_.column_points;
    }
}

MetricDelaunayResult2 MetricMesher::run(std::uint64_t budget) {
    insert_columns(budget);
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
        // The field at the final vertices (restore_input_terms may renumber them).
        VertexMetrics at{unit_, {}, {}, &memo_};
        for (tri::VertIdx v = 0; v < mesh.vertex_count(); ++v)
            at.push_back(options_.metric(mesh.point(v)[0], mesh.point(v)[1]));
        SwapMemory memory;
        // The quadrilateral swaps in the metric, counted (after every pass that moves or adds
        // points).
        const auto swap_counted = [&] {
            const tri::EdgeSwapCounters swapped = quad_swaps(mesh, at, memory);
            result.counters.swaps += swapped.swaps;
            result.counters.swap_budget_hits += swapped.budget_stops;
        };
        result.counters.swaps = 0;
        result.counters.swap_budget_hits = 0;
        swap_counted();
        // Rounds of splits of the edges still long and removals at the edges too short, each
        // followed by swaps. After the insertion passes in a metric that varies (and rotates),
        // vertices lie near the middle of long edges, where the spacing test keeps the edge from
        // being split, and pairs lie too close; the swaps make two shorter edges of the first,
        // the removals (remove_vertices_2d, which keeps the mesh exactly valid) undo the second.
        // Removals renumber the triangles: not done when they carry attributes.
        const auto first_inserted = static_cast<tri::VertIdx>(boundary_.xy.size() / 2);
        for (int round = 0; round < kEditRounds; ++round) {
            if (result.counters.inserted + result.counters.late_splits >= budget) break;
            const std::uint64_t split =
                split_long_edges(mesh, at, out.triangle_attributes, options_.metric,
                                 options_.min_spacing, options_.turning_columns, memory);
            result.counters.late_splits += split;
            if (split > 0) {
                swap_counted();
            }
            std::uint64_t removed = 0;
            if (out.triangle_attributes.empty()) {
                removed = remove_short_edges(mesh, at, first_inserted, memory);
                result.counters.late_removals += removed;
                if (removed > 0) {
                    swap_counted();
                }
            }
            // Each round changes fewer vertices; 0.5% of them is not worth another (on a
            // constant or straight metric the first round is the last).
            if (200 * (split + removed) <= mesh.vertex_count()) break;
        }
        // Smoothing of the inserted points (the boundary's stay), each followed by swaps; edges
        // measured as the quality report does.
        const std::vector<double> relax(mesh.vertex_count(), 0.5);
        for (int pass = 0; pass < options_.smoothing_passes; ++pass) {
            const std::vector<double> unmoved = mesh.xy;
            const PointSmoothingCounters2 smoothed =
                smooth_metric_points_2d(mesh, at.at, relax, 0.3, MoveLimit::MetricLength,
                                        first_inserted, true, true, &memo_);
            result.counters.smoothing_moves += smoothed.moves;
            for (tri::VertIdx v = first_inserted; v < mesh.vertex_count(); ++v) {
                at.at[v] = options_.metric(mesh.point(v)[0], mesh.point(v)[1]);
                at.logs[v] = scaled_log_form(at.at[v], unit_);
            }
            // The triangles at a moved point (whose metric moved with it) are new; an unmoved
            // point's metric is the field's value at the same point, the same as before.
            for (tri::TriIdx t = 0; t < mesh.triangle_count(); ++t) {
                for (unsigned k = 0; k < 3; ++k) {
                    const std::size_t v = mesh.triangles[3 * t + k];
                    if (mesh.xy[2 * v] != unmoved[2 * v] ||
                        mesh.xy[2 * v + 1] != unmoved[2 * v + 1]) {
                        memory.stamps.touch(t);
                        break;
                    }
                }
            }
            swap_counted();
        }
        // The final optimization: rounds of vertex relocation towards unit edges, swaps and
        // splits of the edges still long, until a round changes under 0.1% of the vertices.
        RelocationMemory settled;
        for (int round = 0; round < options_.optimization_rounds; ++round) {
            ++result.counters.optimization_rounds;
            const std::uint64_t moved =
                relocate_vertices(mesh, at, options_.metric, first_inserted, memory, settled);
            result.counters.relocations += moved;
            swap_counted();
            std::uint64_t split = 0;
            if (result.counters.inserted + result.counters.late_splits < budget) {
                split = split_long_edges(mesh, at, out.triangle_attributes, options_.metric,
                                         options_.min_spacing, options_.turning_columns, memory);
                result.counters.late_splits += split;
                if (split > 0) {
                    swap_counted();
                }
            }
            if (1000 * (moved + split) <= mesh.vertex_count()) break;
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
    DomainBoundary2 boundary = discretize_domain_boundary(
        domain,
        [&field](const double* a, const double* b) {
            const std::array<double, 2> u = unit_vector(b[0] - a[0], b[1] - a[1]);
            return SizeFunction::analytic(
                [&field, u](double x, double y) {
                    return 1.0 / metric_length(field(x, y), u[0], u[1]);
                },
                "the metric's size along a boundary piece");
        },
        options.max_steiner_points);
    const std::uint64_t boundary_points = boundary.xy.size() / 2 - boundary.cdt.mesh.xy.size() / 2;
    // The means' memo: a small direct-mapped table (2^10 slots, 56 kB) that stays in the
    // first-level caches. Callgrind counted 32% fewer instructions with 64 slots per estimated
    // triangle, but wall time is bound by memory there: stretched_bench (2026-12-03, medians of
    // 3, one quiet run) gave circle100 / naca0012 layer1000 / three-element layer1000 45 / 153 /
    // 240 ms with 16 slots per triangle (at most 2^16), 47 / 143 / 213 with 8 (2^15), 48 / 137 /
    // 195 with 4 (2^13), and 50 / 132 / 184 with 2^10, against 55 / 136 / 184 before the memo.
    const std::size_t memo_slots = std::size_t{1} << 10;
    MetricMesher mesher(domain.pslg(), options, std::move(boundary), cdt, memo_slots);
    MetricDelaunayResult2 result = mesher.run(budget);
    result.counters.boundary_points = boundary_points;
    return result;
}

std::vector<std::pair<std::string, std::uint64_t>> counter_list(const MetricDelaunayCounters2& c) {
    return counters_by_name(kMetricDelaunayCounterNames, c);
}

}  // namespace exactmesh::generators
