// SPDX-License-Identifier: MIT
// TetGen's .node / .ele / .face / .neigh formats (see tetgen_format.hpp).
#include "io/tetgen_format.hpp"

#include <algorithm>
#include <limits>
#include <utility>

#include "io/records.hpp"
#include "io/text_file.hpp"

namespace exactmesh::io {

namespace {

using detail::expect_end;
using detail::expect_field_count;
using detail::expect_record_number;
using detail::field_names;
using detail::plausible;
using detail::plural;
using triangulation::kNone;

/// 4 face slots per tetrahedron must be addressable by a 32-bit index.
constexpr std::uint64_t kMaxTets = triangulation::kMaxTetSlots;

/// triangulation/'s corner order <-> TetGen's: the first two corners swapped (an involution).
constexpr unsigned kTetGenCorner[4] = {1, 0, 2, 3};

}  // namespace

NodeFile3 parse_node_3d(std::string_view text, const std::string& file_name) {
    TextLines lines(text, file_name);
    if (!lines.next_data_line()) {
        lines.fail_at_end(
            "no header line (expected '<#vertices> <dimension=3> <#attributes> <#boundary "
            "markers>')");
    }
    detail::VertexSection section;
    const std::uint64_t count =
        detail::parse_vertex_section(lines, text.size(), 3, "a 3D TetGen file", section);
    expect_end(lines, count, count == 1 ? "vertex" : "vertices");
    NodeFile3 nodes;
    nodes.xyz = std::move(section.coordinates);
    nodes.first_index = section.first_index;
    nodes.attribute_count = section.attribute_count;
    nodes.attributes = std::move(section.attributes);
    nodes.has_markers = section.has_markers;
    nodes.markers = std::move(section.markers);
    return nodes;
}

NodeFile3 read_node_3d(const std::filesystem::path& path) {
    return parse_node_3d(read_text_file(path), path.string());
}

unsigned read_node_dimension(const std::filesystem::path& path) {
    return detail::node_dimension(read_text_file(path), path.string());
}

std::string format_node_3d(const NodeFile3& nodes) {
    const std::uint32_t count = nodes.vertex_count();
    std::string out;
    out.reserve(72 * std::size_t{count} + 64);
    append_unsigned(out, count);
    out += " 3 ";
    append_unsigned(out, nodes.attribute_count);
    out += nodes.has_markers ? " 1\n" : " 0\n";
    for (std::uint32_t v = 0; v < count; ++v) {
        append_unsigned(out, std::uint64_t{v} + nodes.first_index);
        for (std::size_t c = 0; c < 3; ++c) {
            out += ' ';
            append_double(out, nodes.xyz[3 * std::size_t{v} + c]);
        }
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

void write_node_3d(const std::filesystem::path& path, const NodeFile3& nodes) {
    write_text_file(path, format_node_3d(nodes));
}

TetFile parse_ele_3d(std::string_view text, const std::string& file_name,
                     std::uint32_t vertex_first_index, std::uint32_t vertex_count) {
    TextLines lines(text, file_name);
    if (!lines.next_data_line()) {
        lines.fail_at_end(
            "no header line (expected '<#tetrahedra> <nodes per tetrahedron=4> <#attributes>')");
    }
    const auto& header = lines.fields();
    if (header.size() > 3) {
        lines.fail_quoting_line("header has " + std::to_string(header.size()) +
                                " fields, expected at most 3 (#tetrahedra, nodes per tetrahedron, "
                                "#attributes)");
    }
    const std::uint64_t count = lines.parse_unsigned(header[0], "tetrahedron count", kMaxTets);
    std::uint64_t corners = 4;
    if (header.size() > 1) {
        corners = lines.parse_unsigned(header[1], "nodes per tetrahedron",
                                       std::numeric_limits<std::uint64_t>::max());
        if (corners != 4 && corners != 10) {
            lines.fail("nodes per tetrahedron must be 4 (or 10 for quadratic tetrahedra), got " +
                       std::to_string(corners) +
                       (corners == 3 ? " (a 2D Triangle .ele file?)" : ""));
        }
    }
    TetFile ele;
    if (header.size() > 2) {
        ele.attribute_count = static_cast<std::uint32_t>(
            lines.parse_unsigned(header[2], "attribute count", detail::kMaxAttributes));
    }
    const std::uint64_t expected = 1 + corners + ele.attribute_count;
    const std::string names =
        field_names(corners == 4 ? "number, v1, v2, v3, v4" : "number, v1, ..., v10",
                    ele.attribute_count, false);
    const std::uint64_t last_vertex =
        std::uint64_t{vertex_first_index} + vertex_count;  // exclusive
    const std::string numbering = vertex_count == 0 ? std::string("the node file has no vertices")
                                                    : "the node file numbers its vertices " +
                                                          std::to_string(vertex_first_index) +
                                                          " to " + std::to_string(last_vertex - 1);
    ele.tets.reserve(4 * plausible(count, text.size(), 10));
    std::string attribute_name;
    for (std::uint64_t i = 0; i < count; ++i) {
        if (!lines.next_data_line()) {
            lines.fail_at_end("file ends after " + std::to_string(i) + " of " +
                              plural(count, "announced tetrahedron", "announced tetrahedra"));
        }
        expect_field_count(lines, expected, names);
        const auto& fields = lines.fields();
        expect_record_number(lines, fields[0], "tetrahedron", i, ele.first_index);
        VertIdx corner[4];
        for (std::uint64_t k = 0; k < corners; ++k) {
            const std::uint64_t v = lines.parse_unsigned(fields[1 + k], "vertex number",
                                                         std::numeric_limits<std::uint32_t>::max());
            if (v < vertex_first_index || v >= last_vertex) {
                lines.fail("vertex number " + std::to_string(v) + " out of range: " + numbering);
            }
            if (k < 4) corner[k] = static_cast<VertIdx>(v - vertex_first_index);
        }
        for (const unsigned k : kTetGenCorner) ele.tets.push_back(corner[k]);
        for (std::uint32_t a = 0; a < ele.attribute_count; ++a) {
            attribute_name = "attribute " + std::to_string(a + 1);
            ele.attributes.push_back(
                lines.parse_finite_double(fields[1 + corners + a], attribute_name));
        }
    }
    expect_end(lines, count, count == 1 ? "tetrahedron" : "tetrahedra");
    return ele;
}

TetFile read_ele_3d(const std::filesystem::path& path, std::uint32_t vertex_first_index,
                    std::uint32_t vertex_count) {
    return parse_ele_3d(read_text_file(path), path.string(), vertex_first_index, vertex_count);
}

std::string format_ele_3d(std::span<const VertIdx> tets, std::uint32_t first_index) {
    const std::size_t count = tets.size() / 4;
    std::string out;
    out.reserve(48 * count + 32);
    append_unsigned(out, count);
    out += " 4 0\n";
    for (std::size_t t = 0; t < count; ++t) {
        append_unsigned(out, t + first_index);
        for (const unsigned k : kTetGenCorner) {
            out += ' ';
            append_unsigned(out, std::uint64_t{tets[4 * t + k]} + first_index);
        }
        out += '\n';
    }
    return out;
}

void write_ele_3d(const std::filesystem::path& path, std::span<const VertIdx> tets,
                  std::uint32_t first_index) {
    write_text_file(path, format_ele_3d(tets, first_index));
}

std::string format_boundary_faces(std::span<const VertIdx> tets, std::span<const TetIdx> neighbors,
                                  std::uint32_t first_index) {
    const std::size_t count = tets.size() / 4;
    std::size_t faces = 0;
    for (std::size_t f = 0; f < neighbors.size(); ++f) faces += neighbors[f] == kNone ? 1 : 0;
    std::string out;
    out.reserve(40 * faces + 32);
    append_unsigned(out, faces);
    out += " 0\n";
    std::size_t number = first_index;
    for (std::size_t t = 0; t < count; ++t) {
        for (unsigned k = 0; k < 4; ++k) {
            if (neighbors[4 * t + k] != kNone) continue;
            append_unsigned(out, number++);
            // kFaceVertex[k] sees corner k (inside) on its positive orient3d side: seen from
            // outside, counter-clockwise.
            for (const unsigned c : triangulation::kFaceVertex[k]) {
                out += ' ';
                append_unsigned(out, std::uint64_t{tets[4 * t + c]} + first_index);
            }
            out += '\n';
        }
    }
    return out;
}

void write_boundary_faces(const std::filesystem::path& path, std::span<const VertIdx> tets,
                          std::span<const TetIdx> neighbors, std::uint32_t first_index) {
    write_text_file(path, format_boundary_faces(tets, neighbors, first_index));
}

std::string format_neigh_3d(std::span<const TetIdx> neighbors, std::uint32_t first_index) {
    const std::size_t count = neighbors.size() / 4;
    std::string out;
    out.reserve(48 * count + 32);
    append_unsigned(out, count);
    out += " 4\n";
    for (std::size_t t = 0; t < count; ++t) {
        append_unsigned(out, t + first_index);
        for (const unsigned k : kTetGenCorner) {
            const TetIdx neighbor = neighbors[4 * t + k];
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

void write_neigh_3d(const std::filesystem::path& path, std::span<const TetIdx> neighbors,
                    std::uint32_t first_index) {
    write_text_file(path, format_neigh_3d(neighbors, first_index));
}

}  // namespace exactmesh::io
