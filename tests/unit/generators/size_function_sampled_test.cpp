// SPDX-License-Identifier: MIT
// SizeFunction::quadtree and SizeFunction::smoothed, built by one shared SizeFunction::sampled:
// each refuses an unbounded field with its own message, keeps the field's description, and
// evaluates through its own grid (quadtree() or smoothing_grid(), never the other).
#include <gtest/gtest.h>

#include <string>

#include "base/errors.hpp"
#include "generators/sizing/size_function.hpp"
#include "tests/support/error_message.hpp"

namespace em = exactmesh;
namespace gen = exactmesh::generators;

namespace {

/// The InputError's message ("" when none is thrown).
std::string message_of_unbounded(bool quadtree) {
    return em::testing::error_message<em::InputError>([&] {
        if (quadtree) {
            gen::SizeFunction::quadtree(gen::SizeFunction(), {0, 0, 1, 1});
        } else {
            gen::SizeFunction::smoothed(gen::SizeFunction(), {0, 0, 1, 1});
        }
    });
}

}  // namespace

TEST(Generators_SizeFunctionSampled, UnboundedFieldsAreRefusedNamingTheKind) {
    EXPECT_EQ(message_of_unbounded(true), "size quadtree: the size field is unbounded (none)");
    EXPECT_EQ(message_of_unbounded(false), "size smoothing: the size field is unbounded (none)");
}

TEST(Generators_SizeFunctionSampled, EachKindKeepsItsOwnGridAndFollowsTheField) {
    const gen::SizeFunction field = gen::SizeFunction::uniform(0.25);
    const gen::SizeFunction q = gen::SizeFunction::quadtree(field, {0, 0, 1, 1});
    const gen::SizeFunction s = gen::SizeFunction::smoothed(field, {0, 0, 1, 1});
    ASSERT_NE(q.quadtree(), nullptr);
    EXPECT_EQ(q.smoothing_grid(), nullptr);
    ASSERT_NE(s.smoothing_grid(), nullptr);
    EXPECT_EQ(s.quadtree(), nullptr);
    EXPECT_TRUE(q.bounded());
    EXPECT_TRUE(s.bounded());
    // A uniform field is reproduced by both (bilinear interpolation of equal values).
    for (const double x : {0.0, 0.3, 1.0}) {
        EXPECT_DOUBLE_EQ(q(x, 0.7), 0.25) << x;
        EXPECT_DOUBLE_EQ(s(x, 0.7), 0.25) << x;
    }
    EXPECT_NE(q.describe().find(field.describe()), std::string::npos) << q.describe();
    EXPECT_NE(s.describe().find(field.describe()), std::string::npos) << s.describe();
}
