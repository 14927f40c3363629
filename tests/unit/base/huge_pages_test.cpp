// SPDX-License-Identifier: MIT
// Unit tests of base/huge_pages.hpp: the advice is a hint that never changes memory, whatever
// the range (large and aligned pages inside it, small, unaligned, empty). Whether the kernel
// then backs the range with huge pages depends on its settings and is not asserted.
#include "base/huge_pages.hpp"

#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <vector>

TEST(Base_HugePages, AdviceLeavesTheContentsAndTheVectorUsable) {
    std::vector<std::uint32_t> values;
    values.reserve(std::size_t{3} << 20);  // 12 MiB: whole 2 MiB pages inside
    for (std::uint32_t i = 0; i < (1u << 20); ++i) values.push_back(i * 2654435761u);
    exactmesh::advise_huge_pages(values);
    for (std::uint32_t i = 0; i < (1u << 20); ++i) ASSERT_EQ(values[i], i * 2654435761u) << i;
    // Growing into the advised capacity, then past it (a reallocation without the advice).
    for (std::uint32_t i = 1u << 20; i < (4u << 20); ++i) values.push_back(i);
    EXPECT_EQ(values[(3u << 20) + 5], (3u << 20) + 5);
    EXPECT_EQ(values[12345], 12345u * 2654435761u);
}

TEST(Base_HugePages, RangesWithoutAWholeHugePageAreLeftAlone) {
    std::vector<double> small(100, 1.5);
    exactmesh::advise_huge_pages(small);
    exactmesh::advise_huge_pages(small.data() + 1, 8 * sizeof(double));  // unaligned
    exactmesh::advise_huge_pages(nullptr, 0);
    std::vector<double> empty;
    exactmesh::advise_huge_pages(empty);
    for (const double v : small) EXPECT_EQ(v, 1.5);
    EXPECT_TRUE(empty.empty());
}
