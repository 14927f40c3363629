// SPDX-License-Identifier: MIT
// Replays a saved input of fuzz_mesh_generators_2d (tests/data/fuzz/) as the target runs it,
// for the regression tests of its findings: the generator's outcome, its exact check, counters.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

#include "base/errors.hpp"
#include "tests/fuzz/mesh_generators_2d_case.hpp"

namespace exactmesh::testing {

struct FuzzReplay2 {
    std::string generator;
    bool meshed = false;
    std::string error;  ///< the GeometryError or InputError, when not meshed
    triangulation::CheckReport check;
    std::size_t triangles = 0;
    std::vector<std::pair<std::string, std::uint64_t>> counters;
    std::uint64_t counter(const std::string& name) const {
        for (const auto& [key, value] : counters) {
            if (key == name) return value;
        }
        return 0;
    }
};

/// The input tests/data/fuzz/<name>, run with the target's size and the Steiner budget given
/// (the target's 1,000, or 0 for the generator's own).
inline FuzzReplay2 replay_mesh_generators_2d(const std::string& name, std::uint64_t budget) {
    std::ifstream in(std::string(EXACTMESH_SOURCE_DIR) + "/tests/data/fuzz/" + name,
                     std::ios::binary);
    const std::vector<std::uint8_t> data{std::istreambuf_iterator<char>(in),
                                         std::istreambuf_iterator<char>()};
    EXPECT_FALSE(data.empty()) << name;
    FuzzReplay2 r;
    const auto c = fuzz::decode_mesh_generator_case(data.data(), data.size(), budget);
    if (!c) return r;
    r.generator = c->generator->name;
    try {
        const generators::MeshRun2 run = c->generator->run(c->pslg(), c->options);
        r.meshed = true;
        r.triangles = run.mesh.mesh.triangle_count();
        for (const auto& [key, value] : run.counters) r.counters.emplace_back(key, value);
        r.check = fuzz::check_mesh_generator_case(*c, run.mesh, run.quads);
    } catch (const GeometryError& e) {
        r.error = e.what();
    } catch (const InputError& e) {
        r.error = e.what();
    }
    return r;
}

}  // namespace exactmesh::testing
