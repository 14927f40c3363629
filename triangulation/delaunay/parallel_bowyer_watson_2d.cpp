// SPDX-License-Identifier: MIT
// Multicore Bowyer-Watson 2D (see parallel_bowyer_watson_2d.hpp).
#include "triangulation/delaunay/parallel_bowyer_watson_2d.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>
#include <tbb/task_group.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <functional>
#include <optional>
#include <thread>
#include <vector>

#include "base/errors.hpp"
#include "base/huge_pages.hpp"
#include "predicates/incircle.hpp"
#include "predicates/orient2d.hpp"
#include "predicates/sos.hpp"
#include "triangulation/delaunay/delaunay_2d_core.hpp"
#include "triangulation/delaunay/parallel_rounds.hpp"
#include "triangulation/mesh/spatial_sort.hpp"

namespace exactmesh::triangulation {

namespace {

using predicates::Sign;

/// Flags of Shared::hints, above the triangle index (a triangle beyond kHintIndex, past about
/// 5·10^8 points, is not kept as a hint).
constexpr TriIdx kHintIndex = 0x3FFFFFFFu;
constexpr TriIdx kHintStart = 0x40000000u;      ///< the triangle is the point's worker's
constexpr TriIdx kHintElsewhere = 0x80000000u;  ///< it is not

/// What the threads share. During a pass each thread writes only: tv and twin of triangles of
/// its partition (and slots of its own free list and fresh range), the twin half-edge of a
/// mixed triangle facing its cavity, and merged_into of its own points.
struct Shared {
    TriMesh2& mesh;
    std::span<const std::uint32_t> keys;  ///< per mesh vertex: the key of this pass's curve
    const std::vector<VertIdx>& input_index;
    std::vector<VertIdx>& merged_into;
    /// Per vertex (+1 for kInfinite): the new triangle on edge v -> * of the current insertion.
    /// A worker writes only the entries of cavity boundary vertices, which are in its range.
    std::vector<TriIdx>* starting_at = nullptr;
    /// Per mesh vertex: where the last attempt to insert it stopped (kNone: not tried yet),
    /// written by the thread that tried it, read in a later pass (Worker::classify_hints).
    std::vector<TriIdx>* hints = nullptr;
};

enum class Outcome { Inserted, Merged, Deferred };

/// One thread's partition, allocator, scratch and counters (kept from pass to pass, so a thread
/// reuses the fresh slots a pass left unused, in its free list).
/// Aligned to whole cache-line pairs: the counters and scratch one worker writes on every
/// predicate and insertion must not share a line (or the adjacent-line prefetch pair) with what
/// the next worker reads on every triangle (its range).
struct alignas(128) Worker {
    detail::KeyRange range;
    bool owns_all = false;  ///< the sequential prefix and tail: every triangle is ours
    std::vector<TriIdx> free_slots;
    TriIdx fresh_next = 0, fresh_end = 0;

    detail::Cavity2 cavity;
    TriIdx last = kNone;  ///< where the next walk starts (a triangle of ours)
    std::uint64_t rng_state = 0x9E3779B97F4A7C15ull;

    std::span<const VertIdx> points;  ///< this pass's points, in Hilbert order
    std::size_t start = 0;            ///< the point whose walk found `last`
    std::vector<VertIdx> deferred;
    Delaunay2Counters counters{};

    bool owns_vertex(const Shared& shared, VertIdx v) const {
        if (owns_all) return true;
        if (v == kInfinite) return false;
        return range.holds(shared.keys[v]);
    }
    bool owns(const Shared& shared, TriIdx t) const {
        if (owns_all) return true;
        const VertIdx* v = &shared.mesh.tv[3 * t];
        return owns_vertex(shared, v[0]) && owns_vertex(shared, v[1]) && owns_vertex(shared, v[2]);
    }

    /// The conflict test (detail::conflict_2d), counted here (the core's counters are not
    /// shared between threads).
    bool conflict(const Shared& shared, TriIdx t, VertIdx p) {
        return detail::conflict_2d(shared.mesh, shared.input_index, counters, t, p);
    }

    TriIdx allocate(TriMesh2& mesh) {
        if (!free_slots.empty()) {
            const TriIdx t = free_slots.back();
            free_slots.pop_back();
            return t;
        }
        if (fresh_next < fresh_end) return fresh_next++;
        // Only the sequential worker may grow the arrays (its fresh range is then the arrays'
        // tail): no thread runs beside it.
        EM_ASSERT(owns_all && fresh_end == mesh.triangle_slots());
        mesh.tv.resize(mesh.tv.size() + 3, kNone);
        mesh.twin.resize(mesh.twin.size() + 3, kNone);
        ++fresh_end;
        return fresh_next++;
    }

    /// Visibility walk from `last` (as Delaunay2Core::walk_to) that gives up on leaving the
    /// partition: then kNone, and `last` becomes the last triangle of ours it crossed.
    TriIdx walk(const Shared& shared, VertIdx p, TriIdx from) {
        const TriMesh2& mesh = shared.mesh;
        TriIdx t = from;
        if (mesh.is_infinite(t)) {
            // Only the sequential worker owns infinite triangles: step across the hull edge.
            for (unsigned k = 0; k < 3; ++k) {
                const EdgeIdx e = 3 * t + k;
                if (mesh.tv[e] != kInfinite && mesh.tv[next_edge(e)] != kInfinite) {
                    t = triangle_of(mesh.twin[e]);
                    break;
                }
            }
        }
        // Leaving the partition: the next points lie near p, so their walks start here, not
        // again from where this one did (which, for points along a border, crossed most of the
        // partition each time).
        TriIdx stopped = kNone;
        // In the random order from the first step (see visibility_walk_2d).
        const TriIdx found = detail::visibility_walk_2d(
            mesh, t, p, counters, 0, [this, &shared](TriIdx u) { return owns(shared, u); },
            [this] { return detail::walk_random_offset_2d(rng_state); }, stopped);
        if (found == kNone) last = stopped;
        return found;
    }

    /// Inserts p (Bowyer-Watson, as bowyer_watson_2d's insert_point) when its walk and cavity
    /// stay in the partition; else changes nothing and returns Deferred.
    Outcome insert(Shared& shared, VertIdx p) {
        TriMesh2& mesh = shared.mesh;
        TriIdx& hint = (*shared.hints)[p];
        if (!owns_all && hint != kNone && (hint & kHintElsewhere) != 0) {
            return Outcome::Deferred;  // it lies next to another partition's triangles
        }
        const TriIdx from = start_for(shared, p, hint);
        if (from == kNone) return Outcome::Deferred;
        const TriIdx seed = walk(shared, p, from);
        if (seed == kNone) {
            if (last <= kHintIndex) hint = last;  // where the walk stopped
            return Outcome::Deferred;
        }
        if (!mesh.is_infinite(seed)) {
            for (unsigned k = 0; k < 3; ++k) {
                const VertIdx v = mesh.tv[3 * seed + k];
                const double* a = mesh.point(v);
                const double* b = mesh.point(p);
                if (a[0] == b[0] && a[1] == b[1]) {
                    shared.merged_into[shared.input_index[p]] = shared.input_index[v];
                    ++counters.duplicates;
                    last = seed;
                    return Outcome::Merged;
                }
            }
        }
        // A neighbour of a triangle of ours is ours or mixed (they share two vertices), so
        // reading it is safe; a mixed one may bound the cavity but not join it. The cavity's
        // dead marks are on triangles of ours, which no other worker reads.
        if (!cavity.find(
                mesh, seed, [&](TriIdx u) { return conflict(shared, u, p); },
                [&](TriIdx u) { return owns(shared, u); })) {
            last = seed;  // ours and untouched: near the next points
            if (seed <= kHintIndex) hint = seed;
            return Outcome::Deferred;
        }
        counters.cavity_triangles += cavity.triangles().size();
        // The entries of starting_at the star may write are its own vertices' (cavity triangles
        // are ours), so no other worker touches them during the pass.
        for (const detail::CavityEdge2& b : cavity.boundary())
            EM_ASSERT(owns_vertex(shared, b.origin) && owns_vertex(shared, b.destination));
        last = detail::replace_cavity_2d(
            mesh, cavity.triangles(), cavity.boundary(), p, [&] { return allocate(mesh); },
            *shared.starting_at);
        return Outcome::Inserted;
    }

    /// A triangle of ours p's walk may start from: `last` or, when nearer to p (a guess from
    /// rounded coordinates: any start gives the same insertion), where p's last attempt
    /// stopped (`hint`, p's entry of the hints); kNone when neither may. A point deferred along one
    /// curve's border is tried next along the other curve, far from the last point there.
    TriIdx start_for(const Shared& shared, VertIdx p, TriIdx hint) const {
        const TriMesh2& mesh = shared.mesh;
        if (hint != kNone && (owns_all || (hint & kHintStart) != 0)) {
            const TriIdx h = hint & kHintIndex;
            // Ours at the pass's start, so only this thread has changed it since.
            if (!mesh.is_dead(h) && owns(shared, h)) {
                if (last == kNone) return h;
                return distance_to(shared, h, p) < distance_to(shared, last, p) ? h : last;
            }
        }
        return last;
    }

    /// The larger coordinate difference between p and a finite corner of t (no overflow to a
    /// decision: only a choice between two starts).
    static double distance_to(const Shared& shared, TriIdx t, VertIdx p) {
        const TriMesh2& mesh = shared.mesh;
        const VertIdx* v = &mesh.tv[3 * t];
        const double* a = mesh.point(v[0] != kInfinite ? v[0] : v[1]);
        const double* q = mesh.point(p);
        return std::max(std::fabs(a[0] - q[0]), std::fabs(a[1] - q[1]));
    }

    /// Before a pass, with every thread only reading: the hint of each of this pass's points
    /// flagged kHintStart when that triangle is this partition's (then only this thread changes
    /// it during the pass), else kHintElsewhere (p lies next to another partition's or mixed
    /// triangles: it waits without walking); dropped when the triangle is dead.
    void classify_hints(Shared& shared) const {
        std::vector<TriIdx>& hints = *shared.hints;
        for (const VertIdx p : points) {
            if (hints[p] == kNone) continue;
            const TriIdx t = hints[p] & kHintIndex;
            if (shared.mesh.is_dead(t)) {
                hints[p] = kNone;
            } else {
                hints[p] = t | (owns(shared, t) ? kHintStart : kHintElsewhere);
            }
        }
    }

    /// Inserts this pass's points from points[start] (whose walk found `last` in the
    /// partition) to the end, then back from points[start - 1] to the first, so that each walk
    /// is short; the deferred ones go to `deferred`, sorted as `points`.
    void run(Shared& shared) {
        deferred.clear();
        if (last == kNone) {
            deferred.assign(points.begin(), points.end());
        } else {
            Sweep sweep{*this, shared};
            detail::sweep_partition(sweep, points, start, shared.keys, deferred);
        }
        counters.deferred_points += deferred.size();
    }

    /// The worker as detail::sweep_partition's sweep.
    struct Sweep {
        Worker& worker;
        Shared& shared;
        TriIdx anchor = kNone;

        bool try_insert(VertIdx p) {
            if (worker.insert(shared, p) == Outcome::Deferred) return false;
            ++worker.counters.parallel_points;
            return true;
        }
        bool same_point(VertIdx a, VertIdx b) const {
            const double* pa = shared.mesh.point(a);
            const double* pb = shared.mesh.point(b);
            return pa[0] == pb[0] && pa[1] == pb[1];
        }
        void remember_start() { anchor = worker.last; }
        /// Back to the start: the anchor slot is ours (made or reused by this worker only).
        void return_to_start() {
            if (anchor != kNone && !shared.mesh.is_dead(anchor) && worker.owns(shared, anchor))
                worker.last = anchor;
        }
    };
};

void add_work_counters(Delaunay2Counters& to, const Delaunay2Counters& from) {
    to.duplicates += from.duplicates;
    to.orient_calls += from.orient_calls;
    to.incircle_calls += from.incircle_calls;
    to.walk_steps += from.walk_steps;
    to.cavity_triangles += from.cavity_triangles;
    to.parallel_points += from.parallel_points;
    to.deferred_points += from.deferred_points;
}

/// The second pass's curve: the Hilbert curve of the grid moved by 0.382 of its width (the golden
/// section, far from dyadic and third fractions) along both axes (wrapping around). Its ranges'
/// borders are not the dyadic lines of the first curve's (which a transposed curve would share: its
/// quarters are the same quadrants), so the points deferred along the first borders mostly lie
/// inside them.
constexpr std::uint32_t kSecondCurveShift = 25033;  // 2^16 (1 - 0.618...)

/// What is computed on the arena before the mesh exists: the BRIO order, both curves' keys (in
/// the caller's order), the mesh arrays sized for every pass (tv kNone: dead slots) and the
/// per-vertex arrays (first touched here, beside the order, not by the calling thread alone).
struct Prepared {
    std::vector<VertIdx> order;
    std::vector<std::uint32_t> keys[2];
    std::vector<VertIdx> tv;
    std::vector<EdgeIdx> twin;
    std::vector<TriIdx> starting_at;  ///< n + 1 entries kNone (ParallelConstruction's)
    std::vector<TriIdx> hints;        ///< n entries kNone
};

Prepared prepare(std::span<const double> xy, std::uint64_t seed, unsigned threads,
                 tbb::task_arena& arena) {
    const std::size_t n = xy.size() / 2;
    // The passes hand out about 2 (n + deferred points) fresh slots: sized once, here, beside
    // the order (growing pass by pass copied the arrays and left their first touch, page
    // faults included, to the calling thread between passes).
    const std::size_t slots = 4 + 2 * n + n / 8 + 64 * std::size_t{threads};
    Prepared out;
    // On huge pages where the kernel grants them: a page fault per 2 MiB, not per 4 KiB.
    auto make_array = [](std::vector<std::uint32_t>& array, std::size_t size, std::uint32_t fill) {
        array.reserve(size);
        advise_huge_pages(array);
        array.assign(size, fill);
    };
    // The random stream beside both curves' keys, then the rounds beside the arrays (the order
    // as one thread's insertion_order_2d: as a single task, its nested parallel parts found the
    // other thread busy, and it ended 14 ms after everything else on 10^6 points).
    std::vector<std::uint32_t> position;
    detail::run_together(
        arena,
        [&] { position = inverse_permutation(random_permutation(xy.size() / 2, seed), true); },
        [&] { out.keys[0] = hilbert_keys_2d(xy, 0, true); },
        [&] { out.keys[1] = hilbert_keys_2d(xy, kSecondCurveShift, true); });
    detail::run_together(
        arena, [&] { out.order = brio_order(out.keys[0], position, true); },
        [&] { make_array(out.tv, 3 * slots, kNone); },
        [&] { make_array(out.twin, 3 * slots, kNone); },
        [&] {
            out.starting_at.assign(n + 1, kNone);
            out.hints.assign(n, kNone);
        });
    return out;
}

class ParallelConstruction {
  public:
    /// `arena` runs the T = `threads` partitions (on fewer threads if it has fewer); `prepared`
    /// (of the same points and T) gives its arrays and keys.
    ParallelConstruction(detail::Delaunay2Core& core, unsigned threads, tbb::task_arena& arena,
                         Prepared& prepared)
        : core_(core),
          shared_{core.mesh, {}, core.input_index, core.merged_into},
          workers_(threads),
          arena_(arena) {
        const std::uint32_t n = core.mesh.vertex_count();
        TriMesh2& mesh = core.mesh;
        // The prepared arrays take the first triangles' entries and replace the mesh's.
        high_water_ = mesh.triangle_slots();
        EM_ASSERT(prepared.tv.size() >= mesh.tv.size());
        std::copy(mesh.tv.begin(), mesh.tv.end(), prepared.tv.begin());
        std::copy(mesh.twin.begin(), mesh.twin.end(), prepared.twin.begin());
        mesh.tv.swap(prepared.tv);
        mesh.twin.swap(prepared.twin);
        detail::keys_by_mesh_vertex(runner_, arena_, core.input_index, prepared.keys, keys_);
        shared_.keys = keys_[0];
        starting_at_.swap(prepared.starting_at);
        EM_ASSERT(starting_at_.size() == std::size_t{n} + 1);
        shared_.starting_at = &starting_at_;
        hints_.swap(prepared.hints);
        EM_ASSERT(hints_.size() == n);
        shared_.hints = &hints_;
        sequential_.owns_all = true;
    }

    /// Inserts `points` one by one (the prefix and the tail).
    void insert_sequentially(std::span<const VertIdx> points) {
        sequential_.last = core_.last_triangle;
        sequential_.fresh_next = high_water_;
        sequential_.fresh_end = core_.mesh.triangle_slots();
        for (const VertIdx p : points) {
            const Outcome outcome = sequential_.insert(shared_, p);
            EM_ASSERT(outcome != Outcome::Deferred);
            core_.progress.tick();
        }
        core_.last_triangle = sequential_.last;
        high_water_ = sequential_.fresh_next;
        sequential_.fresh_end = sequential_.fresh_next;
    }

    /// One pass: `points` (sorted by the keys of `curve`, from bounds[0] on, wrapping) cut by
    /// `bounds` (T + 1 increasing keys of that curve, as key_range_bounds) into the workers'
    /// ranges; returns the deferred points, in the order of `points`.
    std::vector<VertIdx> pass(std::span<const VertIdx> points, int curve,
                              const std::vector<std::uint64_t>& bounds) {
        TriMesh2& mesh = core_.mesh;
        const std::vector<std::uint32_t>& keys = keys_[curve];
        shared_.keys = keys;
        const std::size_t count = workers_.size();
        // Each insertion writes its star (k + 2 triangles) over its cavity's k: two fresh slots
        // per point cover a worker's whole list, so the arrays need not grow during the pass.
        const std::vector<std::span<const VertIdx>> parts =
            detail::split_by_bounds(keys, points, bounds);
        for (std::size_t w = 0; w < count; ++w) {
            Worker& worker = workers_[w];
            worker.range = {bounds[w], bounds[w + 1]};
            worker.points = parts[w];
            for (TriIdx t = worker.fresh_next; t < worker.fresh_end; ++t)
                worker.free_slots.push_back(t);
            const std::size_t needed = 2 * worker.points.size() + 2;
            worker.fresh_next = high_water_;
            worker.fresh_end = static_cast<TriIdx>(worker.fresh_next + needed);
            high_water_ = worker.fresh_end;
        }
        if (mesh.triangle_slots() < high_water_) {
            // Rare: more deferred points than the first sizing allowed for.
            const std::size_t slots = high_water_ + high_water_ / 8;
            mesh.tv.resize(3 * slots, kNone);
            mesh.twin.resize(3 * slots, kNone);
        }
        for (Worker& worker : workers_) {
            find_start(worker);
        }
        runner_.run(arena_, count, [&](std::size_t w) { workers_[w].classify_hints(shared_); });
        const auto started = std::chrono::steady_clock::now();
        runner_.run(arena_, count, [&](std::size_t w) { workers_[w].run(shared_); });
        core_.counters.parallel_microseconds += detail::microseconds_since(started);
        std::vector<VertIdx> deferred;
        for (Worker& worker : workers_) {
            for (std::size_t i = worker.deferred.size(); i < worker.points.size(); ++i)
                core_.progress.tick();
            deferred.insert(deferred.end(), worker.deferred.begin(), worker.deferred.end());
            if (worker.last != kNone) core_.last_triangle = worker.last;
        }
        ++core_.counters.parallel_rounds;
        return deferred;
    }

    /// The ranges of a pass over `points` along `curve`, about equal in points.
    std::vector<std::uint64_t> bounds(std::span<const VertIdx> points, int curve,
                                      bool shifted) const {
        return detail::key_range_bounds(keys_[curve], points, workers_.size(), shifted);
    }

    const std::vector<std::uint32_t>& keys(int curve) const { return keys_[curve]; }

    /// Drops the unused slots at the arrays' end (all dead).
    void trim() {
        core_.mesh.tv.resize(3 * static_cast<std::size_t>(high_water_));
        core_.mesh.twin.resize(3 * static_cast<std::size_t>(high_water_));
    }

    void finish_counters() {
        for (const Worker& worker : workers_) add_work_counters(core_.counters, worker.counters);
        add_work_counters(core_.counters, sequential_.counters);
    }

  private:
    /// A triangle of the worker's partition to start its walks from, and the point it was found
    /// for (detail::find_start_index; the walks are sequential and read-only); kNone when none
    /// lands in the partition. A point deferred before walks from where its attempt stopped,
    /// next to it: from the last walk's end, across the sparse points of a second pass, these
    /// walks took 23 ms of the 36 ms between passes (10^6 uniform points, two threads).
    void find_start(Worker& worker) {
        worker.last = kNone;
        worker.start = 0;
        TriIdx found = kNone;
        const std::optional<std::size_t> start =
            detail::find_start_index(worker.points.size(), [&](std::size_t i) {
                const VertIdx p = worker.points[i];
                if (hints_[p] != kNone && !core_.mesh.is_dead(hints_[p] & kHintIndex))
                    core_.last_triangle = hints_[p] & kHintIndex;
                found = core_.walk_to(p);
                return worker.owns(shared_, found);
            });
        if (!start) return;
        worker.last = found;
        worker.start = *start;
    }

    detail::Delaunay2Core& core_;
    std::vector<std::uint32_t> keys_[2];
    /// Slots below it were handed out (some are dead or still free); the arrays' slots from it
    /// on are unused (dead).
    TriIdx high_water_ = 0;
    detail::PartitionRunner runner_;
    std::vector<TriIdx> starting_at_;
    std::vector<TriIdx> hints_;
    Shared shared_;
    std::vector<Worker> workers_;
    Worker sequential_;
    tbb::task_arena& arena_;
};

}  // namespace

Delaunay2Result parallel_bowyer_watson_2d(std::span<const double> xy,
                                          const Delaunay2Options& options, unsigned threads) {
    EM_ASSERT(threads >= 1);
    using Clock = std::chrono::steady_clock;
    Clock::time_point phase = Clock::now();
    // More partitions than hardware threads still give the same triangles; the arena only runs
    // them on the threads there are.
    tbb::task_arena arena(
        std::min(static_cast<int>(threads), tbb::this_task_arena::max_concurrency()));
    // The BRIO order of the sequential construction, its keys and rounds computed on the
    // arena's threads (the same permutation).
    validate_points_2d(xy);
    Prepared prepared = prepare(xy, options.seed, threads, arena);
    detail::PartitionRunner runner;
    const ChunkRunner on_arena = [&](std::size_t count,
                                     const std::function<void(std::size_t)>& body) {
        runner.run(arena, count, body);
    };
    detail::Delaunay2Core core(xy, std::move(prepared.order), on_arena);
    core.progress = ProgressCounter(options.progress, xy.size() / 2, "points inserted");
    core.counters.order_microseconds = lap_microseconds(phase);
    core.counters.threads = threads;
    std::vector<bool> skip;
    if (!core.make_first_triangle(skip)) return core.collinear_result();
    const std::uint32_t n = core.mesh.vertex_count();

    const detail::BrioRounds rounds =
        detail::brio_rounds(n, threads, options.parallel_round_minimum);

    ParallelConstruction construction(core, threads, arena, prepared);
    core.counters.keys_microseconds = lap_microseconds(phase);
    const std::vector<VertIdx> prefix = detail::unskipped_vertices(skip, 0, rounds.prefix_end);
    construction.insert_sequentially(prefix);
    core.counters.sequential_prefix = prefix.size();
    std::uint64_t sequential = lap_microseconds(phase);

    const std::vector<VertIdx> pending = detail::run_parallel_rounds(construction, rounds, skip);
    // The rounds' time less the threads' passes: what the calling thread does alone.
    core.counters.partition_microseconds =
        lap_microseconds(phase) - core.counters.parallel_microseconds;
    construction.insert_sequentially(pending);
    core.counters.sequential_tail = pending.size();
    core.counters.sequential_microseconds = sequential + lap_microseconds(phase);
    construction.trim();
    construction.finish_counters();
    Delaunay2Result result = core.take_result(threads, on_arena);
    result.counters.result_microseconds = lap_microseconds(phase);
    return result;
}

}  // namespace exactmesh::triangulation
