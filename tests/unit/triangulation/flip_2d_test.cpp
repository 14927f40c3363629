// SPDX-License-Identifier: MIT
// The 2D flip kernel (triangulation/mesh/flip_2d.hpp): after each primitive the half-edge mesh is
// valid (twins mutual and sharing the edge reversed, every triangle strictly counter-clockwise
// by exact orient2d), the layout is the documented one, the flags stay on the edges they marked;
// incremental insertion and Lawson flipping written on the kernel alone reach exactly
// bowyer_watson_2d's triangulation (which does not use the kernel), cocircular grids included;
// HalfEdgeEdit round-trips a Triangulation2.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <random>
#include <set>
#include <vector>

#include "base/errors.hpp"
#include "generators/inputs/sweep_triangulation_2d.hpp"
#include "predicates/incircle.hpp"
#include "predicates/orient2d.hpp"
#include "predicates/sos.hpp"
#include "tests/support/canonical_triangles_2d.hpp"
#include "triangulation/delaunay/bowyer_watson_2d.hpp"
#include "triangulation/mesh/flip_2d.hpp"
#include "triangulation/modification/edge_swap_2d.hpp"

namespace em = exactmesh;
namespace tri = exactmesh::triangulation;
using em::predicates::Sign;

namespace {

using Triangles = exactmesh::testing::CanonicalTriangles;
// The kernel's primitives reuse or append slots and never leave one dead, so every slot counts.
constexpr auto canonical = exactmesh::testing::canonical_triangles;

/// Every live triangle strictly counter-clockwise; twins mutual, on the same edge reversed,
/// with equal flags; kNone twins only where allowed (a mesh without the infinite vertex).
void expect_valid(const tri::TriMesh2& mesh) {
    ASSERT_EQ(mesh.twin.size(), mesh.tv.size());
    if (!mesh.flags.empty()) {
        ASSERT_EQ(mesh.flags.size(), mesh.tv.size());
    }
    for (tri::TriIdx t = 0; t < mesh.triangle_slots(); ++t) {
        if (mesh.is_dead(t)) continue;
        const tri::VertIdx* v = &mesh.tv[3 * t];
        ASSERT_EQ(em::predicates::orient2d(mesh.point(v[0]), mesh.point(v[1]), mesh.point(v[2])),
                  Sign::Positive)
            << "triangle " << t;
        for (unsigned k = 0; k < 3; ++k) {
            const tri::EdgeIdx e = 3 * t + k, f = mesh.twin[e];
            if (f == tri::kNone) continue;
            ASSERT_FALSE(mesh.is_dead(tri::triangle_of(f))) << "edge " << e;
            ASSERT_EQ(mesh.twin[f], e) << "edge " << e;
            ASSERT_EQ(mesh.origin(f), mesh.destination(e)) << "edge " << e;
            ASSERT_EQ(mesh.destination(f), mesh.origin(e)) << "edge " << e;
            if (!mesh.flags.empty()) {
                ASSERT_EQ(mesh.flags[e], mesh.flags[f]) << "edge " << e;
            }
        }
    }
}

/// The half-edge u -> v, or kNone.
tri::EdgeIdx find_edge(const tri::TriMesh2& mesh, tri::VertIdx u, tri::VertIdx v) {
    for (tri::EdgeIdx e = 0; e < mesh.tv.size(); ++e) {
        if (!mesh.is_dead(tri::triangle_of(e)) && mesh.origin(e) == u && mesh.destination(e) == v)
            return e;
    }
    return tri::kNone;
}

std::uint8_t flag_of(const tri::TriMesh2& mesh, tri::VertIdx u, tri::VertIdx v) {
    const tri::EdgeIdx e = find_edge(mesh, u, v);
    EXPECT_NE(e, tri::kNone) << u << " -> " << v;
    return e == tri::kNone ? 0xFF : mesh.flags[e];
}

/// The square (0,0) (2,0) (2,2) (0,2) = vertices 0..3, cut by the diagonal 0 - 2 into
/// (0, 1, 2) and (0, 2, 3), with the diagonal and the bottom side flagged, plus vertex 4 = (1, 1)
/// (on the diagonal), 5 = (1.5, 0.5) (inside (0, 1, 2)), 6 = (1, 0) (on the bottom side).
tri::TriMesh2 flagged_square() {
    tri::Triangulation2 square;
    square.xy = {0, 0, 2, 0, 2, 2, 0, 2, 1, 1, 1.5, 0.5, 1, 0};
    square.triangles = {0, 1, 2, 0, 2, 3};
    square.constrained = {1, 0, 1, 1, 0, 0};  // 0-1 (bottom), 2-0 and its twin 0-2
    tri::link_neighbors_2d(square);
    tri::TriMesh2 mesh;
    {
        tri::HalfEdgeEdit edit(square);
        mesh = edit.mesh();  // a copy; the edit gives the square back
    }
    return mesh;
}

}  // namespace

TEST(Triangulation_Flip2, HalfEdgeEditRoundTripsAndFindsTwins) {
    tri::Triangulation2 square;
    square.xy = {0, 0, 2, 0, 2, 2, 0, 2};
    square.triangles = {0, 1, 2, 0, 2, 3};
    square.constrained = {0, 0, 1, 1, 0, 0};
    tri::link_neighbors_2d(square);
    const tri::Triangulation2 before = square;
    {
        tri::HalfEdgeEdit edit(square);
        const tri::TriMesh2& mesh = edit.mesh();
        expect_valid(mesh);
        EXPECT_EQ(mesh.twin[2], 3u);  // 2 -> 0 in t0 faces 0 -> 2 in t1
        EXPECT_EQ(mesh.twin[0], tri::kNone);
        EXPECT_EQ(mesh.flags, before.constrained);
        EXPECT_TRUE(square.triangles.empty());  // moved, not copied
    }
    EXPECT_EQ(square.xy, before.xy);
    EXPECT_EQ(square.triangles, before.triangles);
    EXPECT_EQ(square.neighbors, before.neighbors);
    EXPECT_EQ(square.constrained, before.constrained);

    tri::Triangulation2 broken = before;
    broken.neighbors[0] = 1;  // t1 does not hold the edge 1 -> 0
    EXPECT_THROW(tri::HalfEdgeEdit edit(broken), em::InternalError);
    EXPECT_EQ(broken.triangles, before.triangles);  // nothing moved
}

TEST(Triangulation_Flip2, SplitTriangleLayoutTwinsAndFlags) {
    tri::TriMesh2 mesh = flagged_square();
    const tri::SplitTriangles made = tri::split_triangle_2d(mesh, 0, 5);
    ASSERT_EQ(made.count, 3u);
    EXPECT_EQ(made.triangles[0], 0u);  // slot reused first
    expect_valid(mesh);
    EXPECT_EQ(mesh.triangle_slots(), 4u);
    const std::array<std::array<tri::VertIdx, 2>, 3> sides{{{0, 1}, {1, 2}, {2, 0}}};
    for (unsigned i = 0; i < 3; ++i) {
        const tri::TriIdx t = made.triangles[i];
        EXPECT_EQ(mesh.tv[3 * t], 5u);  // p at local 0
        EXPECT_EQ(mesh.origin(made.side(i)), sides[i][0]);
        EXPECT_EQ(mesh.destination(made.side(i)), sides[i][1]);
        EXPECT_EQ(mesh.flags[3 * t], 0);  // spokes unmarked
        EXPECT_EQ(mesh.flags[3 * t + 2], 0);
    }
    EXPECT_EQ(flag_of(mesh, 0, 1), 1);  // sides keep their marks
    EXPECT_EQ(flag_of(mesh, 1, 2), 0);
    EXPECT_EQ(flag_of(mesh, 2, 0), 1);
    EXPECT_EQ(flag_of(mesh, 0, 2), 1);
    EXPECT_EQ(canonical(mesh.tv), (Triangles{{0, 1, 5}, {1, 2, 5}, {0, 5, 2}, {0, 2, 3}}));
}

TEST(Triangulation_Flip2, SplitInteriorEdgeTwoToFourKeepsTheConstraintOnBothHalves) {
    tri::TriMesh2 mesh = flagged_square();
    const tri::EdgeIdx e = find_edge(mesh, 2, 0);
    const tri::SplitTriangles made = tri::split_edge_2d(mesh, e, 4);
    ASSERT_EQ(made.count, 4u);
    expect_valid(mesh);
    EXPECT_EQ(canonical(mesh.tv), (Triangles{{1, 2, 4}, {2, 3, 4}, {0, 4, 3}, {0, 1, 4}}));
    for (unsigned i = 0; i < 4; ++i) EXPECT_EQ(mesh.tv[3 * made.triangles[i]], 4u);
    EXPECT_EQ(flag_of(mesh, 0, 4), 1);
    EXPECT_EQ(flag_of(mesh, 4, 2), 1);
    EXPECT_EQ(flag_of(mesh, 1, 4), 0);
    EXPECT_EQ(flag_of(mesh, 3, 4), 0);
    EXPECT_EQ(flag_of(mesh, 0, 1), 1);
    EXPECT_EQ(flag_of(mesh, 2, 3), 0);
    // Counter-clockwise around p, each side opposite p.
    for (unsigned i = 0; i < 4; ++i) {
        EXPECT_EQ(mesh.destination(made.side(i)), mesh.origin(made.side((i + 1) % 4)));
    }
}

TEST(Triangulation_Flip2, SplitBoundaryEdgeOneToTwo) {
    tri::TriMesh2 mesh = flagged_square();
    const tri::EdgeIdx e = find_edge(mesh, 0, 1);
    ASSERT_EQ(mesh.twin[e], tri::kNone);
    const tri::SplitTriangles made = tri::split_edge_2d(mesh, e, 6);
    ASSERT_EQ(made.count, 2u);
    expect_valid(mesh);
    EXPECT_EQ(canonical(mesh.tv), (Triangles{{1, 2, 6}, {0, 6, 2}, {0, 2, 3}}));
    const tri::EdgeIdx left = find_edge(mesh, 0, 6), right = find_edge(mesh, 6, 1);
    ASSERT_NE(left, tri::kNone);
    ASSERT_NE(right, tri::kNone);
    EXPECT_EQ(mesh.twin[left], tri::kNone);
    EXPECT_EQ(mesh.twin[right], tri::kNone);
    EXPECT_EQ(mesh.flags[left], 1);
    EXPECT_EQ(mesh.flags[right], 1);
    EXPECT_EQ(flag_of(mesh, 6, 2), 0);
    EXPECT_EQ(flag_of(mesh, 2, 0), 1);
}

TEST(Triangulation_Flip2, FlipPutsTheDiagonalWhereAskedAndKeepsSideFlags) {
    for (unsigned k1 = 0; k1 < 3; ++k1) {
        for (unsigned k2 = 0; k2 < 3; ++k2) {
            tri::TriMesh2 mesh = flagged_square();
            mesh.flags.assign(mesh.flags.size(), 0);
            // Mark the sides 1 -> 2 and 3 -> 0 (both boundary) to see them travel.
            mesh.flags[find_edge(mesh, 1, 2)] = 1;
            mesh.flags[find_edge(mesh, 3, 0)] = 2;
            const tri::EdgeIdx e = find_edge(mesh, 0, 2);  // u = 0, v = 2, x = 3, y = 1
            const tri::TriIdx t1 = tri::triangle_of(e), t2 = tri::triangle_of(mesh.twin[e]);
            const tri::FlipEdges flipped = tri::flip_2d(mesh, e, k1, k2);
            expect_valid(mesh);
            EXPECT_EQ(flipped.diagonal, 3 * t1 + k1);
            EXPECT_EQ(mesh.twin[flipped.diagonal], 3 * t2 + k2);
            EXPECT_EQ(mesh.origin(flipped.diagonal), 1u);  // y -> x
            EXPECT_EQ(mesh.destination(flipped.diagonal), 3u);
            const std::array<std::array<tri::VertIdx, 2>, 4> sides{
                {{3, 0}, {0, 1}, {1, 2}, {2, 3}}};
            for (unsigned i = 0; i < 4; ++i) {
                EXPECT_EQ(mesh.origin(flipped.sides[i]), sides[i][0]);
                EXPECT_EQ(mesh.destination(flipped.sides[i]), sides[i][1]);
            }
            EXPECT_EQ(mesh.flags[flipped.sides[0]], 2);
            EXPECT_EQ(mesh.flags[flipped.sides[2]], 1);
            EXPECT_EQ(mesh.flags[flipped.diagonal], 0);
            EXPECT_EQ(canonical(mesh.tv), (Triangles{{0, 1, 3}, {1, 2, 3}}));
        }
    }
}

namespace {

/// Inserts p by the kernel: brute-force exact location, 1-3 or edge split, then Lawson flips
/// (SoS incircle, Green-Sibson's layout) that never flip a flagged or boundary edge.
void insert_with_kernel(tri::TriMesh2& mesh, tri::VertIdx p) {
    tri::SplitTriangles made;
    bool placed = false;
    for (tri::TriIdx t = 0; t < mesh.triangle_slots() && !placed; ++t) {
        if (mesh.is_dead(t)) continue;
        int zero = -1, negative = 0;
        for (unsigned k = 0; k < 3; ++k) {
            const Sign s =
                em::predicates::orient2d(mesh.point(mesh.origin(3 * t + k)),
                                         mesh.point(mesh.destination(3 * t + k)), mesh.point(p));
            if (s == Sign::Negative) ++negative;
            if (s == Sign::Zero) zero = static_cast<int>(k);
        }
        if (negative != 0) continue;
        made = zero < 0 ? tri::split_triangle_2d(mesh, t, p)
                        : tri::split_edge_2d(mesh, 3 * t + static_cast<unsigned>(zero), p);
        placed = true;
    }
    ASSERT_TRUE(placed) << "point " << p << " outside the mesh";
    std::vector<tri::EdgeIdx> stack;
    for (unsigned i = 0; i < made.count; ++i) stack.push_back(made.side(i));
    while (!stack.empty()) {
        const tri::EdgeIdx e = stack.back();
        stack.pop_back();
        const tri::EdgeIdx f = mesh.twin[e];
        if (f == tri::kNone || mesh.flags[e] != 0) continue;
        const tri::VertIdx a = mesh.tv[3 * tri::triangle_of(e)], b = mesh.origin(e),
                           c = mesh.destination(e), d = mesh.tv[tri::prev_edge(f)];
        if (em::predicates::incircle_sos(mesh.point(a), mesh.point(b), mesh.point(c), mesh.point(d),
                                         a, b, c, d) != Sign::Positive)
            continue;
        const tri::FlipEdges flipped = tri::flip_2d(mesh, e, 2, 0);
        ASSERT_EQ(mesh.tv[3 * tri::triangle_of(flipped.sides[1])], p);
        ASSERT_EQ(mesh.tv[3 * tri::triangle_of(flipped.sides[2])], p);
        stack.push_back(flipped.sides[1]);
        stack.push_back(flipped.sides[2]);
    }
}

/// Square [0, 4]^2 (vertices 0..3), then the other points of the integer grid (cocircular
/// quadruples everywhere, many on edges and on the boundary), then random points, shuffled.
std::vector<double> square_grid_and_random(unsigned random_points, unsigned seed) {
    std::vector<double> xy = {0, 0, 4, 0, 4, 4, 0, 4};
    std::vector<std::array<double, 2>> rest;
    for (int i = 0; i <= 4; ++i) {
        for (int j = 0; j <= 4; ++j) {
            if ((i == 0 || i == 4) && (j == 0 || j == 4)) continue;
            rest.push_back({double(i), double(j)});
        }
    }
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> inside(0.0, 4.0);
    for (unsigned i = 0; i < random_points; ++i) rest.push_back({inside(rng), inside(rng)});
    std::shuffle(rest.begin(), rest.end(), rng);
    for (const auto& q : rest) xy.insert(xy.end(), {q[0], q[1]});
    return xy;
}

tri::TriMesh2 square_mesh(const std::vector<double>& xy, bool constrain_diagonal) {
    tri::TriMesh2 mesh;
    mesh.xy = xy;
    mesh.tv = {0, 1, 2, 0, 2, 3};
    mesh.twin = {tri::kNone, tri::kNone, 3, 2, tri::kNone, tri::kNone};
    // The boundary marked 1, the diagonal 0 - 2 marked 2 when constrained.
    const std::uint8_t diagonal = constrain_diagonal ? 2 : 0;
    mesh.flags = {1, 1, diagonal, diagonal, 1, 1};
    return mesh;
}

}  // namespace

TEST(Triangulation_Flip2, IncrementalLawsonOnTheKernelIsExactlyDelaunay) {
    for (unsigned seed = 1; seed <= 6; ++seed) {
        const std::vector<double> xy = square_grid_and_random(40 * seed, seed);
        tri::TriMesh2 mesh = square_mesh(xy, false);
        for (tri::VertIdx p = 4; p < mesh.vertex_count(); ++p) {
            insert_with_kernel(mesh, p);
            if (testing::Test::HasFatalFailure()) return;
        }
        expect_valid(mesh);
        EXPECT_EQ(canonical(mesh.tv), canonical(tri::bowyer_watson_2d(xy).triangles))
            << "seed " << seed;
        // Every boundary half-edge kept its mark through the 1-2 splits; no interior edge has one.
        std::size_t boundary = 0;
        for (tri::EdgeIdx e = 0; e < mesh.tv.size(); ++e) {
            if (mesh.is_dead(tri::triangle_of(e))) continue;
            EXPECT_EQ(mesh.flags[e], mesh.twin[e] == tri::kNone ? 1 : 0) << "edge " << e;
            boundary += mesh.twin[e] == tri::kNone ? 1 : 0;
        }
        EXPECT_EQ(boundary, 16u);  // 4 sides, 5 grid points each
    }
}

TEST(Triangulation_Flip2, ConstrainedDiagonalSurvivesSplitsAndFlips) {
    const std::vector<double> xy = square_grid_and_random(150, 99);
    tri::TriMesh2 mesh = square_mesh(xy, true);
    for (tri::VertIdx p = 4; p < mesh.vertex_count(); ++p) {
        insert_with_kernel(mesh, p);
        if (testing::Test::HasFatalFailure()) return;
    }
    expect_valid(mesh);
    // The diagonal is now the chain (0,0) (1,1) (2,2) (3,3) (4,4), every piece marked, and no other
    // edge marked 2.
    std::set<std::array<double, 4>> marked;
    for (tri::EdgeIdx e = 0; e < mesh.tv.size(); ++e) {
        if (mesh.flags[e] != 2) continue;
        const double* a = mesh.point(mesh.origin(e));
        const double* b = mesh.point(mesh.destination(e));
        if (a[0] < b[0]) marked.insert({a[0], a[1], b[0], b[1]});
        EXPECT_EQ(a[0], a[1]);
        EXPECT_EQ(b[0], b[1]);
    }
    EXPECT_EQ(marked, (std::set<std::array<double, 4>>{
                          {0, 0, 1, 1}, {1, 1, 2, 2}, {2, 2, 3, 3}, {3, 3, 4, 4}}));
}

TEST(Triangulation_Flip2, LawsonSwapsOnTheKernelFromASweepReachBowyerWatson) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<double> xy;
    for (int i = 0; i < 2 * 500; ++i) xy.push_back(unit(rng));
    tri::Triangulation2 sweep = em::generators::sweep_triangulation_2d(xy);
    std::uint64_t flips = 0;
    {
        tri::HalfEdgeEdit edit(sweep);
        tri::TriMesh2& mesh = edit.mesh();
        bool changed = true;
        while (changed) {
            changed = false;
            for (tri::EdgeIdx e = 0; e < mesh.tv.size(); ++e) {
                const tri::EdgeIdx f = mesh.twin[e];
                if (f == tri::kNone) continue;
                const tri::VertIdx a = mesh.origin(e), b = mesh.destination(e),
                                   c = mesh.tv[tri::prev_edge(e)], d = mesh.tv[tri::prev_edge(f)];
                if (em::predicates::orient2d(mesh.point(c), mesh.point(a), mesh.point(d)) !=
                        Sign::Positive ||
                    em::predicates::orient2d(mesh.point(d), mesh.point(b), mesh.point(c)) !=
                        Sign::Positive)
                    continue;
                if (em::predicates::incircle_sos(mesh.point(a), mesh.point(b), mesh.point(c),
                                                 mesh.point(d), a, b, c, d) != Sign::Positive)
                    continue;
                tri::flip_2d(mesh, e, e % 3, (e + 1) % 3);  // any layout will do
                ++flips;
                changed = true;
            }
        }
        expect_valid(mesh);
    }
    EXPECT_GT(flips, 500u);
    EXPECT_EQ(canonical(sweep.triangles), canonical(tri::bowyer_watson_2d(xy).triangles));
}
