// SPDX-License-Identifier: MIT
// Name tables of enums (issue 12): each enum the CLI names or parses (segment recovery, swap
// criteria, sample domains, mesh options) lists its (name, value) pairs once, and both
// directions (value -> name for printing, name -> value for parsing) read that one table, so
// a name cannot be printed one way and parsed another, and the error lists every known name.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "base/errors.hpp"

namespace exactmesh {

/// One row of an enum's name table. The names are string literals, so `name.data()` is
/// null-terminated (segment_recovery_name returns a const char*).
template <class Enum>
struct EnumName {
    std::string_view name;
    Enum value;
};

/// The name of `value` in `table`; `fallback` for a value outside the table (only a value cast
/// from an out-of-range integer).
template <class Enum, std::size_t N>
constexpr std::string_view name_of(const std::array<EnumName<Enum>, N>& table, Enum value,
                                   std::string_view fallback = "?") {
    for (const EnumName<Enum>& row : table) {
        if (row.value == value) return row.name;
    }
    return fallback;
}

/// The value named `text`, or nothing when no row has that name.
template <class Enum, std::size_t N>
constexpr std::optional<Enum> find_name(const std::array<EnumName<Enum>, N>& table,
                                        std::string_view text) {
    for (const EnumName<Enum>& row : table) {
        if (row.name == text) return row.value;
    }
    return std::nullopt;
}

/// The names in table order, separated by ", ", the last two by `last_separator`
/// ("a, b, c" or, with " or ", "a, b or c").
template <class Enum, std::size_t N>
std::string known_names(const std::array<EnumName<Enum>, N>& table,
                        std::string_view last_separator = ", ") {
    std::string known;
    for (std::size_t i = 0; i < N; ++i) {
        if (i > 0) known += i + 1 == N ? last_separator : std::string_view(", ");
        known += table[i].name;
    }
    return known;
}

/// The value named `text`. @throws InputError "unknown <what> '<text>' (known: <names>)".
template <class Enum, std::size_t N>
Enum parse_name(const std::array<EnumName<Enum>, N>& table, std::string_view text,
                std::string_view what, SourceLocation where = SourceLocation::current()) {
    if (const std::optional<Enum> value = find_name(table, text)) return *value;
    throw InputError("unknown " + std::string(what) + " '" + std::string(text) +
                         "' (known: " + known_names(table) + ")",
                     where);
}

}  // namespace exactmesh
