// SPDX-License-Identifier: MIT
// Tests of generators/mesh_3d/size_conformity_3d: each edge once, its length over the size at
// its midpoint, the same at 2^+-600 (no squared length).
#include "generators/mesh_3d/size_conformity_3d.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "base/errors.hpp"

namespace exactmesh::generators {
namespace {

/// The corner tetrahedron (0, 0, 0), (s, 0, 0), (0, s, 0), (0, 0, s) and its mirror image across
/// x = 0 sharing the face x = 0: 9 edges, 4 of length s, 5 of length s sqrt 2.
triangulation::Tetrahedralization3 two_corner_tets(double s) {
    triangulation::Tetrahedralization3 mesh;
    mesh.xyz = {0, 0, 0, s, 0, 0, 0, s, 0, 0, 0, s, -s, 0, 0};
    mesh.tets = {0, 1, 2, 3, 0, 2, 4, 3};
    return mesh;
}

TEST(Generators_SizeConformity3d, EachEdgeOnceOverTheSizeAtItsMidpoint) {
    for (const int e : {0, 600, -600}) {
        const double s = std::ldexp(1.0, e);
        const SizeConformity3 c = size_conformity_3d(two_corner_tets(s), SizeFunction3::uniform(s));
        EXPECT_EQ(c.edges, 9u) << e;
        EXPECT_EQ(c.min, 1.0) << e;
        EXPECT_DOUBLE_EQ(c.max, std::sqrt(2.0)) << e;
        EXPECT_DOUBLE_EQ(c.median, std::sqrt(2.0)) << e;  // 4 ones, 5 roots of 2
        EXPECT_DOUBLE_EQ(c.mean, (4 + 5 * std::sqrt(2.0)) / 9) << e;
        EXPECT_DOUBLE_EQ(c.within, 4.0 / 9) << e;  // sqrt 2 lies above 1.4
    }
    // The size read at each edge's midpoint: twice the length along x, so the x edges halve.
    const SizeConformity3 graded = size_conformity_3d(
        two_corner_tets(1),
        SizeFunction3::analytic([](double x, double, double) { return x != 0 ? 2.0 : 1.0; }, "x"));
    EXPECT_EQ(graded.min, 0.5);
    // A size that is not a number > 0 at a midpoint is the size's InputError.
    EXPECT_THROW(size_conformity_3d(
                     two_corner_tets(1),
                     SizeFunction3::analytic([](double, double, double) { return 0.0; }, "zero")),
                 InputError);
}

}  // namespace
}  // namespace exactmesh::generators
