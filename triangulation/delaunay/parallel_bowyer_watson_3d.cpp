// SPDX-License-Identifier: MIT
// Multicore Bowyer-Watson 3D (see parallel_bowyer_watson_3d.hpp).
#include "triangulation/delaunay/parallel_bowyer_watson_3d.hpp"

#include <tbb/task_arena.h>
#include <tbb/task_group.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "base/errors.hpp"
#include "base/huge_pages.hpp"
#include "base/stopwatch.hpp"
#include "triangulation/delaunay/bowyer_watson_3d_cavity.hpp"
#include "triangulation/delaunay/delaunay_3d_core.hpp"
#include "triangulation/mesh/spatial_sort.hpp"

namespace exactmesh::triangulation {

namespace {

/// Flags of Shared3::hints (above the tetrahedron index, which fits in 30 bits).
constexpr TetIdx kHintStart = 0x40000000u;      ///< the tetrahedron is the point's worker's
constexpr TetIdx kHintElsewhere = 0x80000000u;  ///< it is not
static_assert((kMaxTetSlots & (kHintStart | kHintElsewhere)) == 0);

/// What the threads share. During a pass each thread writes only: tv and adj of tetrahedra of
/// its partition (and of the dead slots of its free list), the face slot of a mixed tetrahedron
/// facing its cavity, and merged_into of its own points.
struct Shared3 {
    TetMesh3& mesh;
    const std::vector<VertIdx>& input_index;
    std::vector<VertIdx>& merged_into;
    std::span<const std::uint32_t> keys;  ///< per mesh vertex: the key of this pass's curve
    /// Per mesh vertex: where the last attempt to insert it stopped (kNone: not tried yet),
    /// written by the thread that tried it, read in a later pass.
    std::vector<TetIdx> hints;
};

/// The slots not in use between passes (the calling thread's alone): mesh.free_tets, then fresh
/// slots from high_water on, the arrays grown (with room to spare) when they run out.
class SlotPool {
  public:
    explicit SlotPool(TetMesh3& mesh) : mesh_(mesh) {}

    TetIdx high_water = 0;  ///< slots from it on were never handed out (dead)

    /// Fills `list` up to `target` slots.
    void fill(std::vector<TetIdx>& list, std::size_t target) {
        const std::size_t missing = take_freed(list, target);
        const TetIdx first = fresh_range(missing);
        for (TetIdx t = first; t < high_water; ++t) list.push_back(t);
    }

    /// Moves freed slots into `list` up to `target`; returns how many are still missing.
    std::size_t take_freed(std::vector<TetIdx>& list, std::size_t target) {
        std::vector<TetIdx>& pool = mesh_.free_tets;
        while (list.size() < target && !pool.empty()) {
            list.push_back(pool.back());
            pool.pop_back();
        }
        return list.size() < target ? target - list.size() : 0;
    }

    /// The first of `count` fresh slots [first, high_water), the arrays grown if needed.
    TetIdx fresh_range(std::size_t count) {
        const TetIdx first = high_water;
        const std::size_t needed = high_water + count;
        if (needed > mesh_.tet_slots()) {
            // Rare (more tetrahedra per point than the first sizing allowed for): reserved
            // exactly, so that the arrays do not double.
            const std::size_t slots = needed + needed / 16;
            EM_ASSERT(slots <= kMaxTetSlots);
            mesh_.tv.reserve(4 * slots);
            mesh_.adj.reserve(4 * slots);
            mesh_.tv.resize(4 * slots, kNone);
            mesh_.adj.resize(4 * slots, kNone);
        }
        high_water = static_cast<TetIdx>(needed);
        return first;
    }

    /// Takes back the slots of `list` and the fresh slots [next, end).
    void give_back(std::vector<TetIdx>& list, TetIdx& next, TetIdx end) {
        mesh_.free_tets.insert(mesh_.free_tets.end(), list.begin(), list.end());
        list.clear();
        for (; next < end; ++next) mesh_.free_tets.push_back(next);
    }

  private:
    TetMesh3& mesh_;
};

/// A thread's partition as the region of a CavityInserter3: the tetrahedra whose four vertices
/// have keys in `range`; with `whole`, every tetrahedron (the sequential prefix and tail).
struct Partition3 {
    static constexpr bool kPartitioned = true;
    Shared3& shared;
    SlotPool& pool;
    detail::KeyRange range;
    bool whole = false;
    std::vector<TetIdx> free_list;
    /// Fresh slots [fresh_next, fresh_end) handed to this partition for the pass, moved to
    /// free_list only as cavities need them (a list of them all would cost 4 bytes a slot).
    TetIdx fresh_next = 0, fresh_end = 0;
    TetIdx last_tet = kNone;  ///< where the next walk starts (a tetrahedron of the partition)
    Delaunay3Counters work{};

    /// The infinite vertex is every partition's: a tetrahedron still belongs to at most one
    /// (it has three finite vertices), and a neighbour of one of p's shares three vertices of p
    /// with it, so it is p's or mixed; points whose cavities meet the hull are then inserted
    /// by the threads too, not left to the sequential tail.
    bool owns_vertex(VertIdx v) const {
        return whole || v == kInfinite || range.holds(shared.keys[v]);
    }
    bool owns(TetIdx t) const {
        if (whole) return true;
        const VertIdx* v = &shared.mesh.tv[4 * std::size_t{t}];
        return owns_vertex(v[0]) && owns_vertex(v[1] & kVertexBits) && owns_vertex(v[2]) &&
               owns_vertex(v[3]);
    }
    /// The finite tetrahedron a walk from t starts in: t, or the one behind its hull face.
    TetIdx finite_start(TetIdx t) const {
        const TetMesh3& mesh = shared.mesh;
        return mesh.is_infinite(t) ? tet_of(mesh.adj[4 * std::size_t{t} + kInfiniteSlot]) : t;
    }
    /// A walk may start from t: it is ours and so is its finite_start (behind a hull face of
    /// ours may be a mixed tetrahedron, which a walk must not end in).
    bool can_start(TetIdx t) const {
        return t != kNone && !shared.mesh.is_dead(t) && owns(t) && owns(finite_start(t));
    }
    detail::ConflictTest3 tests() { return {shared.mesh, shared.input_index.data(), work}; }
    Delaunay3Counters& counters() { return work; }
    std::vector<TetIdx>& free_tets() { return free_list; }
    /// A thread's list was filled before the pass (the arrays must not grow while threads
    /// run); only the whole mesh, alone, takes more.
    bool make_room(std::size_t faces) {
        while (free_list.size() < faces && fresh_next < fresh_end)
            free_list.push_back(fresh_next++);
        if (free_list.size() >= faces) return true;
        if (!whole) return false;
        pool.fill(free_list, faces + 64);
        return true;
    }
};

enum class Outcome { Inserted, Merged, Deferred };

/// One thread's partition, its insertion scratch, its points of the pass and counters (kept
/// from pass to pass). Aligned to whole cache-line pairs: what one worker writes on every
/// predicate must not share a line (or the adjacent-line prefetch pair) with another's.
struct alignas(128) Worker3 {
    Worker3(Shared3& shared, SlotPool& pool)
        : region{shared, pool, {}, false, {}, 0, 0, kNone, {}}, inserter(region, shared.mesh) {}

    Partition3 region;
    detail::CavityInserter3<Partition3> inserter;
    std::uint64_t rng_state = 0x9E3779B97F4A7C15ull;
    std::span<const VertIdx> points;  ///< this pass's points, in curve order
    std::size_t start = 0;            ///< the point whose walk found region.last_tet
    std::vector<VertIdx> deferred;

    /// Inserts p (walk, then bowyer_watson_3d's cavity and star) when the walk and the cavity
    /// stay in the partition; else changes nothing and returns Deferred.
    Outcome insert(VertIdx p) {
        TetMesh3& mesh = region.shared.mesh;
        const TetIdx hint = region.shared.hints[p];
        if (!region.whole && hint != kNone && (hint & kHintElsewhere) != 0) {
            return Outcome::Deferred;  // it lies next to another partition's tetrahedra
        }
        TetIdx t = start_for(p, hint);
        if (t == kNone) return Outcome::Deferred;
        const detail::Location3 where = detail::walk_3d(
            mesh, t, p, rng_state, region.work, [this](TetIdx u) { return region.owns(u); });
        // The next points lie near p: their walks start here, whether it went on or not.
        region.last_tet = t;
        if (where.tet == kNone) {
            region.shared.hints[p] = t;
            return Outcome::Deferred;
        }
        const VertIdx same = detail::duplicate_vertex(mesh, where);
        if (same != kNone) {
            const std::vector<VertIdx>& index = region.shared.input_index;
            region.shared.merged_into[index[p]] = index[same];
            ++region.work.duplicates;
            return Outcome::Merged;
        }
        if (inserter.insert(p, where.tet)) return Outcome::Inserted;
        region.shared.hints[p] = where.tet;
        return Outcome::Deferred;
    }

    /// The finite tetrahedron p's walk starts from: the last walk's end (a new tetrahedron of the
    /// last point, or where the last walk stopped: if infinite, the one behind its hull face is
    /// new too, since the face holds the point, or the one the walk came from, so ours) or,
    /// when nearer to p, where p's last attempt stopped (a guess from rounded coordinates: any
    /// start gives the same insertion); kNone when neither may start a walk. A point deferred
    /// along one curve's border is tried next along the other curve, far from the last point
    /// there: its walks took 57 steps on average from the last walk's end (10^6 uniform points).
    /// `hint`: p's entry of the hints (classified before the pass).
    TetIdx start_for(VertIdx p, TetIdx hint) const {
        const bool last_ok = region.can_start(region.last_tet);
        if (hint != kNone && (region.whole || (hint & kHintStart) != 0)) {
            const TetIdx h = hint & kMaxTetSlots;
            if (region.can_start(h)) {
                const TetIdx near = region.finite_start(h);
                if (!last_ok) return near;
                const TetIdx last = region.finite_start(region.last_tet);
                return distance_to(near, p) < distance_to(last, p) ? near : last;
            }
        }
        return last_ok ? region.finite_start(region.last_tet) : kNone;
    }

    /// Before a pass, with every thread only reading: the hint of each of this pass's points
    /// (where its last attempt stopped, next to it) flagged kHintStart when that tetrahedron is
    /// this partition's (then only this thread changes it during the pass), else kHintElsewhere
    /// (p lies next to another partition's or mixed tetrahedra: it waits without walking);
    /// dropped when the tetrahedron is dead.
    void classify_hints() {
        std::vector<TetIdx>& hints = region.shared.hints;
        for (const VertIdx p : points) {
            if (hints[p] == kNone) continue;
            const TetIdx t = hints[p] & kMaxTetSlots;
            if (region.shared.mesh.is_dead(t)) {
                hints[p] = kNone;
            } else {
                hints[p] = t | (region.can_start(t) ? kHintStart : kHintElsewhere);
            }
        }
    }

    /// The largest coordinate difference between p and t's first corner (no overflow to a
    /// decision: only a choice between two starts).
    double distance_to(TetIdx t, VertIdx p) const {
        const TetMesh3& mesh = region.shared.mesh;
        const double* a = mesh.point(mesh.tv[4 * std::size_t{t}]);
        const double* q = mesh.point(p);
        return std::max(std::max(std::fabs(a[0] - q[0]), std::fabs(a[1] - q[1])),
                        std::fabs(a[2] - q[2]));
    }

    /// Inserts this pass's points (detail::sweep_partition); the deferred ones go to
    /// `deferred`, in the order of `points`.
    void run() {
        deferred.clear();
        if (region.last_tet == kNone) {
            deferred.assign(points.begin(), points.end());
        } else {
            Sweep sweep{*this};
            detail::sweep_partition(sweep, points, start, region.shared.keys, deferred);
        }
        region.work.deferred_points += deferred.size();
    }

    /// The worker as detail::sweep_partition's sweep.
    struct Sweep {
        Worker3& worker;
        TetIdx anchor = kNone;

        bool try_insert(VertIdx p) {
            if (worker.insert(p) == Outcome::Deferred) return false;
            ++worker.region.work.parallel_points;
            return true;
        }
        bool same_point(VertIdx a, VertIdx b) const {
            const double* pa = worker.region.shared.mesh.point(a);
            const double* pb = worker.region.shared.mesh.point(b);
            return pa[0] == pb[0] && pa[1] == pb[1] && pa[2] == pb[2];
        }
        void remember_start() { anchor = worker.region.last_tet; }
        /// Back to the start: the anchor slot is ours (made or reused by this worker only).
        void return_to_start() {
            const Partition3& region = worker.region;
            if (region.can_start(anchor)) worker.region.last_tet = anchor;
        }
    };
};

void add_work_counters(Delaunay3Counters& to, const Delaunay3Counters& from) {
    to.duplicates += from.duplicates;
    to.orient_calls += from.orient_calls;
    to.insphere_calls += from.insphere_calls;
    to.walk_steps += from.walk_steps;
    to.cavity_tets += from.cavity_tets;
    to.parallel_points += from.parallel_points;
    to.deferred_points += from.deferred_points;
}

/// The second pass's curve: the Hilbert curve of the grid moved by 0.382 of its width along
/// every axis (wrapping around), whose ranges' borders are not the first curve's dyadic planes.
constexpr std::uint32_t kSecondCurveShift = 391;  // 2^10 (1 - 0.618...)

/// Tetrahedron slots made ready before the construction: about 6.7 per uniform point, as
/// Delaunay3Core reserves, and room for each thread's list.
std::size_t prepared_slots(std::size_t n, unsigned threads) {
    return 7 * n + 64 + 1024 * std::size_t{threads};
}

/// What is computed on the arena before the mesh exists: the BRIO order, both curves' keys (in
/// the caller's order) and the mesh arrays (tv kNone: dead slots).
struct Prepared {
    std::vector<VertIdx> order;
    std::vector<std::uint32_t> keys[2];
    std::vector<VertIdx> tv;
    std::vector<FaceIdx> adj;
};

Prepared prepare(std::span<const double> xyz, std::uint64_t seed, unsigned threads,
                 tbb::task_arena& arena) {
    const std::size_t slots = prepared_slots(xyz.size() / 3, threads);
    Prepared out;
    auto make_array = [slots](std::vector<std::uint32_t>& array) {
        array.reserve(4 * slots);
        advise_huge_pages(array);
        array.resize(4 * slots, kNone);
    };
    // As in 2D: the random stream beside both curves' keys, then the rounds beside the arrays
    // (the order as one thread's insertion_order_3d).
    std::vector<std::uint32_t> position;
    detail::run_together(
        arena,
        [&] { position = inverse_permutation(random_permutation(xyz.size() / 3, seed), true); },
        [&] { out.keys[0] = hilbert_keys_3d(xyz, 0, true); },
        [&] { out.keys[1] = hilbert_keys_3d(xyz, kSecondCurveShift, true); });
    detail::run_together(
        arena, [&] { out.order = brio_order(out.keys[0], position, true); },
        [&] { make_array(out.tv); }, [&] { make_array(out.adj); });
    return out;
}

class ParallelConstruction3 {
  public:
    /// `arena` runs the T = `threads` partitions (on fewer threads if it has fewer); `prepared`
    /// (of the same points and T) gives its arrays and keys.
    ParallelConstruction3(detail::Delaunay3Core& core, ProgressCounter& progress, unsigned threads,
                          tbb::task_arena& arena, Prepared& prepared)
        : core_(core),
          progress_(progress),
          shared_{core.mesh,
                  core.input_index,
                  core.merged_into,
                  {},
                  std::vector<TetIdx>(core.mesh.vertex_count(), kNone)},
          pool_(core.mesh),
          sequential_(shared_, pool_),
          arena_(arena) {
        TetMesh3& mesh = core.mesh;
        // The prepared arrays take the first tetrahedra's entries and replace the mesh's.
        pool_.high_water = mesh.tet_slots();
        EM_ASSERT(prepared.tv.size() >= mesh.tv.size());
        std::copy(mesh.tv.begin(), mesh.tv.end(), prepared.tv.begin());
        std::copy(mesh.adj.begin(), mesh.adj.end(), prepared.adj.begin());
        mesh.tv.swap(prepared.tv);
        mesh.adj.swap(prepared.adj);
        detail::keys_by_mesh_vertex(runner_, arena_, core.input_index, prepared.keys, keys_);
        shared_.keys = keys_[0];
        for (unsigned w = 0; w < threads; ++w)
            workers_.push_back(std::make_unique<Worker3>(shared_, pool_));
        sequential_.region.whole = true;
    }

    /// Inserts `points` one by one (the prefix and the tail).
    void insert_sequentially(std::span<const VertIdx> points) {
        TetIdx t = core_.last_tet;
        if (t == kNone || core_.mesh.is_dead(t)) {
            for (t = 0; core_.mesh.is_dead(t); ++t) {
            }
        }
        sequential_.region.last_tet = t;
        for (const VertIdx p : points) {
            const Outcome outcome = sequential_.insert(p);
            EM_ASSERT(outcome != Outcome::Deferred);
            progress_.tick();
        }
        core_.last_tet = sequential_.region.last_tet;
        pool_.give_back(sequential_.region.free_list, sequential_.region.fresh_next,
                        sequential_.region.fresh_end);
    }

    /// One pass: `points` (sorted by the keys of `curve`, from bounds[0] on, wrapping) cut by
    /// `bounds` (T + 1 increasing keys of that curve, as key_range_bounds) into the workers'
    /// ranges; returns the deferred points, in the order of `points`.
    std::vector<VertIdx> pass(std::span<const VertIdx> points, int curve,
                              const std::vector<std::uint64_t>& bounds) {
        const std::vector<std::uint32_t>& keys = keys_[curve];
        shared_.keys = keys;
        const std::vector<std::span<const VertIdx>> parts =
            detail::split_by_bounds(keys, points, bounds);
        for (std::size_t w = 0; w < workers_.size(); ++w) {
            Worker3& worker = *workers_[w];
            worker.region.range = {bounds[w], bounds[w + 1]};
            worker.points = parts[w];
            // About 6.7 new tetrahedra per point, and room for the largest cavities' faces; a
            // worker that runs short defers the rest of its points.
            if (!worker.points.empty()) {
                Partition3& region = worker.region;
                const std::size_t missing =
                    pool_.take_freed(region.free_list, 7 * worker.points.size() + 256);
                region.fresh_next = pool_.fresh_range(missing);
                region.fresh_end = pool_.high_water;
            }
            find_start(worker);
        }
        const auto started = std::chrono::steady_clock::now();
        runner_.run(arena_, workers_.size(), [&](std::size_t w) { workers_[w]->classify_hints(); });
        runner_.run(arena_, workers_.size(), [&](std::size_t w) { workers_[w]->run(); });
        core_.counters.parallel_microseconds += microseconds_since(started);
        std::vector<VertIdx> deferred;
        for (const std::unique_ptr<Worker3>& worker : workers_) {
            for (std::size_t i = worker->deferred.size(); i < worker->points.size(); ++i)
                progress_.tick();
            deferred.insert(deferred.end(), worker->deferred.begin(), worker->deferred.end());
            if (worker->region.last_tet != kNone) core_.last_tet = worker->region.last_tet;
            Partition3& region = worker->region;
            pool_.give_back(region.free_list, region.fresh_next, region.fresh_end);
        }
        ++core_.counters.parallel_rounds;
        return deferred;
    }

    std::vector<std::uint64_t> bounds(std::span<const VertIdx> points, int curve,
                                      bool shifted) const {
        return detail::key_range_bounds(keys_[curve], points, workers_.size(), shifted);
    }

    const std::vector<std::uint32_t>& keys(int curve) const { return keys_[curve]; }

    /// Drops the unused slots at the arrays' end (all dead) and the keys.
    void finish() {
        TetMesh3& mesh = core_.mesh;
        mesh.tv.resize(4 * std::size_t{pool_.high_water});
        mesh.adj.resize(4 * std::size_t{pool_.high_water});
        std::vector<TetIdx>().swap(mesh.free_tets);
        for (std::vector<std::uint32_t>& keys : keys_) std::vector<std::uint32_t>().swap(keys);
        for (const std::unique_ptr<Worker3>& worker : workers_)
            add_work_counters(core_.counters, worker->region.work);
        add_work_counters(core_.counters, sequential_.region.work);
    }

  private:
    /// A tetrahedron of the worker's partition to start its walks from, and the point it was
    /// found for (detail::find_start_index; the walks are sequential and read-only).
    void find_start(Worker3& worker) {
        worker.region.last_tet = kNone;
        worker.start = 0;
        TetIdx found = kNone;
        const std::optional<std::size_t> start =
            detail::find_start_index(worker.points.size(), [&](std::size_t i) {
                // A point deferred before walks from where its attempt stopped, next to it.
                const VertIdx p = worker.points[i];
                const TetIdx hint = shared_.hints[p];
                if (hint != kNone && !core_.mesh.is_dead(hint & kMaxTetSlots))
                    core_.last_tet = hint & kMaxTetSlots;
                found = core_.walk_to(p).tet;
                return worker.region.can_start(found);
            });
        if (!start) return;
        worker.region.last_tet = found;
        worker.start = *start;
    }

    detail::Delaunay3Core& core_;
    ProgressCounter& progress_;
    std::vector<std::uint32_t> keys_[2];
    Shared3 shared_;
    SlotPool pool_;
    std::vector<std::unique_ptr<Worker3>> workers_;
    Worker3 sequential_;
    detail::PartitionRunner runner_;
    tbb::task_arena& arena_;
};

}  // namespace

Delaunay3Result parallel_bowyer_watson_3d(std::span<const double> xyz,
                                          const Delaunay3Options& options, unsigned threads) {
    EM_ASSERT(threads >= 1);
    using Clock = std::chrono::steady_clock;
    Clock::time_point phase = Clock::now();
    // More partitions than hardware threads still give the same tetrahedra; the arena only
    // runs them on the threads there are.
    tbb::task_arena arena(
        std::min(static_cast<int>(threads), tbb::this_task_arena::max_concurrency()));
    validate_points_3d(xyz);
    Prepared prepared = prepare(xyz, options.seed, threads, arena);
    detail::Delaunay3Core core(xyz, std::move(prepared.order), 0);
    core.counters.order_microseconds = lap_microseconds(phase);
    core.counters.threads = threads;
    std::vector<bool> skip;
    if (!core.make_first_tet(skip)) return core.coplanar_result(xyz);
    ProgressCounter progress(options.progress, core.mesh.vertex_count(), "points inserted");
    const std::uint32_t n = core.mesh.vertex_count();
    const detail::BrioRounds rounds =
        detail::brio_rounds(n, threads, options.parallel_round_minimum);

    ParallelConstruction3 construction(core, progress, threads, arena, prepared);
    prepared = Prepared{};
    core.counters.keys_microseconds = lap_microseconds(phase);
    const std::vector<VertIdx> prefix = detail::unskipped_vertices(skip, 0, rounds.prefix_end);
    construction.insert_sequentially(prefix);
    core.counters.sequential_prefix = prefix.size();
    const std::uint64_t sequential = lap_microseconds(phase);

    const std::vector<VertIdx> pending = detail::run_parallel_rounds(construction, rounds, skip);
    // The rounds' time less the threads' passes: what the calling thread does alone.
    core.counters.partition_microseconds =
        lap_microseconds(phase) - core.counters.parallel_microseconds;
    construction.insert_sequentially(pending);
    core.counters.sequential_tail = pending.size();
    construction.finish();
    core.counters.sequential_microseconds = sequential + lap_microseconds(phase);
    detail::PartitionRunner runner;
    Delaunay3Result result = core.take_result(
        xyz, threads, [&](std::size_t count, const std::function<void(std::size_t)>& body) {
            runner.run(arena, count, body);
        });
    result.counters.result_microseconds = lap_microseconds(phase);
    return result;
}

}  // namespace exactmesh::triangulation
