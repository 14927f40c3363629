// SPDX-License-Identifier: MIT
// Gmsh .msh 4.1, VTK .vtu and SVG writers: structure, numbering, exact coordinates, and
// pictures that stay finite and readable for degenerate extents and ~10^4 triangles.
#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "io/gmsh_format.hpp"
#include "io/svg_picture.hpp"
#include "io/text_file.hpp"
#include "io/vtk_format.hpp"

namespace io = exactmesh::io;

namespace {

// Square 0-1-2-3 (counter-clockwise) with centre 4; four triangles around the centre.
const std::vector<double> kSquareXy{0, 0, 1, 0, 1, 1, 0, 1, 0.5, 0.5};
const std::vector<io::VertIdx> kSquareTriangles{0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4};

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

std::size_t count_of(const std::string& text, const std::string& needle) {
    std::size_t count = 0;
    for (std::size_t at = text.find(needle); at != std::string::npos;
         at = text.find(needle, at + needle.size())) {
        ++count;
    }
    return count;
}

/// The value of attribute `name` on the first element that has it.
double attribute(const std::string& svg, const std::string& name) {
    const std::string key = " " + name + "=\"";
    const std::size_t at = svg.find(key);
    EXPECT_NE(at, std::string::npos) << name;
    double value = 0;
    const char* begin = svg.data() + at + key.size();
    std::from_chars(begin, svg.data() + svg.size(), value);
    return value;
}

/// The coordinates in the dots path ("M x yh0 ..."), in order.
std::vector<std::pair<double, double>> dots(const std::string& svg) {
    std::vector<std::pair<double, double>> result;
    const std::size_t start = svg.find("stroke-linecap=\"round\"");
    const std::size_t d = svg.find("d=\"", start) + 3;
    const std::size_t end = svg.find('"', d);
    std::istringstream in(svg.substr(d, end - d));
    for (std::string token; std::getline(in, token, 'M');) {
        if (token.find("h0") == std::string::npos) continue;
        std::istringstream pair(token);
        double x = 0, y = 0;
        pair >> x >> y;
        result.emplace_back(x, y);
    }
    return result;
}

TEST(Io_MeshWriters, GmshHasNodesAndTriangleElementsWithOneBasedTags) {
    const auto lines = lines_of(io::format_msh(kSquareXy, kSquareTriangles));
    const std::vector<std::string> expected{"$MeshFormat", "4.1 0 8",   "$EndMeshFormat",
                                            "$Nodes",      "1 5 1 5",   "2 1 0 5",
                                            "1",           "2",         "3",
                                            "4",           "5",         "0 0 0",
                                            "1 0 0",       "1 1 0",     "0 1 0",
                                            "0.5 0.5 0",   "$EndNodes", "$Elements",
                                            "1 4 1 4",     "2 1 2 4",   "1 1 2 5",
                                            "2 2 3 5",     "3 3 4 5",   "4 4 1 5",
                                            "$EndElements"};
    EXPECT_EQ(lines, expected);
}

TEST(Io_MeshWriters, GmshCoordinatesRoundTripAndEmptyMeshesAreValid) {
    const std::vector<double> xy{0.1, -1e-310, 1.7976931348623157e308, 1.0 / 3.0};
    const auto lines = lines_of(io::format_msh(xy, {}));
    ASSERT_EQ(lines.size(), 14u);
    EXPECT_EQ(lines[8], "0.1 -1e-310 0");
    EXPECT_EQ(lines[9], "1.7976931348623157e+308 0.3333333333333333 0");
    EXPECT_EQ(lines[11], "$Elements");
    EXPECT_EQ(lines[12], "0 0 0 0");
    const auto empty = lines_of(io::format_msh({}, {}));
    EXPECT_EQ(empty[4], "0 0 0 0");
}

TEST(Io_MeshWriters, VtuListsPointsCellsOffsetsAndNodeNumbers) {
    const std::string vtu = io::format_vtu(kSquareXy, kSquareTriangles, 1);
    EXPECT_NE(vtu.find("<VTKFile type=\"UnstructuredGrid\""), std::string::npos);
    EXPECT_NE(vtu.find("NumberOfPoints=\"5\" NumberOfCells=\"4\""), std::string::npos);
    EXPECT_NE(vtu.find("Name=\"node_number\" format=\"ascii\">\n1\n2\n3\n4\n5\n"),
              std::string::npos);
    EXPECT_NE(vtu.find("format=\"ascii\">\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0.5 0.5 0\n"),
              std::string::npos);
    EXPECT_NE(vtu.find("Name=\"connectivity\" format=\"ascii\">\n0 1 4\n1 2 4\n2 3 4\n3 0 4\n"),
              std::string::npos);
    EXPECT_NE(vtu.find("Name=\"offsets\" format=\"ascii\">\n3\n6\n9\n12\n"), std::string::npos);
    EXPECT_NE(vtu.find("Name=\"types\" format=\"ascii\">\n5\n5\n5\n5\n"), std::string::npos);
    EXPECT_EQ(count_of(vtu, "<DataArray"), count_of(vtu, "</DataArray>"));
    EXPECT_EQ(vtu.substr(vtu.size() - 11), "</VTKFile>\n");
}

// A mixed mesh (advancing layers with --quads): the square as one quadrilateral beside two
// triangles of a neighbouring square. VTK: quads after the triangles, offsets growing by 4,
// type 9 (VTK_QUAD); Gmsh: two element blocks, triangles (type 2) then quadrangles (type 3),
// tags running on.
TEST(Io_MeshWriters, QuadrilateralsAreVtkQuadsAndGmshQuadrangles) {
    const std::vector<double> xy{0, 0, 1, 0, 1, 1, 0, 1, 2, 0, 2, 1};
    const std::vector<io::VertIdx> triangles{1, 4, 5, 1, 5, 2};
    const std::vector<io::VertIdx> quads{0, 1, 2, 3};
    const std::string vtu = io::format_vtu(xy, triangles, 0, {}, quads);
    EXPECT_NE(vtu.find("NumberOfPoints=\"6\" NumberOfCells=\"3\""), std::string::npos);
    EXPECT_NE(vtu.find("Name=\"connectivity\" format=\"ascii\">\n1 4 5\n1 5 2\n0 1 2 3\n"),
              std::string::npos);
    EXPECT_NE(vtu.find("Name=\"offsets\" format=\"ascii\">\n3\n6\n10\n"), std::string::npos);
    EXPECT_NE(vtu.find("Name=\"types\" format=\"ascii\">\n5\n5\n9\n"), std::string::npos);
    const std::vector<std::string> msh = lines_of(io::format_msh(xy, triangles, {}, quads));
    std::size_t elements = 0;
    while (elements < msh.size() && msh[elements] != "$Elements") ++elements;
    ASSERT_LT(elements + 7, msh.size());
    EXPECT_EQ(msh[elements + 1], "2 3 1 3");
    EXPECT_EQ(msh[elements + 2], "2 1 2 2");
    EXPECT_EQ(msh[elements + 3], "1 2 5 6");
    EXPECT_EQ(msh[elements + 4], "2 2 6 3");
    EXPECT_EQ(msh[elements + 5], "2 1 3 1");
    EXPECT_EQ(msh[elements + 6], "3 1 2 3 4");
    EXPECT_EQ(msh[elements + 7], "$EndElements");
    // Quadrilaterals alone: one block.
    const std::vector<std::string> only = lines_of(io::format_msh(xy, {}, {}, quads));
    std::size_t at = 0;
    while (at < only.size() && only[at] != "$Elements") ++at;
    ASSERT_LT(at + 4, only.size());
    EXPECT_EQ(only[at + 1], "1 1 1 1");
    EXPECT_EQ(only[at + 2], "2 1 3 1");
    EXPECT_EQ(only[at + 3], "1 1 2 3 4");
}

// The field at the vertices: Gmsh's $NodeData after $Elements (one string tag, the view name
// "u"; one real tag, the time; three integer tags: time step, components, node count; then
// "tag value" per node), VTK's point array "u" (the active scalars); none when not given.
TEST(Io_MeshWriters, VertexFieldIsGmshNodeDataAndVtkPointDataNamedU) {
    const std::vector<double> field{0.5, -1.0 / 3.0, 1e-300, 2, 7};
    const auto lines = lines_of(io::format_msh(kSquareXy, kSquareTriangles, field));
    const std::vector<std::string> node_data{"$EndElements",
                                             "$NodeData",
                                             "1",
                                             "\"u\"",
                                             "1",
                                             "0",
                                             "3",
                                             "0",
                                             "1",
                                             "5",
                                             "1 0.5",
                                             "2 -0.3333333333333333",
                                             "3 1e-300",
                                             "4 2",
                                             "5 7",
                                             "$EndNodeData"};
    ASSERT_GE(lines.size(), node_data.size());
    EXPECT_EQ(std::vector<std::string>(lines.end() - static_cast<std::ptrdiff_t>(node_data.size()),
                                       lines.end()),
              node_data);
    EXPECT_EQ(io::format_msh(kSquareXy, kSquareTriangles).find("$NodeData"), std::string::npos);

    const std::string vtu = io::format_vtu(kSquareXy, kSquareTriangles, 1, field);
    EXPECT_NE(vtu.find("<PointData Scalars=\"u\">"), std::string::npos);
    EXPECT_NE(vtu.find("<DataArray type=\"Float64\" Name=\"u\" format=\"ascii\">\n0.5\n"
                       "-0.3333333333333333\n1e-300\n2\n7\n        </DataArray>\n      "
                       "</PointData>"),
              std::string::npos);
    EXPECT_EQ(count_of(vtu, "<DataArray"), count_of(vtu, "</DataArray>"));
    EXPECT_EQ(io::format_vtu(kSquareXy, kSquareTriangles, 1).find("Name=\"u\""), std::string::npos);

    // 3D: the same sections after the tetrahedra.
    const std::vector<double> xyz{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    const std::vector<io::VertIdx> tet{0, 1, 2, 3};
    const std::vector<double> field3{1, 2, 3, 4};
    const std::string msh3 = io::format_msh_3d(xyz, tet, field3);
    EXPECT_NE(msh3.find("$EndElements\n$NodeData\n1\n\"u\"\n1\n0\n3\n0\n1\n4\n1 1\n2 2\n3 3\n4 "
                        "4\n$EndNodeData\n"),
              std::string::npos);
    const std::string vtu3 = io::format_vtu_3d(xyz, tet, 0, field3);
    EXPECT_NE(vtu3.find("Name=\"u\" format=\"ascii\">\n1\n2\n3\n4\n"), std::string::npos);
}

TEST(Io_MeshWriters, SvgIsFittedWithYPointingUp) {
    const std::string svg = io::format_svg(kSquareXy, kSquareTriangles);
    EXPECT_NE(svg.find("<svg xmlns=\"http://www.w3.org/2000/svg\""), std::string::npos);
    EXPECT_NE(svg.find("viewBox=\"0 0 1000.00 1000.00\""), std::string::npos);
    EXPECT_EQ(count_of(svg, "Z"), 4u);  // one closed sub-path per triangle
    const auto points = dots(svg);
    ASSERT_EQ(points.size(), 5u);
    // (0,0) is at the bottom left, (1,1) at the top right: y grows upwards.
    EXPECT_LT(points[0].first, points[2].first);
    EXPECT_GT(points[0].second, points[2].second);
    for (const auto& [x, y] : points) {
        EXPECT_GE(x, 0.0);
        EXPECT_LE(x, 1000.0);
        EXPECT_GE(y, 0.0);
        EXPECT_LE(y, 1000.0);
    }
}

TEST(Io_MeshWriters, SvgHandlesDegenerateAndHugeExtents) {
    for (const std::vector<double>& xy :
         {std::vector<double>{}, std::vector<double>{3, 4}, std::vector<double>{0, 1, 2, 1, 5, 1},
          std::vector<double>{-1.7e308, -1.7e308, 1.7e308, 1.7e308, 1.7e308, -1.7e308}}) {
        const std::string svg = io::format_svg(xy, {});
        EXPECT_EQ(svg.find("nan"), std::string::npos) << svg;
        EXPECT_EQ(svg.find("inf"), std::string::npos) << svg;
        EXPECT_GT(attribute(svg, "width"), 0.0);
        EXPECT_GT(attribute(svg, "height"), 0.0);
        EXPECT_EQ(dots(svg).size(), xy.size() / 2);
    }
}

TEST(Io_MeshWriters, SvgStaysCompactAndThinLinedForManyTriangles) {
    // A 71x71 grid split into 2·70·70 = 9800 triangles.
    const int n = 71;
    std::vector<double> xy;
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            xy.push_back(i);
            xy.push_back(j * 0.5);
        }
    }
    std::vector<io::VertIdx> triangles;
    for (int j = 0; j + 1 < n; ++j) {
        for (int i = 0; i + 1 < n; ++i) {
            const auto v = static_cast<io::VertIdx>(j * n + i);
            triangles.insert(triangles.end(), {v, v + 1, v + n + 1, v, v + n + 1, v + n});
        }
    }
    const std::string svg = io::format_svg(xy, triangles);
    EXPECT_EQ(count_of(svg, "Z"), 9800u);
    EXPECT_LT(svg.size(), 1'000'000u);
    EXPECT_LT(attribute(svg, "stroke-width"), 1.0);  // lines thinner than the ~10-unit cells
    EXPECT_NEAR(attribute(svg, "height") / attribute(svg, "width"), 0.5, 0.03);
}

// The point list Gmsh's $Nodes and VTK's <Points> share: exact shortest decimals, z = 0 in 2D.
TEST(PointList, TwoAndThreeDimensionsLineByLine) {
    std::string out = "x\n";
    io::append_points_3d(out, std::vector<double>{0.1, -1e-310, 3, 1.0 / 3.0}, 2);
    EXPECT_EQ(out, "x\n0.1 -1e-310 0\n3 0.3333333333333333 0\n");
    out.clear();
    io::append_points_3d(out, std::vector<double>{1, 2, 3, -0.5, 0, 1.7976931348623157e308}, 3);
    EXPECT_EQ(out, "1 2 3\n-0.5 0 1.7976931348623157e+308\n");
    out.clear();
    io::append_points_3d(out, std::vector<double>{}, 3);
    EXPECT_EQ(out, "");
}

}  // namespace
