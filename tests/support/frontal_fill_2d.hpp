// SPDX-License-Identifier: MIT
// frontal_fill: the frontal generator as the fill of the layered generators (their `fill`
// option), with a size and a Steiner budget, for the tests of advancing layers. Test support.
#pragma once

#include <cstdint>
#include <utility>

#include "generators/boundary/mesh_domain_2d.hpp"
#include "generators/mesh_2d/frontal_delaunay_2d.hpp"
#include "generators/sizing/size_function.hpp"
#include "triangulation/constrained/constrained_2d.hpp"

namespace exactmesh::testing {

inline triangulation::Cdt2Result frontal_fill(const generators::MeshDomain2& domain,
                                              const generators::SizeFunction& size,
                                              std::uint64_t budget) {
    generators::FrontalDelaunayOptions2 frontal;
    frontal.size = size;
    frontal.max_steiner_points = budget;
    return std::move(generators::frontal_delaunay_2d(domain, frontal).mesh);
}

}  // namespace exactmesh::testing
