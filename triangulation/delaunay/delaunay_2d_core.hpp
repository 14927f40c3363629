// SPDX-License-Identifier: MIT
// Shared machinery of the 2D Delaunay constructions (internal to triangulation/): the points in
// insertion order, the exact conflict test with the infinite vertex, the visibility walk, the
// first triangle, and the conversion to the caller's numbering.
#pragma once

#include <chrono>
#include <cstdint>
#include <span>
#include <vector>

#include "base/errors.hpp"
#include "base/stopwatch.hpp"
#include "predicates/incircle.hpp"
#include "predicates/orient2d.hpp"
#include "predicates/sign.hpp"
#include "triangulation/delaunay/delaunay_2d.hpp"
#include "triangulation/delaunay/result_numbering.hpp"
#include "triangulation/delaunay/walk_random.hpp"
#include "triangulation/mesh/mesh2.hpp"

namespace exactmesh::triangulation::detail {

using predicates::Sign;

using exactmesh::microseconds_since;

/// One edge o -> d of a Bowyer-Watson cavity's boundary: `inside` the half-edge of a cavity
/// triangle, `outside` its twin in a triangle that stays.
struct CavityEdge2 {
    EdgeIdx inside, outside;
    VertIdx origin, destination;
};

/// True when one of the three vertices of a live triangle is kInfinite: a finite vertex is
/// below 2^31 and kInfinite is not, so one test of the top bit covers the three.
inline bool has_infinite_vertex(const VertIdx* v) {
    constexpr std::uint32_t kTopBit = 0x80000000u;
    static_assert(kMaxPoints < kTopBit && (kInfinite & kTopBit) != 0);
    return ((v[0] | v[1] | v[2]) & kTopBit) != 0;
}

/// incircle's exact tie (the four points cocircular): the symbolic perturbation by the
/// caller's indices `input_index` (mesh vertex -> caller's index).
Sign incircle_tie_2d(const TriMesh2& mesh, const std::vector<VertIdx>& input_index, VertIdx a,
                     VertIdx b, VertIdx c, VertIdx d);

/// The perturbed incircle of four finite mesh vertices (incircle_tie_2d on an exact tie),
/// counted in `counters`. Inline (the filter's stage too): Bowyer-Watson cavities call it for
/// every triangle they meet, and the call cost a fifth of the filter's work.
inline Sign incircle_2d(const TriMesh2& mesh, const std::vector<VertIdx>& input_index,
                        Delaunay2Counters& counters, VertIdx a, VertIdx b, VertIdx c, VertIdx d) {
    ++counters.incircle_calls;
    const Sign s = predicates::incircle(mesh.point(a), mesh.point(b), mesh.point(c), mesh.point(d));
    return s != Sign::Zero ? s : incircle_tie_2d(mesh, input_index, a, b, c, d);
}

/// conflict_2d for an infinite triangle (a, b, inf): p beyond the hull edge ab, or strictly
/// inside the segment ab.
bool conflict_infinite_2d(const TriMesh2& mesh, Delaunay2Counters& counters, TriIdx t, VertIdx p);

/// True when p lies in the perturbed circumcircle of the live triangle t (for an infinite
/// triangle, conflict_infinite_2d): the conflict test of the sequential and the parallel
/// constructions, counted in `counters`.
inline bool conflict_2d(const TriMesh2& mesh, const std::vector<VertIdx>& input_index,
                        Delaunay2Counters& counters, TriIdx t, VertIdx p) {
    const VertIdx* v = &mesh.tv[3 * static_cast<std::size_t>(t)];
    if (has_infinite_vertex(v)) return conflict_infinite_2d(mesh, counters, t, p);
    return incircle_2d(mesh, input_index, counters, v[0], v[1], v[2], p) == Sign::Positive;
}

/// A triangle of a Bowyer-Watson cavity and its vertices, read before its slot was marked dead.
struct CavityTriangle2 {
    TriIdx triangle;
    VertIdx v[3];
};

/// A Bowyer-Watson cavity: its triangles and its boundary edges (o -> d with the cavity on the
/// left), in buffers kept between insertions that grow and never shrink, written through counts
/// (push_back's growth check per entry cost about 74 instructions per point at 10^6 uniform
/// points, 4% of the insertion's).
class Cavity2 {
  public:
    std::span<const CavityTriangle2> triangles() const {
        return {triangles_.data(), triangle_count_};
    }
    std::span<const CavityEdge2> boundary() const { return {boundary_.data(), boundary_count_}; }

    /// The conflict region of p grown from `seed` (in conflict with p), breadth first (it is
    /// connected [Watson81]). `conflict(u)` tells whether p lies in the perturbed circumcircle
    /// of the live triangle u; `may_join(u)` whether u may join (a parallel worker's
    /// partition). A triangle is marked dead (tv[3t] = kNone) when it joins, so the search
    /// needs no visit marks: the conflict test reads that entry anyway. When a triangle in
    /// conflict may not join, the marks are undone and it returns false: the mesh is as it was.
    template <class Conflict, class MayJoin>
    bool find(TriMesh2& mesh, TriIdx seed, Conflict&& conflict, MayJoin&& may_join) {
        triangle_count_ = boundary_count_ = 0;
        reserve(1);
        join(mesh, seed);
        for (std::size_t i = 0; i < triangle_count_; ++i) {
            reserve(3);  // at most three more entries in each buffer
            const CavityTriangle2 c = triangles_[i];
            // The three neighbours' vertices asked for at once, before the first test waits
            // on one of them.
            const EdgeIdx* const twins = &mesh.twin[3 * static_cast<std::size_t>(c.triangle)];
            for (unsigned k = 0; k < 3; ++k)
                __builtin_prefetch(&mesh.tv[3 * static_cast<std::size_t>(triangle_of(twins[k]))]);
            for (unsigned k = 0; k < 3; ++k) {
                const EdgeIdx e = 3 * c.triangle + k;
                const EdgeIdx f = twins[k];
                const TriIdx u = triangle_of(f);
                if (mesh.is_dead(u)) continue;  // in the cavity already
                if (!conflict(u)) {
                    boundary_[boundary_count_++] = {e, f, c.v[k], c.v[k == 2 ? 0 : k + 1]};
                } else if (may_join(u)) {
                    join(mesh, u);
                } else {
                    for (const CavityTriangle2& t : triangles()) mesh.tv[3 * t.triangle] = t.v[0];
                    return false;
                }
            }
        }
        return true;
    }

  private:
    void reserve(std::size_t more) {
        if (triangles_.size() < triangle_count_ + more)
            triangles_.resize(2 * triangles_.size() + 16);
        if (boundary_.size() < boundary_count_ + more) boundary_.resize(2 * boundary_.size() + 16);
    }
    void join(TriMesh2& mesh, TriIdx t) {
        VertIdx* const v = &mesh.tv[3 * static_cast<std::size_t>(t)];
        triangles_[triangle_count_++] = {t, {v[0], v[1], v[2]}};
        v[0] = kNone;
        __builtin_prefetch(&mesh.twin[3 * static_cast<std::size_t>(t)]);  // read when it is grown
    }

    std::vector<CavityTriangle2> triangles_;
    std::vector<CavityEdge2> boundary_;
    std::size_t triangle_count_ = 0, boundary_count_ = 0;
};

/// Bowyer-Watson's star of p over a cavity's boundary: a triangle (o, d, p) on each boundary
/// edge o -> d, counter-clockwise because the cavity is star-shaped from p, in boundary order,
/// its slot from allocate(); linked across o -> d to `outside`, and its edge d -> p to edge
/// p -> d of the triangle on the boundary edge that starts at d (unique: the boundary is one
/// closed cycle), found through `starting_at` (per vertex, the last entry for kInfinite: n + 1
/// entries). Scanning the boundary's origins instead, as the constrained triangulation's fan
/// does, made 10^6 uniform points' insertion 11% slower (306 -> 340 ms): here the table's
/// entries are hot (neighbours in BRIO order) and the scan's loop exits mispredict. Returns the
/// first new triangle.
template <class Allocate>
TriIdx connect_star_2d(TriMesh2& mesh, std::span<const CavityEdge2> boundary, VertIdx p,
                       Allocate&& allocate, std::vector<TriIdx>& starting_at) {
    const std::uint32_t n = mesh.vertex_count();
    const auto slot = [n](VertIdx v) { return v == kInfinite ? n : v; };
    TriIdx first = kNone;
    for (const CavityEdge2& b : boundary) {
        const TriIdx t = allocate();
        mesh.tv[3 * t] = b.origin;
        mesh.tv[3 * t + 1] = b.destination;
        mesh.tv[3 * t + 2] = p;
        mesh.link(3 * t, b.outside);
        if (first == kNone) first = t;
        starting_at[slot(b.origin)] = t;
    }
    for (const CavityEdge2& b : boundary) {
        const TriIdx t = starting_at[slot(b.origin)];
        const TriIdx u = starting_at[slot(b.destination)];
        mesh.link(3 * t + 1, 3 * u + 2);
    }
    return first;
}

/// Replaces the cavity found by Cavity2::find with p's star (connect_star_2d). The star has
/// two triangles more than the cavity: the cavity is a disk whose vertices all lie on its
/// boundary (no vertex leaves a Delaunay triangulation, and the infinite vertex cannot be
/// inside, p cannot see every hull edge), so by Euler's formula its b boundary edges bound
/// c = b - 2 triangles. The star's triangles take the cavity's slots, last found first (the
/// order a free list gave them), then two from `allocate()`. Returns the first new triangle.
template <class Allocate>
TriIdx replace_cavity_2d(TriMesh2& mesh, std::span<const CavityTriangle2> cavity,
                         std::span<const CavityEdge2> boundary, VertIdx p, Allocate&& allocate,
                         std::vector<TriIdx>& starting_at) {
    EM_ASSERT(boundary.size() == cavity.size() + 2);
    std::size_t next = cavity.size();
    return connect_star_2d(
        mesh, boundary, p, [&] { return next > 0 ? cavity[--next].triangle : allocate(); },
        starting_at);
}

/// The visibility walk [Devillers, Pion, Teillaud 2002] from the finite triangle t to p: a
/// triangle containing p (closed), or an infinite one whose hull edge sees p; kNone when
/// `may_enter(u)` refuses the next triangle u (then `stopped` is the last one entered).
/// The edge a step entered by has p strictly on its left (the step left the other triangle
/// because p was strictly right of it), so it is not tested again. For the first
/// `fixed_order_steps` steps the other two are tested in a fixed order, the edge before the
/// entered one first: in a (perturbed) Delaunay triangulation this walk never comes back to a
/// triangle [Edelsbrunner 1990, acyclicity of the in-front relation; DPT02 §2], so it needs no
/// random choice. At 10^6 uniform points (BRIO) it makes 6.63 orientation tests per point,
/// against 7.32 with the edge after the entered one first and 6.85 for a random choice, which
/// took 6% longer (its branches mispredict). Then each step starts at `random_offset()`, which
/// ends on any triangulation. The orders end in the same triangle by different paths: the
/// parallel workers, whose walks must stay in their partition, keep the random order from the
/// first step (with the fixed one their paths left it far more often: 90,414 deferred points
/// against 25,386 at 10^6 uniform points on 2 threads).
template <class MayEnter, class RandomOffset>
TriIdx visibility_walk_2d(const TriMesh2& mesh, TriIdx t, VertIdx p, Delaunay2Counters& counters,
                          std::uint64_t fixed_order_steps, MayEnter&& may_enter,
                          RandomOffset&& random_offset, TriIdx& stopped) {
    const VertIdx* const tv = mesh.tv.data();
    const EdgeIdx* const twin = mesh.twin.data();
    const double* const pp = mesh.point(p);
    static constexpr std::uint32_t kAfter[4] = {1, 2, 0, 0};   // local edge after k
    static constexpr std::uint32_t kBefore[4] = {2, 0, 1, 1};  // before k; none entered: 1
    std::uint64_t steps = 0;
    EdgeIdx entered = kNone;
    for (;;) {
        ++steps;
        const VertIdx* const v = tv + 3 * static_cast<std::size_t>(t);
        if (entered != kNone) {
            // Both triangles the step may go to next, asked for while the tests below wait
            // on t's corners.
            const std::uint32_t j = entered - 3 * t;
            __builtin_prefetch(tv + 3 * static_cast<std::size_t>(
                                            triangle_of(twin[3 * std::size_t{t} + kBefore[j]])));
            __builtin_prefetch(tv + 3 * static_cast<std::size_t>(
                                            triangle_of(twin[3 * std::size_t{t} + kAfter[j]])));
        }
        if (has_infinite_vertex(v)) break;  // crossed a hull edge that sees p
        const double* const corner[3] = {mesh.point(v[0]), mesh.point(v[1]), mesh.point(v[2])};
        // orient2d(corner[k], corner[k + 1], p) for the edges tested, each difference taken once.
        const double dx[3] = {corner[0][0] - pp[0], corner[1][0] - pp[0], corner[2][0] - pp[0]};
        const double dy[3] = {corner[0][1] - pp[1], corner[1][1] - pp[1], corner[2][1] - pp[1]};
        // True when p is strictly right of edge k (corner k to k + 1): beyond it.
        const auto beyond = [&](std::uint32_t k) {
            ++counters.orient_calls;
            const std::uint32_t j = kAfter[k];
            return predicates::orient2d_with_differences(corner[k], corner[j], pp, dx[k], dy[k],
                                                         dx[j], dy[j]) == Sign::Negative;
        };
        std::uint32_t next = 3;  // the edge to cross; 3: none, t holds p
        if (entered != kNone && steps <= fixed_order_steps) {
            // The two edges other than the entered one, unrolled (the common step).
            const std::uint32_t j = entered - 3 * t;
            if (beyond(kBefore[j])) {
                next = kBefore[j];
            } else if (beyond(kAfter[j])) {
                next = kAfter[j];
            }
        } else {
            const std::uint32_t skip = entered == kNone ? 3 : entered - 3 * t;
            std::uint32_t k = steps > fixed_order_steps ? random_offset() : kBefore[3];
            for (std::uint32_t i = 0; i < 3; ++i, k = kAfter[k]) {
                if (k != skip && beyond(k)) {
                    next = k;
                    break;
                }
            }
        }
        if (next == 3) break;
        const EdgeIdx across = twin[3 * t + next];
        if (!may_enter(triangle_of(across))) {
            counters.walk_steps += steps;
            stopped = t;
            return kNone;
        }
        entered = across;
        t = triangle_of(across);
    }
    counters.walk_steps += steps;
    stopped = t;
    return t;
}

class Delaunay2Core {
  public:
    /// Validates the input, orders it (options.order) and copies it into mesh.xy.
    Delaunay2Core(std::span<const double> xy, const Delaunay2Options& options);
    /// Same, with mesh vertex v holding the caller's point order[v] (a permutation), copied in
    /// chunks on `run`'s threads when given.
    /// @pre xy validated (validate_points_2d): the order was computed from it.
    Delaunay2Core(std::span<const double> xy, std::vector<VertIdx> order,
                  const ChunkRunner& run = {});

    TriMesh2 mesh;
    std::vector<VertIdx> input_index;  ///< mesh vertex -> caller's index
    std::vector<VertIdx> merged_into;  ///< caller's index -> first caller index with equal point
    Delaunay2Counters counters;

    /// Exact orientation of three finite mesh vertices.
    Sign orient(VertIdx a, VertIdx b, VertIdx c);
    /// Perturbed incircle of four finite mesh vertices (incircle_2d, the core's counters).
    Sign incircle(VertIdx a, VertIdx b, VertIdx c, VertIdx d) {
        return incircle_2d(mesh, input_index, counters, a, b, c, d);
    }
    /// True when p lies in the perturbed circumcircle of t (conflict_2d, the core's counters).
    /// @pre t is not dead.
    bool conflict(TriIdx t, VertIdx p) { return conflict_2d(mesh, input_index, counters, t, p); }
    /// True when the finite points a, b, p are collinear and p lies strictly between a and b.
    bool strictly_between(VertIdx a, VertIdx b, VertIdx p) const;
    bool same_point(VertIdx a, VertIdx b) const {
        const double* p = mesh.point(a);
        const double* q = mesh.point(b);
        return p[0] == q[0] && p[1] == q[1];
    }

    /// Builds the first triangle and its three infinite neighbours from the first three
    /// non-collinear points in insertion order; records duplicates met on the way. Returns
    /// false when all points are collinear (then there is no triangle). `skip` receives the
    /// mesh vertices already used or merged, so the caller does not insert them again.
    bool make_first_triangle(std::vector<bool>& skip);

    /// Visibility walk [Devillers, Pion, Teillaud 2002] from the last visited triangle to one
    /// in conflict with p. When p equals a vertex, records the duplicate and returns kNone.
    TriIdx locate(VertIdx p);
    /// The visibility walk alone: a triangle containing p (closed) or an infinite triangle
    /// whose hull edge sees p; p may equal one of its vertices. Sets last_triangle.
    TriIdx walk_to(VertIdx p);

    /// The finite triangles in the caller's numbering; consumes the mesh. The compaction runs
    /// in `chunks` slot ranges by `run` (compact_cells): the same result for any chunks.
    Delaunay2Result take_result(std::size_t chunks = 1, const ChunkRunner& run = {});
    /// The result for collinear input (no triangle): only duplicates are detected, by sorting.
    Delaunay2Result collinear_result();

    TriIdx last_triangle = kNone;

    /// Points inserted, for options.progress: the insertion loops tick it once per point.
    ProgressCounter progress;

    /// Records that the triangle last_triangle was made by inserting p (for grid location).
    void note_inserted(VertIdx p);

  private:
    /// Multi-level grid over the bounding box: for each cell of each level, a triangle made by
    /// the last insertion inside it. Levels 0..depth_, level l has 2^l x 2^l cells.
    struct JumpGrid {
        bool enabled = false;
        int depth = 0;
        double min_x = 0, min_y = 0, scale_x = 0, scale_y = 0;
        std::vector<std::uint32_t> level_offset;
        std::vector<TriIdx> triangle;
    } jump_;
    void build_jump_grid(const Delaunay2Options& options);
    /// Finest-level cell coordinates of point p.
    void jump_cell(VertIdx p, std::uint32_t& ix, std::uint32_t& iy) const;

    std::uint64_t rng_state_ = 0x9E3779B97F4A7C15ull;
};

}  // namespace exactmesh::triangulation::detail
