// SPDX-License-Identifier: MIT
// Tests of generators/boundary/mesh_domain_2d.hpp (issue 12): the domain's triangulation is built
// once, lazily, equal to the one each step used to build for itself, and a generator run over it
// gives the mesh it gives on the PSLG.
#include "generators/boundary/mesh_domain_2d.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "base/errors.hpp"
#include "generators/boundary/graded_boundary_size_2d.hpp"
#include "generators/boundary/region_areas_2d.hpp"
#include "generators/boundary/sample_domains.hpp"
#include "generators/mesh_2d/mesh_generators_2d.hpp"
#include "tests/support/error_message.hpp"
#include "tests/support/pslg_fixtures_2d.hpp"
#include "triangulation/constrained/constrained_2d.hpp"

namespace gen = exactmesh::generators;
namespace tri = exactmesh::triangulation;
using exactmesh::testing::Input;

namespace {

/// A unit square split at x = 0.5 into two regions (attributes 7.5 and -3), maximum areas as
/// given.
Input two_regions(double left_area, double right_area) {
    return {{0, 0, 0.5, 0, 1, 0, 1, 1, 0.5, 1, 0, 1},
            {0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 0, 1, 4},
            {},
            {0.25, 0.5, 7.5, left_area, 0.75, 0.5, -3, right_area}};
}

void expect_same_triangulation(const tri::Cdt2Result& a, const tri::Cdt2Result& b) {
    EXPECT_EQ(a.mesh.xy, b.mesh.xy);
    EXPECT_EQ(a.mesh.triangles, b.mesh.triangles);
    EXPECT_EQ(a.pieces, b.pieces);
    EXPECT_EQ(a.piece_segment, b.piece_segment);
    EXPECT_EQ(a.warnings, b.warnings);
}

}  // namespace

TEST(MeshDomain2, BuiltOnceOnFirstUseAsTheDomainOfThePslg) {
    const Input in = exactmesh::testing::from_domain(
        gen::sample_domain(gen::SampleDomain::Key, gen::SizeFunction::uniform(0.05)));
    tri::Cdt2Options options;
    options.recovery = tri::SegmentRecovery::Conforming;  // the domain takes Swap instead
    const gen::MeshDomain2 domain(in.pslg(), options);
    EXPECT_FALSE(domain.built());
    const tri::Cdt2Result& first = domain.triangulation();
    EXPECT_TRUE(domain.built());
    EXPECT_EQ(&first, &domain.triangulation());  // the same object, not a rebuild
    EXPECT_EQ(domain.domain_options().recovery, tri::SegmentRecovery::Swap);
    EXPECT_TRUE(domain.domain_options().remove_exterior);
    tri::Cdt2Options swap;
    swap.remove_exterior = true;
    expect_same_triangulation(first, tri::constrained_delaunay_2d(in.pslg(), swap));
    EXPECT_FALSE(domain.attributes_are_region_numbers());
}

TEST(MeshDomain2, RegionAreasNumberTheAttributesAndKeepTheTriangles) {
    const Input in = two_regions(0.001, 0.01);
    const gen::MeshDomain2 domain(in.pslg());
    ASSERT_TRUE(domain.attributes_are_region_numbers());
    const tri::Cdt2Result& cdt = domain.triangulation();
    const tri::Cdt2Result plain = tri::constrained_delaunay_2d(in.pslg());
    expect_same_triangulation(cdt, plain);
    ASSERT_EQ(cdt.triangle_attributes.size(), plain.triangle_attributes.size());
    for (std::size_t t = 0; t < cdt.triangle_attributes.size(); ++t) {
        EXPECT_EQ(gen::region_attribute_of(in.regions, cdt.triangle_attributes[t]),
                  plain.triangle_attributes[t]);
    }
    // Without areas, the attributes stay the input's.
    const Input attributes = two_regions(0, 0);
    const gen::MeshDomain2 plain_domain(attributes.pslg());
    EXPECT_FALSE(plain_domain.attributes_are_region_numbers());
    EXPECT_EQ(plain_domain.triangulation().triangle_attributes,
              tri::constrained_delaunay_2d(attributes.pslg()).triangle_attributes);
}

TEST(MeshDomain2, ANonFiniteAttributeIsReportedThoughTheAttributesAreNumbered) {
    Input in = two_regions(0.001, 0.01);
    in.regions[2] = std::numeric_limits<double>::quiet_NaN();
    const gen::MeshDomain2 domain(in.pslg());
    EXPECT_THROW(domain.triangulation(), exactmesh::InputError);
}

TEST(MeshDomain2, EveryGeneratorMakesTheSameMeshOverTheSharedDomain) {
    // A domain already built and used by the graded size (as `exactmesh mesh` shares it) gives
    // every generator the same mesh as fresh domains built for each step: nothing a step does
    // to the shared triangulation leaks into the next.
    ASSERT_FALSE(gen::mesh_generators_2d().empty());
    const Input in = exactmesh::testing::from_domain(
        gen::sample_domain(gen::SampleDomain::Key, gen::SizeFunction::uniform(0.05)));
    for (const gen::MeshGenerator2& generator : gen::mesh_generators_2d()) {
        SCOPED_TRACE(std::string(generator.name));
        gen::MeshOptions2 options;
        const gen::MeshDomain2 domain(in.pslg(), options.cdt);
        options.size = gen::graded_size_from_boundary(domain);
        const gen::MeshRun2 shared = generator.run_on_domain(domain, options);
        gen::MeshOptions2 alone;
        alone.size = gen::graded_size_from_boundary(in.pslg());
        const gen::MeshRun2 own = generator.run(in.pslg(), alone);
        EXPECT_EQ(shared.mesh.mesh.xy, own.mesh.mesh.xy);
        EXPECT_EQ(shared.mesh.mesh.triangles, own.mesh.mesh.triangles);
        EXPECT_EQ(shared.mesh.warnings, own.mesh.warnings);
        EXPECT_EQ(shared.counters, own.counters);
        EXPECT_GT(shared.mesh.mesh.triangle_count(), 100u);
    }
}

TEST(MeshDomain2, TheSizeBudgetIsCheckedOverTheDomainWhateverTheRecovery) {
    // Conforming recovery: the budget's estimate is taken over the shared (Swap) domain, as
    // the generators take it, with the message Swap gives, and no triangulation of its own.
    const Input in = exactmesh::testing::from_domain(
        gen::sample_domain(gen::SampleDomain::Key, gen::SizeFunction::uniform(0.05)));
    std::string message[2];
    for (const tri::SegmentRecovery recovery :
         {tri::SegmentRecovery::Swap, tri::SegmentRecovery::Conforming}) {
        gen::MeshOptions2 options;
        options.cdt.recovery = recovery;
        options.size = gen::SizeFunction::uniform(1e-5);
        const gen::MeshDomain2 domain(in.pslg(), options.cdt);
        message[recovery == tri::SegmentRecovery::Conforming] =
            exactmesh::testing::error_message<exactmesh::InputError>(
                [&] { gen::check_size_budget(domain, options, true); });
        EXPECT_TRUE(domain.built());
        options.size = gen::SizeFunction::uniform(0.05);
        EXPECT_NO_THROW(gen::check_size_budget(domain, options, true));
    }
    EXPECT_NE(message[0].find("automatic budget"), std::string::npos) << message[0];
    EXPECT_EQ(message[0], message[1]);
}

TEST(RegionAreas2, TrianglesOfSideTheSameAtEveryScale) {
    // The unit of the size budget and the regional one (check_size_budget): the right triangle
    // of legs 1 holds 2 / sqrt(3) equilateral triangles of side 1, at 2^600 and 2^-600 alike.
    const double expected = 1 / 0.8660254037844386;
    for (const int k : {0, 600, -600}) {
        const double u = std::ldexp(1.0, k);
        const double p[2] = {0, 0}, q[2] = {u, 0}, r[2] = {0, u};
        EXPECT_EQ(gen::triangles_of_side(p, q, r, u), expected) << k;
        EXPECT_EQ(gen::triangles_of_side(p, q, r, 2 * u), expected / 4) << k;
        EXPECT_EQ(gen::triangles_of_area(p, q, r, 0.5 * u * 0.5 * u),
                  gen::triangles_of_side(p, q, r, gen::equilateral_side_of_area(0.25 * u * u)))
            << k;
    }
    const double big = std::numeric_limits<double>::max();
    const double p[2] = {-big, -big}, q[2] = {big, -big}, r[2] = {-big, big};
    EXPECT_EQ(gen::triangles_of_side(p, q, r, 1), std::numeric_limits<double>::infinity());
}

TEST(MeshDomain2, HonouredOptions) {
    const gen::MeshGenerator2& refinement = gen::find_mesh_generator_2d("delaunay-refinement");
    const gen::MeshGenerator2& quadtree = gen::find_mesh_generator_2d("quadtree");
    EXPECT_TRUE(refinement.honours.contains(gen::MeshOption::MinAngle));
    EXPECT_TRUE(refinement.honours.contains(gen::MeshOption::RegionAttributes));
    EXPECT_FALSE(quadtree.honours.contains(gen::MeshOption::MinAngle));
    EXPECT_FALSE(quadtree.honours.contains(gen::MeshOption::RegionAttributes));
    for (const gen::MeshGenerator2& g : gen::mesh_generators_2d()) {
        EXPECT_TRUE(g.honours.contains(gen::MeshOption::Size)) << g.name;
        EXPECT_TRUE(g.honours.contains(gen::MeshOption::MaxSteinerPoints)) << g.name;
    }
    EXPECT_EQ(gen::mesh_option_name(gen::MeshOption::MinAngle), "--min-angle");
}
