// SPDX-License-Identifier: MIT
// Shewchuk's Triangle file formats [Shewchuk96, "Triangle" documentation: .node, .ele, .neigh]:
// readers that reject every malformed input with the file, the line and the offending text,
// and writers whose output Triangle, Show Me and this library read back exactly.
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>

#include "io/point_set_2d.hpp"

namespace exactmesh::io {

/// Reads a .node file: a header `<#vertices> <dimension=2> <#attributes> <#markers 0|1>` (trailing
/// header fields may be omitted, as Triangle allows; they default to 2, 0 and 0), then one line
/// per vertex `<number> <x> <y> [attributes...] [marker]`. '#' starts a comment anywhere; blank
/// lines and CRLF endings are fine. Vertices are numbered consecutively from 0 or 1 (the first
/// vertex's number sets the base). Coordinates are correctly rounded (std::from_chars).
/// @throws FormatError "file:line: problem" on unreadable or malformed input, including
///         non-finite, overflowing or underflowing coordinates and data past the last vertex.
NodeFile read_node(const std::filesystem::path& path);
/// read_node on text already in memory; `file_name` is used in messages.
NodeFile parse_node(std::string_view text, const std::string& file_name);

/// The .node text of `nodes` (coordinates printed shortest round-trip, so reading is exact).
std::string format_node(const NodeFile& nodes);
void write_node(const std::filesystem::path& path, const NodeFile& nodes);

/// Reads a .poly file (Triangle's planar straight-line graph): a vertex section as in .node
/// (a count of 0 means the vertices are in the .node file of the same name, read too), then
/// `<#segments> <#markers 0|1>` and `<number> <endpoint> <endpoint> [marker]` lines, then
/// `<#holes>` and `<number> <x> <y>` lines, then optionally `<#regions>` and
/// `<number> <x> <y> <attribute> [<maximum area>]` lines. Segment endpoints must name
/// existing vertices (in the file's numbering); numbers follow the vertices' base.
/// @throws FormatError "file:line: problem" as read_node.
PolyFile read_poly(const std::filesystem::path& path);
/// The .node file a .poly with no vertices of its own names: the same name with the extension
/// .node (.NODE when the .poly's extension is upper case and that file exists).
std::filesystem::path poly_node_path(const std::filesystem::path& poly_path);
/// read_poly on text in memory; `node_path` is read when the vertex count is 0.
PolyFile parse_poly(std::string_view text, const std::string& file_name,
                    const std::filesystem::path& node_path);

/// .poly text with the vertices, `segments` (2·#S, 0-based, numbered like the vertices), no
/// holes; segment markers when given (#S values).
std::string format_poly(const NodeFile& vertices, std::span<const VertIdx> segments,
                        std::span<const std::int32_t> segment_markers = {});
void write_poly(const std::filesystem::path& path, const NodeFile& vertices,
                std::span<const VertIdx> segments,
                std::span<const std::int32_t> segment_markers = {});

/// Reads a .ele file: `<#triangles> <nodes per triangle 3|6> <#attributes>`, then
/// `<number> <v1> <v2> <v3> [3 more nodes] [attributes...]`. Triangles are numbered
/// consecutively from 0 or 1; vertex numbers must lie in the .node file's numbering
/// [vertex_first_index, vertex_first_index + vertex_count). Only the corners are kept.
/// @throws FormatError with the same precision as read_node.
EleFile read_ele(const std::filesystem::path& path, std::uint32_t vertex_first_index,
                 std::uint32_t vertex_count);
EleFile parse_ele(std::string_view text, const std::string& file_name,
                  std::uint32_t vertex_first_index, std::uint32_t vertex_count);

/// The .ele text: `#T 3 0`, then `<t> <v1> <v2> <v3>` (counter-clockwise, as given), triangles
/// and vertices numbered from `first_index`, as Triangle numbers its output like its input.
/// `triangles`: 3·#T 0-based vertex indices.
/// With `attributes` (one per triangle, e.g. regional attributes) the header says 1 attribute
/// and each line ends with it.
std::string format_ele(std::span<const VertIdx> triangles, std::uint32_t first_index,
                       std::span<const double> attributes = {});
void write_ele(const std::filesystem::path& path, std::span<const VertIdx> triangles,
               std::uint32_t first_index, std::span<const double> attributes = {});

/// The .neigh text: `#T 3`, then `<t> <n1> <n2> <n3>`, neighbor i being the triangle OPPOSITE
/// vertex i (Triangle's convention), -1 on the hull. `neighbors_across_edges` uses the
/// triangulation/ convention instead: slot 3t+k is the triangle across edge (v[k], v[k+1]),
/// kNone on the hull; the edge opposite vertex i is (v[i+1], v[i+2]), slot 3t+(i+1)%3.
std::string format_neigh(std::span<const TriIdx> neighbors_across_edges, std::uint32_t first_index);
void write_neigh(const std::filesystem::path& path, std::span<const TriIdx> neighbors_across_edges,
                 std::uint32_t first_index);

}  // namespace exactmesh::io
