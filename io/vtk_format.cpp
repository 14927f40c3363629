// SPDX-License-Identifier: MIT
// VTK XML UnstructuredGrid ASCII writer (see vtk_format.hpp).
#include "io/vtk_format.hpp"

#include "io/text_file.hpp"

namespace exactmesh::io {

namespace {
constexpr int kVtkTriangle = 5;
}  // namespace

std::string format_vtu(std::span<const double> xy, std::span<const VertIdx> triangles,
                       std::uint32_t first_index) {
    const std::size_t points = xy.size() / 2;
    const std::size_t cells = triangles.size() / 3;
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

    out += "      <PointData Scalars=\"node_number\">\n";
    out += "        <DataArray type=\"Int64\" Name=\"node_number\" format=\"ascii\">\n";
    for (std::size_t v = 0; v < points; ++v) {
        append_unsigned(out, v + first_index);
        out += '\n';
    }
    out += "        </DataArray>\n      </PointData>\n";

    out += "      <Points>\n";
    out += "        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
    for (std::size_t v = 0; v < points; ++v) {
        append_double(out, xy[2 * v]);
        out += ' ';
        append_double(out, xy[2 * v + 1]);
        out += " 0\n";
    }
    out += "        </DataArray>\n      </Points>\n";

    out += "      <Cells>\n";
    out += "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
    for (std::size_t t = 0; t < cells; ++t) {
        for (std::size_t k = 0; k < 3; ++k) {
            if (k > 0) out += ' ';
            append_unsigned(out, triangles[3 * t + k]);
        }
        out += '\n';
    }
    out += "        </DataArray>\n";
    out += "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
    for (std::size_t t = 0; t < cells; ++t) {
        append_unsigned(out, 3 * (t + 1));
        out += '\n';
    }
    out += "        </DataArray>\n";
    out += "        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
    for (std::size_t t = 0; t < cells; ++t) {
        append_unsigned(out, kVtkTriangle);
        out += '\n';
    }
    out += "        </DataArray>\n      </Cells>\n";
    out += "    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
    return out;
}

void write_vtu(const std::filesystem::path& path, std::span<const double> xy,
               std::span<const VertIdx> triangles, std::uint32_t first_index) {
    write_text_file(path, format_vtu(xy, triangles, first_index));
}

}  // namespace exactmesh::io
