// SPDX-License-Identifier: MIT
// The 3D generators' scale invariance, checked one way by every generator's test: a mesh of the
// PLC scaled by 2^k is the reference mesh with every coordinate times 2^k (the coordinates by
// scaled_coordinates.hpp's coordinates_scaled_by), the same tetrahedra and subfaces.
#pragma once

#include <gtest/gtest.h>

#include "tests/support/scaled_coordinates.hpp"
#include "triangulation/mesh/conforming_mesh_3d.hpp"

namespace exactmesh::testing {

inline void expect_scaled_mesh(const triangulation::ConformingMesh3& scaled,
                               const triangulation::ConformingMesh3& reference, int exponent) {
    EXPECT_EQ(scaled.mesh.tets, reference.mesh.tets) << "scaled by 2^" << exponent;
    EXPECT_EQ(scaled.subfaces, reference.subfaces) << "scaled by 2^" << exponent;
    EXPECT_TRUE(coordinates_scaled_by(scaled.mesh.xyz, reference.mesh.xyz, exponent));
}

}  // namespace exactmesh::testing
