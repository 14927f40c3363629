// SPDX-License-Identifier: MIT
// TetGen .node/.ele/.face/.neigh and the 3D Gmsh and VTK writers: exact round trips, numbering
// bases, TetGen's orientation (the first two corners swapped on the way out and back), and one
// precise error (file, line, problem) for every kind of malformed input.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "io/format_error.hpp"
#include "io/gmsh_format.hpp"
#include "io/tetgen_format.hpp"
#include "io/vtk_format.hpp"
#include "triangulation/mesh/mesh3.hpp"

namespace io = exactmesh::io;

namespace {

/// A unit tetrahedron in triangulation/'s orientation (orient3d > 0: det[b-a, c-a, d-a] < 0)
/// and a second one sharing its face (0, 1, 2).
const std::vector<double> kXyz{0, 0, 0, 0, 1, 0, 1, 0, 0, 0, 0, 1, 0, 0, -1};
const std::vector<std::uint32_t> kTets{0, 1, 2, 3, 1, 0, 2, 4};
const std::vector<std::uint32_t> kNeighbors{
    std::uint32_t(-1), std::uint32_t(-1), std::uint32_t(-1), 1,
    std::uint32_t(-1), std::uint32_t(-1), std::uint32_t(-1), 0};

/// Expects parse to throw a FormatError at `line` whose message contains `needle`.
template <class Parse>
::testing::AssertionResult fails_with(Parse parse, std::uint64_t line, const std::string& needle) {
    try {
        parse();
    } catch (const io::FormatError& e) {
        if (e.line() != line) {
            return ::testing::AssertionFailure()
                   << "line " << e.line() << ", expected " << line << ": " << e.what();
        }
        if (std::string(e.what()).find(needle) == std::string::npos) {
            return ::testing::AssertionFailure() << "'" << e.what() << "' lacks '" << needle << "'";
        }
        return ::testing::AssertionSuccess();
    }
    return ::testing::AssertionFailure() << "no error";
}

}  // namespace

TEST(Io_TetGen, NodeFilesReadExactlyInEitherBase) {
    const io::TetgenNodeFile n = io::parse_tetgen_node(
        "# a comment\n3 3 1 1\n1 0.1 -2e-310 3  7.5 -4 # trailing comment\r\n2 1 2 3 0 0\n3 +4 5 6 "
        "1 2",
        "a.node");
    EXPECT_EQ(n.first_index, 1u);
    EXPECT_EQ(n.xyz, (std::vector<double>{0.1, -2e-310, 3, 1, 2, 3, 4, 5, 6}));
    EXPECT_EQ(n.attributes, (std::vector<double>{7.5, 0, 1}));
    EXPECT_EQ(n.markers, (std::vector<std::int32_t>{-4, 0, 2}));
    // The header's dimension may be omitted (3 is assumed); formatting round-trips exactly.
    const io::TetgenNodeFile m =
        io::parse_tetgen_node("2\n0 1 2 3\n1 0.30000000000000004 5 6\n", "b.node");
    EXPECT_EQ(m.first_index, 0u);
    EXPECT_EQ(io::parse_tetgen_node(io::format_tetgen_node(n.xyz, n.first_index), "c.node").xyz,
              n.xyz);
    EXPECT_EQ(io::parse_tetgen_node(io::format_tetgen_node(m.xyz, m.first_index), "c.node").xyz,
              m.xyz);
}

TEST(Io_TetGen, NodeErrorsNameFileLineAndProblem) {
    struct Case {
        const char* text;
        std::uint64_t line;
        const char* message;
    };
    const Case cases[] = {
        {"3 2 0 0\n", 1, "x.node:1: dimension must be 3, got 2"},
        {"2 3\n0 1 2 3\n1 1 2\n", 3, "expected 4 fields (number, x, y, z), got 3"},
        {"2 3\n0 1 2 3\n1 1 2 nan\n", 3, "non-finite z coordinate 'nan'"},
        {"2 3\n0 1 2 3\n1 1 2 1e999\n", 3, "z coordinate '1e999' overflows a double"},
        {"3 3\n0 1 2 3\n1 1 2 3\n", 3, "file ends after 2 of 3 announced vertices"},
        {"1 3\n0 1 2 3\n1 1 2 3\n", 3, "unexpected data after the 1 announced vertex"},
        {"2 3\n0 1 2 3\n5 1 2 3\n", 3, "vertex number 5 out of sequence, expected 1"}};
    for (const Case& c : cases) {
        EXPECT_TRUE(fails_with([&] { io::parse_tetgen_node(c.text, "x.node"); }, c.line, c.message))
            << c.text;
    }
    // The dimension a header declares picks the reader.
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / "exactmesh_tetgen_test";
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "three.node") << "1 3 0 0\n1 0 0 0\n";
    std::ofstream(dir / "two.node") << "1 2 0 0\n1 0 0\n";
    std::ofstream(dir / "bare.node") << "1\n1 0 0\n";
    EXPECT_EQ(io::read_node_dimension(dir / "three.node"), 3u);
    EXPECT_EQ(io::read_node_dimension(dir / "two.node"), 2u);
    EXPECT_EQ(io::read_node_dimension(dir / "bare.node"), 2u);
    std::ofstream(dir / "four.node") << "1 4 0 0\n1 0 0 0 0\n";
    EXPECT_TRUE(fails_with([&] { io::read_node_dimension(dir / "four.node"); }, 1,
                           "dimension must be 2 or 3, got 4"));
}

TEST(Io_TetGen, EleRoundTripSwapsToTetGensOrientation) {
    const std::string text = io::format_tetgen_ele(kTets, 1);
    // TetGen's order: last two corners swapped, numbered from 1.
    EXPECT_EQ(text, "2 4 0\n1 1 2 4 3\n2 2 1 5 3\n");
    const io::TetgenEleFile back = io::parse_tetgen_ele(text, "t.ele", 1, 5);
    EXPECT_EQ(back.tets, kTets);
    EXPECT_EQ(back.first_index, 1u);
    // Region attributes (TetGen -A): a fifth column, read back as regions.
    const std::vector<double> attributes{2, -0.5};
    const std::string with_regions = io::format_tetgen_ele(kTets, 1, attributes);
    EXPECT_EQ(with_regions, "2 4 1\n1 1 2 4 3 2\n2 2 1 5 3 -0.5\n");
    const io::TetgenEleFile regions_back = io::parse_tetgen_ele(with_regions, "r.ele", 1, 5);
    EXPECT_EQ(regions_back.tets, kTets);
    EXPECT_EQ(regions_back.regions, attributes);
    // Ten-node tetrahedra keep their corners; a region attribute is read.
    const io::TetgenEleFile quadratic =
        io::parse_tetgen_ele("1 10 1\n0 0 1 3 2 4 4 4 4 4 4 -2.5\n", "q.ele", 0, 5);
    EXPECT_EQ(quadratic.tets, (std::vector<std::uint32_t>{0, 1, 2, 3}));
    EXPECT_EQ(quadratic.regions, (std::vector<double>{-2.5}));
    EXPECT_TRUE(fails_with([] { io::parse_tetgen_ele("1 4 0\n1 1 2 3 9\n", "t.ele", 1, 5); }, 2,
                           "t.ele:2: node number 9 out of range: the node file numbers its "
                           "points 1 to 5"));
    EXPECT_TRUE(fails_with([] { io::parse_tetgen_ele("1 3 0\n1 1 2 3\n", "t.ele", 1, 5); }, 1,
                           "nodes per tetrahedron must be 4 (or 10 for quadratic tetrahedra), got "
                           "3 (a 2D Triangle .ele file?)"));
    EXPECT_TRUE(fails_with([] { io::parse_tetgen_ele("2 4 0\n1 1 2 3 4\n", "t.ele", 1, 5); }, 2,
                           "file ends after 1 of 2 announced tetrahedra"));
    EXPECT_TRUE(fails_with([] { io::parse_tetgen_ele("", "t.ele", 1, 5); }, 1, "no header line"));
}

TEST(Io_TetGen, BoundaryFacesAndNeighbors) {
    // 6 boundary faces (3 per tetrahedron), counter-clockwise seen from outside: the first
    // tetrahedron's face opposite corner 3 is shared; its face opposite corner 0 is (1, 3, 2).
    const std::string faces = io::format_tetgen_boundary_faces(kTets, kNeighbors, 0);
    EXPECT_EQ(faces.substr(0, faces.find('\n')), "6 0");
    EXPECT_NE(faces.find("\n0 1 3 2\n"), std::string::npos) << faces;
    // Outward normal of face (1, 3, 2): (p3 - p1) x (p2 - p1) = (0,-1,1) x (1,-1,0) = (1, 1, 1),
    // pointing away from vertex 0 = (0, 0, 0) of the tetrahedron: outward.
    EXPECT_EQ(io::format_tetgen_neigh(kNeighbors, 1), "2 4\n1 -1 -1 2 -1\n2 -1 -1 1 -1\n");
}

TEST(Io_TetGen, GmshAndVtkTetrahedra) {
    const std::string msh = io::format_msh_3d(kXyz, kTets);
    EXPECT_NE(msh.find("$Nodes\n1 5 1 5\n3 1 0 5\n"), std::string::npos) << msh;
    EXPECT_NE(msh.find("\n0 1 0\n"), std::string::npos);  // three coordinates, no padding
    // One block of 2 tetrahedra (type 4) in the volume, Gmsh's positive Jacobian.
    EXPECT_NE(msh.find("$Elements\n1 2 1 2\n3 1 4 2\n1 2 1 3 4\n2 1 2 3 5\n$EndElements"),
              std::string::npos)
        << msh;
    const std::string vtu = io::format_vtu_3d(kXyz, kTets, 1);
    EXPECT_NE(vtu.find("NumberOfPoints=\"5\" NumberOfCells=\"2\""), std::string::npos);
    EXPECT_NE(vtu.find("\n1 0 2 3\n0 1 2 4\n"), std::string::npos) << vtu;
    EXPECT_NE(vtu.find("\n4\n8\n"), std::string::npos);    // offsets
    EXPECT_NE(vtu.find("\n10\n10\n"), std::string::npos);  // VTK_TETRA
    // The 2D writers are unchanged by the shared code: z = 0 appended.
    EXPECT_NE(
        io::format_msh(std::vector<double>{0, 0, 1, 0, 0, 1}, std::vector<std::uint32_t>{0, 1, 2})
            .find("\n1 0 0\n"),
        std::string::npos);
}
