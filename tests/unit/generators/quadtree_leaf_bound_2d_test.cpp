// SPDX-License-Identifier: MIT
// The quadtree's lower bound on the leaves its feature criterion forces (quadtree_leaf_bound_2d):
// its value on two parallel pieces, the pairs it leaves out (pieces of one segment, a shared
// vertex, a narrow wedge), the same bits at 2^±600, never above the leaves the tree builds
// (combs of fingers 1e-2 to 1e-4 wide, turned, at graded and uniform sizes), and a comb far too
// fine refused before the tree with the bound in its message, the same at 2^±600.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "base/errors.hpp"
#include "generators/boundary/graded_boundary_size_2d.hpp"
#include "generators/mesh_2d/quadtree_leaf_bound_2d.hpp"
#include "generators/mesh_2d/quadtree_mesh_2d.hpp"
#include "tests/support/pslg_fixtures_2d.hpp"

namespace em = exactmesh;
namespace gen = exactmesh::generators;

namespace {

using exactmesh::testing::Input;

bool never_narrow(std::uint32_t, std::uint32_t) {
    return false;
}

/// Two vertical pieces of length `length` at distance `gap`, segments 0 and 1, scaled by `scale`.
std::vector<gen::FeaturePiece2> parallel_pieces(double length, double gap, double scale) {
    return {{{0, 0}, {0, length * scale}, 0, 1, 0},
            {{gap * scale, 0}, {gap * scale, length * scale}, 2, 3, 1}};
}

gen::QuadtreeFrame2 frame(double scale) {
    gen::QuadtreeFrame2 f;
    f.x0 = -scale, f.y0 = -scale, f.side = 4 * scale;
    f.smallest_side = std::ldexp(f.side, -28);
    f.margin = 0.25;
    return f;
}

/// The rectangle [-1, 1] x [-1, 0] with fingers of the given widths standing on its top (each
/// 0.1 to 0.9 high, at random places), turned by `angle` about the origin.
Input comb(const std::vector<double>& widths, double angle, std::mt19937_64& random) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<double> outline = {-1, -1, 1, -1, 1, 0};
    const double slot = 1.8 / static_cast<double>(widths.size());
    for (std::size_t k = widths.size(); k-- > 0;) {
        const double x = -0.9 + slot * (static_cast<double>(k) + 0.1 + 0.5 * unit(random));
        const double depth = 0.1 + 0.8 * unit(random);
        outline.insert(outline.end(), {x + widths[k], 0, x + widths[k], depth, x, depth, x, 0});
    }
    outline.insert(outline.end(), {-1, 0});
    const double c = std::cos(angle), s = std::sin(angle);
    for (std::size_t i = 0; i < outline.size(); i += 2) {
        const double x = outline[i], y = outline[i + 1];
        outline[i] = c * x - s * y, outline[i + 1] = s * x + c * y;
    }
    Input in;
    em::testing::add_loop(in, outline);
    return in;
}

Input scaled(Input in, int exponent) {
    for (double& v : in.xy) v = std::ldexp(v, exponent);
    return in;
}

}  // namespace

TEST(Generators_QuadtreeLeafBound2, TwoParallelPiecesGiveTheMarginTimesLengthOverGap) {
    // A leaf on one piece is at most gap / margin wide: length·margin / gap of them at least.
    const gen::QuadtreeLeafBound2 b =
        gen::quadtree_leaf_bound_2d(parallel_pieces(0.5, 1e-3, 1), frame(1), never_narrow);
    EXPECT_NEAR(b.leaves, 0.25 * 0.5 / 1e-3, 1e-6 * 125);
    EXPECT_EQ(b.pairs, 1u);
    EXPECT_NEAR(b.closest_gap, 1e-3, 1e-15);  // in the square's coordinates, rounded there
    // The same bits at every scale 2^k.
    for (const int k : {-600, 600}) {
        const double scale = std::ldexp(1.0, k);
        const gen::QuadtreeLeafBound2 s = gen::quadtree_leaf_bound_2d(
            parallel_pieces(0.5, 1e-3, scale), frame(scale), never_narrow);
        EXPECT_EQ(s.leaves, b.leaves) << k;
        EXPECT_EQ(s.closest_gap, std::ldexp(b.closest_gap, k)) << k;
    }
    // Turned by 45 degrees, a square holds sqrt(2) times more of a piece: the bound drops so.
    const double r = std::sqrt(0.5);
    const std::vector<gen::FeaturePiece2> turned = {
        {{0, 0}, {0.5 * r, 0.5 * r}, 0, 1, 0},
        {{1e-3 * r, -1e-3 * r}, {(0.5 + 1e-3) * r, (0.5 - 1e-3) * r}, 2, 3, 1}};
    EXPECT_NEAR(gen::quadtree_leaf_bound_2d(turned, frame(1), never_narrow).leaves,
                0.25 * 0.5 / 1e-3 * r, 1e-3 * 125);
}

TEST(Generators_QuadtreeLeafBound2, PiecesTheTreeDoesNotSeparateCountNothing) {
    std::vector<gen::FeaturePiece2> pieces = parallel_pieces(0.5, 1e-9, 1);
    pieces[1].segment = 0;  // one segment
    EXPECT_EQ(gen::quadtree_leaf_bound_2d(pieces, frame(1), never_narrow).leaves, 0.0);
    pieces = parallel_pieces(0.5, 1e-9, 1);
    pieces[1].vb = 0;  // a shared vertex
    EXPECT_EQ(gen::quadtree_leaf_bound_2d(pieces, frame(1), never_narrow).leaves, 0.0);
    pieces = parallel_pieces(0.5, 1e-9, 1);
    EXPECT_EQ(gen::quadtree_leaf_bound_2d(pieces, frame(1),
                                          [](std::uint32_t, std::uint32_t) {
                                              return true;  // a narrow wedge
                                          })
                  .leaves,
              0.0);
    // Far apart: a bound, not above the one leaf each piece's square needs.
    EXPECT_LE(
        gen::quadtree_leaf_bound_2d(parallel_pieces(0.5, 1, 1), frame(1), never_narrow).leaves,
        1.0);
}

TEST(Generators_QuadtreeLeafBound2, NeverAboveTheLeavesTheTreeBuilds) {
    std::mt19937_64 random(20261207);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int run = 0; run < 24; ++run) {
        std::vector<double> widths(1 + run % 4);
        for (double& w : widths) w = std::pow(10.0, -2 - 2 * unit(random));
        const double angle = run % 3 == 0 ? 0.0 : 6.283185307179586 * unit(random);
        const Input in = comb(widths, angle, random);
        gen::QuadtreeOptions2 options;
        options.size = run % 2 == 0 ? gen::graded_size_from_boundary(in.pslg())
                                    : gen::SizeFunction::uniform(0.05);
        const gen::QuadtreeResult2 r = gen::quadtree_mesh_2d(in.pslg(), options);
        const gen::QuadtreeCounters2& c = r.counters;
        EXPECT_GT(c.leaf_bound, 0u) << run;
        EXPECT_LE(c.leaf_bound, c.leaves) << run;
        std::printf("comb %2d: %zu fingers, narrowest %.2e, turned %.3f: bound %llu, leaves %llu\n",
                    run, widths.size(), *std::min_element(widths.begin(), widths.end()), angle,
                    static_cast<unsigned long long>(c.leaf_bound),
                    static_cast<unsigned long long>(c.leaves));
    }
}

TEST(Generators_QuadtreeLeafBound2, FarTooFineCombIsRefusedBeforeTheTree) {
    // One finger 1e-10 wide and 0.1 to 0.9 long: billions of leaves. The bound alone refuses it
    // (its message: "at least N leaves"), the same N at 2^±600.
    std::mt19937_64 random(7);
    const Input in = comb({1e-10}, 0.3, random);
    std::string first;
    for (const int k : {0, -600, 600}) {
        const Input s = scaled(in, k);
        gen::QuadtreeOptions2 options;
        options.size = gen::graded_size_from_boundary(s.pslg());
        try {
            gen::quadtree_mesh_2d(s.pslg(), options);
            ADD_FAILURE() << "meshed at 2^" << k;
        } catch (const em::InputError& e) {
            const std::string what = e.what();
            const std::size_t at = what.find("at least ");
            ASSERT_NE(at, std::string::npos) << what;
            const std::string count = what.substr(at, what.find(" leaves", at) - at);
            if (k == 0) first = count;
            EXPECT_EQ(count, first) << what;
        }
    }
}
