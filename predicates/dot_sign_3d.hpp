// SPDX-License-Identifier: MIT
// dot_sign_3d(p, a, b): the exact sign of (a - p) . (b - p), i.e. whether p lies inside
// (Negative), on (Zero) or outside (Positive) the sphere with diameter ab (Thales): the
// encroachment test of 3D Delaunay refinement and boundary recovery [Shewchuk97 §3.4, in 3D].
// Stages: a relative double filter on the differences scaled by a power of two (Gappa-proven
// constant, proofs/gappa/dot_sign_3d_filter.g; it abstains when a nonzero difference is below
// 2^-400 of the largest), then GMP rationals.
#pragma once

#include <optional>

#include "predicates/sign.hpp"

namespace exactmesh::predicates {

/// Sign of (a - p) . (b - p), exact. Coordinates finite (3 doubles each).
Sign dot_sign_3d(const double* p, const double* a, const double* b);

/// The filter stage: the sign when certified, std::nullopt otherwise.
std::optional<Sign> dot_sign_3d_filter(const double* p, const double* a, const double* b);

}  // namespace exactmesh::predicates
