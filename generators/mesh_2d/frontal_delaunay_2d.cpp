// SPDX-License-Identifier: MIT
// Frontal Delaunay mesh generation (see frontal_delaunay_2d.hpp).
//
// State beside the ConstrainedTriangulation2 (built over the input vertices and the boundary
// points, with the boundary pieces as its segments): per triangle slot a status (accepted,
// active, waiting), a version that grows whenever an edit writes the slot, and the slot's key
// R / f; a binary heap of (key, slot, version) for the active triangles, whose stale entries
// are skipped when popped (lazy deletion). Loop: pop the worst active triangle; place its point
// on its shortest front edge; insert it (then classify the triangles the insertion wrote, and
// activate the non-accepted triangles beside accepted ones) or reject it (then accept the
// triangle and activate its non-accepted neighbours).
#include "generators/mesh_2d/frontal_delaunay_2d.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <queue>
#include <string>
#include <vector>

#include "base/errors.hpp"
#include "base/number_text.hpp"
#include "base/progress.hpp"
#include "generators/boundary/domain_boundary_2d.hpp"
#include "generators/boundary/region_areas_2d.hpp"
#include "predicates/incircle.hpp"
#include "triangulation/constrained/constrained_triangulation_2d.hpp"

namespace exactmesh::generators {

namespace {

namespace tri = exactmesh::triangulation;
using predicates::Sign;
using tri::EdgeIdx;
using tri::kNone;
using tri::TriIdx;
using tri::VertIdx;

enum class Status : std::uint8_t { Outside, Waiting, Active, Accepted };

struct ActiveEntry {
    double key;  // R / f: larger first
    TriIdx t;
    std::uint32_t version;
    bool operator<(const ActiveEntry& o) const { return key < o.key || (key == o.key && t > o.t); }
};

constexpr double kSqrt3 = 1.7320508075688772;

/// A power of two near the largest of `magnitudes` (1 when it is 0, not finite or subnormal): the
/// measures below divide their differences by it, which is exact, so that squares and products
/// of differences near 1e300 do not overflow (nor change where they did not).
double scale_of(std::initializer_list<double> magnitudes) {
    double m = 0;
    for (const double v : magnitudes) m = std::max(m, std::fabs(v));
    if (!std::isnormal(m)) return 1;
    return std::ldexp(1.0, std::ilogb(m));
}

class Frontal {
  public:
    /// The triangulation is the boundary's pieces as the segments of a new PSLG over the
    /// boundary's points (input vertices first, with their numbers), the input's holes and
    /// regions: the same domain, its boundary split to the size.
    Frontal(const tri::Pslg& pslg, const FrontalDelaunayOptions2& options,
            DomainBoundary2&& boundary, const tri::Cdt2Options& cdt_options)
        : options_(options),
          boundary_(std::move(boundary)),
          cdt_(tri::Pslg{boundary_.xy, boundary_.pieces, pslg.holes, pslg.regions,
                         piece_lines(boundary_)},
               cdt_options),
          mesh_(cdt_.mesh()) {}

    FrontalDelaunayResult2 run();

  private:
    const FrontalDelaunayOptions2& options_;
    DomainBoundary2 boundary_;
    tri::ConstrainedTriangulation2 cdt_;
    const tri::TriMesh2& mesh_;  // the triangulation's, valid across edits
    FrontalDelaunayCounters2 counters_;
    std::priority_queue<ActiveEntry> heap_;
    std::vector<Status> status_;          // per triangle slot
    std::vector<std::uint32_t> version_;  // per triangle slot
    std::vector<double> key_;             // per triangle slot: R / f
    std::vector<std::uint32_t> seen_;     // per triangle slot: stamp of the last scan
    std::uint32_t stamp_ = 0;
    std::vector<TriIdx> stack_, scanned_;
    std::uint64_t budget_ = 0;
    /// Points inserted, for options.cdt.progress (total: the expected count, set_budget).
    ProgressCounter progress_;

    const double* point(VertIdx v) const { return mesh_.point(v); }
    double size_at(double x, double y) const {
        const double s = options_.size(x, y);
        if (!(s > 0)) {
            throw InputError("size function: not a number > 0 at " +
                             format_point(std::array<double, 2>{x, y}.data()) + " (" +
                             options_.size.describe() + ")");
        }
        return s;
    }
    void grow_slots();
    std::uint32_t next_stamp();
    void set_budget();
    /// Writes status_ and key_ of a triangle in the domain (accepted or waiting).
    void classify(TriIdx t);
    /// Beside an accepted triangle or a boundary piece?
    bool on_front(TriIdx t) const;
    void activate(TriIdx t);
    void activate_neighbours(TriIdx t);
    void accept(TriIdx t);
    void process_touched();
    /// The front edge of t to advance from (the shortest), or kNone.
    EdgeIdx front_edge(TriIdx t) const;
    /// Rebay's point for front half-edge e of its triangle.
    std::array<double, 2> place(EdgeIdx e) const;
    /// Some vertex of the cavity of (x, y) from t (the triangles whose circumcircle holds it,
    /// reached across unconstrained edges in the domain) closer than `limit`?
    bool too_close(TriIdx t, double x, double y, double limit);
    void step(TriIdx t);
};

void Frontal::grow_slots() {
    const std::size_t slots = mesh_.triangle_slots();
    if (status_.size() < slots) {
        status_.resize(slots, Status::Outside);
        version_.resize(slots, 0);
        key_.resize(slots, 0);
        seen_.resize(slots, 0);
    }
}

std::uint32_t Frontal::next_stamp() {
    if (++stamp_ == 0) {
        std::fill(seen_.begin(), seen_.end(), 0u);
        stamp_ = 1;
    }
    return stamp_;
}

void Frontal::set_budget() {
    double lo_x = INFINITY, lo_y = INFINITY, hi_x = -INFINITY, hi_y = -INFINITY;
    for (std::size_t i = 0; i + 1 < boundary_.xy.size(); i += 2) {
        lo_x = std::min(lo_x, boundary_.xy[i]);
        hi_x = std::max(hi_x, boundary_.xy[i]);
        lo_y = std::min(lo_y, boundary_.xy[i + 1]);
        hi_y = std::max(hi_y, boundary_.xy[i + 1]);
    }
    // As Delaunay refinement: at least 10^6, 64 per boundary vertex, and 16 times the element
    // count the size asks for over the bounding box (equilateral_count_in_box).
    const double estimate = equilateral_count_in_box(options_.size, lo_x, lo_y, hi_x, hi_y);
    const double vertices = static_cast<double>(mesh_.vertex_count());
    budget_ = options_.max_steiner_points != 0
                  ? options_.max_steiner_points
                  : static_cast<std::uint64_t>(
                        std::min(std::max({1e6, 64 * vertices, 16 * estimate}), 4e9));
    // The frontal method makes close to the ideal count: about 1.2 times as many vertices as
    // the equilateral estimate's half. A hint only, capped at 2^21 vertices.
    const double expected =
        std::min({0.6 * estimate, static_cast<double>(budget_), 0x1p21}) + vertices;
    progress_ = ProgressCounter(
        options_.cdt.progress,
        estimate > 0 ? static_cast<std::uint64_t>(std::min(0.6 * estimate, 4e9)) : 0,
        "Steiner points inserted");
    cdt_.reserve(static_cast<std::uint32_t>(expected));
    status_.reserve(static_cast<std::size_t>(2 * expected));
    version_.reserve(static_cast<std::size_t>(2 * expected));
    key_.reserve(static_cast<std::size_t>(2 * expected));
    seen_.reserve(static_cast<std::size_t>(2 * expected));
}

void Frontal::classify(TriIdx t) {
    const double* p[3] = {point(mesh_.tv[3 * t]), point(mesh_.tv[3 * t + 1]),
                          point(mesh_.tv[3 * t + 2])};
    // R = abc / (4 area), in the differences from p0 over their scale (a measure, not a
    // decision): R = radius * scale.
    double ax = p[1][0] - p[0][0], ay = p[1][1] - p[0][1];
    double bx = p[2][0] - p[0][0], by = p[2][1] - p[0][1];
    double cx = p[2][0] - p[1][0], cy = p[2][1] - p[1][1];
    const double scale = scale_of({ax, ay, bx, by, cx, cy});
    ax /= scale, ay /= scale, bx /= scale, by /= scale, cx /= scale, cy /= scale;
    const double area2 = std::fabs(ax * by - ay * bx);
    const double product =
        std::sqrt((ax * ax + ay * ay) * (bx * bx + by * by) * (cx * cx + cy * cy));
    const double radius = area2 > 0 ? product / (2 * area2) : INFINITY;
    const double s = size_at((p[0][0] + p[1][0] + p[2][0]) / 3, (p[0][1] + p[1][1] + p[2][1]) / 3);
    const double key = radius * kSqrt3 / s * scale;  // R / f, f = s / sqrt 3
    key_[t] = std::isnan(key) ? INFINITY : key;
    status_[t] = key_[t] <= options_.acceptance ? Status::Accepted : Status::Waiting;
}

bool Frontal::on_front(TriIdx t) const {
    for (unsigned k = 0; k < 3; ++k) {
        const EdgeIdx e = 3 * t + k;
        if (cdt_.segment_of(e) != kNone ||
            status_[tri::triangle_of(mesh_.twin[e])] == Status::Accepted)
            return true;
    }
    return false;
}

void Frontal::activate(TriIdx t) {
    if (status_[t] == Status::Waiting) {
        status_[t] = Status::Active;
        heap_.push({key_[t], t, version_[t]});
    }
}

void Frontal::activate_neighbours(TriIdx t) {
    for (unsigned k = 0; k < 3; ++k) {
        const EdgeIdx e = 3 * t + k;
        if (cdt_.segment_of(e) == kNone) activate(tri::triangle_of(mesh_.twin[e]));
    }
}

void Frontal::accept(TriIdx t) {
    status_[t] = Status::Accepted;
    ++counters_.forced_accepts;
    activate_neighbours(t);
}

void Frontal::process_touched() {
    grow_slots();
    const std::uint32_t stamp = next_stamp();
    scanned_.clear();
    for (const TriIdx t : cdt_.touched()) {
        if (seen_[t] == stamp) continue;
        seen_[t] = stamp;
        ++version_[t];
        if (!cdt_.in_domain(t)) {
            status_[t] = Status::Outside;
            continue;
        }
        classify(t);
        scanned_.push_back(t);
    }
    cdt_.clear_touched();
    // Then the front: beside every accepted triangle, and every triangle on the front.
    for (const TriIdx t : scanned_) {
        if (status_[t] == Status::Accepted) {
            activate_neighbours(t);
        } else if (on_front(t)) {
            activate(t);
        }
    }
}

EdgeIdx Frontal::front_edge(TriIdx t) const {
    EdgeIdx best = kNone;
    double best_length = INFINITY;
    for (unsigned k = 0; k < 3; ++k) {
        const EdgeIdx e = 3 * t + k;
        if (cdt_.segment_of(e) == kNone &&
            status_[tri::triangle_of(mesh_.twin[e])] != Status::Accepted)
            continue;
        const double* a = point(mesh_.origin(e));
        const double* b = point(mesh_.destination(e));
        const double length = std::hypot(b[0] - a[0], b[1] - a[1]);
        // Any front edge beats none, whatever its length (infinite where the difference of
        // coordinates overflows): kNone would take t off the front.
        if (best == kNone || length < best_length) {
            best_length = length;
            best = e;
        }
    }
    return best;
}

std::array<double, 2> Frontal::place(EdgeIdx e) const {
    const double* a = point(mesh_.origin(e));
    const double* b = point(mesh_.destination(e));
    const double* c = point(mesh_.tv[tri::prev_edge(e)]);  // the apex
    // In the differences over their scale (exact, as in classify): the point is M + d scale n.
    const double mx = 0.5 * (a[0] + b[0]), my = 0.5 * (a[1] + b[1]);
    const double scale = scale_of({b[0] - a[0], b[1] - a[1]});
    const double ex = (b[0] - a[0]) / scale, ey = (b[1] - a[1]) / scale;
    const double length = std::hypot(ex, ey);
    const double p = 0.5 * length;
    const double nx = -ey / length,
                 ny = ex / length;  // the inward normal: the triangle is on e's left
    // The circumcenter relative to M: on the bisector at signed distance q (towards the apex);
    // the circle through a, b, c has q = (|c - m|^2 - p^2) / (2 (c - m) . n).
    const double wx = (c[0] - mx) / scale, wy = (c[1] - my) / scale;
    const double height = wx * nx + wy * ny;  // > 0: the apex is on the left
    const double q = (wx * wx + wy * wy - p * p) / (2 * height);
    const double radius = std::hypot(p, q);
    const double f = size_at(mx, my) / kSqrt3 / scale;  // the ideal circumradius at M
    double d;
    if (q >= p) {
        // Rebay: rho between p (the diametral circle of the edge) and (p^2 + q^2) / (2q) (the
        // circle through a, b and the circumcenter, whose far point is the circumcenter).
        const double rho = std::min(std::max(f, p), (p * p + q * q) / (2 * q));
        d = std::min(rho + std::sqrt(std::max(0.0, rho * rho - p * p)), q);
    } else {
        // The circumcenter lies closer to the edge than p (or beyond it): the edge itself is
        // too long for the size. Rebay's ideal distance, kept inside the circumcircle (whose
        // far point on the bisector is at q + R) by half.
        const double rho = std::max(f, p);
        d = std::min(rho + std::sqrt(std::max(0.0, rho * rho - p * p)), 0.5 * (q + radius));
    }
    return {mx + d * scale * nx, my + d * scale * ny};
}

bool Frontal::too_close(TriIdx t, double x, double y, double limit) {
    // Distances in units of the power of two at the limit (no overflow or underflow of the
    // squares: the same decision at every scale).
    const int shift = limit > 0 && std::isfinite(limit) ? -std::ilogb(limit) : 0;
    const double scaled_limit = std::ldexp(limit, shift);
    const double limit2 = scaled_limit * scaled_limit;
    const double xq[2] = {x, y};
    const std::uint32_t stamp = next_stamp();
    stack_.assign(1, t);
    seen_[t] = stamp;
    bool close = false;
    while (!stack_.empty() && !close) {
        const TriIdx u = stack_.back();
        stack_.pop_back();
        for (unsigned k = 0; k < 3; ++k) {
            const double* v = point(mesh_.tv[3 * u + k]);
            const double dx = std::ldexp(v[0] - x, shift), dy = std::ldexp(v[1] - y, shift);
            if (dx * dx + dy * dy < limit2) close = true;
            const EdgeIdx e = 3 * u + k;
            if (cdt_.segment_of(e) != kNone) continue;
            const TriIdx n = tri::triangle_of(mesh_.twin[e]);
            if (seen_[n] == stamp || !cdt_.in_domain(n)) continue;
            seen_[n] = stamp;
            ++counters_.closeness_incircle;
            if (predicates::incircle(point(mesh_.tv[3 * n]), point(mesh_.tv[3 * n + 1]),
                                     point(mesh_.tv[3 * n + 2]), xq) != Sign::Negative) {
                stack_.push_back(n);
            }
        }
    }
    return close;
}

void Frontal::step(TriIdx t) {
    const EdgeIdx e = front_edge(t);
    if (e == kNone) {
        // Its accepted neighbours went away since it was queued: it waits again.
        status_[t] = Status::Waiting;
        return;
    }
    if (counters_.points_inserted >= budget_) {
        throw GeometryError("frontal Delaunay: more than " + std::to_string(budget_) +
                            " Steiner points; stopped (raise --max-steiner, or coarsen the size)");
    }
    const auto x = place(e);
    if (!std::isfinite(x[0]) || !std::isfinite(x[1])) {
        ++counters_.rejected_no_conflict;
        accept(t);
        return;
    }
    if (options_.min_distance > 0 &&
        too_close(t, x[0], x[1], options_.min_distance * size_at(x[0], x[1]))) {
        ++counters_.rejected_too_close;
        accept(t);
        return;
    }
    switch (cdt_.insert_in_cavity(t, x[0], x[1])) {
        case tri::CavityInsertion::Inserted:
            ++counters_.points_inserted;
            progress_.tick();
            process_touched();
            return;
        case tri::CavityInsertion::Encroaches:
            // Beyond a piece of its cavity (outside the domain, or inside a hole) or in the
            // closed diametral circle of one.
            if (in_domain(boundary_, x[0], x[1])) {
                ++counters_.rejected_encroach;
            } else {
                ++counters_.rejected_outside;
            }
            break;
        case tri::CavityInsertion::Duplicate:
            ++counters_.rejected_too_close;
            break;
        case tri::CavityInsertion::NotInConflict:
        case tri::CavityInsertion::Outside:
            ++counters_.rejected_no_conflict;
            break;
    }
    accept(t);
}

FrontalDelaunayResult2 Frontal::run() {
    if (cdt_.collinear())
        throw InputError(
            "frontal Delaunay: the points are collinear; the segments enclose no region");
    set_budget();
    grow_slots();
    std::uint64_t inside = 0;
    for (TriIdx t = 0; t < mesh_.triangle_slots(); ++t) {
        if (!cdt_.in_domain(t)) continue;
        ++inside;
        classify(t);
    }
    if (inside == 0) {
        throw InputError(
            "frontal Delaunay: the segments enclose no region (every triangle is outside the "
            "domain)");
    }
    for (TriIdx t = 0; t < mesh_.triangle_slots(); ++t) {
        if (cdt_.in_domain(t) && status_[t] != Status::Accepted && on_front(t)) activate(t);
    }
    cdt_.clear_touched();
    while (!heap_.empty()) {
        const ActiveEntry top = heap_.top();
        heap_.pop();
        if (top.version != version_[top.t] || status_[top.t] != Status::Active) {
            ++counters_.stale_pops;
            continue;
        }
        ++counters_.active_pops;
        step(top.t);
    }
    // Every domain triangle is accepted: a waiting one would have a waiting neighbour across
    // every edge, and the domain's triangles are connected to its boundary pieces.
    for (TriIdx t = 0; t < mesh_.triangle_slots(); ++t) {
        if (!cdt_.in_domain(t)) continue;
        if (status_[t] != Status::Accepted) {
            throw InternalError("frontal Delaunay: triangle slot " + std::to_string(t) +
                                " left unaccepted with an empty front");
        }
    }
    counters_.cavity_triangles = cdt_.counters().cavity_triangles;
    for (TriIdx t = 0; t < mesh_.triangle_slots(); ++t) {
        if (!cdt_.in_domain(t)) continue;
        if (key_[t] <= options_.acceptance) {
            ++counters_.accepted_triangles;
        } else {
            ++counters_.forced_triangles;
        }
    }
    FrontalDelaunayResult2 result;
    tri::Cdt2Result mesh = std::move(cdt_).take_result();
    counters_.orient_calls = boundary_.cdt.counters.orient_calls + mesh.counters.orient_calls;
    counters_.incircle_calls = boundary_.cdt.counters.incircle_calls + mesh.counters.incircle_calls;
    restore_input_terms(boundary_, mesh);
    mesh.counters.orient_calls = counters_.orient_calls;
    mesh.counters.incircle_calls = counters_.incircle_calls;
    result.mesh = std::move(mesh);
    result.counters = counters_;
    return result;
}

}  // namespace

FrontalDelaunayResult2 frontal_delaunay_2d(const tri::Pslg& pslg,
                                           const FrontalDelaunayOptions2& options) {
    return frontal_delaunay_2d(MeshDomain2(pslg, options.cdt), options);
}

FrontalDelaunayResult2 frontal_delaunay_2d(const MeshDomain2& domain,
                                           const FrontalDelaunayOptions2& options) {
    if (!options.size.bounded()) {
        throw InputError(
            "frontal Delaunay needs a size function (the front advances by it); none was given");
    }
    if (!(options.acceptance >= 1 && options.acceptance <= 4)) {
        throw InputError("frontal Delaunay: acceptance " + std::to_string(options.acceptance) +
                         " is outside [1, 4] (circumradius over s / sqrt 3)");
    }
    if (!(options.min_distance >= 0 && options.min_distance < 1)) {
        throw InputError("frontal Delaunay: min_distance " + std::to_string(options.min_distance) +
                         " is outside [0, 1) (times the size)");
    }
    const tri::Cdt2Options& cdt = domain.domain_options();
    // Regional maximum areas are sizes here: the equilateral edge of the area, where smaller
    // than the size (region_areas_2d.hpp), for the boundary's split as for the front.
    FrontalDelaunayOptions2 sized = options;
    sized.size = size_with_region_areas(domain, options.size);
    DomainBoundary2 boundary =
        discretize_domain_boundary(domain, sized.size,
                                   options.max_boundary_points != 0 ? options.max_boundary_points
                                                                    : options.max_steiner_points);
    const std::uint64_t boundary_points = boundary.xy.size() / 2 - boundary.cdt.mesh.xy.size() / 2;
    // The rebuilt PSLG's warnings (none but merged duplicates, already reported) are dropped.
    Frontal frontal(domain.pslg(), sized, std::move(boundary), cdt);
    FrontalDelaunayResult2 result = frontal.run();
    result.counters.boundary_points = boundary_points;
    return result;
}

std::vector<std::pair<std::string, std::uint64_t>> counter_list(const FrontalDelaunayCounters2& c) {
    return counters_by_name(kFrontalDelaunayCounterNames, c);
}

}  // namespace exactmesh::generators
