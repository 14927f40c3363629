// SPDX-License-Identifier: MIT
// Delaunay refinement (Steiner triangulation) of a PSLG domain: Ruppert's algorithm with
// Shewchuk's improvements [Ruppert95: "A Delaunay refinement algorithm for quality 2-dimensional
// mesh generation", J. Algorithms 18(3); Shewchuk02: "Delaunay refinement algorithms for
// triangular mesh generation", CGTA 22; Miller-Pav-Walkington03: "When and why Ruppert's
// algorithm works", IMR; seed material, issue 6 generator 3].
//  - The constrained Delaunay triangulation of the domain (ConstrainedTriangulation2) is kept
//    throughout; a piece of a segment is split when a vertex lies in its closed diametral circle
//    (encroachment), at the midpoint, or on a concentric shell (the power of two nearest half its
//    length) about an input vertex where segments meet [Ruppert95 §4]; an encroached piece goes
//    before every bad triangle that is not worse than the triangle of the encroaching vertex
//    (the order does not matter to the proof; this one keeps cavities small beside narrow
//    strips, whose sides encroach each other down to the strip's width).
//  - The worst bad triangle (radius-edge ratio above B = 1 / (2 sin theta_min), i.e. an
//    angle below theta_min, or an edge longer than the size function at its midpoint, or an
//    area above its region's maximum area: Triangle's -a, region_areas_2d.hpp) gets its
//    circumcenter, correctly rounded (predicates/constructions), inserted by Bowyer-Watson; a
//    circumcenter that encroaches pieces is not inserted, and those pieces are split instead.
//  - Small input angles (below 60 degrees, inside the domain): the skinny triangle at such an
//    apex (its shortest edge joins the two segments on one shell, its third vertex the apex)
//    keeps the input angle and is not split [Miller-Pav-Walkington03]; a rejected circumcenter
//    of a skinny triangle does not split a piece at the apex when the new vertex would lie
//    closer to another than the triangle's shortest edge [Shewchuk00: "Mesh generation for
//    domains with small angles", SoCG]: refinement never descends into the apex.
//  - Then the polish: triangles whose smallest angle is below a higher polish angle (automatic:
//    theta_min + 10, at most 32 degrees) are refined on the same way, worst first, within a
//    budget of 10% more Steiner points; when it runs out, the refinement returns to theta_min.
//    The guarantee below is the proven refinement's; the polish only lifts the minimum angle
//    (to the polish angle on the sample domains, for 0.2-7% more points).
// Guarantee (proofs/invariants/delaunay_refinement.md): for theta_min <= arcsin(1/(2 sqrt 2)) =
// 20.7 degrees and no two segments meeting at less than 60 degrees the refinement terminates,
// and then every triangle has every angle >= theta_min and every edge no longer than the size
// at its midpoint. With smaller input angles it terminates in every test (the rules above; no
// proof here) and the angle bound holds away from them. Above 20.7 degrees (up to 34) there is
// no proof either: a budget of Steiner points stops a run that does not terminate, with a
// GeometryError.
// Cost: O(n log n + m) for m output vertices in practice (O(1) bucketed queue operations,
// cavities of O(1) expected size; the initial constrained triangulation O(n log n)). Predicates:
// orient2d, incircle (SoS), corner_dot_sign (encroachment); construction: circumcenter.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "base/counter_table.hpp"
#include "base/errors.hpp"
#include "generators/sizing/size_function.hpp"
#include "triangulation/constrained/constrained_2d.hpp"

namespace exactmesh::generators {

/// 20.7 degrees: arcsin(1 / (2 sqrt 2)), the largest angle bound with a termination proof.
inline constexpr double kGuaranteedMinAngle = 20.7;
/// The largest angle bound accepted (no proof; in practice Delaunay refinement stops
/// terminating a little above 33 degrees on most domains).
inline constexpr double kMaxMinAngle = 34.0;

/// The automatic polish aims at most this high (degrees): refinement still ends quickly there
/// (about 1% more Steiner points from 30 degrees on the sample domains; above about 33 it stops
/// terminating on most domains).
inline constexpr double kMaxPolishAngle = 32.0;

/// The order in which the refinement inserts its points (RefinementOptions2::order).
enum class RefinementOrder {
    /// One point at a time, for the worst bad triangle (or encroached piece) first: the
    /// sequential refinement, on one thread.
    WorstFirst,
    /// Rounds: up to kRefinementRoundSize of the worst bad triangles are taken at once: those
    /// of the worst key's two buckets (keys within 9%; none after an encroached piece that comes
    /// first), skipping a triangle with a vertex of one already taken (it waits), and a round
    /// of fewer than 64 is only its first triangle (a worst-first step; taken directly when
    /// the two buckets hold fewer than 64 entries, stale ones included). Their circumcentres
    /// and conflict zones are found in parallel by reading the mesh only, then, in the order
    /// they were taken, each is inserted unless its zone (or a triangle beside it) meets the
    /// zone of one inserted before it in the round; those wait for the next round. The fans
    /// are written, and their triangles assessed (without a cached size), in parallel. What a
    /// round holds never depends on the thread count, so neither does the mesh; it is not
    /// WorstFirst's mesh (the same criteria and guarantee, a different order: within 0.3% of
    /// its points on the sample domains, 3-10% more on small domains refined to 30 degrees
    /// without a size, the same at 25).
    Rounds,
};

/// The most bad triangles one round of RefinementOrder::Rounds takes.
inline constexpr std::size_t kRefinementRoundSize = 1024;

struct RefinementOptions2 {
    /// Every angle of the mesh at least this (degrees), away from small input angles; 0 turns
    /// the angle criterion off. At most kMaxMinAngle.
    double min_angle = kGuaranteedMinAngle;
    /// Every edge at most as long as the size at its midpoint (none: no size criterion).
    SizeFunction size;
    /// Stop with GeometryError after this many Steiner points (0: automatic, at least 10^6 and
    /// 16 times the element count the size function asks for).
    std::uint64_t max_steiner_points = 0;
    /// The polish, after the refinement to min_angle: triangles whose smallest angle is below
    /// this (degrees) are refined further, worst first, while the Steiner points it adds stay
    /// within polish_fraction of those before it plus 64; when that runs out the refinement
    /// returns to min_angle. Negative: automatic, min(min_angle + 10, kMaxPolishAngle); at most
    /// min_angle: none. At most kMaxMinAngle.
    double polish_angle = -1;
    double polish_fraction = 0.1;
    /// The initial constrained Delaunay triangulation (recovery Swap or Cavity).
    triangulation::Cdt2Options cdt;
    RefinementOrder order = RefinementOrder::WorstFirst;
    /// Threads of the rounds (0: every core); WorstFirst runs on one (any other count is an
    /// InputError).
    unsigned threads = 1;
};

struct RefinementCounters2 {
    std::uint64_t circumcenters = 0;   ///< Steiner points inserted at circumcenters
    std::uint64_t segment_splits = 0;  ///< Steiner points inserted on segments
    std::uint64_t shell_splits = 0;    ///< of those, on concentric shells
    std::uint64_t segment_bends = 0;   ///< pieces split at an existing vertex within rounding
    std::uint64_t rejected_circumcenters = 0;  ///< circumcenters not inserted (they encroached)
    std::uint64_t encroachment_tests = 0;      ///< corner_dot_sign calls of the refinement
    std::uint64_t bad_triangles = 0;           ///< bad triangles queued (with repeats)
    std::uint64_t small_angle_skips = 0;       ///< skinny triangles left at small input angles
    /// encroachments not acted on: the vertex and the piece on two segments of a narrow wedge
    std::uint64_t narrow_wedge_skips = 0;
    std::uint64_t unsplittable = 0;      ///< bad triangles whose circumcenter rounds onto a vertex
    std::uint64_t cavity_triangles = 0;  ///< triangles replaced by circumcenter insertions
    std::uint64_t largest_cavity = 0;    ///< the most triangles one insertion replaced
    /// triangles of the conflict zones of insertions rejected at a segment (with
    /// cavity_triangles, the work bounded at 64 per budgeted Steiner point)
    std::uint64_t rejected_cavity_triangles = 0;
    std::uint64_t flips = 0;               ///< Lawson flips (initial triangulation and splits)
    std::uint64_t polish_points = 0;       ///< Steiner points of the polish
    std::uint64_t polish_stopped = 0;      ///< 1: the polish's budget ran out
    std::uint64_t circumcenter_exact = 0;  ///< circumcenters that needed the exact path
    std::uint64_t orient_calls = 0;
    std::uint64_t incircle_calls = 0;
    std::uint64_t rounds = 0;           ///< rounds of RefinementOrder::Rounds
    std::uint64_t round_conflicts = 0;  ///< bad triangles a round left for the next one
    std::uint64_t threads = 1;          ///< threads the refinement ran on
    std::uint64_t steiner_points() const { return circumcenters + segment_splits; }
};

/// The counters' names as `exactmesh mesh --stats` prints them, in this order (one row
/// per field: counter_table_complete).
inline constexpr std::array kRefinementCounterNames{
    derived_counter<RefinementCounters2>(
        "steiner_points",
        [](const RefinementCounters2& c) -> std::uint64_t { return c.steiner_points(); }),
    counter("circumcenters", &RefinementCounters2::circumcenters),
    counter("segment_splits", &RefinementCounters2::segment_splits),
    counter("shell_splits", &RefinementCounters2::shell_splits),
    counter("segment_bends", &RefinementCounters2::segment_bends),
    counter("rejected_circumcenters", &RefinementCounters2::rejected_circumcenters),
    counter("bad_triangles_queued", &RefinementCounters2::bad_triangles),
    counter("small_angle_skips", &RefinementCounters2::small_angle_skips),
    counter("narrow_wedge_skips", &RefinementCounters2::narrow_wedge_skips),
    counter("unsplittable", &RefinementCounters2::unsplittable),
    counter("cavity_triangles", &RefinementCounters2::cavity_triangles),
    counter("largest_cavity", &RefinementCounters2::largest_cavity),
    counter("rejected_cavity_triangles", &RefinementCounters2::rejected_cavity_triangles),
    counter("delaunay_flips", &RefinementCounters2::flips),
    counter("circumcenter_exact_path", &RefinementCounters2::circumcenter_exact),
    counter("orient_calls", &RefinementCounters2::orient_calls),
    counter("incircle_calls", &RefinementCounters2::incircle_calls),
    counter("encroachment_tests", &RefinementCounters2::encroachment_tests),
    counter("polish_points", &RefinementCounters2::polish_points),
    counter("polish_stopped", &RefinementCounters2::polish_stopped),
    counter("rounds", &RefinementCounters2::rounds),
    counter("round_conflicts", &RefinementCounters2::round_conflicts),
    counter("threads", &RefinementCounters2::threads)};
static_assert(counter_table_complete(kRefinementCounterNames, 1));

/// Where the rounds of RefinementOrder::Rounds spent their time (wall-clock seconds on the
/// calling thread; all zero in the WorstFirst order). Not counters: they differ from run to
/// run, where the counters are the same for every thread count.
struct RoundPhaseSeconds2 {
    double form = 0;    ///< taking the rounds' bad triangles off the queue (serial)
    double probe = 0;   ///< circumcentres and their cavities (every thread)
    double accept = 0;  ///< accepting the probes in order, rejections carried out (serial)
    double fans = 0;    ///< writing the fans and assessing their triangles (every thread)
    double queue = 0;   ///< queueing the new triangles' verdicts (serial)
    /// worst-first steps between rounds, where the worst bad triangles are too few for one
    double steps = 0;
};

/// The phases' names as `exactmesh mesh --stats` prints them (round_NAME_seconds), in order.
std::vector<std::pair<std::string, double>> phase_list(const RoundPhaseSeconds2& s);

struct RefinementResult2 {
    /// The mesh in the caller's numbering: input vertices first (as constrained_delaunay_2d
    /// numbers them), then added ones; exterior and holes removed; pieces and warnings.
    triangulation::Cdt2Result mesh;
    RefinementCounters2 counters;
    RoundPhaseSeconds2 round_seconds;
};

/// Refinement stopped by a budget: the Steiner points, the conflict-zone work bounded with
/// them, or, under the automatic budget, a size that asks for more triangles than that budget
/// could hold, refused before any point is inserted. A GeometryError, so callers that do not
/// tell budgets apart see no change; Steiner restart catches it to coarsen its size and retry.
/// Under the automatic Steiner budget, the most triangles a size may ask for over the domain's
/// bounding box (equilateral_count_in_box): the budget is 16 times that count, at most 4e9.
inline constexpr double kAutomaticRefinementTriangles = 4e9 / 16;

class RefinementBudgetError : public GeometryError {
  public:
    using GeometryError::GeometryError;
};

/// Refines the domain the PSLG's segments enclose (holes and exterior removed as
/// constrained_delaunay_2d removes them). A region of pslg.regions with a maximum area A > 0
/// (its 4th number) bounds the area of each of its triangles by A, decided exactly
/// (predicates/triangle_area.hpp); the result's triangle_attributes are the regions' own.
/// @throws InputError on bad input (as constrained_delaunay_2d), threads other than 1 with the
///         WorstFirst order, a polish angle above
///         kMaxMinAngle or NaN, a negative or non-finite polish fraction, a min_angle outside
///         [0, kMaxMinAngle], or when the segments enclose no region.
/// @throws RefinementBudgetError (a GeometryError) when the Steiner point budget or the
///         conflict-zone work is exhausted, or at once when the size asks for more than
///         kAutomaticRefinementTriangles triangles over the bounding box without
///         max_steiner_points; GeometryError when a piece becomes too short to split in
///         double precision.
RefinementResult2 delaunay_refinement_2d(const triangulation::Pslg& pslg,
                                         const RefinementOptions2& options = {});

}  // namespace exactmesh::generators
