// SPDX-License-Identifier: MIT
// The cases of fuzz_tetmesh_3d (tests/fuzz/tetmesh_3d_case.hpp) without sanitizers or clang, so
// the release CI runs them: its seeds and saved findings, tests/data/fuzz/tetmesh_3d_*.bin
// (each PLC form through each 3D generator, free vertices on and 1e-12..1e-300 near the
// surface, at 2^0 and 2^+-300). Each must end meshed with every check passed (conformity, input
// vertices kept, the radius-edge bound after refinement) or with InputError or GeometryError.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "tests/fuzz/tetmesh_3d_case.hpp"

namespace fz = exactmesh::fuzz;

namespace {

std::vector<std::filesystem::path> saved_cases() {
    std::vector<std::filesystem::path> paths;
    const std::filesystem::path folder =
        std::filesystem::path(EXACTMESH_SOURCE_DIR) / "tests" / "data" / "fuzz";
    for (const auto& entry : std::filesystem::directory_iterator(folder)) {
        const std::string name = entry.path().filename().string();
        if (name.starts_with("tetmesh_3d_") && name.ends_with(".bin"))
            paths.push_back(entry.path());
    }
    std::sort(paths.begin(), paths.end());
    return paths;
}

}  // namespace

TEST(Generators_TetmeshFuzzCases, SeedsAndFindingsPassEveryCheck) {
    const std::vector<std::filesystem::path> paths = saved_cases();
    ASSERT_GE(paths.size(), 30u) << "the seeds of scripts/fuzz_smoke are missing";
    std::array<int, static_cast<std::size_t>(fz::TetmeshGenerator::Count)> meshed{};
    std::array<int, static_cast<std::size_t>(fz::TetmeshForm::Count)> meshed_forms{};
    for (const auto& path : paths) {
        std::ifstream in(path, std::ios::binary);
        const std::vector<std::uint8_t> data{std::istreambuf_iterator<char>(in),
                                             std::istreambuf_iterator<char>()};
        ASSERT_FALSE(data.empty()) << path;
        const fz::TetmeshCase c = fz::decode_tetmesh_case(data.data(), data.size());
        const fz::TetmeshOutcome outcome = fz::run_tetmesh_case(c);
        EXPECT_EQ(outcome.failure, "") << path << "\n" << fz::describe_tetmesh_case(c);
        EXPECT_TRUE(outcome.meshed || !outcome.error.empty()) << path;
        if (outcome.meshed) {
            ++meshed[static_cast<std::size_t>(c.generator)];
            ++meshed_forms[static_cast<std::size_t>(c.form)];
        }
    }
    // The seeds reach the end of the pipeline with every generator, not only its errors.
    for (std::size_t g = 0; g < meshed.size(); ++g)
        EXPECT_GT(meshed[g], 0) << fz::tetmesh_generator_name(static_cast<fz::TetmeshGenerator>(g));
    // ... and with every form (touching boxes: stars in two pieces at the shared edge or corner).
    for (std::size_t f = 0; f < meshed_forms.size(); ++f)
        EXPECT_GT(meshed_forms[f], 0) << fz::tetmesh_form_name(static_cast<fz::TetmeshForm>(f));
}

TEST(Generators_TetmeshFuzzCases, DecodingIsTotalAndScaled) {
    // Every byte string decodes, the empty one to a box at 2^-600 with no free vertex.
    const fz::TetmeshCase empty = fz::decode_tetmesh_case(nullptr, 0);
    EXPECT_EQ(empty.form, fz::TetmeshForm::Box);
    EXPECT_EQ(empty.scale_exponent, -600);
    EXPECT_EQ(empty.plc.vertex_count(), 8u);
    EXPECT_EQ(empty.plc.facets.size(), 6u);
    EXPECT_EQ(empty.plc.xyz[3 * 7], std::ldexp(1.0, -600));
    // A star of level 3 (38 vertices, 72 triangles) with 6 free vertices at scale 2^0.
    std::vector<std::uint8_t> star{3, 1, 0, 600 & 255, 600 >> 8, 2};
    for (int i = 0; i < 38; ++i) star.push_back(static_cast<std::uint8_t>(7 * i));
    star.push_back(6);
    for (int i = 0; i < 42; ++i) star.push_back(static_cast<std::uint8_t>(11 * i + 3));
    const fz::TetmeshCase c = fz::decode_tetmesh_case(star.data(), star.size());
    EXPECT_EQ(c.form, fz::TetmeshForm::Star);
    EXPECT_EQ(c.scale_exponent, 0);
    EXPECT_EQ(c.free_vertices, 6u);
    EXPECT_EQ(c.plc.vertex_count(), 38u + 6u);
    EXPECT_EQ(c.plc.facets.size(), 72u);
}
