// SPDX-License-Identifier: MIT
// Tests of triangulation/mesh/locate_2d.hpp (issue 12): the shared bucket-grid locator answers the
// lowest-numbered triangle containing a point (closed), as a scan of every triangle does, on
// vertices, on edges, inside, outside and on a fan of slivers (where the grid coarsens).
#include "triangulation/mesh/locate_2d.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "predicates/orient2d.hpp"
#include "triangulation/constrained/constrained_2d.hpp"

namespace tri = exactmesh::triangulation;
namespace pred = exactmesh::predicates;

namespace {

/// The lowest-numbered triangle containing (x, y) (closed), by a scan of every triangle.
tri::TriIdx scan(const tri::Triangulation2& mesh, double x, double y) {
    const double p[2] = {x, y};
    for (tri::TriIdx t = 0; t < mesh.triangle_count(); ++t) {
        const double* a = mesh.point(mesh.triangles[3 * t]);
        const double* b = mesh.point(mesh.triangles[3 * t + 1]);
        const double* c = mesh.point(mesh.triangles[3 * t + 2]);
        if (pred::orient2d(a, b, p) != pred::Sign::Negative &&
            pred::orient2d(b, c, p) != pred::Sign::Negative &&
            pred::orient2d(c, a, p) != pred::Sign::Negative)
            return t;
    }
    return tri::kNone;
}

/// Every vertex, every edge's midpoint (rounded: on the edge or beside it), random points in
/// and around the mesh's box: the locator's answer is the scan's.
void expect_locator_is_scan(const tri::Triangulation2& mesh, double per_cell) {
    const tri::TriangleLocator2 locator(mesh, per_cell);
    std::size_t found = 0, on_vertices = 0;
    auto expect = [&](double x, double y) {
        const tri::TriIdx t = locator.locate(mesh, x, y);
        ASSERT_EQ(t, scan(mesh, x, y)) << "at (" << x << ", " << y << ")";
        found += t != tri::kNone;
    };
    for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
        expect(mesh.xy[2 * v], mesh.xy[2 * v + 1]);
        ++on_vertices;
    }
    for (std::size_t e = 0; e < mesh.triangles.size(); ++e) {
        const double* a = mesh.point(mesh.triangles[e]);
        const double* b = mesh.point(mesh.triangles[e % 3 == 2 ? e - 2 : e + 1]);
        expect(0.5 * a[0] + 0.5 * b[0], 0.5 * a[1] + 0.5 * b[1]);
    }
    double x0 = mesh.xy[0], x1 = x0, y0 = mesh.xy[1], y1 = y0;
    for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
        x0 = std::min(x0, mesh.xy[2 * v]), x1 = std::max(x1, mesh.xy[2 * v]);
        y0 = std::min(y0, mesh.xy[2 * v + 1]), y1 = std::max(y1, mesh.xy[2 * v + 1]);
    }
    std::mt19937_64 random(12);
    std::uniform_real_distribution<double> ux(x0 - 0.1 * (x1 - x0), x1 + 0.1 * (x1 - x0));
    std::uniform_real_distribution<double> uy(y0 - 0.1 * (y1 - y0), y1 + 0.1 * (y1 - y0));
    for (int k = 0; k < 2000; ++k) expect(ux(random), uy(random));
    EXPECT_GT(found, on_vertices);  // the vertices, and many points inside
}

}  // namespace

TEST(Locate2, AnswersTheLowestTriangleContainingThePoint) {
    // A square with a hole, its CDT with the exterior and the hole removed.
    const std::vector<double> xy{0, 0, 4, 0, 4, 4, 0, 4, 1, 1, 3, 1, 3, 3, 1, 3, 2, 0.5};
    const std::vector<tri::VertIdx> segments{0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 5, 6, 6, 7, 7, 4};
    const std::vector<double> holes{2, 2};
    const tri::Cdt2Result cdt = tri::constrained_delaunay_2d({xy, segments, holes, {}});
    ASSERT_GT(cdt.mesh.triangle_count(), 8u);
    for (const double per_cell : {0.5, 1.0, 4.0}) expect_locator_is_scan(cdt.mesh, per_cell);
    const tri::TriangleLocator2 locator(cdt.mesh);
    EXPECT_EQ(locator.locate(cdt.mesh, 2, 2), tri::kNone);  // in the hole
    EXPECT_EQ(locator.locate(cdt.mesh, 5, 1), tri::kNone);  // outside the box
    EXPECT_EQ(locator.locate(cdt.mesh, std::nan(""), 1), tri::kNone);
    EXPECT_EQ(locator.locate(cdt.mesh, 1, std::numeric_limits<double>::infinity()), tri::kNone);
}

TEST(Locate2, AFanOfSliversCoarsensTheGridAndFindsTheSameTriangles) {
    // 400 slivers from (0, 0) to a long arc: each box meets many cells of the fine grid.
    tri::Triangulation2 fan;
    fan.xy = {0, 0};
    const int n = 400;
    for (int k = 0; k <= n; ++k) {
        const double angle = 0.5 * k / n;
        fan.xy.insert(fan.xy.end(), {1000 * std::cos(angle), 1000 * std::sin(angle)});
    }
    for (tri::VertIdx k = 1; k <= static_cast<tri::VertIdx>(n); ++k) {
        fan.triangles.insert(fan.triangles.end(), {0, k, k + 1});
    }
    const tri::BucketGrid2 grid(fan.xy, fan.triangles, fan.triangles, 3, 1.0);
    // Coarsened: at most 16 list entries per item (plus 4096).
    std::size_t entries = 0;
    for (std::uint32_t r = 0; r < grid.rows(); ++r)
        for (std::uint32_t c = 0; c < grid.columns(); ++c) entries += grid.cell(c, r).size();
    EXPECT_LE(entries, 16u * n + 4096);
    EXPECT_GE(entries, static_cast<std::size_t>(n));
    expect_locator_is_scan(fan, 1.0);
}

TEST(Locate2, EveryCellListsTheItemsWhoseBoxMeetsIt) {
    const std::vector<double> xy{0, 0, 10, 0, 10, 10, 0, 10, 3, 7};
    const std::vector<tri::VertIdx> box{0, 1, 2, 3};
    const std::vector<tri::VertIdx> edges{0, 4, 4, 2, 1, 3};
    const tri::BucketGrid2 grid(xy, box, edges, 2, 0.25);
    ASSERT_FALSE(grid.empty());
    EXPECT_TRUE(grid.in_box(10, 10));
    EXPECT_FALSE(grid.in_box(10, 10.000001));
    for (std::uint32_t r = 0; r < grid.rows(); ++r) {
        for (std::uint32_t c = 0; c < grid.columns(); ++c) {
            for (std::uint32_t e = 0; e < 3; ++e) {
                const double* a = &xy[2 * edges[2 * e]];
                const double* b = &xy[2 * edges[2 * e + 1]];
                const bool meets = std::min(grid.column(a[0]), grid.column(b[0])) <= c &&
                                   c <= std::max(grid.column(a[0]), grid.column(b[0])) &&
                                   std::min(grid.row(a[1]), grid.row(b[1])) <= r &&
                                   r <= std::max(grid.row(a[1]), grid.row(b[1]));
                const auto list = grid.cell(c, r);
                EXPECT_EQ(std::find(list.begin(), list.end(), e) != list.end(), meets)
                    << "cell " << c << ", " << r << ", edge " << e;
            }
        }
    }
}
