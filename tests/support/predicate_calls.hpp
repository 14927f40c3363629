// SPDX-License-Identifier: MIT
// Calls a predicate of N points on a test's coordinates, held either as N pointers or as one flat
// array of N·D doubles, so that a test names each predicate's stages once instead of spelling
// out p[0], p[1], ... for every stage and arity. Test support.
#pragma once

#include <cstddef>
#include <utility>

namespace exactmesh::testing {

/// f(p[0], ..., p[N-1]).
template <std::size_t N, class F>
decltype(auto) call_on_points(F f, const double* const* p) {
    return [&]<std::size_t... I>(std::index_sequence<I...>)->decltype(auto) {
        return f(p[I]...);
    }
    (std::make_index_sequence<N>{});
}

/// f(x, x + D, ..., x + (N-1)·D): the N points of a flat array of coordinates.
template <std::size_t N, std::size_t D, class F>
decltype(auto) call_on_flat(F f, const double* x) {
    return [&]<std::size_t... I>(std::index_sequence<I...>)->decltype(auto) {
        return f((x + I * D)...);
    }
    (std::make_index_sequence<N>{});
}

}  // namespace exactmesh::testing
