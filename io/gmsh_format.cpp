// SPDX-License-Identifier: MIT
// Gmsh MSH 4.1 ASCII writer (see gmsh_format.hpp).
#include "io/gmsh_format.hpp"

#include "io/text_file.hpp"

namespace exactmesh::io {

std::string format_msh(std::span<const double> xy, std::span<const VertIdx> triangles) {
    const std::size_t nodes = xy.size() / 2;
    const std::size_t elements = triangles.size() / 3;
    std::string out;
    out.reserve(56 * nodes + 40 * elements + 256);
    out += "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";

    // numEntityBlocks numNodes minNodeTag maxNodeTag, then one block on surface entity 1:
    // entityDim entityTag parametric numNodesInBlock, the tags, then the coordinates.
    out += "$Nodes\n";
    if (nodes == 0) {
        out += "0 0 0 0\n";
    } else {
        out += "1 ";
        append_unsigned(out, nodes);
        out += " 1 ";
        append_unsigned(out, nodes);
        out += "\n2 1 0 ";
        append_unsigned(out, nodes);
        out += '\n';
        for (std::size_t v = 0; v < nodes; ++v) {
            append_unsigned(out, v + 1);
            out += '\n';
        }
        for (std::size_t v = 0; v < nodes; ++v) {
            append_double(out, xy[2 * v]);
            out += ' ';
            append_double(out, xy[2 * v + 1]);
            out += " 0\n";
        }
    }
    out += "$EndNodes\n";

    // numEntityBlocks numElements minElementTag maxElementTag, then
    // entityDim entityTag elementType(2 = 3-node triangle) numElementsInBlock.
    out += "$Elements\n";
    if (elements == 0) {
        out += "0 0 0 0\n";
    } else {
        out += "1 ";
        append_unsigned(out, elements);
        out += " 1 ";
        append_unsigned(out, elements);
        out += "\n2 1 2 ";
        append_unsigned(out, elements);
        out += '\n';
        for (std::size_t t = 0; t < elements; ++t) {
            append_unsigned(out, t + 1);
            for (std::size_t k = 0; k < 3; ++k) {
                out += ' ';
                append_unsigned(out, std::uint64_t{triangles[3 * t + k]} + 1);
            }
            out += '\n';
        }
    }
    out += "$EndElements\n";
    return out;
}

void write_msh(const std::filesystem::path& path, std::span<const double> xy,
               std::span<const VertIdx> triangles) {
    write_text_file(path, format_msh(xy, triangles));
}

}  // namespace exactmesh::io
