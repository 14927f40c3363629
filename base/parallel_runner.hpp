// SPDX-License-Identifier: MIT
// Running work on a oneTBB arena in a form ThreadSanitizer follows (libtbb is not
// instrumented): the multicore Delaunay constructions' passes and preparation, and the
// parallel refinement's rounds. Header-only; the user links TBB::tbb.
#pragma once

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>
#include <tbb/task_group.h>

#include <atomic>
#include <cstddef>
#include <cstdint>

namespace exactmesh {

/// Runs each of `tasks` as a task of `arena` while the calling thread runs `main_task` there,
/// and waits for all (the preparation of both constructions: order, keys, mesh arrays). The
/// release/acquire pairs are PartitionRunner's, for ThreadSanitizer.
template <class MainTask, class... Tasks>
void run_together(tbb::task_arena& arena, MainTask&& main_task, Tasks&&... tasks) {
    std::atomic<int> started{0}, finished{0};
    started.store(1, std::memory_order_release);
    arena.execute([&] {
        tbb::task_group group;
        (group.run([&] {
            (void)started.load(std::memory_order_acquire);
            tasks();
            finished.fetch_add(1, std::memory_order_release);
        }),
         ...);
        main_task();
        group.wait();
    });
    (void)finished.load(std::memory_order_acquire);
}

/// Runs the partitions of a pass on an arena, one task per partition.
/// The release/acquire pairs on the two counters repeat what the task scheduler already
/// guarantees (what the caller did before happens before each task, each task before what
/// follows), in a form ThreadSanitizer sees: libtbb is not instrumented.
class PartitionRunner {
  public:
    /// Calls run_partition(w) for w in [0, count), in parallel on `arena`.
    template <class RunPartition>
    void run(tbb::task_arena& arena, std::size_t count, RunPartition&& run_partition) {
        epoch_.fetch_add(1, std::memory_order_release);
        arena.execute([&] {
            tbb::parallel_for(
                tbb::blocked_range<std::size_t>(0, count, 1),
                [&](const tbb::blocked_range<std::size_t>& r) {
                    (void)epoch_.load(std::memory_order_acquire);
                    for (std::size_t w = r.begin(); w != r.end(); ++w) run_partition(w);
                    finished_.fetch_add(1, std::memory_order_release);
                },
                tbb::simple_partitioner());
        });
        (void)finished_.load(std::memory_order_acquire);
    }

    /// Calls body(begin, end) over [0, n) in chunks of about `grain`, in parallel on `arena`.
    template <class Body>
    void run_chunks(tbb::task_arena& arena, std::size_t n, Body&& body,
                    std::size_t grain = std::size_t{1} << 14) {
        epoch_.fetch_add(1, std::memory_order_release);
        arena.execute([&] {
            tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, grain),
                              [&](const tbb::blocked_range<std::size_t>& r) {
                                  (void)epoch_.load(std::memory_order_acquire);
                                  body(r.begin(), r.end());
                                  finished_.fetch_add(1, std::memory_order_release);
                              });
        });
        (void)finished_.load(std::memory_order_acquire);
    }

  private:
    std::atomic<std::uint64_t> epoch_{0}, finished_{0};
};

}  // namespace exactmesh
