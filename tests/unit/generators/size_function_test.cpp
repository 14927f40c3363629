// SPDX-License-Identifier: MIT
// Size functions: the source formula's values (point and line sources, the cap, gamma 0/1/2 and
// general), scaling, the --size text (a number, or the documented file format) and its errors;
// the background mesh (exact on linear fields inside, the nearest point's value outside, every
// input error naming its item), the quadtree (2:1 balanced, continuous across leaves, exact on
// bilinear fields, its budgets), the smoothed field (the gradient bound and the range where the
// raw sources have kinks and slopes above the bound) and the file items of all three.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "base/errors.hpp"
#include "generators/sizing/background_size_2d.hpp"
#include "generators/sizing/size_function.hpp"
#include "generators/sizing/size_quadtree_2d.hpp"
#include "generators/sizing/size_smoothing_2d.hpp"
#include "predicates/orient2d.hpp"
#include "tests/support/error_message.hpp"

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
    const gen::PointSource p{1, 2, 0.1, 0.5, 2};     // d = 0.5 at (1, 2.5)
    const gen::LineSource l{0, 0, 4, 0, 0.2, 2, 1};  // d = |y| over the segment
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
        "# a comment\n\nuniform 0.5   # the cap\npoint 1 2 0.1 0.5 2\nline 0 0 4 0 0.2 2 1\n",
        "s.txt");
    EXPECT_EQ(f.point_sources().size(), 1u);
    EXPECT_EQ(f.line_sources().size(), 1u);
    EXPECT_NEAR(f(1, 2.5), 0.5, 1e-15);  // 0.65 capped
    EXPECT_NEAR(f(1, 1.9), 0.1 * (1 + 0.04) + 0.2 * (1 + 0.95), 1e-15);
    EXPECT_EQ(gen::parse_size_sources("uniform 0.125\n", "u")(3, 3), 0.125);
    // A UTF-8 byte order mark is skipped, as the mesh files' readers skip it.
    EXPECT_EQ(gen::parse_size_sources("\xEF\xBB\xBFuniform 0.125\r\n", "u")(3, 3), 0.125);
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
    EXPECT_EQ(message("point 1 2 3\n").rfind("s.txt:1: point takes 5 numbers", 0), 0u)
        << message("point 1 2 3\n");
    EXPECT_EQ(message("\nline 0 0 1 1 0.1 x 1\n").rfind("s.txt:2: 'x' is not a finite number", 0),
              0u);
    EXPECT_EQ(message("circle 1 2 3\n").rfind("s.txt:1: unknown item 'circle'", 0), 0u);
    EXPECT_EQ(message("point 0 0 0.1 -2 1\n").rfind("s.txt:1: point source 1: radius must be", 0),
              0u)
        << message("point 0 0 0.1 -2 1\n");
    EXPECT_EQ(message("uniform 1\nuniform 2\n").rfind("s.txt:2: a second uniform line", 0), 0u);
    EXPECT_EQ(message("# nothing\n").rfind("s.txt: no size given", 0), 0u);
}

// ---- background mesh ----

namespace {

/// A background mesh of an nx x ny grid of points over [0, 2] x [0, 1], the inner points moved
/// off the grid, each quad cut along a diagonal (alternating); sizes from `size`.
gen::SizeFunction grid_background(int nx, int ny, const std::function<double(double, double)>& size,
                                  std::vector<double>* xy_out = nullptr) {
    std::vector<double> xy, sizes;
    std::vector<std::uint32_t> triangles;
    for (int j = 0; j < ny; ++j) {
        for (int i = 0; i < nx; ++i) {
            double x = 2.0 * i / (nx - 1), y = 1.0 * j / (ny - 1);
            if (i > 0 && i + 1 < nx && j > 0 && j + 1 < ny)
                x += 0.2 / nx * std::sin(3.0 * i + j), y += 0.2 / ny * std::cos(i + 5.0 * j);
            xy.insert(xy.end(), {x, y});
            sizes.push_back(size(x, y));
        }
    }
    for (int j = 0; j + 1 < ny; ++j) {
        for (int i = 0; i + 1 < nx; ++i) {
            const auto v = static_cast<std::uint32_t>(i + nx * j), right = v + 1,
                       up = v + static_cast<std::uint32_t>(nx);
            if ((i + j) % 2 == 0) {
                triangles.insert(triangles.end(), {v, right, up + 1, v, up + 1, up});
            } else {
                triangles.insert(triangles.end(), {v, right, up, right, up + 1, up});
            }
        }
    }
    if (xy_out) *xy_out = xy;
    return gen::SizeFunction::background_mesh(std::move(xy), std::move(sizes),
                                              std::move(triangles));
}

double linear(double x, double y) {
    return 0.5 + 0.3 * x - 0.2 * y;
}

/// The message of the exactmesh error `f` throws ("" when it throws none).
std::string error_text(const std::function<void()>& f) {
    return em::testing::error_message<em::Error>(f);
}

}  // namespace

TEST(Generators_SizeFunction, BackgroundMeshInterpolatesLinearFieldsExactly) {
    const gen::SizeFunction f = grid_background(9, 6, linear);
    ASSERT_NE(f.background_mesh(), nullptr);
    EXPECT_EQ(f.describe(), "background mesh: 54 vertices, 80 triangles");
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> ux(0, 2), uy(0, 1);
    double worst = 0;
    for (int k = 0; k < 20000; ++k) {
        const double x = ux(random), y = uy(random);
        ASSERT_NE(f.background_mesh()->locate(x, y), em::triangulation::kNone);
        worst = std::max(worst, std::fabs(f(x, y) - linear(x, y)));
    }
    EXPECT_LT(worst, 1e-15 * 8);
    // Outside, the value at the nearest point of the mesh: here the box's nearest point (the
    // outer vertices are not moved).
    for (const auto& [x, y] : std::vector<std::pair<double, double>>{
             {-1, 0.5}, {3, 2}, {1.3, -0.4}, {2.5, 0.2}, {-5, -5}}) {
        EXPECT_EQ(f.background_mesh()->locate(x, y), em::triangulation::kNone);
        EXPECT_NEAR(f(x, y), linear(std::clamp(x, 0.0, 2.0), std::clamp(y, 0.0, 1.0)), 1e-15 * 4)
            << x << " " << y;
    }
    EXPECT_EQ(f.background_mesh()->boundary_edges().size(), 2u * 2 * (8 + 5));
    EXPECT_NEAR(f.scaled(2)(1, 0.5), 2 * linear(1, 0.5), 1e-14);
}

TEST(Generators_SizeFunction, BackgroundMeshNearestPointOfANonConvexMesh) {
    // An L: the unit square and the square right of it, below y = 1, plus the square above the
    // first; sizes 1 at the vertices but 3 at (2, 0) and (2, 1).
    const std::vector<double> xy = {0, 0, 1, 0, 2, 0, 0, 1, 1, 1, 2, 1, 0, 2, 1, 2};
    const std::vector<double> sizes = {1, 1, 3, 1, 1, 3, 1, 1};
    const std::vector<std::uint32_t> triangles = {0, 1, 4, 0, 4, 3, 1, 2, 5,
                                                  1, 5, 4, 3, 4, 7, 3, 7, 6};
    const gen::SizeFunction f = gen::SizeFunction::background_mesh(xy, sizes, triangles);
    // (1.8, 1.9): nearest is (1.8, 1) on the edge 4-5 (distance 0.9), not (1, 1.9) (0.8)? The
    // point (1, 1.9) is nearer: 0.8 < 0.9, on the edge 4-7 (sizes 1).
    EXPECT_NEAR(f(1.8, 1.9), 1.0, 1e-15);
    // (1.8, 1.5): (1.8, 1) at 0.5 beats (1, 1.5) at 0.8: size 1 + 0.8 * 2.
    EXPECT_NEAR(f(1.8, 1.5), 2.6, 1e-15);
    EXPECT_NEAR(f(1.5, 0.5), 2.0, 1e-15);  // inside
    // Far away, the far corner.
    EXPECT_NEAR(f(100, -100), 3.0, 1e-15);
}

TEST(Generators_SizeFunction, BackgroundMeshOfLongSliversLocatesEveryPoint) {
    // A fan of 5,000 slivers from the centre to a circle: most meet many buckets (the grid
    // coarsens instead of listing each in thousands of cells). Every point of the polygon is
    // found, by the exact tests, in a triangle that does contain it.
    const int n = 5000;
    std::vector<double> xy = {0, 0}, sizes = {1};
    std::vector<std::uint32_t> triangles;
    for (int k = 0; k < n; ++k) {
        const double theta = 2 * std::numbers::pi * k / n;
        xy.insert(xy.end(), {std::cos(theta), std::sin(theta)});
        sizes.push_back(linear(std::cos(theta), std::sin(theta)));
        triangles.insert(triangles.end(), {0, static_cast<std::uint32_t>(k + 1),
                                           static_cast<std::uint32_t>((k + 1) % n + 1)});
    }
    sizes[0] = linear(0, 0);
    const gen::SizeFunction f = gen::SizeFunction::background_mesh(xy, sizes, triangles);
    std::mt19937_64 random(9);
    std::uniform_real_distribution<double> u(-0.99, 0.99);
    for (int k = 0; k < 20000; ++k) {
        const double x = u(random), y = u(random);
        if (std::hypot(x, y) > 0.99) continue;
        const auto t = f.background_mesh()->locate(x, y);
        ASSERT_NE(t, em::triangulation::kNone) << x << " " << y;
        const double p[2] = {x, y};
        for (int e = 0; e < 3; ++e) {
            ASSERT_NE(em::predicates::orient2d(
                          &xy[2 * triangles[3 * t + static_cast<unsigned>(e)]],
                          &xy[2 * triangles[3 * t + static_cast<unsigned>((e + 1) % 3)]], p),
                      em::predicates::Sign::Negative);
        }
        ASSERT_NEAR(f(x, y), linear(x, y), 1e-12);
    }
}

TEST(Generators_SizeFunction, BackgroundMeshErrorsNameTheItem) {
    using Item = gen::BackgroundMeshError::Item;
    auto fails = [](std::vector<double> xy, std::vector<double> sizes,
                    std::vector<std::uint32_t> triangles, Item item, std::size_t index,
                    const std::string& start) {
        try {
            gen::SizeFunction::background_mesh(std::move(xy), std::move(sizes),
                                               std::move(triangles));
        } catch (const gen::BackgroundMeshError& error) {
            EXPECT_EQ(error.item(), item) << error.what();
            EXPECT_EQ(error.index(), index) << error.what();
            EXPECT_EQ(std::string(error.what()).rfind(start, 0), 0u) << error.what();
            return;
        }
        ADD_FAILURE() << "no error for " << start;
    };
    const std::vector<double> xy = {0, 0, 1, 0, 0, 1, 1, 1};
    const std::vector<double> sizes = {1, 1, 1, 1};
    fails({0, 0, 1}, {1}, {0, 0, 0}, Item::Mesh, 0, "background mesh: odd number of coordinates");
    fails(xy, {1, 1, 1}, {0, 1, 2}, Item::Mesh, 0, "background mesh: 4 vertices but 3 sizes");
    fails(xy, sizes, {}, Item::Mesh, 0, "background mesh: no triangle");
    fails(xy, sizes, {0, 1}, Item::Mesh, 0,
          "background mesh: triangle indices not a multiple of 3");
    fails({0, 0, 1, std::nan(""), 0, 1}, {1, 1, 1}, {0, 1, 2}, Item::Vertex, 1,
          "background mesh: vertex 1: non-finite");
    fails(xy, {1, 1, 0, 1}, {0, 1, 2}, Item::Vertex, 2,
          "background mesh: vertex 2: size must be a finite number > 0");
    fails(xy, {1, 1, 1, INFINITY}, {0, 1, 2}, Item::Vertex, 3,
          "background mesh: vertex 3: size must be");
    fails(xy, sizes, {0, 1, 2, 1, 3, 4}, Item::Triangle, 1,
          "background mesh: triangle 1: vertex index 4 out of range");
    fails(xy, sizes, {0, 1, 1}, Item::Triangle, 0, "background mesh: triangle 0: repeats a vertex");
    fails(xy, sizes, {0, 1, 2, 1, 2, 3}, Item::Triangle, 1,
          "background mesh: triangle 1: inverted (clockwise)");
    fails({0, 0, 1, 1, 2, 2}, {1, 1, 1}, {0, 1, 2}, Item::Triangle, 0,
          "background mesh: triangle 0: degenerate");
    // Exactly collinear only: 2^-50 off the line is a (thin) triangle.
    EXPECT_NO_THROW(gen::SizeFunction::background_mesh({0, 0, 1, 1 - std::ldexp(1.0, -50), 2, 2},
                                                       {1, 1, 1}, {0, 1, 2}));
    fails(xy, sizes, {0, 1, 3, 0, 1, 2}, Item::Triangle, 1,
          "background mesh: triangle 1: overlaps triangle 0");
}

// ---- quadtree ----

namespace {

/// The sources add up, so each is felt near itself only when the cap is low.
gen::SizeFunction graded_sources() {
    return gen::SizeFunction::sources({{0.3, 0.4, 0.004, 0.05, 1}},
                                      {{0.1, 0.9, 0.9, 0.95, 0.004, 0.1, 1}}, 0.1);
}

}  // namespace

TEST(Generators_SizeFunction, QuadtreeIsBalancedContinuousAndFollowsTheField) {
    const gen::SizeFunction field = graded_sources();
    const gen::SizeBox box{0, 0, 1.2, 1};
    gen::QuadtreeSizeOptions options;
    options.tolerance = 0.02;
    const gen::SizeFunction f = gen::SizeFunction::quadtree(field, box, options);
    const gen::SizeQuadtree2& q = *f.quadtree();
    EXPECT_GT(q.leaf_count(), 500u);
    EXPECT_EQ(f.describe().rfind("quadtree of (sources: 1 point, 1 line, cap 0.1", 0), 0u)
        << f.describe();
    double worst_jump = 0, worst_error = 0;
    int level_gap = 0;
    for (std::uint32_t i = 0; i < q.leaf_count(); ++i) {
        const auto& leaf = q.leaf(i);
        if (leaf.x0 >= box.x1 || leaf.y0 >= box.y1) continue;
        const double w = leaf.x1 - leaf.x0, eps = w * 1e-6;
        // Points on the leaf's sides, compared with the neighbour's own bilinear formula there.
        for (int k = 0; k <= 8; ++k) {
            const double t = k / 8.0;
            const double side[4][4] = {{leaf.x0 + t * w, leaf.y0, 0, -eps},
                                       {leaf.x0 + t * w, leaf.y1, 0, eps},
                                       {leaf.x0, leaf.y0 + t * w, -eps, 0},
                                       {leaf.x1, leaf.y0 + t * w, eps, 0}};
            for (const auto& s : side) {
                const double nx = s[0] + s[2], ny = s[1] + s[3];
                if (nx < 0 || ny < 0 || nx > box.x1 || ny > box.y1 || s[0] > box.x1 ||
                    s[1] > box.y1)
                    continue;
                const std::uint32_t other = q.locate_leaf(nx, ny);
                if (other == i) continue;
                // Edge neighbours (not the diagonal ones met at the corners) differ by one level.
                if (k > 0 && k < 8)
                    level_gap = std::max(level_gap, std::abs(q.leaf(other).level - leaf.level));
                const double mine = q.leaf_value(i, s[0], s[1]),
                             theirs = q.leaf_value(other, s[0], s[1]);
                worst_jump = std::max(worst_jump, std::fabs(mine - theirs) / mine);
            }
        }
        // The size rule: no leaf in the box larger than the field at its centre.
        const double cx = std::min(0.5 * (leaf.x0 + leaf.x1), box.x1),
                     cy = std::min(0.5 * (leaf.y0 + leaf.y1), box.y1);
        EXPECT_LE(w, field(cx, cy) * 1.0000001) << i;
    }
    EXPECT_LE(level_gap, 1);  // 2:1 balanced
    EXPECT_LT(worst_jump, 1e-14);
    std::mt19937_64 random(3);
    std::uniform_real_distribution<double> ux(box.x0, box.x1), uy(box.y0, box.y1);
    for (int k = 0; k < 20000; ++k) {
        const double x = ux(random), y = uy(random);
        worst_error = std::max(worst_error, std::fabs(f(x, y) - field(x, y)) / field(x, y));
    }
    EXPECT_LT(worst_error, 0.1) << "quadtree relative error";
    std::printf("quadtree: %u leaves, depth %d, largest relative error %.4f over 20000 points\n",
                q.leaf_count(), q.depth(), worst_error);
    // Outside the box: the value at the nearest point of the box.
    EXPECT_EQ(f(-1, 0.5), f(0, 0.5));
    EXPECT_EQ(f(2, 3), f(1.2, 1));
}

TEST(Generators_SizeFunction, QuadtreeReproducesBilinearFieldsExactly) {
    // A bilinear field is followed by the corners alone: only the size rule splits, and the
    // hanging corners' means are exact values of the field.
    const auto bilinear = [](double x, double y) {
        return 0.05 + 0.02 * x + 0.03 * y + 0.04 * x * y;
    };
    const gen::SizeFunction f = gen::SizeFunction::quadtree(
        gen::SizeFunction::analytic(bilinear, "bilinear"), {0, 0, 1, 1});
    EXPECT_GT(f.quadtree()->leaf_count(), 64u);
    std::mt19937_64 random(5);
    std::uniform_real_distribution<double> u(0, 1);
    double worst = 0;
    for (int k = 0; k < 20000; ++k) {
        const double x = u(random), y = u(random);
        worst = std::max(worst, std::fabs(f(x, y) - bilinear(x, y)));
    }
    EXPECT_LT(worst, 1e-16 * 8);
}

TEST(Generators_SizeFunction, QuadtreeErrors) {
    const gen::SizeFunction field = graded_sources();
    EXPECT_THROW(gen::SizeFunction::quadtree(field, {0, 0, 0, 1}), em::InputError);
    EXPECT_THROW(gen::SizeFunction::quadtree(gen::SizeFunction(), {0, 0, 1, 1}), em::InputError);
    gen::QuadtreeSizeOptions bad;
    bad.tolerance = 0;
    EXPECT_THROW(gen::SizeFunction::quadtree(field, {0, 0, 1, 1}, bad), em::InputError);
    bad = {};
    bad.max_depth = 31;
    EXPECT_THROW(gen::SizeFunction::quadtree(field, {0, 0, 1, 1}, bad), em::InputError);
    // The error of the quadtree of `f` over the unit square starts with `prefix`.
    const auto expect_error = [](const gen::SizeFunction& f,
                                 const gen::QuadtreeSizeOptions& options,
                                 const std::string& prefix) {
        EXPECT_EQ(error_text([&] {
                      gen::SizeFunction::quadtree(f, {0, 0, 1, 1}, options);
                  }).rfind(prefix, 0),
                  0u)
            << prefix;
    };
    gen::QuadtreeSizeOptions shallow;
    shallow.max_depth = 4;
    expect_error(field, shallow, "size quadtree: a cell at the maximum depth 4");
    // Over the budget: by the up-front estimate of the cell-factor rule (at once), or, with the
    // tolerance rule alone (no estimate), while the tree is built.
    gen::QuadtreeSizeOptions few;
    few.max_leaves = 100;
    expect_error(field, few, "size quadtree: the size field asks for about ");
    few.cell_factor = 0;
    few.tolerance = 1e-4;
    expect_error(field, few, "size quadtree: more than 100 leaves");
    // A uniform size of 3e-4 on the unit square: 4^12 leaves, refused before any is built
    // (it took 5.7 s and 850 MB to reach the budget of 2^22).
    expect_error(gen::SizeFunction::uniform(3e-4), {},
                 "size quadtree: the size field asks for about 1.68e+07 leaves");
    // The message names a sample where the field is not > 0 (the estimate's first).
    const gen::SizeFunction hole =
        gen::SizeFunction::analytic([](double x, double) { return x - 0.5; }, "x - 0.5");
    expect_error(hole, {}, "size quadtree: the size field is -0.49");
}

// ---- smoothing ----

TEST(Generators_SizeFunction, SmoothedFieldHasBoundedGradientAndStaysInRange) {
    // The min of two cones of slope 0.5 and a cap: kinks at the apexes, along the ridge where
    // the cones meet and along the cap's contour, and slopes above the gradation asked for.
    const auto cones = [](double x, double y) {
        return std::min({0.2, 0.01 + 0.5 * std::hypot(x - 0.3, y - 0.5),
                         0.01 + 0.5 * std::hypot(x - 0.6, y - 0.55)});
    };
    const gen::SizeFunction raw = gen::SizeFunction::analytic(cones, "two cones");
    gen::SmoothingOptions options;
    options.nx = 121;
    options.ny = 101;
    options.gradation = 0.2;
    const gen::SizeBox box{0, 0, 1.2, 1};
    const gen::SizeFunction f = gen::SizeFunction::smoothed(raw, box, options);
    const gen::SmoothedSizeGrid2& g = *f.smoothing_grid();
    EXPECT_LE(g.residual(), 1e-10);
    EXPECT_GT(g.iterations(), 0);
    const auto& s = g.values();
    const auto& s0 = g.raw_values();
    const auto [lo, hi] = std::minmax_element(s0.begin(), s0.end());
    // Per cell |ds/dx| and |ds/dy| (the bilinear derivatives are means of node differences),
    // and the largest change of slope between neighbouring cells (a kink's measure).
    // Kinks away from the pinned minima (the apexes stay cones, of slope g): nodes more than
    // 3 cells from every pin.
    std::vector<char> near_pin(s.size(), 0);
    for (std::size_t k = 0; k < s.size(); ++k) {
        if (!g.pinned(k)) continue;
        const auto pi = static_cast<std::int64_t>(k % g.nx()),
                   pj = static_cast<std::int64_t>(k / g.nx());
        for (std::int64_t j = std::max<std::int64_t>(0, pj - 3);
             j <= std::min<std::int64_t>(g.ny() - 1, pj + 3); ++j) {
            for (std::int64_t i = std::max<std::int64_t>(0, pi - 3);
                 i <= std::min<std::int64_t>(g.nx() - 1, pi + 3); ++i) {
                near_pin[static_cast<std::size_t>(i + g.nx() * j)] = 1;
            }
        }
    }
    auto slopes = [&](const std::vector<double>& v, double& steepest, double& kink) {
        steepest = kink = 0;
        for (std::uint32_t j = 0; j < g.ny(); ++j) {
            for (std::uint32_t i = 0; i + 1 < g.nx(); ++i) {
                const std::size_t k = i + std::size_t{g.nx()} * j;
                const double dx = (v[k + 1] - v[k]) / g.hx();
                steepest = std::max(steepest, std::fabs(dx));
                if (i + 2 < g.nx() && !near_pin[k] && !near_pin[k + 1] && !near_pin[k + 2])
                    kink = std::max(kink, std::fabs((v[k + 2] - v[k + 1]) / g.hx() - dx));
            }
        }
        for (std::uint32_t j = 0; j + 1 < g.ny(); ++j) {
            for (std::uint32_t i = 0; i < g.nx(); ++i) {
                const std::size_t k = i + std::size_t{g.nx()} * j;
                steepest = std::max(steepest, std::fabs((v[k + g.nx()] - v[k]) / g.hy()));
            }
        }
    };
    double raw_steepest, raw_kink, steepest, kink;
    slopes(s0, raw_steepest, raw_kink);
    slopes(s, steepest, kink);
    std::printf(
        "smoothing: raw slope %.3f, kink %.3f; smoothed slope %.3f, kink %.3f; %d CG iterations\n",
        raw_steepest, raw_kink, steepest, kink, g.iterations());
    EXPECT_GT(raw_steepest, 0.45);
    EXPECT_EQ(g.pinned_count(), 2u);                       // the apexes
    EXPECT_LE(steepest, options.gradation * (1 + 1e-12));  // |ds/dx|, |ds/dy| <= g in every cell
    EXPECT_LT(kink, raw_kink / 4);
    for (const double v : s) {
        ASSERT_GE(v, *lo);
        ASSERT_LE(v, *hi);
    }
    // The bilinear evaluation, also between nodes (derivatives by differences at a few points).
    std::mt19937_64 random(11);
    std::uniform_real_distribution<double> ux(0, 1.2), uy(0, 1);
    for (int k = 0; k < 2000; ++k) {
        const double x = ux(random), y = uy(random), h = 1e-7;
        const double value = f(x, y);
        ASSERT_GE(value, *lo);
        ASSERT_LE(value, *hi);
        const double gx = (f(std::min(x + h, 1.2), y) - f(std::max(x - h, 0.0), y)) /
                          (std::min(x + h, 1.2) - std::max(x - h, 0.0));
        const double gy = (f(x, std::min(y + h, 1.0)) - f(x, std::max(y - h, 0.0))) /
                          (std::min(y + h, 1.0) - std::max(y - h, 0.0));
        ASSERT_LE(std::hypot(gx, gy), std::sqrt(2.0) * options.gradation * (1 + 1e-4))
            << x << " " << y;
    }
    EXPECT_EQ(f(0, 0), s[0]);
    EXPECT_EQ(f(5, 5), s.back());
    EXPECT_EQ(f.describe(), "smoothed (two cones) on a 121 x 101 grid, gradation 0.2, length 0.02");
    // The apexes are pinned: the size there is the raw one.
    EXPECT_EQ(f(0.3, 0.5), 0.01);
    EXPECT_EQ(f(0.6, 0.55), 0.01);
    // Unpinned, the smoothing lifts them by about g L, and the slope bound holds without the
    // second limit (the differences' own maximum principle).
    options.pin_minima = false;
    const gen::SizeFunction lifted = gen::SizeFunction::smoothed(raw, box, options);
    const gen::SmoothedSizeGrid2& h = *lifted.smoothing_grid();
    double free_steepest, free_kink;
    slopes(h.values(), free_steepest, free_kink);
    std::printf("smoothing without pins: apex %.5f (raw 0.01), slope %.3f, kink %.3f\n",
                lifted(0.3, 0.5), free_steepest, free_kink);
    EXPECT_GT(lifted(0.3, 0.5), 0.011);
    EXPECT_LE(free_steepest, options.gradation * (1 + 1e-12));
    EXPECT_EQ(h.pinned_count(), 0u);
}

TEST(Generators_SizeFunction, SmoothingErrors) {
    const gen::SizeFunction raw = graded_sources();
    gen::SmoothingOptions options;
    EXPECT_THROW(gen::SizeFunction::smoothed(raw, {1, 0, 0, 1}, options), em::InputError);
    options.nx = 1;
    EXPECT_THROW(gen::SizeFunction::smoothed(raw, {0, 0, 1, 1}, options), em::InputError);
    options = {};
    options.gradation = 0;
    EXPECT_THROW(gen::SizeFunction::smoothed(raw, {0, 0, 1, 1}, options), em::InputError);
    options = {};
    options.length = -1;
    EXPECT_THROW(gen::SizeFunction::smoothed(raw, {0, 0, 1, 1}, options), em::InputError);
    options = {};
    options.residual = 0;
    EXPECT_THROW(gen::SizeFunction::smoothed(raw, {0, 0, 1, 1}, options), em::InputError);
    EXPECT_THROW(gen::SizeFunction::smoothed(gen::SizeFunction(), {0, 0, 1, 1}), em::InputError);
    const gen::SizeFunction infinite = gen::SizeFunction::analytic(
        [](double, double) { return std::numeric_limits<double>::infinity(); }, "inf");
    EXPECT_EQ(error_text([&] {
                  gen::SizeFunction::smoothed(infinite, {0, 0, 1, 1});
              }).rfind("size smoothing: the size field is inf", 0),
              0u);
    // Without a gradient limit the range still holds.
    options = {};
    options.gradation = std::numeric_limits<double>::infinity();
    const gen::SizeFunction unlimited = gen::SizeFunction::smoothed(raw, {0, 0, 1, 1}, options);
    const auto& v = unlimited.smoothing_grid()->values();
    const auto& r = unlimited.smoothing_grid()->raw_values();
    EXPECT_GE(*std::min_element(v.begin(), v.end()), *std::min_element(r.begin(), r.end()));
    EXPECT_LE(*std::max_element(v.begin(), v.end()), *std::max_element(r.begin(), r.end()));
}

// ---- the file format's new items ----

TEST(Generators_SizeFunction, ParsesBackgroundMeshQuadtreeAndSmoothFiles) {
    const gen::SizeFunction mesh = gen::parse_size_sources(
        "# a background mesh\nvertex 0 0 0.1\nvertex 1 0 0.2\nvertex 0 1 0.3\ntriangle 0 1 2\n",
        "b.txt");
    ASSERT_NE(mesh.background_mesh(), nullptr);
    EXPECT_NEAR(mesh(0.25, 0.25), 0.1 + 0.25 * 0.1 + 0.25 * 0.2, 1e-15);
    const gen::SizeFunction tree = gen::parse_size_sources(
        "point 0.5 0.5 0.01 0.1 1\nuniform 0.2\nbox 0 0 1 1\nquadtree 0.01 2\n", "q.txt");
    ASSERT_NE(tree.quadtree(), nullptr);
    EXPECT_NEAR(tree(0.5, 0.5), 0.01, 1e-15);  // a corner of four leaves
    const gen::SizeFunction smooth = gen::parse_size_sources(
        "smooth 33 17 0.5 0.1\nline 0 0 1 0 0.01 0.1 1\nuniform 0.2\nbox 0 0 2 1\n", "s.txt");
    ASSERT_NE(smooth.smoothing_grid(), nullptr);
    EXPECT_EQ(smooth.smoothing_grid()->nx(), 33u);
    EXPECT_EQ(smooth.smoothing_grid()->ny(), 17u);
    EXPECT_EQ(smooth.smoothing_grid()->gradation(), 0.5);
    EXPECT_EQ(smooth.smoothing_grid()->length(), 0.1);
    // A quadtree over a background mesh.
    const gen::SizeFunction both = gen::parse_size_sources(
        "vertex 0 0 0.1\nvertex 1 0 0.2\nvertex 0 1 0.3\nvertex 1 1 0.1\ntriangle 0 1 3\ntriangle "
        "0 3 2\nbox 0 0 1 "
        "1\nquadtree\n",
        "bq.txt");
    ASSERT_NE(both.quadtree(), nullptr);
    EXPECT_NEAR(both(0.5, 0.25), 0.125, 0.01);
}

TEST(Generators_SizeFunction, NewFileItemsErrorsNameTheLine) {
    auto message = [](const char* text) {
        return error_text([text] { gen::parse_size_sources(text, "f.txt"); });
    };
    auto starts = [&](const char* text, const char* start) {
        const std::string m = message(text);
        EXPECT_EQ(m.rfind(start, 0), 0u) << "text:\n" << text << "message: " << m;
    };
    starts("vertex 0 0\n", "f.txt:1: vertex takes 3 numbers (X Y S), got 2");
    starts("vertex 0 0 -1\n", "f.txt:1: vertex size must be a finite number > 0");
    starts("vertex 0 0 1\ntriangle 0 1.5 2\n", "f.txt:2: '1.5' is not a vertex number");
    starts("vertex 0 0 1\ntriangle 0 -1 2\n", "f.txt:2: '-1' is not a vertex number");
    starts("vertex 0 0 1\ntriangle 0 1\n", "f.txt:2: triangle takes 3 numbers (I J K), got 2");
    starts("vertex 0 0 1\nvertex 1 0 1\n", "f.txt:2: vertex lines but no triangle line");
    starts("vertex 0 0 1\nvertex 1 0 1\nvertex 0 1 1\n\ntriangle 0 1 3\n",
           "f.txt:5: triangle 0: vertex index 3 out of range (3 vertices)");
    starts("vertex 0 0 1\nvertex 1 0 1\nvertex 0 1 1\ntriangle 0 2 1\n",
           "f.txt:4: triangle 0: inverted (clockwise)");
    starts("vertex 0 0 1\nvertex 1 0 1\nvertex 2 0 1\ntriangle 0 1 2\n",
           "f.txt:4: triangle 0: degenerate");
    starts(
        "vertex 0 0 1\nvertex 1 0 1\nvertex 0 1 1\nvertex 1 1 1\ntriangle 0 1 2\n# x\ntriangle 0 1 "
        "3\n",
        "f.txt:7: triangle 1: overlaps triangle 0");
    starts("triangle 0 1 2\n", "f.txt:1: triangle 0: vertex index 0 out of range (0 vertices)");
    starts("point 0 0 1 1 1\nvertex 0 0 1\n",
           "f.txt:2: sources (uniform, point, line) and a background mesh");
    starts("vertex 0 0 1\nuniform 1\n",
           "f.txt:2: sources (uniform, point, line) and a background mesh");
    starts("uniform 1\nbox 0 0 1\n", "f.txt:2: box takes 4 numbers (X0 Y0 X1 Y1), got 3");
    starts("uniform 1\nbox 0 0 0 1\n", "f.txt:2: box needs X0 < X1 and Y0 < Y1");
    starts("uniform 1\nbox 0 0 1 1\nbox 0 0 1 1\n", "f.txt:3: a second box line");
    starts("uniform 1\nquadtree\n", "f.txt:2: quadtree needs a box line");
    starts("uniform 1\nsmooth 10 10\n", "f.txt:2: smooth needs a box line");
    starts("uniform 1\nquadtree 1 2 3\n",
           "f.txt:2: quadtree takes 0 to 2 numbers ([TOL [FACTOR]]), got 3");
    starts("uniform 1\nsmooth 10\n",
           "f.txt:2: smooth takes 2 to 4 numbers (NX NY [GRADE [LENGTH]]), got 1");
    starts("uniform 1\nsmooth 1 10\n", "f.txt:2: NX must be an integer in [2, 16384]");
    starts("uniform 1\nsmooth 10 2.5\n", "f.txt:2: NY must be an integer in [2, 16384]");
    starts("uniform 1\nquadtree\nsmooth 10 10\n", "f.txt:3: at most one quadtree or smooth line");
    starts("uniform 1\nbox 0 0 1 1\nquadtree -1\n",
           "f.txt:3: size quadtree: the tolerance must be");
    starts("uniform 1\nbox 0 0 1 1\nsmooth 10 10 0\n",
           "f.txt:3: size smoothing: the gradation must be > 0");
    try {
        gen::parse_size_sources("point 0 0 1e-9 1e-9 1\nbox 0 0 1 1\nquadtree 0.01 1\n", "f.txt");
        ADD_FAILURE() << "no error";
    } catch (const em::GeometryError& error) {
        EXPECT_EQ(std::string(error.what()).rfind("f.txt:3: size quadtree: ", 0), 0u)
            << error.what();
    }
    starts("# nothing\nbox 0 0 1 1\n", "f.txt: no size given");
}

// fuzz_adaptation_2d's finding (tests/data/fuzz/adaptation_2d_local_remesh_flat_background_triangle
// .bin): a background triangle counter-clockwise by exact orient2d (area 5.1e-18 at sides ~2)
// whose area rounds to 0 in doubles; the barycentric coordinates of a point on its side were
// 0 / 0, and the size NaN (the advancing front then refused "the size function is NaN"). Now
// every point of it gets a finite size within its corners' values, on a side the side's linear
// value, the same at 2^-600 and 2^600.
TEST(Generators_SizeFunction, BackgroundSliverFlatInDoublesHasFiniteSizes) {
    const std::vector<double> corners{-2.0,
                                      -1.0,
                                      -0x1.037bb0142af6cp+0,
                                      -0x1.abd3e55c0e524p-1,
                                      -0x1.bdd80a157b609p-6,
                                      -0x1.57a7cab81ca48p-1};
    ASSERT_EQ(em::predicates::orient2d(&corners[0], &corners[2], &corners[4]),
              em::predicates::Sign::Positive);
    for (const std::vector<double>& sizes :
         {std::vector<double>{4, 4, 4}, std::vector<double>{1, 2, 3}}) {
        std::vector<double> reference;
        for (const int k : {0, -600, 600}) {
            std::vector<double> xy = corners;
            for (double& c : xy) c = std::ldexp(c, k);
            std::vector<double> scaled_sizes = sizes;
            for (double& s : scaled_sizes) s = std::ldexp(s, k);
            const gen::SizeFunction f =
                gen::SizeFunction::background_mesh(xy, scaled_sizes, {0, 1, 2});
            std::vector<double> values;
            // The midpoint of each side (the one the fuzzer found: (-1.5068030380839281,
            // -0.91780050634732135) on the first), the corners and points near the middle.
            for (int i = 0; i < 3; ++i) {
                const double* a = &xy[2 * i];
                const double* b = &xy[2 * ((i + 1) % 3)];
                for (const double t : {0.0, 0.5, 0.25}) {
                    const double x = a[0] + t * (b[0] - a[0]), y = a[1] + t * (b[1] - a[1]);
                    const double s = f(x, y);
                    ASSERT_TRUE(std::isfinite(s)) << "2^" << k << " side " << i << " t " << t;
                    EXPECT_GE(s, std::ldexp(*std::min_element(sizes.begin(), sizes.end()), k));
                    EXPECT_LE(s, std::ldexp(*std::max_element(sizes.begin(), sizes.end()), k));
                    values.push_back(std::ldexp(s, -k));
                }
            }
            // The corners are their own sizes.
            EXPECT_EQ(values[0], sizes[0]);
            EXPECT_EQ(values[3], sizes[1]);
            EXPECT_EQ(values[6], sizes[2]);
            if (k == 0)
                reference = values;
            else
                EXPECT_EQ(values, reference) << "2^" << k;
        }
    }
    EXPECT_EQ(gen::SizeFunction::background_mesh(corners, {4, 4, 4}, {0, 1, 2})(
                  -1.5068030380839281, -0.91780050634732135),
              4.0);
}

// fuzz_adaptation_2d's finding (tests/data/fuzz/adaptation_2d_remesh_zero_size_far_vertex.bin):
// the adaptation's background mesh keeps an input vertex of no triangle 2^520 away from a
// triangle of sides ~1, so the bucket grid's cells are ~2^519 wide and every side's scaled
// length squared underflowed to 0: the nearest-side search at a point outside took 0 / 0, found
// no side, and returned the size 0 (the frontal generator refused it as the user's). Now the side
// is a point at that scale and the value is its end's.
TEST(Generators_SizeFunction, BackgroundFarOutsideATinyTriangleTakesItsValue) {
    const double far = std::ldexp(1.0, 520);
    std::vector<double> reference;
    for (const int k : {0, -600, 400}) {
        std::vector<double> xy{0, 0, 1, 0, 0, 1, far, far};
        for (double& c : xy) c = std::ldexp(c, k);
        const std::vector<double> sizes{std::ldexp(1.0, k), std::ldexp(2.0, k), std::ldexp(3.0, k),
                                        std::ldexp(4.0, k)};
        const gen::SizeFunction f = gen::SizeFunction::background_mesh(xy, sizes, {0, 1, 2});
        std::vector<double> values;
        for (const auto& [x, y] : {std::pair{2 * far, far}, std::pair{far, 0.0},
                                   std::pair{-far, -far}, std::pair{0.5, 0.5}}) {
            const double s = f(std::ldexp(x, k), std::ldexp(y, k));
            ASSERT_TRUE(std::isfinite(s)) << "2^" << k;
            EXPECT_GE(s, std::ldexp(1.0, k)) << "2^" << k << " at " << x << ", " << y;
            EXPECT_LE(s, std::ldexp(3.0, k)) << "2^" << k << " at " << x << ", " << y;
            values.push_back(std::ldexp(s, -k));
        }
        if (k == 0)
            reference = values;
        else
            EXPECT_EQ(values, reference) << "2^" << k;
    }
}

TEST(Generators_SizeFunction, ScaledSizeIsCappedNeverInfinite) {
    // A background mesh whose sizes span 1e-300 to 1e231, scaled by 1e98: the far vertex's size
    // would overflow; with the ceiling it is the ceiling, and the near one is scaled exactly.
    const std::vector<double> xy = {0, 0, -3e231, 0, 0, -3e30};
    const gen::SizeFunction size =
        gen::SizeFunction::background_mesh(xy, {1e-300, 1e231, 1e30}, {0, 1, 2});
    const double ceiling = gen::size_ceiling_2d(xy);
    EXPECT_EQ(ceiling, 6e231);
    const gen::SizeFunction scaled = size.scaled(1e98, ceiling);
    EXPECT_EQ(scaled(-3e231, 0), ceiling);
    EXPECT_DOUBLE_EQ(scaled(0, 0), 1e98 * 1e-300);
    EXPECT_TRUE(std::isinf(size.scaled(1e98)(-3e231, 0)));
    // A later ceiling lowers an earlier one, never raises it; the description names it.
    EXPECT_EQ(scaled.scaled(1, 1e300)(-3e231, 0), ceiling);
    EXPECT_EQ(scaled.scaled(1, 1e200)(-3e231, 0), 1e200);
    EXPECT_NE(scaled.describe().find("at most"), std::string::npos);
    // Scale invariance: the ceiling of the points scaled by 2^k is the ceiling scaled by 2^k,
    // for every k the points allow; a box spanning beyond the largest double saturates.
    for (const int k : {-600, -1, 1, 60}) {
        std::vector<double> s = xy;
        for (double& v : s) v = std::ldexp(v, k);
        EXPECT_EQ(gen::size_ceiling_2d(s), std::ldexp(ceiling, k)) << k;
    }
    EXPECT_EQ(gen::size_ceiling_2d(std::vector<double>{-1.7e308, 0, 1.7e308, 1}),
              std::numeric_limits<double>::max());
    EXPECT_EQ(gen::size_ceiling_2d(std::vector<double>{1, 1, 1, 1}),
              std::numeric_limits<double>::max());
}
