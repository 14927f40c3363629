// SPDX-License-Identifier: MIT
// What the multicore Bowyer-Watson constructions (parallel_bowyer_watson_2d, _3d) share, after
// HXT's partitioned insertion [MarotPellerinRemacle19 §3]: the thread count; the BRIO rounds,
// split into a sequential prefix and the rounds the threads insert; the ranges of Hilbert keys
// that cut a round into one partition per thread (integers, no geometry); lists of vertices
// sorted and merged by key; where in its list a thread starts walking; and running the
// partitions of a pass on a oneTBB arena in a form ThreadSanitizer follows.
#pragma once

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>
#include <tbb/task_group.h>

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "base/parallel_runner.hpp"
#include "triangulation/mesh/mesh2.hpp"

namespace exactmesh::triangulation {

/// The most threads a caller may ask for (the command's --threads, the Python module's
/// threads=): far above any machine's cores, and low enough that per-thread scratch stays small.
inline constexpr unsigned kMaxThreads = 1024;

/// The thread count `threads` asks for: itself, or every hardware thread for 0 (at least 1).
unsigned resolve_thread_count(unsigned threads);

namespace detail {

/// A half-open range of Hilbert keys [low, high) (64-bit so that a range can end past
/// 2^32 - 1), wrapping around: the last range of a shifted pass ends at its first range's low
/// plus 2^32, and holds the keys from its low on and those below that first low.
struct KeyRange {
    std::uint64_t low = 0, high = 0;
    bool holds(std::uint32_t key) const {
        return static_cast<std::uint32_t>(key - static_cast<std::uint32_t>(low)) < high - low;
    }
};

/// The BRIO rounds as insertion_order made them for n points (brio_round_begins: [n/8, n),
/// [n/64, n/8), ... down to 64 points), each sorted by Hilbert key. Rounds of fewer than
/// round_minimum points per thread (and the first points) are the sequential prefix; the others go
/// to the threads.
struct BrioRounds {
    std::vector<std::uint32_t> begin;  ///< round r holds mesh vertices [begin[r], begin[r + 1])
    std::size_t first_parallel = 0;    ///< the first round the threads insert
    std::uint32_t prefix_end = 0;      ///< vertices below it are inserted sequentially
};
BrioRounds brio_rounds(std::uint32_t n, unsigned threads, std::uint32_t round_minimum);

/// The mesh vertices [begin, end) whose `skip` flag is not set (the first simplex's vertices).
std::vector<VertIdx> unskipped_vertices(const std::vector<bool>& skip, std::uint32_t begin,
                                        std::uint32_t end);

/// The keys at the fractions i / count of `points` (i = 1..count-1; keys[v] is v's key), framed
/// by 0 and 2^32: count ranges about equal in points. `shifted`: the keys at the fractions
/// (i + 1/2) / count (i = 0..count-1), then the first plus 2^32: ranges whose borders lie
/// half a range along the curve from the unshifted ones, the last wrapping around.
std::vector<std::uint64_t> key_range_bounds(std::span<const std::uint32_t> keys,
                                            std::span<const VertIdx> points, std::size_t count,
                                            bool shifted = false);

/// `points` (sorted by keys from bounds[0] on, wrapping: rotate_to_bound) cut by `bounds`
/// (count + 1 increasing keys, as key_range_bounds): the points of each range, in order.
std::vector<std::span<const VertIdx>> split_by_bounds(std::span<const std::uint32_t> keys,
                                                      std::span<const VertIdx> points,
                                                      std::span<const std::uint64_t> bounds);

/// Rotates `points` (sorted by (key, vertex)) to start at the first key at least `low` (the
/// order of a shifted pass, whose ranges start there and wrap around).
void rotate_to_bound(std::span<const std::uint32_t> keys, std::vector<VertIdx>& points,
                     std::uint64_t low);

/// Sorts vertices by (key, vertex).
void sort_by_key(std::span<const std::uint32_t> keys, std::vector<VertIdx>& points);

/// Merges two lists of vertices sorted by (key, vertex).
std::vector<VertIdx> merge_by_key(std::span<const std::uint32_t> keys, std::span<const VertIdx> a,
                                  std::span<const VertIdx> b);

/// Where a thread starts: the first index i of its `size` points for which lands_inside(i)
/// (a read-only walk to point i ends in the thread's partition), tried at the middle of the
/// list first (farthest from the ranges' ends along the curve), then at fractions 1/4, 3/4,
/// 1/8, ...; nothing when none of 32 tries lands (then the thread's points wait).
template <class LandsInside>
std::optional<std::size_t> find_start_index(std::size_t size, LandsInside&& lands_inside) {
    if (size == 0) return std::nullopt;
    for (std::size_t denominator = 2, tries = 0; tries < 32; denominator *= 2) {
        for (std::size_t numerator = 1; numerator < denominator && tries < 32;
             numerator += 2, ++tries) {
            const std::size_t i = size * numerator / denominator;
            if (lands_inside(i)) return i;
        }
        if (denominator >= size) break;
    }
    return std::nullopt;
}

/// A thread's pass over its points (sorted by (key, vertex), the key of the pass's curve):
/// from points[start] (whose walk found the thread's start) to the end, then back from the
/// points before start to the first, so that each walk is short. Copies of one point (equal
/// coordinates, hence equal keys) are nevertheless tried in the list's order, which is the
/// sequential construction's insertion order: the copy inserted (the others merge into it) is
/// the sequential one, and with it the index the symbolic perturbation reads, so that the
/// result stays the sequential one on degenerate inputs with repeated points. For that, start
/// moves to the first point of its run of equal keys, the way back takes each run of equal
/// keys forward, and a point whose earlier copy was deferred in this pass is deferred too
/// (their walks may end differently). `sweep` provides:
///   bool try_insert(VertIdx p);          inserts or merges p (true), or defers it (false)
///   bool same_point(VertIdx a, VertIdx b) const;   equal coordinates
///   void remember_start();               called after the first point
///   void return_to_start();              called before the way back
/// The deferred points go to `deferred`, in the order of `points`.
template <class Sweep>
void sweep_partition(Sweep& sweep, std::span<const VertIdx> points, std::size_t start,
                     std::span<const std::uint32_t> keys, std::vector<VertIdx>& deferred) {
    deferred.clear();
    if (points.empty()) return;
    auto same_run = [&](std::size_t i, std::size_t j) {
        return keys[points[i]] == keys[points[j]];
    };
    while (start > 0 && same_run(start - 1, start)) --start;
    std::vector<std::size_t> deferred_at;  // positions in points
    std::size_t run_first_deferred = 0;    // deferred_at entries of the current run start here
    auto try_point = [&](std::size_t i) {
        const VertIdx p = points[i];
        for (std::size_t k = run_first_deferred; k < deferred_at.size(); ++k) {
            if (sweep.same_point(p, points[deferred_at[k]])) {
                deferred_at.push_back(i);  // an earlier copy waits: so does this one
                return;
            }
        }
        if (!sweep.try_insert(p)) deferred_at.push_back(i);
    };
    for (std::size_t i = start; i < points.size(); ++i) {
        if (i == start || !same_run(i - 1, i)) run_first_deferred = deferred_at.size();
        try_point(i);
        if (i == start) sweep.remember_start();
    }
    sweep.return_to_start();
    for (std::size_t end = start; end > 0;) {
        std::size_t begin = end - 1;
        while (begin > 0 && same_run(begin - 1, begin)) --begin;
        run_first_deferred = deferred_at.size();
        for (std::size_t i = begin; i < end; ++i) try_point(i);
        end = begin;
    }
    std::sort(deferred_at.begin(), deferred_at.end());
    for (const std::size_t i : deferred_at) deferred.push_back(points[i]);
}

/// The parallel rounds of both dimensions: each round's points, with those still pending from
/// the round before, in two passes: along curve 0, then the points it deferred along curve 1
/// (whose ranges' borders lie elsewhere, so that they mostly fall inside a range). After the
/// last round, two more passes over what is still pending, along curve 0 and then curve 1 with
/// their ranges shifted by half a range (the last round's borders then lie inside ranges): 10^6
/// Gaussian points in 3D left 110,605 points to the sequential tail without them (both curves'
/// borders cross the dense core), 25,961 with them; uniform points 17,881 and 3,115.
/// Returns the points still pending (for the sequential tail), sorted by curve 0's keys.
/// `construction` provides keys(curve) (per mesh vertex), bounds(points, curve, shifted) and
/// pass(points, curve, bounds) (returns the deferred points).
template <class Construction>
std::vector<VertIdx> run_parallel_rounds(Construction& construction, const BrioRounds& rounds,
                                         const std::vector<bool>& skip) {
    std::vector<VertIdx> pending, points;
    for (std::size_t r = rounds.first_parallel; r + 1 < rounds.begin.size(); ++r) {
        const std::vector<VertIdx> round =
            unskipped_vertices(skip, rounds.begin[r], rounds.begin[r + 1]);
        points = merge_by_key(construction.keys(0), pending, round);
        std::vector<VertIdx> deferred =
            construction.pass(points, 0, construction.bounds(points, 0, false));
        sort_by_key(construction.keys(1), deferred);
        pending = construction.pass(deferred, 1, construction.bounds(points, 1, false));
        sort_by_key(construction.keys(0), pending);
    }
    for (const int curve : {0, 1}) {
        if (pending.empty()) break;
        sort_by_key(construction.keys(curve), pending);
        const std::vector<std::uint64_t> shifted = construction.bounds(points, curve, true);
        rotate_to_bound(construction.keys(curve), pending, shifted.front());
        pending = construction.pass(pending, curve, shifted);
    }
    sort_by_key(construction.keys(0), pending);
    return pending;
}

using exactmesh::PartitionRunner;
using exactmesh::run_together;

/// Both curves' keys by mesh vertex (keys[c][v] = keys_by_input[c][input_index[v]]): the
/// keys are computed in the caller's order, the passes read them by mesh vertex.
inline void keys_by_mesh_vertex(PartitionRunner& runner, tbb::task_arena& arena,
                                std::span<const VertIdx> input_index,
                                const std::vector<std::uint32_t> (&keys_by_input)[2],
                                std::vector<std::uint32_t> (&keys)[2]) {
    for (std::vector<std::uint32_t>& curve : keys) curve.resize(input_index.size());
    runner.run_chunks(arena, input_index.size(), [&](std::size_t begin, std::size_t end) {
        for (std::size_t v = begin; v != end; ++v) {
            keys[0][v] = keys_by_input[0][input_index[v]];
            keys[1][v] = keys_by_input[1][input_index[v]];
        }
    });
}

}  // namespace detail
}  // namespace exactmesh::triangulation
