// SPDX-License-Identifier: MIT
// Size conformity of a tetrahedral mesh to a 3D size function (issue 15's quality report: the 3D
// counterpart of quality_2d's size_conformity): every edge's length over the size at its
// midpoint, once per edge. A report, not a decision: lengths are std::hypot of the coordinate
// differences (no squares to overflow at 2^600 or underflow at 2^-600), so the ratios of a mesh
// and its size scaled by 2^k are the same.
#pragma once

#include <cstdint>

#include "generators/sizing/size_function_3d.hpp"
#include "triangulation/mesh/tetrahedralization_3d.hpp"

namespace exactmesh::generators {

struct SizeConformity3 {
    std::uint64_t edges = 0;
    double min = 0, median = 0, mean = 0, max = 0;  ///< edge length / size at its midpoint
    double within = 0;  ///< share of edges with a ratio in [0.7, 1.4] (frontal's target band)
};

/// @pre mesh has a tetrahedron; size.defined(). @throws InputError when the size is not a
/// finite number > 0 at an edge's midpoint.
SizeConformity3 size_conformity_3d(const triangulation::Tetrahedralization3& mesh,
                                   const SizeFunction3& size);

}  // namespace exactmesh::generators
