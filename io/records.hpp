// SPDX-License-Identifier: MIT
// Record-level plumbing shared by the Triangle (2D) and TetGen (3D) text formats, internal to
// io/: counts and names in messages, field counts, consecutive record numbers (the first sets
// the base, 0 or 1), the end of the announced records, and the vertex section of a .node file
// in either dimension. Every failure is a FormatError naming the file and the line.
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "io/text_file.hpp"

namespace exactmesh::io::detail {

inline constexpr std::uint64_t kMaxAttributes = std::numeric_limits<std::uint32_t>::max() - 8;

/// "3 vertices", "1 vertex".
std::string plural(std::uint64_t n, const char* singular, const char* plural_form);

/// "number, x, y, 2 attributes, marker": what a line must hold, for error messages.
std::string field_names(const char* leading, std::uint64_t attributes, bool marker);

void expect_field_count(const TextLines& lines, std::uint64_t expected, const std::string& names);

/// The number of the next record: the first one sets the base (0 or 1), the others follow.
std::uint32_t expect_record_number(const TextLines& lines, std::string_view token, const char* what,
                                   std::uint64_t position, std::uint32_t& first_index);

/// Fails when data follows the `count` announced records.
void expect_end(TextLines& lines, std::uint64_t count, const char* what_plural);

/// The vertex section of a .node or .poly file, in `dimension` coordinates per vertex.
struct VertexSection {
    std::vector<double> coordinates;  ///< dimension·#V, in file order
    std::uint32_t first_index = 0;    ///< number of the first vertex: 0 or 1
    std::uint32_t attribute_count = 0;
    std::vector<double> attributes;  ///< attribute_count·#V
    bool has_markers = false;
    std::vector<std::int32_t> markers;  ///< #V when has_markers
};

/// Parses the header on the current line (`<#vertices> [<dimension>] [<#attributes>]
/// [<#markers 0|1>]`; an omitted dimension is `dimension`, another one is an error naming
/// `format`), then the vertices. Returns the announced count.
std::uint64_t parse_vertex_section(TextLines& lines, unsigned dimension, const char* format,
                                   VertexSection& section);

/// The dimension field of a .node header (2 when omitted, as Triangle reads it), for callers
/// that dispatch on it; reads the header line only; fails as the readers do on a missing or
/// malformed header.
unsigned node_dimension(TextLines& lines);

}  // namespace exactmesh::io::detail
