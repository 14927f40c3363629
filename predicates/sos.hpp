// SPDX-License-Identifier: MIT
// Symbolic perturbation (Simulation of Simplicity [EdelsbrunnerMücke90]) with ties broken by
// vertex index: a larger index means a larger infinitesimal perturbation. The rules and their
// proofs are in proofs/invariants/symbolic_perturbation.md.
//  - incircle_sos / insphere_sos perturb the lifted coordinate w = |p|^2 only
//  [DevillersTeillaud11]:
//    points do not move, so the exact orient2d/orient3d stay consistent with them, and the
//    Delaunay triangulation they define is unique (the regular triangulation with weights
//    -eps^index). Zero only when the cofactors all vanish: four collinear points in 2D,
//    five coplanar points in 3D; Delaunay algorithms never ask that.
//  - in_ellipse_sos perturbs the lifted coordinate q(p) = p^T M p the same way: its cofactors
//    are the same orient2d minors (the metric appears only in the lift column), so ties are
//    broken exactly as incircle_sos breaks them, whatever M, and with M the identity the two
//    agree on every input.
//  - orient2d_sos perturbs the coordinates themselves; never Zero for three distinct points.
#pragma once

#include <cstdint>

#include "predicates/sign.hpp"

namespace exactmesh::predicates {

/// orient2d of the points perturbed by index; equals orient2d when that is nonzero.
Sign orient2d_sos(const double* a, const double* b, const double* c, std::uint32_t ia,
                  std::uint32_t ib, std::uint32_t ic);

/// incircle with lifted coordinates perturbed by index; equals incircle when that is nonzero.
Sign incircle_sos(const double* a, const double* b, const double* c, const double* d,
                  std::uint32_t ia, std::uint32_t ib, std::uint32_t ic, std::uint32_t id);

/// in_ellipse with lifted coordinates perturbed by index; equals in_ellipse when that is nonzero.
Sign in_ellipse_sos(const double* a, const double* b, const double* c, const double* d,
                    const double* m, std::uint32_t ia, std::uint32_t ib, std::uint32_t ic,
                    std::uint32_t id);

/// insphere with lifted coordinates perturbed by index; equals insphere when that is nonzero.
Sign insphere_sos(const double* a, const double* b, const double* c, const double* d,
                  const double* e, std::uint32_t ia, std::uint32_t ib, std::uint32_t ic,
                  std::uint32_t id, std::uint32_t ie);

}  // namespace exactmesh::predicates
