// SPDX-License-Identifier: MIT
// Optional per-thread predicate counters: calls, and the stage each call ended in.
// Compiled in only with EXACTMESH_PREDICATE_STATS; otherwise EM_STAT expands to nothing.
#pragma once

#include <cstdint>

namespace exactmesh::predicates {

/// Counters for one predicate. A call ends in exactly one stage, so
/// calls == filter + exact_differences + adaptive + expansion + gmp.
struct StageCounts {
    std::uint64_t calls = 0;
    std::uint64_t filter = 0;             ///< certified by the floating-point filter (stage A)
    std::uint64_t exact_differences = 0;  ///< differences were exact: stage B, exactly, decided
    std::uint64_t adaptive = 0;           ///< certified by an error bound of stage B or C
    std::uint64_t expansion = 0;          ///< full expansion arithmetic (stage C)
    std::uint64_t gmp = 0;                ///< outside the expansion-safe range: GMP (stage D)
    /// Not a stage of its own: calls whose coordinates were outside the expansion-safe range
    /// and were scaled into it by a power of two (exact), then decided by the stages above.
    std::uint64_t rescaled = 0;
};

/// The comparisons of angle_comparisons_2d/3d and within_rounding_of_segment use the same
/// stages: filter (a relative filter, or a long double one), exact_differences (expansion
/// arithmetic on exact differences), adaptive (direction_dot_sign's long double stage), gmp.
struct PredicateStats {
    StageCounts orient2d, incircle, orient3d, insphere;
    StageCounts compare_angles, compare_lengths, corner_dot_sign, direction_dot_sign;
    StageCounts within_rounding_of_segment, compare_dihedral, compare_volume_edge;
    StageCounts in_ellipse, compare_metric_lengths;
    /// dot_sign_3d and the refinement decisions of tet_quality_3d: filter (a relative double
    /// filter) or gmp; dot_sign_3d also expansion (exact products of the exact differences);
    /// in_equatorial_sphere_3d also expansion (four points in one coordinate plane: the 2D
    /// incircle and orient2d).
    StageCounts dot_sign_3d, compare_radius_edge_3d, compare_tet_volume_3d;
    StageCounts in_equatorial_sphere_3d, compare_angle_60_3d, compare_lengths_3d;
};

/// True when the library was built with EXACTMESH_PREDICATE_STATS.
bool stats_enabled() noexcept;
/// This thread's counters (all zero when stats are disabled).
PredicateStats& thread_stats() noexcept;
void reset_thread_stats() noexcept;

}  // namespace exactmesh::predicates

#if defined(EXACTMESH_PREDICATE_STATS)
#define EM_STAT(pred, stage) (++::exactmesh::predicates::thread_stats().pred.stage)
#else
#define EM_STAT(pred, stage) ((void)0)
#endif
