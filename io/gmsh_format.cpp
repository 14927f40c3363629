// SPDX-License-Identifier: MIT
// Gmsh MSH 4.1 ASCII writer (see gmsh_format.hpp).
#include "io/gmsh_format.hpp"

#include "io/text_file.hpp"

namespace exactmesh::io {

namespace {

/// The headers of a $Nodes or $Elements section holding `count` entries tagged 1..count in one
/// block on entity (entity_dim, 1): "numEntityBlocks count minTag maxTag", then "entityDim
/// entityTag <kind> count" (kind: parametric 0 for nodes, the element type for elements); an
/// empty section is "0 0 0 0" alone.
void append_block_headers(std::string& out, std::size_t count, int entity_dim, int kind) {
    if (count == 0) {
        out += "0 0 0 0\n";
        return;
    }
    out += "1 ";
    append_unsigned(out, count);
    out += " 1 ";
    append_unsigned(out, count);
    out += '\n';
    append_unsigned(out, static_cast<std::uint64_t>(entity_dim));
    out += " 1 ";
    append_unsigned(out, static_cast<std::uint64_t>(kind));
    out += ' ';
    append_unsigned(out, count);
    out += '\n';
}

constexpr int kGmshQuadrangle = 3;

/// One element block's header line: "entityDim entityTag elementType count" (entity 1).
void append_block_header(std::string& out, int entity_dim, int element_type, std::size_t count) {
    append_unsigned(out, static_cast<std::uint64_t>(entity_dim));
    out += " 1 ";
    append_unsigned(out, static_cast<std::uint64_t>(element_type));
    out += ' ';
    append_unsigned(out, count);
    out += '\n';
}

/// The $NodeData section of one scalar per node (node v tagged v + 1), named "u" [MSH 4.1:
/// string tags (the view name), real tags (the time), integer tags (the time step, the
/// number of components, the number of nodes), then "nodeTag value" lines].
void append_node_data(std::string& out, std::span<const double> values) {
    out += "$NodeData\n1\n\"u\"\n1\n0\n3\n0\n1\n";
    append_unsigned(out, values.size());
    out += '\n';
    for (std::size_t v = 0; v < values.size(); ++v) {
        append_unsigned(out, v + 1);
        out += ' ';
        append_double(out, values[v]);
        out += '\n';
    }
    out += "$EndNodeData\n";
}

/// One block of nodes on entity (entity_dim, 1) and one block of elements of `element_type`
/// with `corners` nodes each, written in the order `corner_order`. `coordinates`: dimension
/// values per node (z = 0 appended in 2D); `vertex_field`: #V values or empty.
std::string format_msh_cells(std::span<const double> coordinates, unsigned dimension,
                             std::span<const VertIdx> cells, unsigned corners,
                             const unsigned* corner_order, int entity_dim, int element_type,
                             std::span<const double> vertex_field,
                             std::span<const VertIdx> quads = {}) {
    const std::size_t nodes = coordinates.size() / dimension;
    const std::size_t elements = cells.size() / corners;
    const std::size_t quad_count = quads.size() / 4;
    std::string out;
    out.reserve(56 * nodes + 40 * elements + 256);
    out += "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";

    // The headers, the node tags, then the coordinates.
    out += "$Nodes\n";
    append_block_headers(out, nodes, entity_dim, 0);  // not parametric
    for (std::size_t v = 0; v < nodes; ++v) {
        append_unsigned(out, v + 1);
        out += '\n';
    }
    append_points_3d(out, coordinates, dimension);
    out += "$EndNodes\n";

    // The headers, then each element's tag and its nodes.
    out += "$Elements\n";
    if (quad_count == 0) {
        append_block_headers(out, elements, entity_dim, element_type);
    } else {
        // A mixed mesh: a block of triangles (when there are any), then one of quadrilaterals
        // (element type 3, corners counter-clockwise), tagged on after the triangles.
        const std::size_t total = elements + quad_count;
        append_unsigned(out, elements > 0 ? 2 : 1);
        out += ' ';
        append_unsigned(out, total);
        out += " 1 ";
        append_unsigned(out, total);
        out += '\n';
        if (elements > 0) append_block_header(out, entity_dim, element_type, elements);
    }
    for (std::size_t t = 0; t < elements; ++t) {
        append_unsigned(out, t + 1);
        for (std::size_t k = 0; k < corners; ++k) {
            out += ' ';
            append_unsigned(out, std::uint64_t{cells[corners * t + corner_order[k]]} + 1);
        }
        out += '\n';
    }
    if (quad_count > 0) {
        append_block_header(out, entity_dim, kGmshQuadrangle, quad_count);
        for (std::size_t q = 0; q < quad_count; ++q) {
            append_unsigned(out, elements + q + 1);
            for (std::size_t k = 0; k < 4; ++k) {
                out += ' ';
                append_unsigned(out, std::uint64_t{quads[4 * q + k]} + 1);
            }
            out += '\n';
        }
    }
    out += "$EndElements\n";
    if (!vertex_field.empty()) append_node_data(out, vertex_field);
    return out;
}

constexpr unsigned kTriangleOrder[3] = {0, 1, 2};
/// Gmsh's tetrahedron has a positive Jacobian det[v1 - v0, v2 - v0, v3 - v0] > 0, the opposite
/// of triangulation/'s orient3d > 0: the first two corners swapped.
constexpr unsigned kTetOrder[4] = {1, 0, 2, 3};
constexpr int kGmshTriangle = 2;
constexpr int kGmshTetrahedron = 4;

}  // namespace

std::string format_msh(std::span<const double> xy, std::span<const VertIdx> triangles,
                       std::span<const double> vertex_field, std::span<const VertIdx> quads) {
    return format_msh_cells(xy, 2, triangles, 3, kTriangleOrder, 2, kGmshTriangle, vertex_field,
                            quads);
}

std::string format_msh_3d(std::span<const double> xyz, std::span<const VertIdx> tets,
                          std::span<const double> vertex_field) {
    return format_msh_cells(xyz, 3, tets, 4, kTetOrder, 3, kGmshTetrahedron, vertex_field);
}

void write_msh_3d(const std::filesystem::path& path, std::span<const double> xyz,
                  std::span<const VertIdx> tets) {
    write_text_file(path, format_msh_3d(xyz, tets));
}

void write_msh(const std::filesystem::path& path, std::span<const double> xy,
               std::span<const VertIdx> triangles) {
    write_text_file(path, format_msh(xy, triangles));
}

}  // namespace exactmesh::io
