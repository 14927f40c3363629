// SPDX-License-Identifier: MIT
// Green-Sibson 3D Delaunay tetrahedralization by incremental insertion and flips [Joe91;
// EdelsbrunnerShah96; GreenSibson78 in 3D; seed material §2.2]: locate the point, split its
// tetrahedron in four (1-4), or the face it lies on and both neighbours in six (2-6), or the
// n tetrahedra around the edge it lies on in 2n; then restore the Delaunay property by 2-3,
// 3-2 and 4-4 flips of the faces opposite the new point (its link), propagating outwards.
// Invariant: every face not in the link of the new point is locally (perturbed) Delaunay;
// each flip removes one tetrahedron in conflict with the point from the link's far side
// (proofs/invariants/delaunay_3d.md). Ties: insphere_sos, as bowyer_watson_3d, so both return
// the same tetrahedralization.
// Cost: O(n log n) expected for uniform points with BRIO (expected O(1) flips per point).
// Predicates: orient3d (walk, split and flip cases), insphere_sos (flips).
#pragma once

#include <span>

#include "triangulation/delaunay/delaunay_3d.hpp"

namespace exactmesh::triangulation {

/// The Delaunay tetrahedralization of xyz (3·#V coordinates). Throws InputError on bad input.
Delaunay3Result green_sibson_3d(std::span<const double> xyz, const Delaunay3Options& options = {});

}  // namespace exactmesh::triangulation
