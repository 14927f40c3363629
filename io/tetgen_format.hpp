// SPDX-License-Identifier: MIT
// TetGen's .node and .ele files for 3D point sets and tetrahedralizations [Si15: H. Si,
// "TetGen, a Delaunay-based quality tetrahedral mesh generator", ACM TOMS 41(2), 2015; the
// TetGen 1.5 manual, §5.2.1 and §5.2.4]: minimal, strict readers (every malformed input an error
// naming the file, the line and the text) and writers whose output TetGen and this library
// read back exactly. Orientation: TetGen lists the corners of a tetrahedron with
// orient3d(n1, n2, n3, n4) < 0 in Shewchuk's sign convention (its checkmesh() calls a positive
// orient3d "inverted"), the opposite of Tetrahedralization3's; the reader stores (n1, n2, n4, n3)
// and the writer writes (v0, v1, v3, v2), so TetGen's files and ours agree.
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace exactmesh::io {

/// The content of a TetGen .node file.
struct TetgenNodeFile {
    std::vector<double> xyz;            ///< 3·#V coordinates, in file order
    std::uint32_t first_index = 0;      ///< number of the first point: 0 or 1
    std::uint32_t attribute_count = 0;  ///< attributes per point
    std::vector<double> attributes;     ///< attribute_count·#V
    bool has_markers = false;
    std::vector<std::int32_t> markers;  ///< #V boundary markers when has_markers

    std::uint32_t vertex_count() const { return static_cast<std::uint32_t>(xyz.size() / 3); }
};

/// The content of a TetGen .ele file, in exactmesh's orientation and 0-based vertex indices.
struct TetgenEleFile {
    std::vector<std::uint32_t> tets;    ///< 4·#T corners: (n1, n2, n4, n3) of each file line
    std::uint32_t first_index = 0;      ///< number of the first tetrahedron: 0 or 1
    bool has_region = false;
    std::vector<double> regions;        ///< #T region attributes when has_region

    std::uint32_t tet_count() const { return static_cast<std::uint32_t>(tets.size() / 4); }
};

/// Reads `<#points> <dimension=3> <#attributes> <#markers 0|1>` (trailing header fields may be
/// omitted) and `<number> <x> <y> <z> [attributes...] [marker]` lines; '#' comments, blank
/// lines and CRLF are fine; numbering from 0 or 1 (the first point sets it).
/// @throws FormatError "file:line: problem" on any malformed input.
TetgenNodeFile read_tetgen_node(const std::filesystem::path& path);
TetgenNodeFile parse_tetgen_node(std::string_view text, const std::string& file_name);

/// Reads `<#tetrahedra> <nodes per tetrahedron 4|10> <region attribute 0|1>` and
/// `<number> <n1> <n2> <n3> <n4> [6 more nodes] [region]` lines; node numbers must lie in the
/// .node file's numbering [vertex_first_index, vertex_first_index + vertex_count).
TetgenEleFile read_tetgen_ele(const std::filesystem::path& path, std::uint32_t vertex_first_index,
                              std::uint32_t vertex_count);
TetgenEleFile parse_tetgen_ele(std::string_view text, const std::string& file_name,
                               std::uint32_t vertex_first_index, std::uint32_t vertex_count);

/// `#V 3 0 0` and the points, numbered from first_index, coordinates shortest round-trip.
std::string format_tetgen_node(std::span<const double> xyz, std::uint32_t first_index);
void write_tetgen_node(const std::filesystem::path& path, std::span<const double> xyz, std::uint32_t first_index);

/// `#T 4 0` and the tetrahedra (exactmesh orientation in, TetGen's written), tetrahedra and
/// vertices numbered from first_index.
std::string format_tetgen_ele(std::span<const std::uint32_t> tets, std::uint32_t first_index);
void write_tetgen_ele(const std::filesystem::path& path, std::span<const std::uint32_t> tets,
                      std::uint32_t first_index);

}  // namespace exactmesh::io
