// SPDX-License-Identifier: MIT
// Calls a predicate of N points on a test's coordinates, held either as N pointers or as one flat
// array of N·D doubles, and lists a predicate's stages by its name, so that a test names each
// predicate once instead of spelling out its stages and p[0], p[1], ... for every arity. Test
// support.
#pragma once

#include <algorithm>
#include <cstddef>
#include <utility>

/// The stages of predicate `name`, as template arguments in the order adaptive, exact, filter,
/// reference (raw coordinates), reference (difference form), plain double evaluation: every
/// predicate X comes as X, X_exact, X_filter, reference::X, reference::X_differences and X_fast.
#define EM_TEST_STAGES(name)                                                                \
    &::exactmesh::predicates::name, &::exactmesh::predicates::name##_exact,                 \
        &::exactmesh::predicates::name##_filter, &::exactmesh::predicates::reference::name, \
        &::exactmesh::predicates::reference::name##_differences,                            \
        &::exactmesh::predicates::name##_fast

namespace exactmesh::testing {

/// A string literal as a template argument (a predicate's name in its traits).
template <std::size_t L>
struct Name {
    char text[L];
    // Implicit, so that a string literal can be the template argument.
    constexpr Name(const char (&s)[L]) { std::copy_n(s, L, text); }
};

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
