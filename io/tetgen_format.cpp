// SPDX-License-Identifier: MIT
// TetGen's .node and .ele formats (see tetgen_format.hpp).
#include "io/tetgen_format.hpp"

#include <algorithm>
#include <limits>

#include "io/format_error.hpp"
#include "io/text_file.hpp"

namespace exactmesh::io {

namespace {

constexpr std::uint64_t kMaxPoints = 0x3FFFFFFFu;
constexpr std::uint64_t kMaxTets = (0xFFFFFFFFull - 1) / 4;
constexpr std::uint64_t kMaxAttributes = 1u << 20;

std::string plural(std::uint64_t n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

std::uint32_t record_number(const TextLines& lines, std::string_view token, const char* what, std::uint64_t position,
                            std::uint32_t& first_index) {
    const std::uint64_t number = lines.parse_unsigned(token, std::string(what) + " number",
                                                      std::numeric_limits<std::uint32_t>::max());
    if (position == 0) {
        if (number > 1) lines.fail("first " + std::string(what) + " number must be 0 or 1, got " + std::to_string(number));
        first_index = static_cast<std::uint32_t>(number);
    } else if (number != first_index + position) {
        lines.fail(std::string(what) + " number " + std::to_string(number) + " out of sequence, expected " +
                   std::to_string(first_index + position));
    }
    return static_cast<std::uint32_t>(number);
}

std::size_t plausible(std::uint64_t announced, std::size_t text_size, std::size_t min_record_bytes) {
    return static_cast<std::size_t>(std::min<std::uint64_t>(announced, text_size / min_record_bytes));
}

}  // namespace

TetgenNodeFile parse_tetgen_node(std::string_view text, const std::string& file_name) {
    TextLines lines(text, file_name);
    if (!lines.next_data_line()) {
        lines.fail_at_end("no header line (expected '<#points> <dimension=3> <#attributes> <#boundary markers>')");
    }
    TetgenNodeFile nodes;
    const auto& header = lines.fields();
    if (header.size() > 4) {
        lines.fail_quoting_line("header has " + std::to_string(header.size()) +
                                " fields, expected at most 4 (#points, dimension, #attributes, #boundary markers)");
    }
    const std::uint64_t count = lines.parse_unsigned(header[0], "point count", kMaxPoints);
    if (header.size() > 1) {
        const std::uint64_t dimension = lines.parse_unsigned(header[1], "dimension", std::numeric_limits<std::uint64_t>::max());
        if (dimension != 3) lines.fail("dimension must be 3 for a TetGen .node file, got " + std::to_string(dimension));
    }
    if (header.size() > 2) {
        nodes.attribute_count = static_cast<std::uint32_t>(lines.parse_unsigned(header[2], "attribute count", kMaxAttributes));
    }
    if (header.size() > 3) {
        const std::uint64_t markers = lines.parse_unsigned(header[3], "boundary marker count", std::numeric_limits<std::uint64_t>::max());
        if (markers > 1) lines.fail("boundary marker count must be 0 or 1, got " + std::to_string(markers));
        nodes.has_markers = markers == 1;
    }
    const std::uint64_t expected = 4 + std::uint64_t{nodes.attribute_count} + (nodes.has_markers ? 1 : 0);
    nodes.xyz.reserve(3 * plausible(count, text.size(), 8));
    static const char* const kAxes[3] = {"x coordinate", "y coordinate", "z coordinate"};
    for (std::uint64_t i = 0; i < count; ++i) {
        if (!lines.next_data_line()) {
            lines.fail_at_end("file ends after " + std::to_string(i) + " of " + plural(count, "announced point", "announced points"));
        }
        const auto& fields = lines.fields();
        if (fields.size() != expected) {
            lines.fail_quoting_line("expected " + plural(expected, "field", "fields") + " (number, x, y, z" +
                                    (nodes.attribute_count > 0 ? ", " + plural(nodes.attribute_count, "attribute", "attributes") : "") +
                                    (nodes.has_markers ? ", marker" : "") + "), got " + std::to_string(fields.size()));
        }
        record_number(lines, fields[0], "point", i, nodes.first_index);
        for (int k = 0; k < 3; ++k) nodes.xyz.push_back(lines.parse_finite_double(fields[1 + static_cast<std::size_t>(k)], kAxes[k]));
        for (std::uint32_t a = 0; a < nodes.attribute_count; ++a) {
            nodes.attributes.push_back(lines.parse_finite_double(fields[4 + a], "attribute " + std::to_string(a + 1)));
        }
        if (nodes.has_markers) {
            nodes.markers.push_back(static_cast<std::int32_t>(lines.parse_signed(
                fields.back(), "boundary marker", std::numeric_limits<std::int32_t>::min(), std::numeric_limits<std::int32_t>::max())));
        }
    }
    if (lines.next_data_line()) {
        lines.fail_quoting_line("unexpected data after the " + plural(count, "announced point", "announced points"));
    }
    return nodes;
}

TetgenNodeFile read_tetgen_node(const std::filesystem::path& path) {
    return parse_tetgen_node(read_text_file(path), path.string());
}

TetgenEleFile parse_tetgen_ele(std::string_view text, const std::string& file_name, std::uint32_t vertex_first_index,
                               std::uint32_t vertex_count) {
    TextLines lines(text, file_name);
    if (!lines.next_data_line()) {
        lines.fail_at_end("no header line (expected '<#tetrahedra> <nodes per tetrahedron=4> <region attribute 0|1>')");
    }
    const auto& header = lines.fields();
    if (header.size() > 3) {
        lines.fail_quoting_line("header has " + std::to_string(header.size()) +
                                " fields, expected at most 3 (#tetrahedra, nodes per tetrahedron, region attribute)");
    }
    const std::uint64_t count = lines.parse_unsigned(header[0], "tetrahedron count", kMaxTets);
    std::uint64_t corners = 4;
    if (header.size() > 1) {
        corners = lines.parse_unsigned(header[1], "nodes per tetrahedron", std::numeric_limits<std::uint64_t>::max());
        if (corners != 4 && corners != 10) {
            lines.fail("nodes per tetrahedron must be 4 (or 10 for quadratic tetrahedra), got " + std::to_string(corners));
        }
    }
    TetgenEleFile ele;
    if (header.size() > 2) {
        const std::uint64_t region = lines.parse_unsigned(header[2], "region attribute flag", std::numeric_limits<std::uint64_t>::max());
        if (region > 1) lines.fail("region attribute flag must be 0 or 1, got " + std::to_string(region));
        ele.has_region = region == 1;
    }
    const std::uint64_t expected = 1 + corners + (ele.has_region ? 1 : 0);
    const std::uint64_t last = std::uint64_t{vertex_first_index} + vertex_count;
    const std::string numbering = vertex_count == 0 ? std::string("the node file has no points")
                                                    : "the node file numbers its points " + std::to_string(vertex_first_index) +
                                                          " to " + std::to_string(last - 1);
    ele.tets.reserve(4 * plausible(count, text.size(), 10));
    for (std::uint64_t i = 0; i < count; ++i) {
        if (!lines.next_data_line()) {
            lines.fail_at_end("file ends after " + std::to_string(i) + " of " +
                              plural(count, "announced tetrahedron", "announced tetrahedra"));
        }
        const auto& fields = lines.fields();
        if (fields.size() != expected) {
            lines.fail_quoting_line("expected " + plural(expected, "field", "fields") + " (number, " +
                                    (corners == 4 ? "4 nodes" : "10 nodes") + (ele.has_region ? ", region" : "") + "), got " +
                                    std::to_string(fields.size()));
        }
        record_number(lines, fields[0], "tetrahedron", i, ele.first_index);
        std::uint32_t n[4];
        for (std::uint64_t k = 0; k < corners; ++k) {
            const std::uint64_t v = lines.parse_unsigned(fields[1 + k], "node number", std::numeric_limits<std::uint32_t>::max());
            if (v < vertex_first_index || v >= last) lines.fail("node number " + std::to_string(v) + " out of range: " + numbering);
            if (k < 4) n[k] = static_cast<std::uint32_t>(v - vertex_first_index);
        }
        // TetGen's orientation to exactmesh's: swap the last two corners.
        ele.tets.insert(ele.tets.end(), {n[0], n[1], n[3], n[2]});
        if (ele.has_region) ele.regions.push_back(lines.parse_finite_double(fields.back(), "region attribute"));
    }
    if (lines.next_data_line()) {
        lines.fail_quoting_line("unexpected data after the " + plural(count, "announced tetrahedron", "announced tetrahedra"));
    }
    return ele;
}

TetgenEleFile read_tetgen_ele(const std::filesystem::path& path, std::uint32_t vertex_first_index, std::uint32_t vertex_count) {
    return parse_tetgen_ele(read_text_file(path), path.string(), vertex_first_index, vertex_count);
}

std::string format_tetgen_node(std::span<const double> xyz, std::uint32_t first_index) {
    const std::size_t count = xyz.size() / 3;
    std::string out;
    out.reserve(64 * count + 32);
    append_unsigned(out, count);
    out += " 3 0 0\n";
    for (std::size_t v = 0; v < count; ++v) {
        append_unsigned(out, v + first_index);
        for (int k = 0; k < 3; ++k) {
            out += ' ';
            append_double(out, xyz[3 * v + static_cast<std::size_t>(k)]);
        }
        out += '\n';
    }
    return out;
}

void write_tetgen_node(const std::filesystem::path& path, std::span<const double> xyz, std::uint32_t first_index) {
    write_text_file(path, format_tetgen_node(xyz, first_index));
}

std::string format_tetgen_ele(std::span<const std::uint32_t> tets, std::uint32_t first_index) {
    const std::size_t count = tets.size() / 4;
    std::string out;
    out.reserve(40 * count + 32);
    append_unsigned(out, count);
    out += " 4 0\n";
    static constexpr int kFileOrder[4] = {0, 1, 3, 2};
    for (std::size_t t = 0; t < count; ++t) {
        append_unsigned(out, t + first_index);
        for (const int k : kFileOrder) {
            out += ' ';
            append_unsigned(out, std::uint64_t{tets[4 * t + static_cast<std::size_t>(k)]} + first_index);
        }
        out += '\n';
    }
    return out;
}

void write_tetgen_ele(const std::filesystem::path& path, std::span<const std::uint32_t> tets, std::uint32_t first_index) {
    write_text_file(path, format_tetgen_ele(tets, first_index));
}

}  // namespace exactmesh::io
