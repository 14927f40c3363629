// SPDX-License-Identifier: MIT
// Tests of base/counter_table.hpp: a name table lists every field once, in order, and the
// generators' tables keep the names --stats printed before the tables (issue 12).
#include "base/counter_table.hpp"

#include <gtest/gtest.h>

#include <array>
#include <string>
#include <string_view>

#include "generators/mesh_2d/advancing_front_2d.hpp"
#include "generators/mesh_2d/mesh_generators_2d.hpp"
#include "generators/mesh_2d/quadtree_mesh_2d.hpp"
#include "triangulation/delaunay/delaunay_2d.hpp"

namespace gen = exactmesh::generators;

namespace {

struct ThreeCounters {
    std::uint64_t first = 0;
    std::uint32_t second = 0;
    std::uint64_t third = 0;
};

constexpr std::array kAll{exactmesh::counter("first", &ThreeCounters::first),
                          exactmesh::counter("second", &ThreeCounters::second),
                          exactmesh::counter("third", &ThreeCounters::third)};
constexpr std::array kMissing{exactmesh::counter("first", &ThreeCounters::first),
                              exactmesh::counter("third", &ThreeCounters::third)};
constexpr std::array kTwice{exactmesh::counter("first", &ThreeCounters::first),
                            exactmesh::counter("again", &ThreeCounters::first),
                            exactmesh::counter("third", &ThreeCounters::third)};
// The same table as kAll, each name written once.
constexpr std::array kByMacro = EM_COUNTER_TABLE(ThreeCounters, first, second, third);

/// Same names, same fields (64- and 32-bit), in the same order.
template <class Counters, std::size_t N>
constexpr bool same_rows(const std::array<exactmesh::CounterName<Counters>, N>& a,
                         const std::array<exactmesh::CounterName<Counters>, N>& b) {
    for (std::size_t i = 0; i < N; ++i) {
        if (a[i].name != b[i].name || a[i].field != b[i].field ||
            a[i].narrow_field != b[i].narrow_field || a[i].is_derived != b[i].is_derived)
            return false;
    }
    return true;
}

}  // namespace

TEST(CounterTable, CompleteOnlyWhenEveryFieldIsNamedOnce) {
    static_assert(exactmesh::counter_table_complete(kAll));
    static_assert(!exactmesh::counter_table_complete(kMissing));
    static_assert(!exactmesh::counter_table_complete(kTwice));
    // A derived row is allowed only when declared.
    static_assert(!exactmesh::counter_table_complete(kAll, 1));
    EXPECT_TRUE(exactmesh::counter_table_complete(kAll));
}

TEST(CounterTable, ListsNamesAndValuesInTableOrder) {
    const ThreeCounters c{7, 11, 13};
    const auto list = exactmesh::counters_by_name(kAll, c);
    ASSERT_EQ(list.size(), 3u);
    EXPECT_EQ(list[0], (std::pair<std::string, std::uint64_t>{"first", 7}));
    EXPECT_EQ(list[1], (std::pair<std::string, std::uint64_t>{"second", 11}));
    EXPECT_EQ(list[2], (std::pair<std::string, std::uint64_t>{"third", 13}));
}

TEST(CounterTable, GeneratorTablesKeepTheirNames) {
    gen::RefinementCounters2 r;
    r.circumcenters = 3;
    r.segment_splits = 4;
    r.flips = 9;
    const auto refinement = gen::counter_list(r);
    ASSERT_EQ(refinement.size(), 23u);
    EXPECT_EQ(refinement.front(), (std::pair<std::string, std::uint64_t>{"steiner_points", 7}));
    EXPECT_EQ(refinement[13], (std::pair<std::string, std::uint64_t>{"delaunay_flips", 9}));
    EXPECT_EQ(refinement[19].first, "polish_stopped");
    EXPECT_EQ(refinement.back().first, "threads");
    gen::QuadtreeCounters2 q;
    q.depth = 5;
    q.leaf_bound = 11;
    const auto quadtree = gen::counter_list(q);
    ASSERT_EQ(quadtree.size(), 24u);
    EXPECT_EQ(quadtree[1], (std::pair<std::string, std::uint64_t>{"leaf_bound", 11}));
    EXPECT_EQ(quadtree[6], (std::pair<std::string, std::uint64_t>{"depth", 5}));
    EXPECT_EQ(quadtree.back().first, "band_piece_splits");
    const auto front = gen::counter_list(gen::AdvancingFrontCounters2{});
    ASSERT_EQ(front.size(), 13u);
    EXPECT_EQ(front.back().first, "orient_calls");
}

TEST(CounterTable, MacroNamesEachRowAfterItsMember) {
    static_assert(kByMacro.size() == 3);
    static_assert(same_rows(kByMacro, kAll));
    static_assert(exactmesh::counter_table_complete(kByMacro));
    const ThreeCounters c{7, 11, 13};
    EXPECT_EQ(exactmesh::counters_by_name(kByMacro, c), exactmesh::counters_by_name(kAll, c));
    // A table built by the macro, against the rows it was written as before.
    namespace tri = exactmesh::triangulation;
    using D = tri::Delaunay2Counters;
    constexpr std::array kDelaunay2Before{
        exactmesh::counter("points", &D::points),
        exactmesh::counter("duplicates", &D::duplicates),
        exactmesh::counter("orient_calls", &D::orient_calls),
        exactmesh::counter("incircle_calls", &D::incircle_calls),
        exactmesh::counter("walk_steps", &D::walk_steps),
        exactmesh::counter("cavity_triangles", &D::cavity_triangles),
        exactmesh::counter("flips", &D::flips),
        exactmesh::counter("candidates", &D::candidates),
        exactmesh::counter("threads", &D::threads),
        exactmesh::counter("sequential_prefix", &D::sequential_prefix),
        exactmesh::counter("parallel_rounds", &D::parallel_rounds),
        exactmesh::counter("parallel_points", &D::parallel_points),
        exactmesh::counter("deferred_points", &D::deferred_points),
        exactmesh::counter("sequential_tail", &D::sequential_tail),
        exactmesh::counter("order_microseconds", &D::order_microseconds),
        exactmesh::counter("keys_microseconds", &D::keys_microseconds),
        exactmesh::counter("sequential_microseconds", &D::sequential_microseconds),
        exactmesh::counter("partition_microseconds", &D::partition_microseconds),
        exactmesh::counter("parallel_microseconds", &D::parallel_microseconds),
        exactmesh::counter("result_microseconds", &D::result_microseconds)};
    static_assert(same_rows(tri::kDelaunay2CounterNames, kDelaunay2Before));
    EXPECT_EQ(tri::kDelaunay2CounterNames.size(), 20u);
}
