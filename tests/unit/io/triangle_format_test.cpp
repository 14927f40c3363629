// SPDX-License-Identifier: MIT
// Triangle .node/.ele/.neigh: exact round trips, the syntax Triangle accepts (comments, 1-based
// numbering, CRLF, omitted header fields), and every error path, each message checked for the
// file name, the line number and the problem.
#include <gtest/gtest.h>
#include <unistd.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <string>
#include <string_view>
#include <vector>

#include "io/format_error.hpp"
#include "io/triangle_format.hpp"
#include "triangulation/mesh/mesh2.hpp"

namespace fs = std::filesystem;
namespace io = exactmesh::io;
using exactmesh::triangulation::kNone;

namespace {

class Io_TriangleFormat : public ::testing::Test {
  protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = fs::temp_directory_path() /
               ("exactmesh_io_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override {
        std::error_code ec;
        fs::remove_all(dir_, ec);
    }

    fs::path write(const std::string& name, std::string_view content) const {
        const fs::path path = dir_ / name;
        std::ofstream out(path, std::ios::binary);
        out.write(content.data(), static_cast<std::streamsize>(content.size()));
        return path;
    }

    /// Reads `content` as a .node file; passes when it fails with a FormatError that names the
    /// file and `line` ("path:line: ...") and whose message contains `problem`.
    ::testing::AssertionResult node_error(std::string_view content, std::uint64_t line,
                                          const std::string& problem) const {
        const fs::path path = write("points.node", content);
        return expect_error([&] { io::read_node(path); }, path, line, problem);
    }

    /// The same for a .ele file read against a .node file of `vertex_count` vertices.
    ::testing::AssertionResult ele_error(std::string_view content, std::uint32_t first_index,
                                         std::uint32_t vertex_count, std::uint64_t line,
                                         const std::string& problem) const {
        const fs::path path = write("mesh.ele", content);
        return expect_error([&] { io::read_ele(path, first_index, vertex_count); }, path, line,
                            problem);
    }

    template <class Read>
    static ::testing::AssertionResult expect_error(Read read, const fs::path& path,
                                                   std::uint64_t line, const std::string& problem) {
        try {
            read();
        } catch (const io::FormatError& error) {
            const std::string what = error.what();
            const std::string location = line == 0
                                             ? path.string() + ": "
                                             : path.string() + ":" + std::to_string(line) + ": ";
            if (error.file() != path.string() || error.line() != line ||
                what.rfind(location, 0) != 0 || what.find(problem) == std::string::npos) {
                return ::testing::AssertionFailure()
                       << "message \"" << what << "\" (line " << error.line()
                       << ") does not start with \"" << location << "\" or lacks \"" << problem
                       << "\"";
            }
            return ::testing::AssertionSuccess() << what;
        } catch (const std::exception& other) {
            return ::testing::AssertionFailure() << "wrong exception type: " << other.what();
        }
        return ::testing::AssertionFailure() << "no exception for " << path;
    }

    fs::path dir_;
};

std::uint64_t bits(double value) {
    return std::bit_cast<std::uint64_t>(value);
}

// ---------------------------------------------------------------------------------------------
// Accepted syntax

TEST_F(Io_TriangleFormat, ReadsZeroBasedFileWithAttributesAndMarkers) {
    const auto nodes = io::read_node(write("a.node",
                                           "3 2 2 1\n"
                                           "0 0 0 10 20 1\n"
                                           "1 2.5 -1 11 21 0\n"
                                           "2 -3 4e2 12 22 -7\n"));
    EXPECT_EQ(nodes.first_index, 0u);
    EXPECT_EQ(nodes.vertex_count(), 3u);
    EXPECT_EQ(nodes.xy, (std::vector<double>{0, 0, 2.5, -1, -3, 400}));
    EXPECT_EQ(nodes.attribute_count, 2u);
    EXPECT_EQ(nodes.attributes, (std::vector<double>{10, 20, 11, 21, 12, 22}));
    EXPECT_TRUE(nodes.has_markers);
    EXPECT_EQ(nodes.markers, (std::vector<std::int32_t>{1, 0, -7}));
}

TEST_F(Io_TriangleFormat, ReadsOneBasedFileWithCommentsBlankLinesAndTabs) {
    const auto nodes = io::read_node(write("b.node",
                                           "# leading comment\n"
                                           "\n"
                                           "4\t2 0 1   # header comment\n"
                                           "   \n"
                                           "1 0 0 1\n"
                                           "# between vertices\n"
                                           "2\t4.  0 1#no space before the comment\n"
                                           "3 +4 3e0 1\n"
                                           "4 .5 2.5E0 0   \n"
                                           "# trailing comment\n\n"));
    EXPECT_EQ(nodes.first_index, 1u);
    EXPECT_EQ(nodes.xy, (std::vector<double>{0, 0, 4, 0, 4, 3, 0.5, 2.5}));
    EXPECT_EQ(nodes.markers, (std::vector<std::int32_t>{1, 1, 1, 0}));
    // Each vertex's own line, comments and blank lines counted (messages name it).
    EXPECT_EQ(nodes.lines, (std::vector<std::uint64_t>{5, 7, 8, 9}));
}

TEST_F(Io_TriangleFormat, CrlfLineEndingsReadLikeLf) {
    const std::string lf = "# c\n3 2 0 1\n1 0 0 5\n2 1 0 5\n3 0 1 5\n";
    std::string crlf;
    for (const char c : lf) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
    const auto a = io::read_node(write("lf.node", lf));
    const auto b = io::read_node(write("crlf.node", crlf));
    EXPECT_EQ(a.xy, b.xy);
    EXPECT_EQ(a.markers, b.markers);
    EXPECT_EQ(b.first_index, 1u);
    // An error in a CRLF file quotes the line without its '\r'.
    EXPECT_TRUE(node_error("2 2 0 0\r\n0 0 0\r\n1 1 2 3\r\n", 3,
                           "expected 3 fields (number, x, y), got 4: \"1 1 2 3\""));
}

TEST_F(Io_TriangleFormat, HeaderMayOmitTrailingFieldsAsTriangleAllows) {
    const auto only_count = io::read_node(write("c1.node", "2\n0 1 2\n1 3 4\n"));
    EXPECT_EQ(only_count.xy, (std::vector<double>{1, 2, 3, 4}));
    EXPECT_FALSE(only_count.has_markers);
    const auto with_dimension = io::read_node(write("c2.node", "1 2\n0 1 2"));  // no final newline
    EXPECT_EQ(with_dimension.xy, (std::vector<double>{1, 2}));
}

TEST_F(Io_TriangleFormat, ZeroVerticesIsAnEmptyPointSet) {
    const auto nodes = io::read_node(write("z.node", "0 2 0 0\n"));
    EXPECT_EQ(nodes.vertex_count(), 0u);
}

TEST_F(Io_TriangleFormat, CoordinatesAreCorrectlyRounded) {
    const auto nodes = io::read_node(write("r.node",
                                           "4 2 0 0\n"
                                           "0 0.1 9007199254740993\n"  // 2^53 + 1: tie, to even
                                           "1 2.4703282292062328e-324 -0\n"
                                           "2 1.7976931348623157e308 4e-320\n"
                                           "3 -2.2250738585072014e-308 0.30000000000000004\n"));
    EXPECT_EQ(bits(nodes.xy[0]), bits(0.1));
    EXPECT_EQ(nodes.xy[1], 9007199254740992.0);
    EXPECT_EQ(nodes.xy[2], std::numeric_limits<double>::denorm_min());
    EXPECT_TRUE(std::signbit(nodes.xy[3]));
    EXPECT_EQ(nodes.xy[4], std::numeric_limits<double>::max());
    EXPECT_EQ(bits(nodes.xy[5]), bits(4e-320));
    EXPECT_EQ(nodes.xy[6], -std::numeric_limits<double>::min());
    EXPECT_EQ(bits(nodes.xy[7]), bits(0.1 + 0.2));
}

// ---------------------------------------------------------------------------------------------
// Round trips

TEST_F(Io_TriangleFormat, NodeRoundTripIsBitExact) {
    std::mt19937_64 random(7);
    io::NodeFile nodes;
    nodes.first_index = 1;
    nodes.attribute_count = 1;
    nodes.has_markers = true;
    const double specials[] = {0.0,
                               -0.0,
                               0.1,
                               1.0 / 3.0,
                               1e308,
                               -1e-308,
                               4.9e-324,
                               1e-310,
                               std::nextafter(1.0, 2.0),
                               std::numeric_limits<double>::max()};
    for (const double s : specials) {
        nodes.xy.push_back(s);
        nodes.xy.push_back(-s);
    }
    for (int i = 0; i < 500; ++i) {
        for (int k = 0; k < 2; ++k) {
            double value;
            do {
                value = std::bit_cast<double>(random());
            } while (!std::isfinite(value));
            nodes.xy.push_back(value);
        }
    }
    for (std::uint32_t v = 0; v < nodes.vertex_count(); ++v) {
        nodes.attributes.push_back(static_cast<double>(v) / 7.0);
        nodes.markers.push_back(static_cast<std::int32_t>(v % 5) - 2);
    }
    const fs::path path = dir_ / "round.node";
    io::write_node(path, nodes);
    const io::NodeFile back = io::read_node(path);
    ASSERT_EQ(back.xy.size(), nodes.xy.size());
    for (std::size_t i = 0; i < nodes.xy.size(); ++i) {
        ASSERT_EQ(bits(back.xy[i]), bits(nodes.xy[i])) << "coordinate " << i;
    }
    EXPECT_EQ(back.first_index, 1u);
    EXPECT_EQ(back.attributes, nodes.attributes);
    EXPECT_EQ(back.markers, nodes.markers);
}

TEST_F(Io_TriangleFormat, EleRoundTripKeepsNumberingBase) {
    const std::vector<io::VertIdx> triangles{0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4};
    for (const std::uint32_t first : {0u, 1u}) {
        const fs::path path = dir_ / ("round" + std::to_string(first) + ".ele");
        io::write_ele(path, triangles, first);
        const io::EleFile ele = io::read_ele(path, first, 5);
        EXPECT_EQ(ele.triangles, triangles);
        EXPECT_EQ(ele.first_index, first);
        EXPECT_EQ(ele.triangle_count(), 4u);
    }
    EXPECT_EQ(io::format_ele(triangles, 1), "4 3 0\n1 1 2 5\n2 2 3 5\n3 3 4 5\n4 4 1 5\n");
}

TEST_F(Io_TriangleFormat, EleReadsQuadraticTrianglesAndAttributes) {
    const io::EleFile ele = io::read_ele(write("q.ele",
                                               "# six nodes, one attribute\r\n"
                                               "1 6 1\r\n"
                                               "0 0 1 2 3 4 5 -2.5\r\n"),
                                         0, 6);
    EXPECT_EQ(ele.triangles, (std::vector<io::VertIdx>{0, 1, 2}));
    EXPECT_EQ(ele.attributes, (std::vector<double>{-2.5}));
}

TEST_F(Io_TriangleFormat, NeighListsTheTriangleOppositeEachVertex) {
    // Square 0-1-2-3 split by the diagonal 0-2. Across-edge convention: t0 = (0,1,2) has t1
    // across edge (2,0), slot 2; t1 = (0,2,3) has t0 across edge (0,2), slot 0.
    const std::vector<io::TriIdx> across{kNone, kNone, 1, 0, kNone, kNone};
    // Opposite-vertex convention: t0's neighbour opposite vertex 1 (the edge 2-0) is t1; t1's
    // neighbour opposite vertex 3 (the edge 0-2) is t0.
    EXPECT_EQ(io::format_neigh(across, 0), "2 3\n0 -1 1 -1\n1 -1 -1 0\n");
    EXPECT_EQ(io::format_neigh(across, 1), "2 3\n1 -1 2 -1\n2 -1 -1 1\n");
    const fs::path path = dir_ / "square.neigh";
    io::write_neigh(path, across, 1);
    std::ifstream in(path);
    std::string header;
    std::getline(in, header);
    EXPECT_EQ(header, "2 3");
}

// ---------------------------------------------------------------------------------------------
// .node errors: every one names the file, the line and the problem

TEST_F(Io_TriangleFormat, MissingFileIsNamed) {
    const fs::path path = dir_ / "absent.node";
    EXPECT_TRUE(expect_error([&] { io::read_node(path); }, path, 0,
                             "cannot open for reading: No such file or directory"));
    EXPECT_TRUE(expect_error([&] { io::read_node(dir_); }, dir_, 0, "is a directory"));
}

TEST_F(Io_TriangleFormat, EmptyOrCommentOnlyFileHasNoHeader) {
    EXPECT_TRUE(node_error("", 1, "no header line"));
    EXPECT_TRUE(node_error("# just\n\n# comments\n", 3, "no header line"));
}

TEST_F(Io_TriangleFormat, HeaderErrors) {
    EXPECT_TRUE(node_error("abc 2 0 0\n", 1, "vertex count 'abc' is not a non-negative integer"));
    EXPECT_TRUE(node_error("# c\n-3 2 0 0\n", 2, "vertex count '-3' is negative"));
    EXPECT_TRUE(node_error("2000000000 2 0 0\n", 1,
                           "vertex count '2000000000' is too large (at most 1073741823)"));
    EXPECT_TRUE(node_error("99999999999999999999999 2 0 0\n", 1, "is too large"));
    EXPECT_TRUE(node_error("3 3 0 0\n", 1, "dimension must be 2, got 3"));
    EXPECT_TRUE(node_error("3 two 0 0\n", 1, "dimension 'two' is not a non-negative integer"));
    EXPECT_TRUE(node_error("3 2 x 0\n", 1, "attribute count 'x' is not a non-negative integer"));
    EXPECT_TRUE(node_error("3 2 0 2\n", 1, "boundary marker count must be 0 or 1, got 2"));
    EXPECT_TRUE(node_error("3 2 0 0 7\n", 1, "header has 5 fields, expected at most 4"));
}

TEST_F(Io_TriangleFormat, WrongFieldCountQuotesTheLine) {
    const std::string content =
        "# header, then three vertices with markers\n"
        "4 2 0 1\n"
        "1 0 0 1\n"
        "2 1.5 2\n";
    const fs::path path = write("points.node", content);
    try {
        io::read_node(path);
        FAIL() << "no error";
    } catch (const io::FormatError& error) {
        EXPECT_EQ(
            std::string(error.what()),
            path.string() + ":4: expected 4 fields (number, x, y, marker), got 3: \"2 1.5 2\"");
        EXPECT_EQ(error.line(), 4u);
        EXPECT_EQ(error.file(), path.string());
    }
    EXPECT_TRUE(node_error("1 2 2 0\n0 1 2 3\n", 2,
                           "expected 5 fields (number, x, y, 2 attributes), got 4: \"0 1 2 3\""));
}

TEST_F(Io_TriangleFormat, TrailingGarbageOnALineIsAnError) {
    EXPECT_TRUE(node_error("2 2 0 0\n0 0 0\n1 1 1 junk\n", 3,
                           "expected 3 fields (number, x, y), got 4: \"1 1 1 junk\""));
    EXPECT_TRUE(node_error("2 2 0 0\n0 0 0\n1 1.5x 1\n", 3, "x coordinate '1.5x' is not a number"));
    EXPECT_TRUE(node_error("1 2 0 0\n0 0x10 1\n", 2, "x coordinate '0x10' is not a number"));
    EXPECT_TRUE(node_error("1 2 0 0\n0 1 2,5\n", 2, "y coordinate '2,5' is not a number"));
    EXPECT_TRUE(node_error("1 2 0 0\n0 1 1e\n", 2, "y coordinate '1e' is not a number"));
}

TEST_F(Io_TriangleFormat, TrailingDataAfterTheVerticesIsAnError) {
    EXPECT_TRUE(node_error("2 2 0 0\n0 0 0\n1 1 1\n# fine\n2 5 5\n", 5,
                           "unexpected data after the 2 announced vertices: \"2 5 5\""));
}

TEST_F(Io_TriangleFormat, NonNumericCoordinates) {
    EXPECT_TRUE(node_error("1 2 0 0\n0 abc 1\n", 2, "x coordinate 'abc' is not a number"));
    EXPECT_TRUE(node_error("1 2 0 0\n0 1 --2\n", 2, "y coordinate '--2' is not a number"));
    EXPECT_TRUE(
        node_error("1 2 0 0\n0 \x01\xff 1\n", 2, "x coordinate '\\x01\\xff' is not a number"));
}

TEST_F(Io_TriangleFormat, NonFiniteCoordinates) {
    EXPECT_TRUE(node_error("4 2 0 0\n0 0 0\n1 2 0\n\n2 1 nan\n3 0 2\n", 5,
                           "non-finite y coordinate 'nan'"));
    EXPECT_TRUE(node_error("1 2 0 0\n0 inf 0\n", 2, "non-finite x coordinate 'inf'"));
    EXPECT_TRUE(node_error("1 2 0 0\n0 0 -Infinity\n", 2, "non-finite y coordinate '-Infinity'"));
    EXPECT_TRUE(node_error("1 2 0 0\n0 NaN(1) 0\n", 2, "non-finite x coordinate 'NaN(1)'"));
}

TEST_F(Io_TriangleFormat, CoordinatesOutsideTheDoubleRange) {
    EXPECT_TRUE(node_error("1 2 0 0\n0 1e400 0\n", 2, "x coordinate '1e400' overflows a double"));
    EXPECT_TRUE(
        node_error("1 2 0 0\n0 0 -123.4e307\n", 2, "y coordinate '-123.4e307' overflows a double"));
    EXPECT_TRUE(node_error("1 2 0 0\n0 1e-400 0\n", 2,
                           "x coordinate '1e-400' underflows to zero in a double"));
    EXPECT_TRUE(node_error("1 2 0 0\n0 0 0.0001e-320\n", 2, "underflows to zero"));
}

TEST_F(Io_TriangleFormat, VertexNumbering) {
    EXPECT_TRUE(
        node_error("2 2 0 0\n2 0 0\n3 1 1\n", 2, "first vertex number must be 0 or 1, got 2"));
    EXPECT_TRUE(node_error("3 2 0 0\n0 0 0\n1 1 1\n3 2 2\n", 4,
                           "vertex number 3 out of sequence, expected 2"));
    EXPECT_TRUE(node_error("3 2 0 0\n1 0 0\n1 1 1\n2 2 2\n", 3,
                           "vertex number 1 out of sequence, expected 2"));
    EXPECT_TRUE(
        node_error("1 2 0 0\n1.0 0 0\n", 2, "vertex number '1.0' is not a non-negative integer"));
    EXPECT_TRUE(node_error("1 2 0 0\n-1 0 0\n", 2, "vertex number '-1' is negative"));
}

TEST_F(Io_TriangleFormat, FewerVertexLinesThanAnnounced) {
    EXPECT_TRUE(node_error("5 2 0 0\n0 0 0\n1 2 0\n2 1 1\n", 4,
                           "file ends after 3 of 5 announced vertices"));
    EXPECT_TRUE(
        node_error("2 2 0 0\n0 0 0\n# cut here\n", 3, "file ends after 1 of 2 announced vertices"));
    EXPECT_TRUE(node_error("1 2 0 0", 1, "file ends after 0 of 1 announced vertex"));
}

TEST_F(Io_TriangleFormat, MarkerAndAttributeErrors) {
    EXPECT_TRUE(node_error("1 2 0 1\n0 0 0 1.5\n", 2, "boundary marker '1.5' is not an integer"));
    EXPECT_TRUE(node_error("1 2 0 1\n0 0 0 99999999999\n", 2,
                           "boundary marker '99999999999' is out of range"));
    EXPECT_TRUE(node_error("1 2 1 0\n0 0 0 inf\n", 2, "non-finite attribute 1 'inf'"));
    EXPECT_TRUE(node_error("1 2 2 0\n0 0 0 1 two\n", 2, "attribute 2 'two' is not a number"));
}

// ---------------------------------------------------------------------------------------------
// .ele errors

TEST_F(Io_TriangleFormat, EleMissingOrEmpty) {
    const fs::path path = dir_ / "absent.ele";
    EXPECT_TRUE(
        expect_error([&] { io::read_ele(path, 0, 3); }, path, 0, "cannot open for reading"));
    EXPECT_TRUE(ele_error("# nothing\n", 0, 3, 1, "no header line"));
}

TEST_F(Io_TriangleFormat, EleHeaderErrors) {
    EXPECT_TRUE(ele_error("x 3 0\n", 0, 3, 1, "triangle count 'x' is not a non-negative integer"));
    EXPECT_TRUE(ele_error("1 4 0\n", 0, 3, 1, "nodes per triangle must be 3"));
    EXPECT_TRUE(ele_error("1 3 0 0\n", 0, 3, 1, "header has 4 fields, expected at most 3"));
    EXPECT_TRUE(ele_error("1 3 -1\n", 0, 3, 1, "attribute count '-1' is negative"));
}

TEST_F(Io_TriangleFormat, EleLineErrors) {
    EXPECT_TRUE(ele_error("1 3 0\n0 0 1\n", 0, 3, 2,
                          "expected 4 fields (number, v1, v2, v3), got 3: \"0 0 1\""));
    EXPECT_TRUE(ele_error("1 3 0\n0 0 1 2 junk\n", 0, 3, 2, "expected 4 fields"));
    EXPECT_TRUE(ele_error("1 3 0\n0 0 1 two\n", 0, 3, 2,
                          "vertex number 'two' is not a non-negative integer"));
    EXPECT_TRUE(ele_error("1 3 1\n0 0 1 2 nan\n", 0, 3, 2, "non-finite attribute 1 'nan'"));
}

TEST_F(Io_TriangleFormat, EleVertexOutOfTheNodeFilesRange) {
    EXPECT_TRUE(
        ele_error("1 3 0\n1 0 1 2\n", 1, 4, 2,
                  "vertex number 0 out of range: the node file numbers its vertices 1 to 4"));
    EXPECT_TRUE(ele_error("1 3 0\n1 1 2 5\n", 1, 4, 2, "vertex number 5 out of range"));
    EXPECT_TRUE(ele_error("1 3 0\n0 0 1 2\n", 0, 0, 2, "the node file has no vertices"));
}

TEST_F(Io_TriangleFormat, EleTriangleNumbering) {
    EXPECT_TRUE(
        ele_error("1 3 0\n5 0 1 2\n", 0, 3, 2, "first triangle number must be 0 or 1, got 5"));
    EXPECT_TRUE(ele_error("2 3 0\n1 0 1 2\n3 0 1 2\n", 0, 3, 3,
                          "triangle number 3 out of sequence, expected 2"));
}

TEST_F(Io_TriangleFormat, EleTruncatedOrWithTrailingData) {
    EXPECT_TRUE(ele_error("3 3 0\n0 0 1 2\n1 0 1 2\n", 0, 3, 3,
                          "file ends after 2 of 3 announced triangles"));
    EXPECT_TRUE(ele_error("1 3 0\n0 0 1 2\n1 0 1 2\n", 0, 3, 3,
                          "unexpected data after the 1 announced triangle: \"1 0 1 2\""));
}

// ---------------------------------------------------------------------------------------------
// Writer errors

TEST_F(Io_TriangleFormat, WritingIntoAMissingDirectoryNamesTheFile) {
    const fs::path path = dir_ / "no_such_dir" / "out.ele";
    const std::vector<io::VertIdx> triangles{0, 1, 2};
    EXPECT_TRUE(expect_error([&] { io::write_ele(path, triangles, 0); }, path, 0,
                             "cannot open for writing: No such file or directory"));
    const fs::path node_path = dir_ / "no_such_dir" / "out.node";
    EXPECT_TRUE(expect_error([&] { io::write_node(node_path, io::NodeFile{}); }, node_path, 0,
                             "cannot open for writing"));
}

TEST_F(Io_TriangleFormat, ErrorsAreInputErrors) {
    const fs::path path = write("bad.node", "1 2 0 0\n0 nan 0\n");
    EXPECT_THROW(io::read_node(path), exactmesh::InputError);
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// .poly

TEST_F(Io_TriangleFormat, PolyWithSegmentsHolesAndRegions) {
    const fs::path path = write("domain.poly",
                                "# a square with a hole\n"
                                "4 2 0 1\n1 0 0 5\n2 4 0 5\n3 4 4 5\n4 0 4 5\n"
                                "4 1\n1 1 2 7\n2 2 3 7\n3 3 4 7\n4 4 1 7\n"
                                "1\n1 2 2\n"
                                "2\n1 1 1 3.5 0.1\n2 3 3 -2\n");
    const io::PolyFile poly = io::read_poly(path);
    EXPECT_EQ(poly.vertices.vertex_count(), 4u);
    EXPECT_EQ(poly.vertices.first_index, 1u);
    EXPECT_EQ(poly.segments, (std::vector<io::VertIdx>{0, 1, 1, 2, 2, 3, 3, 0}));
    EXPECT_EQ(poly.segment_markers, (std::vector<std::int32_t>{7, 7, 7, 7}));
    EXPECT_EQ(poly.holes, (std::vector<double>{2, 2}));
    EXPECT_EQ(poly.regions, (std::vector<double>{1, 1, 3.5, 0.1, 3, 3, -2, -1}));
    // Round trip of vertices and segments.
    const fs::path copy = dir_ / "copy.poly";
    io::write_poly(copy, poly.vertices, poly.segments, poly.segment_markers);
    const io::PolyFile again = io::read_poly(copy);
    EXPECT_EQ(again.vertices.xy, poly.vertices.xy);
    EXPECT_EQ(again.segments, poly.segments);
    EXPECT_EQ(again.segment_markers, poly.segment_markers);
}

TEST_F(Io_TriangleFormat, PolyWithoutVerticesReadsTheNodeFile) {
    write("shape.node", "3 2 0 0\n0 0 0\n1 1 0\n2 0 1\n");
    const fs::path path = write("shape.poly", "0 2 0 0\n3 0\n0 0 1\n1 1 2\n2 2 0\n0\n");
    const io::PolyFile poly = io::read_poly(path);
    EXPECT_TRUE(poly.vertices_from_node_file);
    EXPECT_EQ(poly.vertices.vertex_count(), 3u);
    EXPECT_EQ(poly.segment_count(), 3u);
    EXPECT_TRUE(poly.holes.empty());
}

TEST_F(Io_TriangleFormat, PolyErrorsNameFileLineAndProblem) {
    auto poly_error = [&](std::string_view content, std::uint64_t line,
                          const std::string& problem) {
        const fs::path path = write("bad.poly", content);
        return expect_error([&] { io::read_poly(path); }, path, line, problem);
    };
    EXPECT_TRUE(poly_error("3 2 0 0\n0 0 0\n1 1 0\n2 0 1\n1 0\n0 0 3\n0\n", 6,
                           "segment endpoint 3 names no vertex"));
    EXPECT_TRUE(poly_error("3 2 0 0\n0 0 0\n1 1 0\n2 0 1\n2 0\n0 0 1\n", 6,
                           "file ends after 1 of 2 announced segments"));
    EXPECT_TRUE(
        poly_error("3 2 0 0\n0 0 0\n1 1 0\n2 0 1\n1 0\n0 0 1\n", 6, "before the hole count"));
    EXPECT_TRUE(
        poly_error("3 2 0 0\n0 0 0\n1 1 0\n2 0 1\n0 0\n1\n0 nan 0\n", 7, "hole x coordinate"));
    EXPECT_TRUE(poly_error("3 2 0 0\n0 0 0\n1 1 0\n2 0 1\n0 0\n0\n1\n0 1 1\n", 8,
                           "expected 4 or 5 fields"));
    EXPECT_TRUE(poly_error("3 2 0 0\n0 0 0\n1 1 0\n2 0 1\n1 3\n0 0 1\n0\n", 5,
                           "segment marker count must be 0 or 1"));
    // 0 vertices: the .node of the same name is read, and its absence is reported by name.
    const fs::path path = write("bad.poly", "0 2 0 0\n0 0\n0\n");
    EXPECT_TRUE(expect_error([&] { io::read_poly(path); }, dir_ / "bad.node", 0, "cannot open"));
}
