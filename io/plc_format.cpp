// SPDX-License-Identifier: MIT
// Readers of piecewise linear complexes (see plc_format.hpp).
#include "io/plc_format.hpp"

#include <array>
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <map>
#include <memory>
#include <utility>

#include "io/format_error.hpp"
#include "io/records.hpp"
#include "io/tetgen_format.hpp"
#include "io/text_file.hpp"
#include "io/triangle_format.hpp"

namespace exactmesh::io {

namespace {

using detail::expect_end;
using detail::expect_field_count;
using detail::expect_record_number;

constexpr detail::RecordName kFacets{"facet", "facets"};
constexpr detail::RecordName kPolygons{"polygon", "polygons"};
constexpr detail::RecordName kHoles{"hole", "holes"};
constexpr detail::RecordName kRegions{"region", "regions"};
constexpr detail::RecordName kFaces{"face", "faces"};

/// Facets, polygons, corners and holes: far more than any file holds, small enough that
/// counts times record sizes cannot overflow.
constexpr std::uint64_t kMaxRecords = std::uint64_t{1} << 32;

/// Part 1 of a .poly/.smesh: the points, or the .node file's when the count is 0.
void parse_points(TextLines& lines, const std::filesystem::path& node_path, PlcFile& plc) {
    detail::read_header(lines, "<#points> <dimension=3> <#attributes> <#boundary markers>");
    detail::VertexSection section;
    const std::uint64_t count = detail::parse_vertex_section(lines, 3, "a 3D TetGen file", section);
    if (count == 0) {
        // TetGen's convention: the points are in the .node file of the same name.
        TetgenNodeFile nodes = read_tetgen_node(node_path);
        plc.xyz = std::move(nodes.xyz);
        plc.first_index = nodes.first_index;
        plc.vertices_from_node_file = true;
        return;
    }
    plc.xyz = std::move(section.coordinates);
    plc.first_index = section.first_index;
}

/// A header holding one count ("<#holes>", "<#regions>").
std::uint64_t parse_count_header(const TextLines& lines, detail::RecordName name) {
    const auto& header = lines.fields();
    if (header.size() != 1) {
        lines.fail_quoting_line(std::string(name.singular) +
                                " header must hold one field, the number of " + name.plural);
    }
    return lines.parse_unsigned(header[0], std::string(name.singular) + " count", kMaxRecords);
}

/// `<number> <x> <y> <z>` hole lines (a facet's or the volume's), numbered from `base`.
void parse_hole_lines(TextLines& lines, std::uint64_t count, std::uint32_t base,
                      std::vector<double>& holes, std::vector<std::uint64_t>* hole_lines) {
    std::uint32_t hole_base = base;
    for (std::uint64_t i = 0; i < count; ++i) {
        detail::next_record(lines, i, count, kHoles);
        expect_field_count(lines, 4, "number, x, y, z");
        expect_record_number(lines, lines.fields()[0], "hole", i, hole_base);
        if (hole_lines != nullptr) hole_lines->push_back(lines.line_number());
        holes.push_back(lines.parse_finite_double(lines.fields()[1], "hole x coordinate"));
        holes.push_back(lines.parse_finite_double(lines.fields()[2], "hole y coordinate"));
        holes.push_back(lines.parse_finite_double(lines.fields()[3], "hole z coordinate"));
    }
}

/// Parts 3 and 4 of a .poly/.smesh: the volume holes, then optionally the regions.
void parse_holes_and_regions(TextLines& lines, PlcFile& plc) {
    if (!lines.next_data_line()) lines.fail_at_end("file ends before the hole count ('<#holes>')");
    parse_hole_lines(lines, parse_count_header(lines, kHoles), plc.first_index, plc.holes,
                     &plc.hole_lines);
    if (!lines.next_data_line()) return;
    const std::uint64_t count = parse_count_header(lines, kRegions);
    std::uint32_t region_base = plc.first_index;
    for (std::uint64_t i = 0; i < count; ++i) {
        detail::next_record(lines, i, count, kRegions);
        const auto& fields = lines.fields();
        if (fields.size() != 5 && fields.size() != 6) {
            lines.fail_quoting_line(
                "expected 5 or 6 fields (number, x, y, z, attribute[, maximum volume]), got " +
                std::to_string(fields.size()));
        }
        expect_record_number(lines, fields[0], "region", i, region_base);
        plc.region_lines.push_back(lines.line_number());
        plc.regions.push_back(lines.parse_finite_double(fields[1], "region x coordinate"));
        plc.regions.push_back(lines.parse_finite_double(fields[2], "region y coordinate"));
        plc.regions.push_back(lines.parse_finite_double(fields[3], "region z coordinate"));
        plc.regions.push_back(lines.parse_finite_double(fields[4], "region attribute"));
        plc.regions.push_back(fields.size() == 6
                                  ? lines.parse_finite_double(fields[5], "region maximum volume")
                                  : -1.0);
    }
    expect_end(lines, count, kRegions);
}

/// The facet header of part 2: the count and the marker flag.
std::uint64_t parse_facet_header(TextLines& lines, PlcFile& plc) {
    if (!lines.next_data_line()) {
        lines.fail_at_end("file ends before the facet header ('<#facets> <#boundary markers>')");
    }
    detail::expect_header_fields(lines, 2, "facet header", "#facets, #boundary markers");
    const auto& header = lines.fields();
    const std::uint64_t count = lines.parse_unsigned(header[0], "facet count", kMaxRecords);
    if (header.size() > 1) {
        plc.has_facet_markers = detail::parse_flag(lines, header[1], "facet marker count");
    }
    return count;
}

std::int32_t parse_marker(const TextLines& lines, std::string_view token) {
    return static_cast<std::int32_t>(lines.parse_signed(token, "facet marker",
                                                        std::numeric_limits<std::int32_t>::min(),
                                                        std::numeric_limits<std::int32_t>::max()));
}

PlcFile parse_poly_lines(TextLines& lines, const std::filesystem::path& node_path) {
    PlcFile plc;
    parse_points(lines, node_path, plc);
    const detail::VertexNumbers corners(plc.first_index, plc.vertex_count(), "corner", "points");
    const std::uint64_t facet_count = parse_facet_header(lines, plc);
    plc.facets.reserve(lines.plausible_records(facet_count, 4));
    for (std::uint64_t f = 0; f < facet_count; ++f) {
        detail::next_record(lines, f, facet_count, kFacets);
        const auto& header = lines.fields();
        const std::size_t max_fields = plc.has_facet_markers ? 3 : 2;
        if (header.size() > max_fields) {
            lines.fail_quoting_line(
                "facet line has " + std::to_string(header.size()) + " fields, expected at most " +
                std::to_string(max_fields) +
                (plc.has_facet_markers
                     ? " (#polygons, #holes, marker)"
                     : " (#polygons, #holes; the facet header announces no markers)"));
        }
        PlcFacetRecord facet;
        facet.line = lines.line_number();
        const std::uint64_t polygons =
            lines.parse_unsigned(header[0], "polygon count", kMaxRecords);
        if (polygons == 0)
            lines.fail("facet " + std::to_string(f + plc.first_index) + " has no polygons");
        const std::uint64_t holes =
            header.size() > 1 ? lines.parse_unsigned(header[1], "facet hole count", kMaxRecords)
                              : 0;
        if (header.size() > 2) facet.marker = parse_marker(lines, header[2]);
        facet.polygons.reserve(lines.plausible_records(polygons, 4));
        for (std::uint64_t p = 0; p < polygons; ++p) {
            detail::next_record(lines, p, polygons, kPolygons);
            const auto& fields = lines.fields();
            const std::uint64_t n = lines.parse_unsigned(fields[0], "corner count", kMaxRecords);
            if (n == 0) lines.fail("a polygon needs at least 1 corner, got 0");
            expect_field_count(lines, n + 1, "#corners, " + detail::plural(n, "corner", "corners"));
            std::vector<std::uint32_t> polygon;
            polygon.reserve(n);
            for (std::uint64_t k = 0; k < n; ++k)
                polygon.push_back(corners.parse(lines, fields[1 + k]));
            facet.polygons.push_back(std::move(polygon));
        }
        parse_hole_lines(lines, holes, plc.first_index, facet.holes, nullptr);
        plc.facets.push_back(std::move(facet));
    }
    parse_holes_and_regions(lines, plc);
    return plc;
}

PlcFile parse_smesh_lines(TextLines& lines, const std::filesystem::path& node_path) {
    PlcFile plc;
    parse_points(lines, node_path, plc);
    const detail::VertexNumbers corners(plc.first_index, plc.vertex_count(), "corner", "points");
    const std::uint64_t facet_count = parse_facet_header(lines, plc);
    plc.facets.reserve(lines.plausible_records(facet_count, 8));
    for (std::uint64_t f = 0; f < facet_count; ++f) {
        detail::next_record(lines, f, facet_count, kFacets);
        const auto& fields = lines.fields();
        const std::uint64_t n = lines.parse_unsigned(fields[0], "corner count", kMaxRecords);
        if (n == 0) lines.fail("a facet needs at least 1 corner, got 0");
        const std::uint64_t marker = plc.has_facet_markers ? 1 : 0;
        expect_field_count(
            lines, n + 1 + marker,
            "#corners, " + detail::plural(n, "corner", "corners") + (marker ? ", marker" : ""));
        PlcFacetRecord facet;
        facet.line = lines.line_number();
        std::vector<std::uint32_t> polygon;
        polygon.reserve(n);
        for (std::uint64_t k = 0; k < n; ++k)
            polygon.push_back(corners.parse(lines, fields[1 + k]));
        facet.polygons.push_back(std::move(polygon));
        if (marker) facet.marker = parse_marker(lines, fields.back());
        plc.facets.push_back(std::move(facet));
    }
    parse_holes_and_regions(lines, plc);
    return plc;
}

PlcFile parse_off_lines(TextLines& lines) {
    detail::read_header(lines, "OFF");
    if (lines.fields()[0] != "OFF") {
        lines.fail("expected the keyword OFF on the first line, got '" +
                   printable(lines.fields()[0]) + "'" +
                   (lines.fields()[0].find("OFF") != std::string_view::npos
                        ? " (only plain OFF is read: no colours, normals or texture per vertex)"
                        : ""));
    }
    // The counts follow on the same line or on the next one.
    std::vector<std::string_view> counts(lines.fields().begin() + 1, lines.fields().end());
    if (counts.empty()) {
        if (!lines.next_data_line()) {
            lines.fail_at_end("file ends before the counts ('<#vertices> <#faces> <#edges>')");
        }
        counts = lines.fields();
    }
    if (counts.size() < 2 || counts.size() > 3) {
        lines.fail_quoting_line("expected the counts <#vertices> <#faces> [<#edges>], got " +
                                detail::plural(counts.size(), "field", "fields"));
    }
    const std::uint64_t vertex_count = lines.parse_unsigned(counts[0], "vertex count", 0x3FFFFFFFu);
    const std::uint64_t face_count = lines.parse_unsigned(counts[1], "face count", kMaxRecords);
    if (counts.size() == 3) lines.parse_unsigned(counts[2], "edge count", kMaxRecords);
    PlcFile plc;
    plc.xyz.reserve(3 * lines.plausible_records(vertex_count, 6));
    for (std::uint64_t v = 0; v < vertex_count; ++v) {
        detail::next_record(lines, v, vertex_count, detail::kVertices);
        expect_field_count(lines, 3, "x, y, z");
        plc.xyz.push_back(lines.parse_finite_double(lines.fields()[0], "x coordinate"));
        plc.xyz.push_back(lines.parse_finite_double(lines.fields()[1], "y coordinate"));
        plc.xyz.push_back(lines.parse_finite_double(lines.fields()[2], "z coordinate"));
    }
    const detail::VertexNumbers corners(0, static_cast<std::uint32_t>(vertex_count),
                                        "vertex number", "vertices");
    plc.facets.reserve(lines.plausible_records(face_count, 8));
    for (std::uint64_t f = 0; f < face_count; ++f) {
        detail::next_record(lines, f, face_count, kFaces);
        const auto& fields = lines.fields();
        const std::uint64_t n = lines.parse_unsigned(fields[0], "corner count", kMaxRecords);
        if (n == 0) lines.fail("a face needs at least 1 corner, got 0");
        const std::uint64_t colour = fields.size() < n + 1 ? 0 : fields.size() - n - 1;
        if (fields.size() < n + 1 || (colour != 0 && colour != 3 && colour != 4)) {
            lines.fail_quoting_line("expected " + detail::plural(n + 1, "field", "fields") +
                                    " (#corners, " + detail::plural(n, "corner", "corners") +
                                    ") and an optional colour of 3 or 4 numbers, got " +
                                    std::to_string(fields.size()));
        }
        for (std::uint64_t c = 0; c < colour; ++c) {
            lines.parse_finite_double(fields[1 + n + c], "colour component");
        }
        PlcFacetRecord facet;
        facet.line = lines.line_number();
        std::vector<std::uint32_t> polygon;
        polygon.reserve(n);
        for (std::uint64_t k = 0; k < n; ++k)
            polygon.push_back(corners.parse(lines, fields[1 + k]));
        facet.polygons.push_back(std::move(polygon));
        plc.facets.push_back(std::move(facet));
    }
    expect_end(lines, face_count, kFaces);
    return plc;
}

/// Merges corners with equal coordinates (exactly; -0 == 0) into vertices numbered in order of
/// first appearance.
class VertexMerger {
  public:
    explicit VertexMerger(PlcFile& plc) : plc_(plc) {}
    std::uint32_t add(double x, double y, double z) {
        // Adding +0 turns -0 into +0 and changes nothing else.
        const std::array<double, 3> key{x + 0.0, y + 0.0, z + 0.0};
        const auto [it, inserted] = index_.emplace(key, plc_.vertex_count());
        if (inserted) plc_.xyz.insert(plc_.xyz.end(), key.begin(), key.end());
        return it->second;
    }

  private:
    PlcFile& plc_;
    std::map<std::array<double, 3>, std::uint32_t> index_;
};

void add_triangle_facet(PlcFile& plc, std::array<std::uint32_t, 3> corners, std::uint64_t line) {
    PlcFacetRecord facet;
    facet.polygons.push_back({corners[0], corners[1], corners[2]});
    facet.line = line;
    plc.facets.push_back(std::move(facet));
}

/// The next data line must be the keyword(s) `words`.
void expect_keywords(TextLines& lines, std::initializer_list<std::string_view> words,
                     const char* what) {
    if (!lines.next_data_line()) lines.fail_at_end(std::string("file ends before '") + what + "'");
    const auto& fields = lines.fields();
    bool match = fields.size() == words.size();
    std::size_t k = 0;
    for (const std::string_view word : words) {
        if (!match) break;
        match = fields[k++] == word;
    }
    if (!match) lines.fail_quoting_line(std::string("expected '") + what + "'");
}

/// An ASCII STL, a line at a time (from memory or streamed from a file).
PlcFile parse_ascii_stl_lines(TextLines& lines) {
    PlcFile plc;
    VertexMerger merger(plc);
    if (!lines.next_data_line() || lines.fields()[0] != "solid") {
        lines.fail("expected 'solid' at the start of an ASCII STL file");
    }
    for (;;) {
        if (!lines.next_data_line()) lines.fail_at_end("file ends before 'endsolid'");
        const auto& fields = lines.fields();
        if (fields[0] == "endsolid") {
            if (!lines.next_data_line()) break;
            if (lines.fields()[0] != "solid") {
                lines.fail_quoting_line("expected 'solid' or the end of the file after 'endsolid'");
            }
            continue;
        }
        if (fields[0] != "facet" || fields.size() != 5 || fields[1] != "normal") {
            lines.fail_quoting_line("expected 'facet normal <nx> <ny> <nz>' or 'endsolid'");
        }
        const std::uint64_t line = lines.line_number();
        expect_keywords(lines, {"outer", "loop"}, "outer loop");
        std::array<std::uint32_t, 3> corners{};
        for (std::uint32_t& corner : corners) {
            if (!lines.next_data_line()) lines.fail_at_end("file ends inside a facet");
            const auto& vertex = lines.fields();
            if (vertex[0] != "vertex" || vertex.size() != 4) {
                lines.fail_quoting_line(
                    "expected 'vertex <x> <y> <z>' (an STL facet has exactly 3 vertices)");
            }
            const double x = lines.parse_finite_double(vertex[1], "x coordinate");
            const double y = lines.parse_finite_double(vertex[2], "y coordinate");
            const double z = lines.parse_finite_double(vertex[3], "z coordinate");
            corner = merger.add(x, y, z);
        }
        expect_keywords(lines, {"endloop"}, "endloop");
        expect_keywords(lines, {"endfacet"}, "endfacet");
        add_triangle_facet(plc, corners, line);
    }
    return plc;
}

float little_endian_float(const unsigned char* bytes) {
    const std::uint32_t bits = std::uint32_t{bytes[0]} | (std::uint32_t{bytes[1]} << 8) |
                               (std::uint32_t{bytes[2]} << 16) | (std::uint32_t{bytes[3]} << 24);
    return std::bit_cast<float>(bits);
}

PlcFile parse_binary_stl(std::string_view bytes, const std::string& file_name,
                         std::uint64_t count) {
    PlcFile plc;
    plc.facet_lines_are_triangles = true;
    VertexMerger merger(plc);
    const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
    for (std::uint64_t t = 0; t < count; ++t) {
        const unsigned char* record = data + 84 + 50 * t;
        std::array<std::uint32_t, 3> corners{};
        for (int c = 0; c < 3; ++c) {
            double p[3];
            for (int k = 0; k < 3; ++k) {
                p[k] = little_endian_float(record + 12 + 12 * c + 4 * k);
                if (!std::isfinite(p[k])) {
                    throw FormatError(file_name, 0,
                                      "binary STL triangle " + std::to_string(t + 1) + ": corner " +
                                          std::to_string(c + 1) + " has a non-finite coordinate");
                }
            }
            corners[static_cast<std::size_t>(c)] = merger.add(p[0], p[1], p[2]);
        }
        add_triangle_facet(plc, corners, t + 1);
    }
    return plc;
}

}  // namespace

PlcFile parse_tetgen_poly_3d(std::string_view text, const std::string& file_name,
                             const std::filesystem::path& node_path) {
    TextLines lines(text, file_name);
    return parse_poly_lines(lines, node_path);
}

PlcFile read_tetgen_poly_3d(const std::filesystem::path& path) {
    TextLines lines(path);
    return parse_poly_lines(lines, poly_node_path(path));
}

PlcFile parse_smesh(std::string_view text, const std::string& file_name,
                    const std::filesystem::path& node_path) {
    TextLines lines(text, file_name);
    return parse_smesh_lines(lines, node_path);
}

PlcFile read_smesh(const std::filesystem::path& path) {
    TextLines lines(path);
    return parse_smesh_lines(lines, poly_node_path(path));
}

PlcFile parse_off(std::string_view text, const std::string& file_name) {
    TextLines lines(text, file_name);
    return parse_off_lines(lines);
}

PlcFile read_off(const std::filesystem::path& path) {
    TextLines lines(path);
    return parse_off_lines(lines);
}

namespace {

/// The triangle count of a binary STL's head (84 bytes or more).
std::uint64_t binary_stl_count(std::string_view head) {
    const auto* data = reinterpret_cast<const unsigned char*>(head.data());
    return std::uint64_t{data[80]} | (std::uint64_t{data[81]} << 8) |
           (std::uint64_t{data[82]} << 16) | (std::uint64_t{data[83]} << 24);
}

/// Whether `head` (the start of a file) can start an ASCII STL: 'solid' after an optional UTF-8
/// byte order mark and blanks (a head of blanks alone is left to the line reader to judge).
bool starts_like_ascii_stl(std::string_view head) {
    if (head.substr(0, 3) == "\xEF\xBB\xBF") head.remove_prefix(3);
    std::size_t start = 0;
    while (start < head.size() && (head[start] == ' ' || head[start] == '\t' ||
                                   head[start] == '\r' || head[start] == '\n')) {
        ++start;
    }
    return start == head.size() || head.substr(start, 5) == "solid";
}

[[noreturn]] void fail_neither_stl(const std::string& file_name, const std::string& length) {
    throw FormatError(file_name, 0,
                      "neither an ASCII STL file (starting with 'solid') nor a binary one (84 + "
                      "50 x count bytes, count at byte 80), " +
                          length);
}

}  // namespace

PlcFile parse_stl(std::string_view bytes, const std::string& file_name) {
    if (bytes.size() >= 84 && bytes.size() == 84 + 50 * binary_stl_count(bytes))
        return parse_binary_stl(bytes, file_name, binary_stl_count(bytes));
    if (!starts_like_ascii_stl(bytes.substr(0, 4096)))
        fail_neither_stl(file_name, detail::plural(bytes.size(), "byte", "bytes") + " long");
    TextLines lines(bytes, file_name);
    return parse_ascii_stl_lines(lines);
}

PlcFile read_stl(const std::filesystem::path& path) {
    // The head and the file's size decide: a binary file (exactly 84 + 50 x count bytes) is
    // read whole, anything else is streamed as ASCII a line at a time, so that /dev/zero or a
    // large file that is no STL fails at its start instead of being read into memory first
    // (1 GB and 2.6 s for /dev/zero before). A binary STL must be a regular file: its size is
    // what tells it apart.
    TextLines lines(path);  // the open errors (missing, a directory) of every reader
    std::error_code ec;
    const bool regular = std::filesystem::is_regular_file(path, ec);
    const std::uint64_t size = regular ? std::filesystem::file_size(path, ec) : 0;
    std::string head;
    {
        std::unique_ptr<std::FILE, int (*)(std::FILE*)> in(std::fopen(path.c_str(), "rb"),
                                                           &std::fclose);
        if (in) {
            head.resize(regular ? 84 : 0);
            head.resize(std::fread(head.data(), 1, head.size(), in.get()));
        }
    }
    if (regular && !ec && head.size() == 84 && size == 84 + 50 * binary_stl_count(head))
        return parse_stl(read_text_file(path, size), path.string());
    if (regular && !starts_like_ascii_stl(head))
        fail_neither_stl(path.string(), detail::plural(size, "byte", "bytes") + " long");
    return parse_ascii_stl_lines(lines);
}

PlcFile read_plc(const std::filesystem::path& path) {
    if (has_extension(path, ".poly")) return read_tetgen_poly_3d(path);
    if (has_extension(path, ".smesh")) return read_smesh(path);
    if (has_extension(path, ".off")) return read_off(path);
    if (has_extension(path, ".stl")) return read_stl(path);
    throw FormatError(path.string(), 0,
                      "unknown PLC file extension (expected .poly, .smesh, .off or .stl)");
}

}  // namespace exactmesh::io
