// SPDX-License-Identifier: MIT
// libFuzzer target for one predicate, chosen at compile time (EXACTMESH_FUZZ_PREDICATE names one
// of the traits below; tests/fuzz/CMakeLists.txt builds fuzz_orient2d, fuzz_orient3d,
// fuzz_incircle and fuzz_insphere from this file): the filter, the exact stage and the adaptive
// predicate under permutations, against the exact GMP sign; non-finite input must throw
// GeometryError [Shewchuk97 §4].
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>

#include "predicates/incircle.hpp"
#include "predicates/insphere.hpp"
#include "predicates/orient2d.hpp"
#include "predicates/orient3d.hpp"
#include "tests/fuzz/fuzz_reference.hpp"
#include "tests/support/predicate_calls.hpp"

// Outside an anonymous namespace: three of the four traits go unused in each executable.
namespace exactmesh::fuzz::predicate_traits {

namespace pred = exactmesh::predicates;

using exactmesh::testing::call_on_points;

/// The three stages check_input compares: the adaptive predicate, its exact stages, its filter.
template <std::size_t N, auto Adaptive, auto Exact, auto Filter>
struct Stages {
    static constexpr std::size_t kPoints = N;
    static pred::Sign adaptive(const double* const* p) { return call_on_points<N>(Adaptive, p); }
    static pred::Sign exact(const double* const* p) { return call_on_points<N>(Exact, p); }
    static std::optional<pred::Sign> filter(const double* const* p) {
        return call_on_points<N>(Filter, p);
    }
};

/// Orders of four points that test a predicate alternating in all of them: the identity, even and
/// odd ones, and ones that move the last point.
constexpr std::array<std::array<int, 4>, 5> kFourPointPermutations = {
    {{0, 1, 2, 3}, {1, 2, 0, 3}, {1, 0, 2, 3}, {3, 1, 2, 0}, {1, 2, 3, 0}}};

struct Orient2d : Stages<3, &pred::orient2d, &pred::orient2d_exact, &pred::orient2d_filter> {
    static constexpr const char* kName = "orient2d";
    static constexpr std::size_t kDim = 2;
    static constexpr bool kLifted = false;
    // All six orders: orient2d is alternating in its three points.
    static constexpr std::array<std::array<int, 3>, 6> kPermutations = {
        {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {1, 0, 2}, {0, 2, 1}, {2, 1, 0}}};
};

struct Orient3d : Stages<4, &pred::orient3d, &pred::orient3d_exact, &pred::orient3d_filter> {
    static constexpr const char* kName = "orient3d";
    static constexpr std::size_t kDim = 3;
    static constexpr bool kLifted = false;
    // det [a-d; b-d; c-d] is alternating in all four points, d included.
    static constexpr auto kPermutations = kFourPointPermutations;
};

struct Incircle : Stages<4, &pred::incircle, &pred::incircle_exact, &pred::incircle_filter> {
    static constexpr const char* kName = "incircle";
    static constexpr std::size_t kDim = 2;
    static constexpr bool kLifted = true;
    // The lifted 4x4 determinant is alternating in all four points, d included.
    static constexpr auto kPermutations = kFourPointPermutations;
};

struct Insphere : Stages<5, &pred::insphere, &pred::insphere_exact, &pred::insphere_filter> {
    static constexpr const char* kName = "insphere";
    static constexpr std::size_t kDim = 3;
    static constexpr bool kLifted = true;
    // The lifted 5x5 determinant is alternating in all five points, e included.
    static constexpr std::array<std::array<int, 5>, 5> kPermutations = {
        {{0, 1, 2, 3, 4}, {1, 2, 0, 3, 4}, {1, 0, 2, 3, 4}, {4, 1, 2, 3, 0}, {1, 2, 3, 4, 0}}};
};

}  // namespace exactmesh::fuzz::predicate_traits

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    return exactmesh::fuzz::check_input<
        exactmesh::fuzz::predicate_traits::EXACTMESH_FUZZ_PREDICATE>(data, size);
}
