// SPDX-License-Identifier: MIT
// Built-in sample domains of 3D mesh generation (issue 15), piecewise linear complexes that
// pass validate_plc_3d and check_surface_closed_3d, so `exactmesh tetmesh --domain` and the
// benchmarks need no input file:
//  - box-with-hole: the unit cube [0, 1]^3 with a centred cubic cavity [0.25, 0.75]^3 (a volume
//    hole point at its centre); outer facets marker 1, cavity facets marker 2;
//  - ellipsoid: the ellipsoid x^2 + (y / 0.75)^2 + (z / 0.5)^2 = 1, triangulated as the
//    octahedron's faces subdivided n times (n = ceil(pi / 2 / size)) and projected radially onto
//    the analytic surface, each point computed in long double and rounded once to double;
//    8 n^2 triangle facets, marker 1;
//  - wing: the NACA 0012 section of the 2D naca0012 domain (generators/boundary, chord 1, same
//    sampling) extruded from the wall z = 0 to the wall z = 1 inside the far-field box
//    [-1.5, 2.5] x [-2, 2] x [0, 1]; each wall facet is the box side with the section as a
//    hole; far field marker 1, walls 2, wing surface 3; a volume hole point inside the wing.
#pragma once

#include <string_view>

#include "triangulation/recovery_3d/plc_3d.hpp"

namespace exactmesh::generators {

enum class SampleDomain3 { BoxWithHole, Ellipsoid, Wing };

inline constexpr SampleDomain3 kAllSampleDomains3[] = {
    SampleDomain3::BoxWithHole, SampleDomain3::Ellipsoid, SampleDomain3::Wing};

/// "box-with-hole", "ellipsoid", "wing".
std::string_view sample_domain_3d_name(SampleDomain3 d);
/// @throws InputError naming the unknown domain and the known ones.
SampleDomain3 sample_domain_3d_from_name(std::string_view name);

/// The domain's PLC. `size` (> 0) is the target edge length of curved surfaces: the
/// ellipsoid's triangles, the wing section's sampling (a uniform size in the 2D domain); <= 0
/// takes the domain's default (0.1 for the ellipsoid, the 2D naca0012 domain's graded size for
/// the wing). The box has no curved surface and ignores it.
/// @throws InputError for a NaN or infinite size, or one that asks for more than 10^6 surface
/// vertices (with the estimate), before any sampling.
triangulation::Plc3 sample_domain_3d(SampleDomain3 d, double size = 0);

}  // namespace exactmesh::generators
