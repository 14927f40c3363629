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

/// A permutation of 0..n-1 (n = xy.size()/2): the order in which to insert the points. With
/// `parallel`, the Brio order's keys and rounds are computed on every thread of the current
/// oneTBB arena (the same permutation); then `keys`, if given, receives hilbert_keys_2d(xy).
std::vector<std::uint32_t> insertion_order_2d(std::span<const double> xy, InsertionOrder order,
                                              std::uint64_t seed, bool parallel = false,
                                              std::vector<std::uint32_t>* keys = nullptr);

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

/// The same in 3D (n = xyz.size()/3): BRIO rounds sorted along a 3D Hilbert curve; `parallel`
/// and `keys` (then hilbert_keys_3d(xyz)) as in insertion_order_2d.
std::vector<std::uint32_t> insertion_order_3d(std::span<const double> xyz, InsertionOrder order,
                                              std::uint64_t seed, bool parallel = false,
                                              std::vector<std::uint32_t>* keys = nullptr);

/// The position of each point along the Hilbert curve of a 2^10 x 2^10 x 2^10 grid over the
/// points' bounding box (the keys of insertion_order_3d's rounds); `cell_shift` and `parallel`
/// as in hilbert_keys_2d (parallel_bowyer_watson_3d's second curve).
std::vector<std::uint32_t> hilbert_keys_3d(std::span<const double> xyz,
                                           std::uint32_t cell_shift = 0, bool parallel = false);

/// Sorts `indices` in place along a 3D Hilbert curve over the bounding box of their points.
void hilbert_sort_3d(std::span<const double> xyz, std::span<std::uint32_t> indices);

}  // namespace exactmesh::triangulation
