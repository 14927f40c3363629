// SPDX-License-Identifier: MIT
// SVG pictures with a window (--view) and smallest-angle shading (--shade min-angle): what is
// left out, what is clipped, line widths from the triangles in the window, invalid windows,
// and the same picture at coordinates scaled by 2^±600.
#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "base/errors.hpp"
#include "io/svg_picture.hpp"

namespace io = exactmesh::io;

namespace {

struct Grid {
    std::vector<double> xy;
    std::vector<io::VertIdx> triangles;
};

/// n x n unit cells, each split in two triangles; corners at integer coordinates times `scale`.
Grid grid(int n, double scale = 1.0) {
    Grid g;
    for (int j = 0; j <= n; ++j) {
        for (int i = 0; i <= n; ++i) g.xy.insert(g.xy.end(), {i * scale, j * scale});
    }
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            const auto v = static_cast<io::VertIdx>(j * (n + 1) + i);
            const auto up = static_cast<io::VertIdx>(v + n + 1);
            g.triangles.insert(g.triangles.end(), {v, v + 1, up + 1, v, up + 1, up});
        }
    }
    return g;
}

std::size_t count_of(const std::string& text, const std::string& needle) {
    std::size_t count = 0;
    for (std::size_t at = text.find(needle); at != std::string::npos;
         at = text.find(needle, at + needle.size()))
        ++count;
    return count;
}

double attribute(const std::string& svg, const std::string& name) {
    const std::string key = " " + name + "=\"";
    const std::size_t at = svg.find(key);
    if (at == std::string::npos) return std::nan("");
    double value = std::nan("");
    std::from_chars(svg.data() + at + key.size(), svg.data() + svg.size(), value);
    return value;
}

/// Every number in the d="..." attributes of the picture.
std::vector<double> path_numbers(const std::string& svg) {
    std::vector<double> numbers;
    for (std::size_t at = svg.find(" d=\""); at != std::string::npos;
         at = svg.find(" d=\"", at + 1)) {
        const std::size_t begin = at + 4, end = svg.find('"', begin);
        for (std::size_t i = begin; i < end;) {
            const char c = svg[i];
            if ((c >= '0' && c <= '9') || c == '-') {
                double value = 0;
                const auto result = std::from_chars(svg.data() + i, svg.data() + end, value);
                numbers.push_back(value);
                i = static_cast<std::size_t>(result.ptr - svg.data());
            } else {
                ++i;
            }
        }
    }
    return numbers;
}

std::string without_desc(std::string svg) {
    const std::size_t begin = svg.find("<desc>"), end = svg.find("</desc>");
    if (begin != std::string::npos && end != std::string::npos) svg.erase(begin, end - begin);
    return svg;
}

}  // namespace

TEST(Io_SvgPicture, ViewDropsTrianglesOutsideAndClipsTheOthers) {
    const Grid g = grid(10);
    io::SvgOptions options;
    options.view = io::SvgWindow{2.5, 2.5, 4.5, 3.5};  // 2 x 1 cells, cutting cells in half
    const std::string svg = io::format_svg(g.xy, g.triangles, options);
    EXPECT_NE(svg.find("viewBox=\"0 0 1000.00 500.00\""), std::string::npos) << svg;
    EXPECT_NE(svg.find("<clipPath id=\"view\">"), std::string::npos);
    EXPECT_NE(svg.find("clip-path=\"url(#view)\""), std::string::npos);
    // Cells with i in 2..4 and j in 2..3 overlap the window: 3 x 2 cells, 12 triangles.
    EXPECT_EQ(count_of(svg, "Z"), 12u);
    EXPECT_NE(svg.find("12 in the window"), std::string::npos);
    // Clipped polygons stay within the window grown by its pad (5% of the width).
    for (const double value : path_numbers(svg)) {
        EXPECT_GE(value, -50.0 - 1e-9);
        EXPECT_LE(value, 1050.0 + 1e-9);
    }
    // Only the points inside the window are drawn: (3, 3) and (4, 3).
    const std::size_t dots = svg.find("stroke=\"#c0392b\"");
    ASSERT_NE(dots, std::string::npos);
    EXPECT_EQ(count_of(svg.substr(dots), "h0"), 2u);
}

TEST(Io_SvgPicture, ViewFarFromEveryTriangleDrawsNone) {
    const Grid g = grid(4);
    io::SvgOptions options;
    options.view = io::SvgWindow{10, 10, 11, 11};
    const std::string svg = io::format_svg(g.xy, g.triangles, options);
    EXPECT_EQ(count_of(svg, "Z"), 0u);
    EXPECT_EQ(svg.find("nan"), std::string::npos);
    EXPECT_NE(svg.find("</svg>"), std::string::npos);
}

TEST(Io_SvgPicture, LineWidthFollowsTheTrianglesInTheWindow) {
    const Grid g = grid(200);  // 80,000 triangles
    const std::string whole = io::format_svg(g.xy, g.triangles);
    io::SvgOptions options;
    options.view = io::SvgWindow{100, 100, 120, 120};  // 20 x 20 cells: ~800 triangles
    const std::string zoom = io::format_svg(g.xy, g.triangles, options);
    const double whole_stroke = attribute(whole, "stroke-width");
    const double zoom_stroke = attribute(zoom, "stroke-width");
    // The cells are 10x wider on screen; so are the lines (the whole mesh would give the
    // whole picture's hairlines).
    EXPECT_GT(zoom_stroke, 5 * whole_stroke);
    EXPECT_LT(zoom_stroke, 1.5 + 1e-9);
    // A 20 x 20 grid drawn whole has the same density on screen: the same width, to 20%.
    const Grid small = grid(20);
    const double small_stroke =
        attribute(io::format_svg(small.xy, small.triangles), "stroke-width");
    EXPECT_NEAR(zoom_stroke, small_stroke, 0.2 * small_stroke);
}

TEST(Io_SvgPicture, SamePictureAtCoordinatesScaledByTwoToThe600) {
    for (const int k : {600, -600}) {
        const double s = std::ldexp(1.0, k);
        const Grid g = grid(8), scaled = grid(8, s);
        io::SvgOptions options, scaled_options;
        options.shade = scaled_options.shade = io::SvgShade::MinAngle;
        options.view = io::SvgWindow{1.5, 0.5, 5.25, 3};
        scaled_options.view = io::SvgWindow{1.5 * s, 0.5 * s, 5.25 * s, 3 * s};
        const std::string svg = io::format_svg(g.xy, g.triangles, options);
        const std::string scaled_svg = io::format_svg(scaled.xy, scaled.triangles, scaled_options);
        EXPECT_EQ(without_desc(svg), without_desc(scaled_svg)) << "k = " << k;
    }
}

TEST(Io_SvgPicture, InvalidWindowsAreInputErrors) {
    const double inf = std::numeric_limits<double>::infinity();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const io::SvgWindow bad[] = {{0, 0, 0, 1},   {1, 0, 0, 1},   {0, 1, 1, 1},    {0, 2, 1, 1},
                                 {nan, 0, 1, 1}, {0, 0, inf, 1}, {-inf, 0, 1, 1}, {0, 0, 1, nan}};
    const Grid g = grid(2);
    for (const io::SvgWindow& window : bad) {
        EXPECT_FALSE(io::svg_window_problem(window).empty());
        io::SvgOptions options;
        options.view = window;
        EXPECT_THROW(io::format_svg(g.xy, g.triangles, options), exactmesh::InputError);
    }
    EXPECT_NE(io::svg_window_problem({1, 0, 0, 1}).find("X1"), std::string::npos);
    EXPECT_NE(io::svg_window_problem({0, 1, 1, 1}).find("Y1"), std::string::npos);
    EXPECT_NE(io::svg_window_problem({0, 0, inf, 1}).find("not finite"), std::string::npos);
    EXPECT_TRUE(io::svg_window_problem({-1.7e308, -1e-300, 1.7e308, 1e-300}).empty());
}

TEST(Io_SvgPicture, MinAngleIsScaleFree) {
    const double equilateral[] = {0, 0, 2, 0, 1, std::sqrt(3.0)};
    const double right[] = {0, 0, 1, 0, 0, 1};
    const double flat[] = {0, 0, 1, 0, 2, 0};
    const double point[] = {3, 3, 3, 3, 3, 3};
    const auto min_angle = [](const double* p, double s) {
        const double q[] = {p[0] * s, p[1] * s, p[2] * s, p[3] * s, p[4] * s, p[5] * s};
        return io::triangle_min_angle_degrees(q, q + 2, q + 4);
    };
    for (const double s : {1.0, std::ldexp(1.0, 600), std::ldexp(1.0, -600), std::ldexp(1.0, 1020),
                           std::ldexp(1.0, -1000)}) {
        EXPECT_NEAR(min_angle(equilateral, s), 60.0, 1e-6) << s;
        EXPECT_NEAR(min_angle(right, s), 45.0, 1e-9) << s;
        EXPECT_EQ(min_angle(flat, s), 0.0) << s;
        EXPECT_EQ(min_angle(point, s), 0.0) << s;
    }
    // Corners at +-1.7e308: edge vectors would overflow without the scaling.
    const double huge[] = {-1.7e308, -1.7e308, 1.7e308, -1.7e308, -1.7e308, 1.7e308};
    EXPECT_NEAR(io::triangle_min_angle_degrees(huge, huge + 2, huge + 4), 45.0, 1e-9);
    // A triangle 2^-540 across at 2^-500: the products of its edge vectors (2^-1080) would
    // underflow to zero without the scaling.
    const double at = std::ldexp(1.0, -500), across = std::ldexp(1.0, -540);
    const double tiny[] = {at, at, at + across, at, at, at + across};
    EXPECT_NEAR(io::triangle_min_angle_degrees(tiny, tiny + 2, tiny + 4), 45.0, 1e-9);
    // A sliver: 1 degree is 1 degree.
    const double t = std::tan(1.0 * 3.14159265358979323846 / 180.0);
    const double sliver[] = {0, 0, 1, 0, 1, t};
    EXPECT_NEAR(io::triangle_min_angle_degrees(sliver, sliver + 2, sliver + 4), 1.0, 1e-9);
}

TEST(Io_SvgPicture, ShadingFillsByClassAndDrawsTheColourBar) {
    // An equilateral triangle and a 2-degree sliver beside it.
    const double t = std::tan(2.0 * 3.14159265358979323846 / 180.0);
    const std::vector<double> xy{0, 0, 2, 0, 1, std::sqrt(3.0), 3, 0, 5, 0, 5, 2 * t};
    const std::vector<io::VertIdx> triangles{0, 1, 2, 3, 4, 5};
    io::SvgOptions options;
    options.shade = io::SvgShade::MinAngle;
    const std::string svg = io::format_svg(xy, triangles, options);
    EXPECT_NE(svg.find("<path fill=\"#a50026\""), std::string::npos);  // 0-5 degrees
    EXPECT_NE(svg.find("<path fill=\"#8ec2dd\""), std::string::npos);  // 55-60 degrees
    EXPECT_EQ(count_of(svg, "<path fill=\"#"), 2u);
    EXPECT_EQ(count_of(svg, "<rect x="), 12u);  // the colour bar's classes
    EXPECT_NE(svg.find("smallest angle of each triangle (degrees)"), std::string::npos);
    EXPECT_NE(svg.find(">60</text>"), std::string::npos);
    // The bar sits below the picture: the height grows, the width does not.
    const std::string plain = io::format_svg(xy, triangles);
    EXPECT_EQ(attribute(svg, "width"), attribute(plain, "width"));
    EXPECT_GT(attribute(svg, "height"), attribute(plain, "height"));
}

TEST(Io_SvgPicture, SegmentsAreClippedToTheWindow) {
    const std::vector<double> xy{-1e300, 0.5, 1e300, 0.5, 0, 0, 1, 0, 0, 1};
    const std::vector<io::VertIdx> triangles{2, 3, 4};
    io::SvgOptions options;
    options.segments = {0, 1};  // crosses the window from far left to far right
    options.view = io::SvgWindow{0, 0, 1, 1};
    const std::string svg = io::format_svg(xy, triangles, options);
    const std::size_t segment = svg.find("stroke=\"#111111\"");
    ASSERT_NE(segment, std::string::npos);
    for (const double value : path_numbers(svg)) {
        EXPECT_TRUE(std::isfinite(value));
        EXPECT_GE(value, -50.0 - 1e-9);
        EXPECT_LE(value, 1050.0 + 1e-9);
    }
    EXPECT_EQ(svg.find("inf"), std::string::npos);
}
