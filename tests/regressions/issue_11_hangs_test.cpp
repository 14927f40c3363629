// SPDX-License-Identifier: MIT
// Issue 11, hangs of Delaunay refinement with its default size: nested squares a hair apart ran
// for minutes (restoring Delaunay after each boundary split looked up edges by walking the star
// of a vertex with thousands of slivers in its fan: quadratic). Each test here was a hang; each
// now ends in a few seconds in a release build (keep it so: no TIMEOUT property is set on the
// discovered tests), with a valid mesh or one clear error naming the budget.
#include <gtest/gtest.h>

#include <string>

#include "base/errors.hpp"
#include "generators/mesh_2d/mesh_generators_2d.hpp"
#include "tests/support/mesh_checks_2d.hpp"
#include "tests/support/pslg_fixtures_2d.hpp"

namespace {

namespace em = exactmesh;
namespace gen = exactmesh::generators;
using exactmesh::testing::add_loop;
using exactmesh::testing::Input;

/// `count` squares [-h, h]^2, h = 1 + k gap, each a closed loop.
Input nested_squares(int count, double gap) {
    Input in;
    for (int k = 0; k < count; ++k) {
        const double h = 1 + k * gap;
        add_loop(in, {-h, -h, h, -h, h, h, -h, h});
    }
    return in;
}

std::string geometry_error(const Input& in, const gen::MeshOptions2& options) {
    try {
        gen::find_mesh_generator_2d("delaunay-refinement").run(in.pslg(), options);
    } catch (const em::GeometryError& error) {
        return error.what();
    }
    return {};
}

TEST(Regression, issue_11_nested_squares_1e_5_apart_end_at_the_budget) {
    // Three squares 1e-5 apart: the strips between them need millions of triangles at 20.7
    // degrees; the automatic budget of 10^6 Steiner points ends the run (3.5 s) with an error
    // that names the budget and the narrow strips first (it blamed only --min-angle).
    const std::string error = geometry_error(nested_squares(3, 1e-5), {});
    EXPECT_NE(error.find("more than 1000000 Steiner points"), std::string::npos) << error;
    EXPECT_NE(error.find("the automatic budget: raise --max-steiner"), std::string::npos) << error;
    EXPECT_NE(error.find("strips far narrower"), std::string::npos) << error;
}

TEST(Regression, issue_11_thirty_nested_squares_1e_6_apart_end_at_the_budget) {
    const std::string error = geometry_error(nested_squares(30, 1e-6), {});
    EXPECT_NE(error.find("more than 1000000 Steiner points"), std::string::npos) << error;
}

TEST(Regression, issue_11_nested_squares_1e_3_apart_give_a_valid_mesh) {
    // The same shape with gaps the budget allows: a constrained Delaunay mesh of the squares
    // and the strips (no hole point: all of it is the domain, so the even-odd outside test of
    // the check does not apply), every angle at least 20.7 degrees (the input's are 90).
    const Input in = nested_squares(3, 1e-3);
    const gen::MeshRun2 run = gen::find_mesh_generator_2d("delaunay-refinement").run(in.pslg(), {});
    const auto& result = run.mesh;
    const auto check = exactmesh::testing::check_quality_mesh(
        result.mesh, result.input_vertex_count, in.xy, in.segments, result.pieces, {}, false);
    EXPECT_TRUE(check.ok) << check.problem;
    EXPECT_GE(check.min_angle, 20.7);
    EXPECT_GT(result.mesh.triangle_count(), 10000u);
}

}  // namespace
