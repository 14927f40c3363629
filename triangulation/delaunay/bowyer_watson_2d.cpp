// SPDX-License-Identifier: MIT
// Bowyer-Watson 2D (see bowyer_watson_2d.hpp).
#include "triangulation/delaunay/bowyer_watson_2d.hpp"

#include <chrono>
#include <vector>

#include "base/errors.hpp"
#include "triangulation/delaunay/delaunay_2d_core.hpp"
#include "triangulation/delaunay/parallel_bowyer_watson_2d.hpp"

namespace exactmesh::triangulation {

namespace {

/// The cavity and its boundary, kept between insertions so they allocate nothing.
struct Cavity {
    detail::Cavity2 region;
    std::vector<TriIdx> starting_at;  ///< per vertex (+1 for kInfinite), connect_star_2d's
};

/// Inserts p, whose walk ended in `seed` (in conflict with p).
/// `fresh` is the next unused slot: each insertion takes two.
void insert_point(detail::Delaunay2Core& core, Cavity& cavity, TriIdx& fresh, VertIdx p,
                  TriIdx seed) {
    TriMesh2& mesh = core.mesh;
    cavity.region.find(
        mesh, seed, [&core, p](TriIdx u) { return core.conflict(u, p); },
        [](TriIdx) { return true; });
    core.counters.cavity_triangles += cavity.region.triangles().size();
    core.last_triangle = detail::replace_cavity_2d(
        mesh, cavity.region.triangles(), cavity.region.boundary(), p,
        [&mesh, &fresh] {
            EM_ASSERT(fresh < mesh.triangle_slots());
            return fresh++;
        },
        cavity.starting_at);
}

}  // namespace

Delaunay2Result bowyer_watson_2d(std::span<const double> xy, const Delaunay2Options& options) {
    // The parallel construction partitions the BRIO rounds; other orders run sequentially.
    if (options.threads != 1 && options.order == InsertionOrder::Brio &&
        options.location != PointLocation::Grid) {
        const unsigned threads = resolve_thread_count(options.threads);
        if (threads > 1) return parallel_bowyer_watson_2d(xy, options, threads);
    }
    using Clock = std::chrono::steady_clock;
    Clock::time_point phase = Clock::now();
    detail::Delaunay2Core core(xy, options);
    core.counters.order_microseconds = detail::microseconds_since(phase);
    std::vector<bool> skip;
    if (!core.make_first_triangle(skip)) {
        // All points collinear (or fewer than three distinct): no triangle. Duplicates still
        // map to their first occurrence.
        return core.collinear_result();
    }
    phase = Clock::now();
    Cavity cavity;
    cavity.starting_at.assign(core.mesh.vertex_count() + 1, kNone);
    // Each insertion adds two triangles (replace_cavity_2d), so n points make 2n - 2 in all,
    // the infinite ones included (the first triangle and its three infinite neighbours are 3
    // points' 4), fewer when points are merged: the arrays are sized once. Slots left over stay
    // dead (tv == kNone); the result's compaction skips them.
    TriIdx fresh = core.mesh.triangle_slots();
    const std::size_t slots = 2 * static_cast<std::size_t>(core.mesh.vertex_count());
    core.mesh.tv.resize(3 * slots, kNone);
    core.mesh.twin.resize(3 * slots, kNone);
    for (VertIdx p = 0; p < core.mesh.vertex_count(); ++p) {
        if (skip[p]) continue;
        const TriIdx t = core.locate(p);
        if (t == kNone) continue;  // duplicate, merged
        insert_point(core, cavity, fresh, p, t);
        core.note_inserted(p);
        core.progress.tick();
    }
    core.counters.sequential_microseconds = detail::microseconds_since(phase);
    phase = Clock::now();
    Delaunay2Result result = core.take_result();
    result.counters.result_microseconds = detail::microseconds_since(phase);
    return result;
}

}  // namespace exactmesh::triangulation
