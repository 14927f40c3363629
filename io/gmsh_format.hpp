// SPDX-License-Identifier: MIT
// Gmsh MSH 4.1 ASCII output [Gmsh reference manual, "MSH file format"]: all points as nodes of
// one surface entity, triangles as 3-node elements (element type 2). No $Entities section: it
// is optional, and Gmsh then treats entity 1 as a discrete surface.
#pragma once

#include <filesystem>
#include <span>
#include <string>

#include "io/point_set_2d.hpp"

namespace exactmesh::io {

/// The .msh text. `xy`: 2·#V coordinates; `triangles`: 3·#T 0-based vertex indices, CCW.
/// Gmsh tags start at 1, so node v has tag v + 1 (the input's own number when it was
/// 1-based) and triangle t has tag t + 1. z is written as 0. Doubles round-trip exactly.
std::string format_msh(std::span<const double> xy, std::span<const VertIdx> triangles);
void write_msh(const std::filesystem::path& path, std::span<const double> xy,
               std::span<const VertIdx> triangles);

}  // namespace exactmesh::io
