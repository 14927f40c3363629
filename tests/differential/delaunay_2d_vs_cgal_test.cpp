// SPDX-License-Identifier: MIT
// Differential campaign: our three 2D Delaunay algorithms (Bowyer-Watson also on 2, 3 and 4
// threads) against CGAL's
// Delaunay_triangulation_2 (Epick), compared by DESIGN.md's rules: identical triangles where
// the Delaunay triangulation is unique; otherwise both exactly Delaunay, same vertex set, same
// triangle count and the same "strict" edges (hull edges and edges whose two triangles are not
// cocircular: exactly the edges every Delaunay triangulation of the points has).
#include <gtest/gtest.h>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <map>
#include <set>
#include <span>
#include <string>
#include <vector>

#include "generators/inputs/inputs.hpp"
#include "predicates/incircle.hpp"
#include "tests/support/test_scale.hpp"
#include "triangulation/checks/check_2d.hpp"
#include "triangulation/delaunay/bowyer_watson_2d.hpp"
#include "triangulation/delaunay/green_sibson_2d.hpp"
#include "triangulation/delaunay/tanemura_merriam_2d.hpp"

namespace tri = exactmesh::triangulation;
namespace gen = exactmesh::generators;

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<std::uint32_t, K>;
using Tds = CGAL::Triangulation_data_structure_2<Vb>;
using CgalDelaunay = CGAL::Delaunay_triangulation_2<K, Tds>;

using exactmesh::testing::test_scale;

/// CGAL's finite triangles, vertices mapped to our duplicate representatives.
std::vector<tri::VertIdx> cgal_triangles(const std::vector<double>& xy,
                                         const std::vector<tri::VertIdx>& merged_into) {
    std::vector<std::pair<K::Point_2, std::uint32_t>> points;
    for (std::uint32_t i = 0; i < xy.size() / 2; ++i) {
        points.emplace_back(K::Point_2(xy[2 * i], xy[2 * i + 1]), i);
    }
    CgalDelaunay dt(points.begin(), points.end());
    std::vector<tri::VertIdx> out;
    for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) {
        for (int k = 0; k < 3; ++k) out.push_back(merged_into[f->vertex(k)->info()]);
    }
    return out;
}

using Edge = std::pair<tri::VertIdx, tri::VertIdx>;
struct Summary {
    std::set<std::array<tri::VertIdx, 3>> triangles;  ///< rotated to the smallest vertex
    std::set<Edge> strict_edges;                      ///< hull edges + non-cocircular edges
    std::set<tri::VertIdx> vertices;
    bool unique = true;  ///< no interior edge with a cocircular quadrilateral
};

Summary summarize(const std::vector<double>& xy, const std::vector<tri::VertIdx>& t) {
    Summary s;
    std::map<Edge, tri::VertIdx> apex;  // directed edge -> opposite vertex
    for (std::size_t i = 0; i < t.size(); i += 3) {
        std::array<tri::VertIdx, 3> a{t[i], t[i + 1], t[i + 2]};
        for (unsigned k = 0; k < 3; ++k) {
            apex[{a[k], a[(k + 1) % 3]}] = a[(k + 2) % 3];
            s.vertices.insert(a[k]);
        }
        std::rotate(a.begin(), std::min_element(a.begin(), a.end()), a.end());
        s.triangles.insert(a);
    }
    for (const auto& [edge, c] : apex) {
        const auto it = apex.find({edge.second, edge.first});
        const Edge undirected = std::minmax(edge.first, edge.second);
        if (it == apex.end()) {
            s.strict_edges.insert(undirected);
            continue;
        }
        const double* p = xy.data();
        const auto sign = exactmesh::predicates::incircle(p + 2 * edge.first, p + 2 * edge.second,
                                                          p + 2 * c, p + 2 * it->second);
        if (sign == exactmesh::predicates::Sign::Zero) {
            s.unique = false;
        } else {
            s.strict_edges.insert(undirected);
        }
    }
    return s;
}

struct Algorithm {
    const char* name;
    tri::Delaunay2Function build;
};
/// Bowyer-Watson on `Threads` threads (parallel_bowyer_watson_2d.hpp), with parallel rounds from
/// 8 points per thread so that the campaign's small inputs run them too.
template <unsigned Threads>
tri::Delaunay2Result bowyer_watson_threads(std::span<const double> xy,
                                           const tri::Delaunay2Options& options) {
    tri::Delaunay2Options parallel = options;
    parallel.order = tri::InsertionOrder::Brio;
    parallel.threads = Threads;
    parallel.parallel_round_minimum = 8;
    return tri::bowyer_watson_2d(xy, parallel);
}

const Algorithm kAlgorithms[] = {{"bowyer-watson", &tri::bowyer_watson_2d},
                                 {"green-sibson", &tri::green_sibson_2d},
                                 {"tanemura-merriam", &tri::tanemura_merriam_2d},
                                 {"bowyer-watson --threads 2", &bowyer_watson_threads<2>},
                                 {"bowyer-watson --threads 3", &bowyer_watson_threads<3>},
                                 {"bowyer-watson --threads 4", &bowyer_watson_threads<4>}};

/// Compares every algorithm (in a seed-chosen order) with CGAL on xy; returns disagreements.
int compare_with_cgal(const std::vector<double>& xy, std::uint64_t seed, const std::string& label) {
    int disagreements = 0;
    const tri::InsertionOrder orders[] = {tri::InsertionOrder::Given, tri::InsertionOrder::Random,
                                          tri::InsertionOrder::Brio};
    std::vector<tri::VertIdx> cgal;
    Summary reference;
    bool have_reference = false;
    for (const Algorithm& algorithm : kAlgorithms) {
        const tri::Delaunay2Result ours = algorithm.build(xy, {orders[seed % 3], seed});
        if (!have_reference) {
            cgal = cgal_triangles(xy, ours.merged_into);
            reference = summarize(xy, cgal);
            have_reference = true;
        }
        const Summary mine = summarize(xy, ours.triangles);
        const tri::CheckReport check = tri::check_delaunay_2d(xy, ours.triangles);
        std::string problem;
        if (!check.ok) {
            problem = "not Delaunay: " + check.problem;
        } else if (reference.unique && mine.triangles != reference.triangles) {
            problem = "unique triangulation differs from CGAL's";
        } else if (ours.triangles.size() != cgal.size()) {
            problem = "triangle count " + std::to_string(ours.triangles.size() / 3) + " vs CGAL " +
                      std::to_string(cgal.size() / 3);
        } else if (mine.vertices != reference.vertices) {
            problem = "vertex sets differ";
        } else if (mine.strict_edges != reference.strict_edges) {
            problem = "strictly Delaunay edges differ";
        }
        if (!problem.empty()) {
            ++disagreements;
            ADD_FAILURE() << label << ", " << algorithm.name << " (seed " << seed
                          << "): " << problem;
        }
    }
    return disagreements;
}

}  // namespace

TEST(Differential_Delaunay2VsCgal, EverySubsetOfThe3x3Grid) {
    // All 466 subsets of at least 3 points of the 3 x 3 grid: collinear, cocircular, hull cases.
    int cases = 0, disagreements = 0;
    for (std::uint32_t mask = 0; mask < 512; ++mask) {
        if (__builtin_popcount(mask) < 3) continue;
        std::vector<double> xy;
        for (int k = 0; k < 9; ++k) {
            if (mask & (1u << k)) {
                xy.push_back(k % 3);
                xy.push_back(k / 3);
            }
        }
        disagreements += compare_with_cgal(xy, mask, "3x3 subset " + std::to_string(mask));
        ++cases;
    }
    EXPECT_EQ(cases, 466);
    EXPECT_EQ(disagreements, 0);
}

TEST(Differential_Delaunay2VsCgal, SeededCampaignOverAllDistributions) {
    // 9 distributions x seeds x sizes from 3 to ~2000 points.
    const int seeds = std::max(2, static_cast<int>(190 * test_scale()));
    int cases = 0, disagreements = 0;
    for (const gen::Distribution d : gen::kAllDistributions) {
        for (int seed = 0; seed < seeds; ++seed) {
            const std::uint32_t n =
                seed % 10 == 9 ? 2000u : 3u + static_cast<std::uint32_t>(seed * 37 % 300);
            const std::vector<double> xy =
                gen::generate_points_2d(d, n, static_cast<std::uint64_t>(seed));
            disagreements += compare_with_cgal(
                xy, static_cast<std::uint64_t>(seed),
                std::string(gen::distribution_name(d)) + " n=" + std::to_string(n));
            ++cases;
        }
    }
    std::printf("differential campaign: %d cases x 6 algorithm runs, %d disagreements\n", cases,
                disagreements);
    EXPECT_EQ(disagreements, 0);
}

TEST(Differential_Delaunay2VsCgal, DelaunatorCorpusFixtures) {
    // Point sets from ../shared/corpus/delaunator (JSON arrays of [x, y]).
    const char* files[] = {"issue13",     "issue43",     "issue44",     "robustness1",
                           "robustness2", "robustness3", "robustness4", "ukraine"};
    for (const char* name : files) {
        const std::string path =
            std::string(EXACTMESH_CORPUS_DIR) + "/delaunator/" + name + ".json";
        FILE* f = std::fopen(path.c_str(), "r");
        ASSERT_NE(f, nullptr) << "missing corpus file " << path;
        std::string text;
        for (int c; (c = std::fgetc(f)) != EOF;) text.push_back(static_cast<char>(c));
        std::fclose(f);
        std::vector<double> xy;
        for (std::size_t i = 0; i < text.size();) {
            const char c = text[i];
            if (c == '-' || c == '.' || (c >= '0' && c <= '9')) {
                std::size_t used = 0;
                xy.push_back(std::stod(text.substr(i, 64), &used));
                i += used;
            } else {
                ++i;
            }
        }
        ASSERT_EQ(xy.size() % 2, 0u) << path;
        EXPECT_EQ(compare_with_cgal(xy, 1, name), 0);
        EXPECT_EQ(compare_with_cgal(xy, 2, name), 0);
    }
}
