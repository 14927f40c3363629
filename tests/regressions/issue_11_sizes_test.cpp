// SPDX-License-Identifier: MIT
// Issue 11, impossible sizes: every generator of the registry refuses at once (InputError naming
// the size and the estimate) a size whose element count exceeds the budget, and a size that is 0
// inside the domain, instead of minutes, gigabytes and "out of memory" (exit 3). Each test takes
// milliseconds; before the fix these runs were hangs.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "base/errors.hpp"
#include "generators/mesh_2d/mesh_generators_2d.hpp"
#include "generators/sizing/size_function.hpp"
#include "tests/support/pslg_fixtures_2d.hpp"

namespace {

namespace em = exactmesh;
namespace gen = exactmesh::generators;
namespace tri = exactmesh::triangulation;
using exactmesh::testing::polygon;

/// The InputError text of one registry run (empty when it meshes or throws something else).
std::string input_error(const gen::MeshGenerator2& g, const tri::Pslg& pslg,
                        const gen::MeshOptions2& options) {
    try {
        g.run(pslg, options);
    } catch (const em::InputError& error) {
        return error.what();
    } catch (const std::exception&) {
    }
    return {};
}

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

TEST(Regression, issue_11_tiny_uniform_size_is_refused_by_every_generator) {
    const auto square = polygon({0, 0, 1, 0, 1, 1, 0, 1});
    for (const double h : {1e-300, 1e-7}) {
        gen::MeshOptions2 options;
        options.size = gen::SizeFunction::uniform(h);
        for (const gen::MeshGenerator2& g : gen::mesh_generators_2d()) {
            const std::string error = input_error(g, square.pslg(), options);
            SCOPED_TRACE(std::string(g.name) + " at " + std::to_string(h));
            EXPECT_TRUE(contains(error, "the size (uniform")) << error;
            EXPECT_TRUE(contains(error, "automatic budget of 6.71089e+07 triangles")) << error;
            EXPECT_FALSE(contains(error, "min-angle")) << error;
        }
    }
}

TEST(Regression, issue_11_size_file_of_1e_300_is_refused) {
    const auto square = polygon({0, 0, 1, 0, 1, 1, 0, 1});
    gen::MeshOptions2 options;
    options.size = gen::parse_size_sources("uniform 1e-300\n", "tiny.size");
    for (const gen::MeshGenerator2& g : gen::mesh_generators_2d()) {
        const std::string error = input_error(g, square.pslg(), options);
        EXPECT_TRUE(contains(error, "far more than 1e300 triangles")) << g.name << ": " << error;
    }
}

TEST(Regression, issue_11_size_that_touches_zero_names_the_point) {
    const auto square = polygon({0, 0, 1, 0, 1, 1, 0, 1});
    gen::MeshOptions2 options;
    options.size = gen::SizeFunction::analytic([](double x, double) { return x; }, "x");
    for (const gen::MeshGenerator2& g : gen::mesh_generators_2d()) {
        const std::string error = input_error(g, square.pslg(), options);
        EXPECT_TRUE(contains(error, "the size function (x) is 0 at (0, 0)"))
            << g.name << ": " << error;
    }
    options.size = gen::SizeFunction::analytic([](double, double) { return NAN; }, "nan");
    EXPECT_TRUE(
        contains(input_error(gen::find_mesh_generator_2d("frontal"), square.pslg(), options),
                 "the size function (nan) is NaN at"));
}

TEST(Regression, issue_11_explicit_budget_is_checked_before_meshing) {
    // 2.3 10^6 triangles asked for, 1,000 Steiner points allowed: refused by the generators
    // whose budget is a hard limit; the advancing fronts close the front instead (a warning).
    const auto square = polygon({0, 0, 1, 0, 1, 1, 0, 1});
    gen::MeshOptions2 options;
    options.size = gen::SizeFunction::uniform(1e-3);
    options.max_steiner_points = 1000;
    for (const char* name : {"delaunay-refinement", "quadtree", "frontal"}) {
        const std::string error =
            input_error(gen::find_mesh_generator_2d(name), square.pslg(), options);
        EXPECT_TRUE(contains(error, "--max-steiner budget of about 2008 triangles"))
            << name << error;
    }
}

TEST(Regression, issue_11_element_estimate_is_the_equilateral_count_and_scale_invariant) {
    // The unit square at size 0.1: area / (sqrt(3) / 4 h^2) = 230.94 triangles; the same
    // square and size scaled by 2^600 and 2^-600 give the same estimate exactly.
    for (const int k : {0, 600, -600}) {
        const double s = std::ldexp(1.0, k);
        const auto square = polygon({0, 0, s, 0, s, s, 0, s});
        tri::Cdt2Options cdt;
        const tri::Cdt2Result domain = tri::constrained_delaunay_2d(square.pslg(), cdt);
        const double estimate =
            gen::minimum_triangle_count(domain.mesh, gen::SizeFunction::uniform(0.1 * s), 1e300);
        EXPECT_NEAR(estimate, 230.94010767585, 1e-9) << "scale 2^" << k;
    }
    // A feasible size still meshes through the check.
    const auto square = polygon({0, 0, 1, 0, 1, 1, 0, 1});
    gen::MeshOptions2 options;
    options.size = gen::SizeFunction::uniform(0.1);
    for (const gen::MeshGenerator2& g : gen::mesh_generators_2d()) {
        EXPECT_GT(g.run(square.pslg(), options).mesh.mesh.triangle_count(), 100u) << g.name;
    }
}

}  // namespace
