// SPDX-License-Identifier: MIT
// One name table per counters struct (issue 12): each generator's counters are listed once, as
// (name, field) pairs next to the struct, and `exactmesh mesh --stats`, the benchmarks and the
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

namespace exactmesh::generators {

/// One row of a counters struct's name table: the name --stats prints and how to read it.
template <class Counters>
struct CounterName {
    std::string_view name;
    std::uint64_t (*read)(const Counters&);
};

namespace detail {

template <class Class, class Field>
Class class_of_member(Field Class::*);

template <auto Member>
using CountersOf = decltype(class_of_member(Member));

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

/// The reader of one field (a whole-number counter) of a counters struct.
template <auto Member>
std::uint64_t read_counter(const detail::CountersOf<Member>& counters) {
    return static_cast<std::uint64_t>(counters.*Member);
}

/// A row naming the field `Member`: counter<&AdvancingFrontCounters2::triangles>("triangles").
template <auto Member>
constexpr CounterName<detail::CountersOf<Member>> counter(std::string_view name) {
    return {name, &read_counter<Member>};
}

/// True when `table` has one row per field of Counters plus `derived` rows read by functions of
/// their own (RefinementCounters2's steiner_points), and no two rows read the same way: then
/// every field is named, each once.
template <class Counters, std::size_t N>
constexpr bool counter_table_complete(const std::array<CounterName<Counters>, N>& table,
                                      std::size_t derived = 0) {
    if (N != detail::aggregate_field_count<Counters>() + derived) return false;
    for (std::size_t i = 0; i < N; ++i) {
        for (std::size_t j = i + 1; j < N; ++j) {
            if (table[i].read == table[j].read || table[i].name == table[j].name) return false;
        }
    }
    return true;
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

}  // namespace exactmesh::generators
