// SPDX-License-Identifier: MIT
// Frontal Delaunay tetrahedral mesh generation (see frontal_delaunay_3d.hpp).
//
// State beside the restricted Delaunay machinery (restricted_delaunay_3d.hpp): per tetrahedron
// slot a status (waiting, active, accepted), a version that grows whenever an insertion reuses
// the slot, and the key R / f; a binary heap of (key, slot, version) for the active
// tetrahedra, whose stale entries are skipped when popped. Loop: pop the worst active
// tetrahedron; place its point from its front face; insert it (then classify the new
// tetrahedra and activate the waiting ones beside accepted ones) or reject it (then accept the
// tetrahedron and activate its waiting neighbours).
#include "generators/mesh_3d/frontal_delaunay_3d.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <span>
#include <string>
#include <vector>

#include "base/errors.hpp"
#include "base/number_text.hpp"
#include "generators/mesh_3d/feature_size_3d.hpp"
#include "generators/mesh_3d/gap_estimate_3d.hpp"
#include "generators/mesh_3d/restricted_delaunay_3d.hpp"
#include "generators/mesh_3d/scaled_differences_3d.hpp"

namespace exactmesh::generators {

using namespace restricted_3d;  // NOLINT: the shared machinery and its aliases

namespace {

enum class Status : std::uint8_t { Waiting, Active, Accepted };

struct ActiveEntry {
    double key;  // R / f: larger first
    TetIdx t;
    std::uint32_t version;
    bool operator<(const ActiveEntry& o) const { return key < o.key || (key == o.key && t > o.t); }
};

constexpr double kRegularCircumradius = 0.61237243569579452;  // sqrt(3/8): edge 1
constexpr double kSqrt2 = 1.4142135623730951;

using vec3::cross;
using vec3::dot;
using vec3::sub;
using vec3::Vec;
double norm(const Vec& p) {
    return std::sqrt(dot(p, p));
}

/// The circumcentre of the triangle 0, u, v (relative to its first corner).
Vec triangle_center(const Vec& u, const Vec& v) {
    const Vec n = cross(u, v);
    const double uu = dot(u, u), vv = dot(v, v), nn = dot(n, n);
    const Vec w{uu * v[0] - vv * u[0], uu * v[1] - vv * u[1], uu * v[2] - vv * u[2]};
    const Vec c = cross(w, n);
    return {c[0] / (2 * nn), c[1] / (2 * nn), c[2] / (2 * nn)};
}

/// The circumcentre of the tetrahedron 0, u, v, w (relative to its first corner).
Vec tet_center(const Vec& u, const Vec& v, const Vec& w) {
    const Vec vw = cross(v, w), wu = cross(w, u), uv = cross(u, v);
    const double det2 = 2 * dot(u, vw);
    const double uu = dot(u, u), vv = dot(v, v), ww = dot(w, w);
    Vec c;
    for (int i = 0; i < 3; ++i) c[i] = (uu * vw[i] + vv * wu[i] + ww * uv[i]) / det2;
    return c;
}

class Frontal final : public RestrictedDelaunay3 {
  public:
    Frontal(const Plc3& plc, ConformingMesh3 recovered, const FrontalDelaunay3Options& options,
            std::uint64_t budget, int exponent)
        : RestrictedDelaunay3(plc, std::move(recovered), budget, "frontal delaunay 3d"),
          options_(options),
          exponent_(exponent) {}

    FrontalDelaunay3Result run();
    FrontalDelaunay3Counters result_counters;

  private:
    const FrontalDelaunay3Options& options_;
    int exponent_;  ///< differences are measured in units of 2^exponent_ (near the size)
    bool interior_ = false;
    FrontalDelaunay3Counters& fc_ = result_counters;
    std::vector<Status> status_;
    std::vector<std::uint32_t> version_;
    std::vector<double> key_;
    std::priority_queue<ActiveEntry> heap_;
    std::vector<TetIdx> created_;
    // Boundary fitting's subfaces and subsegments over the size, by how far over (circumradius
    // or length / the bound), the largest first; encroached ones (the base's queues) go before
    // them. First come, first split, the order followed the recovered mesh's numbering: with
    // the recovery's Delaunay numbered by seeds 2 and 3 the wing at size 0.08 never ended (flat
    // subfaces of a facet not Delaunay there had their centres beyond a segment, which was
    // split down to 2^-22); seed 1 took 10,064 subface splits and 2.8 s, the flattest
    // tetrahedron 0.41 degrees after sliver removal (with the runaway stopped by a rule since
    // withdrawn, seeds 1-6 ranged up to 11,681 splits, 13.4 s and 0.004 degrees). Largest
    // first, seeds 1-6 take 9,346 to 9,356 splits, about 2 s and 5.6 to 6.7 degrees (a split
    // of the largest keeps the facet Delaunay more often: its centre is far from every vertex).
    std::priority_queue<std::pair<double, Key3>> oversize_subfaces_;
    std::priority_queue<std::pair<double, std::uint64_t>> oversize_segments_;

    /// v's position relative to `origin`, in units of 2^exponent_ (exact scaling).
    Vec relative(const double* p, const double* origin) const {
        return {std::ldexp(p[0] - origin[0], -exponent_), std::ldexp(p[1] - origin[1], -exponent_),
                std::ldexp(p[2] - origin[2], -exponent_)};
    }
    /// The size at p in units of 2^exponent_.
    double size_at(const Vec& p) const {
        return std::ldexp(options_.size(p[0], p[1], p[2]), -exponent_);
    }
    Vec centroid(std::initializer_list<VertIdx> vertices) const {
        Vec c{0, 0, 0};
        for (const VertIdx v : vertices)
            for (int i = 0; i < 3; ++i) c[i] += point(v)[i];
        const double n = static_cast<double>(vertices.size());
        return {c[0] / n, c[1] / n, c[2] / n};
    }

    void grow_slots() {
        const std::size_t slots = m_.tet_slots();
        if (status_.size() < slots) {
            status_.resize(slots, Status::Waiting);
            version_.resize(slots, 0);
            key_.resize(slots, 0);
        }
    }

    void on_created(TetIdx t) override {
        grow_slots();
        ++version_[t];
        if (interior_) {
            created_.push_back(t);
            return;
        }
        // Boundary fitting: queue the subfaces and subsegments of t over the size.
        for (unsigned k = 0; k < 4; ++k) {
            const Key3 key = face_key(t, k);
            if (subfaces_.count(key) == 0) continue;
            const double* a = point(key[0]);
            const Vec u = relative(point(key[1]), a), v = relative(point(key[2]), a);
            const double r = norm(triangle_center(u, v));
            const double f = size_at(centroid({key[0], key[1], key[2]})) / kSqrt2;
            if (r > f) oversize_subfaces_.push({r / f, key});
        }
        for (const auto& e : kEdges) {
            const VertIdx a = m_.vertex(t, e[0]), b = m_.vertex(t, e[1]);
            const std::uint64_t key = edge_key(a, b);
            if (subsegments_.count(key) == 0) continue;
            const double l = norm(relative(point(b), point(a)));
            const double f = kSqrt2 * size_at(centroid({a, b}));
            if (l > f) oversize_segments_.push({l / f, key});
        }
    }

    /// Writes key_ and status_ of a live tetrahedron (accepted or waiting).
    void classify(TetIdx t) {
        const double* a = point(m_.vertex(t, 0));
        const Vec u = relative(point(m_.vertex(t, 1)), a), v = relative(point(m_.vertex(t, 2)), a),
                  w = relative(point(m_.vertex(t, 3)), a);
        const double radius = norm(tet_center(u, v, w));
        const double f =
            kRegularCircumradius *
            size_at(centroid({m_.vertex(t, 0), m_.vertex(t, 1), m_.vertex(t, 2), m_.vertex(t, 3)}));
        const double key = radius / f;
        key_[t] = std::isnan(key) ? INFINITY : key;
        status_[t] = key_[t] <= options_.acceptance ? Status::Accepted : Status::Waiting;
    }

    bool is_front_face(TetIdx t, unsigned k) const {
        const FaceIdx g = m_.adj[4 * t + k];
        return g == kNone || is_subface(t, k) ||
               status_[triangulation::tet_of(g)] == Status::Accepted;
    }

    bool on_front(TetIdx t) const {
        for (unsigned k = 0; k < 4; ++k)
            if (is_front_face(t, k)) return true;
        return false;
    }

    void activate(TetIdx t) {
        if (status_[t] != Status::Waiting) return;
        status_[t] = Status::Active;
        heap_.push({key_[t], t, version_[t]});
    }

    void activate_neighbours(TetIdx t) {
        for (unsigned k = 0; k < 4; ++k) {
            const FaceIdx g = m_.adj[4 * t + k];
            if (g != kNone && !is_subface(t, k)) activate(triangulation::tet_of(g));
        }
    }

    void accept(TetIdx t) {
        status_[t] = Status::Accepted;
        ++fc_.forced_accepts;
        activate_neighbours(t);
    }

    /// Rebay's point for front face k of t (see the header), or a non-finite point.
    std::array<double, 3> place(TetIdx t, unsigned k) const {
        const unsigned* lf = triangulation::kFaceVertex[k];
        const double* a = point(m_.vertex(t, lf[0]));
        const Vec u = relative(point(m_.vertex(t, lf[1])), a);
        const Vec v = relative(point(m_.vertex(t, lf[2])), a);
        const Vec w = relative(point(m_.vertex(t, k)), a);  // the apex: the inner side
        const Vec m = triangle_center(u, v);
        const double r = norm(m);
        Vec n = cross(u, v);
        const double length = norm(n);
        for (double& x : n) x /= length;
        if (dot(n, w) < 0)
            for (double& x : n) x = -x;
        const Vec c = tet_center(u, v, w);
        const double q = dot(sub(c, m), n);
        const double radius = norm(c);
        Vec absolute_m;
        for (int i = 0; i < 3; ++i) absolute_m[i] = a[i] + std::ldexp(m[i], exponent_);
        const double f = kRegularCircumradius * size_at(absolute_m);
        double d;
        if (q >= r) {
            const double rho = std::min(std::max(f, r), (r * r + q * q) / (2 * q));
            d = std::min(rho + std::sqrt(std::max(0.0, rho * rho - r * r)), q);
        } else {
            // The circumcentre lies closer to the face than r (or behind it): the face is
            // large for the size. Rebay's distance, kept inside the circumsphere (whose far
            // point on the normal is at q + R) by half.
            const double rho = std::max(f, r);
            d = std::min(rho + std::sqrt(std::max(0.0, rho * rho - r * r)), 0.5 * (q + radius));
        }
        std::array<double, 3> x;
        for (int i = 0; i < 3; ++i) x[i] = a[i] + std::ldexp(m[i] + d * n[i], exponent_);
        return x;
    }

    /// The front face of t with the smallest circumradius, or 4.
    unsigned front_face(TetIdx t) const {
        unsigned best = 4;
        double best_radius = INFINITY;
        for (unsigned k = 0; k < 4; ++k) {
            if (!is_front_face(t, k)) continue;
            const unsigned* lf = triangulation::kFaceVertex[k];
            const double* a = point(m_.vertex(t, lf[0]));
            const double r = norm(triangle_center(relative(point(m_.vertex(t, lf[1])), a),
                                                  relative(point(m_.vertex(t, lf[2])), a)));
            if (best == 4 || r < best_radius) {
                best = k;
                best_radius = r;
            }
        }
        return best;
    }

    /// Whether p lies strictly inside the equatorial sphere of a subface or the diametral
    /// sphere of a subsegment of `tets` (the cavity, or some of its tetrahedra; exact).
    bool encroaches(const double* p, std::span<const TetIdx> tets) const {
        for (const TetIdx t : tets) {
            for (unsigned k = 0; k < 4; ++k) {
                const Key3 key = face_key(t, k);
                if (subfaces_.count(key) != 0 &&
                    predicates::in_equatorial_sphere_3d(p, point(key[0]), point(key[1]),
                                                        point(key[2])) == Sign::Positive)
                    return true;
            }
            for (const auto& e : kEdges) {
                const VertIdx a = m_.vertex(t, e[0]), b = m_.vertex(t, e[1]);
                if (subsegments_.count(edge_key(a, b)) != 0 &&
                    predicates::dot_sign_3d(p, point(a), point(b)) == Sign::Negative)
                    return true;
            }
        }
        return false;
    }

    /// Some vertex of `tets` (the cavity, or some of its tetrahedra) closer to p than
    /// `fraction` h(p) (min_distance h(p) by default)?
    bool too_close(const double* p, std::span<const TetIdx> tets, double fraction = -1) const {
        const double limit =
            (fraction < 0 ? options_.min_distance : fraction) * size_at({p[0], p[1], p[2]});
        for (const TetIdx t : tets) {
            for (unsigned k = 0; k < 4; ++k) {
                const Vec d = relative(point(m_.vertex(t, k)), p);
                if (dot(d, d) < limit * limit) return true;
            }
        }
        return false;
    }

    /// A boundary split point within 2^-20 h of a vertex of its cavity is refused: the
    /// circumcentres of two subfaces that shared a circumcircle (the second left behind when
    /// the first one's facet cavity could not grow) landed a few ulps apart on the wing's
    /// walls, and their edge (1e-15 h) made tetrahedra with dihedral angles of 1e-16 degrees.
    bool boundary_point_allowed(const double* p) const override {
        return !too_close(p, cavity_, 0x1p-20);
    }

    void step(TetIdx t);
    void fit_boundary();
};

void Frontal::fit_boundary() {
    for (TetIdx t = 0; t < m_.tet_slots(); ++t)
        if (!m_.is_dead(t)) examine(t);
    while (true) {
        if (!segment_queue_.empty()) {
            const std::uint64_t key = segment_queue_.front();
            segment_queue_.pop_front();
            split_subsegment(key);
        } else if (!oversize_segments_.empty()) {
            const std::uint64_t key = oversize_segments_.top().second;
            oversize_segments_.pop();
            split_subsegment(key);
        } else if (!subface_queue_.empty()) {
            const Key3 key = subface_queue_.front();
            subface_queue_.pop_front();
            split_subface(key);
        } else if (!oversize_subfaces_.empty()) {
            const Key3 key = oversize_subfaces_.top().second;
            oversize_subfaces_.pop();
            split_subface(key);
        } else {
            break;
        }
    }
    fc_.segment_splits = counters_.segment_splits + counters_.shell_splits;
    fc_.subface_splits = counters_.subface_splits;
    fc_.boundary_rejections = counters_.rejected_points;
    fc_.longest_edge_subfaces = counters_.longest_edge_subfaces;
}

void Frontal::step(TetIdx t) {
    const unsigned k = front_face(t);
    if (k == 4) {
        status_[t] = Status::Waiting;  // its accepted neighbours went away since it was queued
        return;
    }
    const std::array<double, 3> x = place(t, k);
    if (!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2])) {
        ++fc_.rejected_cavity;
        accept(t);
        return;
    }
    TetIdx s = kNone;
    Key3 blocking{};
    if (walk_to(t, x.data(), s, blocking) != Walk::Reached) {
        ++fc_.rejected_outside;
        accept(t);
        return;
    }
    for (unsigned i = 0; i < 4; ++i) {
        if (same_point(point(m_.vertex(s, i)), x.data())) {
            ++fc_.rejected_too_close;
            accept(t);
            return;
        }
    }
    // s (the seed, never removed) and t (required) are in every cavity that can be committed,
    // so a subface or subsegment of theirs that x encroaches, or a vertex of theirs too close
    // to x, rejects x whatever the cavity: asked first, the same rejections (the same mesh)
    // without growing the cavity, which beside flat recovered tetrahedra has hundreds or
    // thousands of tetrahedra (and most such points were rejected after growing).
    const TetIdx first_two[2] = {s, t};
    if (encroaches(x.data(), first_two)) {
        ++fc_.early_rejections;
        ++fc_.rejected_encroach;
        accept(t);
        return;
    }
    if (options_.min_distance > 0 && too_close(x.data(), first_two)) {
        ++fc_.early_rejections;
        ++fc_.rejected_too_close;
        accept(t);
        return;
    }
    const Split& none = no_split();
    // t must go: x is inside its circumsphere by construction, and a cavity shrunk away from
    // t would leave it active with the same point to place.
    if (!build_cavity(x.data(), s, none, t) || !in_attempt(t)) {
        ++fc_.rejected_cavity;
        accept(t);
        return;
    }
    if (encroaches(x.data(), cavity_)) {
        ++fc_.rejected_encroach;
        accept(t);
        return;
    }
    if (options_.min_distance > 0 && too_close(x.data(), cavity_)) {
        ++fc_.rejected_too_close;
        accept(t);
        return;
    }
    created_.clear();
    commit(x, VertexFeature3::Volume, kNone, 0.0, none, {}, {});
    ++fc_.interior_points;
    for (const TetIdx u : created_) classify(u);
    for (const TetIdx u : created_) {
        if (status_[u] == Status::Accepted) {
            activate_neighbours(u);
        } else if (on_front(u)) {
            activate(u);
        }
    }
}

FrontalDelaunay3Result Frontal::run() {
    fit_boundary();
    interior_ = true;
    queue_encroachment_ = false;
    grow_slots();
    for (TetIdx t = 0; t < m_.tet_slots(); ++t)
        if (!m_.is_dead(t)) classify(t);
    for (TetIdx t = 0; t < m_.tet_slots(); ++t)
        if (!m_.is_dead(t) && status_[t] != Status::Accepted && on_front(t)) activate(t);
    while (!heap_.empty()) {
        const ActiveEntry top = heap_.top();
        heap_.pop();
        if (m_.is_dead(top.t) || top.version != version_[top.t] ||
            status_[top.t] != Status::Active) {
            ++fc_.stale_pops;
            continue;
        }
        ++fc_.active_pops;
        step(top.t);
    }
    for (TetIdx t = 0; t < m_.tet_slots(); ++t) {
        if (m_.is_dead(t)) continue;
        classify(t);
        if (status_[t] == Status::Accepted) ++fc_.accepted_tets;
    }
    fc_.cavity_tets = counters_.cavity_tets;
    fc_.batched_removals = counters_.batched_removals;
    FrontalDelaunay3Result result;
    result.mesh = finish();
    result.counters = fc_;
    return result;
}

/// The size's estimate of the Steiner points: the regular tetrahedra of edge h(centroid) that
/// fill each recovered tetrahedron (h^3 / (6 sqrt 2) each), summed, over about 5 tetrahedra per
/// vertex; or the surface's points (below), when more. Each tetrahedron's edge vectors are scaled
/// by the power of two of its own largest difference and the count is formed in logarithms, so a
/// domain at 2^600 with a size of 0.1 (a count near 2^1800) gives a huge estimate, not an overflow
/// (it used to give NaN, which no budget refused: 10^6 segment splits in a minute). The sum is
/// capped at 1e300.
double estimate_points(const ConformingMesh3& recovered, const SizeFunction3& size) {
    const auto& m = recovered.mesh;
    double tets = 0;
    for (TetIdx t = 0; t < m.tet_count(); ++t) {
        const double* p[4];
        Vec centroid{0, 0, 0};
        for (unsigned k = 0; k < 4; ++k) {
            p[k] = m.point(m.tets[4 * std::size_t{t} + k]);
            for (int i = 0; i < 3; ++i) centroid[i] += p[k][i] / 4;
        }
        Vec d[3];
        const int scale = scaled_differences(p, 4, d);
        if (scale == kCoincident) continue;
        const double six_volume = std::fabs(dot(d[0], cross(d[1], d[2])));
        if (!(six_volume > 0)) continue;
        // Volume = six_volume / 6 * 2^(3 scale).
        const double h = size(centroid[0], centroid[1], centroid[2]);
        const double log2_count =
            std::log2(six_volume / 6) + 3.0 * scale - 3 * std::log2(h) + std::log2(6 * kSqrt2);
        tets += std::exp2(std::min(log2_count, 1000.0));
    }
    // The surface: frontal insertion places points on the subfaces at the size too, about one
    // per equilateral triangle of edge h(centroid) and a half (sqrt(3)/4 h^2 each, two per
    // point), whatever the volume behind them: a needle (a tetrahedron with an edge 2^31 long
    // over a unit triangle) has a volume of 1/6 but a surface of 2^31, which the volume term
    // missed (frontal insertion then ran for minutes). Scaled like the volume term.
    double surface_points = 0;
    for (std::size_t f = 0; f + 2 < recovered.subfaces.size(); f += 3) {
        const double* p[3] = {m.point(recovered.subfaces[f]), m.point(recovered.subfaces[f + 1]),
                              m.point(recovered.subfaces[f + 2])};
        Vec centroid{0, 0, 0};
        for (unsigned k = 0; k < 3; ++k)
            for (int i = 0; i < 3; ++i) centroid[i] += p[k][i] / 3;
        Vec d[2];
        const int scale = scaled_differences(p, 3, d);
        if (scale == kCoincident) continue;
        const Vec n = cross(d[0], d[1]);
        const double twice_area = std::sqrt(dot(n, n));
        if (!(twice_area > 0)) continue;
        // Area = twice_area / 2 * 2^(2 scale).
        const double h = size(centroid[0], centroid[1], centroid[2]);
        const double log2_count = std::log2(twice_area / 2) + 2.0 * scale - 2 * std::log2(h) -
                                  std::log2(std::sqrt(3.0) / 4) - 1;
        surface_points += std::exp2(std::min(log2_count, 1000.0));
    }
    // The segments likewise: a point every h along each subsegment (a needle's facets are thin:
    // its edges 2^31 long at size 4096 ask for 1.5 10^6 points where its area asks for 150).
    double segment_points = 0;
    for (std::size_t e = 0; e + 1 < recovered.subsegments.size(); e += 2) {
        const double* p[2] = {m.point(recovered.subsegments[e]),
                              m.point(recovered.subsegments[e + 1])};
        Vec d[1];
        const int scale = scaled_differences(p, 2, d);
        if (scale == kCoincident) continue;
        const double *a = p[0], *b = p[1];
        const double h = size(a[0] / 2 + b[0] / 2, a[1] / 2 + b[1] / 2, a[2] / 2 + b[2] / 2);
        const double log2_count = std::log2(std::sqrt(dot(d[0], d[0]))) + scale - std::log2(h);
        segment_points += std::exp2(std::min(log2_count, 1000.0));
    }
    return std::min(std::max({tets / 5, surface_points, segment_points}), 1e300);
}

}  // namespace

FrontalDelaunay3Result frontal_delaunay_3d(const Plc3& plc, ConformingMesh3 recovered,
                                           const FrontalDelaunay3Options& given) {
    if (!given.size.defined())
        throw InputError("frontal delaunay 3d: a size (target edge length) is required");
    if (!(given.feature_gradation >= 0) || !std::isfinite(given.feature_gradation))
        throw InputError(
            "frontal delaunay 3d: the feature gradation must be a finite number >= "
            "0, got " +
            format_number(given.feature_gradation));
    FrontalDelaunay3Options options = given;
    if (given.feature_gradation > 0)
        options.size = feature_graded_size_3d(plc, given.size, given.feature_gradation);
    if (!(options.acceptance >= 1 && options.acceptance <= 4))
        throw InputError("frontal delaunay 3d: the acceptance must be in [1, 4], got " +
                         format_number(options.acceptance));
    if (!(options.min_distance >= 0 && options.min_distance < 1))
        throw InputError("frontal delaunay 3d: the minimum distance must be in [0, 1), got " +
                         format_number(options.min_distance));
    if (recovered.mesh.vertex_count() == 0)
        throw InputError("frontal delaunay 3d: the domain has no vertex");
    // The unit of the measures: the power of two at the size at the first vertex (exact
    // scaling, so decisions are the same for the input and size times 2^k).
    const double* first = recovered.mesh.point(0);
    const int exponent = std::ilogb(options.size(first[0], first[1], first[2]));
    const double estimate = estimate_points(recovered, options.size);
    const std::uint64_t budget = steiner_budget_3d(recovered, options.max_steiner_points);
    if (estimate > static_cast<double>(budget)) {
        throw InputError("frontal delaunay 3d: Steiner point budget of " + std::to_string(budget) +
                         " exceeded at once: the size " + options.size.describe() +
                         " asks for about " + format_approximate(estimate, 3) +
                         " points (the most of: domain volume / (h^3 / (6 sqrt 2)) / 5 per vertex, "
                         "surface area / (sqrt(3) / 4 h^2) / 2, segment length / h); raise the "
                         "size or the budget");
    }
    if (options.estimate_gaps)
        refuse_gaps_far_over_budget_3d(plc, recovered, budget, "frontal delaunay 3d");
    Frontal frontal(plc, std::move(recovered), options, budget, exponent);
    frontal.result_counters.estimated_points =
        static_cast<std::uint64_t>(std::min(estimate, 1.8e19));
    FrontalDelaunay3Result result = frontal.run();
    result.size = options.size;
    return result;
}

}  // namespace exactmesh::generators
