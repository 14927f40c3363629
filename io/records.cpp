// SPDX-License-Identifier: MIT
// Record-level plumbing shared by the text formats (see records.hpp).
#include "io/records.hpp"

#include <algorithm>

#include "triangulation/mesh/mesh2.hpp"

namespace exactmesh::io::detail {

std::string plural(std::uint64_t n, const char* singular, const char* plural_form) {
    return std::to_string(n) + " " + (n == 1 ? singular : plural_form);
}

std::string field_names(const char* leading, std::uint64_t attributes, bool marker) {
    std::string names = leading;
    if (attributes > 0) names += ", " + plural(attributes, "attribute", "attributes");
    if (marker) names += ", marker";
    return names;
}

void expect_field_count(const TextLines& lines, std::uint64_t expected, const std::string& names) {
    const std::size_t got = lines.fields().size();
    if (got != expected) {
        lines.fail_quoting_line("expected " + plural(expected, "field", "fields") + " (" + names +
                                "), got " + std::to_string(got));
    }
}

std::uint32_t expect_record_number(const TextLines& lines, std::string_view token, const char* what,
                                   std::uint64_t position, std::uint32_t& first_index) {
    const std::uint64_t number = lines.parse_unsigned(token, std::string(what) + " number",
                                                      std::numeric_limits<std::uint32_t>::max());
    if (position == 0) {
        if (number > 1) {
            lines.fail("first " + std::string(what) + " number must be 0 or 1, got " +
                       std::to_string(number));
        }
        first_index = static_cast<std::uint32_t>(number);
    } else if (number != first_index + position) {
        lines.fail(std::string(what) + " number " + std::to_string(number) +
                   " out of sequence, expected " + std::to_string(first_index + position));
    }
    return static_cast<std::uint32_t>(number);
}

void next_record(TextLines& lines, std::uint64_t position, std::uint64_t count, RecordName name) {
    if (!lines.next_data_line()) {
        lines.fail_at_end("file ends after " + std::to_string(position) + " of " +
                          std::to_string(count) + " announced " + name.of(count));
    }
}

void read_header(TextLines& lines, const char* format) {
    if (!lines.next_data_line()) {
        lines.fail_at_end(std::string("no header line (expected '") + format + "')");
    }
}

void expect_end(TextLines& lines, std::uint64_t count, RecordName name) {
    if (lines.next_data_line()) {
        lines.fail_quoting_line("unexpected data after the " + std::to_string(count) +
                                " announced " + name.of(count));
    }
}

void expect_header_fields(const TextLines& lines, std::size_t max_fields, const char* header,
                          const char* names) {
    const std::size_t got = lines.fields().size();
    if (got > max_fields) {
        lines.fail_quoting_line(std::string(header) + " has " + std::to_string(got) +
                                " fields, expected at most " + std::to_string(max_fields) + " (" +
                                names + ")");
    }
}

bool parse_flag(const TextLines& lines, std::string_view token, const char* what) {
    const std::uint64_t value =
        lines.parse_unsigned(token, what, std::numeric_limits<std::uint64_t>::max());
    if (value > 1) lines.fail(std::string(what) + " must be 0 or 1, got " + std::to_string(value));
    return value == 1;
}

VertexNumbers::VertexNumbers(std::uint32_t first_index, std::uint32_t vertex_count,
                             const char* field, const char* vertices)
    : first_index_(first_index),
      last_(std::uint64_t{first_index} + vertex_count),
      field_(field),
      numbering_(vertex_count == 0
                     ? std::string("the node file has no ") + vertices
                     : std::string("the node file numbers its ") + vertices + " " +
                           std::to_string(first_index) + " to " + std::to_string(last_ - 1)) {}

std::uint32_t VertexNumbers::parse(const TextLines& lines, std::string_view token) const {
    const std::uint64_t v =
        lines.parse_unsigned(token, field_, std::numeric_limits<std::uint32_t>::max());
    if (v < first_index_ || v >= last_) {
        lines.fail(std::string(field_) + " " + std::to_string(v) + " out of range: " + numbering_);
    }
    return static_cast<std::uint32_t>(v - first_index_);
}

std::uint64_t parse_vertex_section(TextLines& lines, unsigned dimension, const char* format,
                                   VertexSection& section) {
    expect_header_fields(lines, 4, "header",
                         "#vertices, dimension, #attributes, #boundary markers");
    const auto& header = lines.fields();
    const std::uint64_t count =
        lines.parse_unsigned(header[0], "vertex count", triangulation::kMaxPoints);
    if (header.size() > 1) {
        const std::uint64_t given =
            lines.parse_unsigned(header[1], "dimension", std::numeric_limits<std::uint64_t>::max());
        if (given != dimension) {
            lines.fail("dimension must be " + std::to_string(dimension) + ", got " +
                       std::to_string(given) + " (" + format + ")");
        }
    }
    if (header.size() > 2) {
        section.attribute_count = static_cast<std::uint32_t>(
            lines.parse_unsigned(header[2], "attribute count", kMaxAttributes));
    }
    if (header.size() > 3)
        section.has_markers = parse_flag(lines, header[3], "boundary marker count");
    const std::uint64_t expected =
        1 + dimension + std::uint64_t{section.attribute_count} + (section.has_markers ? 1 : 0);
    const std::string names = field_names(dimension == 2 ? "number, x, y" : "number, x, y, z",
                                          section.attribute_count, section.has_markers);
    static constexpr const char* kAxis[3] = {"x coordinate", "y coordinate", "z coordinate"};

    section.coordinates.reserve(dimension * lines.plausible_records(count, 2 + 2 * dimension));
    std::string attribute_name;
    for (std::uint64_t i = 0; i < count; ++i) {
        next_record(lines, i, count, kVertices);
        expect_field_count(lines, expected, names);
        const auto& fields = lines.fields();
        expect_record_number(lines, fields[0], "vertex", i, section.first_index);
        section.lines.push_back(lines.line_number());
        for (unsigned c = 0; c < dimension; ++c) {
            section.coordinates.push_back(lines.parse_finite_double(fields[1 + c], kAxis[c]));
        }
        for (std::uint32_t a = 0; a < section.attribute_count; ++a) {
            attribute_name = "attribute " + std::to_string(a + 1);
            section.attributes.push_back(
                lines.parse_finite_double(fields[1 + dimension + a], attribute_name));
        }
        if (section.has_markers) {
            section.markers.push_back(static_cast<std::int32_t>(lines.parse_signed(
                fields.back(), "boundary marker", std::numeric_limits<std::int32_t>::min(),
                std::numeric_limits<std::int32_t>::max())));
        }
    }
    return count;
}

unsigned node_dimension(TextLines& lines) {
    read_header(lines, "<#vertices> <dimension> <#attributes> <#boundary markers>");
    const auto& header = lines.fields();
    lines.parse_unsigned(header[0], "vertex count", triangulation::kMaxPoints);
    if (header.size() < 2) return 2;
    const std::uint64_t dimension =
        lines.parse_unsigned(header[1], "dimension", std::numeric_limits<std::uint64_t>::max());
    if (dimension != 2 && dimension != 3) {
        lines.fail("dimension must be 2 or 3, got " + std::to_string(dimension));
    }
    return static_cast<unsigned>(dimension);
}

}  // namespace exactmesh::io::detail
