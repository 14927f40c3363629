// SPDX-License-Identifier: MIT
// Red-green h-refinement with history: after every refine and derefine the history passes the
// exact check (leaf mesh counter-clockwise and conforming, nesting, inherited constraints), no
// marked edge is left, root vertices keep index and coordinates, neighbours differ by at most one
// level; refining then derefining everything returns the root array for array; a linear field is
// transferred exactly on dyadic grids; scaling by 2^-600 and 2^600 gives the same triangles;
// sliver splits are refused, never inverted; bad input is an InputError.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <unordered_set>
#include <vector>

#include "base/errors.hpp"
#include "generators/adaptation/h_refinement_2d.hpp"
#include "generators/boundary/sample_domains.hpp"
#include "generators/inputs/inputs.hpp"
#include "generators/mesh_2d/delaunay_refinement_2d.hpp"
#include "predicates/orient2d.hpp"
#include "triangulation/checks/check_conforming_2d.hpp"
#include "triangulation/constrained/constrained_2d.hpp"

namespace em = exactmesh;
namespace gen = exactmesh::generators;
namespace tri = exactmesh::triangulation;

namespace {

/// The convex-hull Delaunay triangulation of `xy` (with `segments` and exterior removed when
/// segments are given): a Triangulation2 as exactmesh's generators produce it.
tri::Triangulation2 mesh_of(const std::vector<double>& xy,
                            const std::vector<tri::VertIdx>& segments = {}) {
    tri::Cdt2Options options;
    options.remove_exterior = !segments.empty();
    return tri::constrained_delaunay_2d({xy, segments, {}, {}}, options).mesh;
}

/// (n+1)^2 grid points i/8, j/8 (dyadic, so every midpoint down to many levels is exact).
std::vector<double> grid_points(int n) {
    std::vector<double> xy;
    for (int j = 0; j <= n; ++j) {
        for (int i = 0; i <= n; ++i) {
            xy.push_back(i / 8.0);
            xy.push_back(j / 8.0);
        }
    }
    return xy;
}

std::uint64_t key(tri::VertIdx a, tri::VertIdx b) {
    return a < b ? (std::uint64_t{a} << 32) | b : (std::uint64_t{b} << 32) | a;
}

/// Each edge of the leaf mesh once, marked with probability p.
std::vector<tri::VertIdx> random_marks(const tri::Triangulation2& m, double p,
                                       std::mt19937_64& rng) {
    std::bernoulli_distribution pick(p);
    std::vector<tri::VertIdx> marks;
    for (tri::TriIdx t = 0; t < m.triangle_count(); ++t) {
        for (unsigned k = 0; k < 3; ++k) {
            const tri::VertIdx a = m.triangles[3 * t + k], b = m.triangles[3 * t + (k + 1) % 3];
            if ((m.neighbors[3 * t + k] == tri::kNone || a < b) && pick(rng)) {
                marks.push_back(a);
                marks.push_back(b);
            }
        }
    }
    return marks;
}

std::vector<tri::VertIdx> all_edges(const tri::Triangulation2& m) {
    std::mt19937_64 rng(0);
    return random_marks(m, 1.0, rng);
}

std::vector<tri::TriIdx> all_leaves(const gen::HRefinedMesh2& h) {
    std::vector<tri::TriIdx> t(h.leaf_mesh().triangle_count());
    for (tri::TriIdx i = 0; i < t.size(); ++i) t[i] = i;
    return t;
}

/// An independent exact test of the leaf mesh's geometry: check_conforming_mesh_2d (no fold at
/// any vertex, by exact angular order; every root vertex kept) with the root's boundary and
/// constrained edges as the segments, each a chain of leaf edges through vertices within
/// rounding of it, and the leaf mesh's boundary edges flagged as their pieces.
tri::CheckReport check_no_fold(const gen::HRefinedMesh2& h, const tri::Triangulation2& root) {
    tri::Triangulation2 m = h.leaf_mesh();
    m.constrained.resize(m.triangles.size(), 0);
    for (std::size_t e = 0; e < m.neighbors.size(); ++e) {
        if (m.neighbors[e] == tri::kNone) m.constrained[e] = 1;
    }
    std::vector<tri::VertIdx> segments;
    for (tri::TriIdx t = 0; t < root.triangle_count(); ++t) {
        for (unsigned k = 0; k < 3; ++k) {
            const tri::VertIdx a = root.triangles[3 * t + k],
                               b = root.triangles[3 * t + (k + 1) % 3];
            if (root.neighbors[3 * t + k] == tri::kNone ||
                (root.is_constrained(t, static_cast<int>(k)) && a < b))
                segments.insert(segments.end(), {a, b});
        }
    }
    return tri::check_conforming_mesh_2d(m, root.vertex_count(), segments);
}

/// The exact check, root vertices unmoved, no unrefused mark left, levels across edges within 1.
void expect_valid_after_refine(const gen::HRefinedMesh2& h, const tri::Triangulation2& root,
                               const std::vector<tri::VertIdx>& marks,
                               const gen::HRefinementCounters2& c, const std::string& what) {
    const auto report = gen::check_h_refined_mesh_2d(h);
    ASSERT_TRUE(report.ok) << what << ": " << report.problem;
    const auto fold = check_no_fold(h, root);
    ASSERT_TRUE(fold.ok) << what << ": " << fold.problem;
    const tri::Triangulation2& m = h.leaf_mesh();
    ASSERT_GE(m.xy.size(), root.xy.size());
    EXPECT_TRUE(std::equal(root.xy.begin(), root.xy.end(), m.xy.begin())) << what;
    if (c.refused_edges == 0) {
        std::unordered_set<std::uint64_t> edges;
        for (tri::TriIdx t = 0; t < m.triangle_count(); ++t) {
            for (unsigned k = 0; k < 3; ++k)
                edges.insert(key(m.triangles[3 * t + k], m.triangles[3 * t + (k + 1) % 3]));
        }
        for (std::size_t i = 0; i + 1 < marks.size(); i += 2)
            EXPECT_FALSE(edges.count(key(marks[i], marks[i + 1])))
                << what << ": marked edge " << marks[i] << " - " << marks[i + 1] << " left";
    }
    for (tri::TriIdx t = 0; t < m.triangle_count(); ++t) {
        for (unsigned k = 0; k < 3; ++k) {
            const tri::TriIdx u = m.neighbors[3 * t + k];
            if (u == tri::kNone) continue;
            const auto lt = h.level(t), lu = h.level(u);
            EXPECT_LE(std::max(lt, lu) - std::min(lt, lu), 1u)
                << what << ": triangles " << t << " and " << u;
        }
    }
}

void expect_same(const tri::Triangulation2& a, const tri::Triangulation2& b,
                 const std::string& what) {
    EXPECT_EQ(a.xy, b.xy) << what;
    EXPECT_EQ(a.triangles, b.triangles) << what;
    EXPECT_EQ(a.neighbors, b.neighbors) << what;
    EXPECT_EQ(a.constrained, b.constrained) << what;
}

/// derefine(every leaf) until nothing changes; at most `limit` calls.
void derefine_all(gen::HRefinedMesh2& h, int limit, const std::string& what) {
    for (int i = 0; i < limit; ++i) {
        const auto before = h.leaf_mesh().triangle_count();
        h.derefine(all_leaves(h));
        const auto report = gen::check_h_refined_mesh_2d(h);
        ASSERT_TRUE(report.ok) << what << " derefine " << i << ": " << report.problem;
        if (h.leaf_mesh().triangle_count() == before) return;
    }
}

tri::Triangulation2 square_with_boundary(int n) {
    std::vector<double> xy = grid_points(n);
    std::vector<tri::VertIdx> segments;
    const auto at = [n](int i, int j) { return static_cast<tri::VertIdx>(j * (n + 1) + i); };
    // The square's four sides, plus one interior segment (a diagonal of the grid).
    segments.insert(segments.end(), {at(0, 0), at(n, 0), at(n, 0), at(n, n), at(n, n), at(0, n),
                                     at(0, n), at(0, 0), at(1, 1), at(n - 1, n - 1)});
    return mesh_of(xy, segments);
}

// The last edge of triangle 0 (in its corner order) that has a neighbour across it.
std::array<tri::VertIdx, 2> interior_edge_of_first_triangle(const tri::Triangulation2& root) {
    tri::VertIdx a = 0, b = 0;
    for (unsigned k = 0; k < 3; ++k) {
        if (root.neighbors[k] != tri::kNone) {
            a = root.triangles[k];
            b = root.triangles[(k + 1) % 3];
        }
    }
    return {a, b};
}

}  // namespace

TEST(Generators_HRefinement2, RandomMarksOverSeveralLevelsStayValidAndDerefineToTheRoot) {
    for (const gen::Distribution d : {gen::Distribution::Uniform, gen::Distribution::Gaussian,
                                      gen::Distribution::Grid, gen::Distribution::Cocircular}) {
        for (std::uint64_t seed = 1; seed <= 3; ++seed) {
            const tri::Triangulation2 root = mesh_of(gen::generate_points_2d(d, 80, seed));
            const std::string what =
                std::string(gen::distribution_name(d)) + " seed " + std::to_string(seed);
            gen::HRefinedMesh2 h(root);
            expect_same(h.leaf_mesh(), root, what + " (root)");
            std::mt19937_64 rng(seed);
            std::uint64_t greens = 0, undone = 0;
            for (int level = 0; level < 4; ++level) {
                const auto marks = random_marks(h.leaf_mesh(), 0.15, rng);
                const auto c = h.refine(marks);
                EXPECT_EQ(c.refused_edges, 0u) << what;
                greens += c.green;
                undone += c.green_undone;
                expect_valid_after_refine(h, root, marks, c,
                                          what + " level " + std::to_string(level));
            }
            EXPECT_GT(greens, 0u) << what;
            EXPECT_GT(h.leaf_mesh().triangle_count(), root.triangle_count());
            (void)undone;
            derefine_all(h, 40, what);
            expect_same(h.leaf_mesh(), root, what + " (after derefinement)");
        }
    }
}

TEST(Generators_HRefinement2, InterleavedRefineAndPartialDerefineStayValid) {
    for (const gen::Distribution d :
         {gen::Distribution::Uniform, gen::Distribution::Grid, gen::Distribution::NearCollinear}) {
        for (std::uint64_t seed = 1; seed <= 2; ++seed) {
            const tri::Triangulation2 root = mesh_of(gen::generate_points_2d(d, 40, seed));
            const std::string what =
                std::string(gen::distribution_name(d)) + " seed " + std::to_string(seed);
            gen::HRefinedMesh2 h(root);
            std::mt19937_64 rng(seed);
            std::uint64_t derefined = 0;
            for (int step = 0; step < 15; ++step) {
                if (step % 3 != 2) {
                    const auto marks = random_marks(h.leaf_mesh(), 0.08, rng);
                    const auto c = h.refine(marks);
                    expect_valid_after_refine(h, root, marks, c,
                                              what + " step " + std::to_string(step));
                    continue;
                }
                std::bernoulli_distribution pick(0.8);
                std::vector<tri::TriIdx> flagged;
                for (tri::TriIdx t = 0; t < h.leaf_mesh().triangle_count(); ++t) {
                    if (pick(rng)) flagged.push_back(t);
                }
                const auto before = h.counters().derefined;
                h.derefine(flagged);
                derefined += h.counters().derefined - before;
                const auto report = gen::check_h_refined_mesh_2d(h);
                ASSERT_TRUE(report.ok) << what << " step " << step << ": " << report.problem;
                const auto fold = check_no_fold(h, root);
                ASSERT_TRUE(fold.ok) << what << " step " << step << ": " << fold.problem;
                EXPECT_TRUE(std::equal(root.xy.begin(), root.xy.end(), h.leaf_mesh().xy.begin()));
            }
            EXPECT_GT(derefined, 0u) << what;
            derefine_all(h, 60, what);
            expect_same(h.leaf_mesh(), root, what + " (after derefinement)");
        }
    }
}

TEST(Generators_HRefinement2, GreenPairsAreUndoneWhenAChildNeedsRefinement) {
    std::uint64_t undone = 0;
    for (std::uint64_t seed = 1; seed <= 4; ++seed) {
        const tri::Triangulation2 root =
            mesh_of(gen::generate_points_2d(gen::Distribution::Uniform, 40, seed));
        gen::HRefinedMesh2 h(root);
        std::mt19937_64 rng(seed);
        for (int level = 0; level < 5; ++level) {
            const auto marks = random_marks(h.leaf_mesh(), 0.1, rng);
            const auto c = h.refine(marks);
            undone += c.green_undone;
            expect_valid_after_refine(h, root, marks, c, "seed " + std::to_string(seed));
        }
    }
    EXPECT_GT(undone, 0u);
}

TEST(Generators_HRefinement2, OneSharedEdgeGivesTwoGreensThenARedUndoesOne) {
    // Two triangles sharing the diagonal of the unit square.
    const std::vector<double> xy{0, 0, 1, 0, 1, 1, 0, 1};
    const tri::Triangulation2 root = mesh_of(xy);
    ASSERT_EQ(root.triangle_count(), 2u);
    gen::HRefinedMesh2 h(root);
    // The interior edge.
    const auto [a, b] = interior_edge_of_first_triangle(root);
    const std::vector<tri::VertIdx> diagonal{a, b};
    auto c = h.refine(diagonal);
    EXPECT_EQ(c.green, 2u);
    EXPECT_EQ(c.red, 0u);
    expect_valid_after_refine(h, root, diagonal, c, "diagonal");
    ASSERT_EQ(h.leaf_mesh().vertex_count(), 5u);
    EXPECT_EQ(h.leaf_mesh().xy[8], 0.5);
    EXPECT_EQ(h.leaf_mesh().xy[9], 0.5);
    // Half of the diagonal: both green pairs are undone, both parents go red at once, and their
    // red children split the half in the same pass.
    const std::vector<tri::VertIdx> half{a, 4};
    c = h.refine(half);
    EXPECT_EQ(c.green_undone, 2u);
    EXPECT_GE(c.red, 2u);
    EXPECT_EQ(c.rounds, 1u);
    expect_valid_after_refine(h, root, half, c, "half diagonal");
    derefine_all(h, 10, "square");
    expect_same(h.leaf_mesh(), root, "square");
}

TEST(Generators_HRefinement2, CoarseningARedTriangleTakesItsGreenNeighboursAlong) {
    const tri::Triangulation2 root =
        mesh_of(gen::generate_points_2d(gen::Distribution::Uniform, 30, 4));
    gen::HRefinedMesh2 h(root);
    // An interior triangle (three neighbours), all its edges marked: red, three greens.
    tri::TriIdx inner = tri::kNone;
    for (tri::TriIdx t = 0; t < root.triangle_count() && inner == tri::kNone; ++t) {
        if (root.neighbors[3 * t] != tri::kNone && root.neighbors[3 * t + 1] != tri::kNone &&
            root.neighbors[3 * t + 2] != tri::kNone)
            inner = t;
    }
    ASSERT_NE(inner, tri::kNone);
    const std::vector<tri::VertIdx> marks{
        root.triangles[3 * inner],     root.triangles[3 * inner + 1], root.triangles[3 * inner + 1],
        root.triangles[3 * inner + 2], root.triangles[3 * inner + 2], root.triangles[3 * inner]};
    const auto c = h.refine(marks);
    EXPECT_EQ(c.red, 1u);
    EXPECT_EQ(c.green, 3u);
    expect_valid_after_refine(h, root, marks, c, "one red");
    // Flag only the four red children: the greens go with them.
    std::vector<tri::TriIdx> red_children;
    for (tri::TriIdx t = 0; t < h.leaf_mesh().triangle_count(); ++t) {
        const auto& node = h.nodes()[h.leaf_nodes()[t]];
        if (node.parent == inner) red_children.push_back(t);
    }
    ASSERT_EQ(red_children.size(), 4u);
    // Flagging three of them coarsens nothing.
    h.derefine(std::span(red_children).first(3));
    EXPECT_EQ(h.leaf_mesh().triangle_count(), root.triangle_count() + 3 + 3);
    ASSERT_TRUE(gen::check_h_refined_mesh_2d(h).ok);
    const std::vector<tri::VertIdx> map = h.derefine(red_children);
    EXPECT_EQ(map.size(), root.vertex_count() + 3);
    EXPECT_EQ(h.counters().derefined, 4u);
    EXPECT_EQ(h.counters().removed_vertices, 3u);
    expect_same(h.leaf_mesh(), root, "one red coarsened");
}

// A red parent whose neighbour stays refined coarsens into the green pair on their shared edge
// (the closure refine() would have made), not into nothing and not kept whole; then, with the
// neighbour flagged too, both return to the root.
TEST(Generators_HRefinement2, ARedParentBesideAFinerNeighbourCoarsensToAGreenPair) {
    const tri::Triangulation2 root = mesh_of(grid_points(1));  // the unit square, two triangles
    ASSERT_EQ(root.triangle_count(), 2u);
    gen::HRefinedMesh2 h(root);
    h.refine(all_edges(root));
    ASSERT_EQ(h.leaf_mesh().triangle_count(), 8u);
    ASSERT_EQ(h.leaf_mesh().vertex_count(), 9u);
    // Flag the first root triangle's four children (leaves are in history order).
    std::vector<tri::TriIdx> first;
    for (tri::TriIdx t = 0; t < h.leaf_mesh().triangle_count(); ++t)
        if (h.nodes()[h.leaf_nodes()[t]].parent == 0) first.push_back(t);
    ASSERT_EQ(first.size(), 4u);
    const std::vector<tri::VertIdx> map = h.derefine(first);
    ASSERT_TRUE(gen::check_h_refined_mesh_2d(h).ok) << gen::check_h_refined_mesh_2d(h).problem;
    EXPECT_EQ(h.counters().red_to_green, 1u);
    EXPECT_EQ(h.counters().derefined, 0u);
    // Two green children and the neighbour's four; its two outer split points are gone, the
    // diagonal's stays (the neighbour's children use it).
    EXPECT_EQ(h.leaf_mesh().triangle_count(), 6u);
    EXPECT_EQ(h.leaf_mesh().vertex_count(), 7u);
    EXPECT_EQ(std::count(map.begin(), map.end(), tri::kNone), 2);
    const gen::HRefinementNode2& parent = h.nodes()[0];
    EXPECT_EQ(parent.child_count, 2);
    // Everything flagged: the green pair and the neighbour's red children go together.
    derefine_all(h, 5, "green pair");
    expect_same(h.leaf_mesh(), root, "after the green pair");
}

TEST(Generators_HRefinement2, RefiningEverythingThreeTimesIsRedOnlyAndDerefinesExactly) {
    const tri::Triangulation2 root = square_with_boundary(6);
    gen::HRefinedMesh2 h(root);
    std::uint64_t triangles = root.triangle_count();
    for (int level = 1; level <= 3; ++level) {
        const auto marks = all_edges(h.leaf_mesh());
        const auto c = h.refine(marks);
        EXPECT_EQ(c.green, 0u);
        EXPECT_EQ(c.red, triangles);
        triangles *= 4;
        EXPECT_EQ(h.leaf_mesh().triangle_count(), triangles);
        expect_valid_after_refine(h, root, marks, c, "level " + std::to_string(level));
        for (tri::TriIdx t = 0; t < h.leaf_mesh().triangle_count(); ++t)
            EXPECT_EQ(h.level(t), static_cast<std::uint32_t>(level));
    }
    for (int level = 3; level >= 1; --level) {
        h.derefine(all_leaves(h));
        const auto report = gen::check_h_refined_mesh_2d(h);
        ASSERT_TRUE(report.ok) << report.problem;
        triangles /= 4;
        EXPECT_EQ(h.leaf_mesh().triangle_count(), triangles);
    }
    expect_same(h.leaf_mesh(), root, "square with boundary");
}

TEST(Generators_HRefinement2, ConstrainedBoundaryFlagsFollowTheChildren) {
    const tri::Triangulation2 root = square_with_boundary(5);
    ASSERT_FALSE(root.constrained.empty());
    gen::HRefinedMesh2 h(root);
    std::mt19937_64 rng(7);
    for (int level = 0; level < 4; ++level) {
        const auto marks = random_marks(h.leaf_mesh(), 0.2, rng);
        const auto c = h.refine(marks);
        expect_valid_after_refine(h, root, marks, c, "level " + std::to_string(level));
    }
    // Every boundary edge of the leaf mesh is constrained (the check proves each flag comes from
    // the root edge the leaf edge lies on).
    const tri::Triangulation2& m = h.leaf_mesh();
    std::size_t constrained = 0;
    for (tri::TriIdx t = 0; t < m.triangle_count(); ++t) {
        for (int k = 0; k < 3; ++k) {
            if (m.neighbors[3 * t + static_cast<unsigned>(k)] == tri::kNone) {
                EXPECT_TRUE(m.is_constrained(t, k));
            }
            constrained += m.is_constrained(t, k);
        }
    }
    EXPECT_GT(constrained, 20u);
    // Random partial derefinement keeps everything valid.
    for (int step = 0; step < 6; ++step) {
        std::vector<tri::TriIdx> flagged;
        std::bernoulli_distribution pick(0.7);
        for (tri::TriIdx t = 0; t < h.leaf_mesh().triangle_count(); ++t) {
            if (pick(rng)) flagged.push_back(t);
        }
        h.derefine(flagged);
        const auto report = gen::check_h_refined_mesh_2d(h);
        ASSERT_TRUE(report.ok) << "step " << step << ": " << report.problem;
    }
    derefine_all(h, 40, "constrained square");
    expect_same(h.leaf_mesh(), root, "constrained square");
}

TEST(Generators_HRefinement2, SampleDomainMeshesWithHolesAndCurvedBoundaries) {
    for (const gen::SampleDomain d : gen::kAllSampleDomains) {
        const gen::SizeFunction size = gen::sample_domain_size(d);
        const gen::DomainPslg domain = gen::sample_domain(d, size);
        gen::RefinementOptions2 options;
        options.size = size;
        const tri::Triangulation2 root =
            gen::delaunay_refinement_2d({domain.xy, domain.segments, domain.holes, {}}, options)
                .mesh.mesh;
        const std::string what(gen::sample_domain_name(d));
        gen::HRefinedMesh2 h(root);
        std::mt19937_64 rng(13);
        for (int level = 0; level < 2; ++level) {
            const auto marks = random_marks(h.leaf_mesh(), 0.05, rng);
            const auto c = h.refine(marks);
            EXPECT_EQ(c.refused_edges, 0u) << what;
            expect_valid_after_refine(h, root, marks, c, what + " level " + std::to_string(level));
        }
        derefine_all(h, 20, what);
        expect_same(h.leaf_mesh(), root, what);
    }
}

TEST(Generators_HRefinement2, RoundedMidpointIsRoundedOnce) {
    EXPECT_EQ(gen::rounded_midpoint(1.0, 3.0), 2.0);
    EXPECT_EQ(gen::rounded_midpoint(-1.0, 1.0), 0.0);
    // Ties go to even: 1 + 2^-53 lies halfway between 1 and 1 + 2^-52.
    EXPECT_EQ(gen::rounded_midpoint(1.0, 1.0 + 0x1p-52), 1.0);
    EXPECT_EQ(gen::rounded_midpoint(1.0 + 0x1p-52, 1.0 + 0x1p-51), 1.0 + 0x1p-51);
    // a + b overflows: the halves are summed.
    const double big = std::numeric_limits<double>::max();
    EXPECT_EQ(gen::rounded_midpoint(big, big), big);
    EXPECT_EQ(gen::rounded_midpoint(big, -big), 0.0);
    // (1.5 - 2^-53) 2^1023, halfway between two doubles: to the even one, 1.5 2^1023.
    EXPECT_EQ(gen::rounded_midpoint(big, 0x1p1023), 0x1.8p1023);
    // Subnormals: the sum is exact, its half rounds once (ties to even).
    const double tiny = std::numeric_limits<double>::denorm_min();
    EXPECT_EQ(gen::rounded_midpoint(tiny, 0.0), 0.0);
    EXPECT_EQ(gen::rounded_midpoint(3 * tiny, 0.0), 2 * tiny);
    EXPECT_EQ(gen::rounded_midpoint(4 * tiny, 2 * tiny), 3 * tiny);
    // Scaling by 2^k scales the midpoint exactly.
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int i = 0; i < 1000; ++i) {
        const double a = u(rng), b = u(rng);
        for (const int k : {-600, 600})
            EXPECT_EQ(gen::rounded_midpoint(std::ldexp(a, k), std::ldexp(b, k)),
                      std::ldexp(gen::rounded_midpoint(a, b), k));
    }
}

TEST(Generators_HRefinement2, LinearFieldIsTransferredExactlyOnADyadicGrid) {
    const tri::Triangulation2 root = mesh_of(grid_points(8));
    gen::HRefinedMesh2 h(root);
    auto linear = [](const tri::Triangulation2& m) {
        std::vector<double> f(m.vertex_count());
        for (tri::VertIdx v = 0; v < f.size(); ++v) f[v] = m.xy[2 * v] + 3 * m.xy[2 * v + 1];
        return f;
    };
    std::vector<double> field = linear(root);
    std::mt19937_64 rng(3);
    for (int level = 0; level < 5; ++level) {
        const std::vector<double> before = field;
        const auto marks = random_marks(h.leaf_mesh(), 0.2, rng);
        h.refine(marks);
        field = h.transfer_field(field);
        ASSERT_EQ(field.size(), h.leaf_mesh().vertex_count());
        EXPECT_TRUE(std::equal(before.begin(), before.end(), field.begin()));  // injection
        EXPECT_EQ(field, linear(h.leaf_mesh()));  // exact at every midpoint
    }
    for (int step = 0; step < 6; ++step) {
        const std::vector<tri::VertIdx> map = h.derefine(all_leaves(h));
        field = gen::restrict_field(field, map);
        EXPECT_EQ(field, linear(h.leaf_mesh()));
    }
}

TEST(Generators_HRefinement2, FieldTransferInterpolatesWithinRoundingOnRandomMeshes) {
    const tri::Triangulation2 root =
        mesh_of(gen::generate_points_2d(gen::Distribution::Uniform, 50, 5));
    gen::HRefinedMesh2 h(root);
    std::vector<double> field(root.vertex_count());
    for (tri::VertIdx v = 0; v < field.size(); ++v) field[v] = root.xy[2 * v] + root.xy[2 * v + 1];
    std::mt19937_64 rng(5);
    for (int level = 0; level < 3; ++level) {
        h.refine(random_marks(h.leaf_mesh(), 0.3, rng));
        field = h.transfer_field(field);
    }
    const tri::Triangulation2& m = h.leaf_mesh();
    for (tri::VertIdx v = 0; v < m.vertex_count(); ++v) {
        const double exact = m.xy[2 * v] + m.xy[2 * v + 1];
        if (v < root.vertex_count()) {
            EXPECT_EQ(field[v], exact);
        } else {
            // Each level rounds the coordinates and the field once: a few ulps of 2.
            EXPECT_NEAR(field[v], exact, 64 * 0x1p-52) << v;
        }
    }
}

TEST(Generators_HRefinement2, ScalingByPowersOfTwoGivesTheSameTriangles) {
    const std::vector<double> xy = gen::generate_points_2d(gen::Distribution::Uniform, 60, 9);
    const tri::Triangulation2 root = mesh_of(xy);
    auto run = [&](int k) {
        tri::Triangulation2 scaled = root;
        for (double& x : scaled.xy) x = std::ldexp(x, k);
        gen::HRefinedMesh2 h(scaled);
        std::mt19937_64 rng(11);
        for (int level = 0; level < 4; ++level) {
            h.refine(random_marks(h.leaf_mesh(), 0.2, rng));
            const auto report = gen::check_h_refined_mesh_2d(h);
            EXPECT_TRUE(report.ok) << k << ": " << report.problem;
        }
        h.derefine(std::vector<tri::TriIdx>{0, 1, 2, 3, 4, 5, 6, 7});
        return h.leaf_mesh();
    };
    const tri::Triangulation2 one = run(0);
    for (const int k : {-600, 600}) {
        const tri::Triangulation2 other = run(k);
        EXPECT_EQ(other.triangles, one.triangles) << k;
        EXPECT_EQ(other.neighbors, one.neighbors) << k;
        ASSERT_EQ(other.xy.size(), one.xy.size());
        for (std::size_t i = 0; i < one.xy.size(); ++i)
            ASSERT_EQ(other.xy[i], std::ldexp(one.xy[i], k)) << k << " coordinate " << i;
    }
}

TEST(Generators_HRefinement2, SliverSplitsAreRefusedNeverInverted) {
    // Edge 0 - 1 is one ulp long: its midpoint rounds to an end (ties to even), so splitting it
    // would make a degenerate child.
    const std::vector<double> xy{1, 0, 1 + 0x1p-52, 0, 1, 1, 2, 2};
    const tri::Triangulation2 root = mesh_of(xy);
    gen::HRefinedMesh2 h(root);
    const std::vector<tri::VertIdx> short_edge{0, 1};
    auto c = h.refine(short_edge);
    EXPECT_GE(c.refused_edges, 1u);
    EXPECT_EQ(c.red + c.green, 0u);
    auto report = gen::check_h_refined_mesh_2d(h);
    ASSERT_TRUE(report.ok) << report.problem;
    expect_same(h.leaf_mesh(), root, "refused");
    // Everything marked: whatever is refused, the mesh stays valid and something is refined.
    for (int level = 0; level < 3; ++level) {
        c = h.refine(all_edges(h.leaf_mesh()));
        report = gen::check_h_refined_mesh_2d(h);
        ASSERT_TRUE(report.ok) << report.problem;
    }
    EXPECT_GT(h.leaf_mesh().triangle_count(), root.triangle_count());
    EXPECT_GT(h.counters().refused_edges, 0u);
}

TEST(Generators_HRefinement2, ManySliversAreRefusedLocally) {
    // 2000 points within a few ulps of a line: thousands of refusals, each settled by local
    // work (this took quadratic time, 54 s for 4000 points, while a refusal restarted the pass).
    const tri::Triangulation2 root =
        mesh_of(gen::generate_points_2d(gen::Distribution::NearCollinear, 2000, 1));
    gen::HRefinedMesh2 h(root);
    for (int level = 0; level < 2; ++level) {
        const auto c = h.refine(all_edges(h.leaf_mesh()));
        const auto report = gen::check_h_refined_mesh_2d(h);
        ASSERT_TRUE(report.ok) << report.problem;
        const auto fold = check_no_fold(h, root);
        ASSERT_TRUE(fold.ok) << fold.problem;
        EXPECT_GT(c.refused_edges, 100u);
        EXPECT_GT(c.red + c.green, 100u);
        EXPECT_LT(c.closure_iterations, 50 * std::uint64_t{h.leaf_mesh().triangle_count()});
    }
}

TEST(Generators_HRefinement2, NearCollinearAndTinyHugeInputsStayValid) {
    for (const gen::Distribution d : {gen::Distribution::NearCollinear, gen::Distribution::Tiny,
                                      gen::Distribution::Huge, gen::Distribution::Duplicates}) {
        const tri::Triangulation2 root = mesh_of(gen::generate_points_2d(d, 60, 2));
        gen::HRefinedMesh2 h(root);
        std::mt19937_64 rng(2);
        for (int level = 0; level < 4; ++level) {
            const auto marks = random_marks(h.leaf_mesh(), 0.5, rng);
            const auto c = h.refine(marks);
            expect_valid_after_refine(
                h, root, marks, c,
                std::string(gen::distribution_name(d)) + " level " + std::to_string(level));
        }
        derefine_all(h, 40, std::string(gen::distribution_name(d)));
        if (h.counters().refused_edges == 0)
            expect_same(h.leaf_mesh(), root, std::string(gen::distribution_name(d)));
    }
}

/// The neighbours of `triangles` matched by their edges.
std::vector<tri::TriIdx> neighbors_of(const std::vector<tri::VertIdx>& triangles) {
    std::vector<tri::TriIdx> neighbors(triangles.size(), tri::kNone);
    for (std::size_t e = 0; e < triangles.size(); ++e) {
        const tri::VertIdx a = triangles[e], b = triangles[e % 3 == 2 ? e - 2 : e + 1];
        for (std::size_t f = 0; f < triangles.size(); ++f) {
            if (triangles[f] == b && triangles[f % 3 == 2 ? f - 2 : f + 1] == a)
                neighbors[e] = static_cast<tri::TriIdx>(f / 3);
        }
    }
    return neighbors;
}

TEST(Generators_HRefinement2, TheCheckFindsCorruptedHistories) {
    // The unit square's two triangles, the diagonal split: two green pairs.
    const std::vector<double> xy{0, 0, 1, 0, 1, 1, 0, 1};
    const tri::Triangulation2 root = mesh_of(xy);
    gen::HRefinedMesh2 h(root);
    const auto [a, b] = interior_edge_of_first_triangle(root);
    h.refine(std::vector<tri::VertIdx>{a, b});
    std::vector<tri::VertIdx> boundary_edge;
    for (unsigned k = 0; k < 3 && boundary_edge.empty(); ++k) {
        if (root.neighbors[k] == tri::kNone)
            boundary_edge = {root.triangles[k], root.triangles[(k + 1) % 3]};
    }
    const auto c = h.refine(boundary_edge);  // undoes one green pair: a red parent
    EXPECT_EQ(c.green_undone, 1u);
    EXPECT_EQ(c.red, 1u);
    ASSERT_TRUE(gen::check_h_refined_mesh_2d(h).ok);
    const std::vector<gen::HRefinementNode2> nodes(h.nodes().begin(), h.nodes().end());
    const std::vector<std::uint32_t> leaves(h.leaf_nodes().begin(), h.leaf_nodes().end());
    const std::vector<std::array<tri::VertIdx, 2>> parents(h.vertex_parents().begin(),
                                                           h.vertex_parents().end());
    auto check = [&](const tri::Triangulation2& leaf, const std::vector<gen::HRefinementNode2>& n,
                     const std::vector<std::uint32_t>& l) {
        return gen::check_h_refinement_history_2d(leaf, n, l, parents, h.root_triangle_count(),
                                                  h.root_vertex_count());
    };
    ASSERT_TRUE(check(h.leaf_mesh(), nodes, leaves).ok);
    {  // a wrong neighbour
        tri::Triangulation2 leaf = h.leaf_mesh();
        std::swap(leaf.neighbors[0], leaf.neighbors[1]);
        EXPECT_FALSE(check(leaf, nodes, leaves).ok);
    }
    {  // a split point off its rounded midpoint
        tri::Triangulation2 leaf = h.leaf_mesh();
        leaf.xy[2 * 4] = std::nextafter(leaf.xy[2 * 4], 2.0);
        const auto report = check(leaf, nodes, leaves);
        EXPECT_FALSE(report.ok);
        EXPECT_NE(report.problem.find("rounded midpoint"), std::string::npos) << report.problem;
    }
    {  // a hanging vertex: the remaining green pair merged back into its parent
        std::vector<gen::HRefinementNode2> n = nodes;
        std::uint32_t green = tri::kNone;
        for (std::uint32_t id = 0; id < n.size(); ++id) {
            if (n[id].alive && n[id].child_count == 2) green = id;
        }
        ASSERT_NE(green, tri::kNone);
        std::vector<std::uint32_t> l;
        for (const std::uint32_t id : leaves) {
            if (n[id].parent != green) {
                l.push_back(id);
            } else if (id == n[green].children[0]) {
                l.push_back(green);
            }
        }
        n[n[green].children[0]].alive = 0;
        n[n[green].children[1]].alive = 0;
        n[green].child_count = 0;
        tri::Triangulation2 leaf = h.leaf_mesh();
        leaf.triangles.clear();
        for (const std::uint32_t id : l)
            leaf.triangles.insert(leaf.triangles.end(), n[id].corners.begin(), n[id].corners.end());
        leaf.neighbors = neighbors_of(leaf.triangles);
        if (!leaf.constrained.empty()) leaf.constrained.assign(leaf.triangles.size(), 0);
        const auto report = check(leaf, n, l);
        EXPECT_FALSE(report.ok);
        EXPECT_NE(report.problem.find("hanging"), std::string::npos) << report.problem;
    }
    {  // a constrained flag that no root edge gives
        tri::Triangulation2 leaf = h.leaf_mesh();
        leaf.constrained.assign(leaf.triangles.size(), 0);
        bool flagged = false;
        for (std::size_t e = 0; e < leaf.neighbors.size() && !flagged; ++e) {
            if (leaf.neighbors[e] == tri::kNone) leaf.constrained[e] = flagged = true;
        }
        ASSERT_TRUE(flagged);
        const auto report = check(leaf, nodes, leaves);
        EXPECT_FALSE(report.ok);
        EXPECT_NE(report.problem.find("constrained"), std::string::npos) << report.problem;
    }
    {  // a child that is not its pattern (turned: the same triangle, other corners first)
        std::vector<gen::HRefinementNode2> n = nodes;
        bool turned = false;
        for (gen::HRefinementNode2& node : n) {
            if (node.alive && node.child_count == 4 && !turned) {
                auto& corners = n[node.children[3]].corners;
                std::rotate(corners.begin(), corners.begin() + 1, corners.end());
                turned = true;
            }
        }
        ASSERT_TRUE(turned);
        const auto report = check(h.leaf_mesh(), n, leaves);
        EXPECT_FALSE(report.ok);
    }
}

TEST(Generators_HRefinement2, BadInputIsAnInputError) {
    const std::vector<double> xy{0, 0, 1, 0, 1, 1, 0, 1};
    const tri::Triangulation2 root = mesh_of(xy);
    {
        tri::Triangulation2 bad = root;
        std::swap(bad.triangles[0], bad.triangles[1]);  // clockwise
        EXPECT_THROW(gen::HRefinedMesh2{bad}, em::InputError);
    }
    {
        tri::Triangulation2 bad = root;
        std::fill(bad.neighbors.begin(), bad.neighbors.end(), tri::kNone);
        EXPECT_THROW(gen::HRefinedMesh2{bad}, em::InputError);
    }
    {
        tri::Triangulation2 bad = root;
        bad.xy[0] = std::nan("");
        EXPECT_THROW(gen::HRefinedMesh2{bad}, em::InputError);
    }
    {
        tri::Triangulation2 bad = root;
        bad.triangles[0] = 99;
        EXPECT_THROW(gen::HRefinedMesh2{bad}, em::InputError);
    }
    gen::HRefinedMesh2 h(root);
    EXPECT_THROW(h.refine(std::vector<tri::VertIdx>{0, 9}), em::InputError);
    EXPECT_THROW(h.refine(std::vector<tri::VertIdx>{0}), em::InputError);
    EXPECT_THROW(h.derefine(std::vector<tri::TriIdx>{5}), em::InputError);
    EXPECT_THROW(h.transfer_field(std::vector<double>{1.0}), em::InputError);
    // A pair that is no edge is ignored and counted.
    const auto c = h.refine(std::vector<tri::VertIdx>{0, 0});
    EXPECT_EQ(c.ignored_marks, 1u);
    expect_same(h.leaf_mesh(), root, "ignored");
}
