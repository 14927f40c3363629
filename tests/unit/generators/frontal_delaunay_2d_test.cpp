// SPDX-License-Identifier: MIT
// Frontal Delaunay (Rebay): every output is exact constrained Delaunay with every segment a
// chain of pieces, has no triangle outside the domain and is closed by pieces; input vertices
// keep their numbers; the counters add up (every output triangle accepted by the radius
// criterion or after a rejected point); edges stay within a measured bound of the size; the
// mean of the triangles' smallest angles beats Delaunay refinement's (20.7 degrees, same size)
// on every sample domain; degenerate inputs (points on segments, duplicates, crossing segments,
// a tiny feature, a sharp angle, a triangle, a slit, the random PSLG distributions) give valid
// meshes; points outside, encroaching or too close are rejected and their triangles accepted;
// bad input and an exhausted budget raise the documented errors.
#include "generators/mesh_2d/frontal_delaunay_2d.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "base/errors.hpp"
#include "generators/boundary/sample_domains.hpp"
#include "generators/inputs/pslg_inputs.hpp"
#include "generators/mesh_2d/delaunay_refinement_2d.hpp"
#include "generators/mesh_2d/mesh_generators_2d.hpp"
#include "generators/mesh_2d/quality_2d.hpp"
#include "tests/support/degenerate_pslgs_2d.hpp"
#include "tests/support/generated_mesh_2d.hpp"
#include "tests/support/mesh_checks_2d.hpp"
#include "tests/support/pslg_fixtures_2d.hpp"
#include "triangulation/checks/check_conforming_2d.hpp"

namespace em = exactmesh;
namespace gen = exactmesh::generators;
namespace tri = exactmesh::triangulation;

namespace {

using exactmesh::testing::from_domain;
using exactmesh::testing::Input;
using exactmesh::testing::polygon;

using Meshed = em::testing::GeneratedMesh2<gen::FrontalDelaunayResult2>;

/// Size conformity measured over every test here: the longest edge over the size at its
/// midpoint stays below this (boundary pieces are at most 1 by the discretization; interior
/// edges of accepted triangles are at most 2 R <= 2 sqrt(3/2) / sqrt 3 = sqrt 2 times the size
/// at the centroid; measured at most 1.40 on the sample domains, 1.41 with the sources).
constexpr double kSizeRatioBound = 1.5;

Meshed mesh(const Input& in, const gen::SizeFunction& size, bool closed_loops = true) {
    gen::FrontalDelaunayOptions2 options;
    options.size = size;
    return em::testing::check_generated_mesh(gen::frontal_delaunay_2d(in.pslg(), options), in, size,
                                             closed_loops, true);
}

/// The counters describe the mesh: each output triangle accepted by the criterion or forced,
/// every vertex the input's, the boundary's or an inserted one; input vertices unmoved.
void expect_consistent(const Input& in, const Meshed& r, const std::string& name) {
    const auto& c = r.result.counters;
    const auto& m = r.result.mesh;
    EXPECT_EQ(c.accepted_triangles + c.forced_triangles, m.mesh.triangle_count()) << name;
    EXPECT_LE(c.forced_triangles, c.forced_accepts) << name;
    EXPECT_EQ(m.mesh.xy.size() / 2,
              in.xy.size() / 2 + m.counters.intersections + c.boundary_points + c.points_inserted)
        << name;
    EXPECT_EQ(m.input_vertex_count, in.xy.size() / 2) << name;
    for (std::size_t i = 0; i < in.xy.size(); ++i) EXPECT_EQ(m.mesh.xy[i], in.xy[i]) << name;
    EXPECT_EQ(m.piece_segment.size() * 2, m.pieces.size()) << name;
    for (const std::uint32_t s : m.piece_segment) EXPECT_LT(s, in.segments.size() / 2) << name;
}

}  // namespace

TEST(Generators_FrontalDelaunay,
     SampleDomainsAreConstrainedDelaunayWithBetterMeanAngleThanRefinement) {
    for (const gen::SampleDomain d : gen::kAllSampleDomains) {
        const gen::SizeFunction size = gen::sample_domain_size(d);
        const Input in = from_domain(gen::sample_domain(d, size));
        const std::string name(gen::sample_domain_name(d));
        const Meshed r = mesh(in, size);
        ASSERT_TRUE(r.check.ok) << name << ": " << r.check.problem;
        expect_consistent(in, r, name);
        EXPECT_GT(r.result.mesh.mesh.triangle_count(), 1000u) << name;
        EXPECT_GT(r.result.counters.points_inserted, 0u) << name;
        EXPECT_LE(r.check.max_size_ratio, kSizeRatioBound) << name;
        // The quality goal: a higher mean smallest angle than Delaunay refinement at
        // its guaranteed bound with the same size function.
        gen::RefinementOptions2 refinement;
        refinement.size = size;
        refinement.min_angle = gen::kGuaranteedMinAngle;
        const auto refined = gen::delaunay_refinement_2d(in.pslg(), refinement);
        const gen::QualityReport2 q =
            gen::quality_report_2d(refined.mesh.mesh.xy, refined.mesh.mesh.triangles, size);
        EXPECT_GT(r.quality.mean_min_angle, q.mean_min_angle) << name;
        std::printf(
            "%s: frontal %llu triangles, mean min angle %.2f, min %.2f, max size ratio %.3f, "
            "forced %llu (accepts %llu: encroach %llu, outside %llu, close %llu); refinement %llu "
            "triangles, mean min angle %.2f, min %.2f, max size ratio %.3f\n",
            name.c_str(), static_cast<unsigned long long>(r.quality.triangles),
            r.quality.mean_min_angle, r.quality.min_angle, r.quality.size_ratio_max,
            static_cast<unsigned long long>(r.result.counters.forced_triangles),
            static_cast<unsigned long long>(r.result.counters.forced_accepts),
            static_cast<unsigned long long>(r.result.counters.rejected_encroach),
            static_cast<unsigned long long>(r.result.counters.rejected_outside),
            static_cast<unsigned long long>(r.result.counters.rejected_too_close),
            static_cast<unsigned long long>(q.triangles), q.mean_min_angle, q.min_angle,
            q.size_ratio_max);
    }
}

TEST(Generators_FrontalDelaunay, SquareWithAHoleAndASlit) {
    // The unit square, a square hole, and a slit (a dangling segment with the domain on both
    // sides) from the boundary into the interior.
    Input in = polygon({0, 0, 1, 0, 1, 1, 0, 1});
    in.xy.insert(in.xy.end(), {0.6, 0.6, 0.8, 0.6, 0.8, 0.8, 0.6, 0.8, 0.3, 0.0, 0.3, 0.45});
    in.segments.insert(in.segments.end(), {4, 5, 5, 6, 6, 7, 7, 4, 8, 9});
    in.holes = {0.7, 0.7};
    for (const double h : {0.1, 0.03}) {
        const Meshed r = mesh(in, gen::SizeFunction::uniform(h), false);
        ASSERT_TRUE(r.check.ok) << h << ": " << r.check.problem;
        expect_consistent(in, r, "hole and slit");
        EXPECT_LE(r.check.max_size_ratio, kSizeRatioBound) << h;
        // No triangle inside the hole (its centroid by the even-odd rule over the hole alone).
        const auto& m = r.result.mesh.mesh;
        for (tri::TriIdx t = 0; t < m.triangle_count(); ++t) {
            double cx = 0, cy = 0;
            for (unsigned k = 0; k < 3; ++k) {
                cx += m.point(m.triangles[3 * t + k])[0] / 3;
                cy += m.point(m.triangles[3 * t + k])[1] / 3;
            }
            EXPECT_FALSE(cx > 0.6 && cx < 0.8 && cy > 0.6 && cy < 0.8) << t;
        }
        // The slit is a chain of pieces with triangles on both sides of each.
        std::uint64_t slit_pieces = 0;
        for (std::size_t p = 0; p < r.result.mesh.piece_segment.size(); ++p) {
            if (r.result.mesh.piece_segment[p] == 8) ++slit_pieces;
        }
        EXPECT_GE(slit_pieces, static_cast<std::uint64_t>(0.45 / h)) << h;
    }
}

TEST(Generators_FrontalDelaunay, GradedPointAndLineSources) {
    // A point source (size 0.002 at (0.5, 0.5), growing linearly over 0.05) and, separately, a
    // line source (0.004 along a diagonal, growing as d^1.5 over 0.1), both capped at 0.1.
    const Input in = polygon({0, 0, 2, 0, 2, 1, 0, 1});
    struct Case {
        const char* name;
        gen::SizeFunction size;
        double fx, fy;  // the finest point
        double cx, cy;  // a far corner, where the size is above 0.06
    };
    const Case cases[] = {
        {"point source", gen::SizeFunction::sources({{0.5, 0.5, 0.002, 0.05, 1.0}}, {}, 0.1), 0.5,
         0.5, 2, 0},
        {"line source",
         gen::SizeFunction::sources({}, {{1.2, 0.2, 1.8, 0.8, 0.004, 0.1, 1.5}}, 0.1), 1.5, 0.5, 0,
         1},
    };
    for (const Case& c : cases) {
        const Meshed r = mesh(in, c.size);
        ASSERT_TRUE(r.check.ok) << c.name << ": " << r.check.problem;
        expect_consistent(in, r, c.name);
        EXPECT_LE(r.check.max_size_ratio, kSizeRatioBound) << c.name;
        // Grading: edges at the source are short, edges in the far corner at least a third of
        // the size there.
        const auto& m = r.result.mesh.mesh;
        double near = 0, far = INFINITY;
        std::uint64_t near_edges = 0, far_edges = 0;
        for (tri::TriIdx t = 0; t < m.triangle_count(); ++t) {
            for (unsigned k = 0; k < 3; ++k) {
                const double* a = m.point(m.triangles[3 * t + k]);
                const double* b = m.point(m.triangles[3 * t + (k + 1) % 3]);
                const double length = std::hypot(b[0] - a[0], b[1] - a[1]);
                if (std::hypot(a[0] - c.fx, a[1] - c.fy) < 0.01) {
                    near = std::max(near, length);
                    ++near_edges;
                }
                if (std::hypot(a[0] - c.cx, a[1] - c.cy) < 0.1) {
                    far = std::min(far, length);
                    ++far_edges;
                }
            }
        }
        EXPECT_GT(near_edges, 10u) << c.name;
        EXPECT_GT(far_edges, 3u) << c.name;
        EXPECT_LT(near, 0.02) << c.name;
        EXPECT_GT(far, 0.06 / 3) << c.name;
        EXPECT_GT(r.quality.mean_min_angle, 45.0) << c.name;
        std::printf(
            "%s: %llu triangles, mean min angle %.2f, min %.2f, size ratio max %.3f median %.3f\n",
            c.name, static_cast<unsigned long long>(r.quality.triangles), r.quality.mean_min_angle,
            r.quality.min_angle, r.quality.size_ratio_max, r.quality.size_ratio_median);
    }
}

TEST(Generators_FrontalDelaunay, DegenerateInputs) {
    struct Case {
        const char* name;
        Input in;
        bool closed_loops = true;  // false: inner segments that close nothing (no even-odd test)
    };
    std::vector<Case> cases;
    cases.push_back({"collinear vertices on segments", em::testing::square_with_points_on_sides()});
    cases.push_back({"tiny hole", em::testing::square_with_tiny_hole()});
    // Duplicate vertices, a duplicated segment and one given through the copies.
    cases.push_back({"duplicates", em::testing::square_with_duplicates()});
    // Two crossing inner segments (split at their correctly rounded intersection).
    {
        Input in = polygon({0, 0, 1, 0, 1, 1, 0, 1});
        in.xy.insert(in.xy.end(), {0.2, 0.3, 0.8, 0.7, 0.2, 0.7, 0.8, 0.3});
        in.segments.insert(in.segments.end(), {4, 5, 6, 7});
        cases.push_back({"crossing segments", in, false});
    }
    // A sharp input angle: a 5-degree wedge.
    {
        const double angle = 5.0 * 3.14159265358979323846 / 180;
        cases.push_back({"sharp angle", polygon({0, 0, 1, 0, std::cos(angle), std::sin(angle)})});
    }
    cases.push_back({"triangle", polygon({0, 0, 1, 0, 0.3, 0.8})});
    // A vertex a few ulps off a skew segment's line.
    cases.push_back({"vertex ulps off a segment", em::testing::vertex_ulps_off_a_segment()});
    for (const Case& c : cases) {
        for (const double h : {0.2, 0.05}) {
            const Meshed r = mesh(c.in, gen::SizeFunction::uniform(h), c.closed_loops);
            ASSERT_TRUE(r.check.ok) << c.name << " at " << h << ": " << r.check.problem;
            expect_consistent(c.in, r, c.name);
            EXPECT_LE(r.check.max_size_ratio, kSizeRatioBound) << c.name << " at " << h;
            if (!c.closed_loops) {
                EXPECT_EQ(r.result.mesh.counters.intersections, 1u) << c.name;
                EXPECT_FALSE(r.result.mesh.warnings.empty()) << c.name;
            }
        }
    }
}

TEST(Generators_FrontalDelaunay, PointsOutsideAFlatTriangleAreRejectedAndTheirTrianglesAccepted) {
    // A triangle 50 times longer than high, meshed at sizes far above its height: the front's
    // points would fall beyond the opposite side; their triangles are accepted as they are.
    const Input in = polygon({0, 0, 1, 0, 0.5, 0.02});
    for (const double h : {0.1, 0.05}) {
        const Meshed r = mesh(in, gen::SizeFunction::uniform(h));
        ASSERT_TRUE(r.check.ok) << h << ": " << r.check.problem;
        expect_consistent(in, r, "flat triangle");
        const auto& c = r.result.counters;
        EXPECT_GT(c.rejected_outside, 0u) << h;
        EXPECT_GT(c.forced_triangles, 0u) << h;
        EXPECT_EQ(c.forced_accepts, c.rejected_outside + c.rejected_encroach +
                                        c.rejected_too_close + c.rejected_no_conflict)
            << h;
    }
}

TEST(Generators_FrontalDelaunay, PointsEncroachingAPieceAreRejected) {
    // A channel 0.05 high whose size grows from 0.01 at the bottom wall to 0.06 at the top: the
    // top wall's pieces are longer than the channel is high, and front points from below land
    // in their diametral circles.
    const Input in = polygon({0, 0, 1, 0, 1, 0.05, 0, 0.05});
    const Meshed r = mesh(
        in, gen::SizeFunction::analytic([](double, double y) { return 0.01 + y; }, "0.01 + y"));
    ASSERT_TRUE(r.check.ok) << r.check.problem;
    expect_consistent(in, r, "graded channel");
    EXPECT_GT(r.result.counters.rejected_encroach, 0u);
    EXPECT_EQ(r.result.counters.rejected_outside, 0u);
}

TEST(Generators_FrontalDelaunay, PointsTooCloseToAVertexAreRejected) {
    // With the closeness limit at 0.9 times the size, merging fronts reject points; each
    // rejection accepts its triangle and the mesh stays valid.
    const Input in = from_domain(gen::sample_domain(gen::SampleDomain::SquareWithHoles));
    gen::FrontalDelaunayOptions2 options;
    options.size = gen::sample_domain_size(gen::SampleDomain::SquareWithHoles);
    options.min_distance = 0.9;
    const auto result = gen::frontal_delaunay_2d(in.pslg(), options);
    const auto& m = result.mesh;
    const auto check =
        em::testing::check_quality_mesh(m.mesh, m.input_vertex_count, in.xy, in.segments, m.pieces);
    ASSERT_TRUE(check.ok) << check.problem;
    EXPECT_GT(result.counters.rejected_too_close, 0u);
    EXPECT_EQ(result.counters.forced_accepts,
              result.counters.rejected_too_close + result.counters.rejected_outside +
                  result.counters.rejected_encroach + result.counters.rejected_no_conflict);
}

TEST(Generators_FrontalDelaunay, RandomPslgsGiveValidMeshesOrAClearError) {
    // The constrained Delaunay test distributions (crossings, overlaps, duplicates, small
    // angles), at a uniform size of a twentieth of their extent: every run ends with an exact
    // constrained Delaunay mesh, or InputError when nothing is enclosed, or GeometryError only
    // where the triangulation itself holds features at the resolution of doubles (grid-lines).
    em::testing::expect_random_pslgs_constrained_delaunay(
        [](const Input& in) -> std::optional<gen::FrontalDelaunayResult2> {
            double lo = INFINITY, hi = -INFINITY;
            for (const double v : in.xy) {
                lo = std::min(lo, v);
                hi = std::max(hi, v);
            }
            if (!(hi > lo)) return std::nullopt;
            gen::FrontalDelaunayOptions2 options;
            options.size = gen::SizeFunction::uniform((hi - lo) / 20);
            return gen::frontal_delaunay_2d(in.pslg(), options);
        });
}

TEST(Generators_FrontalDelaunay, RegionsKeepTheirAttributes) {
    // Two regions split by an inner segment x = 0.5.
    Input in = polygon({0, 0, 0.5, 0, 1, 0, 1, 1, 0.5, 1, 0, 1});
    in.segments.insert(in.segments.end(), {1, 4});
    in.regions = {0.25, 0.5, 1.0, 0, 0.75, 0.5, 2.0, 0};
    const Meshed r = mesh(in, gen::SizeFunction::uniform(0.1), false);
    ASSERT_TRUE(r.check.ok) << r.check.problem;
    const auto& m = r.result.mesh;
    ASSERT_EQ(m.triangle_attributes.size(), m.mesh.triangle_count());
    for (tri::TriIdx t = 0; t < m.mesh.triangle_count(); ++t) {
        double cx = 0;
        for (unsigned k = 0; k < 3; ++k) cx += m.mesh.point(m.mesh.triangles[3 * t + k])[0] / 3;
        EXPECT_EQ(m.triangle_attributes[t], cx < 0.5 ? 1.0 : 2.0) << t;
    }
}

TEST(Generators_FrontalDelaunay, BadInputIsAnInputError) {
    const Input square = polygon({0, 0, 1, 0, 1, 1, 0, 1});
    gen::FrontalDelaunayOptions2 options;
    EXPECT_THROW(gen::frontal_delaunay_2d(square.pslg(), options), em::InputError);  // no size
    options.size = gen::SizeFunction::uniform(0.1);
    options.acceptance = 0.5;
    EXPECT_THROW(gen::frontal_delaunay_2d(square.pslg(), options), em::InputError);
    options.acceptance = 1.5;
    options.min_distance = 1.0;
    EXPECT_THROW(gen::frontal_delaunay_2d(square.pslg(), options), em::InputError);
    options.min_distance = 0.5;
    Input nan = square;
    nan.xy[2] = std::nan("");
    EXPECT_THROW(gen::frontal_delaunay_2d(nan.pslg(), options), em::InputError);
    Input open = square;
    open.segments.resize(6);  // three sides: nothing enclosed
    EXPECT_THROW(gen::frontal_delaunay_2d(open.pslg(), options), em::InputError);
    Input out_of_range = square;
    out_of_range.segments[1] = 9;
    EXPECT_THROW(gen::frontal_delaunay_2d(out_of_range.pslg(), options), em::InputError);
    options.size = gen::SizeFunction::analytic([](double x, double) { return x < 0.5 ? 0.1 : 0.0; },
                                               "zero right");
    EXPECT_THROW(gen::frontal_delaunay_2d(square.pslg(), options), em::InputError);
}

TEST(Generators_FrontalDelaunay, SubnormalPointsWithoutSegmentsMeshTheirHull) {
    // fuzz_mesh_generators_2d (tests/data/fuzz/mesh_generators_2d_frontal_subnormal_box.bin):
    // four points up to 3.7e-294, no segment, size 2^-5 of that. The budget's estimate over the
    // bounding box was 0 / 0 converted to an integer (UBSan); it is now unknown (0). Without a
    // segment the domain is the convex hull (MeshDomain2): meshed, and the mesh passes the
    // exact check (47 triangles on 2026-12-06).
    const std::vector<double> xy = {
        3.7431365209027174e-294, 6.374341177e-314,  0.0, 0.0, 1.35675105885e-312, 0.0,
        1.33636928895241e-309,   1.35675105885e-312};
    gen::FrontalDelaunayOptions2 options;
    options.size = gen::SizeFunction::uniform(std::ldexp(3.7431365209027174e-294, -5));
    options.max_steiner_points = 5000;
    const Input in{xy, {}, {}, {}};
    const auto m = em::testing::check_generated_mesh(gen::frontal_delaunay_2d(in.pslg(), options),
                                                     in, options.size, false, true);
    EXPECT_TRUE(m.check.ok) << m.check.problem;
    EXPECT_GT(m.result.mesh.mesh.triangle_count(), 2u);
}

TEST(Generators_FrontalDelaunay, BudgetStopsWithGeometryError) {
    const Input square = polygon({0, 0, 1, 0, 1, 1, 0, 1});
    gen::FrontalDelaunayOptions2 options;
    // 76 boundary points within the budget of 100, about 400 inside: the front's error.
    options.size = gen::SizeFunction::uniform(0.05);
    options.max_steiner_points = 100;
    EXPECT_THROW(gen::frontal_delaunay_2d(square.pslg(), options), em::GeometryError);
    // 396 boundary points: refused as the boundary is sampled, naming the budget.
    options.size = gen::SizeFunction::uniform(0.01);
    try {
        gen::frontal_delaunay_2d(square.pslg(), options);
        ADD_FAILURE() << "meshed over the budget";
    } catch (const em::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("more than 100 boundary points"), std::string::npos)
            << e.what();
    }
}

TEST(Generators_FrontalDelaunay, CounterListNamesEveryCounter) {
    const Input square = polygon({0, 0, 1, 0, 1, 1, 0, 1});
    gen::FrontalDelaunayOptions2 options;
    options.size = gen::SizeFunction::uniform(0.1);
    const auto result = gen::frontal_delaunay_2d(square.pslg(), options);
    const auto list = gen::counter_list(result.counters);
    ASSERT_FALSE(list.empty());
    bool found = false;
    for (const auto& [name, value] : list) {
        if (name == "points_inserted") {
            found = true;
            EXPECT_EQ(value, result.counters.points_inserted);
        }
    }
    EXPECT_TRUE(found);
    EXPECT_GT(result.counters.points_inserted, 20u);
}

TEST(Generators_FrontalDelaunay, HugeCrossingQuadrilateralEndsInAValidMesh) {
    // fuzz_mesh_generators_2d (tests/data/fuzz/mesh_generators_2d_frontal_empty_front.bin): a
    // unit square crossed by a quadrilateral reaching down to -2.7e302, size 1.4e302. Squared
    // edge lengths overflowed: front_edge found no front edge shorter than infinity, so step took
    // each active triangle off the front as if its accepted neighbours had gone, and the run
    // ended with waiting triangles (InternalError). Now the measures are scaled: every triangle
    // of the boundary's triangulation meets the radius criterion.
    Input in;
    in.xy = {0x0p+0,
             0x0p+0,
             0x1p+0,
             0x0p+0,
             0x1p+0,
             0x1p+0,
             0x0p+0,
             0x1p+0,
             0x1.999999999999ap-2,
             -0x1.999999999999ap+1006,
             0x1.3323333333333p-1,
             0x1.999999999999ap-2,
             0x1.3333333333333p-1,
             0x1.3333333333333p-1,
             0x1.999999999999ap-2,
             0x1.3333333333333p-1};
    in.segments = {0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 5, 6, 6, 7, 7, 4};
    // The crossing loops overlap: the even-odd outside test does not apply.
    const Meshed r = mesh(in, gen::SizeFunction::uniform(0x1.999999999999ap+1003), false);
    ASSERT_TRUE(r.check.ok) << r.check.problem;
    expect_consistent(in, r, "huge crossing quadrilateral");
    EXPECT_EQ(r.result.counters.forced_accepts, 0u);
    EXPECT_EQ(r.result.counters.forced_triangles, 0u);
    EXPECT_EQ(r.result.counters.accepted_triangles, r.result.mesh.mesh.triangle_count());
    EXPECT_LE(r.check.max_size_ratio, kSizeRatioBound);
}

TEST(Generators_FrontalDelaunay, PiecesBendOnlyWhereTheirInputSegmentMay) {
    // fuzz_mesh_generators_2d, seed 5 (2026-12-07; tests/data/fuzz/
    // mesh_generators_2d_frontal_piece_bent_backwards.bin): segment 4-5 leaves vertex 4, 2.4e-185
    // below segment 0-1, and crosses it at a rounded point 8 with vertex 4's x; it also crosses
    // 7-4's rounded pieces at 10, 2e-185 above 8 with the same x. The triangulation over the
    // boundary's pieces bent the vertical piece 8 - 10 through a split point of segment 0-1
    // 3.4e-77 to its left: between 8 and 10 along the piece, behind 8 along segment 4-5, and the
    // check found segment 4 missing (frontal and metric Delaunay; the 2026-12-01 binary too).
    // That triangulation now measures each piece's bends against its input segment's line
    // (Pslg::segment_lines, piece_lines).
    Input in;
    in.xy = {0.0,
             0.0,
             1.0,
             -2.353438274577701e-185,
             4.6672616416828e-62,
             -2.353438279440778e-185,
             2.78135280877724e-310,
             -2.3532219046382903e-185,
             4.66726145911182e-62,
             -2.3534373718238174e-185,
             0.5937744141545408,
             0.4,
             0.6,
             0.6,
             0.4,
             0.6};
    in.segments = {0, 1, 7, 5, 5, 0, 3, 0, 4, 5, 5, 6, 6, 7, 7, 4};
    for (const char* name : {"frontal", "metric-delaunay"}) {
        gen::MeshOptions2 options;
        options.size = gen::SizeFunction::uniform(0.25);
        const tri::Cdt2Result r = gen::find_mesh_generator_2d(name).run(in.pslg(), options).mesh;
        const auto report =
            tri::check_conforming_mesh_2d(r.mesh, r.input_vertex_count, in.segments, r.pieces);
        EXPECT_TRUE(report.ok) << name << ": " << report.problem;
    }
}

TEST(Generators_FrontalDelaunay, A1e300SquareIsTheUnitSquareScaled) {
    // The same overflow on a plain square of side 2^996 (about 6.7e299) at a tenth of that
    // (InternalError before). Scaling by a power of two is exact in every predicate and every
    // measure now, so the mesh is the unit square's, every coordinate times 2^996.
    const Input unit = polygon({0, 0, 1, 0, 1, 1, 0, 1});
    const Input huge = polygon({0, 0, 0x1p996, 0, 0x1p996, 0x1p996, 0, 0x1p996});
    const Meshed a = mesh(unit, gen::SizeFunction::uniform(0.1));
    const Meshed b = mesh(huge, gen::SizeFunction::uniform(std::ldexp(0.1, 996)));
    ASSERT_TRUE(a.check.ok) << a.check.problem;
    ASSERT_TRUE(b.check.ok) << b.check.problem;
    expect_consistent(huge, b, "2^996 square");
    EXPECT_GT(b.result.counters.points_inserted, 0u);
    EXPECT_EQ(b.result.mesh.mesh.triangles, a.result.mesh.mesh.triangles);
    ASSERT_EQ(b.result.mesh.mesh.xy.size(), a.result.mesh.mesh.xy.size());
    for (std::size_t i = 0; i < a.result.mesh.mesh.xy.size(); ++i)
        EXPECT_EQ(b.result.mesh.mesh.xy[i], std::ldexp(a.result.mesh.mesh.xy[i], 996)) << i;
}

TEST(Generators_FrontalDelaunay, ProgressReportsPointsAndKeepsTheResult) {
    // The unit square at size 0.005: several calls of the hook (every 2^14 points inserted),
    // each with the expected count as total; the mesh is the same without the hook.
    const Input in = exactmesh::testing::polygon({0, 0, 1, 0, 1, 1, 0, 1});
    gen::FrontalDelaunayOptions2 options;
    options.size = gen::SizeFunction::uniform(0.005);
    const auto plain = gen::frontal_delaunay_2d(in.pslg(), options);
    std::vector<std::uint64_t> done, total;
    options.cdt.progress.report = [&](std::uint64_t d, std::uint64_t t, const char* what) {
        EXPECT_EQ(std::string(what), "Steiner points inserted");
        done.push_back(d);
        total.push_back(t);
    };
    const auto hooked = gen::frontal_delaunay_2d(in.pslg(), options);
    EXPECT_EQ(plain.mesh.mesh.triangles, hooked.mesh.mesh.triangles);
    EXPECT_EQ(plain.mesh.mesh.xy, hooked.mesh.mesh.xy);
    const std::uint64_t step = std::uint64_t{1} << em::ProgressCounter::kProgressShift;
    const std::uint64_t inserted = hooked.counters.points_inserted;
    ASSERT_GE(inserted, 2 * step);
    ASSERT_EQ(done.size(), inserted / step);
    for (std::size_t k = 0; k < done.size(); ++k) {
        EXPECT_EQ(done[k], (k + 1) * step);
        EXPECT_EQ(total[k], total[0]);
    }
    EXPECT_GT(total[0], inserted / 2);
    EXPECT_LT(total[0], 2 * inserted);
}
