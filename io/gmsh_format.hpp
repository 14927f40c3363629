// SPDX-License-Identifier: MIT
// Gmsh MSH 4.1 ASCII output [Gmsh reference manual, "MSH file format"]: all points as nodes of
// one entity, triangles as 3-node elements (element type 2) on a surface, or tetrahedra as
// 4-node elements (type 4) in a volume. No $Entities section: it is optional, and Gmsh then
// treats entity 1 as a discrete surface or volume. A field at the vertices, when given, follows
// as a $NodeData section (one scalar per node, the view "u", time 0, time step 0).
#pragma once

#include <filesystem>
#include <span>
#include <string>

#include "io/point_set_2d.hpp"

namespace exactmesh::io {

/// The .msh text. `xy`: 2·#V coordinates; `triangles`: 3·#T 0-based vertex indices, CCW.
/// Gmsh tags start at 1, so node v has tag v + 1 (the input's own number when it was
/// 1-based) and triangle t has tag t + 1. z is written as 0. Doubles round-trip exactly.
/// `vertex_field` (#V values, or empty: none) is written as the node data "u".
/// `quads` (4·#Q, counter-clockwise, or empty): quadrilaterals (element type 3) written after
/// the triangles, in a block of their own, tagged on from #T + 1.
std::string format_msh(std::span<const double> xy, std::span<const VertIdx> triangles,
                       std::span<const double> vertex_field = {},
                       std::span<const VertIdx> quads = {});
void write_msh(const std::filesystem::path& path, std::span<const double> xy,
               std::span<const VertIdx> triangles);

/// The .msh text of a tetrahedralization. `xyz`: 3·#V coordinates; `tets`: 4·#T 0-based vertex
/// indices with orient3d > 0 (triangulation/'s convention), written with Gmsh's positive
/// Jacobian (first two corners swapped). Node v has tag v + 1, tetrahedron t tag t + 1.
/// `vertex_field` (#V values, or empty: none) is written as the node data "u".
std::string format_msh_3d(std::span<const double> xyz, std::span<const VertIdx> tets,
                          std::span<const double> vertex_field = {});
void write_msh_3d(const std::filesystem::path& path, std::span<const double> xyz,
                  std::span<const VertIdx> tets);

}  // namespace exactmesh::io
