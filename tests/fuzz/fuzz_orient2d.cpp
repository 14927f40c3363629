// SPDX-License-Identifier: MIT
// libFuzzer target: orient2d (filter, exact stage, adaptive under all permutations) against the
// exact GMP sign; non-finite input must throw GeometryError [Shewchuk97 §4].
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>

#include "predicates/orient2d.hpp"
#include "tests/fuzz/fuzz_reference.hpp"

namespace {

namespace pred = exactmesh::predicates;

struct Orient2d {
    static constexpr const char* kName = "orient2d";
    static constexpr std::size_t kPoints = 3, kDim = 2;
    static constexpr bool kLifted = false;
    // All six orders: orient2d is alternating in its three points.
    static constexpr std::array<std::array<int, 3>, 6> kPermutations = {
        {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {1, 0, 2}, {0, 2, 1}, {2, 1, 0}}};
    static pred::Sign adaptive(const double* const* p) { return pred::orient2d(p[0], p[1], p[2]); }
    static pred::Sign exact(const double* const* p) {
        return pred::orient2d_exact(p[0], p[1], p[2]);
    }
    static std::optional<pred::Sign> filter(const double* const* p) {
        return pred::orient2d_filter(p[0], p[1], p[2]);
    }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    return exactmesh::fuzz::check_input<Orient2d>(data, size);
}
