// SPDX-License-Identifier: MIT
// Stage-A filter constants. Each *_filter_eps is the least double Gappa proves, in
// proofs/gappa/<pred>_filter.g, to bound |det - Det| for differences normalised below 2 in
// magnitude (see proofs/invariants/filters.md); the CTest test `proofs.<pred>_filter` reruns
// Gappa on the values below and fails unless eps is proven and the next double below is not.
// *_filter_min / *_filter_max (powers of two) bound the largest coordinate difference: inside
// that range no intermediate value of the filter overflows, and the proof's underflow term
// 2^(-1074 + degree * log2(1 / min)) is computed from min by the same test.
#pragma once

namespace exactmesh::predicates {

// proofs/gappa/orient2d_filter.g
inline constexpr double orient2d_filter_eps = 0x1p-49;
inline constexpr double orient2d_filter_min = 0x1p-450;
inline constexpr double orient2d_filter_max = 0x1p+450;

// proofs/gappa/orient3d_filter.g
inline constexpr double orient3d_filter_eps = 0x1.8p-46;
inline constexpr double orient3d_filter_min = 0x1p-300;
inline constexpr double orient3d_filter_max = 0x1p+300;

// proofs/gappa/incircle_filter.g
inline constexpr double incircle_filter_eps = 0x1.08p-43;
inline constexpr double incircle_filter_min = 0x1p-220;
inline constexpr double incircle_filter_max = 0x1p+220;

// proofs/gappa/insphere_filter.g
inline constexpr double insphere_filter_eps = 0x1.49fffffffffffp-39;
inline constexpr double insphere_filter_min = 0x1p-180;
inline constexpr double insphere_filter_max = 0x1p+180;

}  // namespace exactmesh::predicates
