// SPDX-License-Identifier: MIT
// Work counters by name. Every counters struct of the library (what --stats prints, what the
// generator registry returns, what the benchmarks report) declares one table of its fields
// beside it, `counter_fields(const Counters&)` (found by argument-dependent lookup), and every
// list of counters is made from that table: no field can be left out of a printout, and every
// printout has the same names in the same order.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace exactmesh {

/// One counter: its printed name and its field.
template <class Counters>
struct CounterField {
    std::string_view name;
    std::uint64_t Counters::*field;
};

/// (name, value) for every field of the table of `counters`, in the table's order.
template <class Counters>
std::vector<std::pair<std::string, std::uint64_t>> counters_by_name(const Counters& counters) {
    std::vector<std::pair<std::string, std::uint64_t>> named;
    for (const auto& [name, field] : counter_fields(counters))
        named.emplace_back(std::string(name), counters.*field);
    return named;
}

}  // namespace exactmesh
