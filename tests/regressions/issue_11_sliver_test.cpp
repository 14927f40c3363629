// SPDX-License-Identifier: MIT
// Issue 11, the advancing front's slow fuzz unit (was tests/data/fuzz/slow/): a quadrilateral 1
// wide and 3e231 tall with both diagonals as segments (x of the far corners 3.6e-304 and 3.1e-322),
// replayed as fuzz_mesh_generators_2d runs it (1,000 Steiner points) and with the generator's
// default budget. It took 1 s and 38 s (release) when the front's placement squared differences
// of 1e230: the projection onto a front edge overflowed (t = inf / inf = NaN, or 0 with an
// infinite distance), no edge-distance test ever rejected a new point, so points went anywhere
// near the front and it ran away (2,000-4,000 new points, none reused) until its budget closed
// it by a CDT whose swap recovery is quadratic, in GMP here (scaling that projection alone made
// the old code fast).
// Since the placement works on differences scaled by the root square's power of two (the scale
// invariance fix), the front meshes it in under 100 triangles, without a closure, in ~30 ms.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "base/errors.hpp"
#include "generators/mesh_2d/mesh_generators_2d.hpp"
#include "tests/support/fuzz_replay_2d.hpp"
#include "triangulation/checks/check_conforming_2d.hpp"
#include "triangulation/checks/check_constrained_2d.hpp"

namespace {

using Replay = exactmesh::testing::FuzzReplay2;

}  // namespace

TEST(Issue11, issue_11_sliver) {
    // Kept fast (well under a second in release) as the hang test of this input: both budgets
    // mesh it without running out, so the front is never closed by the CDT.
    for (const std::uint64_t budget : {std::uint64_t{1000}, std::uint64_t{0}}) {
        const Replay r = exactmesh::testing::replay_mesh_generators_2d(
            "mesh_generators_2d_advancing_front_wide_sliver.bin", budget);
        EXPECT_EQ(r.generator, "advancing-front");
        ASSERT_TRUE(r.meshed) << r.error;
        EXPECT_TRUE(r.check.ok) << r.check.problem;
        EXPECT_GT(r.triangles, 0U);
        EXPECT_EQ(r.counter("closure_runs"), 0U) << "budget " << budget;
    }
}
