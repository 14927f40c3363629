// SPDX-License-Identifier: MIT
// Tanemura-Merriam 2D Delaunay triangulation [TanemuraOgawaOgita83, Merriam92; seed material
// §2.2.3]: gift-wrapping from the convex hull inwards. Each open front edge a -> b takes as
// third vertex the point c on its left whose circle through a, b, c contains no other point
// (perturbed incircle, so the choice is unique); the new triangle's other edges close an
// open edge or open a new one. A uniform grid of about two points per cell finds candidates:
// cells are examined in rings around the edge's midpoint until the rings lie outside the
// current best circle.
// Invariant: every triangle made is a (perturbed) Delaunay triangle; open edges bound the
// triangulated region. Cost: O(n log n) for the hull sort plus expected O(1) cells per edge on
// uniform input; slivers near the hull can widen the search. Predicates: orient2d, incircle_sos.
#pragma once

#include <span>

#include "triangulation/delaunay_2d.hpp"

namespace exactmesh::triangulation {

/// The Delaunay triangulation of xy (2·#V coordinates); options.order is not used.
Delaunay2Result tanemura_merriam_2d(std::span<const double> xy,
                                    const Delaunay2Options& options = {});

}  // namespace exactmesh::triangulation
