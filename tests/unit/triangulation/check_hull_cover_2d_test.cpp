// SPDX-License-Identifier: MIT
// check_hull_cover_2d: a constrained triangulation over the convex hull less its holes (what
// `cdt --convex-hull` makes with hole points) passes; a hole region kept, a region removed with
// no hole point in it, and a hole point on a vertex where constrained edges end fail; a hole
// point on a free vertex passes. At 2^0 and 2^+-600.
#include "triangulation/constrained/check_hull_cover_2d.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "triangulation/constrained/constrained_2d.hpp"

namespace tri = exactmesh::triangulation;

namespace {

/// A square (0, 4)^2 around a square (1, 3)^2, a small triangle loop near a corner of the
/// ring between them, and a free vertex at (3.5, 3.5); coordinates times 2^exponent.
struct Domain {
    std::vector<double> xy;
    std::vector<tri::VertIdx> segments;
    int exponent = 0;

    explicit Domain(int e) : exponent(e) {
        const double corners[] = {0, 0, 4, 0, 4,    4,    0,    4,    1,   1,    3,   1,
                                  3, 3, 1, 3, 0.25, 0.25, 0.75, 0.25, 0.5, 0.75, 3.5, 3.5};
        for (const double c : corners) xy.push_back(std::ldexp(c, e));
        segments = {0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 5, 6, 6, 7, 7, 4, 8, 9, 9, 10, 10, 8};
    }
    std::vector<double> points(std::vector<double> at) const {
        for (double& c : at) c = std::ldexp(c, exponent);
        return at;
    }
    /// The triangulation over the hull less the triangles the holes reach.
    tri::Triangulation2 mesh(const std::vector<double>& holes) const {
        tri::Cdt2Options options;
        options.remove_exterior = false;
        return tri::constrained_delaunay_2d(tri::Pslg{xy, segments, holes, {}}, options).mesh;
    }
};

/// The check of `mesh` against `holes` fails and says `words`.
void expect_failure(const tri::Triangulation2& mesh, const std::vector<double>& holes,
                    const std::string& words) {
    const tri::CheckReport report = tri::check_hull_cover_2d(mesh, holes);
    EXPECT_FALSE(report.ok);
    EXPECT_NE(report.problem.find(words), std::string::npos) << report.problem;
}

}  // namespace

TEST(Triangulation_CheckHullCover2, TheHullLessTheHolesPassesAndEveryOtherRegionFails) {
    for (const int e : {0, 600, -600}) {
        SCOPED_TRACE(e);
        const Domain d(e);
        const std::vector<double> hole = d.points({2, 2});
        // What `cdt --convex-hull` makes: passes.
        EXPECT_EQ(tri::check_hull_cover_2d(d.mesh(hole), hole).problem, "");
        // The hole region kept: its four edges bound the hull less the holes only.
        expect_failure(d.mesh({}), hole, "bounds the convex hull less the holes but not the mesh");
        // The small loop removed too, with no hole point of the check's inside it.
        expect_failure(d.mesh(d.points({2, 2, 0.5, 0.4})), hole,
                       "bounds the mesh but not the convex hull less the holes");
        // A hole point on vertex 4, where two constrained edges end, or on a constrained edge:
        // no side.
        expect_failure(d.mesh(hole), d.points({2, 2, 1, 1}),
                       "is vertex 4, where a constrained edge ends");
        expect_failure(d.mesh(hole), d.points({2, 2, 2, 1}), "lies on the constrained edge (4, 5)");
        // On the free vertex 11: one side, the ring removed with the hole.
        const std::vector<double> ring = d.points({2, 2, 3.5, 3.5});
        EXPECT_EQ(tri::check_hull_cover_2d(d.mesh(ring), ring).problem, "");
        // A hole point outside the hull is ignored, as the producer ignores it.
        const std::vector<double> outside = d.points({2, 2, 9, 9});
        EXPECT_EQ(tri::check_hull_cover_2d(d.mesh(outside), outside).problem, "");
    }
}
