// SPDX-License-Identifier: MIT
// Bowyer-Watson 2D (see bowyer_watson_2d.hpp).
#include "triangulation/delaunay/bowyer_watson_2d.hpp"

#include <chrono>
#include <vector>

#include "triangulation/delaunay/delaunay_2d_core.hpp"
#include "triangulation/delaunay/parallel_bowyer_watson_2d.hpp"

namespace exactmesh::triangulation {

namespace {

/// The cavity and its boundary, kept between insertions so they allocate nothing.
struct Cavity {
    std::vector<TriIdx> triangles;
    std::vector<detail::CavityEdge2> boundary;
    std::vector<std::uint32_t> stamp;  ///< per triangle slot: insertion that visited it
    std::vector<TriIdx> starting_at;   ///< per vertex (+1 for kInfinite), connect_star_2d's
};

void insert_point(detail::Delaunay2Core& core, Cavity& cavity, VertIdx p, TriIdx seed,
                  std::uint32_t stamp) {
    TriMesh2& mesh = core.mesh;
    cavity.triangles.clear();
    cavity.boundary.clear();
    if (cavity.stamp.size() < mesh.triangle_slots())
        cavity.stamp.resize(2 * mesh.triangle_slots(), 0);
    cavity.stamp[seed] = stamp;
    cavity.triangles.push_back(seed);
    // Breadth first: the conflict region is connected [Watson81], so its boundary is reached.
    for (std::size_t i = 0; i < cavity.triangles.size(); ++i) {
        const TriIdx t = cavity.triangles[i];
        for (unsigned k = 0; k < 3; ++k) {
            const EdgeIdx e = 3 * t + k;
            const EdgeIdx f = mesh.twin[e];
            const TriIdx u = triangle_of(f);
            if (cavity.stamp[u] == stamp) continue;
            if (core.conflict(u, p)) {
                cavity.stamp[u] = stamp;
                cavity.triangles.push_back(u);
            } else {
                cavity.boundary.push_back({e, f, mesh.origin(e), mesh.destination(e)});
            }
        }
    }
    core.counters.cavity_triangles += cavity.triangles.size();
    for (const TriIdx t : cavity.triangles) mesh.kill_triangle(t);
    core.last_triangle = detail::connect_star_2d(
        mesh, std::span<const detail::CavityEdge2>(cavity.boundary), p,
        [&mesh] { return mesh.new_triangle(); }, cavity.starting_at);
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
    std::uint32_t stamp = 0;
    for (VertIdx p = 0; p < core.mesh.vertex_count(); ++p) {
        if (skip[p]) continue;
        const TriIdx t = core.locate(p);
        if (t == kNone) continue;  // duplicate, merged
        insert_point(core, cavity, p, t, ++stamp);
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
