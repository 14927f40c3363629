// SPDX-License-Identifier: MIT
// Multicore Bowyer-Watson 3D (issue 17), after HXT's partitioned insertion [MarotPellerinRemacle19
// §3], on oneTBB: the 3D form of parallel_bowyer_watson_2d, with the same rounds, ranges,
// deferral, second curve and sequential tail (parallel_rounds.hpp holds what the two share).
// The BRIO order of bowyer_watson_3d is kept: its small first rounds are inserted sequentially;
// every later round (sorted along the 3D Hilbert curve) is cut into T contiguous ranges of keys,
// one per thread. A vertex belongs to the partition whose key range holds its key (the infinite
// vertex to every partition), a tetrahedron to the partition holding its four vertices (at most
// one: it has three finite vertices). Thread p inserts a point of its range only when the walk
// to it and its whole cavity stay in tetrahedra of p; the cavity's outside neighbours may also
// be "mixed" tetrahedra (vertices in several partitions), which no thread changes during a
// pass: they are tested but never marked, and relinking the face of one that faces the cavity
// writes an entry nobody else reads or writes. A tetrahedron next to one of p's shares three
// vertices with it, so it is p's or mixed: a thread never reads what another writes. Otherwise the
// point is deferred, before anything is changed. Copies of one point are tried in the sequential
// order (detail::sweep_partition), so the copy kept, whose input index the perturbation reads, is
// the sequential one. The insertion itself is bowyer_watson_3d's (bowyer_watson_3d_cavity.hpp, the
// cavity marks in the tetrahedra's vertex slot 1, only on the thread's own). A second pass retries
// the deferred points along another curve (the grid shifted by 0.382 of its width, wrapping); what
// is still deferred joins the next round, and after the last round the rest is inserted
// sequentially. A deferred point remembers the tetrahedron where its attempt stopped (next to
// it): its next walk starts there when that is nearer than the thread's last walk and the
// thread's at the start of the pass; when it is another partition's or mixed then, the point
// waits without walking (points next to the hull, beside the large mixed tetrahedra there, were
// tried in every pass, each walk failing after about 50 steps). Each thread takes new tetrahedra
// from its own free list, filled before each pass from the shared pool (the slots freed so far,
// then fresh slots at the arrays' end): the arrays never grow while threads run; a thread whose
// list runs short defers the point. Deterministic for a thread count: each thread's work depends
// only on its partition and on the frozen mixed tetrahedra. Invariant: the Delaunay
// tetrahedralization under the shared symbolic perturbation (by input index) is unique
// (proofs/invariants/delaunay_3d.md), so the result has exactly the tetrahedra of the sequential
// construction (tested canonically); only their numbering differs. Predicates: orient3d (walks,
// hull faces), insphere + insphere_sos (cavities).
#pragma once

#include <span>

#include "triangulation/delaunay/delaunay_3d.hpp"
#include "triangulation/delaunay/parallel_rounds.hpp"  // resolve_thread_count

namespace exactmesh::triangulation {

/// The Delaunay tetrahedralization of xyz (3·#V coordinates) built by `threads` threads (>= 1)
/// over the BRIO order of options.seed (options.order is not used). Same tetrahedra as
/// bowyer_watson_3d; counters.threads = threads. Throws InputError on bad input.
Delaunay3Result parallel_bowyer_watson_3d(std::span<const double> xyz,
                                          const Delaunay3Options& options, unsigned threads);

}  // namespace exactmesh::triangulation
