// SPDX-License-Identifier: MIT
// Bowyer-Watson 3D Delaunay tetrahedralization [Bowyer81, Watson81; seed material §2.2, in 3D].
// Each point: locate a tetrahedron in conflict (remembering visibility walk), grow the cavity
// of tetrahedra whose perturbed circumsphere contains the point (breadth first over
// neighbours; infinite tetrahedra conflict when the point sees their hull face), and join the
// point to the cavity's boundary faces, which is star-shaped from it.
// Invariant: after every insertion the tetrahedralization is the perturbed Delaunay one (the
// regular triangulation of weights -eps^index; proofs/invariants/delaunay_3d.md).
// Cost: O(n log n) expected for uniform points with BRIO; O(n^2) in the worst case.
// Predicates: orient3d (walk, hull), insphere_sos (cavity).
#pragma once

#include <span>

#include "triangulation/delaunay/delaunay_3d.hpp"

namespace exactmesh::triangulation {

/// The Delaunay tetrahedralization of xyz (3·#V coordinates). Throws InputError on bad input.
Delaunay3Result bowyer_watson_3d(std::span<const double> xyz, const Delaunay3Options& options = {});

}  // namespace exactmesh::triangulation
