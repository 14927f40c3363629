// SPDX-License-Identifier: MIT
// within_rounding_of_segment(w, s0, s1): whether the square of half-width 2^-40 max(|w_x|, |w_y|)
// around w meets the closed segment [s0, s1], exactly: the rule by which constrained
// triangulations bend a segment through a constructed vertex and their checks accept one
// (proofs/invariants/constrained_delaunay.md §4). Stages: a long double filter
// (proofs/gappa/within_rounding_filter.g), then GMP integers.
#pragma once

#include <optional>

namespace exactmesh::predicates {

/// The one rule for the vertices of a segment's chain, shared by the constrained triangulation
/// (where it bends a segment through a vertex) and check_constrained_delaunay_2d (where it accepts
/// one); proofs/invariants/constrained_delaunay.md §4. Vertex w lies within rounding of the closed
/// segment [s0, s1] when the square centred at w with half-width t = 2^-40 max(|w_x|, |w_y|) (at
/// least 2^-1074) meets the segment: relative to w itself, so that a long segment's large far end
/// does not make everything near its small end "within rounding" (a segment spanning
/// 1e-109..1e194 bent along a perpendicular chain 1e-9 away); ample for the points constructed
/// on it (a crossing rounded once lies within half an ulp of w, a rounded split point a few).
/// Exact (a long double filter whose margin within_rounding_filter_eps is proven in
/// proofs/gappa/within_rounding_filter.g, else GMP), and invariant under scaling by 2^k while t
/// is not subnormal. Coordinates finite.
bool within_rounding_of_segment(const double* w, const double* s0, const double* s1);

/// The 3D form, as the checks of 3D meshes use it: w is within rounding of the segment
/// [s0, s1] in each coordinate projection (dropping x, y or z) where the segment is not a
/// point.
bool within_rounding_of_segment_3d(const double* w, const double* s0, const double* s1);

/// The long double filter (stage A): the answer when certified, std::nullopt otherwise.
std::optional<bool> within_rounding_of_segment_filter(const double* w, const double* s0,
                                                      const double* s1);

/// The exact stage alone (stage B): GMP integers on one power-of-two scale.
bool within_rounding_of_segment_exact(const double* w, const double* s0, const double* s1);

}  // namespace exactmesh::predicates
