// SPDX-License-Identifier: MIT
// Issue 13, a given 2D mesh as an adaptation start (mesh_input_2d.hpp): on the sample domains
// meshed and handed over as bare vertices and triangles, one hole point per hole, each exactly
// outside every triangle of the mesh (exact orient2d) and each removing its own hole from the
// boundary's constrained Delaunay triangulation; none for the concavities of a non-convex
// domain; the same points scaled by 2^±600, bit for bit; a mesh that is not Delaunay kept
// as it is and its CDT over the same region; and every kind of bad mesh an InputError.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "base/errors.hpp"
#include "generators/adaptation/mesh_input_2d.hpp"
#include "generators/boundary/sample_domains.hpp"
#include "generators/mesh_2d/mesh_generators_2d.hpp"
#include "predicates/orient2d.hpp"
#include "tests/support/adaptation_fixtures_2d.hpp"

namespace gen = exactmesh::generators;
namespace tri = exactmesh::triangulation;
using exactmesh::InputError;
using exactmesh::predicates::Sign;

namespace {

// Whether p lies in the closed triangle t of `mesh` (exact orient2d).
bool in_closed_triangle(const tri::Triangulation2& mesh, std::size_t t, const double* p) {
    const double* a = mesh.point(mesh.triangles[3 * t]);
    const double* b = mesh.point(mesh.triangles[3 * t + 1]);
    const double* c = mesh.point(mesh.triangles[3 * t + 2]);
    return exactmesh::predicates::orient2d(a, b, p) != Sign::Negative &&
           exactmesh::predicates::orient2d(b, c, p) != Sign::Negative &&
           exactmesh::predicates::orient2d(c, a, p) != Sign::Negative;
}

// Every hole point outside every closed triangle of the mesh; each hole point alone removes
// more than the exterior and, with more holes, less than all of them (a hole of its own); all
// together leave exactly the mesh's region.
void expect_hole_points_outside(const gen::GivenMeshDomain2& given) {
    const tri::Triangulation2& mesh = given.mesh;
    for (std::size_t h = 0; 2 * h < given.holes.size(); ++h) {
        const double* p = &given.holes[2 * h];
        for (std::size_t t = 0; t < mesh.triangle_count(); ++t)
            ASSERT_FALSE(in_closed_triangle(mesh, t, p)) << "hole point " << h << " triangle " << t;
        const std::vector<double> one(p, p + 2);
        const tri::Cdt2Result alone =
            tri::constrained_delaunay_2d({mesh.xy, given.segments, one, {}});
        const tri::Cdt2Result none =
            tri::constrained_delaunay_2d({mesh.xy, given.segments, {}, {}});
        EXPECT_LT(alone.mesh.triangle_count(), none.mesh.triangle_count()) << "hole point " << h;
        if (given.holes.size() > 2) {
            EXPECT_GT(alone.mesh.triangle_count(), mesh.triangle_count()) << "hole point " << h;
        }
    }
    EXPECT_EQ(given.cdt.mesh.triangle_count(), mesh.triangle_count());
    EXPECT_EQ(given.cdt.mesh.vertex_count(), mesh.vertex_count());
}

}  // namespace

TEST(Generators_MeshInput2, OneHolePointPerHoleExactlyOutsideTheMesh) {
    for (const gen::SampleDomain d : gen::kAllSampleDomains) {
        const exactmesh::testing::SampleDomainMesh r = exactmesh::testing::sample_domain_mesh(d);
        const gen::GivenMeshDomain2 given =
            gen::given_mesh_domain_2d(r.mesh.mesh.xy, r.mesh.mesh.triangles);
        SCOPED_TRACE(static_cast<int>(d));
        // The domains' own holes (square-with-holes: three; the airfoils' elements).
        EXPECT_EQ(given.holes.size(), r.domain.holes.size());
        expect_hole_points_outside(given);
        // Delaunay refinement's mesh is the CDT of its vertices and boundary.
        EXPECT_TRUE(given.mesh_is_cdt);
        // Every boundary side is a segment, directed with the mesh on its left.
        EXPECT_EQ(given.cdt.pieces.size(), given.segments.size());
    }
}

TEST(Generators_MeshInput2, HolePointsScaleBitForBit) {
    const auto holes_at = [](double scale) {
        const exactmesh::testing::SampleDomainMesh r =
            exactmesh::testing::sample_domain_mesh(gen::SampleDomain::SquareWithHoles, scale);
        return gen::given_mesh_domain_2d(r.mesh.mesh.xy, r.mesh.mesh.triangles).holes;
    };
    const std::vector<double> unit = holes_at(1);
    ASSERT_EQ(unit.size(), 6u);  // three holes
    for (const int k : {-600, 600}) {
        std::vector<double> expected = unit;
        for (double& c : expected) c = std::ldexp(c, k);
        EXPECT_EQ(holes_at(std::ldexp(1.0, k)), expected) << "2^" << k;
    }
}

// A U-shaped domain (its notch is a concavity, outside the outer boundary: no hole) with a
// square hole in its base (one hole point).
TEST(Generators_MeshInput2, NonConvexDomainGetsPointsForHolesOnly) {
    const std::vector<double> xy{0,   0,   6,   0,   6,   6,   4,   6,
                                 4,   2,   2,   2,   2,   6,   0,   6,     // the U
                                 0.5, 0.5, 1.5, 0.5, 1.5, 1.5, 0.5, 1.5};  // the hole
    const std::vector<tri::VertIdx> outline{0, 1, 1, 2, 2, 3, 3, 4,  4,  5,  5,  6,
                                            6, 7, 7, 0, 8, 9, 9, 10, 10, 11, 11, 8};
    for (const bool with_hole : {false, true}) {
        const std::size_t vertices = with_hole ? xy.size() : 16;
        const std::size_t segments = with_hole ? outline.size() : 16;
        const std::vector<double> hole{1, 1};
        const tri::Cdt2Result mesh = tri::constrained_delaunay_2d(
            {std::span(xy).first(vertices),
             std::span(outline).first(segments),
             with_hole ? std::span<const double>(hole) : std::span<const double>(),
             {}});
        const gen::GivenMeshDomain2 given =
            gen::given_mesh_domain_2d(mesh.mesh.xy, mesh.mesh.triangles);
        EXPECT_EQ(given.holes.size(), with_hole ? 2u : 0u);
        EXPECT_EQ(given.segments.size(), segments);
        expect_hole_points_outside(given);
    }
}

// The quadtree's mesh is valid but not Delaunay: kept as it is for the methods that keep it,
// and its CDT covers the same region with the same vertices.
TEST(Generators_MeshInput2, NonDelaunayMeshIsKeptAndItsCdtCoversTheSameRegion) {
    const gen::DomainPslg domain =
        gen::sample_domain(gen::SampleDomain::Key, gen::sample_domain_size(gen::SampleDomain::Key));
    gen::MeshOptions2 options;
    options.size = gen::sample_domain_size(gen::SampleDomain::Key);
    const tri::Cdt2Result mesh = gen::find_mesh_generator_2d("quadtree")
                                     .run({domain.xy, domain.segments, domain.holes, {}}, options)
                                     .mesh;
    std::vector<double> xy = mesh.mesh.xy;
    std::vector<tri::VertIdx> triangles = mesh.mesh.triangles;
    // Drop vertices no triangle uses (duplicates merged by the generator), renumbering.
    std::vector<tri::VertIdx> number(xy.size() / 2, tri::kNone);
    std::vector<double> used_xy;
    for (tri::VertIdx& v : triangles) {
        if (number[v] == tri::kNone) {
            number[v] = static_cast<tri::VertIdx>(used_xy.size() / 2);
            used_xy.insert(used_xy.end(), {xy[2 * v], xy[2 * v + 1]});
        }
        v = number[v];
    }
    const gen::GivenMeshDomain2 given = gen::given_mesh_domain_2d(used_xy, triangles);
    EXPECT_FALSE(given.mesh_is_cdt);
    EXPECT_EQ(given.holes.size(), domain.holes.size());
    expect_hole_points_outside(given);
    const tri::Cdt2Result kept = gen::given_mesh_result_2d(given);
    EXPECT_EQ(kept.mesh.triangles, triangles);
    EXPECT_EQ(kept.input_vertex_count, kept.mesh.vertex_count());
    EXPECT_EQ(kept.pieces, given.segments);
}

TEST(Generators_MeshInput2, BadMeshesAreInputErrors) {
    // The unit square split by its diagonal.
    const std::vector<double> square{0, 0, 1, 0, 1, 1, 0, 1};
    EXPECT_NO_THROW(gen::given_mesh_domain_2d(square, {0, 1, 2, 0, 2, 3}));
    // An inverted triangle.
    EXPECT_THROW(gen::given_mesh_domain_2d(square, {0, 1, 2, 0, 3, 2}), InputError);
    // A vertex no triangle uses.
    EXPECT_THROW(gen::given_mesh_domain_2d({0, 0, 1, 0, 1, 1, 0, 1, 3, 3}, {0, 1, 2, 0, 2, 3}),
                 InputError);
    // Two vertices at one point (a crack along the diagonal's half).
    EXPECT_THROW(gen::given_mesh_domain_2d({0, 0, 1, 0, 1, 1, 0, 1, 0.5, 0.5, 0.5, 0.5},
                                           {0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 5}),
                 InputError);
    // Two triangles whose boundaries cross.
    EXPECT_THROW(
        gen::given_mesh_domain_2d({0, 0, 2, 0, 0, 2, 1, -1, 3, 1, 1, 1}, {0, 1, 2, 3, 4, 5}),
        InputError);
    // Two triangles touching at a vertex of one inside an edge of the other.
    EXPECT_THROW(
        gen::given_mesh_domain_2d({0, 0, 2, 0, 1, 1, 1, 0, 2, -1, 0, -1}, {0, 1, 2, 3, 5, 4}),
        InputError);
    // The same directed edge twice (overlapping triangles).
    EXPECT_THROW(gen::given_mesh_domain_2d({0, 0, 1, 0, 0, 1, 0.2, 0.2}, {0, 1, 2, 0, 1, 3}),
                 InputError);
    // No triangle at all.
    EXPECT_THROW(gen::given_mesh_domain_2d(square, {}), InputError);
}
