// SPDX-License-Identifier: MIT
// Per-thread predicate counters (see stats.hpp).
#include "predicates/stats.hpp"

namespace exactmesh::predicates {

namespace {
thread_local PredicateStats counters;
}  // namespace

bool stats_enabled() noexcept {
#if defined(EXACTMESH_PREDICATE_STATS)
    return true;
#else
    return false;
#endif
}

PredicateStats& thread_stats() noexcept {
    return counters;
}

void reset_thread_stats() noexcept {
    counters = PredicateStats{};
}

}  // namespace exactmesh::predicates
