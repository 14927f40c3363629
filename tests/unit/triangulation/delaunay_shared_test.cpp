// SPDX-License-Identifier: MIT
// The pieces the 2D and 3D Delaunay code shares: report_first_occurrence (merged duplicates
// reported by their smallest caller index) and compact_cells, the algorithm registries'
// lookup (find_delaunay_algorithm), count_flip (flip_3d.hpp) and the comparison of two
// triangulations (compare_triangulations_2d.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "base/errors.hpp"
#include "tests/support/error_message.hpp"
#include "triangulation/checks/compare_triangulations_2d.hpp"
#include "triangulation/delaunay/bowyer_watson_3d.hpp"
#include "triangulation/delaunay/delaunay_2d.hpp"
#include "triangulation/delaunay/delaunay_3d.hpp"
#include "triangulation/delaunay/green_sibson_2d.hpp"
#include "triangulation/delaunay/result_numbering.hpp"
#include "triangulation/delaunay/tanemura_merriam_2d.hpp"
#include "triangulation/mesh/flip_3d.hpp"

namespace em = exactmesh;
namespace tri = exactmesh::triangulation;
using tri::VertIdx;

TEST(Triangulation_DelaunayShared, FirstOccurrenceNamesTheSmallestCallerIndexOfEachGroup) {
    // Caller points 1, 2 and 4 are equal, the mesh kept 4; 3 and 5 are equal, it kept 3.
    std::vector<VertIdx> merged_into = {0, 4, 4, 3, 4, 3};
    std::vector<VertIdx> input_index = {0, 4, 3};  // mesh vertex -> caller index
    tri::detail::report_first_occurrence(merged_into, input_index);
    EXPECT_EQ(merged_into, (std::vector<VertIdx>{0, 1, 1, 3, 1, 3}));
    EXPECT_EQ(input_index, (std::vector<VertIdx>{0, 1, 3}));
}

TEST(Triangulation_DelaunayShared, FirstOccurrenceLeavesDistinctPointsAlone) {
    std::vector<VertIdx> merged_into = {0, 1, 2, 3};
    std::vector<VertIdx> input_index = {2, 0, 3, 1};
    tri::detail::report_first_occurrence(merged_into, input_index);
    EXPECT_EQ(merged_into, (std::vector<VertIdx>{0, 1, 2, 3}));
    EXPECT_EQ(input_index, (std::vector<VertIdx>{2, 0, 3, 1}));
}

TEST(Triangulation_DelaunayShared, RegistriesFindTheirAlgorithmsAndNameTheKnownOnes) {
    EXPECT_EQ(tri::delaunay_2d_algorithm("green-sibson"), &tri::green_sibson_2d);
    EXPECT_EQ(tri::delaunay_2d_algorithm("tanemura-merriam"), &tri::tanemura_merriam_2d);
    EXPECT_EQ(tri::delaunay_3d_algorithm("bowyer-watson"), &tri::bowyer_watson_3d);
    const struct {
        std::function<void()> lookup;
        const char* message;
    } unknown[] = {
        {[] { tri::delaunay_2d_algorithm("lawson"); },
         "unknown 2D Delaunay algorithm 'lawson' (known: bowyer-watson, green-sibson, "
         "tanemura-merriam)"},
        {[] { tri::delaunay_3d_algorithm("tanemura-merriam"); },
         "unknown 3D Delaunay algorithm 'tanemura-merriam' (known: bowyer-watson, green-sibson)"},
    };
    for (const auto& c : unknown) {
        EXPECT_EQ(em::testing::error_message<em::InputError>(c.lookup), c.message);
    }
}

namespace {
struct AllFlips {
    std::uint64_t flips_23 = 0, flips_32 = 0, flips_44 = 0, flips_22 = 0;
};
struct NoFlip22 {
    std::uint64_t flips_23 = 0, flips_32 = 0, flips_44 = 0;
};
}  // namespace

TEST(Triangulation_DelaunayShared, CountFlipAddsOneToTheCounterOfItsKind) {
    using tri::FlipKind3;
    AllFlips all;
    NoFlip22 some;
    for (const FlipKind3 kind :
         {FlipKind3::Flip23, FlipKind3::Flip32, FlipKind3::Flip32, FlipKind3::Flip44,
          FlipKind3::Flip22, FlipKind3::Flip22, FlipKind3::Flip22, FlipKind3::None}) {
        tri::count_flip(all, kind);
        tri::count_flip(some, kind);
    }
    EXPECT_EQ(all.flips_23, 1u);
    EXPECT_EQ(all.flips_32, 2u);
    EXPECT_EQ(all.flips_44, 1u);
    EXPECT_EQ(all.flips_22, 3u);
    EXPECT_EQ(some.flips_23, 1u);
    EXPECT_EQ(some.flips_32, 2u);
    EXPECT_EQ(some.flips_44, 1u);
}

namespace {
/// Cells by slot: 'd' dead, 'i' infinite, 'f' finite.
struct FakeMesh {
    std::string kinds;
    bool is_dead(std::uint32_t t) const { return kinds[t] == 'd'; }
    bool is_infinite(std::uint32_t t) const { return kinds[t] == 'i'; }
};

/// compact_cells<3> of `mesh` with cell t's vertices 10t, 10t + 1, 10t + 2 (reported as
/// v + 1000) and neighbours across[3t + k] = 3 ((t + k + 1) % slots) + k, in `chunks` run in
/// reverse order (as threads might); returns the count, the numbers and both arrays.
struct Compacted {
    std::uint32_t count = 0;
    std::vector<std::uint32_t> output_index, vertices, across;
};
Compacted compact_fake(const FakeMesh& mesh, std::uint32_t slots, std::size_t chunks) {
    Compacted out;
    std::vector<VertIdx> first;
    for (std::uint32_t t = 0; t < mesh.kinds.size(); ++t) {
        for (std::uint32_t k = 0; k < 3; ++k) {
            out.vertices.push_back(10 * t + k);
            out.across.push_back(3 * ((t + k + 1) % slots) + k);
        }
    }
    for (VertIdx v = 0; v < 10 * mesh.kinds.size(); ++v) first.push_back(v + 1000);
    const tri::detail::ChunkRunner backwards = [](std::size_t count,
                                                  const std::function<void(std::size_t)>& body) {
        for (std::size_t c = count; c-- > 0;) body(c);
    };
    const std::vector<std::uint32_t>& numbers = out.output_index;
    out.count = tri::detail::compact_cells<3>(
        mesh, out.vertices, out.across, first, out.output_index, slots, chunks, backwards,
        [&numbers](std::uint32_t across) { return numbers[across / 3]; });
    return out;
}
}  // namespace

TEST(Triangulation_DelaunayShared, FiniteCellsAreNumberedAndMovedInSlotOrder) {
    const FakeMesh mesh{"fdifffid"};
    const Compacted c = compact_fake(mesh, 8, 1);
    EXPECT_EQ(c.count, 4u);
    const std::uint32_t none = tri::kNone;
    EXPECT_EQ(c.output_index, (std::vector<std::uint32_t>{0, none, none, 1, 2, 3, none, none}));
    // Output cell 1 is slot 3: vertices 30..32 reported as 1030..1032, neighbours the numbers
    // of slots 4, 5, 6.
    EXPECT_EQ(std::vector<std::uint32_t>(c.vertices.begin() + 3, c.vertices.begin() + 6),
              (std::vector<std::uint32_t>{1030, 1031, 1032}));
    EXPECT_EQ(std::vector<std::uint32_t>(c.across.begin() + 3, c.across.begin() + 6),
              (std::vector<std::uint32_t>{2, 3, none}));
    // Output cell 0 is slot 0 (neighbours: slots 1, 2, 3).
    EXPECT_EQ(std::vector<std::uint32_t>(c.across.begin(), c.across.begin() + 3),
              (std::vector<std::uint32_t>{none, none, 1}));
    // Only the first `slots` cells count.
    const Compacted first_four = compact_fake(mesh, 4, 1);
    EXPECT_EQ(first_four.count, 2u);
    EXPECT_EQ(first_four.output_index, (std::vector<std::uint32_t>{0, none, none, 1}));
}

TEST(Triangulation_DelaunayShared, CompactionInChunksGivesTheSequentialResult) {
    // Long runs of dead cells: later chunks' first cells land in earlier chunks' ranges.
    std::mt19937 rng(17);
    FakeMesh mesh;
    for (std::size_t t = 0; t < 40000; ++t) {
        const auto r = static_cast<std::uint32_t>(rng() % 100);
        mesh.kinds += (t > 15000 && t < 19000) || r < 10 ? 'd' : r < 13 ? 'i' : 'f';
    }
    const auto slots = static_cast<std::uint32_t>(mesh.kinds.size());
    const Compacted one = compact_fake(mesh, slots, 1);
    for (const std::size_t chunks : {2u, 3u, 7u, 64u}) {
        const Compacted many = compact_fake(mesh, slots, chunks);
        EXPECT_EQ(many.count, one.count) << chunks;
        EXPECT_EQ(many.output_index, one.output_index) << chunks;
        const std::size_t used = 3 * std::size_t{one.count};
        EXPECT_TRUE(
            std::equal(one.vertices.begin(), one.vertices.begin() + used, many.vertices.begin()))
            << chunks;
        EXPECT_TRUE(std::equal(one.across.begin(), one.across.begin() + used, many.across.begin()))
            << chunks;
    }
}

TEST(Triangulation_DelaunayShared, CanonicalTrianglesKeepOrientationAndIgnoreOrder) {
    // The same two triangles, listed in another order and rotated: equal canonical lists.
    const std::vector<VertIdx> a = {3, 1, 2, 0, 2, 1}, b = {1, 0, 2, 2, 3, 1};
    const auto ca = tri::canonical_triangles_2d(a), cb = tri::canonical_triangles_2d(b);
    EXPECT_EQ(ca, cb);
    EXPECT_EQ(ca, (std::vector<std::array<VertIdx, 3>>{{0, 2, 1}, {1, 2, 3}}));
    // The reversed triangle is another triangle (orientation kept).
    EXPECT_NE(tri::canonical_triangles_2d(std::vector<VertIdx>{0, 1, 2}),
              tri::canonical_triangles_2d(std::vector<VertIdx>{0, 2, 1}));
}

TEST(Triangulation_DelaunayShared, DuplicatePointsAreFoundWithSignedZerosEqual) {
    EXPECT_FALSE(tri::has_duplicate_points_2d(std::vector<double>{0, 0, 1, 0, 0, 1}));
    EXPECT_TRUE(tri::has_duplicate_points_2d(std::vector<double>{0, 0, 1, 0, -0.0, 0}));
    EXPECT_FALSE(tri::has_duplicate_points_2d(std::vector<double>{0, 1, 1, 0}));
}
