// SPDX-License-Identifier: MIT
// Insertion orders (triangulation/mesh/spatial_sort): the Hilbert keys follow a Hilbert curve
// (consecutive keys are grid neighbours); the BRIO order is its definition (the shuffled
// points' rounds, as brio_rounds cuts them, stably sorted by key), the same on several threads
// as on one, for sizes around the rounds' edges and with many equal keys.
#include <gtest/gtest.h>

#include <tbb/task_arena.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <numeric>
#include <vector>

#include "generators/inputs/inputs.hpp"
#include "triangulation/delaunay/parallel_rounds.hpp"
#include "triangulation/mesh/spatial_sort.hpp"

namespace tri = exactmesh::triangulation;
namespace gen = exactmesh::generators;

namespace {

/// Points on a side x side lattice (side a power of two up to 256): the top 2 log2(side) bits
/// of a point's key are its cell's place on the Hilbert curve of that order.
std::vector<double> lattice(std::uint32_t side) {
    std::vector<double> xy;
    for (std::uint32_t i = 0; i < side; ++i) {
        for (std::uint32_t j = 0; j < side; ++j) {
            xy.push_back(i);
            xy.push_back(j);
        }
    }
    return xy;
}

TEST(Triangulation_SpatialSort, HilbertKeysOfALatticeWalkFromNeighbourToNeighbour) {
    for (const std::uint32_t side : {2u, 16u, 256u}) {
        const std::vector<double> xy = lattice(side);
        const std::vector<std::uint32_t> keys = tri::hilbert_keys_2d(xy);
        int bits = 0;
        while ((1u << bits) < side) ++bits;
        // Cell (i, j) spans grid cells i (65535 / (side - 1)) .. : its top bits are i's.
        std::vector<std::uint32_t> at(side * side, UINT32_MAX);  // curve place -> point
        for (std::uint32_t p = 0; p < side * side; ++p) {
            const std::uint32_t place = keys[p] >> (32 - 2 * bits);
            ASSERT_EQ(at[place], UINT32_MAX) << "two cells at place " << place;
            at[place] = p;
        }
        for (std::uint32_t place = 0; place + 1 < side * side; ++place) {
            const std::uint32_t p = at[place], q = at[place + 1];
            const int di = std::abs(static_cast<int>(p / side) - static_cast<int>(q / side));
            const int dj = std::abs(static_cast<int>(p % side) - static_cast<int>(q % side));
            EXPECT_EQ(di + dj, 1) << "side " << side << ", places " << place << " and "
                                  << place + 1;
        }
        EXPECT_EQ(at[0], 0u);  // the curve starts at the lower left corner
    }
}

TEST(Triangulation_SpatialSort, HilbertKeys3dOfALatticeWalkFromNeighbourToNeighbour) {
    const std::uint32_t side = 16;  // 4 bits per axis: the keys' top 12 of 30 bits
    std::vector<double> xyz;
    for (std::uint32_t i = 0; i < side; ++i)
        for (std::uint32_t j = 0; j < side; ++j)
            for (std::uint32_t k = 0; k < side; ++k) {
                xyz.push_back(i);
                xyz.push_back(j);
                xyz.push_back(k);
            }
    const std::vector<std::uint32_t> keys = tri::hilbert_keys_3d(xyz);
    const std::uint32_t count = side * side * side;
    std::vector<std::uint32_t> at(count, UINT32_MAX);
    for (std::uint32_t p = 0; p < count; ++p) {
        const std::uint32_t place = keys[p] >> (30 - 12);
        ASSERT_EQ(at[place], UINT32_MAX);
        at[place] = p;
    }
    for (std::uint32_t place = 0; place + 1 < count; ++place) {
        const std::uint32_t p = at[place], q = at[place + 1];
        int distance = 0;
        for (const std::uint32_t scale : {side * side, side, 1u}) {
            distance +=
                std::abs(static_cast<int>(p / scale % side) - static_cast<int>(q / scale % side));
        }
        EXPECT_EQ(distance, 1) << "places " << place << " and " << place + 1;
    }
}

TEST(Triangulation_SpatialSort, BrioRoundsGrowByEight) {
    for (const std::uint32_t n :
         {0u, 1u, 64u, 65u, 519u, 520u, 1000u, 4096u, 1000000u, 0x3FFFFFFFu}) {
        const std::vector<std::uint32_t> begin = tri::brio_round_begins(n);
        ASSERT_GE(begin.size(), 2u) << n;
        EXPECT_EQ(begin.front(), 0u) << n;
        EXPECT_EQ(begin.back(), n) << n;
        EXPECT_LE(begin.size() > 2 ? begin[1] : n, 64u) << n << ": the first round is small";
        for (std::size_t r = 1; r + 1 < begin.size(); ++r) {
            EXPECT_EQ(begin[r], begin[r + 1] >> 3) << n << " round " << r;
            EXPECT_GT(begin[r + 1], 64u) << n << " round " << r;
        }
    }
    EXPECT_EQ(tri::brio_round_begins(1000000u),
              (std::vector<std::uint32_t>{0, 30, 244, 1953, 15625, 125000, 1000000}));
}

/// The BRIO order by its definition: the shuffled points' rounds (brio_rounds' cuts), each but
/// the first sorted by key with a stable sort.
std::vector<std::uint32_t> reference_brio(const std::vector<std::uint32_t>& keys,
                                          std::uint64_t seed) {
    std::vector<std::uint32_t> perm = tri::random_permutation(keys.size(), seed);
    const tri::detail::BrioRounds rounds =
        tri::detail::brio_rounds(static_cast<std::uint32_t>(keys.size()), 1, 1);
    for (std::size_t r = 0; r + 1 < rounds.begin.size(); ++r) {
        std::stable_sort(perm.begin() + rounds.begin[r], perm.begin() + rounds.begin[r + 1],
                         [&](std::uint32_t a, std::uint32_t b) { return keys[a] < keys[b]; });
    }
    return perm;
}

TEST(Triangulation_SpatialSort, BrioOrderIsItsDefinitionOnAnyThreadCount) {
    tbb::task_arena arena(2);
    for (const std::uint32_t n :
         {0u,   1u,   3u,    64u,   65u,   127u,  128u,   129u,   511u,    512u,    513u,
          519u, 520u, 1000u, 4095u, 4096u, 4097u, 65536u, 65537u, 200001u, 262143u, 262144u}) {
        const std::vector<double> xy = gen::generate_points_2d(gen::Distribution::Gaussian, n, 7);
        const std::vector<std::uint32_t> keys = tri::hilbert_keys_2d(xy);
        const std::vector<std::uint32_t> order =
            tri::insertion_order_2d(xy, tri::InsertionOrder::Brio, 5);
        EXPECT_EQ(order, reference_brio(keys, 5)) << n;
        const std::vector<std::uint32_t> position =
            tri::inverse_permutation(tri::random_permutation(n, 5));
        EXPECT_EQ(order, tri::brio_order(keys, position)) << n;
        std::vector<std::uint32_t> parallel, parallel_position;
        arena.execute([&] {
            parallel_position = tri::inverse_permutation(tri::random_permutation(n, 5), true);
            parallel = tri::brio_order(keys, parallel_position, true);
        });
        EXPECT_EQ(position, parallel_position) << n;
        EXPECT_EQ(order, parallel) << n;
    }
}

TEST(Triangulation_SpatialSort, EqualKeysComeInTheShuffledOrder) {
    // 1,000 copies of 10 points (runs of equal keys), and a grid (many keys shared by the 2^16
    // grid's cells): equal keys keep the shuffle's order, as a stable sort of the shuffled
    // rounds would; the first round stays shuffled; seeds differ.
    std::vector<double> copies;
    for (int copy = 0; copy < 1000; ++copy) {
        for (int i = 0; i < 10; ++i) {
            copies.push_back(i);
            copies.push_back(i * i);
        }
    }
    std::vector<double> fine;
    for (int i = 0; i < 300; ++i) {
        for (int j = 0; j < 300; ++j) {
            fine.push_back(i == 0 && j == 0 ? 1e6 : i * 1e-3);
            fine.push_back(j * 1e-3);
        }
    }
    for (const std::vector<double>* xy : {&copies, &fine}) {
        const std::vector<std::uint32_t> keys = tri::hilbert_keys_2d(*xy);
        const std::vector<std::uint32_t> order =
            tri::insertion_order_2d(*xy, tri::InsertionOrder::Brio, 3);
        EXPECT_EQ(order, reference_brio(keys, 3));
        std::vector<std::uint32_t> parallel;
        tbb::task_arena arena(2);
        arena.execute(
            [&] { parallel = tri::insertion_order_2d(*xy, tri::InsertionOrder::Brio, 3, true); });
        EXPECT_EQ(order, parallel);
        EXPECT_NE(order, tri::insertion_order_2d(*xy, tri::InsertionOrder::Brio, 4));
    }
    EXPECT_NE(tri::random_permutation(1000, 3), tri::random_permutation(1000, 4));
    const std::vector<std::uint32_t> perm = tri::random_permutation(1000, 3);
    const std::vector<std::uint32_t> inverse = tri::inverse_permutation(perm);
    for (std::uint32_t k = 0; k < 1000; ++k) EXPECT_EQ(inverse[perm[k]], k);
}

}  // namespace
