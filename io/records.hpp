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

/// What a section's records are called in messages ("vertex", "vertices").
struct RecordName {
    const char* singular;
    const char* plural;
    const char* of(std::uint64_t count) const { return count == 1 ? singular : plural; }
};

inline constexpr RecordName kVertices{"vertex", "vertices"};

/// Advances to record `position` (0-based) of the `count` announced ones; a text that ends
/// first fails with "file ends after 2 of 5 announced vertices".
void next_record(TextLines& lines, std::uint64_t position, std::uint64_t count, RecordName name);

/// Advances to the header line; a text without one fails with "no header line (expected
/// '<format>')".
void read_header(TextLines& lines, const char* format);

/// Fails when data follows the `count` announced records.
void expect_end(TextLines& lines, std::uint64_t count, RecordName name);

/// A header holding at most `max_fields` fields; else fails with "<header> has 5 fields,
/// expected at most 4 (<names>)".
void expect_header_fields(const TextLines& lines, std::size_t max_fields, const char* header,
                          const char* names);

/// A 0|1 flag of a header (`what`: "boundary marker count", ...).
bool parse_flag(const TextLines& lines, std::string_view token, const char* what);

/// The vertex numbers of a record (a triangle's corners, a tetrahedron's nodes) that must name
/// one of the `vertex_count` vertices of a node file numbered from `first_index`.
class VertexNumbers {
  public:
    /// `field` names the number in messages ("vertex number"), `vertices` the node file's
    /// records ("vertices").
    VertexNumbers(std::uint32_t first_index, std::uint32_t vertex_count, const char* field,
                  const char* vertices);
    /// The 0-based vertex `token` names; fails when it is out of range.
    std::uint32_t parse(const TextLines& lines, std::string_view token) const;

  private:
    std::uint32_t first_index_;
    std::uint64_t last_;  ///< exclusive
    const char* field_;
    std::string numbering_;  ///< "the node file numbers its vertices 1 to 8", for messages
};

/// The vertex section of a .node or .poly file, in `dimension` coordinates per vertex.
struct VertexSection {
    std::vector<double> coordinates;  ///< dimension·#V, in file order
    std::uint32_t first_index = 0;    ///< number of the first vertex: 0 or 1
    std::uint32_t attribute_count = 0;
    std::vector<double> attributes;  ///< attribute_count·#V
    bool has_markers = false;
    std::vector<std::int32_t> markers;  ///< #V when has_markers
    std::vector<std::uint64_t> lines;   ///< #V: the line of each vertex (for messages)
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
