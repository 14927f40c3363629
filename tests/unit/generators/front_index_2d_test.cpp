// SPDX-License-Identifier: MIT
// Tests of generators/mesh_2d/front_index_2d.hpp (issue 12): the advancing fronts' shared loose
// quadtree reports exactly the live items whose box meets the query box, each once, through
// inserts and erasures, for points, short and long edges, and boxes on cell borders.
#include "generators/mesh_2d/front_index_2d.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

namespace gen = exactmesh::generators;

namespace {

std::vector<std::uint32_t> brute_force(const std::vector<gen::FrontBox2>& boxes,
                                       const std::vector<std::uint8_t>& alive,
                                       const gen::FrontBox2& query) {
    std::vector<std::uint32_t> found;
    for (std::uint32_t id = 0; id < boxes.size(); ++id) {
        if (alive[id] && boxes[id].meets(query)) found.push_back(id);
    }
    return found;
}

}  // namespace

TEST(FrontIndex2, ReportsExactlyTheLiveItemsWhoseBoxMeetsTheQuery) {
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> coordinate(0, 16);
    std::uniform_real_distribution<double> length(0, 2);
    gen::FrontIndex2 index(8, 8, 8);
    std::vector<gen::FrontBox2> boxes;
    std::vector<std::uint8_t> alive;
    std::vector<std::uint32_t> found;
    for (int round = 0; round < 40; ++round) {
        // 50 inserts: points (extent: a local size), edges; some on the quadrant borders.
        for (int k = 0; k < 50; ++k) {
            gen::FrontBox2 box;
            const double x = k % 7 == 0 ? 8 : coordinate(random);
            const double y = k % 11 == 0 ? 4 : coordinate(random);
            box.add(x, y);
            double extent = length(random);
            if (k % 3 != 0) {
                box.add(x + (k % 2 == 0 ? 1 : -1) * extent, y + length(random));
                extent = std::max(box.x1 - box.x0, box.y1 - box.y0);
            }
            const auto id = static_cast<std::uint32_t>(boxes.size());
            boxes.push_back(box);
            alive.push_back(1);
            index.insert(id, box, extent);
        }
        // Erase about a third of the live ones (twice for some: a no-op).
        for (std::uint32_t id = 0; id < boxes.size(); ++id) {
            if (random() % 3 == 0) {
                index.erase(id);
                alive[id] = 0;
            }
        }
        for (int q = 0; q < 20; ++q) {
            gen::FrontBox2 query;
            query.add(coordinate(random), coordinate(random));
            if (q % 4 != 0) query.add(query.x0 + length(random), query.y0 + length(random));
            found.clear();
            index.query(query, found);
            std::sort(found.begin(), found.end());
            ASSERT_EQ(std::adjacent_find(found.begin(), found.end()), found.end());  // once each
            ASSERT_EQ(found, brute_force(boxes, alive, query)) << "round " << round;
        }
    }
}

TEST(FrontIndex2, AnItemOutsideTheRootSquareIsStillFound) {
    gen::FrontIndex2 index(0, 0, 1);
    gen::FrontBox2 far;
    far.add(100, -50);
    index.insert(0, far, 0);
    std::vector<std::uint32_t> found;
    index.query(far, found);
    EXPECT_EQ(found, std::vector<std::uint32_t>{0});
    found.clear();
    gen::FrontBox2 near;
    near.add(0, 0);
    index.query(near, found);
    EXPECT_TRUE(found.empty());
}
