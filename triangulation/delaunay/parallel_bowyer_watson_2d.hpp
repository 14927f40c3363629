// SPDX-License-Identifier: MIT
// Multicore Bowyer-Watson 2D (issue 17), after HXT's partitioned insertion [MarotPellerinRemacle19
// §3], on oneTBB. The BRIO order of bowyer_watson_2d is kept: its small first rounds are
// inserted sequentially; every later round (sorted along the Hilbert curve) is cut into T
// contiguous ranges of Hilbert keys, one per thread. A vertex belongs to the partition whose key
// range holds its key (integers, no geometry; the infinite vertex to none), a triangle to the
// partition holding its three vertices. Thread p inserts a point of its range only when the walk
// to it and its whole cavity stay in triangles of p; neighbours of the cavity may also be
// "mixed" triangles (vertices in several partitions, or infinite), which no thread changes during
// a pass, so relinking their twin half-edge touches an entry nobody else reads or writes.
// Otherwise the point is deferred, before anything is changed. Copies of one point are tried in
// the sequential order (detail::sweep_partition), so the copy kept, whose input index the
// perturbation reads, is the sequential one. A second pass moves the
// boundaries by half a range and retries the deferred points; what is still deferred joins the
// next round, and after the last round the few remaining points (near the hull or the last
// boundaries) are inserted sequentially. New triangles come from per-thread free lists and
// per-thread ranges of fresh slots reserved before each pass, so the mesh arrays never grow
// while threads run. Why this design rather than locks or partition-and-merge: no atomics or
// locks on the hot path, no merge step, and each thread's work depends only on its own
// triangles and on mixed ones frozen for the pass, so a run is deterministic for a thread count.
// The second pass uses another curve (the Hilbert curve of the grid shifted by 0.382 of its width,
// wrapping): moving the boundaries along the same curve does not help, since its half and quarter
// ranges share the dyadic border lines. On 10^6 uniform points and 2 threads about 98.9% of the
// points go through the threads; the tail (0.35%) is mostly points next to the hull, whose
// cavities meet long hull triangles spanning ranges. Memory: one starting_at array shared by
// all threads (each writes only entries of its own vertices), so it does not grow with the
// thread count; a cavity's triangles are marked dead in tv while it grows (own triangles, which
// no other thread reads) and unmarked when the point is deferred. ThreadSanitizer (GCC 12, libtbb
// uninstrumented; release/acquire pairs make the task boundaries visible) reports nothing on the
// walk, the cavity, the star or the partition in the unit tests: its reports there (160-166 at
// stop 49) are all on oneTBB's own task objects and ranges, which it cannot see synchronized.
// Invariant: the Delaunay triangulation under the shared symbolic perturbation (by input index) is
// unique, so the result has exactly the triangles of the sequential construction (tested
// canonically); only their numbering differs. Predicates: orient2d, incircle (+ incircle_sos).
#pragma once

#include <span>

#include "triangulation/delaunay/delaunay_2d.hpp"
#include "triangulation/delaunay/parallel_rounds.hpp"  // resolve_thread_count

namespace exactmesh::triangulation {

/// The Delaunay triangulation of xy (2·#V coordinates) built by `threads` threads (>= 1) over
/// the BRIO order of options.seed (options.order and options.location are not used). Same
/// triangles as bowyer_watson_2d; counters.threads = threads. Throws InputError on bad input.
Delaunay2Result parallel_bowyer_watson_2d(std::span<const double> xy,
                                          const Delaunay2Options& options, unsigned threads);

}  // namespace exactmesh::triangulation
