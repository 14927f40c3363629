// SPDX-License-Identifier: MIT
// HRefinedMesh3 (h-refinement of tetrahedra with history): a cube of six tetrahedra, Delaunay
// tetrahedralizations of random points and of a cubic grid (cospherical, coplanar), refined by
// random edge marks for three cycles: the leaf mesh valid, nested, within the jump limit, the
// old vertices kept; derefining everything gives the root arrays back exactly; a linear field is
// carried exactly at old vertices; the same tetrahedra at x2^-600 and x2^600; the 2:4, 2:8, 4:8
// cases and the jump marks happen; bad marks and flags are InputErrors.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <random>
#include <set>
#include <vector>

#include "base/errors.hpp"
#include "generators/adaptation/h_refinement_3d.hpp"
#include "predicates/angle_comparisons_3d.hpp"
#include "predicates/orient3d.hpp"
#include "tests/support/point_sets_3d.hpp"
#include "tests/support/test_scale.hpp"
#include "triangulation/delaunay/delaunay_3d.hpp"

namespace gen = exactmesh::generators;
namespace tri = exactmesh::triangulation;
namespace pred = exactmesh::predicates;
using Edge = std::array<tri::VertIdx, 2>;

namespace {

/// Neighbors by opposite face, brute force (test sizes).
void fill_neighbors(tri::Tetrahedralization3& mesh) {
    mesh.neighbors.assign(mesh.tets.size(), tri::kNone);
    auto face = [&](std::uint32_t t, int f) {
        std::array<tri::VertIdx, 3> v{};
        for (int j = 0, k = 0; j < 4; ++j) {
            if (j != f) v[k++] = mesh.tets[4 * t + j];
        }
        std::sort(v.begin(), v.end());
        return v;
    };
    for (std::uint32_t t = 0; t < mesh.tet_count(); ++t) {
        for (int f = 0; f < 4; ++f) {
            for (std::uint32_t u = 0; u < mesh.tet_count(); ++u) {
                for (int g = 0; g < 4 && u != t; ++g) {
                    if (face(t, f) == face(u, g)) mesh.neighbors[4 * t + f] = u;
                }
            }
        }
    }
}

/// The unit cube cut into six tetrahedra around its diagonal (0,0,0)-(s,s,s), positively
/// oriented.
tri::Tetrahedralization3 cube_of_six(double s = 1.0) {
    tri::Tetrahedralization3 mesh;
    for (int i = 0; i < 8; ++i) {
        mesh.xyz.insert(mesh.xyz.end(), {s * (i & 1), s * (i >> 1 & 1), s * (i >> 2 & 1)});
    }
    const int paths[6][2] = {{1, 3}, {1, 5}, {2, 3}, {2, 6}, {4, 5}, {4, 6}};
    for (const auto& p : paths) {
        std::array<tri::VertIdx, 4> t{0, tri::VertIdx(p[0]), tri::VertIdx(p[1]), 7};
        if (pred::orient3d(mesh.point(t[0]), mesh.point(t[1]), mesh.point(t[2]),
                           mesh.point(t[3])) != pred::Sign::Positive)
            std::swap(t[2], t[3]);
        mesh.tets.insert(mesh.tets.end(), t.begin(), t.end());
    }
    fill_neighbors(mesh);
    return mesh;
}

tri::Tetrahedralization3 delaunay(const std::vector<double>& xyz) {
    return tri::delaunay_3d_algorithm("bowyer-watson")(xyz, {}).mesh;
}

std::vector<Edge> leaf_edges(const tri::Tetrahedralization3& mesh) {
    std::set<Edge> edges;
    for (std::uint32_t t = 0; t < mesh.tet_count(); ++t) {
        for (int i = 0; i < 4; ++i) {
            for (int j = i + 1; j < 4; ++j) {
                const tri::VertIdx a = mesh.tets[4 * t + i], b = mesh.tets[4 * t + j];
                edges.insert({std::min(a, b), std::max(a, b)});
            }
        }
    }
    return {edges.begin(), edges.end()};
}

std::vector<Edge> random_marks(const tri::Tetrahedralization3& mesh, std::mt19937_64& rng,
                               double p) {
    std::vector<Edge> marks;
    std::bernoulli_distribution pick(p);
    for (const Edge& e : leaf_edges(mesh)) {
        if (pick(rng)) marks.push_back(e);
    }
    return marks;
}

void expect_valid(const gen::HRefinedMesh3& h) {
    const gen::HRefinement3Report report = h.check_all();
    EXPECT_TRUE(report.ok) << report.problem;
}

/// Derefines with every leaf flagged until nothing changes.
void derefine_all(gen::HRefinedMesh3& h) {
    for (int guard = 0; guard < 64; ++guard) {
        const std::uint32_t before = h.leaf_count();
        h.derefine(std::vector<std::uint8_t>(before, 1));
        expect_valid(h);
        if (h.leaf_count() == before) return;
    }
}

std::vector<tri::Tetrahedralization3> roots() {
    std::vector<tri::Tetrahedralization3> list;
    list.push_back(cube_of_six());
    list.push_back(delaunay(exactmesh::testing::random_points_3d(60, 7)));
    list.push_back(delaunay(exactmesh::testing::cubic_grid_3d(4)));
    return list;
}

}  // namespace

TEST(Generators_HRefinement3d, RefineAllOfCubeIsEightPerTet) {
    gen::HRefinedMesh3 h(cube_of_six());
    h.refine(leaf_edges(h.leaf_mesh()));
    expect_valid(h);
    EXPECT_EQ(h.leaf_count(), 48u);
    EXPECT_EQ(h.vertex_count(), 8u + 19u);  // 19 edges of the cube's six tetrahedra
    EXPECT_EQ(h.counters().refine_1_8, 6u);
    for (std::uint32_t level : h.leaf_levels()) EXPECT_EQ(level, 1u);
}

TEST(Generators_HRefinement3d, RandomMarksThreeCyclesValidNestedAndIdentityAfterDerefine) {
    std::mt19937_64 rng(2026);
    for (const tri::Tetrahedralization3& root : roots()) {
        ASSERT_GT(root.tet_count(), 0u);
        gen::HRefinedMesh3 h(root);
        for (int cycle = 0; cycle < 3; ++cycle) {
            const tri::Tetrahedralization3 before = h.leaf_mesh();
            h.refine(random_marks(before, rng, 0.08));
            expect_valid(h);
            const tri::Tetrahedralization3 after = h.leaf_mesh();
            // Old vertices are kept, in place, bit for bit.
            ASSERT_GE(after.xyz.size(), before.xyz.size());
            EXPECT_TRUE(std::equal(before.xyz.begin(), before.xyz.end(), after.xyz.begin()));
        }
        EXPECT_GT(h.leaf_count(), root.tet_count());
        derefine_all(h);
        const tri::Tetrahedralization3 back = h.leaf_mesh();
        EXPECT_EQ(back.xyz, root.xyz);
        EXPECT_EQ(back.tets, root.tets);
        EXPECT_EQ(back.neighbors, root.neighbors);
        EXPECT_GT(h.counters().derefined, 0u);
    }
}

TEST(Generators_HRefinement3d, UniformLevelsThenDerefineAllIsIdentity) {
    for (const tri::Tetrahedralization3& root : roots()) {
        gen::HRefinedMesh3 h(root);
        for (int level = 0; level < 2; ++level) h.refine(leaf_edges(h.leaf_mesh()));
        expect_valid(h);
        EXPECT_EQ(h.leaf_count(), 64 * root.tet_count());
        derefine_all(h);
        const tri::Tetrahedralization3 back = h.leaf_mesh();
        EXPECT_EQ(back.xyz, root.xyz);
        EXPECT_EQ(back.tets, root.tets);
        EXPECT_EQ(back.neighbors, root.neighbors);
    }
}

TEST(Generators_HRefinement3d, LinearFieldExactAtOldVertices) {
    std::mt19937_64 rng(11);
    gen::HRefinedMesh3 h(delaunay(exactmesh::testing::random_points_3d(40, 3)));
    auto linear = [](const double* p) { return 0.25 * p[0] - 2.0 * p[1] + p[2] + 1.0; };
    std::vector<double> field;
    {
        const tri::Tetrahedralization3 mesh = h.leaf_mesh();
        for (tri::VertIdx v = 0; v < mesh.vertex_count(); ++v)
            field.push_back(linear(mesh.point(v)));
    }
    for (int cycle = 0; cycle < 3; ++cycle) {
        const std::vector<double> old_field = field;
        h.refine(random_marks(h.leaf_mesh(), rng, 0.1));
        field = h.transfer(old_field);
        const tri::Tetrahedralization3 mesh = h.leaf_mesh();
        ASSERT_EQ(field.size(), mesh.vertex_count());
        for (std::size_t v = 0; v < old_field.size(); ++v) EXPECT_EQ(field[v], old_field[v]);
        // New vertices: the average of the ends, which is the linear field at the exact
        // midpoint; the rounded midpoint moves it by a few ulps only.
        for (std::size_t v = old_field.size(); v < field.size(); ++v) {
            EXPECT_NEAR(field[v], linear(mesh.point(tri::VertIdx(v))), 1e-12);
        }
    }
    // Derefinement is injection.
    const std::vector<double> fine = field;
    const std::uint32_t fine_count = h.vertex_count();
    h.derefine(std::vector<std::uint8_t>(h.leaf_count(), 1));
    ASSERT_LT(h.vertex_count(), fine_count);
    field = h.transfer(fine);
    const tri::Tetrahedralization3 mesh = h.leaf_mesh();
    for (tri::VertIdx v = 0; v < h.root_vertex_count(); ++v) EXPECT_EQ(field[v], fine[v]);
    for (tri::VertIdx v = h.root_vertex_count(); v < mesh.vertex_count(); ++v) {
        EXPECT_NEAR(field[v], linear(mesh.point(v)), 1e-12);
    }
}

TEST(Generators_HRefinement3d, ScaleInvariantTetrahedra) {
    const std::vector<double> points = exactmesh::testing::random_points_3d(50, 5);
    const tri::Tetrahedralization3 base = delaunay(points);
    for (int k : {-600, 600}) {
        tri::Tetrahedralization3 scaled = base;
        for (double& x : scaled.xyz) x = std::ldexp(x, k);
        gen::HRefinedMesh3 a(base), b(scaled);
        std::mt19937_64 rng_a(9), rng_b(9);
        for (int cycle = 0; cycle < 3; ++cycle) {
            a.refine(random_marks(a.leaf_mesh(), rng_a, 0.1));
            b.refine(random_marks(b.leaf_mesh(), rng_b, 0.1));
        }
        expect_valid(b);
        const tri::Tetrahedralization3 ma = a.leaf_mesh(), mb = b.leaf_mesh();
        EXPECT_EQ(ma.tets, mb.tets);
        EXPECT_EQ(ma.neighbors, mb.neighbors);
        ASSERT_EQ(ma.xyz.size(), mb.xyz.size());
        for (std::size_t i = 0; i < ma.xyz.size(); ++i)
            EXPECT_EQ(std::ldexp(ma.xyz[i], k), mb.xyz[i]);
        EXPECT_EQ(a.leaf_levels(), b.leaf_levels());
    }
}

TEST(Generators_HRefinement3d, TransitionalParentsAreRefinedAgain) {
    // One edge of the cube's diagonal fan: every tetrahedron around it splits 1:2.
    gen::HRefinedMesh3 h(cube_of_six());
    const std::vector<Edge> one{{0, 7}};
    h.refine(one);
    expect_valid(h);
    EXPECT_EQ(h.counters().refine_1_2, 6u);
    EXPECT_EQ(h.leaf_count(), 12u);
    // Marking a half of the split edge: the 1:2 parents go 1:8 first (2:8), then deeper.
    const tri::VertIdx mid = h.vertex_count() - 1;
    ASSERT_EQ(h.midpoint_ends(mid), (Edge{0, 7}));
    const std::vector<Edge> half{{0, mid}};
    h.refine(half);
    expect_valid(h);
    EXPECT_GE(h.counters().refine_2_8, 6u);
    EXPECT_EQ(h.counters().refine_2_4, 0u);
    const std::vector<std::uint32_t> levels = h.leaf_levels();
    EXPECT_EQ(*std::max_element(levels.begin(), levels.end()), 2u);

    // A 1:2 parent whose marks stay in one face becomes 1:4 (2:4).
    gen::HRefinedMesh3 g(cube_of_six());
    const std::vector<Edge> face_edge{{0, 1}};
    g.refine(face_edge);
    expect_valid(g);
    const tri::Tetrahedralization3 mesh = g.leaf_mesh();
    // Vertex 1 = (1,0,0), 3 = (1,1,0): edge (1, 3) lies in a face with (0, 1) in the
    // tetrahedron (0, 1, 3, 7).
    const std::vector<Edge> second{{1, 3}};
    g.refine(second);
    expect_valid(g);
    EXPECT_GE(g.counters().refine_2_4 + g.counters().refine_2_8, 1u);
    // A 1:4 parent refined again goes 1:8 (4:8).
    const std::vector<Edge> all = leaf_edges(g.leaf_mesh());
    g.refine(all);
    expect_valid(g);
    EXPECT_GE(g.counters().refine_4_8 + g.counters().refine_2_8, 1u);
}

TEST(Generators_HRefinement3d, JumpLimitGradesTheMesh) {
    gen::HRefinedMesh3 h(delaunay(exactmesh::testing::cubic_grid_3d(4)));
    // Refine around vertex 0 again and again: compatibility and the jump limit grade the mesh.
    for (int cycle = 0; cycle < 4; ++cycle) {
        std::vector<Edge> marks;
        for (const Edge& e : leaf_edges(h.leaf_mesh())) {
            if (e[0] == 0 || e[1] == 0) marks.push_back(e);
        }
        h.refine(marks);
        expect_valid(h);
    }
    const std::vector<std::uint32_t> levels = h.leaf_levels();
    EXPECT_GE(*std::max_element(levels.begin(), levels.end()), 4u);
    EXPECT_TRUE(h.check_jump_limit().ok);
}

TEST(Generators_HRefinement3d, PartialDerefinementKeepsRulesAndCounters) {
    std::mt19937_64 rng(4);
    gen::HRefinedMesh3 h(delaunay(exactmesh::testing::random_points_3d(50, 12)));
    for (int cycle = 0; cycle < 3; ++cycle) h.refine(random_marks(h.leaf_mesh(), rng, 0.1));
    std::bernoulli_distribution pick(0.7);
    for (int cycle = 0; cycle < 3; ++cycle) {
        std::vector<std::uint8_t> flags(h.leaf_count());
        for (auto& f : flags) f = pick(rng);
        h.derefine(flags);
        expect_valid(h);
    }
    const auto by_name = exactmesh::counters_by_name(gen::kHRefinement3CounterNames, h.counters());
    EXPECT_EQ(by_name.size(), 13u);
    EXPECT_GT(h.counters().compatibility_iterations, 0u);
}

TEST(Generators_HRefinement3d, SeededCampaignSparseMarks) {
    // Sparse marks make 1:2 and 1:4 splits, then 2:4, 2:8 and 4:8 reopenings as cycles go on;
    // every state valid, nested and within the jump limit; partial derefinement too; and all
    // the way back to the roots at the end.
    const int seeds = std::max(1, static_cast<int>(12 * exactmesh::testing::test_scale()));
    gen::HRefinement3Counters total;
    for (int seed = 0; seed < seeds; ++seed) {
        std::mt19937_64 rng(static_cast<std::uint64_t>(seed));
        const tri::Tetrahedralization3 root =
            seed % 3 == 2 ? delaunay(exactmesh::testing::cubic_grid_3d(3))
                          : delaunay(exactmesh::testing::random_points_3d(30, std::uint64_t(seed)));
        gen::HRefinedMesh3 h(root);
        for (int cycle = 0; cycle < 5; ++cycle) {
            h.refine(random_marks(h.leaf_mesh(), rng, 0.03));
            expect_valid(h);
            if (cycle == 3) {
                std::bernoulli_distribution pick(0.5);
                std::vector<std::uint8_t> flags(h.leaf_count());
                for (auto& f : flags) f = pick(rng);
                h.derefine(flags);
                expect_valid(h);
            }
        }
        derefine_all(h);
        EXPECT_EQ(h.leaf_mesh().tets, root.tets);
        EXPECT_EQ(h.leaf_mesh().xyz, root.xyz);
        total.refine_2_4 += h.counters().refine_2_4;
        total.refine_2_8 += h.counters().refine_2_8;
        total.refine_4_8 += h.counters().refine_4_8;
        total.derefine_blocked += h.counters().derefine_blocked;
    }
    EXPECT_GT(total.refine_2_4, 0u);
    EXPECT_GT(total.refine_2_8, 0u);
    EXPECT_GT(total.refine_4_8, 0u);
    EXPECT_GT(total.derefine_blocked, 0u);
}

TEST(Generators_HRefinement3d, RoundedMidpointThatWouldInvertIsRefused) {
    // Slivers: d is the rounded point a + s (b - a) + t (c - a), so the tetrahedron's height is a
    // rounding error, and an edge's rounded midpoint can land on the wrong side of the opposite
    // face. Those splits are refused (the mesh stays valid); the others go through.
    std::mt19937_64 rng(77);
    std::uniform_real_distribution<double> unit(1.0, 2.0);
    int refused = 0, split = 0;
    for (int attempt = 0; attempt < 4000 && (refused < 3 || split < 3); ++attempt) {
        tri::Tetrahedralization3 mesh;
        std::array<std::array<double, 3>, 3> abc{};
        for (auto& p : abc) {
            for (double& x : p) x = unit(rng);
        }
        const double s = unit(rng) - 1.0, t = unit(rng) - 1.0;
        std::array<double, 3> d{};
        for (int k = 0; k < 3; ++k)
            d[k] = abc[0][k] + s * (abc[1][k] - abc[0][k]) + t * (abc[2][k] - abc[0][k]);
        for (const auto& p : abc) mesh.xyz.insert(mesh.xyz.end(), p.begin(), p.end());
        mesh.xyz.insert(mesh.xyz.end(), d.begin(), d.end());
        const pred::Sign sign =
            pred::orient3d(mesh.point(0), mesh.point(1), mesh.point(2), mesh.point(3));
        if (sign == pred::Sign::Zero) continue;
        mesh.tets = sign == pred::Sign::Positive ? std::vector<tri::VertIdx>{0, 1, 2, 3}
                                                 : std::vector<tri::VertIdx>{0, 1, 3, 2};
        mesh.neighbors.assign(4, tri::kNone);
        gen::HRefinedMesh3 h(mesh);
        h.refine(leaf_edges(mesh));  // all six: 1:8, or refused
        expect_valid(h);
        if (h.counters().refused_splits > 0) {
            ++refused;
            EXPECT_EQ(h.leaf_mesh().tets, mesh.tets);  // nothing could be split
            EXPECT_EQ(h.vertex_count(), 4u);
        } else {
            ++split;
            EXPECT_EQ(h.leaf_count(), 8u);
        }
    }
    EXPECT_GE(refused, 3);
    EXPECT_GE(split, 3);
}

namespace {

/// The leaves as sorted lists of corner coordinates (independent of numbering and order).
std::multiset<std::array<std::array<double, 3>, 4>> leaf_shapes(
    const tri::Tetrahedralization3& mesh) {
    std::multiset<std::array<std::array<double, 3>, 4>> shapes;
    for (std::uint32_t t = 0; t < mesh.tet_count(); ++t) {
        std::array<std::array<double, 3>, 4> corners{};
        for (int k = 0; k < 4; ++k) {
            const double* p = mesh.point(mesh.tets[4 * t + k]);
            corners[k] = {p[0], p[1], p[2]};
        }
        std::sort(corners.begin(), corners.end());
        shapes.insert(corners);
    }
    return shapes;
}

}  // namespace

TEST(Generators_HRefinement3d, SameLeavesWhateverTheCornerOrder) {
    // Rotating each root tetrahedron's corners (an even permutation: still positive) changes
    // no choice: patterns, diagonals and upgrades depend on global ids and geometry only.
    const tri::Tetrahedralization3 root = delaunay(exactmesh::testing::random_points_3d(40, 31));
    tri::Tetrahedralization3 rotated = root;
    for (std::uint32_t t = 0; t < rotated.tet_count(); ++t) {
        const int turns = static_cast<int>(t % 3);
        for (int r = 0; r < turns; ++r) {
            std::rotate(rotated.tets.begin() + 4 * t, rotated.tets.begin() + 4 * t + 1,
                        rotated.tets.begin() + 4 * t + 3);
        }
    }
    gen::HRefinedMesh3 a(root), b(rotated);
    std::mt19937_64 rng(5);
    for (int cycle = 0; cycle < 3; ++cycle) {
        const tri::Tetrahedralization3 ma = a.leaf_mesh(), mb = b.leaf_mesh();
        const std::vector<Edge> marks = random_marks(ma, rng, 0.1);
        // The same edges in b's numbering (midpoints may be numbered in another order).
        std::map<std::array<double, 3>, tri::VertIdx> id_in_b;
        for (tri::VertIdx v = 0; v < mb.vertex_count(); ++v) {
            id_in_b[{mb.point(v)[0], mb.point(v)[1], mb.point(v)[2]}] = v;
        }
        std::vector<Edge> marks_b;
        for (const Edge& e : marks) {
            const double *p = ma.point(e[0]), *q = ma.point(e[1]);
            marks_b.push_back({id_in_b.at({p[0], p[1], p[2]}), id_in_b.at({q[0], q[1], q[2]})});
        }
        a.refine(marks);
        b.refine(marks_b);
        expect_valid(b);
        ASSERT_EQ(leaf_shapes(a.leaf_mesh()), leaf_shapes(b.leaf_mesh()));
    }
}

TEST(Generators_HRefinement3d, UniformRefinementKeepsQuality) {
    // Three uniform levels of one tetrahedron: the diagonal rule keeps the worst volume-edge
    // quality from collapsing (with the best diagonal it stays within the first level's).
    tri::Tetrahedralization3 mesh;
    mesh.xyz = {0, 0, 0, 1, 0, 0, 0.3, 0.9, 0, 0.4, 0.3, -0.8};
    mesh.tets = {0, 1, 2, 3};
    ASSERT_EQ(pred::orient3d(mesh.point(0), mesh.point(1), mesh.point(2), mesh.point(3)),
              pred::Sign::Positive);
    mesh.neighbors.assign(4, tri::kNone);
    gen::HRefinedMesh3 h(mesh);
    std::vector<long double> worst;
    for (int level = 0; level < 3; ++level) {
        h.refine(leaf_edges(h.leaf_mesh()));
        expect_valid(h);
        const tri::Tetrahedralization3 leaves = h.leaf_mesh();
        long double q = 1;
        for (std::uint32_t t = 0; t < leaves.tet_count(); ++t) {
            q = std::min(q, pred::volume_edge_quality({leaves.point(leaves.tets[4 * t]),
                                                       leaves.point(leaves.tets[4 * t + 1]),
                                                       leaves.point(leaves.tets[4 * t + 2]),
                                                       leaves.point(leaves.tets[4 * t + 3])}));
        }
        worst.push_back(q);
    }
    EXPECT_EQ(h.leaf_count(), 512u);
    EXPECT_GE(worst[2], 0.999L * worst[0]);
}

TEST(Generators_HRefinement3d, BadMarksAndFlagsAreInputErrors) {
    gen::HRefinedMesh3 h(cube_of_six());
    const std::vector<Edge> not_edge{{1, 6}};  // a face diagonal not in any tetrahedron
    EXPECT_THROW(h.refine(not_edge), exactmesh::InputError);
    const std::vector<Edge> loop{{2, 2}};
    EXPECT_THROW(h.refine(loop), exactmesh::InputError);
    EXPECT_THROW(h.derefine(std::vector<std::uint8_t>(3, 1)), exactmesh::InputError);
    EXPECT_THROW(h.transfer(std::vector<double>(2, 0.0)), exactmesh::InputError);
    tri::Tetrahedralization3 broken = cube_of_six();
    broken.tets[5] = 99;
    EXPECT_THROW(gen::HRefinedMesh3{broken}, exactmesh::InputError);
    tri::Tetrahedralization3 inverted = cube_of_six();
    std::swap(inverted.tets[2], inverted.tets[3]);
    EXPECT_THROW(gen::HRefinedMesh3{inverted}, exactmesh::InputError);
    tri::Tetrahedralization3 not_finite = cube_of_six();
    not_finite.xyz[4] = std::nan("");
    EXPECT_THROW(gen::HRefinedMesh3{not_finite}, exactmesh::InputError);
    // Nothing changed by the refused calls.
    EXPECT_EQ(h.leaf_mesh().tets, cube_of_six().tets);
}
