// SPDX-License-Identifier: MIT
// TetGen's 3D file formats [Si15; TetGen 1.6 user's manual, "File formats": .node, .ele, .face,
// .neigh]: readers that reject every malformed input with the file, the line and the offending
// text, and writers whose output TetGen (-r) and this library read back exactly.
//
// Orientation: TetGen lists a tetrahedron's corners (v1, v2, v3, v4) with a positive volume
// det[v2 - v1, v3 - v1, v4 - v1] > 0, i.e. Shewchuk's orient3d(v1, v2, v3, v4) < 0 (TetGen's own
// mesh check calls orient3d >= 0 "inverted"). triangulation/ keeps orient3d > 0, the opposite:
// the writers swap the first two corners (and their neighbors), the reader swaps them back. Gmsh
// and VTK use TetGen's orientation too (gmsh_format, vtk_format). Hull faces in .face are
// written counter-clockwise seen from outside (outward normal by the right-hand rule).
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>

#include "io/point_set_3d.hpp"

namespace exactmesh::io {

/// Reads a TetGen .node file: a header `<#vertices> <dimension=3> <#attributes> <#markers 0|1>`
/// (trailing fields may be omitted; an omitted dimension is 3 here), then one line per vertex
/// `<number> <x> <y> <z> [attributes...] [marker]`. '#' starts a comment; blank lines and CRLF
/// are fine. Vertices are numbered consecutively from 0 or 1. Coordinates are correctly rounded.
/// @throws FormatError "file:line: problem" on unreadable or malformed input, including
///         non-finite, overflowing or underflowing coordinates and data past the last vertex.
NodeFile3 read_node_3d(const std::filesystem::path& path);
NodeFile3 parse_node_3d(std::string_view text, const std::string& file_name);

/// The dimension a .node file declares in its header (2 when the field is omitted, Triangle's
/// default): lets a caller pick read_node or read_node_3d.
/// @throws FormatError on a missing or malformed header, or a dimension other than 2 and 3.
unsigned read_node_dimension(const std::filesystem::path& path);

/// The .node text (coordinates printed shortest round-trip, so reading is exact).
std::string format_node_3d(const NodeFile3& nodes);
void write_node_3d(const std::filesystem::path& path, const NodeFile3& nodes);

/// Reads a TetGen .ele file: `<#tetrahedra> <nodes per tetrahedron 4|10> <#attributes 0|1>`,
/// then `<number> <v1> <v2> <v3> <v4> [6 more nodes] [attribute]`. Vertex numbers must lie in
/// the .node file's numbering. Only the corners are kept, v1 and v2 swapped (see above).
/// @throws FormatError with the same precision as read_node_3d.
TetFile read_ele_3d(const std::filesystem::path& path, std::uint32_t vertex_first_index,
                    std::uint32_t vertex_count);
TetFile parse_ele_3d(std::string_view text, const std::string& file_name,
                     std::uint32_t vertex_first_index, std::uint32_t vertex_count);

/// The .ele text: `#T 4 0`, then `<t> <v1> <v2> <v3> <v4>` in TetGen's orientation, numbered
/// from `first_index`. `tets`: 4·#T 0-based indices in triangulation/'s orientation.
std::string format_ele_3d(std::span<const VertIdx> tets, std::uint32_t first_index);
void write_ele_3d(const std::filesystem::path& path, std::span<const VertIdx> tets,
                  std::uint32_t first_index);

/// The .face text of the boundary: `#F 0`, then `<f> <a> <b> <c>` for every face k of a
/// tetrahedron t with neighbors[4t + k] == kNone (the face opposite corner k, as in
/// Tetrahedralization3), counter-clockwise seen from outside.
std::string format_boundary_faces(std::span<const VertIdx> tets, std::span<const TetIdx> neighbors,
                                  std::uint32_t first_index);
void write_boundary_faces(const std::filesystem::path& path, std::span<const VertIdx> tets,
                          std::span<const TetIdx> neighbors, std::uint32_t first_index);

/// The .neigh text: `#T 4`, then `<t> <n1> <n2> <n3> <n4>`, neighbor i opposite corner i of the
/// tetrahedron as format_ele_3d writes it, -1 on the boundary.
std::string format_neigh_3d(std::span<const TetIdx> neighbors, std::uint32_t first_index);
void write_neigh_3d(const std::filesystem::path& path, std::span<const TetIdx> neighbors,
                    std::uint32_t first_index);

}  // namespace exactmesh::io
