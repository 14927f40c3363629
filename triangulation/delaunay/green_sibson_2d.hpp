// SPDX-License-Identifier: MIT
// Green-Sibson 2D Delaunay triangulation [GreenSibson78, Lawson77; seed material §2.2]:
// locate the point, split its triangle in three (or the edge it lies on and both neighbours
// in four), then restore the Delaunay property by Lawson flips of the edges opposite the new
// point, propagating outwards.
// Invariant: triangles around the new point that are not yet checked sit on a stack; every
// other edge is locally (perturbed) Delaunay. Flips only touch edges opposite the new point.
// Cost: O(n log n) expected with random or BRIO order (expected O(1) flips per point).
// Predicates: orient2d (walk, split case), incircle_sos (flips).
#pragma once

#include <span>

#include "triangulation/delaunay/delaunay_2d.hpp"

namespace exactmesh::triangulation {

/// The Delaunay triangulation of xy (2·#V coordinates). Throws InputError on bad input.
Delaunay2Result green_sibson_2d(std::span<const double> xy, const Delaunay2Options& options = {});

namespace detail {
class Delaunay2Core;
/// Builds the Delaunay triangulation of core's points in core.mesh (insertion order as the core
/// holds them). Returns false, leaving no triangle, when all points are collinear. For
/// constructions that go on editing the mesh (constrained_2d).
bool green_sibson_insert_all(Delaunay2Core& core);
}  // namespace detail

}  // namespace exactmesh::triangulation
