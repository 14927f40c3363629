// SPDX-License-Identifier: MIT
// Regional maximum areas (Triangle's -a with a .poly: the fourth number of a region line, the
// region's largest triangle area; zero, negative or absent: no constraint) for the generators
// that carry regions (issue 11):
//  - Delaunay refinement takes a triangle of a region with maximum area A as too big when its
//    area exceeds A (exact: predicates/triangle_area.hpp), beside its size function;
//  - frontal Delaunay takes the region's area as a size: the edge of the equilateral triangle of
//    area A, s_A = sqrt(4 A / sqrt 3), the smaller of it and the size function
//    (size_with_region_areas);
//  - the budget check of every generator counts area / A triangles in such a region.
// Which region a triangle lies in is found by giving the constrained Delaunay triangulation the
// region's number (1, 2, ...) as its attribute (numbered_regions): attributes flood the regions
// and follow every edit of ConstrainedTriangulation2, so the number is read per triangle.
#pragma once

#include <span>
#include <vector>

#include "generators/sizing/size_function.hpp"
#include "triangulation/constrained/constrained_2d.hpp"

namespace exactmesh::generators {

/// True when some region (4 numbers each) has a maximum area > 0.
bool has_region_areas(std::span<const double> regions);

/// The regions with each attribute replaced by the region's number + 1 (0 stays "no region").
std::vector<double> numbered_regions(std::span<const double> regions);

/// The maximum area of the region whose number + 1 is `numbered_attribute` (a triangle's
/// attribute in a triangulation built from numbered_regions); 0 when none.
double region_area_of(std::span<const double> regions, double numbered_attribute);

/// The original attribute of the region whose number + 1 is `numbered_attribute` (0 for 0).
double region_attribute_of(std::span<const double> regions, double numbered_attribute);

/// s_A = sqrt(4 A / sqrt 3) = 2 sqrt(A) / 3^(1/4), without overflow (+infinity for A <= 0).
double equilateral_side_of_area(double area);

/// The equilateral triangles of side s that triangle (p, q, r) holds: twice its area over
/// s^2 sqrt(3) / 2, the sides divided by s first (no square of a coordinate is formed);
/// +infinity on overflow. The unit of every triangle budget (regional areas, sizes).
double triangles_of_side(const double* p, const double* q, const double* r, double side);

/// area(p, q, r) / A in units of s_A (no square of a coordinate is formed; +infinity on
/// overflow): the triangles of area A that triangle (p, q, r) holds, as a budget counts them.
double triangles_of_area(const double* p, const double* q, const double* r, double area);

/// The number of triangles the regions' maximum areas ask for at least: the sum of area / A
/// over the triangles of `domain` (built from numbered_regions, exterior removed) that lie in a
/// region with A > 0, in units of s_A (no square of a coordinate is formed; +infinity when the
/// count overflows).
double region_area_triangle_count(const triangulation::Cdt2Result& domain,
                                  std::span<const double> regions);

/// `size` where no region has a maximum area, else min(size, s_A of the region at the point)
/// (on a segment or vertex between regions: the smallest of theirs), the region found by exact
/// point location in the input's constrained Delaunay triangulation. An unbounded `size` stays
/// unbounded.
/// @throws InputError as constrained_delaunay_2d.
SizeFunction size_with_region_areas(const triangulation::Pslg& pslg, const SizeFunction& size,
                                    const triangulation::Cdt2Options& cdt);

class MeshDomain2;
/// The same over the domain's triangulation, built once (MeshDomain2::triangulation).
SizeFunction size_with_region_areas(const MeshDomain2& domain, const SizeFunction& size);

}  // namespace exactmesh::generators
