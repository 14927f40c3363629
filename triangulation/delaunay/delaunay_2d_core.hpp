// SPDX-License-Identifier: MIT
// Shared machinery of the 2D Delaunay constructions (internal to triangulation/): the points in
// insertion order, the exact conflict test with the infinite vertex, the visibility walk, the
// first triangle, and the conversion to the caller's numbering.
#pragma once

#include <chrono>
#include <cstdint>
#include <span>
#include <vector>

#include "base/stopwatch.hpp"
#include "predicates/incircle.hpp"
#include "predicates/sign.hpp"
#include "triangulation/delaunay/delaunay_2d.hpp"
#include "triangulation/delaunay/result_numbering.hpp"
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
    /// Perturbed incircle of four finite mesh vertices (ties broken by the caller's indices).
    /// Inline (the filter's stage too): Bowyer-Watson cavities call it for every triangle they
    /// meet, and the call cost a fifth of the filter's work.
    Sign incircle(VertIdx a, VertIdx b, VertIdx c, VertIdx d) {
        ++counters.incircle_calls;
        const Sign s =
            predicates::incircle(mesh.point(a), mesh.point(b), mesh.point(c), mesh.point(d));
        return s != Sign::Zero ? s : incircle_tie(a, b, c, d);
    }
    /// True when p lies in the perturbed circumcircle of t (for an infinite triangle (a, b, inf):
    /// beyond the hull edge ab, or strictly inside the segment ab).
    bool conflict(TriIdx t, VertIdx p) {
        const VertIdx* v = &mesh.tv[3 * t];
        if (v[0] == kInfinite || v[1] == kInfinite || v[2] == kInfinite) {
            return conflict_infinite(t, p);
        }
        return incircle(v[0], v[1], v[2], p) == Sign::Positive;
    }
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
    /// incircle's exact tie (the four points cocircular): the symbolic perturbation.
    Sign incircle_tie(VertIdx a, VertIdx b, VertIdx c, VertIdx d) const;
    /// conflict for an infinite triangle.
    bool conflict_infinite(TriIdx t, VertIdx p);

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
    std::uint32_t random_offset();
};

}  // namespace exactmesh::triangulation::detail
