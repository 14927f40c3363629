// SPDX-License-Identifier: MIT
// Unit tests of generators/mesh_3d/edge_key_maps.hpp (the maps of the 3D generators' insertion,
// restricted_delaunay_3d.hpp, tested through the generators as well).
#include "generators/mesh_3d/edge_key_maps.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <unordered_map>
#include <utility>
#include <vector>

namespace rd = exactmesh::generators::restricted_3d;

TEST(Generators_KeyMap64, AgreesWithUnorderedMapThroughInsertsAndErases) {
    // Random edge keys from a small vertex range (many repeats), inserted and erased in turn so
    // that tombstones pile up and rehashes run both to grow and to clean: every lookup, the
    // size of the entry list and the entries themselves agree with std::unordered_map.
    std::mt19937_64 engine(20261205);
    std::uniform_int_distribution<std::uint32_t> vertex(0, 400);
    rd::KeyMap64<std::uint32_t> map;
    std::unordered_map<std::uint64_t, std::uint32_t> reference;
    for (int step = 0; step < 200000; ++step) {
        const std::uint32_t a = vertex(engine), b = vertex(engine);
        const std::uint64_t key = (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b);
        if (engine() % 3 == 0) {
            map.erase(key);
            reference.erase(key);
        } else {
            const auto value = static_cast<std::uint32_t>(step);
            EXPECT_EQ(map.emplace(key, value), reference.emplace(key, value).second);
        }
        const std::uint32_t* found = map.find(key);
        const auto it = reference.find(key);
        ASSERT_EQ(found != nullptr, it != reference.end()) << step;
        if (found != nullptr) {
            EXPECT_EQ(*found, it->second);
            EXPECT_EQ(map.at(key), it->second);
        }
        EXPECT_EQ(map.count(key), reference.count(key));
    }
    auto entries = map.entries();
    std::vector<std::pair<std::uint64_t, std::uint32_t>> expected(reference.begin(),
                                                                  reference.end());
    std::sort(entries.begin(), entries.end());
    std::sort(expected.begin(), expected.end());
    EXPECT_EQ(entries, expected);
    EXPECT_THROW(static_cast<void>(map.at(~std::uint64_t{0})), exactmesh::InternalError);
}
