// SPDX-License-Identifier: MIT
// Bowyer-Watson 2D Delaunay triangulation [Bowyer81, Watson81; seed material §2.2].
// Each point: locate a triangle in conflict (visibility walk), grow the cavity of triangles
// whose perturbed circumcircle contains the point (breadth first over neighbours), and
// connect the point to the cavity's boundary, which is star-shaped from it.
// Invariant: after every insertion the triangulation is the perturbed Delaunay triangulation.
// Cost: O(n log n) expected with random or BRIO order; O(n^2) for adversarial orders.
// Predicates: orient2d (walk, hull), incircle_sos (cavity).
#pragma once

#include <span>

#include "triangulation/delaunay/delaunay_2d.hpp"

namespace exactmesh::triangulation {

/// The Delaunay triangulation of xy (2·#V coordinates). Throws InputError on bad input.
Delaunay2Result bowyer_watson_2d(std::span<const double> xy, const Delaunay2Options& options = {});

}  // namespace exactmesh::triangulation
