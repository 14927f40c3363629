// SPDX-License-Identifier: MIT
// The pieces the 2D and 3D Delaunay code shares: report_first_occurrence (merged duplicates
// reported by their smallest caller index) and number_finite_cells, the algorithm registries'
// lookup (find_delaunay_algorithm), count_flip (flip_3d.hpp) and the comparison of two
// triangulations (compare_triangulations_2d.hpp).
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <functional>
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
}  // namespace

TEST(Triangulation_DelaunayShared, FiniteCellsAreNumberedConsecutivelyInSlotOrder) {
    const FakeMesh mesh{"fdifffid"};
    std::vector<std::uint32_t> output_index = {7, 7};  // replaced, not appended to
    EXPECT_EQ(tri::detail::number_finite_cells(mesh, 8, output_index), 4u);
    const std::uint32_t none = tri::kNone;
    EXPECT_EQ(output_index, (std::vector<std::uint32_t>{0, none, none, 1, 2, 3, none, none}));
    // Only the first `slots` cells count.
    EXPECT_EQ(tri::detail::number_finite_cells(mesh, 4, output_index), 2u);
    EXPECT_EQ(output_index, (std::vector<std::uint32_t>{0, none, none, 1}));
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
