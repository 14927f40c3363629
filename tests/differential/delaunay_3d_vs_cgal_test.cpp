// SPDX-License-Identifier: MIT
// Differential campaign: our two 3D Delaunay algorithms (Bowyer-Watson, on 1 to 4 threads, and
// Green-Sibson) against
// CGAL's Delaunay_triangulation_3 (Epick), by DESIGN.md's rules lifted to 3D: identical
// tetrahedra where the Delaunay tetrahedralization is unique; otherwise both exactly Delaunay
// (ours by check_delaunay_3d), the same vertex set, the same hull vertices, the same strictly
// Delaunay faces (the faces every Delaunay tetrahedralization of the points has) and the same
// Delaunay cells.
//
// Unlike the triangle count in 2D, the number of tetrahedra is not an invariant: the 8
// cospherical corners of a cube are tetrahedralized by 5 or by 6 tetrahedra, both Delaunay.
// What is invariant is the Delaunay subdivision: its cells are the convex hulls of the points
// on each empty sphere, and every Delaunay tetrahedralization triangulates each cell. The
// tetrahedra of one cell share its sphere, so they are exactly the classes of tetrahedra joined
// across faces whose two apexes are cospherical; the campaign compares the vertex sets of
// those classes (and the tetrahedron counts where the tetrahedralization is unique).
//
// A face f of a Delaunay tetrahedralization is strictly (strongly) Delaunay when some sphere
// through its vertices has every other point strictly outside. With T1, T2 the tetrahedra on
// its sides (T2 absent on the hull), that holds exactly when the apex of T2 is not on T1's
// circumsphere and no other point lies on f's circumcircle: the spheres through f between
// the two circumspheres exclude every point except those on both, i.e. on the circle. A point
// on the circle lies in f's plane on a polygon of cocircular points triangulated around f, so
// it is the third vertex of a face sharing an edge with f: those are the only candidates.
// The tetrahedralization is unique when every face is strictly Delaunay.
#include <gtest/gtest.h>

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <iterator>
#include <map>
#include <random>
#include <set>
#include <span>
#include <string>
#include <vector>

#include "generators/inputs/inputs_3d.hpp"
#include "predicates/insphere.hpp"
#include "predicates/orient3d.hpp"
#include "triangulation/checks/check_3d.hpp"
#include "triangulation/delaunay/bowyer_watson_3d.hpp"
#include "triangulation/delaunay/green_sibson_3d.hpp"

namespace tri = exactmesh::triangulation;
namespace gen = exactmesh::generators;
using exactmesh::predicates::Sign;

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_3<std::uint32_t, K>;
using Tds = CGAL::Triangulation_data_structure_3<Vb>;
using CgalDelaunay = CGAL::Delaunay_triangulation_3<K, Tds>;

double test_scale() {
    const char* s = std::getenv("EXACTMESH_TEST_SCALE");
    return s ? std::atof(s) : 1.0;
}

/// CGAL's finite tetrahedra, vertices mapped to our duplicate representatives, positively
/// oriented in our convention (orient3d > 0; CGAL's cells have the opposite sign).
std::vector<tri::VertIdx> cgal_tets(const std::vector<double>& xyz,
                                    const std::vector<tri::VertIdx>& merged_into) {
    std::vector<std::pair<K::Point_3, std::uint32_t>> points;
    for (std::uint32_t i = 0; i < xyz.size() / 3; ++i) {
        points.emplace_back(K::Point_3(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]), i);
    }
    CgalDelaunay dt(points.begin(), points.end());
    std::vector<tri::VertIdx> out;
    if (dt.dimension() < 3) return out;
    for (auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c) {
        const tri::VertIdx v[4] = {
            merged_into[c->vertex(0)->info()], merged_into[c->vertex(1)->info()],
            merged_into[c->vertex(2)->info()], merged_into[c->vertex(3)->info()]};
        out.insert(out.end(), {v[1], v[0], v[2], v[3]});
    }
    return out;
}

using Tet = std::array<tri::VertIdx, 4>;
using Face = std::array<tri::VertIdx, 3>;

struct Summary {
    std::set<Tet> tets;           ///< sorted vertex sets
    std::set<Face> strict_faces;  ///< sorted vertex sets
    std::set<tri::VertIdx> vertices, hull_vertices;
    std::set<std::vector<tri::VertIdx>> cells;  ///< vertex sets of the Delaunay cells
    bool unique = true;
};

Summary summarize(const std::vector<double>& xyz, const std::vector<tri::VertIdx>& t) {
    Summary s;
    auto p = [&xyz](tri::VertIdx v) { return xyz.data() + 3 * std::size_t{v}; };
    struct Side {
        std::size_t tet;  ///< first index of the tetrahedron in t
        tri::VertIdx apex;
    };
    std::map<Face, std::vector<Side>> faces;
    std::map<std::pair<tri::VertIdx, tri::VertIdx>, std::set<tri::VertIdx>> around_edge;
    for (std::size_t i = 0; i + 3 < t.size(); i += 4) {
        Tet a{t[i], t[i + 1], t[i + 2], t[i + 3]};
        for (unsigned k = 0; k < 4; ++k) {
            Face f{};
            unsigned n = 0;
            for (unsigned j = 0; j < 4; ++j) {
                if (j != k) f[n++] = a[j];
            }
            std::sort(f.begin(), f.end());
            faces[f].push_back({i, a[k]});
            around_edge[{f[0], f[1]}].insert(f[2]);
            around_edge[{f[0], f[2]}].insert(f[1]);
            around_edge[{f[1], f[2]}].insert(f[0]);
            s.vertices.insert(a[k]);
        }
        std::sort(a.begin(), a.end());
        s.tets.insert(a);
    }
    // Union-find over tetrahedra (by first index / 4): one class per Delaunay cell.
    std::vector<std::size_t> cell(t.size() / 4);
    for (std::size_t c = 0; c < cell.size(); ++c) cell[c] = c;
    auto root = [&cell](std::size_t x) {
        while (cell[x] != x) x = cell[x] = cell[cell[x]];
        return x;
    };
    for (const auto& [f, sides] : faces) {
        // The first side's tetrahedron, positively oriented as stored: its sphere.
        const std::size_t i = sides[0].tet;
        const double* q[4] = {p(t[i]), p(t[i + 1]), p(t[i + 2]), p(t[i + 3])};
        bool strict = true;
        if (sides.size() == 2) {
            strict = exactmesh::predicates::insphere(q[0], q[1], q[2], q[3], p(sides[1].apex)) !=
                     Sign::Zero;
            if (!strict) cell[root(i / 4)] = root(sides[1].tet / 4);
        } else {
            s.hull_vertices.insert(f.begin(), f.end());
        }
        for (unsigned e = 0; e < 3 && strict; ++e) {
            const std::pair<tri::VertIdx, tri::VertIdx> edge = e == 0   ? std::pair{f[0], f[1]}
                                                               : e == 1 ? std::pair{f[0], f[2]}
                                                                        : std::pair{f[1], f[2]};
            for (const tri::VertIdx w : around_edge[edge]) {
                if (w == f[0] || w == f[1] || w == f[2]) continue;
                if (exactmesh::predicates::orient3d(p(f[0]), p(f[1]), p(f[2]), p(w)) != Sign::Zero)
                    continue;
                // In f's plane: on its circumcircle exactly when on the sphere through f and
                // the first side's apex (which is off the plane).
                if (exactmesh::predicates::insphere(q[0], q[1], q[2], q[3], p(w)) == Sign::Zero) {
                    strict = false;
                    break;
                }
            }
        }
        if (strict) {
            s.strict_faces.insert(f);
        } else {
            s.unique = false;
        }
    }
    std::map<std::size_t, std::set<tri::VertIdx>> members;
    for (std::size_t c = 0; c < cell.size(); ++c) {
        members[root(c)].insert(t.begin() + static_cast<long>(4 * c),
                                t.begin() + static_cast<long>(4 * c + 4));
    }
    for (const auto& [r, vertices] : members) s.cells.emplace(vertices.begin(), vertices.end());
    return s;
}

struct Algorithm {
    const char* name;
    tri::Delaunay3Function build;
};
/// Bowyer-Watson on `Threads` threads (parallel_bowyer_watson_3d.hpp), with parallel rounds from
/// 8 points per thread so that the campaign's small inputs run them too.
template <unsigned Threads>
tri::Delaunay3Result bowyer_watson_threads(std::span<const double> xyz,
                                           const tri::Delaunay3Options& options) {
    tri::Delaunay3Options parallel = options;
    parallel.order = tri::InsertionOrder::Brio;
    parallel.threads = Threads;
    parallel.parallel_round_minimum = 8;
    return tri::bowyer_watson_3d(xyz, parallel);
}

const Algorithm kAlgorithms[] = {{"bowyer-watson", &tri::bowyer_watson_3d},
                                 {"green-sibson", &tri::green_sibson_3d},
                                 {"bowyer-watson --threads 2", &bowyer_watson_threads<2>},
                                 {"bowyer-watson --threads 3", &bowyer_watson_threads<3>},
                                 {"bowyer-watson --threads 4", &bowyer_watson_threads<4>}};
constexpr std::size_t kAlgorithmCount = std::size(kAlgorithms);

struct Tally {
    int cases = 0;
    int unique = 0;
    int disagreements = 0;
};

/// Compares every algorithm (in a seed-chosen order) with CGAL on xyz.
void compare_with_cgal(const std::vector<double>& xyz, std::uint64_t seed, const std::string& label,
                       Tally& tally) {
    const tri::InsertionOrder orders[] = {tri::InsertionOrder::Given, tri::InsertionOrder::Random,
                                          tri::InsertionOrder::Brio};
    std::vector<tri::VertIdx> cgal;
    Summary reference;
    bool have_reference = false;
    ++tally.cases;
    for (std::size_t a = 0; a < kAlgorithmCount; ++a) {
        const Algorithm& algorithm = kAlgorithms[a];
        const tri::Delaunay3Result ours = algorithm.build(xyz, {orders[(seed + a) % 3], seed});
        if (!have_reference) {
            cgal = cgal_tets(xyz, ours.merged_into);
            reference = summarize(xyz, cgal);
            have_reference = true;
            tally.unique += reference.unique ? 1 : 0;
        }
        const Summary mine = summarize(xyz, ours.mesh.tets);
        const tri::Check3Report check = tri::check_delaunay_3d(ours.mesh);
        std::string problem;
        if (!check.ok) {
            problem = "not Delaunay: " + check.problem;
        } else if (ours.coplanar != cgal.empty()) {
            problem = ours.coplanar ? "no tetrahedron, CGAL has some" : "CGAL has no tetrahedron";
        } else if (reference.unique && mine.tets != reference.tets) {
            problem = "unique tetrahedralization differs from CGAL's";
        } else if (reference.unique && ours.mesh.tets.size() != cgal.size()) {
            problem = "tetrahedron count " + std::to_string(ours.mesh.tets.size() / 4) +
                      " vs CGAL " + std::to_string(cgal.size() / 4);
        } else if (mine.vertices != reference.vertices) {
            problem = "vertex sets differ";
        } else if (mine.hull_vertices != reference.hull_vertices) {
            problem = "hull vertices differ";
        } else if (mine.strict_faces != reference.strict_faces) {
            problem = "strictly Delaunay faces differ";
        } else if (mine.cells != reference.cells) {
            problem = "Delaunay cells differ";
        }
        if (!problem.empty()) {
            ++tally.disagreements;
            ADD_FAILURE() << label << ", " << algorithm.name << " (seed " << seed
                          << "): " << problem;
        }
    }
}

}  // namespace

TEST(Differential_Delaunay3VsCgal, SubsetsOfThe3x3x3Grid) {
    // Random subsets of the 27-point grid: coplanar layers, cospherical cubes, collinear rows,
    // hull facets with many cocircular points.
    const int cases = std::max(20, static_cast<int>(300 * test_scale()));
    std::mt19937_64 rng(33);
    Tally tally;
    for (int c = 0; c < cases; ++c) {
        std::vector<double> xyz;
        const std::uint32_t keep = 4 + static_cast<std::uint32_t>(rng() % 24);
        for (int k = 0; k < 27; ++k) {
            if (rng() % 27 < keep)
                xyz.insert(xyz.end(), {double(k % 3), double(k / 3 % 3), double(k / 9)});
        }
        compare_with_cgal(xyz, static_cast<std::uint64_t>(c), "3x3x3 subset " + std::to_string(c),
                          tally);
    }
    std::printf("3x3x3 subsets: %d cases x %zu algorithms, %d unique, %d disagreements\n",
                tally.cases, kAlgorithmCount, tally.unique, tally.disagreements);
    EXPECT_EQ(tally.disagreements, 0);
}

TEST(Differential_Delaunay3VsCgal, SeededCampaignOverAllDistributions) {
    // 8 distributions x seeds x sizes from 4 to ~400 points (every tenth seed 2000; extreme
    // magnitudes, where every predicate of both sides ends in exact arithmetic, stay small).
    const int seeds = std::max(3, static_cast<int>(100 * test_scale()));
    Tally tally;
    for (const gen::Distribution3 d : gen::kAllDistributions3) {
        const bool extreme = d == gen::Distribution3::Huge || d == gen::Distribution3::Tiny;
        for (int seed = 0; seed < seeds; ++seed) {
            std::uint32_t n = 4u + static_cast<std::uint32_t>(seed * 37 % 400);
            if (seed % 10 == 9) n = 2000;
            if (extreme) n = 4u + static_cast<std::uint32_t>(seed * 7 % 60);
            const std::vector<double> xyz =
                gen::generate_points_3d(d, n, static_cast<std::uint64_t>(seed));
            compare_with_cgal(xyz, static_cast<std::uint64_t>(seed),
                              std::string(gen::distribution_name(d)) + " n=" + std::to_string(n),
                              tally);
        }
    }
    std::printf("differential campaign: %d cases x %zu algorithms, %d unique, %d disagreements\n",
                tally.cases, kAlgorithmCount, tally.unique, tally.disagreements);
    EXPECT_EQ(tally.disagreements, 0);
}
