// SPDX-License-Identifier: MIT
// Delaunay refinement against CGAL's Delaunay_mesher_2 (the reference peer), on the built-in
// sample domains with their own (graded or uniform) size functions and with uniform sizes, at
// 20.7 and 30 degrees: both meshes pass the same exact checks (constrained Delaunay, every
// segment a chain of pieces, nothing outside the domain, closed by pieces), both meet the
// size bound, both meet the angle bound where there is no small input angle, and the element
// counts agree within a factor 1.5 (the algorithms differ in their orders and split points,
// not in their criteria).
#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "generators/delaunay_refinement_2d.hpp"
#include "generators/sample_domains.hpp"
#include "tests/support/cgal_mesh_2d.hpp"
#include "tests/support/mesh_checks_2d.hpp"

namespace em = exactmesh;
namespace gen = exactmesh::generators;
namespace tri = exactmesh::triangulation;

namespace {

void compare(gen::SampleDomain domain, const gen::SizeFunction& size, double min_angle) {
    const std::string label = std::string(gen::sample_domain_name(domain)) + ", " + size.describe() + ", " +
                              std::to_string(min_angle);
    const gen::DomainPslg pslg = gen::sample_domain(domain, size);
    gen::RefinementOptions2 options;
    options.min_angle = min_angle;
    options.size = size;
    const auto ours = gen::delaunay_refinement_2d(tri::Pslg{pslg.xy, pslg.segments, pslg.holes, {}}, options);
    const std::function<double(double, double)> s = [&size](double x, double y) { return size(x, y); };
    const auto our_check = em::testing::check_quality_mesh(ours.mesh.mesh, ours.mesh.input_vertex_count, pslg.xy,
                                                           pslg.segments, ours.mesh.pieces, s);
    ASSERT_TRUE(our_check.ok) << label << " (ours): " << our_check.problem;

    const em::testing::CgalMesh cgal = em::testing::cgal_delaunay_mesh_2d(pslg.xy, pslg.segments, pslg.holes, min_angle, size);
    std::vector<std::uint32_t> cgal_pieces;
    const tri::Triangulation2 theirs = em::testing::cgal_mesh_triangulation(cgal, cgal_pieces);
    const auto cgal_check = em::testing::check_quality_mesh(theirs, static_cast<std::uint32_t>(pslg.xy.size() / 2),
                                                            pslg.xy, pslg.segments, cgal_pieces, s);
    ASSERT_TRUE(cgal_check.ok) << label << " (CGAL): " << cgal_check.problem;

    EXPECT_LE(our_check.max_size_ratio, 1 + 1e-9) << label;
    EXPECT_LE(cgal_check.max_size_ratio, 1 + 1e-9) << label;
    if (domain != gen::SampleDomain::Key) {  // the key has a 10-degree tooth
        EXPECT_GE(our_check.min_angle, min_angle - 1e-9) << label;
        EXPECT_GE(cgal_check.min_angle, min_angle - 1e-6) << label;
    }
    const double ratio = static_cast<double>(ours.mesh.mesh.triangle_count()) / theirs.triangle_count();
    EXPECT_GT(ratio, 1 / 1.5) << label << ": ours " << ours.mesh.mesh.triangle_count() << ", CGAL "
                              << theirs.triangle_count();
    EXPECT_LT(ratio, 1.5) << label << ": ours " << ours.mesh.mesh.triangle_count() << ", CGAL "
                          << theirs.triangle_count();
}

}  // namespace

TEST(Differential_DelaunayRefinement, SampleDomainsWithTheirOwnSizes) {
    for (const gen::SampleDomain d : gen::kAllSampleDomains) {
        for (const double angle : {20.7, 30.0}) compare(d, gen::sample_domain_size(d), angle);
    }
}

TEST(Differential_DelaunayRefinement, SampleDomainsWithUniformSizes) {
    compare(gen::SampleDomain::SquareWithHoles, gen::SizeFunction::uniform(0.01), 20.7);
    compare(gen::SampleDomain::Naca0012, gen::SizeFunction::uniform(0.05), 20.7);
    compare(gen::SampleDomain::Key, gen::SizeFunction::uniform(0.01), 25.0);
}
