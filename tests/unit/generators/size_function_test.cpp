// SPDX-License-Identifier: MIT
// Size functions: the source formula's values (point and line sources, the cap, gamma 0/1/2 and
// general), scaling, the --size text (a number, or the documented file format) and its errors.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "generators/size_function.hpp"
#include "predicates/errors.hpp"

namespace em = exactmesh;
namespace gen = exactmesh::generators;

TEST(Generators_SizeFunction, NoneAndUniform) {
    const gen::SizeFunction none;
    EXPECT_FALSE(none.bounded());
    EXPECT_EQ(none(0.3, 0.4), std::numeric_limits<double>::infinity());
    const gen::SizeFunction u = gen::SizeFunction::uniform(0.25);
    EXPECT_TRUE(u.bounded());
    EXPECT_EQ(u(-7, 1e6), 0.25);
    EXPECT_EQ(u.scaled(2)(0, 0), 0.5);
    EXPECT_THROW(gen::SizeFunction::uniform(0), em::InputError);
    EXPECT_THROW(gen::SizeFunction::uniform(std::nan("")), em::InputError);
}

TEST(Generators_SizeFunction, SourceFormula) {
    // s = sum_k s_k [1 + (d_k / rbar_k)^gamma_k]
    const gen::PointSource p{1, 2, 0.1, 0.5, 2};                // d = 0.5 at (1, 2.5)
    const gen::LineSource l{0, 0, 4, 0, 0.2, 2, 1};             // d = |y| over the segment
    const gen::SizeFunction f = gen::SizeFunction::sources({p}, {l});
    // At (1, 2.5): point d = 0.5 -> 0.1 * (1 + 1) = 0.2; line d = 2.5 -> 0.2 * (1 + 1.25) = 0.45.
    EXPECT_NEAR(f(1, 2.5), 0.65, 1e-15);
    // Beyond the line's end, the distance is to its end point (5, 0) -> (4, 0): d = 1.
    const gen::SizeFunction line_only = gen::SizeFunction::sources({}, {l});
    EXPECT_NEAR(line_only(5, 0), 0.2 * 1.5, 1e-15);
    // General exponent, and the cap.
    const gen::SizeFunction g = gen::SizeFunction::sources({{0, 0, 0.01, 0.1, 1.5}}, {}, 0.05);
    EXPECT_NEAR(g(0.1, 0), 0.02, 1e-15);
    EXPECT_NEAR(g(0.2, 0), 0.01 * (1 + std::pow(2.0, 1.5)), 1e-15);
    EXPECT_EQ(g(10, 0), 0.05);
    // gamma 0: constant 2 s_k.
    EXPECT_NEAR(gen::SizeFunction::sources({{0, 0, 0.3, 1, 0}}, {})(9, 9), 0.6, 1e-15);
    EXPECT_THROW(gen::SizeFunction::sources({{0, 0, -1, 1, 1}}, {}), em::InputError);
    EXPECT_THROW(gen::SizeFunction::sources({{0, 0, 1, 0, 1}}, {}), em::InputError);
    EXPECT_THROW(gen::SizeFunction::sources({{0, 0, 1, 1, -1}}, {}), em::InputError);
    EXPECT_THROW(gen::SizeFunction::sources({}, {}), em::InputError);
}

TEST(Generators_SizeFunction, ParsesNumbersAndFiles) {
    double h = 0;
    EXPECT_TRUE(gen::parse_uniform_size(" 0.05 ", h));
    EXPECT_EQ(h, 0.05);
    EXPECT_FALSE(gen::parse_uniform_size("0", h));
    EXPECT_FALSE(gen::parse_uniform_size("-1", h));
    EXPECT_FALSE(gen::parse_uniform_size("sizes.txt", h));
    EXPECT_FALSE(gen::parse_uniform_size("1e999", h));
    const gen::SizeFunction f = gen::parse_size_sources(
        "# a comment\n\nuniform 0.5   # the cap\npoint 1 2 0.1 0.5 2\nline 0 0 4 0 0.2 2 1\n", "s.txt");
    EXPECT_EQ(f.point_sources().size(), 1u);
    EXPECT_EQ(f.line_sources().size(), 1u);
    EXPECT_NEAR(f(1, 2.5), 0.5, 1e-15);  // 0.65 capped
    EXPECT_NEAR(f(1, 1.9), 0.1 * (1 + 0.04) + 0.2 * (1 + 0.95), 1e-15);
    EXPECT_EQ(gen::parse_size_sources("uniform 0.125\n", "u")(3, 3), 0.125);
}

TEST(Generators_SizeFunction, FileErrorsNameTheLine) {
    auto message = [](const char* text) {
        try {
            gen::parse_size_sources(text, "s.txt");
        } catch (const em::InputError& error) {
            return std::string(error.what());
        }
        return std::string("no error");
    };
    EXPECT_EQ(message("point 1 2 3\n").rfind("s.txt:1: point takes 5 numbers", 0), 0u) << message("point 1 2 3\n");
    EXPECT_EQ(message("\nline 0 0 1 1 0.1 x 1\n").rfind("s.txt:2: 'x' is not a finite number", 0), 0u);
    EXPECT_EQ(message("circle 1 2 3\n").rfind("s.txt:1: unknown item 'circle'", 0), 0u);
    EXPECT_EQ(message("point 0 0 0.1 -2 1\n").rfind("s.txt:1: point source 1: radius must be", 0), 0u)
        << message("point 0 0 0.1 -2 1\n");
    EXPECT_EQ(message("uniform 1\nuniform 2\n").rfind("s.txt:2: a second uniform line", 0), 0u);
    EXPECT_EQ(message("# nothing\n").rfind("s.txt: no size given", 0), 0u);
}
