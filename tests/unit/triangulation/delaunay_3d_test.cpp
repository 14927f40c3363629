// SPDX-License-Identifier: MIT
// The two 3D Delaunay constructions (Bowyer-Watson, Green-Sibson): exact validity
// (check_delaunay_3d), identical output under the shared perturbation for every insertion
// order, agreement with the naive empty-sphere oracle on small sets, degenerate inputs (cubic
// grids, cospherical lattice points, near-coplanar, coplanar, duplicates, extreme magnitudes)
// and bad input; and the check itself rejecting broken tetrahedralizations.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <set>
#include <span>
#include <string>
#include <vector>

#include "base/errors.hpp"
#include "predicates/insphere.hpp"
#include "predicates/orient3d.hpp"
#include "predicates/sos.hpp"
#include "tests/oracles/empty_sphere_delaunay_3d.hpp"
#include "triangulation/checks/check_3d.hpp"
#include "triangulation/delaunay/bowyer_watson_3d.hpp"
#include "triangulation/delaunay/green_sibson_3d.hpp"
#include "triangulation/mesh/spatial_sort.hpp"

namespace em = exactmesh;
namespace tri = exactmesh::triangulation;
using em::predicates::Sign;

namespace {

using Tet = std::array<tri::VertIdx, 4>;
using Tets = std::set<Tet>;

/// Tetrahedra as sorted vertex sets: order-free comparison (orientation is the check's job).
Tets canonical(const std::vector<tri::VertIdx>& tets) {
    Tets s;
    for (std::size_t t = 0; t + 3 < tets.size(); t += 4) {
        Tet a{tets[t], tets[t + 1], tets[t + 2], tets[t + 3]};
        std::sort(a.begin(), a.end());
        s.insert(a);
    }
    return s;
}

/// Every algorithm of the registry.
const std::span<const tri::Delaunay3Algorithm> kAlgorithms = tri::delaunay_3d_algorithms();
const tri::InsertionOrder kOrders[] = {tri::InsertionOrder::Given, tri::InsertionOrder::Random,
                                       tri::InsertionOrder::Brio};
const char* const kOrderNames[] = {"given", "random", "brio"};

bool has_duplicates(const std::vector<double>& xyz) {
    std::set<std::array<double, 3>> seen;
    for (std::size_t i = 0; i + 2 < xyz.size(); i += 3) {
        // +0 and -0 are the same point.
        if (!seen.insert({xyz[i] + 0.0, xyz[i + 1] + 0.0, xyz[i + 2] + 0.0}).second) return true;
    }
    return false;
}

/// Runs both algorithms in every order on xyz: every output passes the exact check; all have
/// the same tetrahedron count and merged_into; without duplicates, the same tetrahedra.
/// Returns the reference (bowyer-watson, given order).
tri::Delaunay3Result expect_all_agree(const std::vector<double>& xyz, const std::string& label) {
    const bool duplicates = has_duplicates(xyz);
    tri::Delaunay3Result reference = tri::bowyer_watson_3d(xyz, {tri::InsertionOrder::Given, 1});
    const Tets expected = canonical(reference.mesh.tets);
    for (const tri::Delaunay3Algorithm& algorithm : kAlgorithms) {
        for (std::size_t o = 0; o < 3; ++o) {
            const tri::Delaunay3Result r = algorithm.build(xyz, {kOrders[o], 7});
            const std::string what =
                label + " " + std::string(algorithm.name) + " " + kOrderNames[o];
            const tri::Check3Report report = tri::check_delaunay_3d(r.mesh);
            EXPECT_TRUE(report.ok) << what << ": " << report.problem;
            if (!report.ok) return reference;
            EXPECT_EQ(r.coplanar, reference.coplanar) << what;
            EXPECT_EQ(r.mesh.tets.size(), reference.mesh.tets.size()) << what;
            EXPECT_EQ(r.merged_into, reference.merged_into) << what;
            EXPECT_EQ(r.mesh.xyz, xyz) << what;
            if (!duplicates) {
                EXPECT_EQ(canonical(r.mesh.tets), expected) << what;
            }
        }
    }
    return reference;
}

/// The perturbed Delaunay tetrahedralization by brute force (tests/oracles): every non-flat
/// 4-subset whose perturbed circumsphere holds no other point. Unique, so it is exactly what
/// the algorithms must return (points must be distinct).
Tets naive_delaunay(const std::vector<double>& xyz) {
    return exactmesh::oracles::empty_sphere_delaunay_3d(xyz);
}

std::vector<double> uniform_points(std::size_t n, std::uint64_t seed, double lo = -1,
                                   double hi = 1) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(lo, hi);
    std::vector<double> xyz(3 * n);
    for (double& v : xyz) v = u(rng);
    return xyz;
}

/// The integer points of a k x k x k grid, shuffled.
std::vector<double> cubic_grid(int k, std::uint64_t seed) {
    std::vector<std::array<double, 3>> points;
    for (int x = 0; x < k; ++x)
        for (int y = 0; y < k; ++y)
            for (int z = 0; z < k; ++z) points.push_back({double(x), double(y), double(z)});
    std::mt19937_64 rng(seed);
    std::shuffle(points.begin(), points.end(), rng);
    std::vector<double> xyz;
    for (const auto& q : points) xyz.insert(xyz.end(), q.begin(), q.end());
    return xyz;
}

/// All integer points with x^2 + y^2 + z^2 = r^2 (exactly cospherical).
std::vector<double> sphere_lattice(int r) {
    std::vector<double> xyz;
    for (int x = -r; x <= r; ++x)
        for (int y = -r; y <= r; ++y)
            for (int z = -r; z <= r; ++z)
                if (x * x + y * y + z * z == r * r)
                    xyz.insert(xyz.end(), {double(x), double(y), double(z)});
    return xyz;
}

}  // namespace

TEST(Triangulation_Delaunay3, TinySetsMatchTheNaiveOracle) {
    // 4 to 12 random points, and the same with coordinates snapped to a 3-level lattice
    // (coplanar and cospherical subsets everywhere).
    for (int trial = 0; trial < 60; ++trial) {
        const std::size_t n = 4 + static_cast<std::size_t>(trial % 9);
        std::vector<double> xyz = uniform_points(n, static_cast<std::uint64_t>(trial));
        if (trial % 2 == 1) {
            for (double& v : xyz) v = std::round(v * 1.4);
        }
        if (has_duplicates(xyz)) continue;
        const std::string label = "trial " + std::to_string(trial);
        const tri::Delaunay3Result r = expect_all_agree(xyz, label);
        if (r.coplanar) continue;
        EXPECT_EQ(canonical(r.mesh.tets), naive_delaunay(xyz)) << label;
    }
}

TEST(Triangulation_Delaunay3, SmallestCases) {
    // Four points: one tetrahedron, positively oriented whatever their order.
    const std::vector<double> four = {0, 0, 0, 0, 1, 0, 1, 0, 0, 0, 0, 1};
    tri::Delaunay3Result r = expect_all_agree(four, "four");
    EXPECT_EQ(r.mesh.tet_count(), 1u);
    EXPECT_EQ(r.mesh.neighbors, std::vector<tri::TetIdx>(4, tri::kNone));
    // A square pyramid: the square's four points are coplanar and cocircular; 2 tetrahedra.
    const std::vector<double> pyramid = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0.5, 0.5, 1};
    r = expect_all_agree(pyramid, "pyramid");
    EXPECT_EQ(r.mesh.tet_count(), 2u);
    // An octahedron: six cospherical points, four tetrahedra around one diagonal.
    const std::vector<double> octahedron = {1, 0,  0, -1, 0, 0, 0, 1, 0,
                                            0, -1, 0, 0,  0, 1, 0, 0, -1};
    r = expect_all_agree(octahedron, "octahedron");
    EXPECT_EQ(r.mesh.tet_count(), 4u);
    EXPECT_EQ(canonical(r.mesh.tets), naive_delaunay(octahedron));
    // A cube: eight cospherical points; 5 or 6 tetrahedra, the oracle decides which.
    const std::vector<double> cube = cubic_grid(2, 3);
    r = expect_all_agree(cube, "cube");
    EXPECT_EQ(canonical(r.mesh.tets), naive_delaunay(cube));
}

TEST(Triangulation_Delaunay3, FewerThanFourNonCoplanarPointsGiveNoTetrahedron) {
    const std::vector<std::vector<double>> cases = {
        {},
        {1, 2, 3},
        {1, 2, 3, 1, 2, 3},
        {0, 0, 0, 1, 1, 1, 2, 2, 2, 3, 3, 3},               // collinear
        {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0.5, 0.5, 0},  // coplanar
        {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 0},               // three points and a duplicate
    };
    for (std::size_t c = 0; c < cases.size(); ++c) {
        for (const tri::Delaunay3Algorithm& algorithm : kAlgorithms) {
            const tri::Delaunay3Result r = algorithm.build(cases[c], {});
            EXPECT_TRUE(r.coplanar) << "case " << c << " " << algorithm.name;
            EXPECT_TRUE(r.mesh.tets.empty()) << "case " << c;
            EXPECT_EQ(r.merged_into.size(), cases[c].size() / 3);
            EXPECT_TRUE(tri::check_delaunay_3d(r.mesh).ok);
        }
    }
    // The duplicate of point 0 maps to it.
    const tri::Delaunay3Result r = tri::green_sibson_3d(cases[5], {});
    EXPECT_EQ(r.merged_into, (std::vector<tri::VertIdx>{0, 1, 2, 0}));
}

TEST(Triangulation_Delaunay3, RandomPointsAgree) {
    for (int trial = 0; trial < 12; ++trial) {
        const std::size_t n = 20 + static_cast<std::size_t>(trial) * 150;
        expect_all_agree(uniform_points(n, 100 + static_cast<std::uint64_t>(trial)),
                         "uniform n=" + std::to_string(n));
    }
}

TEST(Triangulation_Delaunay3, CubicGridsAreMassivelyCospherical) {
    for (int k = 2; k <= 7; ++k) {
        const std::vector<double> xyz = cubic_grid(k, static_cast<std::uint64_t>(k));
        const tri::Delaunay3Result r = expect_all_agree(xyz, "grid " + std::to_string(k));
        // Every unit cube is cut into tetrahedra: the volumes (6x each) sum to 6 (k-1)^3.
        long long six_volumes = 0;
        for (std::size_t t = 0; t < r.mesh.tets.size(); t += 4) {
            const double* a = r.mesh.point(r.mesh.tets[t]);
            const double* b = r.mesh.point(r.mesh.tets[t + 1]);
            const double* c = r.mesh.point(r.mesh.tets[t + 2]);
            const double* d = r.mesh.point(r.mesh.tets[t + 3]);
            six_volumes += std::llround(em::predicates::orient3d_fast(a, b, c, d));
        }
        EXPECT_EQ(six_volumes, 6LL * (k - 1) * (k - 1) * (k - 1)) << "grid " << k;
    }
    // Small grids also against the oracle.
    const std::vector<double> grid3 = cubic_grid(3, 11);
    EXPECT_EQ(canonical(tri::green_sibson_3d(grid3, {}).mesh.tets), naive_delaunay(grid3));
}

TEST(Triangulation_Delaunay3, LatticePointsOnASphere) {
    // Every integer point of spheres of radius 3, 5, 9 and 11 (30 to 102 points, many
    // cocircular and cospherical subsets), all on the hull; without and with the centre.
    for (const int r : {3, 5, 9, 11}) {
        std::vector<double> xyz = sphere_lattice(r);
        const std::size_t on_sphere = xyz.size() / 3;
        const tri::Delaunay3Result hull = expect_all_agree(xyz, "sphere r=" + std::to_string(r));
        // All points are hull vertices of a triangulated convex polytope with no interior
        // vertex: 2V - 4 boundary faces, and every vertex used.
        std::set<tri::VertIdx> used(hull.mesh.tets.begin(), hull.mesh.tets.end());
        EXPECT_EQ(used.size(), on_sphere);
        std::size_t boundary = 0;
        for (const tri::TetIdx u : hull.mesh.neighbors) boundary += u == tri::kNone;
        EXPECT_EQ(boundary, 2 * on_sphere - 4) << "r=" << r;
        xyz.insert(xyz.end(), {0.0, 0.0, 0.0});
        const tri::Delaunay3Result star =
            expect_all_agree(xyz, "sphere and centre r=" + std::to_string(r));
        // With the centre, every tetrahedron has the centre as a vertex (all others lie on the
        // empty sphere around it): the cone over the hull.
        for (std::size_t t = 0; t < star.mesh.tets.size(); t += 4) {
            EXPECT_TRUE(std::find(star.mesh.tets.begin() + static_cast<long>(t),
                                  star.mesh.tets.begin() + static_cast<long>(t) + 4,
                                  static_cast<tri::VertIdx>(on_sphere)) !=
                        star.mesh.tets.begin() + static_cast<long>(t) + 4);
        }
        EXPECT_EQ(star.mesh.tet_count(), 2 * on_sphere - 4);
    }
    EXPECT_EQ(canonical(tri::bowyer_watson_3d(sphere_lattice(3), {}).mesh.tets),
              naive_delaunay(sphere_lattice(3)));
}

TEST(Triangulation_Delaunay3, NearCoplanarByAFewUlps) {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(0.5, 1.5);
    std::uniform_int_distribution<int> ulps(-3, 3);
    for (int trial = 0; trial < 6; ++trial) {
        std::vector<double> xyz;
        const int n = 30 + 40 * trial;
        for (int i = 0; i < n; ++i) {
            const double x = u(rng), y = u(rng);
            double z = x + y;  // the plane z = x + y, off by a few ulps
            for (int k = ulps(rng); k != 0; k += k > 0 ? -1 : 1)
                z = std::nextafter(z, k > 0 ? 4.0 : 0.0);
            xyz.insert(xyz.end(), {x, y, z});
        }
        if (trial % 2 == 0) xyz.insert(xyz.end(), {1.0, 1.0, 5.0});  // one point well off
        expect_all_agree(xyz, "near-coplanar trial " + std::to_string(trial));
    }
    // Exactly coplanar plus one point off the plane: a cone over the planar triangulation.
    std::vector<double> plane;
    for (int i = 0; i < 5; ++i)
        for (int j = 0; j < 5; ++j)
            plane.insert(plane.end(), {double(i), double(j), double(i + j)});
    plane.insert(plane.end(), {0.0, 4.0, 9.0});
    const tri::Delaunay3Result r = expect_all_agree(plane, "plane and apex");
    EXPECT_EQ(r.mesh.tet_count(), 32u);  // 2 triangles per square of the 4x4 planar grid
}

TEST(Triangulation_Delaunay3, DuplicatesAreMergedIntoTheFirstCopy) {
    std::vector<double> xyz = uniform_points(200, 9);
    std::mt19937_64 rng(3);
    for (int i = 0; i < 100; ++i) {
        const std::size_t j = rng() % (xyz.size() / 3);
        xyz.insert(xyz.end(), {xyz[3 * j], xyz[3 * j + 1], xyz[3 * j + 2]});
    }
    xyz.insert(xyz.end(), {-0.0 * xyz[0] + xyz[0], xyz[1], xyz[2]});
    const tri::Delaunay3Result r = expect_all_agree(xyz, "duplicates");
    EXPECT_EQ(r.counters.duplicates, 101u);
    for (std::size_t v = 0; v < r.merged_into.size(); ++v) {
        const tri::VertIdx kept = r.merged_into[v];
        EXPECT_LE(kept, v);
        EXPECT_EQ(r.mesh.point(kept)[0], r.mesh.point(static_cast<tri::VertIdx>(v))[0]);
        EXPECT_EQ(r.merged_into[kept], kept);
    }
    for (const tri::VertIdx v : r.mesh.tets) EXPECT_EQ(r.merged_into[v], v);
    // Signed zeros are the same point.
    const std::vector<double> zeros = {0.0, 0.0, 0.0, 1, 0, 0, 0, 1, 0, 0, 0, 1, -0.0, 0.0, -0.0};
    const tri::Delaunay3Result z = tri::bowyer_watson_3d(zeros, {});
    EXPECT_EQ(z.merged_into[4], 0u);
    EXPECT_EQ(z.mesh.tet_count(), 1u);
}

TEST(Triangulation_Delaunay3, ExtremeMagnitudesGiveTheSameTetrahedra) {
    // Scaling by a power of two changes no predicate sign: the tetrahedra are identical. (Out
    // of the expansion-safe range every predicate ends in GMP: small sets keep this quick.)
    const std::vector<double> base = uniform_points(40, 21);
    const std::vector<double> grid = cubic_grid(3, 2);
    for (const std::vector<double>* points : {&base, &grid}) {
        const Tets expected = canonical(tri::bowyer_watson_3d(*points, {}).mesh.tets);
        for (const int exponent : {-500, 500}) {
            std::vector<double> scaled = *points;
            for (double& v : scaled) v = std::ldexp(v, exponent);
            const tri::Delaunay3Result r =
                expect_all_agree(scaled, "2^" + std::to_string(exponent));
            EXPECT_EQ(canonical(r.mesh.tets), expected) << "2^" << exponent;
        }
    }
    // Overflow range: products of coordinates near 1e300 overflow in double arithmetic.
    std::vector<double> huge = uniform_points(60, 4, -1e300, 1e300);
    expect_all_agree(huge, "1e300");
    huge.insert(huge.end(), {1e308, -1e308, 1.7e308});
    expect_all_agree(huge, "1e308");
}

TEST(Triangulation_Delaunay3, NonFiniteInputIsRejected) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    const std::vector<std::vector<double>> cases = {{0, 0, 0, 1, 0, 0, 0, nan, 0, 0, 0, 1},
                                                    {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, -inf}};
    const tri::VertIdx bad[] = {2, 3};
    for (std::size_t c = 0; c < cases.size(); ++c) {
        for (const tri::Delaunay3Algorithm& algorithm : kAlgorithms) {
            try {
                algorithm.build(cases[c], {});
                ADD_FAILURE() << algorithm.name << " accepted a non-finite coordinate";
            } catch (const em::NonFiniteCoordinate& e) {
                EXPECT_EQ(e.vertex(), bad[c]);
                EXPECT_NE(std::string(e.what()).find("point " + std::to_string(bad[c])),
                          std::string::npos);
            }
        }
    }
    EXPECT_THROW(tri::bowyer_watson_3d(std::vector<double>{0, 0}, {}), em::InputError);
    EXPECT_THROW(tri::delaunay_3d_algorithm("lawson"), em::InputError);
    EXPECT_EQ(tri::delaunay_3d_algorithm("green-sibson"), &tri::green_sibson_3d);
}

TEST(Triangulation_Delaunay3, CountersReportTheWork) {
    const std::vector<double> xyz = uniform_points(2000, 77);
    const tri::Delaunay3Result bw = tri::bowyer_watson_3d(xyz, {});
    const tri::Delaunay3Result gs = tri::green_sibson_3d(xyz, {});
    EXPECT_EQ(bw.counters.points, 2000u);
    EXPECT_GT(bw.counters.cavity_tets, 2000u);
    EXPECT_GT(bw.counters.insphere_calls, bw.counters.cavity_tets);
    EXPECT_GT(bw.counters.walk_steps, 0u);
    EXPECT_EQ(bw.counters.flips_2_3, 0u);
    EXPECT_EQ(gs.counters.outside_hull + gs.counters.splits_1_4 + gs.counters.splits_2_6 +
                  gs.counters.splits_edge,
              1996u);
    EXPECT_GT(gs.counters.outside_hull, 0u);
    EXPECT_GT(gs.counters.flips_2_3, 1000u);
    EXPECT_GT(gs.counters.flips_3_2, 100u);
    EXPECT_EQ(gs.counters.cavity_tets, 0u);
    // A grid in random order exercises the splits on faces and edges, the 4-4 flips and the
    // faces found unflippable and tried again (the output is checked in
    // CubicGridsAreMassivelyCospherical).
    const tri::Delaunay3Result grid =
        tri::green_sibson_3d(cubic_grid(6, 1), {tri::InsertionOrder::Random, 1});
    EXPECT_GT(grid.counters.splits_2_6, 0u);
    EXPECT_GT(grid.counters.splits_edge, 0u);
    EXPECT_GT(grid.counters.flips_4_4, 0u);
    EXPECT_GT(grid.counters.unflippable, 0u);
    EXPECT_TRUE(tri::check_delaunay_3d(grid.mesh).ok);
}

TEST(Triangulation_Delaunay3, HilbertOrderIsAPermutationAndLocal) {
    const std::vector<double> xyz = uniform_points(5000, 8);
    std::vector<std::uint32_t> order = tri::insertion_order_3d(xyz, tri::InsertionOrder::Brio, 3);
    std::vector<std::uint32_t> sorted = order;
    std::sort(sorted.begin(), sorted.end());
    for (std::uint32_t i = 0; i < sorted.size(); ++i) ASSERT_EQ(sorted[i], i);
    // Along the curve consecutive points are close: the mean step of the last round is far
    // below that of a random order.
    std::vector<std::uint32_t> all(5000);
    for (std::uint32_t i = 0; i < all.size(); ++i) all[i] = i;
    auto mean_step = [&xyz](const std::vector<std::uint32_t>& o) {
        double sum = 0;
        for (std::size_t i = 1; i < o.size(); ++i) {
            double s = 0;
            for (int c = 0; c < 3; ++c) {
                const double d = xyz[3 * o[i] + c] - xyz[3 * o[i - 1] + c];
                s += d * d;
            }
            sum += std::sqrt(s);
        }
        return sum / static_cast<double>(o.size() - 1);
    };
    const double random_step = mean_step(all);
    tri::hilbert_sort_3d(xyz, all);
    EXPECT_LT(mean_step(all) * 8, random_step);
}

TEST(Triangulation_Check3, RejectsBrokenTetrahedralizations) {
    const std::vector<double> xyz = uniform_points(40, 13);
    const tri::Delaunay3Result r = tri::bowyer_watson_3d(xyz, {});
    ASSERT_TRUE(tri::check_delaunay_3d(r.mesh).ok);
    {  // a tetrahedron turned inside out
        std::vector<tri::VertIdx> tets = r.mesh.tets;
        std::swap(tets[0], tets[1]);
        const tri::Check3Report c = tri::check_delaunay_3d(xyz, tets, {}, {1, 1});
        EXPECT_FALSE(c.ok);
        EXPECT_EQ(c.tet, 0u);
        EXPECT_NE(c.problem.find("tetrahedron 1 ("), std::string::npos) << c.problem;
        EXPECT_NE(c.problem.find("not positively oriented"), std::string::npos) << c.problem;
    }
    {  // a tetrahedron missing: a hole, a point unused or an open boundary
        std::vector<tri::VertIdx> tets(r.mesh.tets.begin() + 4, r.mesh.tets.end());
        EXPECT_FALSE(tri::check_delaunay_3d(xyz, tets).ok);
    }
    {  // a tetrahedron twice
        std::vector<tri::VertIdx> tets = r.mesh.tets;
        tets.insert(tets.end(), r.mesh.tets.begin(), r.mesh.tets.begin() + 4);
        EXPECT_FALSE(tri::check_delaunay_3d(xyz, tets).ok);
    }
    {  // a wrong neighbor
        std::vector<tri::TetIdx> neighbors = r.mesh.neighbors;
        std::swap(neighbors[0], neighbors[1]);
        if (neighbors[0] != neighbors[1]) {
            const tri::Check3Report c = tri::check_delaunay_3d(xyz, r.mesh.tets, neighbors);
            EXPECT_FALSE(c.ok);
            EXPECT_NE(c.problem.find("neighbor"), std::string::npos) << c.problem;
        }
    }
    {  // a 2-3 flip of a Delaunay face: valid tetrahedralization, not Delaunay
        // Five points: a triangle and two apexes, one each side, whose segment pierces it.
        const std::vector<double> five = {0, 0, 0, 4, 0, 0, 0, 4, 0, 1, 1, 10, 1, 1, -10};
        const tri::Delaunay3Result d = tri::bowyer_watson_3d(five, {});
        ASSERT_EQ(d.mesh.tet_count(), 2u);
        // The three tetrahedra around edge 3-4 instead: (3, 4, a, b) for each edge ab.
        std::vector<tri::VertIdx> flipped;
        for (const auto& e : {std::array<tri::VertIdx, 2>{0, 1}, {1, 2}, {2, 0}}) {
            tri::VertIdx t[4] = {3, 4, e[0], e[1]};
            if (em::predicates::orient3d(d.mesh.point(t[0]), d.mesh.point(t[1]), d.mesh.point(t[2]),
                                         d.mesh.point(t[3])) == Sign::Negative) {
                std::swap(t[2], t[3]);
            }
            flipped.insert(flipped.end(), t, t + 4);
        }
        EXPECT_TRUE(tri::check_tetrahedralization_3d(five, flipped).ok);
        const tri::Check3Report c = tri::check_delaunay_3d(five, flipped);
        EXPECT_FALSE(c.ok);
        EXPECT_NE(c.problem.find("not Delaunay"), std::string::npos) << c.problem;
    }
    {  // no tetrahedra for points that are not coplanar
        const tri::Check3Report c = tri::check_delaunay_3d(xyz, std::vector<tri::VertIdx>{});
        EXPECT_FALSE(c.ok);
        EXPECT_NE(c.problem.find("not coplanar"), std::string::npos) << c.problem;
    }
    {  // a square bipyramid without its lower half: a point left out
        const std::vector<double> pts = {0, 0, 0, 2, 0, 0, 2, 2, 0, 0, 2, 0, 1, 1, 1, 1, 1, -5};
        const tri::Delaunay3Result d = tri::bowyer_watson_3d(pts, {});
        ASSERT_TRUE(tri::check_delaunay_3d(d.mesh).ok);
        // Keep only the tetrahedra of the upper pyramid (without point 5).
        std::vector<tri::VertIdx> upper;
        for (std::size_t t = 0; t < d.mesh.tets.size(); t += 4) {
            if (std::find(d.mesh.tets.begin() + static_cast<long>(t),
                          d.mesh.tets.begin() + static_cast<long>(t) + 4,
                          5u) == d.mesh.tets.begin() + static_cast<long>(t) + 4) {
                upper.insert(upper.end(), d.mesh.tets.begin() + static_cast<long>(t),
                             d.mesh.tets.begin() + static_cast<long>(t) + 4);
            }
        }
        const tri::Check3Report c = tri::check_delaunay_3d(pts, upper);
        EXPECT_FALSE(c.ok);
        EXPECT_NE(c.problem.find("point 5 is not a vertex"), std::string::npos) << c.problem;
    }
}
