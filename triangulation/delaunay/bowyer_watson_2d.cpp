// SPDX-License-Identifier: MIT
// Bowyer-Watson 2D (see bowyer_watson_2d.hpp).
#include "triangulation/delaunay/bowyer_watson_2d.hpp"

#include <algorithm>
#include <chrono>
#include <vector>

#include "triangulation/delaunay/delaunay_2d_core.hpp"
#include "triangulation/delaunay/parallel_bowyer_watson_2d.hpp"

namespace exactmesh::triangulation {

namespace {

/// The cavity and its boundary, kept between insertions so they allocate nothing.
struct Cavity {
    detail::Cavity2 region;
    std::vector<TriIdx> starting_at;  ///< per vertex (+1 for kInfinite), connect_star_2d's
};

/// New triangle slots: the free list first, then slots past the last one used, made in blocks
/// (one growth of tv and twin per block, not one per triangle). Slots made and not used stay
/// dead (tv == kNone); the result's compaction skips them.
class FreshSlots {
  public:
    explicit FreshSlots(TriMesh2& mesh) : mesh_(mesh), next_(mesh.triangle_slots()) {}

    /// Room for `slots` slots in all without another growth.
    void reserve(std::size_t slots) {
        if (slots > mesh_.triangle_slots()) grow(slots - mesh_.triangle_slots());
    }

    TriIdx take() {
        if (!mesh_.free_triangles.empty()) {
            const TriIdx t = mesh_.free_triangles.back();
            mesh_.free_triangles.pop_back();
            return t;
        }
        if (next_ == mesh_.triangle_slots()) grow(std::max<std::size_t>(1024, next_ / 4));
        return next_++;
    }

  private:
    void grow(std::size_t slots) {
        mesh_.tv.resize(mesh_.tv.size() + 3 * slots, kNone);
        mesh_.twin.resize(mesh_.twin.size() + 3 * slots, kNone);
    }

    TriMesh2& mesh_;
    TriIdx next_;
};

/// Inserts p, whose walk ended in `seed` (in conflict with p).
void insert_point(detail::Delaunay2Core& core, Cavity& cavity, FreshSlots& fresh, VertIdx p,
                  TriIdx seed) {
    TriMesh2& mesh = core.mesh;
    cavity.region.find(
        mesh, seed, [&core, p](TriIdx u) { return core.conflict(u, p); },
        [](TriIdx) { return true; });
    core.counters.cavity_triangles += cavity.region.triangles().size();
    core.last_triangle = detail::replace_cavity_2d(
        mesh, cavity.region.triangles(), cavity.region.boundary(), p,
        [&fresh] { return fresh.take(); }, [&mesh](TriIdx t) { mesh.free_triangles.push_back(t); },
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
    FreshSlots fresh(core.mesh);
    // 2n - 2 triangles in all (the infinite ones too) when no point is merged.
    fresh.reserve(2 * static_cast<std::size_t>(core.mesh.vertex_count()));
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
