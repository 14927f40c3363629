// SPDX-License-Identifier: MIT
// The discretized domain boundary: pieces no longer than a uniform size, the front oriented with
// the domain on its left (exact point-in-domain tests on either side of every front edge), slits
// in both directions, holes outside, the CDT's pieces kept when the size is unbounded, curved
// sample domains; domain_mesh_result assembles a valid mesh; bad input raises InputError.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "generators/domain_boundary_2d.hpp"
#include "generators/domain_mesh_2d.hpp"
#include "generators/sample_domains.hpp"
#include "predicates/errors.hpp"
#include "triangulation/check_conforming_2d.hpp"

namespace gen = exactmesh::generators;
namespace tri = exactmesh::triangulation;

namespace {

struct Input {
    std::vector<double> xy;
    std::vector<std::uint32_t> segments;
    std::vector<double> holes;
    tri::Pslg pslg() const { return {xy, segments, holes, {}}; }
};

/// The unit square with a square hole [0.4, 0.6]^2 and a slit from (0.1, 0.5) to (0.3, 0.5).
Input square_with_hole_and_slit() {
    Input in;
    in.xy = {0, 0, 1, 0, 1, 1, 0, 1, 0.4, 0.4, 0.6, 0.4, 0.6, 0.6, 0.4, 0.6, 0.1, 0.5, 0.3, 0.5};
    in.segments = {0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 5, 6, 6, 7, 7, 4, 8, 9};
    in.holes = {0.5, 0.5};
    return in;
}

double length(const gen::DomainBoundary2& b, tri::VertIdx u, tri::VertIdx v) {
    return std::hypot(b.xy[2 * v] - b.xy[2 * u], b.xy[2 * v + 1] - b.xy[2 * u + 1]);
}

TEST(DomainBoundary2, PiecesFollowAUniformSizeAndTheFrontHasTheDomainOnItsLeft) {
    const Input in = square_with_hole_and_slit();
    const double h = 0.07;
    const gen::DomainBoundary2 b =
        gen::discretize_domain_boundary(in.pslg(), gen::SizeFunction::uniform(h));
    EXPECT_EQ(b.input_vertex_count, 10u);
    ASSERT_EQ(b.pieces.size() / 2, b.piece_segment.size());
    ASSERT_EQ(b.front.size() / 2, b.front_segment.size());
    // Outer sides (length 1): 15 pieces each (1 / 0.07 = 14.3); hole sides (0.2): 3; slit (0.2): 3.
    EXPECT_EQ(b.pieces.size() / 2, 4u * 15 + 4 * 3 + 3);
    // Every piece is the size or shorter, and no shorter than half of it here.
    for (std::size_t p = 0; p < b.piece_segment.size(); ++p) {
        const double l = length(b, b.pieces[2 * p], b.pieces[2 * p + 1]);
        EXPECT_LE(l, h * (1 + 1e-12));
        EXPECT_GE(l, 0.5 * h);
    }
    // Front: outer and hole pieces once, slit pieces twice.
    EXPECT_EQ(b.front.size() / 2, 4u * 15 + 4 * 3 + 2 * 3);
    std::size_t slit_edges = 0;
    for (std::size_t e = 0; e < b.front_segment.size(); ++e) {
        const double* p = &b.xy[2 * b.front[2 * e]];
        const double* q = &b.xy[2 * b.front[2 * e + 1]];
        const double mx = 0.5 * (p[0] + q[0]), my = 0.5 * (p[1] + q[1]);
        const double nx = -(q[1] - p[1]), ny = q[0] - p[0];  // left normal, |n| = piece length
        EXPECT_TRUE(gen::in_domain(b, mx + 0.1 * nx, my + 0.1 * ny)) << "front edge " << e;
        if (b.front_segment[e] == 8) {
            ++slit_edges;
            EXPECT_TRUE(gen::in_domain(b, mx - 0.1 * nx, my - 0.1 * ny));
        } else {
            EXPECT_FALSE(gen::in_domain(b, mx - 0.1 * nx, my - 0.1 * ny)) << "front edge " << e;
        }
    }
    EXPECT_EQ(slit_edges, 6u);
    EXPECT_FALSE(gen::in_domain(b, 0.5, 0.5));  // the hole
    EXPECT_FALSE(gen::in_domain(b, 1.5, 0.5));  // outside
    EXPECT_TRUE(gen::in_domain(b, 0, 0));       // closed
    EXPECT_TRUE(gen::in_domain(b, 0.2, 0.2));
}

TEST(DomainBoundary2, GradedSizesGiveShorterPiecesWhereTheSizeIsSmall) {
    const Input in = square_with_hole_and_slit();
    const auto size = gen::SizeFunction::sources({{0, 0, 0.01, 0.1, 1}}, {}, 0.2);
    const gen::DomainBoundary2 b = gen::discretize_domain_boundary(in.pslg(), size);
    for (std::size_t p = 0; p < b.piece_segment.size(); ++p) {
        const tri::VertIdx u = b.pieces[2 * p], v = b.pieces[2 * p + 1];
        const double mx = 0.5 * (b.xy[2 * u] + b.xy[2 * v]),
                     my = 0.5 * (b.xy[2 * u + 1] + b.xy[2 * v + 1]);
        // Integral of ds / s at most 1 per piece: the length is at most the largest size along it
        // (the size grows by at most the piece's length times its gradient, 0.1 here).
        EXPECT_LE(length(b, u, v), size(mx, my) * 1.2) << "piece " << p;
    }
    // Near the source corner the pieces are about 0.01.
    double shortest = 1;
    for (std::size_t p = 0; p < b.piece_segment.size(); ++p)
        shortest = std::min(shortest, length(b, b.pieces[2 * p], b.pieces[2 * p + 1]));
    EXPECT_LT(shortest, 0.015);
}

TEST(DomainBoundary2, UnboundedSizeKeepsTheCdtPiecesAndTheResultIsAValidMesh) {
    const Input in = square_with_hole_and_slit();
    const gen::DomainBoundary2 b = gen::discretize_domain_boundary(in.pslg(), gen::SizeFunction());
    EXPECT_EQ(b.xy, b.cdt.mesh.xy);
    EXPECT_EQ(b.pieces, b.cdt.pieces);
    const tri::Cdt2Result r = gen::domain_mesh_result(b, b.xy, b.cdt.mesh.triangles);
    EXPECT_EQ(r.mesh.neighbors, b.cdt.mesh.neighbors);
    EXPECT_EQ(r.mesh.constrained, b.cdt.mesh.constrained);
    const auto report =
        tri::check_conforming_mesh_2d(r.mesh, r.input_vertex_count, in.segments, r.pieces);
    EXPECT_TRUE(report.ok) << report.problem;
    // A repeated directed edge is an internal error.
    std::vector<tri::VertIdx> twice = b.cdt.mesh.triangles;
    twice.insert(twice.end(), twice.begin(), twice.begin() + 3);
    EXPECT_THROW(gen::domain_mesh_result(b, b.xy, twice), exactmesh::InternalError);
}

TEST(DomainBoundary2, SampleDomainsKeepCurvedPointsAndCrossingSegmentsAreSplit) {
    for (const gen::SampleDomain d : gen::kAllSampleDomains) {
        const gen::DomainPslg domain = gen::sample_domain(d);
        const tri::Pslg pslg{domain.xy, domain.segments, domain.holes, {}};
        const gen::DomainBoundary2 b =
            gen::discretize_domain_boundary(pslg, gen::sample_domain_size(d));
        // The curve points are input vertices: kept with their numbers and coordinates.
        for (std::size_t i = 0; i < domain.xy.size(); ++i) EXPECT_EQ(b.xy[i], domain.xy[i]);
        EXPECT_GE(b.front.size(), domain.segments.size());
    }
    // Two crossing segments inside a square: split at their crossing (a warning), front both ways.
    Input in;
    in.xy = {0, 0, 4, 0, 4, 4, 0, 4, 1, 1, 3, 3, 1, 3, 3, 1};
    in.segments = {0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 6, 7};
    const gen::DomainBoundary2 b =
        gen::discretize_domain_boundary(in.pslg(), gen::SizeFunction::uniform(0.5));
    EXPECT_FALSE(b.cdt.warnings.empty());
    EXPECT_GT(b.xy.size() / 2, 8u);
}

TEST(DomainBoundary2, BadInputIsAnInputError) {
    Input nan = square_with_hole_and_slit();
    nan.xy[3] = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(gen::discretize_domain_boundary(nan.pslg(), gen::SizeFunction::uniform(0.1)),
                 exactmesh::InputError);
    Input open;  // a polyline encloses nothing
    open.xy = {0, 0, 1, 0, 1, 1};
    open.segments = {0, 1, 1, 2};
    EXPECT_THROW(gen::discretize_domain_boundary(open.pslg(), gen::SizeFunction::uniform(0.1)),
                 exactmesh::InputError);
    // A size asking for more than 2^30 pieces.
    const Input square = square_with_hole_and_slit();
    EXPECT_THROW(gen::discretize_domain_boundary(square.pslg(), gen::SizeFunction::uniform(1e-12)),
                 exactmesh::InputError);
}

}  // namespace

TEST(DomainBoundary2, SizeFromBoundaryFollowsTheInputSpacing) {
    // The unit square with its bottom side in ten segments of 0.1: the bottom's inner vertices
    // get 0.1, its corners the mean of 0.1 and 1, the top corners 1; linear in between.
    Input in;
    for (int i = 0; i <= 10; ++i) in.xy.insert(in.xy.end(), {0.1 * i, 0.0});
    in.xy.insert(in.xy.end(), {1, 1, 0, 1});
    for (std::uint32_t i = 0; i < 10; ++i) in.segments.insert(in.segments.end(), {i, i + 1});
    in.segments.insert(in.segments.end(), {10, 11, 11, 12, 12, 0});
    const gen::SizeFunction size = gen::size_from_boundary(in.pslg());
    ASSERT_TRUE(size.bounded());
    EXPECT_NEAR(size(0.5, 0), 0.1, 1e-12);
    EXPECT_NEAR(size(0.25, 0), 0.1, 1e-12);
    EXPECT_NEAR(size(0, 0), 0.55, 1e-12);
    EXPECT_NEAR(size(1, 1), 1.0, 1e-12);
    EXPECT_NEAR(size(0.5, 1), 1.0, 1e-12);
    // Inside, between the two: no smaller than the bottom's, no larger than the top's.
    for (double y = 0.05; y < 1; y += 0.1) {
        const double s = size(0.5, y);
        EXPECT_GE(s, 0.1 - 1e-12);
        EXPECT_LE(s, 1.0 + 1e-12);
    }
    // No enclosed region: an InputError.
    Input open;
    open.xy = {0, 0, 1, 0, 1, 1};
    open.segments = {0, 1, 1, 2};
    EXPECT_THROW(gen::size_from_boundary(open.pslg()), exactmesh::InputError);
}
