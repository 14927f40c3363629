// SPDX-License-Identifier: MIT
// Tests of base/errors.hpp: an exception carries the file and line that raised it, and the
// location type has one layout on every compiler (three plain fields, no library type), so a
// library and a caller built by different compilers agree on the exception object.
#include "base/errors.hpp"

#include <gtest/gtest.h>

#include <string>
#include <type_traits>

namespace {

using exactmesh::Error;
using exactmesh::InputError;
using exactmesh::SourceLocation;

static_assert(std::is_standard_layout_v<SourceLocation> &&
                  std::is_trivially_copyable_v<SourceLocation>,
              "SourceLocation is plain data on every compiler");
static_assert(sizeof(SourceLocation) == 2 * sizeof(const char*) + sizeof(const char*),
              "two pointers and a line number, padded to a pointer");

TEST(Base_Errors, AnExceptionNamesTheFileAndLineThatRaisedIt) {
    int line = 0;
    try {
        line = __LINE__ + 1;
        throw InputError("bad value");
    } catch (const Error& error) {
        EXPECT_STREQ(error.what(), "bad value");
        EXPECT_EQ(error.where().line(), static_cast<unsigned>(line));
        EXPECT_NE(std::string(error.where().file_name()).find("errors_test.cpp"),
                  std::string::npos);
        EXPECT_NE(std::string(error.where().function_name()), "");
    }
}

}  // namespace
