// SPDX-License-Identifier: MIT
// libFuzzer target: orient3d (filter, exact stage, adaptive under permutations) against the
// exact GMP sign; non-finite input must throw GeometryError [Shewchuk97 §4].
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>

#include "predicates/orient3d.hpp"
#include "tests/fuzz/fuzz_reference.hpp"

namespace {

namespace pred = exactmesh::predicates;

struct Orient3d {
    static constexpr const char* kName = "orient3d";
    static constexpr std::size_t kPoints = 4, kDim = 3;
    static constexpr bool kLifted = false;
    // det [a-d; b-d; c-d] is alternating in all four points, d included.
    static constexpr std::array<std::array<int, 4>, 5> kPermutations = {
        {{0, 1, 2, 3}, {1, 2, 0, 3}, {1, 0, 2, 3}, {3, 1, 2, 0}, {1, 2, 3, 0}}};
    static pred::Sign adaptive(const double* const* p) {
        return pred::orient3d(p[0], p[1], p[2], p[3]);
    }
    static pred::Sign exact(const double* const* p) {
        return pred::orient3d_exact(p[0], p[1], p[2], p[3]);
    }
    static std::optional<pred::Sign> filter(const double* const* p) {
        return pred::orient3d_filter(p[0], p[1], p[2], p[3]);
    }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    return exactmesh::fuzz::check_input<Orient3d>(data, size);
}
