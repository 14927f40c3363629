// SPDX-License-Identifier: MIT
// TetGen's 3D file formats [Si15: H. Si, "TetGen, a Delaunay-based quality tetrahedral mesh
// generator", ACM TOMS 41(2), 2015; the TetGen 1.5 manual, §5.2: .node, .ele, .face, .neigh]:
// strict readers (every malformed input an error naming the file, the line and the text) and
// writers whose output TetGen (-r) and this library read back exactly.
//
// Orientation: TetGen lists the corners of a tetrahedron with orient3d(n1, n2, n3, n4) < 0 in
// Shewchuk's sign convention (its checkmesh() calls orient3d >= 0 "inverted"), the opposite of
// Tetrahedralization3's; the reader stores (n1, n2, n4, n3) and the writers write (v0, v1, v3, v2)
// (and the neighbors in the same order), so TetGen's files and ours agree. Gmsh and VTK use
// TetGen's orientation too (gmsh_format, vtk_format). Boundary faces in .face are written
// counter-clockwise seen from outside (outward normal by the right-hand rule).
#pragma once

#include <array>
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
    std::vector<std::uint64_t> lines;   ///< #V: each point's line in the file read (for messages)

    std::uint32_t vertex_count() const { return static_cast<std::uint32_t>(xyz.size() / 3); }
};

/// Where the corners of a file line went: the line's corner k is tets[4t + kTetgenFileCorners[k]]
/// (the reader swaps the last two for exactmesh's orientation); messages list them back in the
/// file's order (triangulation::Check3Numbering::corner_order).
inline constexpr std::array<std::uint8_t, 4> kTetgenFileCorners{0, 1, 3, 2};

/// The content of a TetGen .ele file, in exactmesh's orientation and 0-based vertex indices.
struct TetgenEleFile {
    std::vector<std::uint32_t> tets;  ///< 4·#T corners: (n1, n2, n4, n3) of each file line
    std::uint32_t first_index = 0;    ///< number of the first tetrahedron: 0 or 1
    bool has_region = false;
    std::vector<double> regions;  ///< #T region attributes when has_region

    std::uint32_t tet_count() const { return static_cast<std::uint32_t>(tets.size() / 4); }
};

/// Reads `<#points> <dimension=3> <#attributes> <#markers 0|1>` (trailing header fields may be
/// omitted; an omitted dimension is 3 here) and `<number> <x> <y> <z> [attributes...] [marker]`
/// lines; '#' comments, blank lines and CRLF are fine; numbering from 0 or 1 (the first point
/// sets it). Coordinates are correctly rounded.
/// @throws FormatError "file:line: problem" on any malformed input, including non-finite,
///         overflowing or underflowing coordinates and data past the last point.
TetgenNodeFile read_tetgen_node(const std::filesystem::path& path);
TetgenNodeFile parse_tetgen_node(std::string_view text, const std::string& file_name);

/// The dimension a .node file declares in its header (2 when the field is omitted, Triangle's
/// default): lets a caller pick read_node or read_tetgen_node.
/// @throws FormatError on a missing or malformed header, or a dimension other than 2 and 3.
unsigned read_node_dimension(const std::filesystem::path& path);

/// A TetGen .face file: faces as 3 node numbers each (0-based after reading) and their markers.
struct TetgenFaceFile {
    std::vector<std::uint32_t> faces;  ///< 3·#F corners, in file order
    std::uint32_t first_index = 0;     ///< number of the first face: 0 or 1
    bool has_markers = false;
    std::vector<std::int32_t> markers;  ///< #F boundary markers when has_markers

    std::uint32_t face_count() const { return static_cast<std::uint32_t>(faces.size() / 3); }
};

/// Reads `<#faces> <boundary marker 0|1>` and `<number> <n1> <n2> <n3> [marker]` lines (what
/// `exactmesh tetmesh` and TetGen -p write); node numbers must lie in the .node file's numbering
/// [vertex_first_index, vertex_first_index + vertex_count).
/// @throws FormatError "file:line: problem" on any malformed input.
TetgenFaceFile read_tetgen_face(const std::filesystem::path& path, std::uint32_t vertex_first_index,
                                std::uint32_t vertex_count);

/// Reads `<#tetrahedra> <nodes per tetrahedron 4|10> <region attribute 0|1>` and
/// `<number> <n1> <n2> <n3> <n4> [6 more nodes] [region]` lines; node numbers must lie in the
/// .node file's numbering [vertex_first_index, vertex_first_index + vertex_count).
TetgenEleFile read_tetgen_ele(const std::filesystem::path& path, std::uint32_t vertex_first_index,
                              std::uint32_t vertex_count);
TetgenEleFile parse_tetgen_ele(std::string_view text, const std::string& file_name,
                               std::uint32_t vertex_first_index, std::uint32_t vertex_count);

/// `#V 3 0 0` and the points, numbered from first_index, coordinates shortest round-trip; with
/// `attribute` (#V values: a field at the vertices), `#V 3 1 0` and one attribute per point.
std::string format_tetgen_node(std::span<const double> xyz, std::uint32_t first_index,
                               std::span<const double> attribute = {});
void write_tetgen_node(const std::filesystem::path& path, std::span<const double> xyz,
                       std::uint32_t first_index);

/// `#T 4 0` and the tetrahedra (exactmesh orientation in, TetGen's written), tetrahedra and
/// vertices numbered from first_index. With `attributes` (#T region attributes, as TetGen -A
/// writes them) the header is `#T 4 1` and each line ends with its tetrahedron's attribute.
std::string format_tetgen_ele(std::span<const std::uint32_t> tets, std::uint32_t first_index,
                              std::span<const double> attributes = {});
void write_tetgen_ele(const std::filesystem::path& path, std::span<const std::uint32_t> tets,
                      std::uint32_t first_index);

/// The .face text of the boundary: `#F 0`, then `<f> <a> <b> <c>` for every face k of a
/// tetrahedron t with neighbors[4t + k] == kNone (the face opposite corner k, as in
/// Tetrahedralization3), counter-clockwise seen from outside, numbered from first_index.
std::string format_tetgen_boundary_faces(std::span<const std::uint32_t> tets,
                                         std::span<const std::uint32_t> neighbors,
                                         std::uint32_t first_index);
void write_tetgen_boundary_faces(const std::filesystem::path& path,
                                 std::span<const std::uint32_t> tets,
                                 std::span<const std::uint32_t> neighbors,
                                 std::uint32_t first_index);

/// The .face text of a list of faces with markers: `#F 1`, then `<f> <a> <b> <c> <marker>`
/// (`faces`: 3·#F 0-based vertex indices, written as given; `markers`: #F), numbered from
/// first_index. `exactmesh tetmesh` writes the subfaces of a PLC's facets this way, each with
/// its facet's marker (TetGen -p's .face).
std::string format_tetgen_marked_faces(std::span<const std::uint32_t> faces,
                                       std::span<const int> markers, std::uint32_t first_index);

/// The .neigh text: `#T 4`, then `<t> <n1> <n2> <n3> <n4>`, neighbor i opposite corner i of the
/// tetrahedron as format_tetgen_ele writes it, -1 on the boundary.
std::string format_tetgen_neigh(std::span<const std::uint32_t> neighbors,
                                std::uint32_t first_index);
void write_tetgen_neigh(const std::filesystem::path& path, std::span<const std::uint32_t> neighbors,
                        std::uint32_t first_index);

}  // namespace exactmesh::io
