// SPDX-License-Identifier: MIT
// The record plumbing the Triangle and TetGen readers share (io/records.hpp): each helper's
// exact message, file and line, and what it returns on good input.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <string_view>

#include "io/format_error.hpp"
#include "io/records.hpp"
#include "io/text_file.hpp"
#include "tests/support/error_message.hpp"

namespace io = exactmesh::io;
namespace detail = exactmesh::io::detail;

namespace {

/// The full message (file:line: problem...) that `work` throws, or "" when it throws nothing.
template <class Work>
std::string message_of(Work&& work) {
    return exactmesh::testing::error_message<io::FormatError>(work);
}

TEST(Io_Records, ReadHeaderNamesTheExpectedFormatAtTheEnd) {
    io::TextLines lines("# only a comment\n", "f.node");
    EXPECT_EQ(message_of([&] { detail::read_header(lines, "<#a> <b>"); }),
              "f.node:1: no header line (expected '<#a> <b>')");
    io::TextLines header("3 2\n", "f.node");
    EXPECT_EQ(message_of([&] { detail::read_header(header, "<#a> <b>"); }), "");
    EXPECT_EQ(header.fields().size(), 2u);
}

TEST(Io_Records, NextRecordCountsTheAnnouncedRecords) {
    io::TextLines lines("2\n0 1\n", "f.ele");
    ASSERT_TRUE(lines.next_data_line());
    EXPECT_EQ(message_of([&] { detail::next_record(lines, 0, 2, {"triangle", "triangles"}); }), "");
    EXPECT_EQ(message_of([&] {
                  detail::next_record(lines, 1, 2, {"triangle", "triangles"});
              }),
              "f.ele:2: file ends after 1 of 2 announced triangles");
    io::TextLines one("1\n", "f.ele");
    ASSERT_TRUE(one.next_data_line());
    EXPECT_EQ(message_of([&] { detail::next_record(one, 0, 1, detail::kVertices); }),
              "f.ele:1: file ends after 0 of 1 announced vertex");
}

TEST(Io_Records, ExpectEndNamesTheCountAndQuotesTheLine) {
    io::TextLines lines("1\n0 1\n7 7\n", "f.node");
    ASSERT_TRUE(lines.next_data_line());
    ASSERT_TRUE(lines.next_data_line());
    EXPECT_EQ(message_of([&] { detail::expect_end(lines, 1, detail::kVertices); }),
              "f.node:3: unexpected data after the 1 announced vertex: \"7 7\"");
}

TEST(Io_Records, HeaderFieldsAndFlags) {
    io::TextLines lines("1 2 3\n", "f.poly");
    ASSERT_TRUE(lines.next_data_line());
    EXPECT_EQ(message_of([&] { detail::expect_header_fields(lines, 3, "header", "a, b, c"); }), "");
    EXPECT_EQ(message_of([&] { detail::expect_header_fields(lines, 2, "segment header", "a, b"); }),
              "f.poly:1: segment header has 3 fields, expected at most 2 (a, b): \"1 2 3\"");
    EXPECT_TRUE(detail::parse_flag(lines, "1", "marker count"));
    EXPECT_FALSE(detail::parse_flag(lines, "0", "marker count"));
    EXPECT_EQ(message_of([&] { detail::parse_flag(lines, "2", "marker count"); }),
              "f.poly:1: marker count must be 0 or 1, got 2");
}

TEST(Io_Records, VertexNumbersAreZeroBasedAndInRange) {
    io::TextLines lines("1 2 3\n", "f.ele");
    ASSERT_TRUE(lines.next_data_line());
    const detail::VertexNumbers one_based(1, 4, "vertex number", "vertices");
    EXPECT_EQ(one_based.parse(lines, "1"), 0u);
    EXPECT_EQ(one_based.parse(lines, "4"), 3u);
    EXPECT_EQ(message_of([&] { one_based.parse(lines, "5"); }),
              "f.ele:1: vertex number 5 out of range: the node file numbers its vertices 1 to 4");
    EXPECT_EQ(message_of([&] { one_based.parse(lines, "0"); }),
              "f.ele:1: vertex number 0 out of range: the node file numbers its vertices 1 to 4");
    const detail::VertexNumbers none(0, 0, "node number", "points");
    EXPECT_EQ(message_of([&] { none.parse(lines, "0"); }),
              "f.ele:1: node number 0 out of range: the node file has no points");
}

}  // namespace
