// SPDX-License-Identifier: MIT
// Insertion orders for incremental constructions: as given, uniformly random, and BRIO
// (biased randomized insertion order [AmentaChoiRote03]) with each round sorted along a
// Hilbert curve (2D, or 3D [Skilling04]), so that consecutive points are close and walks stay
// short.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace exactmesh::triangulation {

/// The order in which an incremental construction inserts its points.
enum class InsertionOrder { Given, Random, Brio };

/// "given", "random", "brio" (the command's --order, the Python module's order=).
/// @throws InputError naming the unknown name and the known ones.
InsertionOrder insertion_order_from_name(std::string_view name);

/// A permutation of 0..n-1 (n = xy.size()/2): the order in which to insert the points (Brio:
/// brio_order(hilbert_keys_2d(xy), inverse_permutation(random_permutation(n, seed)))). With
/// `parallel`, the Brio order's keys and rounds are computed on every thread of the current oneTBB
/// arena (the same permutation).
std::vector<std::uint32_t> insertion_order_2d(std::span<const double> xy, InsertionOrder order,
                                              std::uint64_t seed, bool parallel = false);

/// A uniformly random permutation of 0..n-1 drawn from `seed` (one random stream: sequential).
std::vector<std::uint32_t> random_permutation(std::size_t n, std::uint64_t seed);

/// The positions of a permutation: inverse[perm[k]] = k (with `parallel`, on every thread of
/// the current oneTBB arena).
std::vector<std::uint32_t> inverse_permutation(std::span<const std::uint32_t> perm,
                                               bool parallel = false);

/// BRIO rounds grow by 2^kBrioRoundShift = 8: each round holds 7/8 of the points inserted up to
/// its end, as CGAL's spatial_sort in 3D (ratio 0.125; 0.25 in 2D). Any constant ratio keeps
/// BRIO's expected bounds [AmentaChoiRote03, who halve]; a larger last round inserts more points
/// next to the ones just inserted, whose triangles are still in cache. Halving rounds made the
/// insertion of 10^6 uniform points about 20% (2D) and 5-9% (3D) slower on an AMD EPYC with a
/// 1 MiB L2 per core, for 4-7% fewer conflict tests (README, issue 17, stop 53).
inline constexpr unsigned kBrioRoundShift = 3;

/// Where the BRIO rounds of n points begin, then n: round 0 the positions [0, b_1) (at most 64
/// points), round r >= 1 the positions [n >> 3j, n >> 3(j - 1)) with j = R - r for R rounds
/// after round 0 (kBrioRoundShift = 3; repeated division by 8 gives the same bounds).
std::vector<std::uint32_t> brio_round_begins(std::uint32_t n);

/// The BRIO order [AmentaChoiRote03] of n = keys.size() points: with point i at position
/// position[i] of a random permutation, the rounds are brio_round_begins(n)'s ranges of
/// positions; each round's points sorted by key, equal keys by position, but the first round's
/// (random: by position). With `parallel`, on every thread of the current oneTBB arena (the
/// same order).
std::vector<std::uint32_t> brio_order(std::span<const std::uint32_t> keys,
                                      std::span<const std::uint32_t> position,
                                      bool parallel = false);

/// The position of each point (n = xy.size()/2) along the Hilbert curve of a 2^16 x 2^16 grid
/// over the points' bounding box: the keys by which the BRIO rounds of insertion_order_2d are
/// sorted (the same keys for any permutation of the same points). With a `cell_shift`, the grid
/// cells are first moved by that many cells along both axes, wrapping around: another curve,
/// whose ranges have other borders (parallel_bowyer_watson_2d's second pass). With `parallel`,
/// computed on every thread of the current oneTBB arena (the same keys).
std::vector<std::uint32_t> hilbert_keys_2d(std::span<const double> xy, std::uint32_t cell_shift = 0,
                                           bool parallel = false);

/// Sorts `indices` in place along a Hilbert curve over the bounding box of their points.
void hilbert_sort_2d(std::span<const double> xy, std::span<std::uint32_t> indices);

/// The same in 3D (n = xyz.size()/3): BRIO rounds sorted along a 3D Hilbert curve
/// (hilbert_keys_3d); `parallel` as in insertion_order_2d.
std::vector<std::uint32_t> insertion_order_3d(std::span<const double> xyz, InsertionOrder order,
                                              std::uint64_t seed, bool parallel = false);

/// The position of each point along the Hilbert curve of a 2^10 x 2^10 x 2^10 grid over the
/// points' bounding box (the keys of insertion_order_3d's rounds); `cell_shift` and `parallel`
/// as in hilbert_keys_2d (parallel_bowyer_watson_3d's second curve).
std::vector<std::uint32_t> hilbert_keys_3d(std::span<const double> xyz,
                                           std::uint32_t cell_shift = 0, bool parallel = false);

/// Sorts `indices` in place along a 3D Hilbert curve over the bounding box of their points.
void hilbert_sort_3d(std::span<const double> xyz, std::span<std::uint32_t> indices);

}  // namespace exactmesh::triangulation
