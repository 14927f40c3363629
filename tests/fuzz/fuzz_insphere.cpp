// SPDX-License-Identifier: MIT
// libFuzzer target: insphere (filter, exact stage, adaptive under permutations) against the
// exact GMP sign; non-finite input must throw GeometryError [Shewchuk97 §4].
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>

#include "predicates/insphere.hpp"
#include "tests/fuzz/fuzz_reference.hpp"

namespace {

namespace pred = exactmesh::predicates;

struct Insphere {
    static constexpr const char* kName = "insphere";
    static constexpr std::size_t kPoints = 5, kDim = 3;
    static constexpr bool kLifted = true;
    // The lifted 5x5 determinant is alternating in all five points, e included.
    static constexpr std::array<std::array<int, 5>, 5> kPermutations = {
        {{0, 1, 2, 3, 4}, {1, 2, 0, 3, 4}, {1, 0, 2, 3, 4}, {4, 1, 2, 3, 0}, {1, 2, 3, 4, 0}}};
    static pred::Sign adaptive(const double* const* p) {
        return pred::insphere(p[0], p[1], p[2], p[3], p[4]);
    }
    static pred::Sign exact(const double* const* p) {
        return pred::insphere_exact(p[0], p[1], p[2], p[3], p[4]);
    }
    static std::optional<pred::Sign> filter(const double* const* p) {
        return pred::insphere_filter(p[0], p[1], p[2], p[3], p[4]);
    }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    return exactmesh::fuzz::check_input<Insphere>(data, size);
}
