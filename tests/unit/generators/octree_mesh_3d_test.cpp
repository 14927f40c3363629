// SPDX-License-Identifier: MIT
// Tests of generators/mesh_3d/octree_mesh_3d (and octree_3d): box-with-hole and the ellipsoid
// at a uniform and a graded size, every output checked exactly by check_boundary_conformity_3d
// (positive tetrahedra by exact orient3d, mutual neighbours, every subsegment and subface
// present, the boundary made of subfaces), input vertices kept, the domain's volume, a core,
// 2:1 balance of the octree, every face in at most two tetrahedra; the identical mesh for the
// input and size scaled by 2^600 and 2^-600; size and budget errors; region attributes on a
// box cut in two (each tetrahedron on its region's side of the cut, exactly; at 2^+-600; a
// later region point overriding; points in a hole or outside ignored); a region volume bound
// capping the size (the regular tetrahedron's edge, exact under 2^(3k) scaling), at 2^+-300.
#include "generators/mesh_3d/octree_mesh_3d.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>

#include "base/errors.hpp"
#include "generators/boundary_3d/sample_domains_3d.hpp"
#include "generators/mesh_3d/region_volumes_3d.hpp"
#include "generators/mesh_3d/sliver_removal_3d.hpp"
#include "predicates/orient3d.hpp"
#include "predicates/tet_quality_3d.hpp"
#include "tests/support/plcs_3d.hpp"
#include "tests/support/scaled_mesh_3d.hpp"
#include "tests/support/test_scale.hpp"
#include "triangulation/recovery_3d/boundary_recovery_3d.hpp"
#include "triangulation/recovery_3d/check_boundary_conformity_3d.hpp"

namespace exactmesh::generators {
namespace {

using predicates::Sign;
using triangulation::ConformingMesh3;
using triangulation::Plc3;

/// Coarser sizes when EXACTMESH_TEST_SCALE asks for less work, at most 1.25 times, and never
/// above `ceiling`: the box-with-hole needs leaves of 1/16 to have a core (leaves split while
/// their edge exceeds 1.8 h: h in [0.035, 0.069)).
double test_size(double h0, double ceiling) {
    const double scale = exactmesh::testing::test_scale();
    const double factor = scale < 1 ? std::min(1.25, 1 / std::cbrt(scale)) : 1.0;
    return std::min(h0 * factor, ceiling);
}

OctreeMesh3Options options_for(SizeFunction3 size) {
    OctreeMesh3Options options;
    options.size = std::move(size);
    return options;
}

/// Every leaf's neighbours across faces, edges and corners are at most one level coarser.
void expect_balanced(const Octree3& octree) {
    std::size_t violations = 0;
    for (const OctreeCell3& cell : octree.leaves()) {
        for (int d = 0; d < 27; ++d) {
            if (d == 13) continue;
            const std::uint32_t n = octree.find_leaf(cell.level, std::int64_t{cell.i} + d % 3 - 1,
                                                     std::int64_t{cell.j} + (d / 3) % 3 - 1,
                                                     std::int64_t{cell.k} + d / 9 - 1);
            if (n == Octree3::kOutside || n == Octree3::kFiner) continue;
            if (octree.leaves()[n].level + 1 < cell.level) ++violations;
        }
    }
    EXPECT_EQ(violations, 0u) << "2:1 balance";
}

/// Every face of the mesh in one or two tetrahedra, and every tetrahedron positive (exact).
void expect_conforming(const triangulation::Tetrahedralization3& mesh) {
    std::map<std::array<std::uint32_t, 3>, int> faces;
    std::size_t flat = 0;
    for (std::size_t t = 0; t < mesh.tets.size(); t += 4) {
        const std::uint32_t* v = &mesh.tets[t];
        if (predicates::orient3d(mesh.point(v[0]), mesh.point(v[1]), mesh.point(v[2]),
                                 mesh.point(v[3])) != Sign::Positive)
            ++flat;
        for (unsigned k = 0; k < 4; ++k) {
            std::array<std::uint32_t, 3> f{v[(k + 1) % 4], v[(k + 2) % 4], v[(k + 3) % 4]};
            std::sort(f.begin(), f.end());
            ++faces[f];
        }
    }
    EXPECT_EQ(flat, 0u) << "tetrahedra not positively oriented";
    std::size_t over = 0;
    for (const auto& [face, count] : faces) over += count > 2;
    EXPECT_EQ(over, 0u) << "faces in more than two tetrahedra";
}

OctreeMesh3Result mesh_and_check(const Plc3& plc, const SizeFunction3& size,
                                 const std::string& what) {
    const ConformingMesh3 recovered = triangulation::boundary_recovery_3d(plc).mesh;
    const double domain_volume = triangulation::mesh_volume(recovered.mesh);
    OctreeMesh3Result result = octree_mesh_3d(plc, recovered, options_for(size));
    const auto report = triangulation::check_boundary_conformity_3d(plc, result.mesh);
    EXPECT_TRUE(report.ok) << what << ": " << report.problem;
    EXPECT_EQ(result.mesh.input_vertex_count, plc.vertex_count()) << what;
    for (std::size_t i = 0; i < plc.xyz.size(); ++i)
        EXPECT_EQ(result.mesh.mesh.xyz[i], plc.xyz[i]) << what << " coordinate " << i;
    EXPECT_NEAR(triangulation::mesh_volume(result.mesh.mesh), domain_volume, 1e-9 * domain_volume)
        << what;
    expect_conforming(result.mesh.mesh);
    expect_balanced(result.octree);
    const auto& c = result.counters;
    EXPECT_GT(c.core_leaves, 0u) << what;
    EXPECT_GT(c.template_tets, 0u) << what;
    EXPECT_EQ(c.template_tets + c.band_tets, result.mesh.mesh.tet_count()) << what;
    std::printf(
        "%s (%s): %u vertices, %u tets; %llu leaves (%llu core in %llu components, %llu balance "
        "splits), %llu interface squares, %llu band tets, %llu template tets\n",
        what.c_str(), size.describe().c_str(), result.mesh.mesh.vertex_count(),
        result.mesh.mesh.tet_count(), static_cast<unsigned long long>(c.leaves),
        static_cast<unsigned long long>(c.core_leaves),
        static_cast<unsigned long long>(c.core_components),
        static_cast<unsigned long long>(c.balance_splits),
        static_cast<unsigned long long>(c.interface_facets),
        static_cast<unsigned long long>(c.band_tets),
        static_cast<unsigned long long>(c.template_tets));
    return result;
}

TEST(Generators_OctreeMesh3d, BoxWithHoleUniformAndGraded) {
    const Plc3 plc = sample_domain_3d(SampleDomain3::BoxWithHole);
    const double h = test_size(0.06, 0.065);
    const OctreeMesh3Result uniform =
        mesh_and_check(plc, SizeFunction3::uniform(h), "box-with-hole uniform");
    // Sliver removal applies to the merged mesh (the command runs it): still conforming, no
    // tetrahedron left below its threshold here.
    const SliverRemoval3Result improved = sliver_removal_3d(uniform.mesh);
    const auto report = triangulation::check_boundary_conformity_3d(plc, improved.mesh);
    EXPECT_TRUE(report.ok) << report.problem;
    EXPECT_GT(improved.counters.slivers_before, 0u);
    EXPECT_EQ(improved.counters.slivers_after, 0u);
    // Finer near the corner at the origin: leaves of several levels, hanging corners.
    const OctreeMesh3Result graded = mesh_and_check(
        plc,
        SizeFunction3::analytic(
            [h](double x, double y, double z) { return h * (0.5 + 0.8 * (x + y + z) / 3); },
            "graded"),
        "box-with-hole graded");
    EXPECT_GE(graded.counters.max_level, 5u);
    // A size that drops fourfold in one corner: leaves two levels finer there, which the 2:1
    // balance must grade (balance splits), with finer core neighbours across faces and edges.
    const OctreeMesh3Result step = mesh_and_check(
        plc,
        SizeFunction3::analytic(
            [h](double x, double y, double z) { return x < 0.2 && y < 0.2 && z < 0.2 ? h / 4 : h; },
            "step"),
        "box-with-hole step");
    EXPECT_GT(step.counters.balance_splits, 0u);
    EXPECT_GE(step.counters.max_level, 6u);
}

TEST(Generators_OctreeMesh3d, RootCubeIsAlignedToHalfItsPowerOfTwoEdge) {
    // A box straddling zero: the root [-1, 1]^3 (edge 2, aligned to 1).
    const Octree3 centred({-1, -0.75, -0.5}, {1, 0.75, 0.5});
    EXPECT_EQ(centred.root_edge(), 2.0);
    EXPECT_EQ(centred.corner(), (std::array<double, 3>{-1, -1, -1}));
    const Octree3 offset({0.3, 0.3, 0.3}, {0.9, 0.5, 0.4});
    EXPECT_EQ(offset.root_edge(), 1.0);
    EXPECT_EQ(offset.corner(), (std::array<double, 3>{0, 0, 0}));
    // Scaled by 2^k: the root scaled by 2^k.
    for (const int e : {600, -600}) {
        const Octree3 scaled({std::ldexp(0.3, e), std::ldexp(0.3, e), std::ldexp(0.3, e)},
                             {std::ldexp(0.9, e), std::ldexp(0.5, e), std::ldexp(0.4, e)});
        EXPECT_EQ(scaled.root_edge(), std::ldexp(1.0, e));
        EXPECT_EQ(scaled.corner()[0], 0.0);
    }
    // Too far from the origin for exact grid coordinates: refused.
    EXPECT_THROW(Octree3({1e12, 0, 0}, {1e12 + 1, 1, 1}), InputError);
}

TEST(Generators_OctreeMesh3d, EllipsoidUniformAndGraded) {
    const double h = test_size(0.1, 0.12);
    const Plc3 plc = sample_domain_3d(SampleDomain3::Ellipsoid, h);
    mesh_and_check(plc, SizeFunction3::uniform(h), "ellipsoid uniform");
    mesh_and_check(plc,
                   SizeFunction3::analytic(
                       [h](double x, double, double) { return h * (0.6 + 0.4 * std::fabs(x)); },
                       "graded in x"),
                   "ellipsoid graded");
}

TEST(Generators_OctreeMesh3d, DomainsTouchingThemselvesAlongAnEdgeOrAtACorner) {
    // The band of a core made of leaves that meet at an edge or a corner touches itself there,
    // as do these domains: stars in two pieces (the graded box-with-hole above ended in an
    // InternalError before the pieces were kept).
    for (const bool edge : {true, false}) {
        mesh_and_check(triangulation::cubes_touching(edge), SizeFunction3::uniform(0.2),
                       edge ? "cubes sharing an edge" : "cubes sharing a corner");
    }
}

TEST(Generators_OctreeMesh3d, FreeVerticesInsideAreBandVertices) {
    // Free vertices inside the unit cube, one on an octree leaf's face plane (x = 1/4 at
    // h = 0.1: the interface squares of the core lie on multiples of 1/16): the band's PLC
    // refused it as "in a facet but in no facet polygon", and one inside a core leaf would have
    // been left out by the templates. Leaves near a free vertex are band leaves now.
    Plc3 plc = triangulation::box(1, 1, 1);
    plc.xyz.insert(plc.xyz.end(), {0.5, 0.5, 0.5, 0.25, 0.3, 0.7, 0.3125, 0.40625, 0.6});
    const OctreeMesh3Result result =
        mesh_and_check(plc, SizeFunction3::uniform(0.1), "cube with free vertices inside");
    std::vector<bool> used(result.mesh.mesh.vertex_count(), false);
    for (const triangulation::VertIdx v : result.mesh.mesh.tets) used[v] = true;
    for (triangulation::VertIdx v = 8; v < 11; ++v)
        EXPECT_TRUE(used[v]) << "free vertex " << v << " left out";
    for (const int e : {600, -600}) {
        const Plc3 s = triangulation::scaled(plc, e);
        const OctreeMesh3Result scaled =
            octree_mesh_3d(s, triangulation::boundary_recovery_3d(s).mesh,
                           options_for(SizeFunction3::uniform(std::ldexp(0.1, e))));
        exactmesh::testing::expect_scaled_mesh(scaled.mesh, result.mesh, e);
    }
}

TEST(Generators_OctreeMesh3d, AFreeVertexFarOutsideLeavesTheTreeTheDomainsBox) {
    // A hostile campaign's cube with a free vertex 1e6 above it: the octree's box held every
    // vertex, and the size 0.25 asked for 6.4e7 leaves ("leaf budget exceeded at once") where
    // the frontal generator and Delaunay refinement mesh it. The box is the facets' now: the
    // same tree as without the vertex, which no generator keeps (it is outside the domain; the
    // recovered mesh, and so the band's tetrahedra, differ a little: 638 against 656).
    Plc3 plc = triangulation::box(1, 1, 1);
    plc.xyz.insert(plc.xyz.end(), {0.625, 0.1875, 0.5625});
    const OctreeMesh3Result inside =
        mesh_and_check(plc, SizeFunction3::uniform(0.25), "cube with a free vertex");
    plc.xyz.insert(plc.xyz.end(), {0.3125, 0.4375, 1e6});
    const OctreeMesh3Result far =
        mesh_and_check(plc, SizeFunction3::uniform(0.25), "cube with a free vertex far above");
    EXPECT_EQ(far.counters.estimated_leaves, inside.counters.estimated_leaves);
    EXPECT_EQ(far.counters.core_leaves, inside.counters.core_leaves);
    EXPECT_NEAR(static_cast<double>(far.mesh.mesh.tet_count()),
                static_cast<double>(inside.mesh.mesh.tet_count()),
                0.1 * static_cast<double>(inside.mesh.mesh.tet_count()));
}

TEST(Generators_OctreeMesh3d, ScaledByPowersOfTwoGivesTheScaledMesh) {
    const double h = test_size(0.06, 0.065);
    const Plc3 plc = sample_domain_3d(SampleDomain3::BoxWithHole);
    const OctreeMesh3Result reference =
        mesh_and_check(plc, SizeFunction3::uniform(h), "box-with-hole unscaled");
    for (const int e : {600, -600}) {
        const Plc3 s = triangulation::scaled(plc, e);
        const ConformingMesh3 recovered = triangulation::boundary_recovery_3d(s).mesh;
        const OctreeMesh3Result result =
            octree_mesh_3d(s, recovered, options_for(SizeFunction3::uniform(std::ldexp(h, e))));
        EXPECT_TRUE(triangulation::check_boundary_conformity_3d(s, result.mesh).ok) << e;
        exactmesh::testing::expect_scaled_mesh(result.mesh, reference.mesh, e);
        EXPECT_EQ(result.counters.core_leaves, reference.counters.core_leaves);
        EXPECT_EQ(result.counters.estimated_leaves, reference.counters.estimated_leaves);
    }
}

TEST(Generators_OctreeMesh3d, SizeAndBudgetErrors) {
    const Plc3 plc = sample_domain_3d(SampleDomain3::BoxWithHole);
    const ConformingMesh3 recovered = triangulation::boundary_recovery_3d(plc).mesh;
    // No size, a zero or negative size (uniform: refused when made; analytic: when evaluated).
    EXPECT_THROW(octree_mesh_3d(plc, recovered, OctreeMesh3Options{}), InputError);
    EXPECT_THROW(SizeFunction3::uniform(0), InputError);
    EXPECT_THROW(SizeFunction3::uniform(-0.1), InputError);
    EXPECT_THROW(octree_mesh_3d(plc, recovered,
                                options_for(SizeFunction3::analytic(
                                    [](double, double, double) { return -0.1; }, "negative"))),
                 InputError);
    EXPECT_THROW(octree_mesh_3d(plc, recovered,
                                options_for(SizeFunction3::analytic(
                                    [](double, double, double) { return 0.0; }, "zero"))),
                 InputError);
    // The budget: refused at once from the estimate (before any octree is built) ...
    OctreeMesh3Options options = options_for(SizeFunction3::uniform(1e-3));
    options.max_leaves = 100000;
    try {
        octree_mesh_3d(plc, recovered, options);
        ADD_FAILURE() << "no budget error";
    } catch (const InputError& error) {
        const std::string text = error.what();
        EXPECT_NE(text.find("leaf budget of 100000 exceeded at once"), std::string::npos) << text;
        EXPECT_NE(text.find("about 1e+09 leaves"), std::string::npos) << text;
    }
    // ... and while refining, when the estimate passes but the leaves do not.
    // (h = 0.069: leaves split while their edge exceeds 1.8 h = 0.1242, so the unit box ends
    // with 4,096 leaves of 1/16, above the estimate's box volume / h^3 = 3,044.)
    options = options_for(SizeFunction3::uniform(0.069));
    options.max_leaves = 3500;
    try {
        octree_mesh_3d(plc, recovered, options);
        ADD_FAILURE() << "no budget error while refining";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("leaf budget of 3500 exceeded while refining"),
                  std::string::npos)
            << error.what();
    }
}

/// The tetrahedra of `mesh` whose attribute is `attribute`, as a mesh of their own (for volumes).
triangulation::Tetrahedralization3 with_attribute(const ConformingMesh3& mesh, double attribute) {
    triangulation::Tetrahedralization3 part;
    part.xyz = mesh.mesh.xyz;
    for (std::size_t t = 0; t < mesh.tet_attributes.size(); ++t)
        if (mesh.tet_attributes[t] == attribute)
            part.tets.insert(part.tets.end(), mesh.mesh.tets.begin() + 4 * std::ptrdiff_t(t),
                             mesh.mesh.tets.begin() + 4 * std::ptrdiff_t(t + 1));
    return part;
}

/// Checks a mesh of two_regions_box scaled by 2^e independently of the flood: every tetrahedron
/// carries attribute `left` or `right`, and all its corners lie on that attribute's side of the
/// plane x = 2^e or on it, with at least one strictly on that side (exact orient3d against
/// three points of the plane; the left side's sign is the origin's). Returns the count of
/// template tetrahedra (those after the band's in the merged list) per side.
std::array<std::uint32_t, 2> expect_region_sides(const OctreeMesh3Result& result, int e,
                                                 double left, double right) {
    const ConformingMesh3& mesh = result.mesh;
    const auto& m = mesh.mesh;
    std::array<std::uint32_t, 2> templates{0, 0};
    EXPECT_EQ(mesh.tet_attributes.size(), m.tet_count()) << "2^" << e;
    if (mesh.tet_attributes.size() != m.tet_count()) return templates;
    const double one = std::ldexp(1.0, e);
    const double a[3] = {one, 0, 0}, b[3] = {one, one, 0}, c[3] = {one, 0, one};
    const double origin[3] = {0, 0, 0};
    const Sign left_side = predicates::orient3d(a, b, c, origin);
    EXPECT_NE(left_side, Sign::Zero);
    std::uint32_t wrong = 0;
    for (std::uint32_t t = 0; t < m.tet_count(); ++t) {
        const double attribute = mesh.tet_attributes[t];
        EXPECT_TRUE(attribute == left || attribute == right)
            << "tetrahedron " << t << ": " << attribute << " at 2^" << e;
        const Sign side = attribute == left ? left_side : Sign(-static_cast<int>(left_side));
        bool strictly = false;
        for (unsigned k = 0; k < 4; ++k) {
            const Sign s = predicates::orient3d(a, b, c, m.point(m.tets[4 * std::size_t{t} + k]));
            if (s == side) strictly = true;
            if (s != side && s != Sign::Zero) ++wrong;
        }
        if (!strictly) ++wrong;
        if (t >= result.counters.band_tets) ++templates[attribute == left ? 0 : 1];
    }
    EXPECT_EQ(wrong, 0u) << "tetrahedra on the wrong side of x = 2^" << e << " for their attribute";
    return templates;
}

TEST(Generators_OctreeMesh3d, TwoRegionsCarryTheirAttributes) {
    // The box [0, 2] x [0, 1]^2 cut at x = 1 by an internal facet; region 1 left, 2 right.
    const Plc3 plc = triangulation::two_regions_box(-1, -1);
    const double h = test_size(0.1, 0.11);
    const OctreeMesh3Result reference =
        mesh_and_check(plc, SizeFunction3::uniform(h), "two regions");
    EXPECT_TRUE(reference.mesh.tet_max_volume.empty());  // no region has a bound
    const auto templates = expect_region_sides(reference, 0, 1, 2);
    // Both cubes have a core: their template tetrahedra got the attribute by the flood.
    EXPECT_GT(templates[0], 0u);
    EXPECT_GT(templates[1], 0u);
    EXPECT_NEAR(triangulation::mesh_volume(with_attribute(reference.mesh, 1)), 1.0, 1e-9);
    EXPECT_NEAR(triangulation::mesh_volume(with_attribute(reference.mesh, 2)), 1.0, 1e-9);
    // Sliver removal (the command runs it) keeps each tetrahedron's attribute on its side.
    OctreeMesh3Result improved = reference;
    improved.mesh = sliver_removal_3d(reference.mesh).mesh;
    improved.counters.band_tets = improved.mesh.mesh.tet_count();  // no template split known
    expect_region_sides(improved, 0, 1, 2);
    // Scaled by 2^+-600: the scaled mesh with the same attributes.
    for (const int e : {600, -600}) {
        const Plc3 s = triangulation::scaled(plc, e);
        const OctreeMesh3Result scaled =
            octree_mesh_3d(s, triangulation::boundary_recovery_3d(s).mesh,
                           options_for(SizeFunction3::uniform(std::ldexp(h, e))));
        EXPECT_TRUE(triangulation::check_boundary_conformity_3d(s, scaled.mesh).ok) << e;
        exactmesh::testing::expect_scaled_mesh(scaled.mesh, reference.mesh, e);
        EXPECT_EQ(scaled.mesh.tet_attributes, reference.mesh.tet_attributes) << e;
        expect_region_sides(scaled, e, 1, 2);
    }
    // A later region point in the same region overrides an earlier one (TetGen's order): the
    // same mesh, the left cube now 5.
    Plc3 overridden = plc;
    overridden.regions.push_back({0.25, 0.75, 0.125, 5, -1});
    const OctreeMesh3Result later =
        octree_mesh_3d(overridden, triangulation::boundary_recovery_3d(overridden).mesh,
                       options_for(SizeFunction3::uniform(h)));
    EXPECT_EQ(later.mesh.mesh.tets, reference.mesh.mesh.tets);
    expect_region_sides(later, 0, 5, 2);
}

TEST(Generators_OctreeMesh3d, RegularTetEdgeOfVolume) {
    // The regular tetrahedron of edge 1 has volume 1 / (6 sqrt 2).
    EXPECT_NEAR(regular_tet_edge_of_volume(1 / (6 * std::sqrt(2.0))), 1.0, 1e-15);
    EXPECT_NEAR(regular_tet_edge_of_volume(0.001), std::cbrt(6 * std::sqrt(2.0) * 0.001), 1e-15);
    EXPECT_TRUE(std::isinf(regular_tet_edge_of_volume(0)));
    EXPECT_TRUE(std::isinf(regular_tet_edge_of_volume(-1)));
    // The volume times 2^(3k): the same bits times 2^k, also across the exponent's thirds.
    for (const double v : {0.001, 0.3, 1.0, 5.0, 7.9, 1e-300, 1e300})
        for (const int k : {1, -1, 2, 300, -300})
            if (std::isfinite(std::ldexp(v, 3 * k)) && std::ldexp(v, 3 * k) > 1e-300) {
                EXPECT_EQ(regular_tet_edge_of_volume(std::ldexp(v, 3 * k)),
                          std::ldexp(regular_tet_edge_of_volume(v), k))
                    << v << " 2^" << 3 * k;
            }
}

TEST(Generators_OctreeMesh3d, RegionVolumeBoundsCapTheSize) {
    // The left cube bounded at V = 3e-4 (a_V = cbrt(6 sqrt(2) V) = 0.137), the right one not,
    // at size 0.2: the left cube follows a_V, the right one h.
    const double bound = 3e-4, h = 0.2;
    const Plc3 plc = triangulation::two_regions_box(bound, -1);
    const OctreeMesh3Result result = mesh_and_check(plc, SizeFunction3::uniform(h), "bounded");
    const double a = regular_tet_edge_of_volume(bound);
    EXPECT_EQ(result.size(0.5, 0.5, 0.5), a);
    EXPECT_EQ(result.size(1.5, 0.5, 0.5), h);
    EXPECT_EQ(result.size(1.0, 0.5, 0.5), a);  // on the cut: the smaller
    EXPECT_EQ(result.size(3.0, 0.5, 0.5), h);  // outside the domain
    const auto templates = expect_region_sides(result, 0, 1, 2);
    EXPECT_GT(templates[0], 0u);
    const ConformingMesh3& mesh = result.mesh;
    ASSERT_EQ(mesh.tet_max_volume.size(), mesh.mesh.tet_count());
    std::array<std::uint32_t, 2> count{0, 0};
    std::uint32_t over = 0;
    for (std::uint32_t t = 0; t < mesh.mesh.tet_count(); ++t) {
        const bool left = mesh.tet_attributes[t] == 1;
        ++count[left ? 0 : 1];
        EXPECT_EQ(mesh.tet_max_volume[t], left ? bound : -1.0) << t;
        if (!left) continue;
        const std::uint32_t* v = &mesh.mesh.tets[4 * std::size_t{t}];
        over += predicates::compare_tet_volume_3d(mesh.mesh.point(v[0]), mesh.mesh.point(v[1]),
                                                  mesh.mesh.point(v[2]), mesh.mesh.point(v[3]),
                                                  bound) == Sign::Positive;
    }
    std::printf("bounded left cube: %u tetrahedra (mean volume %.3g V), %u over V; right: %u\n",
                count[0], 1.0 / count[0] / bound, over, count[1]);
    // The size is a_V, not a bound on every volume: on average the left tetrahedra are within
    // V (the unit cube over V is 3,333), and the unbounded cube at h = 1.46 a_V is far coarser.
    EXPECT_GE(count[0], static_cast<std::uint32_t>(1 / bound));
    EXPECT_GT(count[0], 2 * count[1]);
    // Scaled by 2^+-300 (the bound by 2^+-900): the scaled mesh, the same regions and bounds.
    for (const int e : {300, -300}) {
        const Plc3 s = triangulation::scaled(plc, e);
        const OctreeMesh3Result scaled =
            octree_mesh_3d(s, triangulation::boundary_recovery_3d(s).mesh,
                           options_for(SizeFunction3::uniform(std::ldexp(h, e))));
        exactmesh::testing::expect_scaled_mesh(scaled.mesh, mesh, e);
        EXPECT_EQ(scaled.mesh.tet_attributes, mesh.tet_attributes) << e;
        ASSERT_EQ(scaled.mesh.tet_max_volume.size(), mesh.tet_max_volume.size());
        for (std::size_t t = 0; t < mesh.tet_max_volume.size(); ++t)
            ASSERT_EQ(scaled.mesh.tet_max_volume[t],
                      mesh.tet_max_volume[t] > 0 ? std::ldexp(mesh.tet_max_volume[t], 3 * e) : -1.0)
                << t;
    }
}

TEST(Generators_OctreeMesh3d, RegionPointsInAHoleOrOutsideAreWarnedAndIgnored) {
    // Box-with-hole (the hole [0.25, 0.75]^3): one region point in the hole, one outside the
    // box, one in the domain. Boundary recovery warns of the two (the octree meshes the same
    // domain and does not repeat them); every tetrahedron gets the third one's attribute.
    Plc3 plc = sample_domain_3d(SampleDomain3::BoxWithHole);
    plc.regions.push_back({0.5, 0.5, 0.5, 9, -1});
    plc.regions.push_back({2, 2, 2, 8, -1});
    plc.regions.push_back({0.1, 0.1, 0.1, 4, -1});
    const triangulation::BoundaryRecovery3Result recovered =
        triangulation::boundary_recovery_3d(plc);
    std::size_t region_warnings = 0;
    for (const std::string& warning : recovered.warnings)
        region_warnings +=
            warning.find("region point") != std::string::npos &&
            warning.find("lies outside the domain or in a hole: ignored") != std::string::npos;
    EXPECT_EQ(region_warnings, 2u);
    const double h = test_size(0.06, 0.065);
    const OctreeMesh3Result result =
        octree_mesh_3d(plc, recovered.mesh, options_for(SizeFunction3::uniform(h)));
    EXPECT_TRUE(triangulation::check_boundary_conformity_3d(plc, result.mesh).ok);
    EXPECT_GT(result.counters.core_leaves, 0u);
    ASSERT_EQ(result.mesh.tet_attributes.size(), result.mesh.mesh.tet_count());
    EXPECT_TRUE(std::all_of(result.mesh.tet_attributes.begin(), result.mesh.tet_attributes.end(),
                            [](double a) { return a == 4; }));
    // Only the two ignored points: every tetrahedron outside every region, attribute 0.
    plc.regions.pop_back();
    const OctreeMesh3Result none =
        octree_mesh_3d(plc, recovered.mesh, options_for(SizeFunction3::uniform(h)));
    ASSERT_EQ(none.mesh.tet_attributes.size(), none.mesh.mesh.tet_count());
    EXPECT_TRUE(std::all_of(none.mesh.tet_attributes.begin(), none.mesh.tet_attributes.end(),
                            [](double a) { return a == 0; }));
}

}  // namespace
}  // namespace exactmesh::generators
