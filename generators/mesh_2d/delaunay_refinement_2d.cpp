// SPDX-License-Identifier: MIT
// Delaunay refinement (see delaunay_refinement_2d.hpp).
//
// State beside the ConstrainedTriangulation2: a bucketed queue of bad triangles (key, slot,
// version), where a slot's version grows whenever an edit writes the slot, so stale entries are
// recognised in O(1); a bucketed queue of encroached pieces to split (by their two vertices, so
// a piece already split is simply not found; keyed by the triangle of the encroaching vertex)
// and a stack of pieces rejected circumcenters encroach; per vertex, for Steiner points on
// segments, the segment and, for shell splits, the apex and the shell's exponent (the rule of
// Miller, Pav and Walkington). Loop: split the forced pieces, then the worst queued piece unless
// a bad triangle is worse (each split queues the pieces its new triangles encroach and its bad
// triangles), else take the worst bad triangle: insert its circumcenter, or, when the
// circumcenter encroaches pieces, split them (forced) and queue the triangle again. Triangles good
// for theta_min but below the polish angle are kept aside (candidates); when the loop ends, they
// are queued with the polish angle as the bound and the loop runs again with a Steiner point
// limit; if it is reached, the queue keeps only what is bad for theta_min and the loop ends the
// proven way. Sizes at edge midpoints (unless uniform) are kept per half-edge (forgotten when the
// slot is rewritten): a new triangle evaluates the size of its new edges only.
#include "generators/mesh_2d/delaunay_refinement_2d.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <thread>
#include <vector>

#include "base/errors.hpp"
#include "base/flat_tables.hpp"
#include "base/huge_pages.hpp"
#include "base/number_text.hpp"
#include "base/parallel_runner.hpp"
#include "base/progress.hpp"
#include "generators/boundary/narrow_wedges_2d.hpp"
#include "generators/boundary/region_areas_2d.hpp"
#include "predicates/angle_comparisons_2d.hpp"
#include "predicates/constructions.hpp"
#include "predicates/power_of_two.hpp"
#include "predicates/triangle_area.hpp"
#include "triangulation/constrained/constrained_triangulation_2d.hpp"
#include "triangulation/delaunay/parallel_rounds.hpp"  // resolve_thread_count

namespace exactmesh::generators {

namespace {

namespace tri = exactmesh::triangulation;
using predicates::Sign;
using tri::EdgeIdx;
using tri::kNone;
using tri::TriIdx;
using tri::VertIdx;

/// Scale invariance (a PSLG scaled by 2^k, |k| <= 600, is refined the same way, scaled): every
/// squared length, area and quality measure is taken on edge vectors first scaled exactly by a
/// power of two, to a largest component in [1, 2). No product then overflows or underflows, and
/// the scaled vectors, so the keys and decisions, are the same bit for bit at every scale.
struct ScaledTriangle {
    double edge[3][2];  ///< edge k: p[k+1] - p[k], scaled
    double length2[3];  ///< their squared lengths
    double cross;       ///< (p1 - p0) x (p2 - p0), scaled twice (twice the area)
    int shift;          ///< the scaling: 2^shift
};

// Inlined into its callers: evaluate runs it for every new triangle, and returning the struct
// through memory cost a fifth of it.
[[gnu::always_inline]] inline ScaledTriangle scaled_triangle(const double* const p[3]) {
    ScaledTriangle r;
    double largest = 0;
    for (int k = 0; k < 3; ++k) {
        r.edge[k][0] = p[(k + 1) % 3][0] - p[k][0];
        r.edge[k][1] = p[(k + 1) % 3][1] - p[k][1];
        largest = std::max({largest, std::fabs(r.edge[k][0]), std::fabs(r.edge[k][1])});
    }
    r.shift = predicates::unit_shift(largest);
    const predicates::PowerOfTwo unit(r.shift);
    for (int k = 0; k < 3; ++k) {
        r.edge[k][0] = unit(r.edge[k][0]);
        r.edge[k][1] = unit(r.edge[k][1]);
        r.length2[k] = r.edge[k][0] * r.edge[k][0] + r.edge[k][1] * r.edge[k][1];
    }
    // p2 - p0 = -edge[2].
    r.cross = r.edge[0][1] * r.edge[2][0] - r.edge[0][0] * r.edge[2][1];
    return r;
}

/// The angle at o between o -> p and o -> q (radians, [0, pi]), on scaled vectors.
double corner_radians(const double* o, const double* p, const double* q) {
    double ux = p[0] - o[0], uy = p[1] - o[1], wx = q[0] - o[0], wy = q[1] - o[1];
    const double largest = std::max({std::fabs(ux), std::fabs(uy), std::fabs(wx), std::fabs(wy)});
    const predicates::PowerOfTwo unit(predicates::unit_shift(largest));
    ux = unit(ux), uy = unit(uy), wx = unit(wx), wy = unit(wy);
    return std::atan2(std::fabs(ux * wy - uy * wx), ux * wx + uy * wy);
}

struct BadTriangle {
    float key;  // larger is worse
    TriIdx t;
    std::uint32_t version : 31;
    std::uint32_t too_big : 1;  // an edge longer than the size (else only skinny)
};

/// Buckets of one class of BucketQueue (too big, or only skinny): a sixteenth of a binade each.
constexpr std::size_t kBucketsPerClass = 1024;
/// The keys a round of RefinementOrder::Rounds takes: the worst bucket and this many below it
/// (1: keys within 9% of the worst; 16, a factor of 2, gave the small domains more points and
/// the 10^6-triangle square with holes larger, slower rounds).
constexpr std::size_t kRoundKeyBand = 1;
/// A round of fewer bad triangles is a worst-first step (its first alone): without it, rounds
/// of a few triangles inserted 10-16% more points on small domains refined to 30 degrees.
constexpr std::size_t kSmallestRound = 64;
/// How many probes ahead a round's probing asks for the triangles it will read (probe_round).
constexpr std::size_t kProbeAhead = 8;

/// Encroached pieces wait beside the bad triangles, by the key of the triangle whose apex
/// encroaches them (below).
struct EncroachedPiece {
    float key;
    VertIdx a, b;
    std::uint32_t too_big;
};

/// Bad triangles (or encroached pieces) by priority, worst first: too big ones before skinny
/// ones (as CGAL's mesher), each by its key, in buckets of a sixteenth of a binade (keys within
/// 4.4% of each other share a bucket), last in first out within a bucket (the triangles an
/// insertion just made are neighbours: their memory is warm). O(1) per push and pop, against
/// O(log n) cache-missing steps of a binary heap over all bad triangles.
template <class Entry>
class BucketQueue {
  public:
    void push(const Entry& b) {
        const std::size_t k = bucket(b);
        buckets_[k].push_back(b);
        top_ = std::max(top_, k);
        ++size_;
    }
    bool empty() const { return size_ == 0; }
    void clear() {
        for (auto& b : buckets_) b.clear();
        top_ = 0;
        size_ = 0;
    }
    /// The bucket of the worst entry (larger is worse); the queue must not be empty.
    std::size_t top_bucket() {
        while (buckets_[top_].empty()) --top_;
        return top_;
    }
    /// The entry `depth` places under the top of the worst bucket pop() takes from (what it
    /// pops `depth` calls later if nothing is pushed meanwhile), or nullptr.
    const Entry* under_top(std::size_t depth) const {
        const std::vector<Entry>& bucket = buckets_[top_];
        return depth < bucket.size() ? &bucket[bucket.size() - 1 - depth] : nullptr;
    }
    /// The entries (stale ones included) in the buckets from `lowest` to the worst.
    std::size_t entries_from(std::size_t lowest) const {
        std::size_t n = 0;
        for (std::size_t k = lowest; k <= top_; ++k) n += buckets_[k].size();
        return n;
    }
    Entry pop() {
        while (buckets_[top_].empty()) --top_;
        const Entry b = buckets_[top_].back();
        buckets_[top_].pop_back();
        --size_;
        return b;
    }

  private:
    std::vector<Entry> buckets_[2 * kBucketsPerClass];  // keys 1 .. 2^64, 2^(1/16) steps
    std::size_t top_ = 0;
    std::size_t size_ = 0;
    static std::size_t bucket(const Entry& b) {
        // The key's exponent and its four leading fraction bits: 16 buckets per binade,
        // monotone in the key (keys are at least 1, so the float's bits from 1.0 up).
        const float key = std::max(1.0f, b.key);
        std::uint32_t bits = 0;
        std::memcpy(&bits, &key, sizeof bits);
        const std::size_t level = (bits - 0x3F800000u) >> 19;
        return (b.too_big ? kBucketsPerClass : 0) +
               std::min<std::size_t>(kBucketsPerClass - 1, level);
    }
};

struct PieceToSplit {
    VertIdx a, b;
    bool forced;  // a rejected circumcenter encroaches it: split without testing the apexes
};

/// What assess() finds of a domain triangle, before anything is queued: its badness key (bad:
/// above 1), whether an edge is too long, its key as a candidate of the polish (0: none), and
/// which of its constrained edges its apexes encroach.
struct Assessment {
    float key = 0;  // the queue's key (at most 1e30), when bad
    bool bad = false;
    bool too_big = false;
    bool in_domain = false;
    std::uint8_t encroached = 0;  // bit k: half-edge 3t + k
    float polish_key = 0;
    /// Rounds: the triangle's version when its fan's thread assessed it (queue() reads it
    /// here rather than in marks_, a cache miss per triangle on the serial thread)
    std::uint32_t version = 0;
};
static_assert(sizeof(Assessment) == 16, "a round's assessments are read on one thread");

/// Steiner points on segments: which segment, and for shell splits the apex and the shell.
struct SegmentVertex {
    std::uint32_t segment = kNone;
    VertIdx apex = kNone;
    int shell = 0;
};

/// The triangles the conflict zones may hold, in all, per budgeted Steiner point (and per
/// initial triangle slot): about ten times what the sample domains need.
constexpr std::uint64_t kCavityWorkPerPoint = 64;

class Refiner {
  public:
    Refiner(const tri::Pslg& pslg, const RefinementOptions2& options)
        : options_(options),
          regions_(pslg.regions),
          region_areas_(has_region_areas(pslg.regions)),
          numbered_regions_(region_areas_ ? numbered_regions(pslg.regions) : std::vector<double>{}),
          cdt_(region_areas_ ? tri::Pslg{pslg.xy, pslg.segments, pslg.holes, numbered_regions_}
                             : pslg,
               options.cdt),
          mesh_(cdt_.mesh()),
          segment_count_(static_cast<std::uint32_t>(pslg.segments.size() / 2)),
          threads_(options.order == RefinementOrder::Rounds
                       ? tri::resolve_thread_count(options.threads)
                       : 1u) {
        // The chunks (and so the mesh) follow threads_; the arena has at most as many threads as
        // the machine lends (more made oneTBB warn on stderr, and only shared the cores).
        if (threads_ > 1) {
            arena_ = std::make_unique<tbb::task_arena>(
                std::min(static_cast<int>(threads_), tbb::this_task_arena::max_concurrency()));
        }
        scratch_.resize(threads_);
    }

    RefinementResult2 run();

  private:
    const RefinementOptions2& options_;
    // Regional maximum areas (region_areas_2d.hpp): when a region has one, the triangulation's
    // attributes are region numbers (numbered_regions), mapped back to the input's attributes in
    // the result.
    std::span<const double> regions_;
    bool region_areas_ = false;
    std::vector<double> numbered_regions_;
    tri::ConstrainedTriangulation2 cdt_;
    const tri::TriMesh2& mesh_;    // the triangulation's, valid across edits
    std::uint32_t segment_count_;  // input segments (cdt_.segment_ends numbers them)
    RefinementCounters2 counters_;
    BucketQueue<BadTriangle> bad_;
    /// Pieces a vertex encroaches (split when no bad triangle is worse than the triangle of the
    /// encroaching apex: see refine), and pieces a rejected circumcenter encroaches (forced_:
    /// split at once).
    BucketQueue<EncroachedPiece> pieces_;
    std::vector<PieceToSplit> forced_;
    /// Tests the constrained edges of domain triangle t for encroachment by their apexes
    /// (Assessment::encroached), counted in `tally`.
    inline void find_encroached_pieces(TriIdx t, Assessment& a, RefinementCounters2& tally) const;
    /// Queues what `a` found of triangle t (whose version is `version`): the bad triangle, the
    /// polish's candidate, the encroached pieces (by t's key).
    void queue(TriIdx t, const Assessment& a, std::uint32_t version);
    /// Per triangle slot, side by side (one cache line where two arrays took two): its version
    /// (a queue entry with an older one is stale) and its batch stamp (process_touched, a round).
    struct SlotMarks {
        std::uint32_t version = 0;
        std::uint32_t seen = 0;
    };
    std::vector<SlotMarks> marks_;
    bool cache_sizes_ = false;       // a size function dearer than a constant: edge_size_ is kept
    std::vector<double> edge_size_;  // per half-edge: the size at its midpoint; 0: unknown
    std::uint32_t batch_ = 0;
    std::vector<SegmentVertex> on_segment_;  // per vertex
    std::vector<std::uint32_t> degree_;      // per initial vertex: constrained edges at it
    VertIdx initial_vertices_ = 0;
    double sine2_bound_ = 0;  // sin^2(min_angle); 0: no angle criterion
    std::uint64_t budget_ = 0;
    /// Triangles the conflict zones may hold in all, inserted or rejected (kCavityWorkPerPoint
    /// per budgeted point and per triangle slot of the initial triangulation; spend_budget).
    std::uint64_t cavity_work_budget_ = 0;
    /// Steiner points inserted, for options.cdt.progress (total: the expected count, below).
    ProgressCounter progress_;

    double asked_sine2_ = 0;  // sin^2(min_angle), also while polishing
    /// Refines until no triangle is bad (true) or `limit` Steiner points exist (false).
    bool refine(std::uint64_t limit);
    /// The polish: refinement to the polish angle within its budget, then (if that ran out)
    /// back to min_angle.
    void polish();
    /// Every domain triangle evaluated again (the bound changed); stale entries dropped.
    void requeue_for_asked_bound();
    void next_batch() {
        if (++batch_ == 0) {
            for (SlotMarks& m : marks_) m.seen = 0;
            batch_ = 1;
        }
    }
    std::vector<BadTriangle> polish_;  // candidates of the polish (with stale entries)
    double polish_sine2_ = 0;          // sin^2(polish angle); 0: no polish
    bool below_asked_bound(TriIdx t) const;
    void check_domain_and_budget();
    void initial_queue();
    /// Triangles written by the last edit: new versions; bad ones and encroached pieces queued.
    void process_touched();
    /// Badness of domain triangle t (reading only, but for the per-half-edge size cache;
    /// counted in `tally`): what evaluate queues. Safe on several threads at once on distinct
    /// triangles when no size is cached (a uniform size or none: parallel_assessment).
    Assessment assess(TriIdx t, RefinementCounters2& tally);
    /// assess and queue (without the encroached pieces).
    void evaluate(TriIdx t) { queue(t, assess(t, counters_), marks_[t].version); }
    /// assess, find_encroached_pieces and queue.
    void evaluate_with_pieces(TriIdx t) {
        Assessment a = assess(t, counters_);
        find_encroached_pieces(t, a, counters_);
        queue(t, a, marks_[t].version);
    }
    /// the apex of e's triangle encroaches e (counted in `tally`)
    bool encroached_from(EdgeIdx e, RefinementCounters2& tally) const;
    struct SplitPoint {
        double x = 0, y = 0;
        VertIdx apex = kNone;  // a concentric-shell split about this vertex
        int shell = 0;         // at distance 2^shell
    };
    /// Where piece e splits: its midpoint, or a concentric shell about its one corner end.
    SplitPoint split_point(EdgeIdx e) const;
    void split_piece(const PieceToSplit& piece);
    bool leave_at_small_angle(EdgeIdx e, double shortest_edge) const;
    std::vector<double> small_apex_angle_;  // per initial vertex: the smallest angle between its
                                            // pieces (radians) when below 60 degrees, else 0
    bool small_angle_rule(VertIdx u, VertIdx v, VertIdx w) const;
    void find_small_input_angles();
    /// Narrow wedges (narrow_wedges_2d: two segments from one end vertex less than a degree
    /// apart): a vertex on one does not encroach the other's pieces, and a skinny triangle
    /// whose shortest edge joins the two is left.
    std::vector<std::uint64_t> narrow_pairs_;
    std::vector<std::vector<std::uint32_t>> segments_at_;  // per initial vertex, with narrow_pairs_
    void find_narrow_wedges();
    bool narrow_pair(std::uint32_t a, std::uint32_t b) const;
    /// Whether vertex w lies on a segment (a Steiner point on it, or an end of it) that makes a
    /// narrow wedge with `segment`.
    bool in_narrow_wedge_with(VertIdx w, std::uint32_t segment) const;
    /// Whether edge u - v joins the two segments of a narrow wedge, neither end being their
    /// common vertex.
    bool joins_narrow_wedge(VertIdx u, VertIdx v) const;
    std::span<const std::uint32_t> segments_of(VertIdx w) const;  // with narrow_pairs_
    void spend_budget();
    const double* point(VertIdx v) const { return mesh_.point(v); }

    // ---- RefinementOrder::Rounds ------------------------------------------------------------
    unsigned threads_ = 1;
    std::unique_ptr<tbb::task_arena> arena_;  // when threads_ > 1
    PartitionRunner runner_;
    /// Per thread: its probes' scratch and the circumcentres it computed on the exact path.
    struct ProbeScratch {
        tri::CavityProbeScratch cavity;
        std::uint64_t exact_circumcenters = 0;
    };
    std::vector<ProbeScratch> scratch_;
    std::vector<BadTriangle> round_;        // the round's bad triangles, in the order taken
    std::vector<tri::CavityProbe> probes_;  // their probes (probes_[i] for round_[i])
    std::vector<const tri::CavityProbe*> accepted_;  // the probes a round inserts
    std::vector<BadTriangle> waiting_;               // taken out while forming a round, put back
    std::vector<BadTriangle> taken_;                 // every valid entry taken out, in order
    std::vector<Assessment> assessments_;            // a round's new triangles, in touched() order
    std::vector<RefinementCounters2> tallies_;       // per chunk of a round's fans
    struct ChunkError {
        std::exception_ptr error;  // the first assessment that threw in the chunk
        std::size_t position = 0;  // its triangle's place in touched()
    };
    std::vector<ChunkError> errors_;  // per chunk of a round's fans
    FlatFlagSet32 round_vertices_;    // the vertices of a round's bad triangles
    /// The slots in the cavities of the points a round inserts (flag kInCavity), and those
    /// beside them, across their boundaries (kBeside): a set sized for the round, which stays in
    /// cache where per-slot stamps over the whole mesh missed it at every look-up.
    FlatFlagSet32 claimed_;
    static constexpr unsigned kInCavity = 1, kBeside = 2;
    RoundPhaseSeconds2 round_seconds_;
    using Clock = std::chrono::steady_clock;
    /// Adds the time since `start` to `phase` and restarts `start`.
    static void lap(double& phase, Clock::time_point& start) {
        const Clock::time_point now = Clock::now();
        phase += std::chrono::duration<double>(now - start).count();
        start = now;
    }
    /// Whether queue entry b is current: its triangle in the domain and not rewritten since b
    /// was queued (else b is stale).
    bool current(const BadTriangle& b) const {
        return b.version == (marks_[b.t].version & 0x7FFFFFFFu) && cdt_.in_domain(b.t);
    }
    /// Whether a round (or its worst-first step) may take the queue's next entry: one is left,
    /// in the buckets from `lowest` up, and no encroached piece comes before it.
    bool band_goes_on(std::size_t lowest) {
        return !bad_.empty() && bad_.top_bucket() >= lowest &&
               (pieces_.empty() || pieces_.top_bucket() < bad_.top_bucket());
    }
    /// One bad triangle, the worst (RefinementOrder::WorstFirst).
    void insert_worst();
    /// The circumcentre of current bad triangle `top`, inserted (or rejected: after_insertion).
    void insert_circumcenter(const BadTriangle& top);
    /// One round (RefinementOrder::Rounds) within `limit` Steiner points.
    void insert_round(std::uint64_t limit);
    /// The round's circumcentres and their cavities, found on every thread (reading only).
    void probe_round();
    /// Whether the probe's cavity and the triangles beside it are as they were when probed: no
    /// point inserted earlier in the round took one of them into its cavity, nor (for the
    /// cavity's own triangles) had one beside it.
    bool unclaimed(const tri::CavityProbe& probe) const;
    void claim(const tri::CavityProbe& probe);
    /// What refine does with a popped bad triangle once its circumcentre's insertion has been
    /// tried (`top`, the outcome, the cavity's size).
    void after_insertion(const BadTriangle& top, tri::CavityInsertion outcome,
                         std::uint64_t cavity_size);
};

void Refiner::check_domain_and_budget() {
    std::uint64_t inside = 0;
    double lo_x = INFINITY, lo_y = INFINITY, hi_x = -INFINITY, hi_y = -INFINITY;
    double regional = 0;  // the triangles the regions' maximum areas ask for
    for (TriIdx t = 0; t < mesh_.triangle_slots(); ++t) {
        if (!cdt_.in_domain(t)) continue;
        ++inside;
        if (region_areas_) {
            regional += triangles_of_area(point(mesh_.tv[3 * t]), point(mesh_.tv[3 * t + 1]),
                                          point(mesh_.tv[3 * t + 2]),
                                          region_area_of(regions_, cdt_.attribute(t)));
        }
        for (unsigned k = 0; k < 3; ++k) {
            const double* p = point(mesh_.tv[3 * t + k]);
            lo_x = std::min(lo_x, p[0]);
            hi_x = std::max(hi_x, p[0]);
            lo_y = std::min(lo_y, p[1]);
            hi_y = std::max(hi_y, p[1]);
        }
    }
    if (inside == 0) {
        throw InputError(
            "delaunay refinement: the segments enclose no region (every triangle is outside the "
            "domain: is the boundary closed, and is a hole point inside the outer boundary?)");
    }
    // Automatic: at least 10^6, 64 per input feature, and 16 times the element count the size
    // function asks for over the domain's bounding box (equilateral_count_in_box).
    const double estimate =
        std::max(equilateral_count_in_box(options_.size, lo_x, lo_y, hi_x, hi_y), regional);
    const double features =
        static_cast<double>(initial_vertices_) + static_cast<double>(mesh_.triangle_slots());
    // A size asking for more than the automatic budget could hold is refused before any point
    // is inserted (a fuzzed Steiner restart on a size interpolated across a narrow wedge's
    // spared triangles asked for 1.9e14 and ran to 24 GB).
    if (options_.max_steiner_points == 0 && estimate > kAutomaticRefinementTriangles) {
        throw RefinementBudgetError(
            "delaunay refinement: the size asks for about " + format_number(estimate) +
            " triangles over the domain's bounding box, more than the automatic Steiner budget "
            "can hold (" +
            format_number(kAutomaticRefinementTriangles) +
            "); stopped before refining: give a larger size, or a --max-steiner budget to try "
            "anyway");
    }
    budget_ = options_.max_steiner_points != 0
                  ? options_.max_steiner_points
                  : static_cast<std::uint64_t>(
                        std::min(std::max({1e6, 64 * features, 16 * estimate}), 4e9));
    // Saturated: a --max-steiner near 2^64 must not wrap the product into a small bound.
    const std::uint64_t counted = budget_ + static_cast<std::uint64_t>(mesh_.triangle_slots());
    cavity_work_budget_ = counted < budget_ || counted > UINT64_MAX / kCavityWorkPerPoint
                              ? UINT64_MAX
                              : kCavityWorkPerPoint * counted;
    // About as many Steiner points as equilateral triangles (see the reservation below); 0, for
    // no size asked, reads as unknown.
    progress_ =
        ProgressCounter(options_.cdt.progress,
                        estimate > 0 ? static_cast<std::uint64_t>(std::min(estimate, 4e9)) : 0,
                        "Steiner points inserted");
    // Room for the expected mesh: refinement makes about twice the ideal count of equilateral
    // triangles, with half as many vertices as triangles. A hint only, so capped at the budget
    // and at 2^21 vertices (about 200 MB reserved); beyond that the arrays grow as they go.
    const double expected_vertices =
        std::min({1.1 * estimate, static_cast<double>(budget_), 0x1p21}) +
        static_cast<double>(mesh_.vertex_count());
    cdt_.reserve(static_cast<std::uint32_t>(expected_vertices));
    marks_.reserve(static_cast<std::size_t>(2 * expected_vertices));
    if (cache_sizes_) edge_size_.reserve(static_cast<std::size_t>(6 * expected_vertices));
    advise_huge_pages(marks_);
    advise_huge_pages(edge_size_);
    on_segment_.reserve(static_cast<std::size_t>(expected_vertices));
}

void Refiner::find_small_input_angles() {
    // Sectors of the domain about each vertex between two consecutive pieces: from each piece
    // v -> w with a domain triangle on its left, turn counter-clockwise about v through domain
    // triangles, summing their angles at v, up to the next piece. A sector below 60 degrees is a
    // small input angle (measured inside the domain: a sharp notch of a hole is none).
    small_apex_angle_.assign(initial_vertices_, 0.0);
    auto corner_angle = [&](VertIdx o, VertIdx p, VertIdx q) {
        return corner_radians(point(o), point(p), point(q));
    };
    for (EdgeIdx e = 0; e < mesh_.tv.size(); ++e) {
        if (cdt_.segment_of(e) == kNone || !cdt_.in_domain(tri::triangle_of(e))) continue;
        const VertIdx v = mesh_.origin(e);
        double sector = 0;
        EdgeIdx g = e;  // v -> w in a domain triangle
        for (std::size_t turns = 0; turns < mesh_.tv.size(); ++turns) {
            const EdgeIdx back = tri::prev_edge(g);  // x -> v
            sector += corner_angle(v, mesh_.destination(g), mesh_.origin(back));
            if (cdt_.segment_of(back) != kNone || sector >= 3.14159265358979323846 / 3) break;
            g = mesh_.twin[back];  // v -> x in the next triangle counter-clockwise
        }
        if (sector < 3.14159265358979323846 / 3) {
            double& angle = small_apex_angle_[v];
            angle = angle == 0 ? std::max(sector, 1e-300) : std::min(angle, sector);
        }
    }
}

void Refiner::find_narrow_wedges() {
    std::vector<std::array<VertIdx, 2>> ends(segment_count_);
    for (std::uint32_t s = 0; s < segment_count_; ++s) ends[s] = cdt_.segment_ends(s);
    narrow_pairs_ = narrow_wedges_2d(mesh_.xy, ends);
    if (narrow_pairs_.empty()) return;
    segments_at_.assign(initial_vertices_, {});
    for (std::uint32_t s = 0; s < segment_count_; ++s) {
        for (const VertIdx v : ends[s])
            if (v < initial_vertices_) segments_at_[v].push_back(s);
    }
}

bool Refiner::narrow_pair(std::uint32_t a, std::uint32_t b) const {
    return a != kNone && b != kNone && narrow_wedge_pair(narrow_pairs_, a, b);
}

std::span<const std::uint32_t> Refiner::segments_of(VertIdx w) const {
    if (w < initial_vertices_) return segments_at_[w];
    if (w < on_segment_.size() && on_segment_[w].segment != kNone)
        return {&on_segment_[w].segment, 1};
    return {};
}

bool Refiner::in_narrow_wedge_with(VertIdx w, std::uint32_t segment) const {
    if (narrow_pairs_.empty()) return false;
    for (const std::uint32_t s : segments_of(w))
        if (narrow_pair(s, segment)) return true;
    return false;
}

bool Refiner::joins_narrow_wedge(VertIdx u, VertIdx v) const {
    if (narrow_pairs_.empty()) return false;
    const auto ends_at = [&](std::uint32_t segment, VertIdx x) {
        const auto ends = cdt_.segment_ends(segment);
        return ends[0] == x || ends[1] == x;
    };
    for (const std::uint32_t a : segments_of(u)) {
        for (const std::uint32_t b : segments_of(v)) {
            if (narrow_pair(a, b) && !ends_at(b, u) && !ends_at(a, v)) return true;
        }
    }
    return false;
}

bool Refiner::small_angle_rule(VertIdx u, VertIdx v, VertIdx w) const {
    // Both ends of the shortest edge u - v on the same concentric shell about the same apex,
    // on different segments, and the third vertex w that apex: the triangle's smallest angle is
    // the input angle itself. A skinny triangle spanning the angle further out (w on a shell
    // farther away) is split: the midpoints between shells make the angle's wedge into
    // triangles no worse than the input angle, and never approach the apex (its own pieces are
    // split on shells only, and rejected circumcenters do not split them: leave_at_small_angle).
    // In a narrow wedge: the shortest edge joins its two segments (neither end their common
    // vertex), so the triangle spans the wedge and is as skinny as the wedge is narrow.
    if (joins_narrow_wedge(u, v)) return true;
    const SegmentVertex* su = u < on_segment_.size() ? &on_segment_[u] : nullptr;
    const SegmentVertex* sv = v < on_segment_.size() ? &on_segment_[v] : nullptr;
    if (su == nullptr || sv == nullptr || su->apex == kNone) return false;
    return su->apex == sv->apex && su->shell == sv->shell && su->segment != sv->segment &&
           w == su->apex;
}

Assessment Refiner::assess(TriIdx t, RefinementCounters2& tally) {
    const VertIdx v[3] = {mesh_.tv[3 * t], mesh_.tv[3 * t + 1], mesh_.tv[3 * t + 2]};
    const double* p[3] = {point(v[0]), point(v[1]), point(v[2])};
    const ScaledTriangle scaled = scaled_triangle(p);
    const double* length2 = scaled.length2;  // edge k: v[k] - v[k+1], scaled
    double size_key = 0;
    if (options_.size.is_uniform()) {
        // One size for all three edges: the largest key is the longest edge's (division by one
        // positive number is monotone, so these are the bits the loop below would give).
        const double s = options_.size(p[0][0], p[0][1]);
        if (!(s > 0)) {
            const double where[2] = {0.5 * (p[0][0] + p[1][0]), 0.5 * (p[0][1] + p[1][1])};
            throw InputError("size function: not a number > 0 at " + format_point(where) + " (" +
                             options_.size.describe() + ")");
        }
        const double scaled_size = predicates::PowerOfTwo(scaled.shift)(s);
        size_key = std::max({length2[0], length2[1], length2[2]}) / (scaled_size * scaled_size);
    } else if (options_.size.bounded()) {
        for (int k = 0; k < 3; ++k) {
            // The size at the edge's midpoint, kept per half-edge: an edge keeps it while its
            // triangle on either side is not rewritten (a cavity's boundary edges, and each new
            // spoke for its second triangle, need no new evaluation).
            const EdgeIdx e = 3 * t + static_cast<EdgeIdx>(k);
            double s = 0;
            if (cache_sizes_) {
                s = edge_size_[e];
                if (!(s > 0)) {
                    const EdgeIdx f = mesh_.twin[e];
                    s = f < edge_size_.size() ? edge_size_[f] : 0.0;
                }
            }
            if (!(s > 0)) {
                const double mx = 0.5 * (p[k][0] + p[(k + 1) % 3][0]),
                             my = 0.5 * (p[k][1] + p[(k + 1) % 3][1]);
                s = options_.size(mx, my);
                if (!(s > 0)) {
                    const double where[2] = {mx, my};
                    throw InputError("size function: not a number > 0 at " + format_point(where) +
                                     " (" + options_.size.describe() + ")");
                }
            }
            if (cache_sizes_) edge_size_[e] = s;
            const double scaled_size =
                predicates::PowerOfTwo(scaled.shift)(s);  // in the scaled units
            size_key = std::max(size_key, length2[k] / (scaled_size * scaled_size));
        }
    }
    if (region_areas_) {
        // Regional maximum area A (Triangle's -a): too big when its area exceeds A, decided
        // exactly (triangle_area_sign); the key is area / A in the scaled frame, comparable with
        // size_key's (length / size)^2, at least just above 1 once the exact test says bad.
        const double area = region_area_of(regions_, cdt_.attribute(t));
        if (area > 0 && predicates::triangle_area_sign(p[0], p[1], p[2], area) == Sign::Positive) {
            const double ratio =
                0.5 * scaled.cross / predicates::PowerOfTwo(2 * scaled.shift)(area);
            size_key = std::max({size_key, ratio, 1 + 1e-9});
        }
    }
    double key = size_key;
    Assessment a;
    a.in_domain = true;
    if (sine2_bound_ > 0) {
        // sin^2 of the smallest angle: (2 area)^2 over the product of the two longer edges'
        // squared lengths (the smallest angle lies between them).
        int shortest = 0;
        for (int k = 1; k < 3; ++k) {
            if (length2[k] < length2[shortest]) shortest = k;
        }
        static constexpr int kNext[3] = {1, 2, 0}, kPrev[3] = {2, 0, 1};
        const int next = kNext[shortest], prev = kPrev[shortest];
        const double cross = scaled.cross;
        const double product = length2[next] * length2[prev];
        const double sine2 = cross * cross / product;
        if (sine2 < sine2_bound_ || sine2 < polish_sine2_) {
            if (small_angle_rule(v[shortest], v[next], v[prev])) {
                if (sine2 < asked_sine2_) ++tally.small_angle_skips;
            } else if (sine2 < sine2_bound_) {
                key = std::max(key, sine2 > 0 ? sine2_bound_ / sine2 : INFINITY);
                if (key <= 1) key = 1 + 1e-9;  // bad, even if only just
            } else if (key <= 1) {
                // Good, but below the polish bound: a candidate of the polish.
                a.polish_key = static_cast<float>(polish_sine2_ / sine2);
            }
        }
    }
    a.key = static_cast<float>(std::min(key, 1e30));
    a.bad = key > 1;
    a.too_big = size_key > 1;
    return a;
}

void Refiner::queue(TriIdx t, const Assessment& a, std::uint32_t version) {
    if (a.polish_key > 0) polish_.push_back({a.polish_key, t, version & 0x7FFFFFFFu, 0u});
    if (a.bad) {
        bad_.push({a.key, t, version & 0x7FFFFFFFu, a.too_big ? 1u : 0u});
        ++counters_.bad_triangles;
    }
    for (unsigned k = 0; k < 3; ++k) {
        if ((a.encroached >> k & 1u) == 0) continue;
        const EdgeIdx e = 3 * t + k;
        pieces_.push({a.key, mesh_.origin(e), mesh_.destination(e), a.too_big ? 1u : 0u});
    }
}

void Refiner::find_encroached_pieces(TriIdx t, Assessment& a, RefinementCounters2& tally) const {
    // Most triangles have no constrained edge: one test for the three.
    const EdgeIdx first = 3 * t;
    if (cdt_.segment_of(first) == kNone && cdt_.segment_of(first + 1) == kNone &&
        cdt_.segment_of(first + 2) == kNone) {
        return;
    }
    for (unsigned k = 0; k < 3; ++k) {
        const EdgeIdx e = 3 * t + k;
        if (cdt_.segment_of(e) != kNone && encroached_from(e, tally))
            a.encroached |= static_cast<std::uint8_t>(1u << k);
    }
}

bool Refiner::encroached_from(EdgeIdx e, RefinementCounters2& tally) const {
    // e lies in a domain triangle; its apex encroaches e when it lies in the closed diametral
    // circle of e (a right or obtuse angle).
    ++tally.encroachment_tests;
    const VertIdx a = mesh_.origin(e), b = mesh_.destination(e), w = mesh_.tv[tri::prev_edge(e)];
    if (predicates::corner_dot_sign(point(w), point(a), point(b)) == Sign::Positive) return false;
    // A vertex across a narrow wedge does not encroach (find_narrow_wedges): splitting there
    // would go on down the wedge until pieces are as short as it is wide.
    if (!narrow_pairs_.empty() && in_narrow_wedge_with(w, cdt_.segment_of(e))) {
        const auto ends = cdt_.segment_ends(cdt_.segment_of(e));
        if (w != ends[0] && w != ends[1]) {
            ++tally.narrow_wedge_skips;
            return false;
        }
    }
    return true;
}

void Refiner::process_touched() {
    next_batch();
    const std::uint32_t slots = mesh_.triangle_slots();
    if (marks_.size() < slots) marks_.resize(slots);
    if (cache_sizes_) {
        if (edge_size_.size() < 3 * std::size_t{slots}) {
            edge_size_.resize(3 * std::size_t{slots}, 0.0);
        }
        // First every rewritten slot forgets its edges' sizes, then the triangles are evaluated
        // (a new triangle may take the size its new neighbour has just found).
        for (const TriIdx t : cdt_.touched()) {
            if (marks_[t].seen == batch_) continue;
            marks_[t].seen = batch_;
            ++marks_[t].version;
            edge_size_[3 * t] = edge_size_[3 * t + 1] = edge_size_[3 * t + 2] = 0.0;
        }
        next_batch();
    }
    // The new slots' stamps and versions are cold (a cavity's slots are anywhere in the arrays):
    // asked for all at once, their cache misses overlap instead of stalling one triangle each.
    for (const TriIdx t : cdt_.touched()) __builtin_prefetch(&marks_[t], 1);
    for (const TriIdx t : cdt_.touched()) {
        if (marks_[t].seen == batch_) continue;
        marks_[t].seen = batch_;
        if (!cache_sizes_) ++marks_[t].version;
        if (!cdt_.in_domain(t)) continue;
        evaluate_with_pieces(t);
    }
    cdt_.clear_touched();
}

void Refiner::initial_queue() {
    const std::uint32_t slots = mesh_.triangle_slots();
    marks_.assign(slots, SlotMarks{});
    if (cache_sizes_) edge_size_.assign(3 * std::size_t{slots}, 0.0);
    for (TriIdx t = 0; t < slots; ++t) {
        if (!cdt_.in_domain(t)) continue;
        evaluate_with_pieces(t);
    }
    cdt_.clear_touched();
}

void Refiner::spend_budget() {
    // A healthy refinement's conflict zones hold about 4 to 8 triangles per point. Where
    // segments meet at tiny angles (five segments 1e-1 to 1e-10 radians apart,
    // tests/data/hostile_2d/fan_five_segments_refinement_slow.poly), the circumcentres of the
    // slivers spanning a wedge lie far along it: their conflict zones grow with the point count
    // and are rejected at a segment, and the run took 447 s to reach the point budget. The zones'
    // total size is bounded as the point count is.
    const tri::ConstrainedTriangulation2Counters& edits = cdt_.counters();
    const std::uint64_t work = edits.cavity_triangles + edits.rejected_cavity_triangles;
    if (work > cavity_work_budget_) {
        throw RefinementBudgetError(
            "delaunay refinement: the conflict zones held more than " +
            std::to_string(cavity_work_budget_) + " triangles (" +
            std::to_string(kCavityWorkPerPoint) + " per budgeted Steiner point) after " +
            std::to_string(counters_.steiner_points()) +
            " Steiner points; stopped: segments meeting at tiny angles (a fan of nearly parallel "
            "segments) put the circumcentres of the slivers across their wedges far along them; "
            "resolving a wedge takes about 1 / angle points");
    }
    if (counters_.steiner_points() >= budget_) {
        char angle[32];
        std::snprintf(angle, sizeof angle, "%g", options_.min_angle);
        // Two causes look alike here: gaps or strips far narrower than the domain (nested
        // squares 1e-5 apart need millions of points at any angle), and an angle the input's
        // small angles make unreachable; name both, the budget first.
        throw RefinementBudgetError(
            "delaunay refinement: more than " + std::to_string(budget_) +
            " Steiner points; stopped (" +
            (options_.max_steiner_points != 0 ? "the --max-steiner budget"
                                              : "the automatic budget") +
            ": raise --max-steiner if the domain has gaps or strips far narrower than its "
            "extent, which need that many points; or, termination being proven up to 20.7 "
            "degrees away from input angles below 60 degrees, minimum angle " +
            angle + " may be unreachable here: lower --min-angle)");
    }
}

Refiner::SplitPoint Refiner::split_point(EdgeIdx e) const {
    const VertIdx a = mesh_.origin(e), b = mesh_.destination(e);
    const std::uint32_t segment = cdt_.segment_of(e);
    // Parameters along the input segment s0 -> s1 (long double): every split point is computed
    // from the segment itself, so rounding never accumulates along it. The products are taken
    // on differences scaled by 2^shift, shift minus the exponent of the segment's larger
    // difference (exact: the same bits as unscaled wherever those neither overflow nor
    // underflow), so that no square leaves the range even where long double is double (MSVC,
    // Apple arm64).
    const auto ends = cdt_.segment_ends(segment);
    const double* s0 = point(ends[0]);
    const double* s1 = point(ends[1]);
    const long double dx0 = static_cast<long double>(s1[0]) - s0[0],
                      dy0 = static_cast<long double>(s1[1]) - s0[1];
    const int shift = -std::ilogb(std::max(std::fabs(dx0), std::fabs(dy0)));
    const long double dx = std::ldexp(dx0, shift), dy = std::ldexp(dy0, shift);
    const long double length2 = dx * dx + dy * dy;  // in [1, 8)
    auto parameter = [&](VertIdx v) {
        return (std::ldexp(static_cast<long double>(point(v)[0]) - s0[0], shift) * dx +
                std::ldexp(static_cast<long double>(point(v)[1]) - s0[1], shift) * dy) /
               length2;
    };
    auto corner = [&](VertIdx v) { return v < initial_vertices_ && degree_[v] >= 2; };
    const long double ta = parameter(a), tb = parameter(b);
    long double t = 0.5L * (ta + tb);
    SplitPoint split;
    if (corner(a) != corner(b)) {
        // Concentric shells: the power of two nearest half the piece's length, from the apex.
        split.apex = corner(a) ? a : b;
        const long double t_apex = split.apex == a ? ta : tb, t_far = split.apex == a ? tb : ta;
        const long double length =
            std::ldexp(std::fabs(t_far - t_apex) * std::sqrt(length2), -shift);
        // Nearest in the geometric sense (log2 rounded), decided exactly on the mantissa m in
        // [1/2, 1) (frexp): 2^(e - 1) when m < 1/sqrt(2), that is when m^2 - 1/2 < 0 (one fma,
        // whose rounding keeps the sign), else 2^e. So the shell moves by exactly k when the
        // input is scaled by 2^k (lround(log2) saw a tie, or not, by the last bit of log2 at
        // lengths like a square's diagonal).
        int exponent = 0;
        const double mantissa = std::frexp(static_cast<double>(length / 2), &exponent);
        split.shell = std::fma(mantissa, mantissa, -0.5) < 0 ? exponent - 1 : exponent;
        const long double distance = std::ldexp(1.0L, split.shell + shift);  // in the scaled units
        t = t_apex + (t_far > t_apex ? 1 : -1) * distance / std::sqrt(length2);
    }
    split.x = static_cast<double>(s0[0] + t * dx0);
    split.y = static_cast<double>(s0[1] + t * dy0);
    return split;
}

bool Refiner::leave_at_small_angle(EdgeIdx e, double shortest_edge) const {
    // Shewchuk's rule for small input angles [Shewchuk00 "Mesh generation for domains with small
    // angles" §3]: a piece at an apex of a small input angle is not split for a rejected
    // circumcenter when the new vertex would lie closer to an existing vertex (across the small
    // angle, or on the piece) than the skinny triangle's shortest edge: splitting would only
    // make smaller skinny triangles towards the apex, without end.
    // The new vertex's distance to its nearest neighbour ("insertion radius") is taken as the
    // distance to the piece's ends and to its two apexes, and to where the cluster's other
    // segments will be split next (the same shell, the smallest angle phi at the apex away):
    // 2 d sin(phi / 2) at distance d from the apex.
    const VertIdx a = mesh_.origin(e), b = mesh_.destination(e);
    auto apex_angle = [&](VertIdx v) { return v < initial_vertices_ ? small_apex_angle_[v] : 0.0; };
    if (apex_angle(a) == 0 && apex_angle(b) == 0) return false;
    const SplitPoint m = split_point(e);
    double radius = INFINITY;
    for (const VertIdx v :
         {a, b, mesh_.tv[tri::prev_edge(e)], mesh_.tv[tri::prev_edge(mesh_.twin[e])]}) {
        if (v == tri::kInfinite) continue;
        radius = std::min(radius, std::hypot(point(v)[0] - m.x, point(v)[1] - m.y));
    }
    for (const VertIdx v : {a, b}) {
        if (apex_angle(v) == 0) continue;
        const double d = std::hypot(point(v)[0] - m.x, point(v)[1] - m.y);
        radius = std::min(radius, 2 * d * std::sin(apex_angle(v) / 2));
    }
    return radius < shortest_edge;
}

void Refiner::split_piece(const PieceToSplit& piece) {
    const EdgeIdx e = cdt_.find_edge(piece.a, piece.b);
    // Already split (a - b may be an edge again, unconstrained, beside a piece bent by rounding).
    if (e == kNone || cdt_.segment_of(e) == kNone) return;
    const std::uint32_t segment = cdt_.segment_of(e);
    if (!piece.forced) {
        // Still encroached from a domain side? (The apex may have changed since.)
        const bool left = cdt_.in_domain(tri::triangle_of(e)) && encroached_from(e, counters_);
        const EdgeIdx f = mesh_.twin[e];
        if (!left && !(cdt_.in_domain(tri::triangle_of(f)) && encroached_from(f, counters_)))
            return;
    }
    spend_budget();
    const SplitPoint m = split_point(e);
    const std::uint32_t before = mesh_.vertex_count();
    const VertIdx v = cdt_.split_constrained_edge(e, m.x, m.y);
    if (v >= before) {
        ++counters_.segment_splits;
        progress_.tick();
        if (on_segment_.size() <= v) on_segment_.resize(v + 1);
        on_segment_[v] = {segment, m.apex, m.shell};
        if (m.apex != kNone) ++counters_.shell_splits;
    } else {
        ++counters_.segment_bends;
    }
    process_touched();
}

bool Refiner::refine(std::uint64_t limit) {
    for (;;) {
        while (!forced_.empty()) {
            const PieceToSplit piece = forced_.back();
            forced_.pop_back();
            split_piece(piece);
        }
        // An encroached piece waits only while a bad triangle is worse than the triangle whose
        // apex encroaches it (ties: the piece first). Any order keeps the guarantee (a
        // circumcenter that encroaches a piece is never inserted), but splitting every piece
        // first made narrow strips cost time in their length per insertion: in a strip 1e-5
        // wide each split's new vertex encroaches the piece opposite, so the strip's sides were
        // split down to 1e-5 before any triangle beside the strip was refined; the triangle
        // inside the inner square beside it became a fan of 10^5 slivers from one vertex, and
        // the first circumcenters there replaced cavities of 10^5 triangles (issue 11: nested
        // squares 1e-5 apart). Taken by key, a fan's slivers are refined once they are worse
        // than the strip's, so the fans (and cavities) stay small.
        if (!pieces_.empty() && (bad_.empty() || pieces_.top_bucket() >= bad_.top_bucket() ||
                                 counters_.steiner_points() >= limit)) {
            const EncroachedPiece piece = pieces_.pop();
            split_piece({piece.a, piece.b, false});
            continue;
        }
        if (bad_.empty()) return true;
        if (counters_.steiner_points() >= limit) return false;
        if (options_.order == RefinementOrder::Rounds) {
            insert_round(limit);
        } else {
            insert_worst();
        }
    }
}

void Refiner::insert_worst() {
    const BadTriangle top = bad_.pop();
    if (current(top)) insert_circumcenter(top);  // else rewritten since
}

void Refiner::insert_circumcenter(const BadTriangle& top) {
    spend_budget();
    const VertIdx v[3] = {mesh_.tv[3 * top.t], mesh_.tv[3 * top.t + 1], mesh_.tv[3 * top.t + 2]};
    // The cavity starts from top.t's neighbours: its twins arrive while the circumcentre is
    // computed.
    __builtin_prefetch(&mesh_.twin[3 * top.t]);
    const auto c = predicates::circumcenter(point(v[0]), point(v[1]), point(v[2]));
    const std::uint64_t replaced_before = cdt_.counters().cavity_triangles;
    const tri::CavityInsertion outcome = cdt_.insert_in_cavity(top.t, c[0], c[1]);
    after_insertion(top, outcome, cdt_.counters().cavity_triangles - replaced_before);
}

void Refiner::after_insertion(const BadTriangle& top, tri::CavityInsertion outcome,
                              std::uint64_t cavity_size) {
    switch (outcome) {
        case tri::CavityInsertion::Inserted:
            ++counters_.circumcenters;
            progress_.tick();
            counters_.largest_cavity = std::max(counters_.largest_cavity, cavity_size);
            // (Rounds evaluate the touched triangles once per round.)
            if (options_.order == RefinementOrder::WorstFirst) process_touched();
            break;
        case tri::CavityInsertion::Encroaches: {
            ++counters_.rejected_circumcenters;
            // sqrt of the smallest squared length (as the rules were tuned), scaled.
            const double* p[3] = {point(mesh_.tv[3 * top.t]), point(mesh_.tv[3 * top.t + 1]),
                                  point(mesh_.tv[3 * top.t + 2])};
            const ScaledTriangle scaled = scaled_triangle(p);
            const double shortest = std::ldexp(
                std::sqrt(std::min({scaled.length2[0], scaled.length2[1], scaled.length2[2]})),
                -scaled.shift);
            bool split = false;
            for (const EdgeIdx e : cdt_.encroached_edges()) {
                // Only skinny triangles are left at small angles; too big ones are split.
                if (!top.too_big && leave_at_small_angle(e, shortest)) continue;
                forced_.push_back({mesh_.origin(e), mesh_.destination(e), true});
                split = true;
            }
            if (split) {
                bad_.push(top);  // still bad unless the splits rewrite it
            } else if (below_asked_bound(top.t)) {
                ++counters_.small_angle_skips;  // left skinny at a small input angle
            }
            break;
        }
        case tri::CavityInsertion::Duplicate:
        case tri::CavityInsertion::NotInConflict:
        case tri::CavityInsertion::Outside:
            // A triangle so small that its rounded circumcenter is one of its vertices (or
            // leaves its circle): nothing to insert; it stays, counted (when it is bad for the
            // bound asked for, not only for the polish's).
            if (top.too_big || below_asked_bound(top.t)) ++counters_.unsplittable;
            break;
    }
}

void Refiner::insert_round(std::uint64_t limit) {
    // The round: the bad triangles refine would pop next (one entry per triangle), up to
    // the round's size and the Steiner points left, while no encroached piece comes first.
    const std::uint64_t room =
        std::min<std::uint64_t>(kRefinementRoundSize, limit - counters_.steiner_points());
    Clock::time_point start = Clock::now();
    // Only triangles nearly as bad as the worst (kRoundKeyBand, and of its class): a round of
    // all the bad triangles at once inserted a tenth to a fifth more points than worst-first
    // on small domains refined to 30 degrees, whose worst triangles' points fix many others.
    const std::size_t worst = bad_.top_bucket();
    const std::size_t lowest = worst % kBucketsPerClass >= kRoundKeyBand
                                   ? worst - kRoundKeyBand
                                   : worst - worst % kBucketsPerClass;
    if (bad_.entries_from(lowest) < kSmallestRound) {
        // Fewer entries than a round's least, stale ones included: the round could only be a
        // worst-first step (below), and forming it would take out and put back every entry of
        // the band for one point (most rounds were such steps: 8,170 of 8,710 at 10^6
        // triangles). The step, directly: the first current entry of the band (the stale ones
        // above it dropped), while no encroached piece comes first. (Forming dropped every stale
        // entry of the band, which could lower the next band: the meshes differ from before
        // this rule, not between thread counts.)
        while (band_goes_on(lowest)) {
            const BadTriangle top = bad_.pop();
            if (!current(top)) continue;  // rewritten since
            insert_circumcenter(top);
            process_touched();
            break;
        }
        lap(round_seconds_.steps, start);
        return;
    }
    round_vertices_.clear(3 * static_cast<std::size_t>(room));
    round_.clear();
    waiting_.clear();
    taken_.clear();
    next_batch();
    // A triangle with a vertex of one taken before it waits for the next round: the new
    // triangles of one insertion are queued together, and their cavities overlap (taken
    // together, two in five met an earlier one's).
    while (round_.size() < room && waiting_.size() < room && band_goes_on(lowest)) {
        // The entries of a round are anywhere in the mesh: what the tests below read of them is
        // asked for a few entries ahead.
        if (const BadTriangle* ahead = bad_.under_top(8)) {
            __builtin_prefetch(&marks_[ahead->t]);
            cdt_.prefetch(ahead->t);
        }
        const BadTriangle top = bad_.pop();
        if (!current(top) || marks_[top.t].seen == batch_) continue;  // stale, or taken already
        const VertIdx* v = &mesh_.tv[3 * top.t];
        if (round_vertices_.flags(v[0]) != 0 || round_vertices_.flags(v[1]) != 0 ||
            round_vertices_.flags(v[2]) != 0) {
            waiting_.push_back(top);
            taken_.push_back(top);
            continue;
        }
        for (int k = 0; k < 3; ++k) round_vertices_.add(v[k], 1);
        marks_[top.t].seen = batch_;
        round_.push_back(top);
        taken_.push_back(top);
    }
    // Back in the queue in the order they came out (reversed: last in, first out). A round of
    // few triangles is a worst-first step: its first alone, the others back too.
    if (round_.size() < kSmallestRound && round_.size() > 1) {
        round_.erase(round_.begin() + 1, round_.end());
        waiting_.swap(taken_);
        waiting_.erase(std::find_if(waiting_.begin(), waiting_.end(),
                                    [&](const BadTriangle& b) { return b.t == round_[0].t; }));
    }
    for (auto w = waiting_.rbegin(); w != waiting_.rend(); ++w) bad_.push(*w);
    lap(round_seconds_.form, start);
    if (round_.empty()) return;
    ++counters_.rounds;
    probe_round();
    lap(round_seconds_.probe, start);
    std::size_t cavities = 0, besides = 0;
    for (std::size_t i = 0; i < round_.size(); ++i) {
        cavities += probes_[i].cavity.size() + 1;
        besides += probes_[i].beside.size();
    }
    claimed_.clear(cavities + besides);
    // In the order taken: each point whose cavity is as probed (apart from the cavities of the
    // points taken before it) goes in, or is rejected as insert_worst rejects it; the others
    // wait for the next round. The first always goes. The points that go in are inserted
    // together, their fans written on every thread: the mesh is the one inserting them one
    // after another would make.
    accepted_.clear();
    for (std::size_t i = 0; i < round_.size(); ++i) {
        const tri::CavityProbe& probe = probes_[i];
        if (!unclaimed(probe)) {
            bad_.push(round_[i]);
            ++counters_.round_conflicts;
            continue;
        }
        spend_budget();
        if (probe.outcome == tri::CavityInsertion::Inserted) {
            claim(probe);
            accepted_.push_back(&probe);
            after_insertion(round_[i], probe.outcome, probe.cavity.size());
        } else {
            after_insertion(round_[i], cdt_.insert_probed(probe), probe.cavity.size());
        }
    }
    // With a size that may be evaluated on several threads at once (every kind but a caller's
    // function) the new triangles are assessed on the thread that wrote them, while they are in
    // its cache, and queued afterwards in the order process_touched queues them: the same queue
    // either way. A fan's triangles forget their cached edge sizes first, then each reads its
    // own and those of the triangles beside the cavity, which no other fan writes (the size at
    // an edge's midpoint is the same number from either side, so where it comes from does not
    // change the mesh). An error (a size not > 0) is kept per chunk and the first in order
    // thrown after the fans, as one thread would throw it.
    lap(round_seconds_.accept, start);
    const std::size_t chunks = threads_ == 1 ? 1 : 4 * std::size_t{threads_};
    const bool assess_in_fans = !cache_sizes_ || options_.size.concurrent();
    tri::ConstrainedTriangulation2::FanWritten written;
    if (assess_in_fans) {
        std::size_t fan_triangles = 0;
        for (const tri::CavityProbe* probe : accepted_) fan_triangles += probe->boundary.size();
        assessments_.assign(fan_triangles, Assessment{});
        tallies_.assign(chunks, RefinementCounters2{});
        errors_.assign(chunks, {});
        // Every new slot is below this (recycled ones are lower still).
        const std::size_t slots = mesh_.triangle_slots() + 2 * accepted_.size();
        if (marks_.size() < slots) marks_.resize(slots);
        if (cache_sizes_ && edge_size_.size() < 3 * slots) edge_size_.resize(3 * slots, 0.0);
        written = [&](std::size_t chunk, std::size_t position, std::span<const TriIdx> fan) {
            if (errors_[chunk].error) return;
            for (const TriIdx t : fan) {
                ++marks_[t].version;
                if (cache_sizes_) {
                    edge_size_[3 * t] = edge_size_[3 * t + 1] = edge_size_[3 * t + 2] = 0.0;
                }
            }
            for (std::size_t j = 0; j < fan.size(); ++j) {
                const TriIdx t = fan[j];
                if (!cdt_.in_domain(t)) continue;
                Assessment& a = assessments_[position + j];
                try {
                    a = assess(t, tallies_[chunk]);
                } catch (...) {
                    errors_[chunk] = {std::current_exception(), position + j};
                    return;
                }
                find_encroached_pieces(t, a, tallies_[chunk]);
                a.version = marks_[t].version;  // what queue() pushes, read here where it is warm
            }
        };
    }
    if (threads_ == 1) {
        cdt_.insert_probed_apart(accepted_, chunks, {}, written);
    } else {
        cdt_.insert_probed_apart(
            accepted_, chunks,
            [&](std::size_t count, const std::function<void(std::size_t)>& body) {
                runner_.run(*arena_, count, body);
            },
            written);
    }
    if (!assess_in_fans) {
        lap(round_seconds_.fans, start);
        process_touched();
        lap(round_seconds_.queue, start);
        return;
    }
    lap(round_seconds_.fans, start);
    const ChunkError* first_error = nullptr;
    for (const ChunkError& e : errors_)
        if (e.error && (first_error == nullptr || e.position < first_error->position))
            first_error = &e;
    if (first_error != nullptr) std::rethrow_exception(first_error->error);
    const std::span<const TriIdx> touched = cdt_.touched();
    for (std::size_t k = 0; k < touched.size(); ++k)
        if (assessments_[k].in_domain) queue(touched[k], assessments_[k], assessments_[k].version);
    for (const RefinementCounters2& tally : tallies_) {
        counters_.small_angle_skips += tally.small_angle_skips;
        counters_.encroachment_tests += tally.encroachment_tests;
        counters_.narrow_wedge_skips += tally.narrow_wedge_skips;
    }
    cdt_.clear_touched();
    lap(round_seconds_.queue, start);
}

void Refiner::probe_round() {
    if (probes_.size() < round_.size()) probes_.resize(round_.size());
    // Every point is probed as the next vertex (only its rank matters: above every vertex).
    const VertIdx next = mesh_.vertex_count();
    // The construction counters are per thread: the exact circumcentres of the other threads
    // are added to the calling thread's at the end (run).
    const std::thread::id caller = std::this_thread::get_id();
    const auto probe = [&](std::size_t begin, std::size_t end) {
        const int index = threads_ > 1 ? tbb::this_task_arena::current_thread_index() : 0;
        ProbeScratch& scratch =
            scratch_[index >= 0 && static_cast<unsigned>(index) < threads_ ? index : 0];
        const predicates::ConstructionStats& stats = predicates::construction_stats();
        const std::uint64_t exact_before = stats.exact_range + stats.exact_uncertified;
        for (std::size_t i = begin; i < end; ++i) {
            // A round's triangles are anywhere in the mesh, each probe a chain of cache misses
            // (the triangle, its vertices' coordinates, its neighbours, theirs): the next
            // probes' first links are asked for ahead, in two stages (a triangle's vertices and
            // twins, then, once they have arrived, the coordinates and the neighbours' vertices).
            if (i + kProbeAhead < end) {
                const TriIdx ahead = round_[i + kProbeAhead].t;
                __builtin_prefetch(&mesh_.tv[3 * ahead]);
                __builtin_prefetch(&mesh_.twin[3 * ahead]);
            }
            if (i + kProbeAhead / 2 < end) {
                const TriIdx ahead = round_[i + kProbeAhead / 2].t;
                for (unsigned k = 0; k < 3; ++k) {
                    __builtin_prefetch(point(mesh_.tv[3 * ahead + k]));
                    __builtin_prefetch(&mesh_.tv[3 * tri::triangle_of(mesh_.twin[3 * ahead + k])]);
                }
            }
            const TriIdx t = round_[i].t;
            const auto c = predicates::circumcenter(
                point(mesh_.tv[3 * t]), point(mesh_.tv[3 * t + 1]), point(mesh_.tv[3 * t + 2]));
            cdt_.probe_cavity(t, c[0], c[1], next, probes_[i], scratch.cavity);
        }
        if (std::this_thread::get_id() != caller) {
            scratch.exact_circumcenters +=
                stats.exact_range + stats.exact_uncertified - exact_before;
        }
    };
    if (threads_ == 1) {
        probe(0, round_.size());
    } else {
        runner_.run_chunks(*arena_, round_.size(), probe, 4 * kProbeAhead);
    }
}

bool Refiner::unclaimed(const tri::CavityProbe& probe) const {
    if (probe.cavity.empty()) return claimed_.flags(probe.start) == 0;  // NotInConflict: t alone
    for (const TriIdx c : probe.cavity)
        if (claimed_.flags(c) != 0) return false;
    for (const TriIdx beside : probe.beside)
        if ((claimed_.flags(beside) & kInCavity) != 0) return false;
    return true;
}

void Refiner::claim(const tri::CavityProbe& probe) {
    // The fan's two new slots are no one's probe; its outer edges link to the triangles
    // beside the cavity.
    for (const TriIdx c : probe.cavity) claimed_.add(c, kInCavity);
    for (const TriIdx beside : probe.beside) claimed_.add(beside, kBeside);
}

bool Refiner::below_asked_bound(TriIdx t) const {
    const double* p[3] = {point(mesh_.tv[3 * t]), point(mesh_.tv[3 * t + 1]),
                          point(mesh_.tv[3 * t + 2])};
    const ScaledTriangle scaled = scaled_triangle(p);
    double length2[3] = {scaled.length2[0], scaled.length2[1], scaled.length2[2]};
    std::sort(length2, length2 + 3);
    return scaled.cross * scaled.cross < asked_sine2_ * length2[1] * length2[2];
}

void Refiner::requeue_for_asked_bound() {
    // The queue holds every triangle bad for the polish bound (and stale entries): those still
    // current and bad for min_angle (or too big) are evaluated again, with keys for min_angle.
    std::vector<TriIdx> keep;
    while (!bad_.empty()) {
        const BadTriangle b = bad_.pop();
        if (!current(b)) continue;
        if (b.too_big || below_asked_bound(b.t)) keep.push_back(b.t);
    }
    next_batch();
    for (const TriIdx t : keep) {
        if (marks_[t].seen == batch_) continue;  // queued twice (a rejected circumcenter requeues)
        marks_[t].seen = batch_;
        evaluate(t);
    }
}

void Refiner::polish() {
    if (polish_sine2_ <= sine2_bound_) return;
    sine2_bound_ = polish_sine2_;
    polish_sine2_ = 0;  // no more candidates
    for (const BadTriangle& b : polish_) {
        if (!current(b)) continue;
        bad_.push(b);
        ++counters_.bad_triangles;
    }
    polish_ = {};
    const std::uint64_t before = counters_.steiner_points();
    const auto extra =
        static_cast<std::uint64_t>(options_.polish_fraction * static_cast<double>(before)) + 64;
    const bool done = refine(std::min(before + extra, budget_));  // never the budget's error
    counters_.polish_points = counters_.steiner_points() - before;
    sine2_bound_ = asked_sine2_;
    if (done) return;
    // The polish's budget is spent: back to min_angle (the proven refinement, from here).
    ++counters_.polish_stopped;
    requeue_for_asked_bound();
    refine(UINT64_MAX);
}

RefinementResult2 Refiner::run() {
    if (cdt_.collinear()) {
        throw InputError(
            "delaunay refinement: the points are collinear; the segments enclose no region");
    }
    initial_vertices_ = mesh_.vertex_count();
    degree_.assign(initial_vertices_, 0);
    for (EdgeIdx e = 0; e < mesh_.tv.size(); ++e) {
        if (mesh_.is_dead(tri::triangle_of(e)) || cdt_.segment_of(e) == kNone) continue;
        ++degree_[mesh_.origin(e)];
    }
    // Apexes of small input angles: two pieces at a vertex less than 60 degrees apart.
    find_small_input_angles();
    find_narrow_wedges();
    if (options_.min_angle > 0) {
        const double s = std::sin(options_.min_angle * 3.14159265358979323846 / 180.0);
        sine2_bound_ = s * s;
    }
    cache_sizes_ = options_.size.bounded() && !options_.size.is_uniform();
    check_domain_and_budget();
    asked_sine2_ = sine2_bound_;
    if (options_.min_angle > 0) {
        const double polish = options_.polish_angle < 0
                                  ? std::min(kMaxPolishAngle, options_.min_angle + 10)
                                  : options_.polish_angle;
        const double s = std::sin(polish * 3.14159265358979323846 / 180.0);
        if (polish > options_.min_angle) polish_sine2_ = s * s;
    }
    predicates::reset_construction_stats();
    initial_queue();
    refine(UINT64_MAX);
    polish();
    const tri::ConstrainedTriangulation2Counters& edits = cdt_.counters();
    counters_.cavity_triangles = edits.cavity_triangles;
    counters_.rejected_cavity_triangles = edits.rejected_cavity_triangles;
    counters_.circumcenter_exact = predicates::construction_stats().exact_range +
                                   predicates::construction_stats().exact_uncertified;
    for (const ProbeScratch& scratch : scratch_)
        counters_.circumcenter_exact += scratch.exact_circumcenters;
    counters_.threads = threads_;
    RefinementResult2 result;
    result.mesh = std::move(cdt_).take_result();
    if (region_areas_) {
        for (double& a : result.mesh.triangle_attributes) a = region_attribute_of(regions_, a);
    }
    counters_.flips = result.mesh.counters.delaunay_flips;
    counters_.orient_calls = result.mesh.counters.orient_calls;
    counters_.incircle_calls = result.mesh.counters.incircle_calls;
    result.counters = counters_;
    result.round_seconds = round_seconds_;
    return result;
}

}  // namespace

std::vector<std::pair<std::string, double>> phase_list(const RoundPhaseSeconds2& s) {
    return {{"round_form_seconds", s.form},     {"round_probe_seconds", s.probe},
            {"round_accept_seconds", s.accept}, {"round_fans_seconds", s.fans},
            {"round_queue_seconds", s.queue},   {"round_steps_seconds", s.steps}};
}

RefinementResult2 delaunay_refinement_2d(const tri::Pslg& pslg, const RefinementOptions2& options) {
    if (!(options.min_angle >= 0 && options.min_angle <= kMaxMinAngle)) {
        char angle[32];
        std::snprintf(angle, sizeof angle, "%g", options.min_angle);
        throw InputError(std::string("minimum angle ") + angle +
                         " is outside [0, 34] degrees (Delaunay refinement "
                         "terminates provably up to 20.7 and in practice up to about 33)");
    }
    if (std::isnan(options.polish_angle) || options.polish_angle > kMaxMinAngle) {
        char angle[32];
        std::snprintf(angle, sizeof angle, "%g", options.polish_angle);
        throw InputError(std::string("polish angle ") + angle +
                         " is above 34 degrees or not a number (negative: automatic)");
    }
    if (!(options.polish_fraction >= 0 && std::isfinite(options.polish_fraction))) {
        char fraction[32];
        std::snprintf(fraction, sizeof fraction, "%g", options.polish_fraction);
        throw InputError(std::string("polish fraction ") + fraction +
                         " is not a finite number >= 0");
    }
    if (options.order == RefinementOrder::WorstFirst && options.threads != 1) {
        throw InputError("the worst-first refinement runs on one thread (" +
                         std::to_string(options.threads) +
                         " asked): more threads need the rounds order");
    }
    Refiner refiner(pslg, options);
    return refiner.run();
}

}  // namespace exactmesh::generators
