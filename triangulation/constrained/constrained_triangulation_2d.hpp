// SPDX-License-Identifier: MIT
// ConstrainedTriangulation2: the constrained Delaunay triangulation of a PSLG (built exactly as
// constrained_delaunay_2d builds it: constrained_2d.hpp), kept open for incremental edits that
// preserve the constrained Delaunay property, for the mesh generators of generators/:
//  - insert_in_cavity: Bowyer-Watson insertion [Bowyer81, Watson81] of a new point from a
//    triangle whose circumcircle holds it; the cavity (conflict zone) grows across unconstrained
//    edges only [Chew89 §3; Shewchuk97 "Delaunay refinement mesh generation" §3.2], so the point
//    is inserted only when it lies inside the cavity and encroaches no constrained edge on the
//    cavity's boundary (else nothing changes and the encroached edges are reported);
//  - split_constrained_edge: a point on (or within rounding of) a constrained edge splits it,
//    then Lawson flips that never cross a constraint restore the constrained Delaunay property.
// The domain (exterior and holes removed as constrained_delaunay_2d removes them) is marked per
// triangle and kept through every edit; nothing outside it is ever edited by insert_in_cavity.
// Invariants after every call: valid topology (twins, positive orientation, convex hull closed
// by the infinite vertex), every edge not constrained locally Delaunay (exact incircle with the
// shared symbolic perturbation), every piece of every segment a constrained edge (chains, with
// split points within rounding of their segment). Predicates: orient2d, incircle (SoS), and the
// exact diametral-circle test corner_dot_sign (predicates/angle_comparisons_2d.hpp).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "base/chunk_runner.hpp"
#include "triangulation/constrained/constrained_2d.hpp"
#include "triangulation/mesh/mesh2.hpp"

namespace exactmesh::triangulation {

namespace detail {
struct CdtState;
}

/// The outcome of ConstrainedTriangulation2::insert_in_cavity.
enum class CavityInsertion {
    Inserted,       ///< the point is a new vertex
    Encroaches,     ///< rejected: it lies in the closed diametral circle of (or beyond) a
                    ///< constrained edge of its cavity; encroached_edges() lists them
    Duplicate,      ///< rejected: it equals a vertex of its cavity
    NotInConflict,  ///< rejected: the start triangle's circumcircle does not hold it
    Outside,        ///< rejected: beyond an unconstrained hull edge of its cavity (never when
                    ///< the start triangle is in the domain: segments enclose it)
};

/// What insert_in_cavity(t, x, y) would do to the triangulation as it is, found by reading only
/// (ConstrainedTriangulation2::probe_cavity): the outcome, the conflict zone and its boundary.
/// Probes of one unchanged triangulation may run on several threads at once (a parallel
/// refinement's rounds); insert_probed carries one out later if nothing it read has changed.
struct CavityProbe {
    CavityInsertion outcome = CavityInsertion::NotInConflict;
    double x = 0, y = 0;              ///< the point
    TriIdx start = kNone;             ///< the triangle the cavity grew from
    std::vector<TriIdx> cavity;       ///< the conflict zone (empty for NotInConflict)
    std::vector<EdgeIdx> boundary;    ///< its boundary, half-edges inside the cavity
    std::vector<EdgeIdx> encroached;  ///< Encroaches: as encroached_edges() would list them
    /// probe_cavity: the triangle across each boundary edge (beside[i] across boundary[i])
    std::vector<TriIdx> beside;
    std::uint64_t incircle_calls = 0;
    std::uint64_t orient_calls = 0;
};

/// One thread's scratch for probe_cavity: stamps per triangle slot for a large cavity (a small
/// one is searched in its own list). Owned by the caller, one per thread.
struct CavityProbeScratch {
    std::vector<std::uint32_t> stamp;
    std::uint32_t current = 0;
};

struct ConstrainedTriangulation2Counters {
    std::uint64_t cavity_insertions = 0;    ///< points inserted by insert_in_cavity
    std::uint64_t cavity_triangles = 0;     ///< triangles replaced by those insertions, summed
    std::uint64_t rejected_insertions = 0;  ///< insert_in_cavity calls that changed nothing
    /// triangles in the conflict zones of rejected insertions (grown, then given up), summed
    std::uint64_t rejected_cavity_triangles = 0;
    std::uint64_t edge_splits = 0;  ///< constrained edges split at a new vertex
    std::uint64_t edge_bends = 0;   ///< constrained edges split at an existing vertex
    std::uint64_t split_flips = 0;  ///< Lawson flips after edge splits
    /// insert_in_metric_cavity: passes that dropped triangles p did not see from its cavity
    std::uint64_t cavity_corrections = 0;
};

class ConstrainedTriangulation2 {
  public:
    /// Builds the constrained Delaunay triangulation of pslg (copied) as constrained_delaunay_2d
    /// does with the same options, and marks the domain. A vertex within rounding of a segment
    /// (within_rounding_of_segment, strictly between its ends) becomes a vertex of it: the
    /// segment bends through it (a warning), as the conforming recovery bends; a refinement
    /// would otherwise have to resolve the ulp-wide gap. Then four corners of a box around the
    /// input are inserted, so that no segment lies on the convex hull (their triangles are
    /// exterior; take_result() leaves them out). options.recovery must be Swap or Cavity (a
    /// conforming triangulation keeps no constraints to refine against) and
    /// options.remove_exterior true (the domain is what the segments enclose).
    /// @throws InputError, GeometryError as constrained_delaunay_2d; GeometryError when the
    ///         box's corners would overflow (coordinates near the largest double).
    ConstrainedTriangulation2(const Pslg& pslg, const Cdt2Options& options = {});
    ~ConstrainedTriangulation2();
    ConstrainedTriangulation2(ConstrainedTriangulation2&&) noexcept;
    ConstrainedTriangulation2& operator=(ConstrainedTriangulation2&&) noexcept;
    ConstrainedTriangulation2(const ConstrainedTriangulation2&) = delete;
    ConstrainedTriangulation2& operator=(const ConstrainedTriangulation2&) = delete;

    // ---- reading --------------------------------------------------------------------------
    /// The triangle slots (dead ones have tv == kNone, infinite ones hold kInfinite). Mesh
    /// vertices [0, input_vertex_count()) are the input's, in an internal order
    /// (input_index()); later ones were added (intersections, then edits) and keep their number
    /// in the result. Valid until the next edit.
    const TriMesh2& mesh() const { return *mesh_; }
    /// The input segment carried by half-edge e, or kNone when e is not constrained.
    std::uint32_t segment_of(EdgeIdx e) const { return (*segment_of_)[e]; }
    /// A live, finite triangle inside the domain (not exterior, not in a hole).
    bool in_domain(TriIdx t) const {
        return !mesh_->is_dead(t) && !mesh_->is_infinite(t) &&
               (removed_->empty() || (*removed_)[t] == 0);
    }
    /// Asks for what in_domain(t) and the triangle's vertices read (a hint for loops over cold
    /// triangles).
    void prefetch(TriIdx t) const {
        __builtin_prefetch(&mesh_->tv[3 * t]);
        if (!removed_->empty()) __builtin_prefetch(&(*removed_)[t]);
    }
    /// The regional attribute of triangle t (0 outside every region, and without regions), as
    /// Cdt2Result::triangle_attributes will give it; kept through every edit.
    double attribute(TriIdx t) const;
    /// True when every input point lies on one line: there is no triangle to edit.
    bool collinear() const;
    std::uint32_t input_vertex_count() const;
    /// Mesh vertex -> the caller's vertex number (identity for added vertices).
    std::span<const VertIdx> input_index() const;
    /// The mesh vertices at the ends of input segment s (kNone, kNone for a dropped segment).
    std::array<VertIdx, 2> segment_ends(std::uint32_t s) const;
    /// The half-edge u -> v, or kNone.
    EdgeIdx find_edge(VertIdx u, VertIdx v) const;
    /// A triangle containing (x, y) (closed), or an infinite triangle when it lies outside the
    /// convex hull (visibility walk, across constraints).
    TriIdx locate(double x, double y);

    // ---- editing --------------------------------------------------------------------------
    /// Bowyer-Watson insertion of (x, y) from triangle t (in the domain), which must have it
    /// in its (perturbed) circumcircle. See CavityInsertion for the outcomes; only Inserted
    /// changes the triangulation. The new vertex is mesh().vertex_count() - 1.
    CavityInsertion insert_in_cavity(TriIdx t, double x, double y);
    /// Bowyer-Watson insertion of (x, y) in the plane mapped by a constant metric (issue 14:
    /// metric Delaunay insertion [George-Borouchaki98 §7; BorouchakiGeorgeHechtLaugSaltel97]):
    /// t must be a domain triangle holding the point (closed); the cavity is every triangle
    /// reached from it across unconstrained edges whose circumscribed ellipse in `metric`
    /// ({M11, M12, M22}, positive definite doubles; in_ellipse with the shared perturbation)
    /// holds the point, then reduced (exact orient2d) until the point sees every boundary edge
    /// strictly: a valid fan whatever the metric. No encroachment test: a point on a
    /// constrained edge is refused (Encroaches, the edge listed), one off it is inserted. After
    /// such insertions the triangulation is no longer constrained Delaunay in the Euclidean
    /// sense (it is what the metric insertions made); topology, orientation, the domain and
    /// the constraints stay valid. Outcomes: Inserted, Duplicate, Encroaches, NotInConflict
    /// (the point is not in t), Outside (beyond the hull).
    CavityInsertion insert_in_metric_cavity(TriIdx t, double x, double y, const double* metric);
    /// What insert_in_cavity(t, x, y) would do now, into `probe`, reading the triangulation only:
    /// any number of threads may probe at once while nothing edits it. The point would be vertex
    /// `index` (its symbolic perturbation's rank: any number above every vertex's, e.g. the next
    /// vertex number; only the order matters).
    void probe_cavity(TriIdx t, double x, double y, VertIdx index, CavityProbe& probe,
                      CavityProbeScratch& scratch) const;
    /// Carries out a probe (counted as insert_in_cavity counts its outcome: only Inserted
    /// changes the triangulation; encroached_edges() then lists a rejection's edges). Valid
    /// while every triangle of the probe's cavity, and each one across its boundary, is as it
    /// was when probed (the caller's independence rule): the edits since touched neither.
    CavityInsertion insert_probed(const CavityProbe& probe);
    /// Carries out probes that each found Inserted, at once: the triangulation is the one
    /// insert_probed would make of them one after another in this order (the same vertex
    /// numbers, slots and links). Valid when each is as probed (as insert_probed asks) and their
    /// cavities lie apart: no triangle of one's cavity is in another's cavity or across its
    /// boundary. The fans are written in `chunks` ranges of the list, by `run` (possibly at
    /// once; empty: one after another); after writing each fan, the chunk's thread calls
    /// written(chunk, position, slots) (when given) with the fan's slots and the position of the
    /// first in the batch's slots (which touched() then lists, in order): it may read those
    /// triangles and the ones beside them, which no other fan writes.
    using FanWritten =
        std::function<void(std::size_t chunk, std::size_t position, std::span<const TriIdx> slots)>;
    void insert_probed_apart(std::span<const CavityProbe* const> probes, std::size_t chunks,
                             const ChunkRunner& run, const FanWritten& written = {});
    /// After insert_in_cavity returned Encroaches: the constrained half-edges (seen from inside
    /// the cavity) whose closed diametral circle holds the point or that it lies beyond.
    std::span<const EdgeIdx> encroached_edges() const;

    /// Splits constrained half-edge e (a -> b) at (x, y), which must lie within rounding of the
    /// segment: exactly on a - b, or off it but inside the two triangles beside it (then the
    /// pieces a - m, m - b bend by at most the rounding). When a neighbouring triangle is a
    /// sliver (a vertex within ulps of the piece), the point moves up to 3 ulps per coordinate
    /// to the sliver's other side. When no such split is possible (a vertex of a neighbouring
    /// triangle lies within rounding of the segment by the check's chain rule,
    /// within_rounding_of_segment, strictly between its ends, for every segment sharing the
    /// piece), the edge bends at that vertex instead. Both pieces keep e's segment(s).
    /// @return the vertex now between a and b (a new one, or the vertex the edge bends at).
    /// @throws GeometryError when (x, y) equals a or b, or no split is possible.
    VertIdx split_constrained_edge(EdgeIdx e, double x, double y);

    /// Room for about `vertices` vertices in all (and their triangles), so that a refinement
    /// that knows its output size does not pay for repeated growth. Only a hint.
    void reserve(std::uint32_t vertices);

    /// Every triangle slot written by edits since the last clear_touched() (with repeats;
    /// some may be dead or rewritten again since): where to look for new bad triangles and
    /// newly encroached edges.
    std::span<const TriIdx> touched() const { return *touched_; }
    void clear_touched() { touched_->clear(); }

    const ConstrainedTriangulation2Counters& counters() const;

    /// The result in the caller's numbering, as constrained_delaunay_2d returns it (exterior and
    /// holes removed, pieces, attributes, warnings; the box's corners left out, vertices added
    /// after them renumbered to close the gap); consumes the triangulation.
    Cdt2Result take_result() &&;

  private:
    struct Owned;
    std::unique_ptr<Owned> owned_;
    detail::CdtState* state_ = nullptr;
    // The state's arrays that the refinement reads per triangle, for the inline readers above
    // (an out-of-line call each was a tenth of the refinement's work on new triangles). The
    // vectors live in *owned_, which never moves.
    const TriMesh2* mesh_ = nullptr;
    const std::vector<std::uint32_t>* segment_of_ = nullptr;
    const std::vector<std::uint8_t>* removed_ = nullptr;
    std::vector<TriIdx>* touched_ = nullptr;
};

}  // namespace exactmesh::triangulation
