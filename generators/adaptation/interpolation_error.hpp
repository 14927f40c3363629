// SPDX-License-Identifier: MIT
// The error of a mesh's piecewise-linear interpolant of an analytic field (issue 13): how every
// adaptation claim is measured. The interpolant takes the field's exact values at the vertices;
// it is compared with the field at every element's centroid and at every edge's midpoint (each
// edge once), where the linear interpolant's error of a smooth field is largest or near it.
//  - maximum: the largest |u_h - u| over those points;
//  - l2: the root of the domain-area- (volume-) weighted mean of the squared error, each element
//    weighted by its measure and taking the mean of its centroid's and its edges' midpoints'
//    squared errors (a quadrature of ∫(u_h - u)² / |Ω|, so an RMS in the field's units).
// Points are constructed in double (a measurement, no decision depends on it); element measures
// are taken in the unit scale (mesh_edges.hpp), so nothing overflows at 2^±600.
#pragma once

#include <span>

#include "generators/adaptation/vertex_field.hpp"
#include "triangulation/mesh/mesh2.hpp"

namespace exactmesh::generators {

struct InterpolationError {
    double maximum = 0;
    double l2 = 0;
    std::size_t samples = 0;  ///< points compared
};

/// Over the elements (3 or 4 vertex indices each, dim 2 or 3) of the mesh whose vertex values
/// are `values` (normally sample_field of the same field and time).
/// @throws InputError as sample_field when the field is not finite at a sample point.
InterpolationError interpolation_error(std::span<const double> coordinates, unsigned dim,
                                       std::span<const triangulation::VertIdx> elements,
                                       std::span<const double> values, const AnalyticField& field,
                                       double t);

}  // namespace exactmesh::generators
