// SPDX-License-Identifier: MIT
// 3D Delaunay refinement with cavities restricted by subfaces (see delaunay_refinement_3d.hpp).
#include "generators/mesh_3d/delaunay_refinement_3d.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "base/errors.hpp"
#include "base/number_text.hpp"
#include "generators/mesh_3d/gap_estimate_3d.hpp"
#include "generators/mesh_3d/small_angle_rule_3d.hpp"
#include "predicates/constructions.hpp"
#include "predicates/dot_sign_3d.hpp"
#include "predicates/incircle.hpp"
#include "predicates/insphere.hpp"
#include "predicates/orient2d.hpp"
#include "predicates/orient3d.hpp"
#include "predicates/tet_quality_3d.hpp"
#include "triangulation/mesh/facet_projection_3d.hpp"
#include "triangulation/mesh/mesh3.hpp"
#include "triangulation/mesh/vertex_keys_3d.hpp"
#include "triangulation/recovery_3d/boundary_recovery_3d.hpp"

#include "generators/mesh_3d/restricted_delaunay_3d.hpp"

namespace exactmesh::generators {

using namespace restricted_3d;  // NOLINT: the shared machinery and its aliases

namespace {

/// How many times a bad tetrahedron's split may be deferred to subsegments or subfaces.
constexpr std::uint32_t kMaxRetries = 64;

class Refinement final : public RestrictedDelaunay3 {
  public:
    Refinement(const Plc3& plc, ConformingMesh3 recovered,
               const DelaunayRefinement3Options& options, std::uint64_t budget)
        : RestrictedDelaunay3(plc, std::move(recovered), budget, "delaunay refinement 3d"),
          options_(options) {}

    DelaunayRefinement3Result run();

  private:
    DelaunayRefinement3Options options_;
    struct QueuedTet {
        TetIdx t;
        std::array<VertIdx, 4> corners;
        std::uint32_t retries;  ///< times its split was deferred to subsegments or subfaces
    };
    std::deque<QueuedTet> tet_queue_;

    void on_created(TetIdx t) override { tet_queue_.push_back({t, m_.tet(t), 0}); }

    /// Tetrahedron t's volume bound (0: none): the global one and its region's, the smaller.
    double volume_bound(TetIdx t) const {
        return tet_volume_bound_3d(options_.max_volume,
                                   max_volumes_.empty() ? 0.0 : max_volumes_[t]);
    }

    /// Whether the tetrahedron with corners c exceeds the radius-edge bound (exact).
    bool over_radius_edge(const std::array<VertIdx, 4>& c) const {
        return predicates::compare_radius_edge_3d(point(c[0]), point(c[1]), point(c[2]),
                                                  point(c[3]),
                                                  options_.radius_edge_bound) == Sign::Positive;
    }

    bool unresolvable(const std::array<VertIdx, 4>& c) const {
        const double* const p[4] = {point(c[0]), point(c[1]), point(c[2]), point(c[3])};
        return tet_finer_than_doubles_resolve_3d(p);
    }

    bool over_volume(TetIdx t, const std::array<VertIdx, 4>& c) const {
        const double bound = volume_bound(t);
        return bound > 0 && predicates::compare_tet_volume_3d(point(c[0]), point(c[1]), point(c[2]),
                                                              point(c[3]), bound) == Sign::Positive;
    }

    /// The cavity of t's circumcentre p seeded with every tetrahedron of the walk from t to p,
    /// when the cavity grown from p's own tetrahedron alone fails (it misses t) and p
    /// encroaches nothing of that tetrahedron (the centre would have been rejected). Where shrunk
    /// cavities left tetrahedra that are not Delaunay, the tetrahedra in conflict with p need not
    /// be connected: on the wing at 7 10^5 tetrahedra the walk from t crossed up to seven
    /// tetrahedra whose spheres leave p out, no subface among them, and 9 centres were rejected,
    /// leaving 2 tetrahedra over the radius-edge bound. The walk's tetrahedra are taken whatever
    /// their spheres, so t goes with its centre; the cavity must still be star-shaped from p and
    /// keep every subface, subsegment and boundary edge (build_cavity's checks).
    bool build_cavity_along_walk(TetIdx t, const double* p) {
        std::vector<TetIdx> path;
        TetIdx s = t;
        Key3 blocking{};
        if (walk_to(t, p, s, blocking, &path) != Walk::Reached || path.size() > kMaxWalkSeeds)
            return false;
        ++counters_.walk_seeded_cavities;
        return build_cavity(p, path, no_split(), t);
    }
    static constexpr std::size_t kMaxWalkSeeds = 64;

    bool split_tet(TetIdx t) {
        const std::array<VertIdx, 4> c{m_.vertex(t, 0), m_.vertex(t, 1), m_.vertex(t, 2),
                                       m_.vertex(t, 3)};
        const std::array<double, 3> center =
            predicates::circumcenter(point(c[0]), point(c[1]), point(c[2]), point(c[3]));
        // Visibility walk towards the centre; stopped by a subface or the boundary.
        TetIdx s = t;
        Key3 blocking{};
        switch (walk_to(t, center.data(), s, blocking)) {
            case Walk::Failed:
                ++counters_.rejected_points;
                return false;
            case Walk::Blocked:
                ++counters_.blocked_circumcenters;
                subface_queue_.push_front(blocking);
                return true;
            case Walk::Reached:
                break;
        }
        for (unsigned k = 0; k < 4; ++k) {
            if (same_point(point(m_.vertex(s, k)), center.data())) {
                ++counters_.rejected_points;
                return false;
            }
        }
        const Split& none = no_split();
        if (!build_cavity(center.data(), s, none, t)) {
            // The centre on a face of its tetrahedron that cannot be crossed: it encroaches that
            // subface (or one of its subsegments), split instead.
            cavity_ = {s};
            if (queue_encroached_segments(center.data()) ||
                queue_encroached_subfaces(center.data()))
                return true;
            if (!build_cavity_along_walk(t, center.data())) {
                ++counters_.rejected_points;
                return false;
            }
        }
        // Encroached subsegments first, then subfaces of the cavity (boundary faces and the
        // subfaces that stopped it).
        if (queue_encroached_segments(center.data()) || queue_encroached_subfaces(center.data()))
            return true;
        commit(center, VertexFeature3::Volume, kNone, 0.0, none, {}, {});
        ++counters_.circumcenters;
        return false;
    }
};

DelaunayRefinement3Result Refinement::run() {
    for (TetIdx t = 0; t < m_.tet_slots(); ++t)
        if (!m_.is_dead(t)) examine(t);
    while (true) {
        if (!segment_queue_.empty()) {
            const std::uint64_t key = segment_queue_.front();
            segment_queue_.pop_front();
            split_subsegment(key);
            continue;
        }
        if (!subface_queue_.empty()) {
            const Key3 key = subface_queue_.front();
            subface_queue_.pop_front();
            split_subface(key);
            continue;
        }
        if (tet_queue_.empty()) break;
        const QueuedTet next = tet_queue_.front();
        tet_queue_.pop_front();
        const auto& corners = next.corners;
        if (m_.is_dead(next.t) || m_.tet(next.t) != corners) continue;
        // Bad: over its volume bound or its radius-edge bound, the volume asked first (half
        // the radius-edge test's cost, and its answer is needed below) and asked once.
        const bool over = over_volume(next.t, corners);
        if (!over && !over_radius_edge(corners)) continue;
        if (!over && small_angles_->spares(corners)) {
            ++counters_.small_angle_tets;
            continue;
        }
        if (unresolvable(corners)) {
            ++counters_.unresolvable_tets;
            continue;
        }
        // A deferred tetrahedron comes back after the splits it queued (unless they removed
        // it); a bounded number of times, so that splits that keep failing cannot loop.
        if (split_tet(next.t)) {
            if (next.retries < kMaxRetries) {
                tet_queue_.push_back({next.t, corners, next.retries + 1});
            } else {
                ++counters_.rejected_points;
            }
        }
    }
    DelaunayRefinement3Result result;
    result.counters = counters_;
    if (!options_.sliver_removal) {
        result.mesh = finish();
        return result;
    }
    const auto start = std::chrono::steady_clock::now();
    auto [conforming, linked] = take_linked();
    SliverRemoval3Result improved = sliver_removal_3d(std::move(conforming), std::move(linked),
                                                      *options_.sliver_removal, &sharp_);
    result.sliver_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    result.mesh = std::move(improved.mesh);
    result.slivers = improved.counters;
    return result;
}

/// A volume bound that asks for far more points than the budget fails at once with the
/// estimate, not after the budget's insertions (each exact, minutes at 10^6): every tetrahedron
/// is at most its bound, so the mesh has at least the sum over the recovered tetrahedra of
/// volume / bound of them (with per-region bounds each tetrahedron divides by its own; one
/// without a bound counts nothing), and a Delaunay tetrahedralization has about 6.5 per vertex;
/// refused when that estimate exceeds the budget (refinement made 1.35 to 8 times its points on
/// the sample domains at V = 10^-3 and 2.44 10^-5; a margin of 6 let a bound asking for 5 times
/// the budget run a million insertions into it). Volumes are taken on
/// coordinates scaled by one power of two, each quotient kept as a double times a power of two
/// and summed at a common exponent, the total compared in logarithms: nothing overflows or
/// underflows at 2^+-600, whatever the bounds' magnitudes.
void refuse_volume_bound_far_over_budget(const ConformingMesh3& recovered,
                                         const DelaunayRefinement3Options& options) {
    const bool region_bounds =
        std::any_of(recovered.tet_max_volume.begin(), recovered.tet_max_volume.end(),
                    [](double bound) { return bound > 0; });
    if (!(options.max_volume > 0) && !region_bounds) return;
    const auto& m = recovered.mesh;
    double largest = 0;
    for (const double x : m.xyz) largest = std::max(largest, std::fabs(x));
    if (!(largest > 0) || !std::isfinite(largest)) return;
    const int e = std::ilogb(largest);
    // tets = sum of (six_volume_t / 6 / mantissa_t) * 2^(3e - exponent_t), bound_t =
    // mantissa_t * 2^exponent_t; kept as sum * 2^sum_exponent.
    double sum = 0;
    int sum_exponent = 0;
    double smallest_bound = 0;
    for (TetIdx t = 0; t < m.tet_count(); ++t) {
        const double bound = tet_volume_bound_3d(recovered, t, options.max_volume);
        if (!(bound > 0)) continue;
        if (!(smallest_bound > 0) || bound < smallest_bound) smallest_bound = bound;
        double q[4][3];
        for (unsigned k = 0; k < 4; ++k) {
            const double* p = m.point(m.tets[4 * std::size_t{t} + k]);
            for (int i = 0; i < 3; ++i) q[k][i] = std::ldexp(p[i], -e);
        }
        double u[3], v[3], w[3];
        for (int i = 0; i < 3; ++i) {
            u[i] = q[1][i] - q[0][i];
            v[i] = q[2][i] - q[0][i];
            w[i] = q[3][i] - q[0][i];
        }
        const double six_volume =
            std::fabs(u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
                      u[2] * (v[0] * w[1] - v[1] * w[0]));
        if (!(six_volume > 0)) continue;
        int bound_exponent = 0;
        const double mantissa = std::frexp(bound, &bound_exponent);
        const double term = six_volume / 6 / mantissa;
        const int term_exponent = 3 * e - bound_exponent;
        if (!(sum > 0)) {
            sum = term;
            sum_exponent = term_exponent;
        } else if (term_exponent > sum_exponent) {
            sum = std::ldexp(sum, sum_exponent - term_exponent) + term;
            sum_exponent = term_exponent;
        } else {
            sum += std::ldexp(term, term_exponent - sum_exponent);
        }
    }
    if (!(sum > 0)) return;
    const std::uint64_t budget = steiner_budget_3d(recovered, options.max_steiner_points);
    const double log2_tets = std::log2(sum) + sum_exponent;
    const double points = std::exp2(std::min(log2_tets, 1000.0)) / 6.5;
    if (points > static_cast<double>(budget)) {
        std::string bounds;
        if (!region_bounds) {
            bounds = "the volume bound " + format_number(options.max_volume) + " asks";
        } else if (options.max_volume > 0) {
            bounds = "the volume bound " + format_number(options.max_volume) +
                     " with the region volume bounds (smallest in force " +
                     format_number(smallest_bound) + ") ask";
        } else {
            bounds =
                "the region volume bounds (smallest " + format_number(smallest_bound) + ") ask";
        }
        throw InputError("delaunay refinement 3d: Steiner point budget of " +
                         std::to_string(budget) + " exceeded at once: " + bounds + " for about " +
                         format_approximate(points, 3) +
                         " Steiner points (sum of volume / bound / 6.5 per vertex); raise the "
                         "bound or the budget");
    }
}

}  // namespace

DelaunayRefinement3Result delaunay_refinement_3d(const Plc3& plc, ConformingMesh3 recovered,
                                                 const DelaunayRefinement3Options& options) {
    if (!(options.radius_edge_bound > 0) || !std::isfinite(options.radius_edge_bound)) {
        throw InputError(
            "delaunay refinement 3d: the radius-edge bound must be a positive "
            "number, got " +
            std::to_string(options.radius_edge_bound));
    }
    if (options.radius_edge_bound < 1) {
        // A circumcentre inserted for a tetrahedron of ratio R / l > B makes edges at least R
        // long, so with B >= 1 no insertion shortens the shortest edge; below 1 each one may, and
        // the insertions do not stop (measured: B = 0.9 on one tetrahedron ran 10^6 insertions,
        // 3 minutes, into the budget). Refused at once instead.
        throw InputError(
            "delaunay refinement 3d: radius-edge bound " +
            format_number(options.radius_edge_bound) +
            " is below 1: circumcentre insertion may then shorten edges without end (and no "
            "tetrahedron at all is below sqrt(6)/4 = 0.612); give at least 1 (2 is TetGen's "
            "default; the termination proof needs more than 2)");
    }
    if (!std::isfinite(options.max_volume)) {
        throw InputError("delaunay refinement 3d: the volume bound must be finite");
    }
    if (!recovered.tet_max_volume.empty()) {
        if (recovered.tet_max_volume.size() != recovered.mesh.tet_count()) {
            throw InputError(
                "delaunay refinement 3d: the region volume bounds need one value per "
                "tetrahedron");
        }
        for (const double bound : recovered.tet_max_volume) {
            if (!std::isfinite(bound))
                throw InputError("delaunay refinement 3d: a region volume bound is not finite");
        }
    }
    refuse_volume_bound_far_over_budget(recovered, options);
    const std::uint64_t budget = steiner_budget_3d(recovered, options.max_steiner_points);
    refuse_gaps_far_over_budget_3d(plc, recovered, budget, "delaunay refinement 3d");
    Refinement refinement(plc, std::move(recovered), options, budget);
    return refinement.run();
}

bool tet_finer_than_doubles_resolve_3d(const double* const (&p)[4]) {
    double largest = 0;
    for (const double* q : p)
        for (int k = 0; k < 3; ++k) largest = std::max(largest, std::fabs(q[k]));
    if (!(largest > 0)) return false;
    const double threshold = std::ldexp(1.0, std::ilogb(largest) - 44);
    for (const auto& e : kEdges) {
        bool below = true;
        for (int k = 0; k < 3 && below; ++k) below = std::fabs(p[e[1]][k] - p[e[0]][k]) < threshold;
        if (below) return true;
    }
    return false;
}

RefinementQuality3 check_refinement_quality_3d(const ConformingMesh3& mesh,
                                               const DelaunayRefinement3Options& options) {
    RefinementQuality3 report;
    const SmallInputAngleRule3 small_angles(mesh, mesh.mesh.xyz);
    const auto& m = mesh.mesh;
    for (TetIdx t = 0; t < m.tet_count(); ++t) {
        const std::array<VertIdx, 4> c{m.tets[4 * std::size_t{t}], m.tets[4 * std::size_t{t} + 1],
                                       m.tets[4 * std::size_t{t} + 2],
                                       m.tets[4 * std::size_t{t} + 3]};
        const double *a = m.point(c[0]), *b = m.point(c[1]), *d = m.point(c[2]), *e = m.point(c[3]);
        const double bound = tet_volume_bound_3d(mesh, t, options.max_volume);
        if (bound > 0 && predicates::compare_tet_volume_3d(a, b, d, e, bound) == Sign::Positive)
            ++report.over_volume;
        if (predicates::compare_radius_edge_3d(a, b, d, e, options.radius_edge_bound) !=
            Sign::Positive)
            continue;
        if (small_angles.spares(c)) {
            ++report.small_angle;
        } else {
            const double* const p[4] = {a, b, d, e};
            ++(tet_finer_than_doubles_resolve_3d(p) ? report.unresolvable : report.over_bound);
        }
    }
    return report;
}

}  // namespace exactmesh::generators