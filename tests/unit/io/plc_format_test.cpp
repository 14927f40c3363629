// SPDX-License-Identifier: MIT
// Tests of io/plc_format: the PLC readers (.poly 3D, .smesh, .off, .stl ASCII and binary) on
// good files and on malformed ones, each error message checked.
#include "io/plc_format.hpp"

#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "io/format_error.hpp"

namespace exactmesh {
namespace {

/// The message of the FormatError `work` throws ("" if none).
std::string format_error(const std::function<void()>& work) {
    try {
        work();
    } catch (const io::FormatError& error) {
        return error.what();
    }
    return "";
}

constexpr const char* kCubePoly = R"(# a unit cube, 1-based, with markers
8 3 0 0
1 0 0 0
2 1 0 0
3 0 1 0
4 1 1 0
5 0 0 1
6 1 0 1
7 0 1 1
8 1 1 1
6 1
1 0 1
4 1 3 7 5
1 0 1
4 2 6 8 4
1 0 2
4 1 5 6 2
1 0 2
4 3 4 8 7
2 1 3   # the bottom: the square and a segment, one facet hole
4 1 2 4 3
2 1 4
1 0.5 0.5 0
1 0 3
4 5 7 8 6
1
1 0.5 0.5 0.5
2
1 0.25 0.5 0.5 7 0.01
2 0.75 0.5 0.5 8
)";

TEST(Io_PlcFormat, ReadsATetGenPoly) {
    const io::PlcFile plc = io::parse_tetgen_poly_3d(kCubePoly, "cube.poly", "cube.node");
    EXPECT_EQ(plc.vertex_count(), 8u);
    EXPECT_EQ(plc.first_index, 1u);
    EXPECT_TRUE(plc.has_facet_markers);
    ASSERT_EQ(plc.facets.size(), 6u);
    EXPECT_EQ(plc.facets[0].polygons, (std::vector<std::vector<std::uint32_t>>{{0, 2, 6, 4}}));
    EXPECT_EQ(plc.facets[4].polygons,
              (std::vector<std::vector<std::uint32_t>>{{0, 1, 3, 2}, {0, 3}}));
    EXPECT_EQ(plc.facets[4].holes, (std::vector<double>{0.5, 0.5, 0}));
    EXPECT_EQ(plc.facets[4].marker, 3);
    EXPECT_EQ(plc.facets[5].marker, 3);
    EXPECT_EQ(plc.facets[4].line, 20u);
    EXPECT_EQ(plc.holes, (std::vector<double>{0.5, 0.5, 0.5}));
    EXPECT_EQ(plc.regions, (std::vector<double>{0.25, 0.5, 0.5, 7, 0.01, 0.75, 0.5, 0.5, 8, -1}));
    // CRLF endings read the same.
    std::string crlf;
    for (const char c : std::string(kCubePoly)) {
        if (c == '\n') crlf += '\r';
        crlf += c;
    }
    const io::PlcFile again = io::parse_tetgen_poly_3d(crlf, "cube.poly", "cube.node");
    EXPECT_EQ(again.xyz, plc.xyz);
    EXPECT_EQ(again.regions, plc.regions);
}

TEST(Io_PlcFormat, PolyWithoutPointsReadsItsNodeFile) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "exactmesh_plc_test";
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "tri.node") << "3 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n";
    std::ofstream(dir / "tri.poly") << "0 3 0 0\n1 0\n1\n3 0 1 2\n0\n";
    const io::PlcFile plc = io::read_plc(dir / "tri.poly");
    EXPECT_TRUE(plc.vertices_from_node_file);
    EXPECT_EQ(plc.vertex_count(), 3u);
    EXPECT_EQ(plc.facets.size(), 1u);
    std::ofstream(dir / "tri.smesh") << "0 3 0 0\n1 0\n3 0 1 2\n0\n";
    EXPECT_EQ(io::read_plc(dir / "tri.smesh").facets[0].polygons[0],
              (std::vector<std::uint32_t>{0, 1, 2}));
    EXPECT_EQ(format_error([&] { io::read_plc(dir / "tri.node"); }),
              (dir / "tri.node").string() +
                  ": unknown PLC file extension (expected .poly, .smesh, .off or .stl)");
}

TEST(Io_PlcFormat, MalformedPolyFilesNameTheLine) {
    struct Case {
        const char* text;
        const char* message;
    };
    const Case cases[] = {
        {"3 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n1 0\n1\n3 1 2 4\n0\n",
         "p.poly:7: corner 4 out of range: the node file numbers its points 1 to 3"},
        {"3 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n1 0\n1 0 5\n3 1 2 3\n0\n",
         "p.poly:6: facet line has 3 fields, expected at most 2 (#polygons, #holes; the facet "
         "header announces no markers): \"1 0 5\""},
        {"3 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n1 0\n1\n3 1 2\n0\n",
         "p.poly:7: expected 4 fields (#corners, 3 corners), got 3: \"3 1 2\""},
        {"3 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n2 0\n1\n3 1 2 3\n",
         "p.poly:7: file ends after 1 of 2 announced facets"},
        {"3 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n1 0\n0\n", "p.poly:6: facet 1 has no polygons"},
        {"3 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n1 0\n1 1\n3 1 2 3\n1 0 0\n0\n",
         "p.poly:8: expected 4 fields (number, x, y, z), got 3: \"1 0 0\""},
        {"3 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n1 0\n1\n3 1 2 3\n0\n1\n1 0 0 0\n",
         "p.poly:10: expected 5 or 6 fields (number, x, y, z, attribute[, maximum volume]), got "
         "4: \"1 0 0 0\""},
        {"3 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n1 0\n1\n3 1 2 3\n",
         "p.poly:7: file ends before the hole count ('<#holes>')"},
        {"3 2 0 0\n", "p.poly:1: dimension must be 3, got 2 (a 3D TetGen file)"},
        {"3 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 nan\n", "p.poly:4: non-finite z coordinate 'nan'"},
    };
    for (const Case& c : cases) {
        EXPECT_EQ(format_error([&] { io::parse_tetgen_poly_3d(c.text, "p.poly", "p.node"); }),
                  c.message)
            << c.text;
    }
}

TEST(Io_PlcFormat, ReadsAndRejectsSmesh) {
    const char* good =
        "4 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 1\n4 1\n3 0 2 1 5\n3 0 1 3 "
        "5\n3 1 2 3 6\n3 0 3 2 6\n0\n";
    const io::PlcFile plc = io::parse_smesh(good, "t.smesh", "t.node");
    ASSERT_EQ(plc.facets.size(), 4u);
    EXPECT_EQ(plc.facets[2].polygons[0], (std::vector<std::uint32_t>{1, 2, 3}));
    EXPECT_EQ(plc.facets[2].marker, 6);
    EXPECT_EQ(format_error([&] {
                  io::parse_smesh("4 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 1\n1 1\n3 0 2 1\n0\n",
                                  "t.smesh", "t.node");
              }),
              "t.smesh:7: expected 5 fields (#corners, 3 corners, marker), got 4: \"3 0 2 1\"");
    EXPECT_EQ(format_error([&] {
                  io::parse_smesh("4 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 1\n1 0\n0\n0\n",
                                  "t.smesh", "t.node");
              }),
              "t.smesh:7: a facet needs at least 1 corner, got 0");
}

TEST(Io_PlcFormat, RegionVolumeBoundsReachThePlc) {
    // TetGen's region list `<#> x y z attribute [max volume]` in a .poly and in a .smesh: the
    // bound is kept (-1 when omitted) and plc_from_file hands it to Region3::max_volume.
    const triangulation::Plc3 poly =
        io::plc_from_file(io::parse_tetgen_poly_3d(kCubePoly, "cube.poly", "cube.node"));
    ASSERT_EQ(poly.regions.size(), 2u);
    EXPECT_EQ(poly.regions[0].attribute, 7);
    EXPECT_EQ(poly.regions[0].max_volume, 0.01);
    EXPECT_EQ(poly.regions[1].attribute, 8);
    EXPECT_EQ(poly.regions[1].max_volume, -1);
    const char* smesh =
        "4 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 1\n4 0\n3 0 2 1\n3 0 1 3\n3 1 2 3\n"
        "3 0 3 2\n0\n2\n0 0.1 0.1 0.1 5 1e-3\n1 0.2 0.1 0.1 -6\n";
    const io::PlcFile file = io::parse_smesh(smesh, "t.smesh", "t.node");
    EXPECT_EQ(file.regions, (std::vector<double>{0.1, 0.1, 0.1, 5, 1e-3, 0.2, 0.1, 0.1, -6, -1}));
    const triangulation::Plc3 plc = io::plc_from_file(file);
    ASSERT_EQ(plc.regions.size(), 2u);
    EXPECT_EQ(plc.regions[0].x, 0.1);
    EXPECT_EQ(plc.regions[0].attribute, 5);
    EXPECT_EQ(plc.regions[0].max_volume, 1e-3);
    EXPECT_EQ(plc.regions[1].attribute, -6);
    EXPECT_EQ(plc.regions[1].max_volume, -1);
    // A bound that is no number names its line.
    EXPECT_NE(format_error([&] {
                  io::parse_smesh(
                      "4 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 1\n4 0\n3 0 2 1\n"
                      "3 0 1 3\n3 1 2 3\n3 0 3 2\n0\n1\n0 0.1 0.1 0.1 5 x\n",
                      "t.smesh", "t.node");
              }).find("t.smesh:13:"),
              std::string::npos);
}

constexpr const char* kCubeOff = R"(OFF
# the unit cube
8 6 12
0 0 0
1 0 0
0 1 0
1 1 0
0 0 1
1 0 1
0 1 1
1 1 1
4 0 2 6 4
4 1 5 7 3
4 0 4 5 1 255 0 0
4 2 3 7 6
4 0 1 3 2 0.5 0.5 0.5 1
4 4 6 7 5
)";

TEST(Io_PlcFormat, ReadsOff) {
    const io::PlcFile plc = io::parse_off(kCubeOff, "cube.off");
    EXPECT_EQ(plc.vertex_count(), 8u);
    EXPECT_EQ(plc.first_index, 0u);
    ASSERT_EQ(plc.facets.size(), 6u);
    EXPECT_EQ(plc.facets[2].polygons[0], (std::vector<std::uint32_t>{0, 4, 5, 1}));
    // The counts may follow the keyword on its line.
    EXPECT_EQ(io::parse_off("OFF 3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "t.off").facets.size(),
              1u);
}

TEST(Io_PlcFormat, MalformedOffFilesNameTheLine) {
    struct Case {
        const char* text;
        const char* message;
    };
    const Case cases[] = {
        {"COFF\n3 1 0\n",
         "t.off:1: expected the keyword OFF on the first line, got 'COFF' (only "
         "plain OFF is read: no colours, normals or texture per vertex)"},
        {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n",
         "t.off:6: vertex number 3 out of range: the node file numbers its vertices 0 to 2"},
        {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 7 7\n",
         "t.off:6: expected 4 fields (#corners, 3 corners) and an optional colour of 3 or 4 "
         "numbers, got 6: \"3 0 1 2 7 7\""},
        {"OFF\n3 1 0\n0 0 0\n1 0 0\n", "t.off:4: file ends after 2 of 3 announced vertices"},
        {"OFF\n3\n",
         "t.off:2: expected the counts <#vertices> <#faces> [<#edges>], got 1 field: "
         "\"3\""},
        {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 1 2\n",
         "t.off:7: unexpected data after the 1 announced face: \"3 0 1 2\""},
    };
    for (const Case& c : cases) {
        EXPECT_EQ(format_error([&] { io::parse_off(c.text, "t.off"); }), c.message) << c.text;
    }
}

constexpr const char* kTwoTrianglesStl = R"(solid square
  facet normal 0 0 1
    outer loop
      vertex 0 0 0
      vertex 1 0 0
      vertex 1 1 0
    endloop
  endfacet
  facet normal 0 0 1
    outer loop
      vertex -0 0 0
      vertex 1 1 0
      vertex 0 1 0
    endloop
  endfacet
endsolid square
)";

TEST(Io_PlcFormat, ReadsAsciiStlMergingEqualCorners) {
    const io::PlcFile plc = io::parse_stl(kTwoTrianglesStl, "s.stl");
    EXPECT_EQ(plc.vertex_count(), 4u);  // -0 and 0 are one corner
    ASSERT_EQ(plc.facets.size(), 2u);
    EXPECT_EQ(plc.facets[0].polygons[0], (std::vector<std::uint32_t>{0, 1, 2}));
    EXPECT_EQ(plc.facets[1].polygons[0], (std::vector<std::uint32_t>{0, 2, 3}));
    EXPECT_EQ(plc.facets[1].line, 9u);
    EXPECT_FALSE(std::signbit(plc.xyz[0]));
}

std::string binary_stl(const std::vector<std::array<float, 9>>& triangles, const char* header) {
    std::string bytes(84, '\0');
    std::memcpy(bytes.data(), header, std::strlen(header));
    const auto count = static_cast<std::uint32_t>(triangles.size());
    for (int k = 0; k < 4; ++k) bytes[80 + k] = static_cast<char>((count >> (8 * k)) & 0xFF);
    for (const auto& triangle : triangles) {
        std::string record(50, '\0');
        for (int c = 0; c < 9; ++c) {
            const auto bits = std::bit_cast<std::uint32_t>(triangle[c]);
            for (int k = 0; k < 4; ++k) {
                record[12 + 4 * c + k] = static_cast<char>((bits >> (8 * k)) & 0xFF);
            }
        }
        bytes += record;
    }
    return bytes;
}

TEST(Io_PlcFormat, ReadsBinaryStl) {
    // A header starting with "solid", as some exporters write: the size decides.
    const std::string bytes =
        binary_stl({{0, 0, 0, 1, 0, 0, 1, 1, 0}, {0, 0, 0, 1, 1, 0, 0, 1, 0.1f}}, "solid fake");
    const io::PlcFile plc = io::parse_stl(bytes, "b.stl");
    EXPECT_EQ(plc.vertex_count(), 4u);
    ASSERT_EQ(plc.facets.size(), 2u);
    EXPECT_EQ(plc.facets[1].polygons[0], (std::vector<std::uint32_t>{0, 2, 3}));
    EXPECT_EQ(plc.xyz[11], static_cast<double>(0.1f));  // floats widen exactly
    const std::string nan_bytes =
        binary_stl({{0, 0, 0, 1, 0, 0, 1, std::numeric_limits<float>::quiet_NaN(), 0}}, "x");
    EXPECT_EQ(format_error([&] { io::parse_stl(nan_bytes, "b.stl"); }),
              "b.stl: binary STL triangle 1: corner 3 has a non-finite coordinate");
}

TEST(Io_PlcFormat, AsciiStlMayStartWithAByteOrderMark) {
    const io::PlcFile plc = io::parse_stl("\xEF\xBB\xBF" + std::string(kTwoTrianglesStl), "s.stl");
    EXPECT_EQ(plc.vertex_count(), 4u);
    EXPECT_EQ(plc.facets.size(), 2u);
    const auto path = std::filesystem::temp_directory_path() / "exactmesh_bom_test.stl";
    {
        std::ofstream out(path, std::ios::binary);
        out << "\xEF\xBB\xBF" << kTwoTrianglesStl;
    }
    EXPECT_EQ(io::read_stl(path).facets.size(), 2u);
    std::filesystem::remove(path);
}

// A device or a large file that is no STL fails on its first line, streamed: /dev/zero was read
// whole up to the 1 GB limit first (2.6 s).
TEST(Io_PlcFormat, StlFromADeviceFailsAtItsFirstLine) {
    if (!std::filesystem::exists("/dev/zero")) GTEST_SKIP() << "no /dev/zero";
    EXPECT_EQ(format_error([] { io::read_stl("/dev/zero"); }),
              "/dev/zero:1: a NUL byte at column 1 (binary data, not a text mesh file)");
}

TEST(Io_PlcFormat, MalformedStlFilesAreNamed) {
    EXPECT_EQ(format_error([&] { io::parse_stl("hello", "s.stl"); }),
              "s.stl: neither an ASCII STL file (starting with 'solid') nor a binary one (84 + 50 "
              "x count bytes, count at byte 80), 5 bytes long");
    EXPECT_EQ(format_error([&] {
                  io::parse_stl(
                      "solid a\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 "
                      "0 0\nvertex 1 1 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid\n",
                      "s.stl");
              }),
              "s.stl:7: expected 'endloop': \"vertex 0 1 0\"");
    EXPECT_EQ(format_error([&] {
                  io::parse_stl("solid a\nfacet normal 0 0 1\nouter loop\nvertex 0 0 x\n", "s.stl");
              }),
              "s.stl:4: z coordinate 'x' is not a number");
    EXPECT_EQ(format_error([&] { io::parse_stl("solid a\nfacet normal 0 0 1\n", "s.stl"); }),
              "s.stl:2: file ends before 'outer loop'");
    EXPECT_EQ(format_error([&] { io::parse_stl("solid a\nfacet 0 0 1\n", "s.stl"); }),
              "s.stl:2: expected 'facet normal <nx> <ny> <nz>' or 'endsolid': \"facet 0 0 1\"");
}

}  // namespace
}  // namespace exactmesh
