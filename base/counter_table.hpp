// SPDX-License-Identifier: MIT
// One name table per counters struct (issue 12): every counters struct of the library (the
// Delaunay, constrained, swapping and cutting counters, each generator's) is listed once, as
// (name, field) pairs next to the struct, and every --stats printout, the benchmarks and the
// tests read them through counters_by_name. counter_table_complete checks at compile time that a
// table names every field of its struct exactly once, so a counter added to a struct and left
// out of its table is a compile error, not a silently missing line of --stats.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace exactmesh {

/// One row of a counters struct's name table: the name --stats prints and the field it reads
/// (a 64- or 32-bit counter), or for a derived counter the function computing it.
template <class Counters>
struct CounterName {
    std::string_view name;
    std::uint64_t Counters::*field = nullptr;
    std::uint32_t Counters::*narrow_field = nullptr;
    std::uint64_t (*derived)(const Counters&) = nullptr;
    bool is_derived = false;  // (a function pointer is compared in no constant expression)

    std::uint64_t read(const Counters& counters) const {
        if (is_derived) return derived(counters);
        return field != nullptr ? counters.*field : counters.*narrow_field;
    }
};

/// A row naming a field: counter("triangles", &AdvancingFrontCounters2::triangles).
template <class Counters>
constexpr CounterName<Counters> counter(std::string_view name, std::uint64_t Counters::*field) {
    return {name, field, nullptr, nullptr, false};
}
template <class Counters>
constexpr CounterName<Counters> counter(std::string_view name, std::uint32_t Counters::*field) {
    return {name, nullptr, field, nullptr, false};
}
/// A row computed from the fields (RefinementCounters2's steiner_points).
template <class Counters>
constexpr CounterName<Counters> derived_counter(std::string_view name,
                                                std::uint64_t (*derived)(const Counters&)) {
    return {name, nullptr, nullptr, derived, true};
}

namespace detail {

/// Converts to anything: counts the fields of an aggregate by brace-initialising it.
struct AnyField {
    template <class T>
    constexpr operator T() const noexcept {
        return T{};
    }
};

template <class T, class... Fields>
constexpr std::size_t aggregate_field_count() {
    if constexpr (requires { T{Fields{}..., AnyField{}}; }) {
        return aggregate_field_count<T, Fields..., AnyField>();
    } else {
        return sizeof...(Fields);
    }
}

}  // namespace detail

/// True when `table` has one row per field of Counters, no two rows name the same field or
/// the same name, and exactly `derived` rows are derived counters: then every field is named,
/// each once. (Member pointers are compared, never function pointers: those are not constant
/// expressions under every compiler and sanitizer: GCC's ASan build refuses them.)
template <class Counters, std::size_t N>
constexpr bool counter_table_complete(const std::array<CounterName<Counters>, N>& table,
                                      std::size_t derived = 0) {
    std::size_t fields = 0, computed = 0;
    for (std::size_t i = 0; i < N; ++i) {
        const CounterName<Counters>& row = table[i];
        const int kinds = (row.field != nullptr) + (row.narrow_field != nullptr) + row.is_derived;
        if (kinds != 1) return false;
        (row.is_derived ? computed : fields) += 1;
        for (std::size_t j = i + 1; j < N; ++j) {
            if (row.name == table[j].name) return false;
            if (row.field != nullptr && row.field == table[j].field) return false;
            if (row.narrow_field != nullptr && row.narrow_field == table[j].narrow_field)
                return false;
        }
    }
    return fields == detail::aggregate_field_count<Counters>() && computed == derived;
}

/// The name table of a counters struct whose printed names are its member names, in the order
/// given: EM_COUNTER_TABLE(Delaunay2Counters, points, duplicates) is
/// std::array{counter("points", &Delaunay2Counters::points),
///            counter("duplicates", &Delaunay2Counters::duplicates)}.
/// Each name is written once, so the printed name cannot drift from the field it reads. A table
/// printing another name than the member's (RefinementCounters2's) lists its rows explicitly.
/// Up to 80 members (a longer list leaves EM_DETAIL_COUNTER_AGAIN unexpanded: a compile error).
#define EM_COUNTER_TABLE(Counters, ...)                                         \
    std::array {                                                                \
        EM_DETAIL_COUNTER_EXPAND(EM_DETAIL_COUNTER_ROWS(Counters, __VA_ARGS__)) \
    }

// The for-each behind EM_COUNTER_TABLE: each row names the next row's macro without calling it
// (EM_DETAIL_COUNTER_AGAIN then a separate ()), and each rescan done by the nested
// EM_DETAIL_COUNTER_EXPANDs (over 80 of them) expands one more row.
#define EM_DETAIL_COUNTER_ROWS(Counters, member, ...) \
    ::exactmesh::counter(#member, &Counters::member)  \
        __VA_OPT__(, EM_DETAIL_COUNTER_AGAIN EM_DETAIL_COUNTER_PARENS(Counters, __VA_ARGS__))
#define EM_DETAIL_COUNTER_AGAIN() EM_DETAIL_COUNTER_ROWS
#define EM_DETAIL_COUNTER_PARENS ()
#define EM_DETAIL_COUNTER_EXPAND(...)                      \
    EM_DETAIL_COUNTER_EXPAND16(EM_DETAIL_COUNTER_EXPAND16( \
        EM_DETAIL_COUNTER_EXPAND16(EM_DETAIL_COUNTER_EXPAND16(__VA_ARGS__))))
#define EM_DETAIL_COUNTER_EXPAND16(...)                  \
    EM_DETAIL_COUNTER_EXPAND4(EM_DETAIL_COUNTER_EXPAND4( \
        EM_DETAIL_COUNTER_EXPAND4(EM_DETAIL_COUNTER_EXPAND4(__VA_ARGS__))))
#define EM_DETAIL_COUNTER_EXPAND4(...)                   \
    EM_DETAIL_COUNTER_EXPAND1(EM_DETAIL_COUNTER_EXPAND1( \
        EM_DETAIL_COUNTER_EXPAND1(EM_DETAIL_COUNTER_EXPAND1(__VA_ARGS__))))
#define EM_DETAIL_COUNTER_EXPAND1(...) __VA_ARGS__

/// Adds every counted field of `from` to `into` (derived rows are computed, not stored): the
/// totals of several runs of one construction.
template <class Counters, std::size_t N>
void add_counters(const std::array<CounterName<Counters>, N>& table, Counters& into,
                  const Counters& from) {
    for (const CounterName<Counters>& row : table) {
        if (row.field != nullptr) into.*(row.field) += from.*(row.field);
        if (row.narrow_field != nullptr) into.*(row.narrow_field) += from.*(row.narrow_field);
    }
}

/// The counters as (name, value) pairs, in the table's order.
template <class Counters, std::size_t N>
std::vector<std::pair<std::string, std::uint64_t>> counters_by_name(
    const std::array<CounterName<Counters>, N>& table, const Counters& counters) {
    std::vector<std::pair<std::string, std::uint64_t>> list;
    list.reserve(N);
    for (const CounterName<Counters>& row : table) {
        list.emplace_back(std::string(row.name), row.read(counters));
    }
    return list;
}

}  // namespace exactmesh
