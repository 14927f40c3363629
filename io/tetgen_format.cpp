// SPDX-License-Identifier: MIT
// TetGen's .node / .ele / .face / .neigh formats (see tetgen_format.hpp). The vertex section and
// the record plumbing are shared with Triangle's formats (io/records).
#include "io/tetgen_format.hpp"

#include <algorithm>
#include <limits>
#include <utility>

#include "io/records.hpp"
#include "io/text_file.hpp"
#include "triangulation/mesh/mesh3.hpp"

namespace exactmesh::io {

namespace {

using detail::expect_end;
using detail::expect_field_count;
using detail::expect_record_number;
using triangulation::kNone;

/// 4 face slots per tetrahedron must be addressable by a 32-bit index.
constexpr std::uint64_t kMaxTets = triangulation::kMaxTetSlots;

constexpr detail::RecordName kTetrahedra{"tetrahedron", "tetrahedra"};

/// exactmesh's corner order <-> TetGen's: the last two corners swapped (an involution).
constexpr unsigned kTetGenCorner[4] = {0, 1, 3, 2};

}  // namespace

namespace {

TetgenNodeFile parse_tetgen_node_lines(TextLines& lines) {
    detail::read_header(lines, "<#points> <dimension=3> <#attributes> <#boundary markers>");
    detail::VertexSection section;
    const std::uint64_t count = detail::parse_vertex_section(lines, 3, "a 3D TetGen file", section);
    expect_end(lines, count, detail::kVertices);
    TetgenNodeFile nodes;
    nodes.xyz = std::move(section.coordinates);
    nodes.first_index = section.first_index;
    nodes.attribute_count = section.attribute_count;
    nodes.attributes = std::move(section.attributes);
    nodes.has_markers = section.has_markers;
    nodes.markers = std::move(section.markers);
    nodes.lines = std::move(section.lines);
    return nodes;
}

TetgenEleFile parse_tetgen_ele_lines(TextLines& lines, std::uint32_t vertex_first_index,
                                     std::uint32_t vertex_count) {
    detail::read_header(lines, "<#tetrahedra> <nodes per tetrahedron=4> <region attribute 0|1>");
    detail::expect_header_fields(lines, 3, "header",
                                 "#tetrahedra, nodes per tetrahedron, region attribute");
    const auto& header = lines.fields();
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
    TetgenEleFile ele;
    if (header.size() > 2)
        ele.has_region = detail::parse_flag(lines, header[2], "region attribute flag");
    const std::uint64_t expected = 1 + corners + (ele.has_region ? 1 : 0);
    const std::string names = std::string(corners == 4 ? "number, 4 nodes" : "number, 10 nodes") +
                              (ele.has_region ? ", region" : "");
    const detail::VertexNumbers nodes(vertex_first_index, vertex_count, "node number", "points");
    ele.tets.reserve(4 * lines.plausible_records(count, 10));
    for (std::uint64_t i = 0; i < count; ++i) {
        detail::next_record(lines, i, count, kTetrahedra);
        expect_field_count(lines, expected, names);
        const auto& fields = lines.fields();
        expect_record_number(lines, fields[0], "tetrahedron", i, ele.first_index);
        std::uint32_t corner[4];
        for (std::uint64_t k = 0; k < corners; ++k) {
            const std::uint32_t v = nodes.parse(lines, fields[1 + k]);
            if (k < 4) corner[k] = v;
        }
        for (const unsigned k : kTetGenCorner) ele.tets.push_back(corner[k]);
        if (ele.has_region) {
            ele.regions.push_back(lines.parse_finite_double(fields.back(), "region attribute"));
        }
    }
    expect_end(lines, count, kTetrahedra);
    return ele;
}

/// A per-tetrahedron TetGen table (.ele, .neigh): "<count><header_rest>", then a line per
/// tetrahedron, its number and append_value(out, t, k) for its 4 slots k in TetGen's order,
/// then " <attributes[t]>" when `attributes` is not empty (.ele's region attribute).
template <class AppendValue>
std::string format_tet_table(std::size_t count, std::uint32_t first_index, const char* header_rest,
                             AppendValue&& append_value, std::span<const double> attributes = {}) {
    std::string out;
    out.reserve(48 * count + 32);
    append_unsigned(out, count);
    out += header_rest;
    for (std::size_t t = 0; t < count; ++t) {
        append_unsigned(out, t + first_index);
        for (const unsigned k : kTetGenCorner) {
            out += ' ';
            append_value(out, t, k);
        }
        if (!attributes.empty()) {
            out += ' ';
            append_double(out, attributes[t]);
        }
        out += '\n';
    }
    return out;
}

}  // namespace

TetgenNodeFile parse_tetgen_node(std::string_view text, const std::string& file_name) {
    TextLines lines(text, file_name);
    return parse_tetgen_node_lines(lines);
}

TetgenNodeFile read_tetgen_node(const std::filesystem::path& path) {
    TextLines lines(path);
    return parse_tetgen_node_lines(lines);
}

unsigned read_node_dimension(const std::filesystem::path& path) {
    TextLines lines(path);
    return detail::node_dimension(lines);
}

TetgenEleFile parse_tetgen_ele(std::string_view text, const std::string& file_name,
                               std::uint32_t vertex_first_index, std::uint32_t vertex_count) {
    TextLines lines(text, file_name);
    return parse_tetgen_ele_lines(lines, vertex_first_index, vertex_count);
}

TetgenEleFile read_tetgen_ele(const std::filesystem::path& path, std::uint32_t vertex_first_index,
                              std::uint32_t vertex_count) {
    TextLines lines(path);
    return parse_tetgen_ele_lines(lines, vertex_first_index, vertex_count);
}

TetgenFaceFile read_tetgen_face(const std::filesystem::path& path, std::uint32_t vertex_first_index,
                                std::uint32_t vertex_count) {
    static constexpr detail::RecordName kFaces{"face", "faces"};
    TextLines lines(path);
    detail::read_header(lines, "<#faces> <boundary marker 0|1>");
    detail::expect_header_fields(lines, 2, "header", "#faces, boundary marker");
    const auto& header = lines.fields();
    const std::uint64_t count = lines.parse_unsigned(header[0], "face count", 4 * kMaxTets);
    TetgenFaceFile file;
    if (header.size() > 1) file.has_markers = detail::parse_flag(lines, header[1], "marker flag");
    const std::uint64_t expected = file.has_markers ? 5 : 4;
    const std::string names = file.has_markers ? "number, 3 nodes, marker" : "number, 3 nodes";
    const detail::VertexNumbers nodes(vertex_first_index, vertex_count, "node number", "points");
    file.faces.reserve(3 * lines.plausible_records(count, 8));
    for (std::uint64_t i = 0; i < count; ++i) {
        detail::next_record(lines, i, count, kFaces);
        expect_field_count(lines, expected, names);
        const auto& fields = lines.fields();
        expect_record_number(lines, fields[0], "face", i, file.first_index);
        for (int k = 1; k <= 3; ++k) file.faces.push_back(nodes.parse(lines, fields[k]));
        if (file.has_markers) {
            const std::int64_t marker =
                lines.parse_signed(fields[4], "boundary marker", INT32_MIN, INT32_MAX);
            file.markers.push_back(static_cast<std::int32_t>(marker));
        }
    }
    expect_end(lines, count, kFaces);
    return file;
}

std::string format_tetgen_node(std::span<const double> xyz, std::uint32_t first_index,
                               std::span<const double> attribute) {
    const std::size_t count = xyz.size() / 3;
    std::string out;
    out.reserve(64 * count + 32);
    append_unsigned(out, count);
    out += attribute.empty() ? " 3 0 0\n" : " 3 1 0\n";
    for (std::size_t v = 0; v < count; ++v) {
        append_unsigned(out, v + first_index);
        for (std::size_t c = 0; c < 3; ++c) {
            out += ' ';
            append_double(out, xyz[3 * v + c]);
        }
        if (!attribute.empty()) {
            out += ' ';
            append_double(out, attribute[v]);
        }
        out += '\n';
    }
    return out;
}

void write_tetgen_node(const std::filesystem::path& path, std::span<const double> xyz,
                       std::uint32_t first_index) {
    write_text_file(path, format_tetgen_node(xyz, first_index));
}

std::string format_tetgen_ele(std::span<const std::uint32_t> tets, std::uint32_t first_index,
                              std::span<const double> attributes) {
    return format_tet_table(
        tets.size() / 4, first_index, attributes.empty() ? " 4 0\n" : " 4 1\n",
        [&](std::string& out, std::size_t t, unsigned k) {
            append_unsigned(out, std::uint64_t{tets[4 * t + k]} + first_index);
        },
        attributes);
}

void write_tetgen_ele(const std::filesystem::path& path, std::span<const std::uint32_t> tets,
                      std::uint32_t first_index) {
    write_text_file(path, format_tetgen_ele(tets, first_index));
}

std::string format_tetgen_boundary_faces(std::span<const std::uint32_t> tets,
                                         std::span<const std::uint32_t> neighbors,
                                         std::uint32_t first_index) {
    const std::size_t count = tets.size() / 4;
    std::size_t faces = 0;
    for (const std::uint32_t n : neighbors) faces += n == kNone ? 1 : 0;
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

void write_tetgen_boundary_faces(const std::filesystem::path& path,
                                 std::span<const std::uint32_t> tets,
                                 std::span<const std::uint32_t> neighbors,
                                 std::uint32_t first_index) {
    write_text_file(path, format_tetgen_boundary_faces(tets, neighbors, first_index));
}

std::string format_tetgen_marked_faces(std::span<const std::uint32_t> faces,
                                       std::span<const int> markers, std::uint32_t first_index) {
    const std::size_t count = faces.size() / 3;
    std::string out;
    out.reserve(48 * count + 32);
    append_unsigned(out, count);
    out += " 1\n";
    for (std::size_t f = 0; f < count; ++f) {
        append_unsigned(out, f + first_index);
        for (unsigned k = 0; k < 3; ++k) {
            out += ' ';
            append_unsigned(out, std::uint64_t{faces[3 * f + k]} + first_index);
        }
        out += ' ';
        out += std::to_string(markers[f]);
        out += '\n';
    }
    return out;
}

std::string format_tetgen_neigh(std::span<const std::uint32_t> neighbors,
                                std::uint32_t first_index) {
    return format_tet_table(neighbors.size() / 4, first_index, " 4\n",
                            [&](std::string& out, std::size_t t, unsigned k) {
                                const std::uint32_t neighbor = neighbors[4 * t + k];
                                if (neighbor == kNone) {
                                    out += "-1";
                                } else {
                                    append_unsigned(out, std::uint64_t{neighbor} + first_index);
                                }
                            });
}

void write_tetgen_neigh(const std::filesystem::path& path, std::span<const std::uint32_t> neighbors,
                        std::uint32_t first_index) {
    write_text_file(path, format_tetgen_neigh(neighbors, first_index));
}

}  // namespace exactmesh::io
