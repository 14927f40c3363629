// SPDX-License-Identifier: MIT
// Metric swaps and point smoothing of a finished mesh (see metric_mesh_edits_2d.hpp).
#include "generators/stretched/metric_mesh_edits_2d.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

#include "predicates/metric_lengths.hpp"
#include "predicates/orient2d.hpp"
#include "predicates/power_of_two.hpp"

namespace exactmesh::generators {

namespace tri = triangulation;
using predicates::Sign;

namespace {

constexpr double kUnitLow = 0.7071067811865476 * (1 - 1e-12);
constexpr double kUnitHigh = 1.4142135623730951 * (1 + 1e-12);
/// A triangle of metric mean ratio below this is a sliver (shorter_diagonal_swaps_2d).
constexpr double kSliverShape = 0.02;

/// {M11, M12, M22} of `m` times h_ref^2: one common scale for a mesh's vertices (h_ref its
/// smallest size, so every ratio h_ref / h is at most 1 and no square overflows).
std::array<double, 3> common_scale_matrix(const Metric2& m, double h_ref) {
    const double a = h_ref / m.h1, b = h_ref / m.h2;
    const double a2 = a * a, b2 = b * b;
    return {m.c * m.c * a2 + m.s * m.s * b2, m.c * m.s * (a2 - b2),
            m.s * m.s * a2 + m.c * m.c * b2};
}

/// The log-Euclidean forms of a mesh's vertex metrics, the sizes first divided by one common
/// power of two (that of the smallest size): a mesh and its metrics scaled by 2^k give the same
/// forms, so means of them are scale-free (never scaled back: the predicates' matrices are
/// normalized anyway), and each vertex's logarithm is taken once.
class LogForms {
  public:
    LogForms(std::span<const Metric2> metrics, MetricFromLogFormMemo* memo)
        : scaled_(metrics.begin(), metrics.end()), forms_(metrics.size()), memo_(memo) {
        double h_min = std::numeric_limits<double>::infinity();
        for (const Metric2& m : metrics) h_min = std::min({h_min, m.h1, m.h2});
        const int e = std::isfinite(h_min) ? std::ilogb(h_min) : 0;
        // PowerOfTwo: the bits of std::ldexp, without its library call.
        const predicates::PowerOfTwo down(-e);
        for (std::size_t v = 0; v < metrics.size(); ++v) {
            scaled_[v].h1 = down(scaled_[v].h1);
            scaled_[v].h2 = down(scaled_[v].h2);
            forms_[v] = log_form(scaled_[v]);
        }
    }
    /// The mean of the vertices' forms, as a metric (in the common unit); the vertices' own
    /// metric when all are the same (a constant field: no exponential to take).
    /// `same` (optional) tells whether the vertices' metrics were all the same.
    template <std::size_t N>
    Metric2 mean(const std::array<tri::VertIdx, N>& vertices, bool* same_out = nullptr) const {
        const Metric2& first = scaled_[vertices[0]];
        bool same = true;
        double l11 = 0, l12 = 0, l22 = 0;
        for (const tri::VertIdx v : vertices) {
            const Metric2& m = scaled_[v];
            same = same && m.h1 == first.h1 && m.h2 == first.h2 && m.c == first.c && m.s == first.s;
            l11 += forms_[v].l11;
            l12 += forms_[v].l12;
            l22 += forms_[v].l22;
        }
        if (same_out != nullptr) *same_out = same;
        if (same) return first;
        constexpr double w = 1.0 / N;
        if (memo_ != nullptr) return (*memo_)(w * l11, w * l12, w * l22);
        return metric_from_log_form(w * l11, w * l12, w * l22);
    }

  private:
    std::vector<Metric2> scaled_;
    std::vector<LogMetric2> forms_;
    MetricFromLogFormMemo* memo_ = nullptr;
};

/// metric_swaps_2d on a Triangulation2 or on one lent as half-edges (TriMesh2).
template <class Mesh>
tri::EdgeSwapCounters metric_swaps(Mesh& mesh, std::span<const Metric2> metrics, bool log_euclidean,
                                   MetricFromLogFormMemo* memo, tri::SwapVerdicts2* verdicts) {
    double h_ref = std::numeric_limits<double>::infinity();
    for (const Metric2& m : metrics) h_ref = std::min({h_ref, m.h1, m.h2});
    std::vector<double> matrices(3 * metrics.size());
    for (std::size_t v = 0; v < metrics.size(); ++v) {
        const std::array<double, 3> m = common_scale_matrix(metrics[v], h_ref);
        std::copy(m.begin(), m.end(), matrices.begin() + 3 * static_cast<std::ptrdiff_t>(v));
    }
    tri::MetricInEllipse criterion;
    criterion.metrics = matrices;
    std::shared_ptr<const LogForms> forms;
    if (log_euclidean) {
        forms = std::make_shared<const LogForms>(metrics, memo);
        // The last matrix of four equal metrics: where the metric is the same over a region (a
        // constant field everywhere) quadrilateral after quadrilateral has it, bit for bit.
        struct LastMatrix {
            std::array<std::uint64_t, 4> mean_bits{};
            double matrix[3] = {0, 0, 0};
            bool valid = false;
        };
        const auto last = std::make_shared<LastMatrix>();
        criterion.quad_metric = [forms, last](tri::VertIdx a, tri::VertIdx b, tri::VertIdx c,
                                              tri::VertIdx d, double* out) {
            bool same = false;
            const Metric2 mean = forms->mean(std::array{a, b, c, d}, &same);
            if (!same) {
                // Scale-free: matrix_for_predicate divides by the mean's smallest size squared.
                matrix_for_predicate(mean, out);
                return;
            }
            const std::array<std::uint64_t, 4> bits = {
                std::bit_cast<std::uint64_t>(mean.h1), std::bit_cast<std::uint64_t>(mean.h2),
                std::bit_cast<std::uint64_t>(mean.c), std::bit_cast<std::uint64_t>(mean.s)};
            if (!last->valid || bits != last->mean_bits) {
                matrix_for_predicate(mean, last->matrix);
                last->mean_bits = bits;
                last->valid = true;
            }
            std::copy(last->matrix, last->matrix + 3, out);
        };
        // The decision is then a function of the quadrilateral's vertices alone.
        criterion.verdicts = verdicts;
    }
    return tri::swap_edges_2d(mesh, criterion);
}

/// shorter_diagonal_swaps_2d on a Triangulation2 or on one lent as half-edges (TriMesh2).
template <class Mesh>
tri::EdgeSwapCounters shorter_diagonal_swaps(Mesh& mesh, std::span<const Metric2> metrics,
                                             MetricFromLogFormMemo* memo,
                                             tri::SwapVerdicts2* verdicts) {
    const auto forms = std::make_shared<const LogForms>(metrics, memo);
    tri::QuadPreference criterion;
    criterion.swap = [forms](const std::array<tri::VertIdx, 4>& v,
                             const std::array<const double*, 4>& p) {
        const Metric2 m_ab = forms->mean(std::array{v[0], v[1]});
        const Metric2 m_cd = forms->mean(std::array{v[2], v[3]});
        const double h_ref = std::min({m_ab.h1, m_ab.h2, m_cd.h1, m_cd.h2});
        const std::array<double, 3> mat_ab = common_scale_matrix(m_ab, h_ref);
        const std::array<double, 3> mat_cd = common_scale_matrix(m_cd, h_ref);
        if (predicates::compare_metric_lengths(p[2], p[3], mat_cd.data(), p[0], p[1],
                                               mat_ab.data()) != Sign::Negative) {
            return false;
        }
        // Not at the cost of the worst triangle's shape (in the quadrilateral's log-Euclidean
        // mean): a vertex just off the middle of a long edge would otherwise make a sliver.
        const Metric2 m = forms->mean(v);
        std::array<std::array<double, 2>, 4> q;
        double largest = 0;
        for (std::size_t i = 0; i < 4; ++i) {
            metric_map(m, p[i][0] - p[0][0], p[i][1] - p[0][1], q[i][0], q[i][1]);
            largest = std::max({largest, std::fabs(q[i][0]), std::fabs(q[i][1])});
        }
        if (!(largest > 0) || !std::isfinite(largest)) return false;
        const int shift = -std::ilogb(largest);
        const predicates::PowerOfTwo scale(shift);
        for (auto& point : q) point = {scale(point[0]), scale(point[1])};
        // Mean ratio 4 sqrt 3 area / (sum of squared edges) of the triangle (i, j, k).
        const auto shape = [&q](std::size_t i, std::size_t j, std::size_t k) {
            const double ux = q[j][0] - q[i][0], uy = q[j][1] - q[i][1];
            const double wx = q[k][0] - q[i][0], wy = q[k][1] - q[i][1];
            const double vx = q[k][0] - q[j][0], vy = q[k][1] - q[j][1];
            const double squares = ux * ux + uy * uy + wx * wx + wy * wy + vx * vx + vy * vy;
            return squares > 0 ? 2 * std::sqrt(3.0) * (ux * wy - uy * wx) / squares : 0.0;
        };
        // a = 0, b = 1, c = 2 (left of a -> b), d = 3: now (a, b, c), (b, a, d); swapped
        // (a, d, c), (b, c, d).
        const double worst_after = std::min(shape(0, 3, 2), shape(1, 2, 3));
        return worst_after >= kSliverShape ||
               worst_after >= std::min(shape(0, 1, 2), shape(1, 0, 3));
    };
    criterion.verdicts = verdicts;
    return tri::swap_edges_2d(mesh, criterion);
}

}  // namespace

tri::EdgeSwapCounters metric_swaps_2d(tri::Triangulation2& mesh, std::span<const Metric2> metrics,
                                      bool log_euclidean, MetricFromLogFormMemo* memo,
                                      tri::SwapVerdicts2* verdicts) {
    return metric_swaps(mesh, metrics, log_euclidean, memo, verdicts);
}

tri::EdgeSwapCounters metric_swaps_2d(tri::TriMesh2& mesh, std::span<const Metric2> metrics,
                                      bool log_euclidean, MetricFromLogFormMemo* memo,
                                      tri::SwapVerdicts2* verdicts) {
    return metric_swaps(mesh, metrics, log_euclidean, memo, verdicts);
}

tri::EdgeSwapCounters shorter_diagonal_swaps_2d(tri::Triangulation2& mesh,
                                                std::span<const Metric2> metrics,
                                                MetricFromLogFormMemo* memo,
                                                tri::SwapVerdicts2* verdicts) {
    return shorter_diagonal_swaps(mesh, metrics, memo, verdicts);
}

tri::EdgeSwapCounters shorter_diagonal_swaps_2d(tri::TriMesh2& mesh,
                                                std::span<const Metric2> metrics,
                                                MetricFromLogFormMemo* memo,
                                                tri::SwapVerdicts2* verdicts) {
    return shorter_diagonal_swaps(mesh, metrics, memo, verdicts);
}

PointSmoothingCounters2 smooth_metric_points_2d(tri::Triangulation2& mesh,
                                                std::span<const Metric2> metrics,
                                                std::span<const double> relax, double limit,
                                                MoveLimit limit_kind, tri::VertIdx first_movable,
                                                bool keep_unit_edges, bool log_euclidean_lengths,
                                                MetricFromLogFormMemo* memo) {
    PointSmoothingCounters2 counters;
    /// How the edge from v to u is measured: in the log-Euclidean mean of the ends' metrics
    /// (taken once per vertex's star: the weights and both unit-edge counts measure the same
    /// edges), or as the mean of its lengths in both.
    struct EdgeMetric {
        bool log_euclidean = false;
        bool same = false;  ///< both ends' metrics equal: one length is both
        Metric2 mean;
    };
    const auto edge_metric = [&](tri::VertIdx v, tri::VertIdx u) {
        const Metric2& a = metrics[v];
        const Metric2& b = metrics[u];
        const bool same = a.h1 == b.h1 && a.h2 == b.h2 && a.c == b.c && a.s == b.s;
        if (log_euclidean_lengths && !same) {
            static constexpr double kHalves[2] = {0.5, 0.5};
            const Metric2 ends[2] = {metrics[v], metrics[u]};
            return EdgeMetric{true, false, log_euclidean_mean(ends, kHalves, memo)};
        }
        return EdgeMetric{false, same, Metric2{}};
    };
    const auto edge_length = [&](const EdgeMetric& edge, tri::VertIdx v, tri::VertIdx u, double ex,
                                 double ey) {
        if (edge.log_euclidean) return metric_length(edge.mean, ex, ey);
        if (edge.same) {
            // Equal metrics (==; their bits differ at most in the sign of a zero direction
            // component, which no product here can carry into the length) measure alike.
            const double length = metric_length(metrics[v], ex, ey);
            return 0.5 * (length + length);
        }
        return 0.5 * (metric_length(metrics[v], ex, ey) + metric_length(metrics[u], ex, ey));
    };
    std::vector<EdgeMetric> star_edges;
    const std::uint32_t nv = mesh.vertex_count();
    std::vector<std::uint32_t> start(std::size_t{nv} + 1, 0);
    for (const tri::VertIdx v : mesh.triangles) ++start[v + 1];
    for (std::uint32_t v = 0; v < nv; ++v) start[v + 1] += start[v];
    std::vector<std::uint32_t> star(mesh.triangles.size());
    {
        std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
        for (std::uint32_t i = 0; i < mesh.triangles.size(); ++i)
            star[fill[mesh.triangles[i]]++] = i / 3;
    }
    for (tri::VertIdx v = first_movable; v < nv; ++v) {
        if (start[v] == start[v + 1] || !(relax[v] > 0)) continue;
        const double px = mesh.xy[2 * std::size_t{v}], py = mesh.xy[2 * std::size_t{v} + 1];
        double sum_w = 0, sum_x = 0, sum_y = 0;
        star_edges.clear();
        for (std::uint32_t j = start[v]; j < start[v + 1]; ++j) {
            const tri::TriIdx t = star[j];
            // Each neighbour once: the one after v in each counter-clockwise triangle (an
            // interior vertex's star is closed, so this visits each neighbour exactly once).
            unsigned k = 0;
            while (mesh.triangles[3 * t + k] != v) ++k;
            const tri::VertIdx u = mesh.triangles[3 * t + (k + 1) % 3];
            const double dx = mesh.point(u)[0] - px, dy = mesh.point(u)[1] - py;
            star_edges.push_back(edge_metric(v, u));
            const double w = edge_length(star_edges.back(), v, u, dx, dy);
            sum_w += w;
            sum_x += w * dx;
            sum_y += w * dy;
        }
        if (!(sum_w > 0)) continue;
        double dx = relax[v] * (sum_x / sum_w), dy = relax[v] * (sum_y / sum_w);
        // A long edge (a triangle across several layers) weighs much and would drag the point
        // by a large part of its cell, and in a stretched cell a shift along the wall by more
        // than a fraction of the thickness shears it into an obtuse triangle: the move is
        // limited (MoveLimit).
        const double step =
            limit_kind == MoveLimit::SmallestSize
                ? predicates::scale_free_norm(dx, dy) / std::min(metrics[v].h1, metrics[v].h2)
                : metric_length(metrics[v], dx, dy);
        if (step > limit) {
            dx *= limit / step;
            dy *= limit / step;
        }
        const double q[2] = {px + dx, py + dy};
        if (!std::isfinite(q[0]) || !std::isfinite(q[1]) || (q[0] == px && q[1] == py)) continue;
        bool valid = true;
        for (std::uint32_t j = start[v]; j < start[v + 1] && valid; ++j) {
            const tri::TriIdx t = star[j];
            const double* corner[3];
            for (unsigned k = 0; k < 3; ++k) {
                const tri::VertIdx w = mesh.triangles[3 * t + k];
                corner[k] = w == v ? q : mesh.point(w);
            }
            valid = predicates::orient2d(corner[0], corner[1], corner[2]) == Sign::Positive;
        }
        if (valid && keep_unit_edges) {
            // The star's edges of unit metric length ([1/sqrt 2, sqrt 2], as the quality report
            // counts them) may not become fewer: smoothing is for shape, not at lengths' cost.
            const auto unit_edges = [&](double x, double y) {
                int count = 0;
                for (std::uint32_t j = start[v]; j < start[v + 1]; ++j) {
                    const tri::TriIdx t = star[j];
                    unsigned k = 0;
                    while (mesh.triangles[3 * t + k] != v) ++k;
                    const tri::VertIdx u = mesh.triangles[3 * t + (k + 1) % 3];
                    const double ex = mesh.point(u)[0] - x, ey = mesh.point(u)[1] - y;
                    const double l = edge_length(star_edges[j - start[v]], v, u, ex, ey);
                    if (l >= kUnitLow && l <= kUnitHigh) ++count;
                }
                return count;
            };
            valid = unit_edges(q[0], q[1]) >= unit_edges(px, py);
        }
        if (!valid) {
            ++counters.refused;
            continue;
        }
        mesh.xy[2 * std::size_t{v}] = q[0];
        mesh.xy[2 * std::size_t{v} + 1] = q[1];
        ++counters.moves;
    }
    return counters;
}

}  // namespace exactmesh::generators
