// SPDX-License-Identifier: MIT
// Triangle's .node / .ele / .neigh formats (see triangle_format.hpp). Stricter than Triangle
// itself, which reads numbers with strtod/strtol and silently ignores whatever follows them.
#include "io/triangle_format.hpp"

#include <algorithm>
#include <limits>

#include "io/records.hpp"
#include "io/text_file.hpp"

namespace exactmesh::io {

namespace {

using detail::expect_end;
using detail::expect_field_count;
using detail::expect_record_number;
using detail::field_names;
using detail::kMaxAttributes;
using triangulation::kMaxPoints;
using triangulation::kNone;

/// 3 corner slots per triangle must be addressable by a 32-bit index.
constexpr std::uint64_t kMaxTriangles = (std::uint64_t{kNone} - 1) / 3;

constexpr detail::RecordName kTriangles{"triangle", "triangles"};
constexpr detail::RecordName kHoles{"hole", "holes"};
constexpr detail::RecordName kRegions{"region", "regions"};

/// What a .node (or the vertex section of a .poly) starts with, for the "no header" message.
constexpr const char* kNodeHeader = "<#vertices> <dimension=2> <#attributes> <#boundary markers>";

/// The count on a .poly header of one field: the hole or the region header.
std::uint64_t parse_count_header(const TextLines& lines, detail::RecordName name) {
    const auto& header = lines.fields();
    if (header.size() != 1) {
        lines.fail_quoting_line(std::string(name.singular) +
                                " header must hold one field, the number of " + name.plural);
    }
    return lines.parse_unsigned(header[0], std::string(name.singular) + " count", kMaxTriangles);
}

/// The 2D vertex section into a NodeFile.
std::uint64_t parse_vertex_section(TextLines& lines, NodeFile& nodes) {
    detail::VertexSection section;
    const std::uint64_t count =
        detail::parse_vertex_section(lines, 2, "a 2D Triangle file", section);
    nodes.xy = std::move(section.coordinates);
    nodes.first_index = section.first_index;
    nodes.attribute_count = section.attribute_count;
    nodes.attributes = std::move(section.attributes);
    nodes.has_markers = section.has_markers;
    nodes.markers = std::move(section.markers);
    nodes.lines = std::move(section.lines);
    return count;
}

NodeFile parse_node_lines(TextLines& lines) {
    detail::read_header(lines, kNodeHeader);
    NodeFile nodes;
    const std::uint64_t count = parse_vertex_section(lines, nodes);
    expect_end(lines, count, detail::kVertices);
    return nodes;
}

}  // namespace

NodeFile parse_node(std::string_view text, const std::string& file_name) {
    TextLines lines(text, file_name);
    return parse_node_lines(lines);
}

NodeFile read_node(const std::filesystem::path& path) {
    TextLines lines(path);
    return parse_node_lines(lines);
}

std::string format_node(const NodeFile& nodes) {
    const std::uint32_t count = nodes.vertex_count();
    std::string out;
    out.reserve(48 * std::size_t{count} + 64);
    append_unsigned(out, count);
    out += " 2 ";
    append_unsigned(out, nodes.attribute_count);
    out += nodes.has_markers ? " 1\n" : " 0\n";
    for (std::uint32_t v = 0; v < count; ++v) {
        append_unsigned(out, std::uint64_t{v} + nodes.first_index);
        out += ' ';
        append_double(out, nodes.xy[2 * std::size_t{v}]);
        out += ' ';
        append_double(out, nodes.xy[2 * std::size_t{v} + 1]);
        for (std::uint32_t a = 0; a < nodes.attribute_count; ++a) {
            out += ' ';
            append_double(out, nodes.attributes[std::size_t{v} * nodes.attribute_count + a]);
        }
        if (nodes.has_markers) {
            out += ' ';
            append_signed(out, nodes.markers[v]);
        }
        out += '\n';
    }
    return out;
}

void write_node(const std::filesystem::path& path, const NodeFile& nodes) {
    write_text_file(path, format_node(nodes));
}

namespace {

PolyFile parse_poly_lines(TextLines& lines, const std::filesystem::path& node_path) {
    detail::read_header(lines, kNodeHeader);
    PolyFile poly;
    const std::uint64_t announced = parse_vertex_section(lines, poly.vertices);
    if (announced == 0) {
        // Triangle's convention: the vertices live in the .node file of the same name. The
        // first segment number then sets the base.
        poly.vertices = read_node(node_path);
        poly.vertices_from_node_file = true;
    }
    const std::uint32_t base = poly.vertices.first_index;
    const std::uint64_t vertex_count = poly.vertices.vertex_count();
    if (!lines.next_data_line()) {
        lines.fail_at_end(
            "file ends before the segment header ('<#segments> <#boundary markers>')");
    }
    {
        detail::expect_header_fields(lines, 2, "segment header", "#segments, #boundary markers");
        const auto& header = lines.fields();
        const std::uint64_t count = lines.parse_unsigned(header[0], "segment count", kMaxTriangles);
        if (header.size() > 1) {
            poly.has_segment_markers = detail::parse_flag(lines, header[1], "segment marker count");
        }
        const std::uint64_t expected = 3 + (poly.has_segment_markers ? 1 : 0);
        const std::string names = poly.has_segment_markers ? "number, endpoint, endpoint, marker"
                                                           : "number, endpoint, endpoint";
        poly.segments.reserve(2 * lines.plausible_records(count, 6));
        std::uint32_t segment_base = base;
        for (std::uint64_t i = 0; i < count; ++i) {
            detail::next_record(lines, i, count, {"segment", "segments"});
            expect_field_count(lines, expected, names);
            const auto& fields = lines.fields();
            expect_record_number(lines, fields[0], "segment", i, segment_base);
            for (int k = 1; k <= 2; ++k) {
                const std::uint64_t v =
                    lines.parse_unsigned(fields[static_cast<std::size_t>(k)], "segment endpoint",
                                         std::numeric_limits<std::uint32_t>::max());
                if (v < base || v >= base + vertex_count) {
                    lines.fail("segment endpoint " + std::to_string(v) + " names no vertex: " +
                               (vertex_count == 0
                                    ? std::string("there are no vertices")
                                    : "the vertices are numbered " + std::to_string(base) + " to " +
                                          std::to_string(base + vertex_count - 1)));
                }
                poly.segments.push_back(static_cast<VertIdx>(v - base));
            }
            if (poly.has_segment_markers) {
                poly.segment_markers.push_back(static_cast<std::int32_t>(lines.parse_signed(
                    fields[3], "segment marker", std::numeric_limits<std::int32_t>::min(),
                    std::numeric_limits<std::int32_t>::max())));
            }
        }
    }
    if (!lines.next_data_line()) lines.fail_at_end("file ends before the hole count ('<#holes>')");
    {
        const std::uint64_t count = parse_count_header(lines, kHoles);
        std::uint32_t hole_base = base;
        for (std::uint64_t i = 0; i < count; ++i) {
            detail::next_record(lines, i, count, kHoles);
            expect_field_count(lines, 3, "number, x, y");
            expect_record_number(lines, lines.fields()[0], "hole", i, hole_base);
            poly.hole_lines.push_back(lines.line_number());
            poly.holes.push_back(lines.parse_finite_double(lines.fields()[1], "hole x coordinate"));
            poly.holes.push_back(lines.parse_finite_double(lines.fields()[2], "hole y coordinate"));
        }
    }
    if (lines.next_data_line()) {
        const std::uint64_t count = parse_count_header(lines, kRegions);
        std::uint32_t region_base = base;
        for (std::uint64_t i = 0; i < count; ++i) {
            detail::next_record(lines, i, count, kRegions);
            const auto& fields = lines.fields();
            if (fields.size() != 4 && fields.size() != 5) {
                lines.fail_quoting_line(
                    "expected 4 or 5 fields (number, x, y, attribute[, maximum area]), got " +
                    std::to_string(fields.size()));
            }
            expect_record_number(lines, fields[0], "region", i, region_base);
            poly.region_lines.push_back(lines.line_number());
            poly.regions.push_back(lines.parse_finite_double(fields[1], "region x coordinate"));
            poly.regions.push_back(lines.parse_finite_double(fields[2], "region y coordinate"));
            poly.regions.push_back(lines.parse_finite_double(fields[3], "region attribute"));
            poly.regions.push_back(fields.size() == 5
                                       ? lines.parse_finite_double(fields[4], "region maximum area")
                                       : -1.0);
        }
        expect_end(lines, count, kRegions);
    }
    return poly;
}

}  // namespace

std::filesystem::path poly_node_path(const std::filesystem::path& poly_path) {
    std::filesystem::path lower = poly_path, upper = poly_path;
    lower.replace_extension(".node");
    upper.replace_extension(".NODE");
    const std::string extension = poly_path.extension().string();
    const bool upper_case =
        extension.size() > 1 && std::none_of(extension.begin(), extension.end(),
                                             [](char c) { return c >= 'a' && c <= 'z'; });
    std::error_code ec;
    return upper_case && std::filesystem::exists(upper, ec) ? upper : lower;
}

PolyFile parse_poly(std::string_view text, const std::string& file_name,
                    const std::filesystem::path& node_path) {
    TextLines lines(text, file_name);
    return parse_poly_lines(lines, node_path);
}

PolyFile read_poly(const std::filesystem::path& path) {
    TextLines lines(path);
    return parse_poly_lines(lines, poly_node_path(path));
}

std::string format_poly(const NodeFile& vertices, std::span<const VertIdx> segments,
                        std::span<const std::int32_t> segment_markers) {
    std::string out = format_node(vertices);
    const std::size_t count = segments.size() / 2;
    const bool markers = !segment_markers.empty();
    append_unsigned(out, count);
    out += markers ? " 1\n" : " 0\n";
    for (std::size_t s = 0; s < count; ++s) {
        append_unsigned(out, s + vertices.first_index);
        for (int k = 0; k < 2; ++k) {
            out += ' ';
            append_unsigned(out, std::uint64_t{segments[2 * s + static_cast<std::size_t>(k)]} +
                                     vertices.first_index);
        }
        if (markers) {
            out += ' ';
            append_signed(out, segment_markers[s]);
        }
        out += '\n';
    }
    out += "0\n";
    return out;
}

void write_poly(const std::filesystem::path& path, const NodeFile& vertices,
                std::span<const VertIdx> segments, std::span<const std::int32_t> segment_markers) {
    write_text_file(path, format_poly(vertices, segments, segment_markers));
}

namespace {

EleFile parse_ele_lines(TextLines& lines, std::uint32_t vertex_first_index,
                        std::uint32_t vertex_count) {
    detail::read_header(lines, "<#triangles> <nodes per triangle=3> <#attributes>");
    detail::expect_header_fields(lines, 3, "header", "#triangles, nodes per triangle, #attributes");
    const auto& header = lines.fields();
    const std::uint64_t count = lines.parse_unsigned(header[0], "triangle count", kMaxTriangles);
    std::uint64_t corners = 3;
    if (header.size() > 1) {
        corners = lines.parse_unsigned(header[1], "nodes per triangle",
                                       std::numeric_limits<std::uint64_t>::max());
        if (corners != 3 && corners != 6) {
            lines.fail("nodes per triangle must be 3 (or 6 for quadratic triangles), got " +
                       std::to_string(corners));
        }
    }
    EleFile ele;
    if (header.size() > 2) {
        ele.attribute_count = static_cast<std::uint32_t>(
            lines.parse_unsigned(header[2], "attribute count", kMaxAttributes));
    }
    const std::uint64_t expected = 1 + corners + ele.attribute_count;
    const std::string names =
        field_names(corners == 3 ? "number, v1, v2, v3" : "number, v1, v2, v3, v4, v5, v6",
                    ele.attribute_count, false);
    const detail::VertexNumbers vertices(vertex_first_index, vertex_count, "vertex number",
                                         "vertices");

    ele.triangles.reserve(3 * lines.plausible_records(count, 8));
    std::string attribute_name;
    for (std::uint64_t i = 0; i < count; ++i) {
        detail::next_record(lines, i, count, kTriangles);
        expect_field_count(lines, expected, names);
        const auto& fields = lines.fields();
        expect_record_number(lines, fields[0], "triangle", i, ele.first_index);
        for (std::uint64_t k = 0; k < corners; ++k) {
            const std::uint32_t v = vertices.parse(lines, fields[1 + k]);
            if (k < 3) ele.triangles.push_back(v);
        }
        for (std::uint32_t a = 0; a < ele.attribute_count; ++a) {
            attribute_name = "attribute " + std::to_string(a + 1);
            ele.attributes.push_back(
                lines.parse_finite_double(fields[1 + corners + a], attribute_name));
        }
    }
    expect_end(lines, count, kTriangles);
    return ele;
}

}  // namespace

EleFile parse_ele(std::string_view text, const std::string& file_name,
                  std::uint32_t vertex_first_index, std::uint32_t vertex_count) {
    TextLines lines(text, file_name);
    return parse_ele_lines(lines, vertex_first_index, vertex_count);
}

EleFile read_ele(const std::filesystem::path& path, std::uint32_t vertex_first_index,
                 std::uint32_t vertex_count) {
    TextLines lines(path);
    return parse_ele_lines(lines, vertex_first_index, vertex_count);
}

std::string format_ele(std::span<const VertIdx> triangles, std::uint32_t first_index,
                       std::span<const double> attributes) {
    const std::size_t count = triangles.size() / 3;
    const bool with_attributes = !attributes.empty();
    std::string out;
    out.reserve(32 * count + 32);
    append_unsigned(out, count);
    out += with_attributes ? " 3 1\n" : " 3 0\n";
    for (std::size_t t = 0; t < count; ++t) {
        append_unsigned(out, t + first_index);
        for (std::size_t k = 0; k < 3; ++k) {
            out += ' ';
            append_unsigned(out, std::uint64_t{triangles[3 * t + k]} + first_index);
        }
        if (with_attributes) {
            out += ' ';
            append_double(out, attributes[t]);
        }
        out += '\n';
    }
    return out;
}

void write_ele(const std::filesystem::path& path, std::span<const VertIdx> triangles,
               std::uint32_t first_index, std::span<const double> attributes) {
    write_text_file(path, format_ele(triangles, first_index, attributes));
}

std::string format_neigh(std::span<const TriIdx> neighbors_across_edges,
                         std::uint32_t first_index) {
    const std::size_t count = neighbors_across_edges.size() / 3;
    std::string out;
    out.reserve(32 * count + 32);
    append_unsigned(out, count);
    out += " 3\n";
    for (std::size_t t = 0; t < count; ++t) {
        append_unsigned(out, t + first_index);
        for (std::size_t i = 0; i < 3; ++i) {
            // Opposite vertex i lies the edge (v[i+1], v[i+2]), stored in slot (i+1) % 3.
            const TriIdx neighbor = neighbors_across_edges[3 * t + (i + 1) % 3];
            out += ' ';
            if (neighbor == kNone) {
                out += "-1";
            } else {
                append_unsigned(out, std::uint64_t{neighbor} + first_index);
            }
        }
        out += '\n';
    }
    return out;
}

void write_neigh(const std::filesystem::path& path, std::span<const TriIdx> neighbors_across_edges,
                 std::uint32_t first_index) {
    write_text_file(path, format_neigh(neighbors_across_edges, first_index));
}

}  // namespace exactmesh::io
