// SPDX-License-Identifier: MIT
// Advancing layers: the mixed mesh passes the exact check (no inverted cell, quads strictly
// convex, every edge in at most two cells, open edges only on pieces, every piece a cell edge),
// keeps every input vertex and segment; a circular hole gets a stack per vertex and no corner
// treatment, an L-shaped hole fans at its convex corners and merges at its concave one; on the
// NACA 0012 domain the aspect ratio at the wall reaches 1000 and no layer triangle exceeds 150
// degrees (exact compare_angles); the mesh of the input scaled by 2^600 or 2^-600 is the mesh
// scaled, bit for bit; walls closer than the layers' thickness stop their stacks by collision
// without any crossing; bad parameters are refused. The truncated O-mesh variant
// (LayerMethod2::TruncatedOMesh) passes the same checks on the NACA 0012 and three-element
// domains (quads kept and split), the random holes and the 2^+-600 scalings, and removes
// cells in the three-element airfoil's gaps.
#include "generators/stretched/advancing_layers_2d.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "base/errors.hpp"
#include "generators/boundary/sample_domains.hpp"
#include "generators/mesh_2d/mesh_generators_2d.hpp"
#include "generators/stretched/truncated_omesh_2d.hpp"
#include "predicates/angle_comparisons_2d.hpp"
#include "predicates/orient2d.hpp"
#include "tests/support/frontal_fill_2d.hpp"
#include "tests/support/pslg_fixtures_2d.hpp"
#include "tests/support/test_scale.hpp"

namespace gen = exactmesh::generators;
namespace tri = exactmesh::triangulation;
namespace pred = exactmesh::predicates;
using exactmesh::testing::Input;

namespace {

/// A square [-1, 1]^2 with a circular hole of n vertices (radius r about (cx, cy)).
void add_circle(Input& in, double cx, double cy, double r, int n) {
    std::vector<double> xy;
    for (int k = 0; k < n; ++k) {
        const double a = 2 * std::numbers::pi * k / n;
        xy.insert(xy.end(), {cx + r * std::cos(a), cy + r * std::sin(a)});
    }
    exactmesh::testing::add_loop(in, xy);
    in.holes.insert(in.holes.end(), {cx, cy});
}

Input square(double half) {
    Input in;
    exactmesh::testing::add_loop(in, {-half, -half, half, -half, half, half, -half, half});
    return in;
}

using exactmesh::testing::frontal_fill;

gen::AdvancingLayersResult2 run(const Input& in, double height, double growth, bool quads,
                                std::uint32_t max_layers = 60, gen::SizeFunction size = {},
                                gen::LayerMethod2 method = gen::LayerMethod2::AdvancingLayers) {
    const gen::MeshDomain2 domain(in.pslg());
    gen::AdvancingLayersOptions2 options;
    options.layers.first_height = height;
    options.layers.growth = growth;
    options.layers.max_layers = max_layers;
    options.layers.quads = quads;
    options.layers.method = method;
    options.size = size;
    options.fill = &frontal_fill;
    return gen::advancing_layers_2d(domain, options);
}

/// Every input vertex in some cell (at its input coordinates), and every input segment a chain
/// of pieces from one end to the other.
void expect_input_kept(const gen::AdvancingLayersResult2& r, const Input& in) {
    const tri::Triangulation2& mesh = r.mesh.mesh;
    std::set<tri::VertIdx> used(mesh.triangles.begin(), mesh.triangles.end());
    used.insert(r.quads.begin(), r.quads.end());
    for (tri::VertIdx v = 0; v < in.xy.size() / 2; ++v) {
        EXPECT_TRUE(used.count(v)) << "input vertex " << v << " is in no cell";
        EXPECT_EQ(mesh.xy[2 * v], in.xy[2 * v]);
        EXPECT_EQ(mesh.xy[2 * v + 1], in.xy[2 * v + 1]);
    }
    for (std::uint32_t s = 0; s < in.segments.size() / 2; ++s) {
        // Walk the pieces of segment s from its first end.
        std::vector<std::pair<tri::VertIdx, tri::VertIdx>> pieces;
        for (std::size_t p = 0; p < r.mesh.piece_segment.size(); ++p)
            if (r.mesh.piece_segment[p] == s)
                pieces.emplace_back(r.mesh.pieces[2 * p], r.mesh.pieces[2 * p + 1]);
        tri::VertIdx at = in.segments[2 * s];
        std::vector<bool> taken(pieces.size(), false);
        for (bool moved = true; moved && at != in.segments[2 * s + 1];) {
            moved = false;
            for (std::size_t p = 0; p < pieces.size(); ++p) {
                if (taken[p] || (pieces[p].first != at && pieces[p].second != at)) continue;
                at = pieces[p].first == at ? pieces[p].second : pieces[p].first;
                taken[p] = moved = true;
                break;
            }
        }
        EXPECT_EQ(at, in.segments[2 * s + 1]) << "segment " << s << " is not a chain of pieces";
    }
}

void expect_valid(const gen::AdvancingLayersResult2& r) {
    const gen::MixedMeshCheck2 check =
        gen::check_mixed_mesh_2d(r.mesh.mesh.xy, r.mesh.mesh.triangles, r.quads, r.mesh.pieces);
    EXPECT_TRUE(check.ok()) << check.summary();
}

double triangle_area(const double* a, const double* b, const double* c) {
    return 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
}

/// The cells' areas add up to the domain's (its constrained triangulation's), to rounding: no
/// two cells overlap and none is missing (the exact check sees topology only).
void expect_area(const gen::AdvancingLayersResult2& r, const Input& in) {
    const gen::MeshDomain2 domain(in.pslg());
    const tri::Triangulation2& d = domain.triangulation().mesh;
    double expected = 0, actual = 0;
    for (std::uint32_t t = 0; t < d.triangle_count(); ++t)
        expected += triangle_area(d.point(d.triangles[3 * t]), d.point(d.triangles[3 * t + 1]),
                                  d.point(d.triangles[3 * t + 2]));
    const tri::Triangulation2& m = r.mesh.mesh;
    for (std::uint32_t t = 0; t < m.triangle_count(); ++t)
        actual += triangle_area(m.point(m.triangles[3 * t]), m.point(m.triangles[3 * t + 1]),
                                m.point(m.triangles[3 * t + 2]));
    for (std::size_t q = 0; q < r.quads.size() / 4; ++q) {
        const double* a = m.point(r.quads[4 * q]);
        actual += triangle_area(a, m.point(r.quads[4 * q + 1]), m.point(r.quads[4 * q + 2])) +
                  triangle_area(a, m.point(r.quads[4 * q + 2]), m.point(r.quads[4 * q + 3]));
    }
    EXPECT_NEAR(actual, expected, 1e-12 * expected);
}

/// The reference corner of 150 degrees: (0, 0), (1, 0), (cos 150, sin 150) rounded to doubles.
const double kOrigin[2] = {0, 0}, kRight[2] = {1, 0}, kAt150[2] = {-0.86602540378443865, 0.5};

/// Whether every one of the first `count` triangles has its largest angle at most the
/// reference 150-degree corner (exact comparison); the largest angle in degrees for the report.
bool layer_angles_at_most_150(const tri::Triangulation2& mesh, std::uint64_t count,
                              double& largest_degrees) {
    const pred::Corner reference{kOrigin, kRight, kAt150};
    bool ok = true;
    largest_degrees = 0;
    for (std::uint64_t t = 0; t < count; ++t) {
        const double* a = mesh.point(mesh.triangles[3 * t]);
        const double* b = mesh.point(mesh.triangles[3 * t + 1]);
        const double* c = mesh.point(mesh.triangles[3 * t + 2]);
        const pred::Corner worst = pred::largest_corner(a, b, c);
        if (pred::compare_angles(worst, reference) == pred::Sign::Positive) ok = false;
        const double ux = worst.p[0] - worst.o[0], uy = worst.p[1] - worst.o[1];
        const double vx = worst.q[0] - worst.o[0], vy = worst.q[1] - worst.o[1];
        largest_degrees =
            std::max(largest_degrees,
                     std::atan2(ux * vy - uy * vx, ux * vx + uy * vy) * 180 / std::numbers::pi);
    }
    return ok;
}

/// The mesh of the input scaled by 2^600 and 2^-600 (and the first height with it), quads kept,
/// is the mesh scaled, bit for bit, and valid; returns the unscaled one.
gen::AdvancingLayersResult2 expect_scaled_the_same(const Input& in, double height, double growth,
                                                   gen::LayerMethod2 method) {
    gen::AdvancingLayersResult2 reference = run(in, height, growth, true, 60, {}, method);
    for (const int k : {600, -600}) {
        Input scaled = in;
        for (double& x : scaled.xy) x = std::ldexp(x, k);
        for (double& x : scaled.holes) x = std::ldexp(x, k);
        const gen::AdvancingLayersResult2 r =
            run(scaled, std::ldexp(height, k), growth, true, 60, {}, method);
        std::vector<double> unscaled = r.mesh.mesh.xy;
        for (double& x : unscaled) x = std::ldexp(x, -k);
        EXPECT_EQ(unscaled, reference.mesh.mesh.xy) << "2^" << k;
        EXPECT_EQ(r.mesh.mesh.triangles, reference.mesh.mesh.triangles) << "2^" << k;
        EXPECT_EQ(r.quads, reference.quads) << "2^" << k;
        EXPECT_EQ(r.stack_layers, reference.stack_layers) << "2^" << k;
        EXPECT_EQ(r.counters.omesh_removed_overlap, reference.counters.omesh_removed_overlap);
        expect_valid(r);
    }
    return reference;
}

}  // namespace

TEST(Generators_AdvancingLayers2, CircularHoleHasLayersAllAroundWithoutCorners) {
    // 64 wall vertices whatever EXACTMESH_TEST_SCALE says: with 16 (the sanitizer pass's 0.02)
    // the stacks of the coarse circle collide before any reaches aspect ratio 1, which is what
    // this test is about; the domain is small either way.
    const int n = 64;
    Input in = square(1);
    add_circle(in, 0, 0, 0.25, n);
    for (const bool quads : {false, true}) {
        const gen::AdvancingLayersResult2 r = run(in, 1e-3, 1.2, quads);
        EXPECT_EQ(r.counters.wall_loops, 1u);
        EXPECT_EQ(r.counters.stacks, static_cast<std::uint64_t>(n));
        EXPECT_EQ(r.counters.fan_corners, 0u);
        EXPECT_EQ(r.counters.merged_corners, 0u);
        for (const auto& [v, layers] : r.stack_layers) EXPECT_GE(layers, 5u) << "stack at " << v;
        EXPECT_EQ(r.counters.stopped_collision, 0u);
        EXPECT_GT(r.counters.stopped_aspect_ratio, 0u);
        EXPECT_GT(r.counters.fill_triangles, 0u);
        if (quads) {
            EXPECT_EQ(r.quads.size() / 4, r.counters.layer_quads);
            EXPECT_EQ(r.counters.quads, r.counters.layer_quads);
        } else {
            EXPECT_TRUE(r.quads.empty());
        }
        expect_valid(r);
        expect_input_kept(r, in);
        expect_area(r, in);
    }
}

TEST(Generators_AdvancingLayers2, ConvexCornersFanAndTheConcaveCornerMerges) {
    // An L-shaped hole: five convex corners (the domain's angle 270 degrees) and one concave
    // corner (90 degrees), in a square.
    Input in = square(1);
    exactmesh::testing::add_loop(
        in, {-0.4, -0.4, 0.4, -0.4, 0.4, -0.1, -0.1, -0.1, -0.1, 0.4, -0.4, 0.4});
    in.holes.insert(in.holes.end(), {-0.3, -0.3});
    for (const bool quads : {false, true}) {
        const gen::AdvancingLayersResult2 r = run(in, 2e-3, 1.25, quads);
        EXPECT_EQ(r.counters.fan_corners, 5u);
        EXPECT_EQ(r.counters.merged_corners, 1u);
        // Each 90-degree fan spreads 4 stacks (30 degrees apart): 3 more than one per vertex.
        EXPECT_EQ(r.counters.stacks, 6u + 5u * 3u);
        EXPECT_GT(r.counters.layers, 3u);
        expect_valid(r);
        expect_input_kept(r, in);
        expect_area(r, in);
    }
}

TEST(Generators_AdvancingLayers2, Naca0012ReachesAspectRatio1000WithNoLayerTriangleAbove150) {
    const gen::DomainPslg domain = gen::sample_domain(gen::SampleDomain::Naca0012);
    const Input in = exactmesh::testing::from_domain(domain);
    // The built-in discretization (0.01 to 0.014 along the chord): a first height of 1e-5
    // gives aspect ratio 1440 at the wall.
    const gen::AdvancingLayersResult2 r = run(in, 1e-5, 1.2, false, 80);
    EXPECT_GE(r.counters.max_wall_aspect_ratio, 1000u);
    double largest = 0;
    EXPECT_TRUE(layer_angles_at_most_150(r.mesh.mesh, r.counters.layer_triangles, largest))
        << largest;
    ::testing::Test::RecordProperty("layer_max_angle", std::to_string(largest));
    EXPECT_GE(r.counters.fan_corners, 1u);  // the trailing edge
    expect_valid(r);
    expect_input_kept(r, in);
    expect_area(r, in);
    for (const auto& [v, layers] : r.stack_layers) EXPECT_GE(layers, 1u) << "stack at " << v;
}

TEST(Generators_AdvancingLayers2, Naca0012AtFirstHeight1em4) {
    // The brief's parameters on the coarsest built-in discretization (16 pieces per surface, the
    // sample domain's minimum): the wall pieces are at most 0.064 long, so the aspect ratio at
    // the wall is about 640 (1000 needs pieces of 0.1); every check holds.
    const gen::DomainPslg domain =
        gen::sample_domain(gen::SampleDomain::Naca0012, gen::SizeFunction::uniform(0.1));
    const Input in = exactmesh::testing::from_domain(domain);
    const gen::AdvancingLayersResult2 r = run(in, 1e-4, 1.2, false);
    EXPECT_GE(r.counters.max_wall_aspect_ratio, 600u);
    double largest = 0;
    EXPECT_TRUE(layer_angles_at_most_150(r.mesh.mesh, r.counters.layer_triangles, largest))
        << largest;
    expect_valid(r);
    expect_input_kept(r, in);
    const gen::AdvancingLayersResult2 q = run(in, 1e-4, 1.2, true);
    expect_valid(q);
    EXPECT_EQ(q.counters.quads, r.counters.layer_quads);
}

TEST(Generators_AdvancingLayers2, ScaledBy2ToThePlusMinus600GivesTheSameMeshScaled) {
    Input circle = square(1);
    add_circle(circle, 0.1, -0.05, 0.3, 24);
    const Input naca = exactmesh::testing::from_domain(
        gen::sample_domain(gen::SampleDomain::Naca0012, gen::SizeFunction::uniform(0.05)));
    for (const Input& in : {circle, naca}) {
        const gen::AdvancingLayersResult2 reference =
            expect_scaled_the_same(in, 2e-3, 1.3, gen::LayerMethod2::AdvancingLayers);
        EXPECT_GT(reference.counters.layer_quads, 100u);
    }
}

TEST(Generators_AdvancingLayers2, AFirstHeightDoublesCannotPlaceBuildsNoLayerAndWarns) {
    // On the NACA 0012 (coordinates up to 1) a first height of 1e-14 to 1e-16 moved points by a
    // few ulps near the trailing edge and not at all elsewhere; the fill then overlapped the
    // layer cells (the mesh failed its check). Below 2^-44 of the walls' largest coordinate no
    // stack is built, at any scale; 2^-43 still builds layers.
    const Input naca = exactmesh::testing::from_domain(
        gen::sample_domain(gen::SampleDomain::Naca0012, gen::SizeFunction::uniform(0.05)));
    // The walls' largest coordinate: the trailing edge at x = 1 (the far field's box is larger,
    // but it is no wall).
    const double largest = 1.0;
    for (const int e : {-600, 0, 600}) {
        SCOPED_TRACE("scale 2^" + std::to_string(e));
        Input scaled = naca;
        for (double& c : scaled.xy) c = std::ldexp(c, e);
        for (double& c : scaled.holes) c = std::ldexp(c, e);
        for (const double height : {1e-15, 1e-100 * largest, 0x1.fp-45 * largest}) {
            SCOPED_TRACE(::testing::Message() << "first height " << height);
            const gen::AdvancingLayersResult2 r =
                run(scaled, std::ldexp(height, e), 1.2, false, 60);
            EXPECT_EQ(r.counters.layer_points, 0u);
            EXPECT_EQ(r.counters.stopped_unresolvable, r.counters.stacks);
            ASSERT_FALSE(r.mesh.warnings.empty());
            EXPECT_NE(r.mesh.warnings.back().find("no layer was built"), std::string::npos)
                << r.mesh.warnings.back();
            expect_valid(r);
            expect_input_kept(r, scaled);
        }
        const gen::AdvancingLayersResult2 thin =
            run(scaled, std::ldexp(0x1p-43 * largest, e), 1.2, false, 60);
        EXPECT_GT(thin.counters.layer_points, 0u);
        EXPECT_EQ(thin.counters.stopped_unresolvable, 0u);
        expect_valid(thin);
    }
}

TEST(Generators_AdvancingLayers2, FreeVerticesBesideTheWallAndSegmentsIntoTheHoleAreKept) {
    // A hostile-input campaign found two failures on a square with a circular hole: the
    // truncated O-mesh laid cells over a free vertex beside the wall (the vertex was left out
    // of the mesh, silently), and a segment from inside the hole out across the wall left its
    // inner piece in no cell, which the mixed mesh check took for a missing boundary piece.
    Input in = square(1);
    add_circle(in, 0, 0, 0.25, 32);
    // Free vertices a first layer (and a few) above the wall, between two wall vertices.
    for (const double r : {0.2505, 0.252, 0.26}) {
        const double a = 2 * std::numbers::pi * 0.5 / 32;
        in.xy.insert(in.xy.end(), {r * std::cos(a), r * std::sin(a)});
    }
    // A segment from inside the hole (x = 0.1) out to x = 0.7, and a free vertex within
    // rounding of its part inside the hole (not exactly on it: the fill then splits that part
    // where the domain's triangulation does not).
    const auto first = static_cast<std::uint32_t>(in.xy.size() / 2);
    const double a[2] = {0.1, -0.05}, b[2] = {0.7, 0.13};
    in.xy.insert(in.xy.end(), {a[0], a[1], b[0], b[1]});
    in.segments.insert(in.segments.end(), {first, first + 1});
    bool near = false;
    for (int k = 1; k < 100 && !near; ++k) {
        const double t = 0.001 * k;  // x up to 0.16, inside the hole
        const double q[2] = {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])};
        if (pred::orient2d(a, b, q) != pred::Sign::Zero) {
            in.xy.insert(in.xy.end(), {q[0], q[1]});
            near = true;
        }
    }
    ASSERT_TRUE(near);
    for (const gen::LayerMethod2 method :
         {gen::LayerMethod2::AdvancingLayers, gen::LayerMethod2::TruncatedOMesh}) {
        SCOPED_TRACE(method == gen::LayerMethod2::TruncatedOMesh ? "O-mesh" : "layers");
        const gen::AdvancingLayersResult2 r = run(in, 1e-3, 1.2, false, 60, {}, method);
        EXPECT_GT(r.counters.layer_points, 0u);
        // Valid, but for the segment's pieces inside the hole (from x = 0.1 to the wall), which
        // stay pieces of the output (as in every generator's) in no cell.
        gen::MixedMeshCheck2 check =
            gen::check_mixed_mesh_2d(r.mesh.mesh.xy, r.mesh.mesh.triangles, r.quads, r.mesh.pieces);
        EXPECT_GE(check.missing_pieces.size(), 2u);
        for (const tri::VertIdx v : check.missing_pieces)
            EXPECT_LT(std::hypot(r.mesh.mesh.xy[2 * v], r.mesh.mesh.xy[2 * v + 1]), 0.2501);
        check.missing_pieces.clear();
        EXPECT_TRUE(check.ok()) << check.summary();
        // Every input vertex but the segment's end inside the hole is in some cell.
        const tri::Triangulation2& mesh = r.mesh.mesh;
        std::set<tri::VertIdx> used(mesh.triangles.begin(), mesh.triangles.end());
        for (tri::VertIdx v = 0; v < first; ++v)
            EXPECT_TRUE(used.count(v)) << "input vertex " << v << " is in no cell";
        EXPECT_TRUE(used.count(first + 1));
        EXPECT_FALSE(used.count(first));      // inside the hole
        EXPECT_FALSE(used.count(first + 2));  // inside the hole
    }
}

TEST(Generators_AdvancingLayers2, OpposingWallsCloserThanTheLayersStopByCollision) {
    // Two square holes 0.02 apart; alone, their layers would grow about 0.1 thick.
    Input in = square(1);
    exactmesh::testing::add_loop(in, {-0.5, -0.2, -0.01, -0.2, -0.01, 0.2, -0.5, 0.2});
    exactmesh::testing::add_loop(in, {0.01, -0.2, 0.5, -0.2, 0.5, 0.2, 0.01, 0.2});
    in.holes.insert(in.holes.end(), {-0.3, 0.0, 0.3, 0.0});
    const gen::AdvancingLayersResult2 r = run(in, 1e-3, 1.2, true);
    EXPECT_EQ(r.counters.wall_loops, 2u);
    EXPECT_GT(r.counters.stopped_collision, 0u);
    EXPECT_GT(r.counters.layers, 8u);  // elsewhere the layers grow on
    expect_valid(r);
    expect_input_kept(r, in);
    // In the gap, no two layer edges cross (exact orient2d on every pair there).
    std::vector<std::array<tri::VertIdx, 2>> edges;
    const auto in_gap = [&](tri::VertIdx v) {
        const double* p = r.mesh.mesh.point(v);
        return std::fabs(p[0]) <= 0.01 && std::fabs(p[1]) <= 0.25;
    };
    for (std::size_t q = 0; q < r.quads.size() / 4; ++q) {
        for (std::size_t k = 0; k < 4; ++k) {
            const tri::VertIdx a = r.quads[4 * q + k], b = r.quads[4 * q + (k + 1) % 4];
            if (in_gap(a) && in_gap(b)) edges.push_back({a, b});
        }
    }
    EXPECT_GT(edges.size(), 10u);
    std::size_t crossings = 0;
    for (std::size_t i = 0; i < edges.size(); ++i) {
        for (std::size_t j = i + 1; j < edges.size(); ++j) {
            const auto& [a, b] = edges[i];
            const auto& [c, d] = edges[j];
            if (a == c || a == d || b == c || b == d) continue;
            const auto at = [&](tri::VertIdx v) { return r.mesh.mesh.point(v); };
            const int o1 = static_cast<int>(pred::orient2d(at(a), at(b), at(c)));
            const int o2 = static_cast<int>(pred::orient2d(at(a), at(b), at(d)));
            const int o3 = static_cast<int>(pred::orient2d(at(c), at(d), at(a)));
            const int o4 = static_cast<int>(pred::orient2d(at(c), at(d), at(b)));
            if (o1 * o2 <= 0 && o3 * o4 <= 0 && !(o1 == 0 && o2 == 0)) ++crossings;
        }
    }
    EXPECT_EQ(crossings, 0u);
    expect_area(r, in);
}

TEST(Generators_AdvancingLayers2, TheRegistryRunsItAndWithoutLayersItIsTheFillAlone) {
    Input in = square(1);
    add_circle(in, 0, 0, 0.25, 32);
    const gen::MeshGenerator2& g = gen::find_mesh_generator_2d("advancing-layers");
    EXPECT_TRUE(g.honours.contains(gen::MeshOption::Layers));
    gen::MeshOptions2 options;
    options.layers.first_height = 1e-3;
    options.layers.quads = true;
    const gen::MeshRun2 layered = g.run(in.pslg(), options);
    EXPECT_FALSE(layered.quads.empty());
    options.layers.first_height = 0;
    const gen::MeshRun2 plain = g.run(in.pslg(), options);
    EXPECT_TRUE(plain.quads.empty());
    const gen::MixedMeshCheck2 check = gen::check_mixed_mesh_2d(
        plain.mesh.mesh.xy, plain.mesh.mesh.triangles, {}, plain.mesh.pieces);
    EXPECT_TRUE(check.ok()) << check.summary();
}

TEST(Generators_AdvancingLayers2, BadParametersAreRefused) {
    EXPECT_THROW(gen::parse_layer_parameters("0,1.2"), exactmesh::InputError);
    EXPECT_THROW(gen::parse_layer_parameters("-1e-4,1.2"), exactmesh::InputError);
    EXPECT_THROW(gen::parse_layer_parameters("1e-4,0.9"), exactmesh::InputError);
    EXPECT_THROW(gen::parse_layer_parameters("1e-4"), exactmesh::InputError);
    EXPECT_THROW(gen::parse_layer_parameters("1e-4,1.2,0"), exactmesh::InputError);
    EXPECT_THROW(gen::parse_layer_parameters("1e-4,1.2,2.5"), exactmesh::InputError);
    EXPECT_THROW(gen::parse_layer_parameters("nan,1.2"), exactmesh::InputError);
    EXPECT_THROW(gen::parse_layer_parameters("1e-4,x"), exactmesh::InputError);
    const gen::LayerParameters2 p = gen::parse_layer_parameters("1e-4,1.2,30");
    EXPECT_EQ(p.first_height, 1e-4);
    EXPECT_EQ(p.growth, 1.2);
    EXPECT_EQ(p.max_layers, 30u);
    EXPECT_EQ(gen::parse_layer_parameters("1e-4,1.2").max_layers, 60u);
}

TEST(Generators_AdvancingLayers2, TheCheckFindsAnInvertedTriangleAndANonConvexQuad) {
    const std::vector<double> xy{0, 0, 1, 0, 1, 1, 0, 1, 0.5, 0.25};
    const std::vector<tri::VertIdx> triangles{0, 2, 1};  // clockwise
    const std::vector<tri::VertIdx> quads{0, 1, 4, 3};   // reflex at 4
    const gen::MixedMeshCheck2 check = gen::check_mixed_mesh_2d(xy, triangles, quads, {});
    EXPECT_EQ(check.inverted_triangles.size(), 1u);
    EXPECT_EQ(check.nonconvex_quads.size(), 1u);
    EXPECT_FALSE(check.ok());
}

TEST(Generators_AdvancingLayers2, AGivenSizeEndsStacksWhoseAspectRatioNeverFallsTo1) {
    // Around a small circle the normals diverge: with growth 1.1 the width grows as fast as
    // the thickness and the aspect ratio stays above 1; the size (0.05) ends the stacks where
    // the next layer would be thicker than it.
    Input in = square(1);
    add_circle(in, 0, 0, 0.05, 24);
    const gen::AdvancingLayersResult2 free = run(in, 1e-3, 1.1, true);
    const gen::AdvancingLayersResult2 sized =
        run(in, 1e-3, 1.1, true, 60, gen::SizeFunction::uniform(0.05));
    EXPECT_EQ(free.counters.stopped_size, 0u);
    EXPECT_EQ(sized.counters.stopped_size, 24u);
    EXPECT_LT(sized.counters.layers, free.counters.layers);
    // 1e-3 * 1.1^k >= 0.05 first at k = 42: the 42 layers below it are kept.
    EXPECT_EQ(sized.counters.layers, 42u);
    expect_valid(sized);
    expect_input_kept(sized, in);
    expect_area(sized, in);
}

TEST(Generators_AdvancingLayers2, QuadQualityMeasuresAnglesAndAspectRatios) {
    const std::vector<double> xy{0, 0, 4, 0, 4, 1, 0, 1, 5, 1};
    const gen::QuadQuality2 rectangle =
        gen::quad_quality_2d(xy, std::vector<tri::VertIdx>{0, 1, 2, 3});
    EXPECT_EQ(rectangle.quads, 1u);
    EXPECT_NEAR(rectangle.min_angle, 90, 1e-12);
    EXPECT_NEAR(rectangle.max_angle, 90, 1e-12);
    EXPECT_EQ(rectangle.max_aspect_ratio, 4);
    const gen::QuadQuality2 trapezoid =
        gen::quad_quality_2d(xy, std::vector<tri::VertIdx>{0, 1, 4, 3});
    EXPECT_NEAR(trapezoid.min_angle, 45, 1e-12);
    EXPECT_NEAR(trapezoid.max_angle, 135, 1e-12);
    EXPECT_EQ(trapezoid.max_aspect_ratio, 5);
}

TEST(Generators_AdvancingLayers2, RandomStarHolesAndNarrowGapsGiveValidMixedMeshes) {
    // Random star-shaped holes (3 to 32 vertices, radii varying by a factor 3, so convex and
    // concave corners, fans, merges and steps all occur), one to three of them, or two pressed
    // against x = +-gap (gap 1e-1 to 1e-6: collinear wall vertices, opposing fronts); random
    // first height, growth, layer count, quads, size. The generator's own exact check must
    // hold (it throws otherwise) and the cells must cover the domain's area.
    const int cases = std::max(1, static_cast<int>(120 * exactmesh::testing::test_scale()));
    for (int c = 0; c < cases; ++c) {
        SCOPED_TRACE("case " + std::to_string(c));
        std::mt19937_64 rng(static_cast<std::uint64_t>(c));
        std::uniform_real_distribution<double> uniform(0, 1);
        const bool pressed = c % 3 == 2;
        const double gap = std::pow(10.0, -1 - 5 * uniform(rng));
        Input in = square(1);
        const int holes = pressed ? 2 : 1 + static_cast<int>(uniform(rng) * 3);
        const double centres[3][2] = {{-0.45, 0}, {0.45, 0}, {0, 0.55}};
        for (int h = 0; h < holes; ++h) {
            const int n = 3 + static_cast<int>(uniform(rng) * 30);
            const double cx = pressed ? (h == 0 ? -0.3 : 0.3) : centres[h][0];
            const double cy = pressed ? 0 : centres[h][1];
            std::vector<double> xy;
            for (int k = 0; k < n; ++k) {
                const double a = 2 * std::numbers::pi * (k + 0.4 * (uniform(rng) - 0.5)) / n;
                const double r = 0.12 + 0.3 * uniform(rng) * (uniform(rng) < 0.5 ? 1 : 0.3);
                double x = cx + r * std::cos(a);
                if (pressed) x = h == 0 ? std::min(x, -gap) : std::max(x, gap);
                xy.insert(xy.end(), {x, cy + r * std::sin(a)});
            }
            exactmesh::testing::add_loop(in, xy);
            in.holes.insert(in.holes.end(), {cx, cy});
        }
        const double height = std::pow(10.0, -1 - 4 * uniform(rng));
        const double growth = 1 + 0.5 * uniform(rng);
        const auto layers = 1 + static_cast<std::uint32_t>(uniform(rng) * 60);
        const bool quads = uniform(rng) < 0.5;
        const gen::SizeFunction size = uniform(rng) < 0.5
                                           ? gen::SizeFunction::uniform(0.05 + 0.2 * uniform(rng))
                                           : gen::SizeFunction();
        for (const gen::LayerMethod2 method :
             {gen::LayerMethod2::AdvancingLayers, gen::LayerMethod2::TruncatedOMesh}) {
            SCOPED_TRACE(method == gen::LayerMethod2::TruncatedOMesh ? "O-mesh" : "layers");
            const gen::AdvancingLayersResult2 r =
                run(in, height, growth, quads, layers, size, method);
            if (method == gen::LayerMethod2::AdvancingLayers) {
                EXPECT_GT(r.counters.layer_points, 0u);
            } else {
                // One ring per hole (fewer where random holes overlap into one loop).
                EXPECT_GE(r.counters.omesh_rings, 1u);
                EXPECT_LE(r.counters.omesh_rings, static_cast<std::uint64_t>(holes));
            }
            expect_valid(r);
            expect_input_kept(r, in);
            expect_area(r, in);
        }
    }
}

TEST(Generators_TruncatedOMesh2, AirfoilsGiveValidMixedMeshesQuadsOrSplit) {
    // The built-in NACA 0012 (one ring) and three-element airfoil (three rings, overlapping in
    // the gaps between slat, main element and flap) at the brief's 1e-4, 1.2.
    for (const auto& [which, rings] : {std::pair{gen::SampleDomain::Naca0012, 1u},
                                       std::pair{gen::SampleDomain::ThreeElement, 3u}}) {
        const Input in = exactmesh::testing::from_domain(gen::sample_domain(which));
        for (const bool quads : {true, false}) {
            SCOPED_TRACE(std::to_string(rings) + (quads ? " rings, quads" : " rings, split"));
            const gen::AdvancingLayersResult2 r =
                run(in, 1e-4, 1.2, quads, 60, {}, gen::LayerMethod2::TruncatedOMesh);
            const gen::AdvancingLayersCounters2& c = r.counters;
            EXPECT_EQ(c.omesh_rings, rings);
            EXPECT_EQ(c.wall_loops, rings);
            EXPECT_GE(c.omesh_min_ring_layers, 10u);  // 1e-4 * 1.2^k reaches the spacing
            EXPECT_LE(c.omesh_max_ring_layers, 60u);
            EXPECT_GT(c.omesh_cells, 0u);
            EXPECT_EQ(c.layer_quads, c.omesh_cells);
            EXPECT_EQ(c.quads, quads ? c.omesh_cells : 0u);
            EXPECT_EQ(c.layer_triangles, quads ? 0u : 2 * c.omesh_cells);
            EXPECT_EQ(c.stopped_collision + c.stopped_aspect_ratio + c.fan_corners, 0u);
            if (rings == 3) {
                // The gaps: the rings overlap there, and their coarser cells go.
                EXPECT_GT(c.omesh_removed_overlap, 0u);
            }
            // Every normal line keeps layers except where a cut took them; the steps between
            // neighbouring lines stay small (at most two layers per column).
            std::uint32_t layered = 0;
            for (const auto& [v, layers] : r.stack_layers) {
                EXPECT_LE(layers, c.omesh_max_ring_layers) << "line at " << v;
                if (layers > 0) ++layered;
            }
            EXPECT_GT(layered, r.stack_layers.size() / 2);
            expect_valid(r);
            expect_input_kept(r, in);
            expect_area(r, in);
        }
    }
}

TEST(Generators_TruncatedOMesh2, ScaledBy2ToThePlusMinus600GivesTheSameMeshScaled) {
    for (const gen::SampleDomain which :
         {gen::SampleDomain::Naca0012, gen::SampleDomain::ThreeElement}) {
        const Input in = exactmesh::testing::from_domain(
            gen::sample_domain(which, gen::SizeFunction::uniform(0.05)));
        const gen::AdvancingLayersResult2 reference =
            expect_scaled_the_same(in, 1e-3, 1.25, gen::LayerMethod2::TruncatedOMesh);
        EXPECT_GT(reference.counters.omesh_cells, 100u);
    }
}

TEST(Generators_TruncatedOMesh2, BadParametersAreRefused) {
    Input in = square(1);
    add_circle(in, 0, 0, 0.3, 16);
    const auto omesh = [&](double height, double growth, std::uint32_t layers) {
        return run(in, height, growth, false, layers, {}, gen::LayerMethod2::TruncatedOMesh);
    };
    EXPECT_THROW(omesh(-1e-3, 1.2, 10), exactmesh::InputError);
    EXPECT_THROW(omesh(std::nan(""), 1.2, 10), exactmesh::InputError);
    EXPECT_THROW(omesh(1e-3, 0.5, 10), exactmesh::InputError);
    EXPECT_THROW(omesh(1e-3, 11, 10), exactmesh::InputError);
    EXPECT_THROW(omesh(1e-3, 1.2, 0), exactmesh::InputError);
    EXPECT_THROW(omesh(1e-3, 1.2, gen::kMaxLayers + 1), exactmesh::InputError);
    // Called directly, it validates too.
    const gen::MeshDomain2 domain(in.pslg());
    gen::AdvancingLayersOptions2 options;
    options.fill = &frontal_fill;
    options.layers.first_height = 0;
    EXPECT_THROW(gen::truncated_omesh_2d(domain, options), exactmesh::InputError);
    // A valid run on the same input: one ring, layers all around.
    const gen::AdvancingLayersResult2 r = omesh(1e-3, 1.2, 10);
    EXPECT_EQ(r.counters.omesh_rings, 1u);
    EXPECT_EQ(r.counters.omesh_cells, 16u * r.counters.omesh_max_ring_layers);
    expect_valid(r);
}
