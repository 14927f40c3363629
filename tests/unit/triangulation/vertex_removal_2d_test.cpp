// SPDX-License-Identifier: MIT
// Vertex removal from 2D constrained Delaunay triangulations: after every removal the mesh passes
// the exact constrained Delaunay check and equals, as a set of triangles, constrained_delaunay_2d
// of the remaining vertices and constrained edges (SoS ties included: grids, cocircular rings);
// straight constraints and straight boundary pieces merge; corners, ends, junctions and bends
// are refused with the mesh unchanged; the same removals on the input scaled by 2^-600 and 2^600
// give the same triangles.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "generators/mesh_2d/delaunay_refinement_2d.hpp"
#include "generators/sizing/size_function.hpp"
#include "tests/support/canonical_triangles_2d.hpp"
#include "tests/support/test_scale.hpp"
#include "triangulation/checks/check_constrained_2d.hpp"
#include "triangulation/constrained/constrained_2d.hpp"
#include "triangulation/modification/vertex_removal_2d.hpp"

namespace tri = exactmesh::triangulation;
using exactmesh::testing::canonical_triangles;
using tri::RemovalStatus;
using tri::VertIdx;

namespace {

tri::Triangulation2 cdt(const std::vector<double>& xy, const std::vector<VertIdx>& segments,
                        bool remove_exterior = true) {
    tri::Cdt2Options options;
    options.remove_exterior = remove_exterior;
    return tri::constrained_delaunay_2d({xy, segments, {}, {}}, options).mesh;
}

/// The constrained edges of the mesh, each once (a < b).
std::vector<VertIdx> flagged_edges(const tri::Triangulation2& mesh) {
    std::set<std::pair<VertIdx, VertIdx>> edges;
    for (tri::TriIdx t = 0; t < mesh.triangle_count(); ++t) {
        for (int k = 0; k < 3; ++k) {
            if (!mesh.is_constrained(t, k)) continue;
            const VertIdx a = mesh.triangles[3 * t + k], b = mesh.triangles[3 * t + (k + 1) % 3];
            edges.emplace(std::min(a, b), std::max(a, b));
        }
    }
    std::vector<VertIdx> out;
    for (const auto& [a, b] : edges) {
        out.push_back(a);
        out.push_back(b);
    }
    return out;
}

/// The mesh passes the exact check, and equals constrained_delaunay_2d of its used vertices (in
/// their order: the SoS ranks) with its constrained edges as segments.
void expect_constrained_delaunay(const tri::Triangulation2& mesh, bool remove_exterior,
                                 const char* where) {
    SCOPED_TRACE(where);
    const auto pieces = flagged_edges(mesh);
    const auto report = tri::check_constrained_delaunay_2d(mesh, 0, pieces);
    ASSERT_TRUE(report.ok) << report.problem;
    std::vector<VertIdx> reduced(mesh.vertex_count(), tri::kNone);
    for (const VertIdx v : mesh.triangles) reduced[v] = 0;
    std::vector<double> xy;
    VertIdx next = 0;
    for (VertIdx v = 0; v < mesh.vertex_count(); ++v) {
        if (reduced[v] == tri::kNone) continue;
        reduced[v] = next++;
        xy.push_back(mesh.point(v)[0]);
        xy.push_back(mesh.point(v)[1]);
    }
    std::vector<VertIdx> segments;
    for (const VertIdx v : pieces) segments.push_back(reduced[v]);
    std::vector<VertIdx> ours;
    for (const VertIdx v : mesh.triangles) ours.push_back(reduced[v]);
    const tri::Triangulation2 reference = cdt(xy, segments, remove_exterior);
    EXPECT_EQ(reference.vertex_count(), next) << "the reference added vertices";
    EXPECT_EQ(canonical_triangles(ours), canonical_triangles(reference.triangles));
}

/// Everything a refusal must leave as it was.
struct Snapshot {
    std::vector<double> xy;
    std::vector<VertIdx> triangles;
    std::vector<tri::TriIdx> neighbors;
    std::vector<std::uint8_t> constrained;
    explicit Snapshot(const tri::Triangulation2& m)
        : xy(m.xy), triangles(m.triangles), neighbors(m.neighbors), constrained(m.constrained) {}
    bool operator==(const Snapshot&) const = default;
};

/// A unit square whose sides carry `side` points each, `interior` random points inside, and
/// `segments` random segments between interior points (crossings split by the builder).
struct Pslg {
    std::vector<double> xy;
    std::vector<VertIdx> segments;
};

Pslg random_square(std::uint64_t seed, unsigned side, unsigned interior, unsigned segments) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0.05, 0.95);
    Pslg p;
    auto add = [&](double x, double y) {
        p.xy.push_back(x);
        p.xy.push_back(y);
        return static_cast<VertIdx>(p.xy.size() / 2 - 1);
    };
    const VertIdx c0 = add(0, 0), c1 = add(1, 0), c2 = add(1, 1), c3 = add(0, 1);
    for (const auto& [a, b] :
         {std::pair{c0, c1}, std::pair{c1, c2}, std::pair{c2, c3}, std::pair{c3, c0}}) {
        VertIdx previous = a;
        for (unsigned i = 1; i <= side; ++i) {
            const double s = static_cast<double>(i) / (side + 1);
            const double x = p.xy[2 * a] + s * (p.xy[2 * b] - p.xy[2 * a]);
            const double y = p.xy[2 * a + 1] + s * (p.xy[2 * b + 1] - p.xy[2 * a + 1]);
            const VertIdx v = add(x, y);
            p.segments.insert(p.segments.end(), {previous, v});
            previous = v;
        }
        p.segments.insert(p.segments.end(), {previous, b});
    }
    const VertIdx first = static_cast<VertIdx>(p.xy.size() / 2);
    for (unsigned i = 0; i < interior; ++i) add(unit(rng), unit(rng));
    std::uniform_int_distribution<VertIdx> pick(first, first + interior - 1);
    for (unsigned i = 0; i < segments; ++i) {
        const VertIdx a = pick(rng), b = pick(rng);
        if (a != b) p.segments.insert(p.segments.end(), {a, b});
    }
    return p;
}

/// Removes random vertices one by one, checking after each; returns the statuses seen.
std::vector<std::size_t> remove_randomly(tri::Triangulation2& mesh, std::uint64_t seed,
                                         unsigned attempts, bool remove_exterior,
                                         unsigned check_every = 1) {
    std::mt19937_64 rng(seed);
    std::vector<std::size_t> seen(10, 0);
    unsigned removed = 0;
    for (unsigned i = 0; i < attempts; ++i) {
        std::uniform_int_distribution<VertIdx> pick(0, mesh.vertex_count() - 1);
        const VertIdx v = pick(rng);
        const Snapshot before(mesh);
        tri::VertexRemoval2Counters counters;
        const RemovalStatus status = tri::remove_vertex_2d(mesh, v, &counters);
        ++seen[static_cast<std::size_t>(status)];
        if (status != RemovalStatus::Removed) {
            EXPECT_EQ(counters.refused, 1u);
            EXPECT_TRUE(Snapshot(mesh) == before)
                << "refusal (" << tri::removal_status_name(status) << ") changed the mesh";
            continue;
        }
        EXPECT_EQ(counters.removed, 1u);
        // A hole of k triangles is refilled by k - 2, a boundary fan of m by m - 1.
        EXPECT_EQ(mesh.triangle_count() + (counters.boundary_merges != 0 ? 1u : 2u),
                  before.triangles.size() / 3);
        EXPECT_EQ(std::count(mesh.triangles.begin(), mesh.triangles.end(), v), 0);
        if (++removed % check_every == 0) {
            expect_constrained_delaunay(mesh, remove_exterior, "after a removal");
            if (::testing::Test::HasFailure()) return seen;
        }
    }
    expect_constrained_delaunay(mesh, remove_exterior, "at the end");
    return seen;
}

std::size_t count(const std::vector<std::size_t>& seen, RemovalStatus s) {
    return seen[static_cast<std::size_t>(s)];
}

// Removing v is refused with `expected` and leaves the mesh as it was, bit for bit.
void expect_refused(tri::Triangulation2& mesh, VertIdx v, RemovalStatus expected) {
    const Snapshot before(mesh);
    EXPECT_EQ(tri::remove_vertex_2d(mesh, v), expected) << "vertex " << v;
    EXPECT_TRUE(Snapshot(mesh) == before) << "vertex " << v;
}

}  // namespace

TEST(VertexRemoval2d, RandomPslgsStayConstrainedDelaunay) {
    const unsigned runs = std::max(1u, static_cast<unsigned>(6 * exactmesh::testing::test_scale()));
    std::vector<std::size_t> total(10, 0);
    for (unsigned seed = 1; seed <= runs; ++seed) {
        SCOPED_TRACE(seed);
        const Pslg p = random_square(seed, 4, 150, 20);
        tri::Triangulation2 mesh = cdt(p.xy, p.segments);
        expect_constrained_delaunay(mesh, true, "the input");
        const auto seen = remove_randomly(mesh, 100 + seed, 300, true);
        for (std::size_t i = 0; i < seen.size(); ++i) total[i] += seen[i];
        if (HasFailure()) return;
    }
    // Scaled with the runs: the sanitizer pass (EXACTMESH_TEST_SCALE=0.02) makes one.
    EXPECT_GT(count(total, RemovalStatus::Removed), 50u * runs);
    EXPECT_GT(count(total, RemovalStatus::Corner), 0u);
    EXPECT_GT(count(total, RemovalStatus::Unused), 0u);
}

TEST(VertexRemoval2d, GridsWithRandomSegmentsStayConstrainedDelaunay) {
    // Integer grids (cocircular cells everywhere) with random horizontal, vertical and diagonal
    // segments through many grid points (split there by the builder): straight constraints,
    // junctions and bends, all ties by SoS.
    const unsigned runs = std::max(1u, static_cast<unsigned>(4 * exactmesh::testing::test_scale()));
    std::vector<std::size_t> total(10, 0);
    for (unsigned seed = 1; seed <= runs; ++seed) {
        SCOPED_TRACE(seed);
        const int n = 12;
        std::mt19937_64 rng(seed);
        std::uniform_int_distribution<int> coordinate(0, n - 1), direction(0, 3), length(2, 8);
        std::vector<double> xy;
        for (int j = 0; j < n; ++j) {
            for (int i = 0; i < n; ++i) xy.insert(xy.end(), {double(i), double(j)});
        }
        auto id = [&](int i, int j) { return static_cast<VertIdx>(j * n + i); };
        std::vector<VertIdx> segments{id(0, 0),         id(n - 1, 0),     id(n - 1, 0),
                                      id(n - 1, n - 1), id(n - 1, n - 1), id(0, n - 1),
                                      id(0, n - 1),     id(0, 0)};
        for (int s = 0; s < 10; ++s) {
            const int i = coordinate(rng), j = coordinate(rng), d = direction(rng), l = length(rng);
            const int di = d == 1 ? 0 : 1, dj = d == 0 ? 0 : (d == 3 ? -1 : 1);
            const int i2 = std::clamp(i + di * l, 0, n - 1), j2 = std::clamp(j + dj * l, 0, n - 1);
            if (d >= 2 && i2 - i != std::abs(j2 - j)) continue;  // keep diagonals at 45 degrees
            if (i2 == i && j2 == j) continue;
            segments.insert(segments.end(), {id(i, j), id(i2, j2)});
        }
        tri::Triangulation2 mesh = cdt(xy, segments);
        expect_constrained_delaunay(mesh, true, "the grid");
        const auto seen = remove_randomly(mesh, 200 + seed, 200, true);
        for (std::size_t i = 0; i < seen.size(); ++i) total[i] += seen[i];
        if (HasFailure()) return;
    }
    // Scaled with the runs: the sanitizer pass (EXACTMESH_TEST_SCALE=0.02) makes one.
    EXPECT_GT(count(total, RemovalStatus::Removed), 50u * runs);
    EXPECT_GT(count(total, RemovalStatus::ConstraintJunction) +
                  count(total, RemovalStatus::ConstraintBend),
              0u);
}

TEST(VertexRemoval2d, ConvexHullMeshesWithoutConstraints) {
    // remove_exterior false: the hull edges carry no flag; collinear hull vertices still merge.
    const Pslg p = random_square(7, 3, 80, 0);
    tri::Triangulation2 mesh = cdt(p.xy, {}, false);
    EXPECT_TRUE(mesh.constrained.empty() ||
                std::all_of(mesh.constrained.begin(), mesh.constrained.end(),
                            [](std::uint8_t f) { return f == 0; }));
    tri::VertexRemoval2Counters counters;
    std::vector<VertIdx> all;
    for (VertIdx v = 0; v < mesh.vertex_count(); ++v) all.push_back(v);
    std::mt19937_64 rng(3);
    std::shuffle(all.begin(), all.end(), rng);
    all.resize(60);
    const auto result = tri::remove_vertices_2d(mesh, all, 0, &counters);
    EXPECT_GT(result.removed, 40u);
    EXPECT_GT(counters.boundary_merges, 0u);
    EXPECT_EQ(counters.removed, result.removed);
    expect_constrained_delaunay(mesh, false, "after the batch");
}

TEST(VertexRemoval2d, GridTiesFollowTheSymbolicPerturbation) {
    // A 9 x 9 integer grid (every cell cocircular), its boundary and the middle row and column
    // constrained; every vertex asked for in turn.
    const int n = 9;
    std::vector<double> xy;
    std::vector<VertIdx> segments;
    auto id = [&](int i, int j) { return static_cast<VertIdx>(j * n + i); };
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            xy.push_back(i);
            xy.push_back(j);
        }
    }
    for (int i = 0; i + 1 < n; ++i) {
        for (const auto& [a, b] :
             {std::pair{id(i, 0), id(i + 1, 0)}, std::pair{id(i, n - 1), id(i + 1, n - 1)},
              std::pair{id(0, i), id(0, i + 1)}, std::pair{id(n - 1, i), id(n - 1, i + 1)}}) {
            segments.insert(segments.end(), {a, b});
        }
    }
    segments.insert(segments.end(), {id(0, 4), id(8, 4), id(4, 0), id(4, 8)});
    tri::Triangulation2 mesh = cdt(xy, segments);
    expect_constrained_delaunay(mesh, true, "the grid");
    std::vector<RemovalStatus> status;
    for (VertIdx v = 0; v < static_cast<VertIdx>(n * n); ++v) {
        status.push_back(tri::remove_vertex_2d(mesh, v));
        expect_constrained_delaunay(mesh, true, "after a grid removal");
        if (HasFailure()) return;
    }
    EXPECT_EQ(status[id(0, 0)], RemovalStatus::Corner);
    EXPECT_EQ(status[id(4, 4)], RemovalStatus::ConstraintJunction);  // the cross's centre
    EXPECT_EQ(status[id(1, 0)], RemovalStatus::Removed);             // a boundary merge
    EXPECT_EQ(status[id(2, 4)], RemovalStatus::Removed);             // a segment merge
    EXPECT_EQ(status[id(1, 1)], RemovalStatus::Removed);             // interior
}

TEST(VertexRemoval2d, CocircularRingsAroundACentre) {
    // Integer points of the circles of radius 5 and 65 (exactly cocircular), and the centre;
    // removing the centre, then ring vertices, resolves every tie as constrained_delaunay_2d.
    std::vector<double> xy{0, 0};
    for (const int r : {5, 65}) {
        for (int x = -r; x <= r; ++x) {
            for (int y = -r; y <= r; ++y) {
                if (x * x + y * y == r * r) {
                    xy.push_back(x);
                    xy.push_back(y);
                }
            }
        }
    }
    tri::Triangulation2 mesh = cdt(xy, {}, false);
    expect_constrained_delaunay(mesh, false, "the rings");
    ASSERT_EQ(tri::remove_vertex_2d(mesh, 0), RemovalStatus::Removed);
    expect_constrained_delaunay(mesh, false, "without the centre");
    unsigned removed = 0;
    for (VertIdx v = 1; v < mesh.vertex_count(); v += 2) {
        const RemovalStatus s = tri::remove_vertex_2d(mesh, v);
        // Points of the outer ring are hull corners: refused. Inner ones are interior.
        removed += s == RemovalStatus::Removed;
        expect_constrained_delaunay(mesh, false, "after a ring removal");
        if (HasFailure()) return;
    }
    EXPECT_GT(removed, 3u);
}

TEST(VertexRemoval2d, RefusalsLeaveTheMeshUnchanged) {
    //  3 ----------------- 2     segments: the square's sides (4 and 6 on them), 4 - 5 - 6,
    //  |       11          |     5 - 9 (5 a junction of three, 9 an end), 7 - 8 - 10 (a bend at
    //  |   7 ------- 8     |     8, 7 an end), which crosses 4 - 6 at a new vertex 12 = (3, 2);
    //  4 ------- 5 --12--- 6     11 alone inside.
    //  |       /       |   |
    //  |     9        10   |
    //  0 ----------------- 1
    const std::vector<double> xy{0, 0, 4, 0, 4, 4, 0, 4, 0, 2, 2, 2,
                                 4, 2, 1, 3, 3, 3, 1, 1, 3, 1, 2, 3.5};
    const std::vector<VertIdx> segments{0, 1, 1, 6, 6, 2, 2, 3, 3, 4, 4,
                                        0, 4, 5, 5, 6, 5, 9, 7, 8, 8, 10};
    tri::Triangulation2 mesh = cdt(xy, segments);
    expect_constrained_delaunay(mesh, true, "the fixture");
    auto refused = [&](VertIdx v, RemovalStatus expected) { expect_refused(mesh, v, expected); };
    refused(0, RemovalStatus::Corner);
    refused(5, RemovalStatus::ConstraintJunction);  // 4 - 5 - 6 and 5 - 9
    refused(4, RemovalStatus::ConstraintJunction);  // boundary with the inner segment 4 - 5
    refused(9, RemovalStatus::ConstraintEnd);
    refused(7, RemovalStatus::ConstraintEnd);
    refused(8, RemovalStatus::ConstraintBend);
    refused(99, RemovalStatus::OutOfRange);
    const std::vector<VertIdx> ask{11, 11, 8, 3};
    const auto result = tri::remove_vertices_2d(mesh, ask, 12);
    EXPECT_EQ(result.status, (std::vector{RemovalStatus::Protected, RemovalStatus::Protected,
                                          RemovalStatus::Protected, RemovalStatus::Protected}));
    EXPECT_EQ(result.removed, 0u);
    const auto second = tri::remove_vertices_2d(mesh, ask, 0);
    EXPECT_EQ(second.status, (std::vector{RemovalStatus::Removed, RemovalStatus::Unused,
                                          RemovalStatus::ConstraintBend, RemovalStatus::Corner}));
    EXPECT_EQ(second.old_to_new[11], tri::kNone);
    EXPECT_EQ(second.old_to_new[10], 10u);
    EXPECT_EQ(second.old_to_new[12], 11u);
    EXPECT_EQ(mesh.vertex_count(), 12u);
    expect_constrained_delaunay(mesh, true, "after the batch");
}

TEST(VertexRemoval2d, PinchedVertexIsRefused) {
    // Two squares meeting at the corner 2 = (1, 1): its triangles form two fans.
    const std::vector<double> xy{0, 0, 1, 0, 1, 1, 0, 1, 2, 1, 2, 2, 1, 2};
    const std::vector<VertIdx> segments{0, 1, 1, 2, 2, 3, 3, 0, 2, 4, 4, 5, 5, 6, 6, 2};
    tri::Triangulation2 mesh = cdt(xy, segments);
    expect_constrained_delaunay(mesh, true, "the fixture");
    expect_refused(mesh, 2, RemovalStatus::NonManifold);
}

TEST(VertexRemoval2d, SegmentVerticesMerge) {
    // A straight segment split at many exactly collinear points (including points a segment
    // passes through) and a boundary side with vertices on it; removing them all leaves u - w.
    std::vector<double> xy{0, 0, 8, 0, 8, 8, 0, 8};
    std::vector<VertIdx> segments{0, 1, 1, 2, 2, 3, 3, 0};
    for (int i = 1; i < 8; ++i) {  // on the diagonal 0 - 2 and on the bottom side
        xy.insert(xy.end(), {double(i), double(i), double(i), 0.0});
    }
    segments.insert(segments.end(), {0, 2});
    xy.insert(xy.end(), {2, 5, 6, 3, 5, 1.5, 1, 6});
    tri::Triangulation2 mesh = cdt(xy, segments);
    expect_constrained_delaunay(mesh, true, "the fixture");
    std::vector<VertIdx> on_lines;
    for (VertIdx v = 4; v < 18; ++v) on_lines.push_back(v);
    tri::VertexRemoval2Counters counters;
    const auto result = tri::remove_vertices_2d(mesh, on_lines, 0, &counters);
    EXPECT_EQ(result.removed, 14u);
    EXPECT_EQ(counters.segment_merges, 7u);
    EXPECT_EQ(counters.boundary_merges, 7u);
    expect_constrained_delaunay(mesh, true, "merged");
    const auto pieces = flagged_edges(mesh);
    EXPECT_EQ(pieces.size(), 2u * 5);  // four sides and the diagonal
}

TEST(VertexRemoval2d, WithinRoundingMerges) {
    // Bottom side 0 - 4 - 1 with 4 a hair below the line (outside the domain): merged, the domain
    // loses the sliver. Top side 2 - 5 - 3 with 5 a hair below (inside the domain): refused.
    // Inner segment 6 - 7 - 8 with 7 a hair off its line: merged.
    const double hair = std::ldexp(1.0, -50);
    const std::vector<double> xy{0,   0,     1,   0,        1,   1,   0,   1,
                                 0.5, -hair, 0.5, 1 - hair, 0.2, 0.5, 0.5, 0.5 + hair,
                                 0.8, 0.5,   0.3, 0.2,      0.7, 0.8};
    const std::vector<VertIdx> segments{0, 4, 4, 1, 1, 2, 2, 5, 5, 3, 3, 0, 6, 7, 7, 8};
    tri::Triangulation2 mesh = cdt(xy, segments);
    expect_constrained_delaunay(mesh, true, "the fixture");
    expect_refused(mesh, 5, RemovalStatus::ChordBlocked);
    EXPECT_EQ(tri::remove_vertex_2d(mesh, 4), RemovalStatus::Removed);
    expect_constrained_delaunay(mesh, true, "4 merged");
    EXPECT_EQ(tri::remove_vertex_2d(mesh, 7), RemovalStatus::Removed);
    expect_constrained_delaunay(mesh, true, "7 merged");
}

TEST(VertexRemoval2d, InteriorChordThroughAVertexIsRefused) {
    // 6 - 7 - 8 with 7 a hair above the line 6 8, and 9 exactly on that line a hair from 7: the
    // merged edge 6 - 8 would pass through 9.
    const double hair = std::ldexp(1.0, -50);
    const std::vector<double> xy{0,
                                 0,
                                 1,
                                 0,
                                 1,
                                 1,
                                 0,
                                 1,
                                 0.3,
                                 0.2,
                                 0.7,
                                 0.8,
                                 0.2,
                                 0.5,
                                 0.5,
                                 0.5 + hair,
                                 0.8,
                                 0.5,
                                 0.5 + 4 * hair,
                                 0.5};
    const std::vector<VertIdx> segments{0, 1, 1, 2, 2, 3, 3, 0, 6, 7, 7, 8};
    tri::Triangulation2 mesh = cdt(xy, segments);
    expect_constrained_delaunay(mesh, true, "the fixture");
    expect_refused(mesh, 7, RemovalStatus::ChordBlocked);
    EXPECT_EQ(tri::remove_vertex_2d(mesh, 9), RemovalStatus::Removed);
    EXPECT_EQ(tri::remove_vertex_2d(mesh, 7), RemovalStatus::Removed);
    expect_constrained_delaunay(mesh, true, "both gone");
}

TEST(VertexRemoval2d, DerefiningARefinedMeshRemovesEverySteinerPoint) {
    // Delaunay refinement of a square with an inner segment, then every added vertex asked for
    // with the input's protected: the interior ones and those on the sides and the segment go
    // (the inner segment's ends and the corners stay), and the input keeps its numbers.
    const std::vector<double> xy{0, 0, 1, 0, 1, 1, 0, 1, 0.2, 0.3, 0.8, 0.6};
    const std::vector<VertIdx> segments{0, 1, 1, 2, 2, 3, 3, 0, 4, 5};
    exactmesh::generators::RefinementOptions2 options;
    options.size = exactmesh::generators::SizeFunction::uniform(0.08);
    auto refined = exactmesh::generators::delaunay_refinement_2d({xy, segments, {}, {}}, options);
    tri::Triangulation2 mesh = std::move(refined.mesh.mesh);
    const VertIdx inputs = refined.mesh.input_vertex_count;
    expect_constrained_delaunay(mesh, true, "the refined mesh");
    ASSERT_GT(mesh.vertex_count(), 100u);
    std::vector<VertIdx> ask;
    for (VertIdx v = 0; v < mesh.vertex_count(); ++v) ask.push_back(v);
    tri::VertexRemoval2Counters counters;
    const auto result = tri::remove_vertices_2d(mesh, ask, inputs, &counters);
    for (VertIdx v = 0; v < inputs; ++v) {
        EXPECT_EQ(result.status[v], RemovalStatus::Protected);
        EXPECT_EQ(result.old_to_new[v], v);
    }
    EXPECT_EQ(result.removed, ask.size() - inputs);
    EXPECT_EQ(mesh.vertex_count(), inputs);
    EXPECT_GT(counters.segment_merges, 0u);
    EXPECT_GT(counters.boundary_merges, 0u);
    expect_constrained_delaunay(mesh, true, "derefined");
    EXPECT_EQ(canonical_triangles(mesh.triangles),
              canonical_triangles(cdt(xy, segments).triangles));
}

TEST(VertexRemoval2d, ScaleInvariance) {
    const Pslg p = random_square(11, 3, 50, 6);
    std::vector<VertIdx> ask;
    for (VertIdx v = 0; v < p.xy.size() / 2; ++v) ask.push_back(v);
    std::mt19937_64 rng(5);
    std::shuffle(ask.begin(), ask.end(), rng);
    tri::Triangulation2 base = cdt(p.xy, p.segments);
    const auto expected = tri::remove_vertices_2d(base, ask);
    EXPECT_GT(expected.removed, 20u);
    for (const int k : {-600, 600}) {
        SCOPED_TRACE(k);
        std::vector<double> scaled = p.xy;
        for (double& c : scaled) c = std::ldexp(c, k);
        tri::Triangulation2 mesh = cdt(scaled, p.segments);
        const auto result = tri::remove_vertices_2d(mesh, ask);
        EXPECT_EQ(result.status, expected.status);
        EXPECT_EQ(result.old_to_new, expected.old_to_new);
        EXPECT_EQ(canonical_triangles(mesh.triangles), canonical_triangles(base.triangles));
        ASSERT_EQ(mesh.xy.size(), base.xy.size());
        for (std::size_t i = 0; i < mesh.xy.size(); ++i)
            EXPECT_EQ(mesh.xy[i], std::ldexp(base.xy[i], k));
        expect_constrained_delaunay(mesh, true, "scaled");
    }
}

TEST(VertexRemoval2d, CounterTableNamesEveryField) {
    tri::VertexRemoval2Counters counters;
    counters.removed = 3;
    const auto rows = exactmesh::counters_by_name(tri::kVertexRemoval2CounterNames, counters);
    ASSERT_EQ(rows.size(), 8u);
    EXPECT_EQ(rows[0].first, "removed");
    EXPECT_EQ(rows[0].second, 3u);
    EXPECT_STREQ(tri::removal_status_name(RemovalStatus::ChordBlocked),
                 "the merged constraint would cross or touch another vertex of its star");
}

TEST(VertexRemoval2d, CentreOfALargeNearlyCocircularRing) {
    // 1024 points on a circle, rounded (nearly cocircular: the incircle filters fail often), and
    // the centre, whose star is the whole ring: one hole of 1024 triangles.
    std::vector<double> xy{0, 0};
    const int n = 1024;
    for (int i = 0; i < n; ++i) {
        const double a = 2 * std::numbers::pi * i / n;
        xy.insert(xy.end(), {std::cos(a), std::sin(a)});
    }
    tri::Triangulation2 mesh = cdt(xy, {}, false);
    tri::VertexRemoval2Counters counters;
    ASSERT_EQ(tri::remove_vertex_2d(mesh, 0, &counters), RemovalStatus::Removed);
    EXPECT_EQ(counters.star_triangles, static_cast<std::uint64_t>(n));
    EXPECT_EQ(mesh.triangle_count(), static_cast<std::uint32_t>(n - 2));
    expect_constrained_delaunay(mesh, false, "without the centre");
}
