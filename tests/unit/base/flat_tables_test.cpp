// SPDX-License-Identifier: MIT
// Unit tests of base/flat_tables.hpp's FlatFlagSet32 (FlatKeyMap64 is exercised by the 3D
// generators' insertion, tests/unit/generators/edge_key_maps_test.cpp and their own tests).
#include "base/flat_tables.hpp"

#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <random>
#include <unordered_map>

TEST(Base_FlatFlagSet32, AgreesWithUnorderedMapThroughRoundsOfAdds) {
    // Rounds as the parallel refinement's: cleared for an expected count (sometimes far below
    // the keys added, so the table grows), then keys with flag 1, 2 or both ORed in; every key
    // asked has the flags a std::unordered_map of the round gives it (0 when absent), including
    // keys of earlier rounds, which a clear must forget.
    std::mt19937_64 engine(20261206);
    std::uniform_int_distribution<std::uint32_t> key(0, 5000);
    exactmesh::FlatFlagSet32 set;
    for (int round = 0; round < 300; ++round) {
        const std::size_t adds = engine() % 2000;
        set.clear(round % 3 == 0 ? adds / 16 : adds);
        std::unordered_map<std::uint32_t, unsigned> reference;
        for (std::size_t i = 0; i < adds; ++i) {
            const std::uint32_t k = key(engine);
            const unsigned flags = 1u + static_cast<unsigned>(engine() % 3);
            set.add(k, flags);
            reference[k] |= flags;
        }
        for (std::uint32_t k = 0; k <= 5000; k += 7) {
            const auto it = reference.find(k);
            ASSERT_EQ(set.flags(k), it == reference.end() ? 0u : it->second)
                << "round " << round << " key " << k;
        }
    }
    // The largest keys (a slot number near 2^32) are keys like any other.
    set.clear(4);
    set.add(0xFFFFFFFEu, 2);
    EXPECT_EQ(set.flags(0xFFFFFFFEu), 2u);
    EXPECT_EQ(set.flags(0xFFFFFFFDu), 0u);
    exactmesh::FlatFlagSet32 fresh;  // asked before any clear: empty
    EXPECT_EQ(fresh.flags(7), 0u);
    fresh.add(7, 1);
    EXPECT_EQ(fresh.flags(7), 1u);
}
