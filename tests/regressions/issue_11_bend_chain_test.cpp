// SPDX-License-Identifier: MIT
// Issue 11, found by the CI's libFuzzer run after the issue was closed (fuzz_mesh_generators_2d,
// 2026-12-02; tests/data/fuzz/mesh_generators_2d_front_bend_subnormal.bin): a triangle of side 1
// whose short sides are subnormal, overlapped by a quadrilateral whose side 5 - 6 runs from
// (-2.4e-185, -2.4e-185) to (4.7e-62, 0.6), passing 2.4e-185 to the left of vertex 2 at
// (0, 3.5e-310). The three frontal generators discretize the boundary first; no split point of
// 5 - 6 could be placed, and the boundary bent the piece at vertex 2 because vertex 2 lies within
// 3 units in the last place of the piece's ends (1.1e-16 in y, 1e-77 in x). The exact checks
// accept a bend only at a vertex within its own rounding of the segment (2^-40 of its
// magnitude: 1e-320 here), so the mesh failed its check: "segment 5 (5, 6) is missing". A bend is
// now taken only where the checks' chain rule holds (within_rounding_of_segment, no step
// backwards); here the piece stays one edge. Every generator, checked exactly.
#include <gtest/gtest.h>

#include <exception>
#include <string>
#include <vector>

#include "generators/mesh_2d/mesh_generators_2d.hpp"
#include "tests/support/fuzz_replay_2d.hpp"
#include "tests/support/generated_mesh_2d.hpp"
#include "tests/support/mesh_checks_2d.hpp"
#include "tests/support/pslg_fixtures_2d.hpp"

namespace {

namespace em = exactmesh;
namespace gen = exactmesh::generators;
namespace tri = exactmesh::triangulation;

}  // namespace

TEST(Issue11BendChain, issue_11_bend_chain_fuzz_unit) {
    const auto r =
        em::testing::replay_mesh_generators_2d("mesh_generators_2d_front_bend_subnormal.bin", 1000);
    EXPECT_EQ(r.generator, "advancing-front");
    ASSERT_TRUE(r.meshed) << r.error;
    EXPECT_TRUE(r.check.ok) << r.check.problem;
    EXPECT_GT(r.triangles, 0U);
}

TEST(Issue11BendChain, issue_11_bend_chain_every_generator) {
    em::testing::Input in;
    in.xy = {0.0,
             0.0,
             1.0,
             0.0,
             0.0,
             0x0.03ffp-1022,
             0.0,
             0x0.03ffp-1022,
             0x0.03ffp-1022,
             0.0,
             -0x1.a3ffp-614,
             -0x1.a3fd999999999p-614,
             0x1.33fd999999999p-204,
             0x1.3333333333333p-1,
             0x1.999999999999ap-2,
             0x1.3333333333333p-1};
    in.segments = {0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 5, 6, 6, 7, 7, 4};
    for (const gen::MeshGenerator2& generator : gen::mesh_generators_2d()) {
        SCOPED_TRACE(std::string(generator.name));
        gen::MeshOptions2 options;
        // The refinement needs no size (its own grading); the others the fuzz target's 1/4.
        if (std::string(generator.name) != "delaunay-refinement")
            options.size = gen::SizeFunction::uniform(0.25);
        try {
            const gen::MeshRun2 run = generator.run(in.pslg(), options);
            const tri::Cdt2Result& m = run.mesh;
            const auto check = em::testing::check_mesh_of_input(m, in, generator.delaunay);
            EXPECT_TRUE(check.ok) << check.problem;
            EXPECT_GT(m.mesh.triangle_count(), 0U);
        } catch (const std::exception& e) {
            // The refinement and the quadtree stop with an error naming the features finer
            // than double precision resolves (a correct outcome; a wrong mesh is not); the
            // three frontal generators mesh it.
            const std::string name(generator.name);
            EXPECT_TRUE(name == "delaunay-refinement" || name == "quadtree") << e.what();
            EXPECT_NE(std::string(e.what()).find("finer than"), std::string::npos) << e.what();
        }
    }
}
