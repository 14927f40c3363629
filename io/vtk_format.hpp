// SPDX-License-Identifier: MIT
// VTK XML UnstructuredGrid (.vtu) ASCII output [VTK file formats, "XML File Formats"]: points
// with z = 0, triangles as VTK_TRIANGLE cells (type 5), and each point's number in the input
// file as the point array "node_number", so ParaView shows the input's own numbering.
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>

#include "io/point_set_2d.hpp"

namespace exactmesh::io {

/// The .vtu text. `xy`: 2·#V coordinates; `triangles`: 3·#T 0-based vertex indices, CCW;
/// node_number = index + first_index. Doubles round-trip exactly.
std::string format_vtu(std::span<const double> xy, std::span<const VertIdx> triangles,
                       std::uint32_t first_index);
void write_vtu(const std::filesystem::path& path, std::span<const double> xy,
               std::span<const VertIdx> triangles, std::uint32_t first_index);

}  // namespace exactmesh::io
