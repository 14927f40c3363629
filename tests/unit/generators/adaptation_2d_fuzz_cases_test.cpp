// SPDX-License-Identifier: MIT
// The cases of fuzz_adaptation_2d (tests/fuzz/adaptation_2d_case.hpp) without sanitizers or
// clang, so the release CI runs them: the seeds scripts/fuzz_smoke gives the target (four shapes
// through each of the five methods: insertion, h-refinement, Steiner restart, global and local
// remeshing, with varied indicators, thresholds, fields, transient runs, smoothing and movement)
// and the target's saved past failures (tests/data/fuzz/adaptation_2d_*.bin). Every cycle and
// derefinement pass passes its exact check within the vertex budget, and h-refinement's
// refine-then-derefine returns the root exactly.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

#include "tests/fuzz/adaptation_2d_case.hpp"

namespace fz = exactmesh::fuzz;

namespace {

struct Shape {
    std::uint8_t mode;
    std::vector<std::pair<int, int>> segments;
    std::vector<std::pair<double, double>> points;
};

/// The seed bytes of scripts/fuzz_smoke (the same formula, in the same order).
std::vector<std::vector<std::uint8_t>> smoke_seeds() {
    const std::vector<Shape> shapes = {
        {0,
         {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 7}, {7, 4}},
         {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.4, 0.4}, {0.6, 0.4}, {0.6, 0.6}, {0.4, 0.6}}},
        {0, {{0, 1}, {1, 2}, {2, 0}}, {{0, 0}, {1, 0}, {0.985, 0.174}}},
        {0, {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 2}, {1, 3}}, {{0, 0}, {1, 0}, {1, 1}, {0, 1}}},
        {1, {{0, 1}, {1, 2}, {2, 3}, {3, 0}}, {{-4, -4}, {4, -3}, {3, 4}, {-3, 3}}},
    };
    std::vector<std::vector<std::uint8_t>> seeds;
    for (int method = 0; method < 5; ++method) {
        for (int i = 0; i < static_cast<int>(shapes.size()); ++i) {
            const Shape& s = shapes[static_cast<std::size_t>(i)];
            std::vector<std::uint8_t> raw{
                s.mode,
                static_cast<std::uint8_t>(method),
                static_cast<std::uint8_t>((i + method) % 4),
                static_cast<std::uint8_t>((method + 2 * i) % 8),
                static_cast<std::uint8_t>((7 * i + 5 * method) % 54),
                static_cast<std::uint8_t>(i % 4 + 4 * ((method + i) % 2) + 8 * (3 + i)),
                160,
                static_cast<std::uint8_t>(96 + 16 * method),
                static_cast<std::uint8_t>(64 + 16 * i),
                static_cast<std::uint8_t>(2 + 5 * ((method + i) % 5) + 25 * (i % 3)),
                static_cast<std::uint8_t>(s.segments.size())};
            for (const auto& [a, b] : s.segments) {
                raw.push_back(static_cast<std::uint8_t>(a));
                raw.push_back(static_cast<std::uint8_t>(b));
            }
            for (const auto& [x, y] : s.points) {
                for (const double v : {x, y}) {
                    std::uint8_t bytes[8];
                    std::memcpy(bytes, &v, 8);
                    raw.insert(raw.end(), bytes, bytes + 8);
                }
            }
            seeds.push_back(std::move(raw));
        }
    }
    return seeds;
}

/// Runs one input as the target does; returns what it ran (for the coverage assertions).
fz::AdaptationOutcome expect_case_passes(const std::vector<std::uint8_t>& raw,
                                         const std::string& what) {
    const auto c = fz::decode_adaptation_case(raw.data(), raw.size());
    if (!c) {
        ADD_FAILURE() << what << ": decodes to no case";
        return {};
    }
    const fz::AdaptationOutcome out = fz::run_adaptation_case(*c);
    EXPECT_EQ(out.problem, "") << what << ": " << fz::describe_adaptation_case(*c);
    return out;
}

}  // namespace

TEST(Generators_AdaptationFuzzCases, SmokeSeedsPassEveryCheck) {
    const auto seeds = smoke_seeds();
    ASSERT_EQ(seeds.size(), 20u);
    int meshed = 0, transient = 0;
    std::uint32_t cycles = 0;
    for (std::size_t i = 0; i < seeds.size(); ++i) {
        const fz::AdaptationOutcome out = expect_case_passes(
            seeds[i], "seed-" + std::to_string(i / 4) + "-0" + std::to_string(i % 4));
        meshed += out.meshed ? 1 : 0;
        transient += out.derefinement_passes > 0 ? 1 : 0;
        cycles += out.cycles_run;
        // Every seed is a valid domain: the first mesh must be made.
        EXPECT_TRUE(out.meshed) << "seed " << i << ": " << out.expected_error;
    }
    EXPECT_EQ(meshed, 20);
    // The seeds reach the transient path and run real cycles (not only early stops).
    EXPECT_GT(transient, 0);
    EXPECT_GE(cycles, 20u);
}

TEST(Generators_AdaptationFuzzCases, SavedFailuresPassEveryCheck) {
    const std::filesystem::path dir =
        std::filesystem::path(EXACTMESH_SOURCE_DIR) / "tests" / "data" / "fuzz";
    int replayed = 0;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        const std::string name = entry.path().filename().string();
        if (name.rfind("adaptation_2d_", 0) != 0 || entry.path().extension() != ".bin") continue;
        std::ifstream in(entry.path(), std::ios::binary);
        const std::vector<std::uint8_t> raw{std::istreambuf_iterator<char>(in),
                                            std::istreambuf_iterator<char>()};
        (void)expect_case_passes(raw, name);
        ++replayed;
    }
    // No saved failure yet is fine; the directory itself must exist.
    EXPECT_GE(replayed, 0);
}
