// SPDX-License-Identifier: MIT
// VTK XML UnstructuredGrid ASCII writer (see vtk_format.hpp).
#include "io/vtk_format.hpp"

#include "io/text_file.hpp"

namespace exactmesh::io {

namespace {

constexpr int kVtkTriangle = 5;
constexpr int kVtkTetra = 10;
constexpr int kVtkQuad = 9;
constexpr unsigned kTriangleOrder[3] = {0, 1, 2};
/// VTK_TETRA: (0, 1, 2) by the right-hand rule has its normal towards point 3, i.e.
/// det[p1 - p0, p2 - p0, p3 - p0] > 0, the opposite of triangulation/'s orient3d > 0: the first
/// two corners swapped.
constexpr unsigned kTetOrder[4] = {1, 0, 2, 3};

/// `coordinates`: dimension values per point (z = 0 appended in 2D); `cells`: `corners` indices
/// each, written in `corner_order`, as VTK cells of `cell_type`; `vertex_field`: #V values of
/// the point array "u", or empty.
std::string format_vtu_cells(std::span<const double> coordinates, unsigned dimension,
                             std::span<const VertIdx> cells_in, unsigned corners,
                             const unsigned* corner_order, int cell_type, std::uint32_t first_index,
                             std::span<const double> vertex_field,
                             std::span<const VertIdx> quads = {}) {
    const std::size_t points = coordinates.size() / dimension;
    const std::size_t simplices = cells_in.size() / corners;
    const std::size_t cells = simplices + quads.size() / 4;
    std::string out;
    out.reserve(64 * points + 48 * cells + 1024);
    out += "<?xml version=\"1.0\"?>\n";
    out += "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n";
    out += "  <UnstructuredGrid>\n";
    out += "    <Piece NumberOfPoints=\"";
    append_unsigned(out, points);
    out += "\" NumberOfCells=\"";
    append_unsigned(out, cells);
    out += "\">\n";

    out += vertex_field.empty() ? "      <PointData Scalars=\"node_number\">\n"
                                : "      <PointData Scalars=\"u\">\n";
    out += "        <DataArray type=\"Int64\" Name=\"node_number\" format=\"ascii\">\n";
    for (std::size_t v = 0; v < points; ++v) {
        append_unsigned(out, v + first_index);
        out += '\n';
    }
    out += "        </DataArray>\n";
    if (!vertex_field.empty()) {
        out += "        <DataArray type=\"Float64\" Name=\"u\" format=\"ascii\">\n";
        for (const double value : vertex_field) {
            append_double(out, value);
            out += '\n';
        }
        out += "        </DataArray>\n";
    }
    out += "      </PointData>\n";

    out += "      <Points>\n";
    out += "        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
    append_points_3d(out, coordinates, dimension);
    out += "        </DataArray>\n      </Points>\n";

    out += "      <Cells>\n";
    out += "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
    for (std::size_t t = 0; t < simplices; ++t) {
        for (std::size_t k = 0; k < corners; ++k) {
            if (k > 0) out += ' ';
            append_unsigned(out, cells_in[corners * t + corner_order[k]]);
        }
        out += '\n';
    }
    // Quadrilaterals after the simplices (VTK_QUAD: corners in order around it).
    for (std::size_t q = 0; q < quads.size() / 4; ++q) {
        for (std::size_t k = 0; k < 4; ++k) {
            if (k > 0) out += ' ';
            append_unsigned(out, quads[4 * q + k]);
        }
        out += '\n';
    }
    out += "        </DataArray>\n";
    out += "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
    for (std::size_t t = 0; t < cells; ++t) {
        append_unsigned(
            out, t < simplices ? corners * (t + 1) : corners * simplices + 4 * (t - simplices + 1));
        out += '\n';
    }
    out += "        </DataArray>\n";
    out += "        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
    for (std::size_t t = 0; t < cells; ++t) {
        append_unsigned(out, static_cast<std::uint64_t>(t < simplices ? cell_type : kVtkQuad));
        out += '\n';
    }
    out += "        </DataArray>\n      </Cells>\n";
    out += "    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
    return out;
}

}  // namespace

std::string format_vtu(std::span<const double> xy, std::span<const VertIdx> triangles,
                       std::uint32_t first_index, std::span<const double> vertex_field,
                       std::span<const VertIdx> quads) {
    return format_vtu_cells(xy, 2, triangles, 3, kTriangleOrder, kVtkTriangle, first_index,
                            vertex_field, quads);
}

std::string format_vtu_3d(std::span<const double> xyz, std::span<const VertIdx> tets,
                          std::uint32_t first_index, std::span<const double> vertex_field) {
    return format_vtu_cells(xyz, 3, tets, 4, kTetOrder, kVtkTetra, first_index, vertex_field);
}

void write_vtu_3d(const std::filesystem::path& path, std::span<const double> xyz,
                  std::span<const VertIdx> tets, std::uint32_t first_index) {
    write_text_file(path, format_vtu_3d(xyz, tets, first_index));
}

void write_vtu(const std::filesystem::path& path, std::span<const double> xy,
               std::span<const VertIdx> triangles, std::uint32_t first_index) {
    write_text_file(path, format_vtu(xy, triangles, first_index));
}

}  // namespace exactmesh::io
