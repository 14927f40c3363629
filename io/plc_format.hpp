// SPDX-License-Identifier: MIT
// Readers of piecewise linear complexes, the input of 3D mesh generation (issue 15): TetGen's
// .poly (3D) and .smesh [the TetGen 1.5 manual §5.2.2-5.2.3], the Object File Format .off and
// STL (ASCII and binary) surfaces. Strict like the other readers: every malformed input is a
// FormatError "file:line: problem" naming the offending value ("file: problem" for binary STL,
// which has no lines); '#' comments, blank lines and CRLF are fine in the text formats.
//
// The result keeps what messages need (lines, markers announced); plc_from_file turns it into
// the triangulation layer's plain Plc3 (triangulation/mesh/plc_3d.hpp, which io/ may include
// like mesh2.hpp and mesh3.hpp).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "triangulation/mesh/plc_3d.hpp"

namespace exactmesh::io {

/// One facet: TetGen's polygons (1 corner: a point, 2: a segment, n >= 3: a closed loop),
/// hole points in the facet, and the facet's boundary marker.
struct PlcFacetRecord {
    std::vector<std::vector<std::uint32_t>> polygons;  ///< 0-based corner indices
    std::vector<double> holes;                         ///< 3·#H points inside the facet's holes
    std::int32_t marker = 0;                           ///< 0 when the file gives none
    std::uint64_t line = 0;  ///< the facet's (first) line; for binary STL the triangle's number
};

/// The content of a PLC file.
struct PlcFile {
    std::vector<double> xyz;               ///< 3·#V coordinates, in file order
    std::uint32_t first_index = 0;         ///< numbering of the vertices in the file: 0 or 1
    bool vertices_from_node_file = false;  ///< a .poly/.smesh of 0 points: read from its .node
    std::vector<PlcFacetRecord> facets;
    bool has_facet_markers = false;
    std::vector<double> holes;    ///< 3·#H volume hole points
    std::vector<double> regions;  ///< 5·#R: x, y, z, attribute, maximum volume (-1: none)
    std::vector<std::uint64_t> hole_lines;    ///< #H: the line of each volume hole
    std::vector<std::uint64_t> region_lines;  ///< #R: the line of each region
    bool facet_lines_are_triangles = false;   ///< binary STL: PlcFacetRecord::line is its number

    std::uint32_t vertex_count() const { return static_cast<std::uint32_t>(xyz.size() / 3); }
};

/// TetGen's 3D .poly: part 1 the points as in a .node file (a count of 0: the points are in
/// the .node file of the same name); part 2 `<#facets> [<#markers 0|1>]`, each facet a line
/// `<#polygons> [<#holes>] [<marker>]` (the marker only when the header announces markers; it
/// may then be omitted, 0), then a line `<#corners> <c1> ... <cn>` per polygon and a line
/// `<hole #> <x> <y> <z>` per facet hole; part 3 `<#holes>` and `<hole #> <x> <y> <z>` lines;
/// part 4 (optional) `<#regions>` and `<region #> <x> <y> <z> <attribute> [<max volume>]`.
/// Corner numbers follow the points' numbering (0 or 1, set by the first point).
PlcFile read_tetgen_poly_3d(const std::filesystem::path& path);
PlcFile parse_tetgen_poly_3d(std::string_view text, const std::string& file_name,
                             const std::filesystem::path& node_path);

/// TetGen's .smesh: as .poly, but each facet is one line `<#corners> <c1> ... <cn> [marker]`
/// (the marker exactly when the facet header announces markers) and has no holes.
PlcFile read_smesh(const std::filesystem::path& path);
PlcFile parse_smesh(std::string_view text, const std::string& file_name,
                    const std::filesystem::path& node_path);

/// The Object File Format: a line `OFF` (the counts may follow on it), `<#vertices> <#faces>
/// [<#edges>]`, a line `<x> <y> <z>` per vertex, a line `<n> <v1> ... <vn> [colour]` per face
/// (a colour of 3 or 4 numbers is ignored); 0-based vertex numbers; each face is one facet.
PlcFile read_off(const std::filesystem::path& path);
PlcFile parse_off(std::string_view text, const std::string& file_name);

/// STL: binary when the file is exactly 84 + 50·#T bytes long (#T the count at byte 80),
/// else ASCII (`solid` ... `facet normal` / `outer loop` / 3 `vertex x y z` / `endloop` /
/// `endfacet` ... `endsolid`; the normals are not read, as the corners define the triangle).
/// Corners with equal coordinates (exactly; -0 equals 0) become one vertex, numbered in order
/// of first appearance; each triangle is one facet.
PlcFile read_stl(const std::filesystem::path& path);
PlcFile parse_stl(std::string_view bytes, const std::string& file_name);

/// Dispatches on the extension (.poly, .smesh, .off, .stl, in any letter case).
/// @throws FormatError naming the file for another extension.
PlcFile read_plc(const std::filesystem::path& path);

/// The PLC of `file`, numbered as the file numbers its vertices (messages of validate_plc_3d
/// then name the file's vertex and facet numbers).
inline triangulation::Plc3 plc_from_file(PlcFile file) {
    triangulation::Plc3 plc;
    plc.xyz = std::move(file.xyz);
    plc.first_index = file.first_index;
    plc.facets.reserve(file.facets.size());
    plc.facet_origin.reserve(file.facets.size());
    plc.facet_origin_kind = file.facet_lines_are_triangles ? "triangle" : "line";
    for (PlcFacetRecord& record : file.facets) {
        plc.facet_origin.push_back(record.line);
        triangulation::Facet3 facet;
        facet.polygons = std::move(record.polygons);
        facet.holes = std::move(record.holes);
        facet.marker = record.marker;
        plc.facets.push_back(std::move(facet));
    }
    plc.holes = std::move(file.holes);
    for (std::size_t r = 0; r + 4 < file.regions.size(); r += 5) {
        plc.regions.push_back({file.regions[r], file.regions[r + 1], file.regions[r + 2],
                               file.regions[r + 3], file.regions[r + 4]});
    }
    return plc;
}

}  // namespace exactmesh::io
