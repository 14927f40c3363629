// SPDX-License-Identifier: MIT
// Issue 11, "slow on a plain input": the generators that need a size (quadtree, both advancing
// fronts, frontal), given none, took the boundary spacing as the size everywhere inside (the
// linear interpolation of size_from_boundary over the domain's CDT): on a polygon of 10^4
// vertices on a circle that asked for about 18 million triangles (the quadtree stopped at its
// leaf budget after 30 s and 1.2 GB, the advancing fronts and frontal ran past 100 s), where
// Delaunay refinement without a size makes 34,000. The default is now graded away from the
// boundary (graded_boundary_size_2d.hpp). Each run here was a hang and now takes a second or two
// in a release build (no TIMEOUT property is set on the discovered tests): every generator
// finishes, its mesh passes the exact check, and its triangle count is within a small factor of
// Delaunay refinement's.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "generators/boundary/graded_boundary_size_2d.hpp"
#include "generators/boundary/sample_domains.hpp"
#include "generators/mesh_2d/mesh_generators_2d.hpp"
#include "tests/support/mesh_checks_2d.hpp"
#include "tests/support/pslg_fixtures_2d.hpp"

namespace {

namespace gen = exactmesh::generators;
using exactmesh::testing::Input;

Input near_circle(int n) {
    std::vector<double> xy;
    for (int k = 0; k < n; ++k) {
        const double t = 2 * M_PI * k / n;
        xy.insert(xy.end(), {std::cos(t), std::sin(t)});
    }
    return exactmesh::testing::polygon(xy);
}

std::uint32_t refinement_count(const Input& in) {
    return gen::find_mesh_generator_2d("delaunay-refinement")
        .run(in.pslg(), {})
        .mesh.mesh.triangle_count();
}

/// Runs every generator that needs a size with the default one; checks each mesh exactly and
/// its count against [low, high] times Delaunay refinement's.
void expect_default_size_like_refinement(const Input& in, const std::string& name, double low,
                                         double high) {
    const double reference = refinement_count(in);
    ::testing::Test::RecordProperty(name + ".delaunay-refinement", static_cast<int>(reference));
    gen::MeshOptions2 options;
    options.size = gen::graded_size_from_boundary(in.pslg());
    for (const gen::MeshGenerator2& generator : gen::mesh_generators_2d()) {
        if (!generator.needs_size) continue;
        SCOPED_TRACE(name + ", " + std::string(generator.name));
        const gen::MeshRun2 run = generator.run(in.pslg(), options);
        const auto& mesh = run.mesh;
        // The exact check (constrained Delaunay or conforming, segments as chains of pieces);
        // the even-odd outside test is skipped: it is O(segments) per triangle here.
        const exactmesh::testing::MeshCheck check = exactmesh::testing::check_quality_mesh(
            mesh.mesh, mesh.input_vertex_count, in.xy, in.segments, mesh.pieces, {}, false,
            generator.delaunay);
        EXPECT_TRUE(check.ok) << check.problem;
        const double count = mesh.mesh.triangle_count();
        EXPECT_GE(count, low * reference) << count << " vs " << reference;
        EXPECT_LE(count, high * reference) << count << " vs " << reference;
        ::testing::Test::RecordProperty(name + "." + std::string(generator.name),
                                        static_cast<int>(count));
    }
}

TEST(Regression, issue_11_default_size_on_a_10000_vertex_circle) {
    // Delaunay refinement: 34,136 triangles. The default (gradation 0.5): advancing front
    // 57k, advancing-front Delaunay 94k, frontal 60k, quadtree 290k (a quadtree leaf is at most
    // the size, so it makes about 4 times the triangles of a front for the same size).
    expect_default_size_like_refinement(near_circle(10000), "circle", 1.0, 10.0);
}

TEST(Regression, issue_11_default_size_on_the_sample_domains) {
    for (const gen::SampleDomain d : gen::kAllSampleDomains) {
        const gen::DomainPslg domain = gen::sample_domain(d);
        expect_default_size_like_refinement(exactmesh::testing::from_domain(domain),
                                            std::string(gen::sample_domain_name(d)), 0.25, 10.0);
    }
}

TEST(Regression, issue_11_default_size_scales_by_powers_of_two) {
    // The field of a domain scaled by 2^k is the field scaled by 2^k, exactly: lengths are taken
    // in a rescaled frame, never as squares that overflow (2^600) or underflow (2^-600).
    const Input in = exactmesh::testing::from_domain(gen::sample_domain(gen::SampleDomain::Key));
    const gen::SizeFunction size = gen::graded_size_from_boundary(in.pslg());
    for (const int k : {-600, 600}) {
        Input scaled = in;
        for (double& v : scaled.xy) v = std::ldexp(v, k);
        for (double& v : scaled.holes) v = std::ldexp(v, k);
        const gen::SizeFunction size_scaled = gen::graded_size_from_boundary(scaled.pslg());
        for (int i = 0; i <= 20; ++i) {
            for (int j = 0; j <= 20; ++j) {
                const double x = -0.5 + 2.0 * i / 20, y = -0.5 + 2.0 * j / 20;
                const double s = size(x, y);
                ASSERT_TRUE(std::isfinite(s) && s > 0) << x << ' ' << y;
                EXPECT_EQ(size_scaled(std::ldexp(x, k), std::ldexp(y, k)), std::ldexp(s, k))
                    << k << ": " << x << ' ' << y;
            }
        }
    }
}

}  // namespace
