// SPDX-License-Identifier: MIT
// VTK XML UnstructuredGrid (.vtu) ASCII output [VTK file formats, "XML File Formats"]: points
// (z = 0 in 2D), triangles as VTK_TRIANGLE cells (type 5) or tetrahedra as VTK_TETRA cells
// (type 10), and each point's number in the input file as the point array "node_number", so
// ParaView shows the input's own numbering; a field at the vertices, when given, as the point
// array "u" (Float64, the active scalars).
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>

#include "io/point_set_2d.hpp"

namespace exactmesh::io {

/// The .vtu text. `xy`: 2·#V coordinates; `triangles`: 3·#T 0-based vertex indices, CCW;
/// node_number = index + first_index. Doubles round-trip exactly. `vertex_field` (#V values, or
/// empty: none) is the point array "u".
/// `quads` (4·#Q, counter-clockwise, or empty): VTK_QUAD cells (type 9) after the triangles.
std::string format_vtu(std::span<const double> xy, std::span<const VertIdx> triangles,
                       std::uint32_t first_index, std::span<const double> vertex_field = {},
                       std::span<const VertIdx> quads = {});
void write_vtu(const std::filesystem::path& path, std::span<const double> xy,
               std::span<const VertIdx> triangles, std::uint32_t first_index);

/// The .vtu text of a tetrahedralization. `xyz`: 3·#V coordinates; `tets`: 4·#T 0-based vertex
/// indices with orient3d > 0 (triangulation/'s convention), written in VTK's orientation (first
/// two corners swapped); node_number = index + first_index; `vertex_field` as format_vtu's.
std::string format_vtu_3d(std::span<const double> xyz, std::span<const VertIdx> tets,
                          std::uint32_t first_index, std::span<const double> vertex_field = {});
void write_vtu_3d(const std::filesystem::path& path, std::span<const double> xyz,
                  std::span<const VertIdx> tets, std::uint32_t first_index);

}  // namespace exactmesh::io
