// SPDX-License-Identifier: MIT
// libFuzzer target: incircle (filter, exact stage, adaptive under permutations) against the
// exact GMP sign; non-finite input must throw GeometryError [Shewchuk97 §4].
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>

#include "predicates/incircle.hpp"
#include "tests/fuzz/fuzz_reference.hpp"

namespace {

namespace pred = exactmesh::predicates;

struct Incircle {
    static constexpr const char* kName = "incircle";
    static constexpr std::size_t kPoints = 4, kDim = 2;
    static constexpr bool kLifted = true;
    // The lifted 4x4 determinant is alternating in all four points, d included.
    static constexpr std::array<std::array<int, 4>, 5> kPermutations = {
        {{0, 1, 2, 3}, {1, 2, 0, 3}, {1, 0, 2, 3}, {3, 1, 2, 0}, {1, 2, 3, 0}}};
    static pred::Sign adaptive(const double* const* p) {
        return pred::incircle(p[0], p[1], p[2], p[3]);
    }
    static pred::Sign exact(const double* const* p) {
        return pred::incircle_exact(p[0], p[1], p[2], p[3]);
    }
    static std::optional<pred::Sign> filter(const double* const* p) {
        return pred::incircle_filter(p[0], p[1], p[2], p[3]);
    }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    return exactmesh::fuzz::check_input<Incircle>(data, size);
}
