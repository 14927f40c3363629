// SPDX-License-Identifier: MIT
// Tanemura-Merriam 2D Delaunay triangulation [TanemuraOgawaOgita83, Merriam92; seed material
// §2.2.3]: gift-wrapping from the convex hull inwards. Each open front edge a -> b takes as
// third vertex the point c on its left whose circle through a, b, c contains no other point
// (perturbed incircle, so the choice is unique); the new triangle's other edges close an
// open edge or open a new one. A uniform grid of about two points per cell (finer where the
// points crowd) finds candidates: square rings of cells around a start point just left of
// ab, each clipped to the cells of the current best circle's part left of ab, until the
// rings hold all of them. A cell that still holds more than 64 points (a cluster far smaller
// than the bounding box, or coordinates spread over many magnitudes) is searched through a
// kd-tree of exact bounding boxes instead. Candidates and boxes are decided in double
// precision where the error bounds make it certain, in a frame scaled by a power of two to
// the edge (so no square under- or overflows) and, near the circle, by its power from the
// nearest of a, b, c (so a point near them on a huge circle is decided at its own scale);
// by the exact predicates otherwise. The front sweeps the grid row by row.
// Invariant: every triangle made is a (perturbed) Delaunay triangle; open edges bound the
// triangulated region; fewer than 2n triangles (asserted). Cost: O(n) for the grid (counting
// sort), O(k log k) for the kd-trees of k crowded points, plus expected O(1) cells per edge
// on evenly spread input; long thin lenses near the hull widen the search, and lenses holding
// O(n) points (points on a convex arc such as the sorted parabola, where every third vertex
// is the arc's first point; near-collinear sets) make it O(n^2). Predicates: orient2d,
// incircle_sos.
#pragma once

#include <span>

#include "triangulation/delaunay/delaunay_2d.hpp"

namespace exactmesh::triangulation {

/// The Delaunay triangulation of xy (2·#V coordinates); options.order and options.location
/// are not used.
Delaunay2Result tanemura_merriam_2d(std::span<const double> xy,
                                    const Delaunay2Options& options = {});

}  // namespace exactmesh::triangulation
