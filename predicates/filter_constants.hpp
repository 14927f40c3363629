// SPDX-License-Identifier: MIT
// Stage-A filter constants. Each *_filter_eps is the bound proven by proofs/gappa/<pred>_filter.g
// for differences normalised to (-2, 2) (see proofs/invariants/filters.md); the CTest test
// `proofs.filter_constants` reruns Gappa and fails if a value here differs from the proven one.
// *_filter_min / *_filter_max bound the largest coordinate difference: inside that range no
// intermediate value of the filter overflows and underflow is covered by the proof's format.
#pragma once

namespace exactmesh::predicates {

// proofs/gappa/orient2d_filter.g
inline constexpr double orient2d_filter_eps = 0x1p-48;
inline constexpr double orient2d_filter_min = 0x1p-450;
inline constexpr double orient2d_filter_max = 0x1p+450;

// proofs/gappa/orient3d_filter.g
inline constexpr double orient3d_filter_eps = 0x1p-45;
inline constexpr double orient3d_filter_min = 0x1p-300;
inline constexpr double orient3d_filter_max = 0x1p+300;

// proofs/gappa/incircle_filter.g
inline constexpr double incircle_filter_eps = 0x1p-43;
inline constexpr double incircle_filter_min = 0x1p-220;
inline constexpr double incircle_filter_max = 0x1p+220;

// proofs/gappa/insphere_filter.g
inline constexpr double insphere_filter_eps = 0x1p-40;
inline constexpr double insphere_filter_min = 0x1p-180;
inline constexpr double insphere_filter_max = 0x1p+180;

}  // namespace exactmesh::predicates
