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

// proofs/gappa/in_ellipse_filter.g: differences and metric entries each normalised by their own
// power of two; min and max bound both maxima (degree 5 in the underflow and overflow terms).
inline constexpr double in_ellipse_filter_eps = 0x1.37fffffffffffp-41;
inline constexpr double in_ellipse_filter_min = 0x1p-180;
inline constexpr double in_ellipse_filter_max = 0x1p+180;

// Relative filters: the sign of a computed value is certified when it exceeds eps times a
// computed bound on the sum of its monomials' magnitudes (a permanent). Each eps is the least
// power of two (so eps * bound is exact) that Gappa proves in proofs/gappa/<name>.g; the CTest
// test `proofs.<name>` (proofs/check_relative_constants.cmake) proves eps and fails eps / 2.
// The model and the reduction to it are in proofs/invariants/filters.md, "Relative filters".

// proofs/gappa/compare_angles_filter.g (predicates/angle_comparisons_2d.cpp)
inline constexpr double compare_angles_filter_eps = 0x1p-49;
// proofs/gappa/compare_lengths_filter.g (predicates/angle_comparisons_2d.cpp)
inline constexpr double compare_lengths_filter_eps = 0x1p-50;
// proofs/gappa/compare_metric_lengths_filter.g (predicates/metric_lengths.cpp)
inline constexpr double compare_metric_lengths_filter_eps = 0x1p-50;
// proofs/gappa/dot_sign_filter.g (corner_dot_sign, direction_dot_sign)
inline constexpr double dot_sign_filter_eps = 0x1p-50;
// The window of the double stages of angle_comparisons_2d: every nonzero computed coordinate
// difference lies in [min, max], so no operation of the filters or the expansions underflows
// or overflows (argument in predicates/angle_comparisons_2d.cpp); outside it, other stages.
inline constexpr double angle_comparisons_2d_window_min = 0x1p-200;
inline constexpr double angle_comparisons_2d_window_max = 0x1p+200;
// proofs/gappa/dot_sign_long_double_filter.g (direction_dot_sign's long double stage)
inline constexpr long double dot_sign_long_double_filter_eps = 0x1p-61L;
// proofs/gappa/within_rounding_filter.g (predicates/within_rounding_of_segment.cpp)
inline constexpr long double within_rounding_filter_eps = 0x1p-61L;
// proofs/gappa/angle_comparisons_3d_filter.g: the long double filter of compare_dihedral and
// compare_volume_edge certifies |value| > factor (k + 1) 2^-64 magnitude for a value with at
// most k <= max_roundings roundings per monomial; it abstains above max_roundings.
inline constexpr long double angle_comparisons_3d_filter_factor = 0x1p+0L;
inline constexpr int angle_comparisons_3d_filter_max_roundings = 64;

// Relative filters with the rounding count in the type (predicates/relative_filter.hpp): each
// eps is the least power of two Gappa proves in proofs/gappa/<name>.g for the largest of the
// filter's counts below, and the CTest test proofs.<name> requires the script to state its goal
// for every count listed here; the code static_asserts that each term's count is at most the
// count it is certified with. The window: every nonzero scaled difference (the largest in
// [1, 2)) is at least window_min, so nothing underflows up to degree 9 (argument in
// relative_filter.hpp and proofs/invariants/filters.md).
// proofs/gappa/dot_sign_3d_filter.g (predicates/dot_sign_3d.cpp)
inline constexpr double dot_sign_3d_filter_eps = 0x1p-50;
inline constexpr int dot_sign_3d_filter_roundings = 5;
inline constexpr double dot_sign_3d_filter_window_min = 0x1p-400;
// proofs/gappa/tet_quality_3d_*_filter.g (predicates/tet_quality_3d.cpp)
inline constexpr double tet_quality_3d_filter_window_min = 0x1p-50;
inline constexpr double tet_quality_3d_lengths_filter_eps = 0x1p-50;
inline constexpr int tet_quality_3d_lengths_filter_roundings = 6;
inline constexpr double tet_quality_3d_angle_filter_eps = 0x1p-49;
inline constexpr int tet_quality_3d_angle_dot_roundings = 5;
inline constexpr int tet_quality_3d_angle_filter_roundings = 12;
inline constexpr double tet_quality_3d_volume_filter_eps = 0x1p-49;
inline constexpr int tet_quality_3d_volume_det_roundings = 8;
inline constexpr int tet_quality_3d_volume_filter_roundings = 9;
inline constexpr double tet_quality_3d_equatorial_filter_eps = 0x1p-48;
inline constexpr int tet_quality_3d_equatorial_filter_roundings = 19;
inline constexpr double tet_quality_3d_radius_edge_filter_eps = 0x1p-48;
inline constexpr int tet_quality_3d_radius_edge_filter_roundings = 28;

// triangle_area_sign's stage A (predicates/triangle_area.cpp) certifies r = fl(det - bound)
// when |r| > eps (|p| + |q|) + result_eps (|det| + |bound|) + floor, all computed, the
// differences scaled to a largest magnitude in [1, 2). proofs/gappa/triangle_area_filter.g; the
// CTest test proofs.triangle_area_filter (proofs/check_triangle_area_constants.cmake) proves the
// three and fails if eps / 2 or result_eps / 2 is proven too (floor is not the least: 2^-1071
// is proven as well; it is kept so that every decision stays the same).
inline constexpr double triangle_area_filter_eps = 0x1p-51;
inline constexpr double triangle_area_filter_result_eps = 0x1p-52;
inline constexpr double triangle_area_filter_floor = 0x1p-1060;

}  // namespace exactmesh::predicates
