// SPDX-License-Identifier: MIT
// Differential campaign: our constrained Delaunay triangulation (swap and cavity recovery, and
// the conforming variant) against CGAL's Constrained_Delaunay_triangulation_2<Epick, Default,
// Exact_intersections_tag> (points, then constraints, through insert_constraints; the convex
// hull kept: remove_exterior = false). Rules (DESIGN.md "Output comparison against CGAL"):
//  - CDT (swap, cavity): the same vertex count, added intersection vertices included (matched
//    to CGAL's by coordinates: identical, or the nearest within kMaxUlps units in the last
//    place of the bounding box's largest magnitude, since CGAL's Epick intersection is a
//    double computation and ours is correctly rounded; the largest difference is reported);
//    the same triangle count and the same constrained edges. Where every unconstrained
//    interior edge of our output is strictly locally Delaunay (no cocircular tie) the
//    triangles are identical; otherwise both outputs pass check_constrained_delaunay_2d and
//    have the same strict edges (hull, constrained and strictly locally Delaunay edges, which
//    every constrained Delaunay triangulation of the PSLG contains).
//  - Swap and cavity: identical (the same vertices, triangles and constraint flags).
//  - Conforming: check_delaunay_2d (plain Delaunay) and every segment a chain of pieces.
#define CGAL_NO_CDT_2_WARNING  // Epick with Exact_intersections_tag warns on every intersection
#include <gtest/gtest.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "generators/inputs/inputs.hpp"
#include "generators/inputs/pslg_inputs.hpp"
#include "predicates/incircle.hpp"
#include "predicates/orient2d.hpp"
#include "tests/support/test_scale.hpp"
#include "triangulation/checks/check_2d.hpp"
#include "triangulation/checks/check_constrained_2d.hpp"
#include "triangulation/constrained/constrained_2d.hpp"

namespace tri = exactmesh::triangulation;
namespace gen = exactmesh::generators;

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Fb = CGAL::Constrained_triangulation_face_base_2<K>;
using Tds = CGAL::Triangulation_data_structure_2<CGAL::Triangulation_vertex_base_2<K>, Fb>;
using CgalCdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_intersections_tag>;

/// Added vertices may differ from CGAL's by this many units in the last place of the largest
/// coordinate magnitude of the input.
constexpr double kMaxUlps = 8;

using exactmesh::testing::test_scale;

using Edge = std::pair<tri::VertIdx, tri::VertIdx>;
using Triangle = std::array<tri::VertIdx, 3>;

Edge undirected(tri::VertIdx a, tri::VertIdx b) {
    return std::minmax(a, b);
}

struct Summary {
    std::set<Triangle> triangles;  ///< rotated to the smallest vertex
    std::set<Edge> constrained;
    std::set<Edge> strict;        ///< hull, constrained and strictly locally Delaunay edges
    std::map<Edge, Edge> apexes;  ///< unconstrained interior edge -> its two apexes
    bool unique = true;           ///< no unconstrained interior edge with a cocircular tie
};

/// The strict edges whose endpoints and (interior) apexes are all outside `moved`: their
/// incircle decision does not depend on a vertex whose coordinates differ between the outputs.
std::set<Edge> stable_strict(const Summary& s, const std::set<tri::VertIdx>& moved) {
    std::set<Edge> out;
    for (const Edge& e : s.strict) {
        if (moved.count(e.first) || moved.count(e.second)) continue;
        if (const auto it = s.apexes.find(e);
            it != s.apexes.end() &&
            (moved.count(it->second.first) || moved.count(it->second.second))) {
            continue;
        }
        out.insert(e);
    }
    return out;
}

Summary summarize(const tri::Triangulation2& m) {
    Summary s;
    for (tri::TriIdx t = 0; t < m.triangle_count(); ++t) {
        Triangle a{m.triangles[3 * t], m.triangles[3 * t + 1], m.triangles[3 * t + 2]};
        for (int k = 0; k < 3; ++k) {
            const tri::VertIdx u = a[static_cast<unsigned>(k)],
                               v = a[static_cast<unsigned>(k + 1) % 3];
            const tri::TriIdx n = m.neighbors[3 * t + static_cast<unsigned>(k)];
            if (m.is_constrained(t, k)) {
                s.constrained.insert(undirected(u, v));
                s.strict.insert(undirected(u, v));
                continue;
            }
            if (n == tri::kNone) {
                s.strict.insert(undirected(u, v));
                continue;
            }
            if (n < t) continue;
            tri::VertIdx apex = tri::kNone;
            for (unsigned j = 0; j < 3; ++j) {
                const tri::VertIdx w = m.triangles[3 * n + j];
                if (w != u && w != v) apex = w;
            }
            s.apexes[undirected(u, v)] = {a[static_cast<unsigned>(k + 2) % 3], apex};
            const auto sign = exactmesh::predicates::incircle(m.point(a[0]), m.point(a[1]),
                                                              m.point(a[2]), m.point(apex));
            if (sign == exactmesh::predicates::Sign::Zero) {
                s.unique = false;
            } else {
                s.strict.insert(undirected(u, v));
            }
        }
        std::rotate(a.begin(), std::min_element(a.begin(), a.end()), a.end());
        s.triangles.insert(a);
    }
    return s;
}

/// Distance in units in the last place of `scale` (a positive magnitude).
double ulps_apart(double a, double b, double scale) {
    const double ulp = std::nextafter(scale, INFINITY) - scale;
    return std::fabs(a - b) / ulp;
}

struct Campaign {
    int cases = 0;
    int disagreements = 0;
    int unique_cases = 0;
    int concurrent = 0;    ///< cases with an unrepresentable crossing of 3+ segments: validity only
    int cgal_invalid = 0;  ///< concurrent cases where CGAL's own output fails the exact check
    int cgal_skipped =
        0;  ///< hull segment through a vertex: ours checked, CGAL not run (it crashes)
    std::uint64_t moved_vertices = 0;  ///< added vertices CGAL placed elsewhere (within kMaxUlps)
    std::uint64_t added_vertices = 0;
    double max_ulps = 0;
};

/// CGAL's constrained Delaunay triangulation in our numbering: input vertices by their first
/// occurrence; CGAL's added vertices matched to ours (`ours`: our output) by coordinates, or
/// appended. Returns an empty problem string, or what failed.
std::string cgal_triangulation(const gen::PslgInput& in, const tri::Cdt2Result& ours,
                               tri::Triangulation2& out, double& max_ulps, int& dimension) {
    std::vector<K::Point_2> points;
    for (std::size_t i = 0; i < in.xy.size(); i += 2) points.emplace_back(in.xy[i], in.xy[i + 1]);
    std::vector<std::pair<std::size_t, std::size_t>> constraints;
    for (std::size_t s = 0; s < in.segments.size(); s += 2)
        constraints.emplace_back(in.segments[s], in.segments[s + 1]);
    CgalCdt cdt;
    // insert_constraints inserts nothing at all when there is no constraint.
    if (constraints.empty()) {
        cdt.insert(points.begin(), points.end());
    } else {
        cdt.insert_constraints(points.begin(), points.end(), constraints.begin(),
                               constraints.end());
    }
    dimension = cdt.dimension();

    double scale = 0;
    for (const double c : in.xy) scale = std::max(scale, std::fabs(c));
    if (scale == 0) scale = 1;
    std::map<std::pair<double, double>, tri::VertIdx> input_of;
    for (tri::VertIdx i = static_cast<tri::VertIdx>(in.xy.size() / 2); i-- > 0;)
        input_of[{in.xy[2 * i], in.xy[2 * i + 1]}] = i;
    out = tri::Triangulation2{};
    out.xy = ours.mesh.xy;
    const tri::VertIdx first_added = ours.input_vertex_count, ours_end = ours.mesh.vertex_count();
    std::vector<std::uint8_t> taken(ours_end, 0);
    std::map<CgalCdt::Vertex_handle, tri::VertIdx> index_of;
    for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
        const double x = v->point().x(), y = v->point().y();
        if (const auto it = input_of.find({x, y}); it != input_of.end()) {
            index_of[v] = it->second;
            continue;
        }
        tri::VertIdx best = tri::kNone;
        double best_ulps = kMaxUlps;
        for (tri::VertIdx w = first_added; w < ours_end; ++w) {
            if (taken[w]) continue;
            const double d = std::max(ulps_apart(x, ours.mesh.xy[2 * w], scale),
                                      ulps_apart(y, ours.mesh.xy[2 * w + 1], scale));
            if (d <= best_ulps) {
                best = w;
                best_ulps = d;
            }
        }
        if (best == tri::kNone) {
            best = out.vertex_count();
            out.xy.insert(out.xy.end(), {x, y});
        } else {
            taken[best] = 1;
            max_ulps = std::max(max_ulps, best_ulps);
            out.xy[2 * best] = x;
            out.xy[2 * best + 1] = y;
        }
        index_of[v] = best;
    }
    if (dimension < 2) return {};
    std::map<CgalCdt::Face_handle, tri::TriIdx> face_index;
    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
        face_index[f] = static_cast<tri::TriIdx>(face_index.size());
    }
    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
        for (int k = 0; k < 3; ++k) out.triangles.push_back(index_of.at(f->vertex(k)));
        for (int k = 0; k < 3; ++k) {
            // Our edge k (v[k], v[k+1]) is CGAL's edge opposite vertex k+2.
            const int opposite = (k + 2) % 3;
            const auto n = f->neighbor(opposite);
            out.neighbors.push_back(cdt.is_infinite(n) ? tri::kNone : face_index.at(n));
            out.constrained.push_back(f->is_constrained(opposite) ? 1 : 0);
        }
    }
    return {};
}

std::string describe(const std::set<Edge>& a, const std::set<Edge>& b) {
    std::string text;
    int shown = 0;
    for (const Edge& e : a) {
        if (b.count(e) || shown >= 4) continue;
        text += " (" + std::to_string(e.first) + "," + std::to_string(e.second) + ")";
        ++shown;
    }
    return text;
}

/// CGAL 5.5's Constrained_triangulation_2::insert_constraint (Exact_intersections_tag) crashes
/// (SIGSEGV; seen on the grid-lines distribution, seed 6) on some inputs with a segment along
/// the convex hull through an input vertex. True when the input has such a segment: ours is
/// still built and checked exactly, CGAL is not run.
bool has_hull_segment_through_vertex(const gen::PslgInput& in) {
    using exactmesh::predicates::Sign;
    const double* p = in.xy.data();
    const std::size_t n = in.xy.size() / 2;
    for (std::size_t s = 0; s < in.segments.size(); s += 2) {
        const double* a = p + 2 * in.segments[s];
        const double* b = p + 2 * in.segments[s + 1];
        if (a[0] == b[0] && a[1] == b[1]) continue;
        bool left = false, right = false, inside = false;
        for (std::size_t i = 0; i < n; ++i) {
            const double* c = p + 2 * i;
            const Sign sign = exactmesh::predicates::orient2d(a, b, c);
            left = left || sign == Sign::Positive;
            right = right || sign == Sign::Negative;
            if (sign == Sign::Zero) {
                const double t = (c[0] - a[0]) * (b[0] - a[0]) + (c[1] - a[1]) * (b[1] - a[1]);
                const double len = (b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]);
                inside = inside || (t > 0 && t < len && !(c[0] == b[0] && c[1] == b[1]));
            }
        }
        if (inside && !(left && right)) return true;
    }
    return false;
}

/// True when three or more segments cross at one point that no double represents (computed
/// exactly, CGAL's Epeck). Both libraries then place two or more nearby rounded vertices
/// where the exact arrangement has one, each by its own cascade of splits, so their vertex
/// counts may differ legitimately: only exact validity is compared for such cases.
bool has_unrepresentable_concurrent_crossing(const gen::PslgInput& in) {
    using Exact = CGAL::Exact_predicates_exact_constructions_kernel;
    std::vector<Exact::Segment_2> segments;
    for (std::size_t s = 0; s < in.segments.size(); s += 2) {
        const Exact::Point_2 a(in.xy[2 * in.segments[s]], in.xy[2 * in.segments[s] + 1]);
        const Exact::Point_2 b(in.xy[2 * in.segments[s + 1]], in.xy[2 * in.segments[s + 1] + 1]);
        if (a != b) segments.emplace_back(a, b);
    }
    std::vector<Exact::Point_2> crossings;
    for (std::size_t i = 0; i < segments.size(); ++i) {
        for (std::size_t j = i + 1; j < segments.size(); ++j) {
            const auto result = CGAL::intersection(segments[i], segments[j]);
            if (!result) continue;
            const Exact::Point_2* p = boost::get<Exact::Point_2>(&*result);
            if (p == nullptr) continue;
            const auto x = CGAL::to_interval(p->x()), y = CGAL::to_interval(p->y());
            if (x.first == x.second && y.first == y.second) continue;  // a double: no rounding
            if (std::find(crossings.begin(), crossings.end(), *p) != crossings.end()) return true;
            crossings.push_back(*p);
        }
    }
    return false;
}

tri::Cdt2Result build(const gen::PslgInput& in, tri::SegmentRecovery recovery, std::uint64_t seed) {
    tri::Cdt2Options options;
    options.recovery = recovery;
    options.remove_exterior = false;
    const tri::InsertionOrder orders[] = {tri::InsertionOrder::Brio, tri::InsertionOrder::Given,
                                          tri::InsertionOrder::Random};
    options.order = orders[seed % 3];
    options.seed = seed;
    return tri::constrained_delaunay_2d(tri::Pslg{in.xy, in.segments, {}, {}}, options);
}

/// One case: ours (three recoveries) against CGAL and each other. Adds to the campaign.
/// `conforming`: false where segments meet at angles of a few ulps (near-collinear input), which
/// midpoint splitting cannot resolve (it would need about 2^50 splits; ours stops with a
/// GeometryError after its budget, as documented).
void compare_case(const gen::PslgInput& in, std::uint64_t seed, const std::string& label,
                  Campaign& campaign, bool with_conforming = true) {
    ++campaign.cases;
    if (std::getenv("EXACTMESH_VERBOSE"))
        std::fprintf(stderr, "case %s (seed %llu)\n", label.c_str(),
                     static_cast<unsigned long long>(seed));
    std::string problem;
    auto fail = [&](const std::string& what) {
        if (problem.empty()) problem = what;
    };
    tri::Cdt2Result swap, cavity, conforming;
    try {
        swap = build(in, tri::SegmentRecovery::Swap, seed);
        cavity = build(in, tri::SegmentRecovery::Cavity, seed);
        if (with_conforming) conforming = build(in, tri::SegmentRecovery::Conforming, seed);
    } catch (const std::exception& e) {
        ++campaign.disagreements;
        ADD_FAILURE() << label << " (seed " << seed << "): ours threw: " << e.what();
        return;
    }
    const std::uint32_t n = static_cast<std::uint32_t>(in.xy.size() / 2);

    // Swap and cavity are identical.
    if (swap.mesh.xy != cavity.mesh.xy) fail("swap and cavity: vertices differ");
    const Summary ours = summarize(swap.mesh);
    const Summary other = summarize(cavity.mesh);
    if (ours.triangles != other.triangles) fail("swap and cavity: triangles differ");
    if (ours.constrained != other.constrained) fail("swap and cavity: constrained edges differ");

    // Exact validity of every output (the check follows a duplicate endpoint to its used copy).
    const std::vector<tri::VertIdx>& segments = in.segments;
    for (const tri::Cdt2Result* r : {&swap, &cavity, &conforming}) {
        if (r == &conforming && !with_conforming) continue;
        const auto report =
            tri::check_constrained_delaunay_2d(r->mesh, r->input_vertex_count, segments);
        if (!report.ok)
            fail(std::string(r == &conforming ? "conforming"
                             : r == &swap     ? "swap"
                                              : "cavity") +
                 " check: " + report.problem);
    }
    if (const auto report = tri::check_delaunay_2d(conforming.mesh.xy, conforming.mesh.triangles);
        with_conforming && !report.ok) {
        fail("conforming is not Delaunay: " + report.problem);
    }
    if (const auto report = tri::check_topology_2d(swap.mesh.xy, swap.mesh.triangles); !report.ok) {
        fail("swap topology: " + report.problem);
    }

    // CGAL.
    if (has_hull_segment_through_vertex(in)) {
        ++campaign.cgal_skipped;
        if (!problem.empty()) {
            ++campaign.disagreements;
            ADD_FAILURE() << label << " (seed " << seed << "): " << problem;
        }
        return;
    }
    tri::Triangulation2 cgal;
    double max_ulps = 0;
    int dimension = 0;
    cgal_triangulation(in, swap, cgal, max_ulps, dimension);
    campaign.max_ulps = std::max(campaign.max_ulps, max_ulps);
    campaign.added_vertices += swap.mesh.vertex_count() - swap.input_vertex_count;
    std::uint32_t distinct = 0;
    for (std::uint32_t i = 0; i < n; ++i) distinct += swap.merged_into[i] == i ? 1u : 0u;
    const std::uint32_t our_vertices =
        distinct + swap.mesh.vertex_count() - swap.input_vertex_count;
    // CGAL's vertex count: its input matches plus its added ones.
    std::set<tri::VertIdx> cgal_vertices;
    for (const tri::VertIdx v : cgal.triangles) cgal_vertices.insert(v);
    const bool concurrent =
        swap.counters.intersections > 1 && has_unrepresentable_concurrent_crossing(in);
    if (concurrent) {
        ++campaign.concurrent;
        // CGAL's double-precision intersections can invert triangles here (ours are checked
        // above); counted, not a disagreement.
        const auto report = tri::check_constrained_delaunay_2d(cgal, n, segments);
        if (dimension == 2 && !report.ok) ++campaign.cgal_invalid;
    } else if (dimension == 2) {
        std::set<tri::VertIdx> our_used(swap.mesh.triangles.begin(), swap.mesh.triangles.end());
        if (our_used.size() != our_vertices)
            fail("ours: " + std::to_string(our_vertices - our_used.size()) + " vertices unused");
        if (cgal_vertices.size() != our_vertices) {
            fail("vertex count " + std::to_string(our_vertices) + " vs CGAL " +
                 std::to_string(cgal_vertices.size()));
        } else if (cgal.vertex_count() != swap.mesh.vertex_count()) {
            fail("an added vertex of CGAL's is more than " + std::to_string(kMaxUlps) +
                 " ulps from ours");
        }
        const Summary theirs = summarize(cgal);
        if (swap.mesh.triangle_count() != cgal.triangle_count()) {
            fail("triangle count " + std::to_string(swap.mesh.triangle_count()) + " vs CGAL " +
                 std::to_string(cgal.triangle_count()));
        }
        if (ours.constrained != theirs.constrained) {
            fail("constrained edges differ: ours only" +
                 describe(ours.constrained, theirs.constrained) + "; CGAL only" +
                 describe(theirs.constrained, ours.constrained));
        }
        // Added vertices CGAL rounded differently: its triangles around them may differ.
        std::set<tri::VertIdx> moved;
        for (tri::VertIdx v = n; v < swap.mesh.vertex_count(); ++v) {
            if (cgal.xy[2 * v] != swap.mesh.xy[2 * v] ||
                cgal.xy[2 * v + 1] != swap.mesh.xy[2 * v + 1])
                moved.insert(v);
        }
        campaign.moved_vertices += moved.size();
        if (ours.unique && moved.empty()) {
            ++campaign.unique_cases;
            if (ours.triangles != theirs.triangles)
                fail("unique constrained Delaunay triangulation differs from CGAL's");
        } else {
            const auto report = tri::check_constrained_delaunay_2d(cgal, n, segments);
            if (!report.ok) fail("CGAL's output fails our check: " + report.problem);
            const std::set<Edge> mine = stable_strict(ours, moved),
                                 their = stable_strict(theirs, moved);
            std::set<Edge> ours_edges, cgal_edges;
            for (const Triangle& t : ours.triangles) {
                for (unsigned k = 0; k < 3; ++k)
                    ours_edges.insert(undirected(t[k], t[(k + 1) % 3]));
            }
            for (const Triangle& t : theirs.triangles) {
                for (unsigned k = 0; k < 3; ++k)
                    cgal_edges.insert(undirected(t[k], t[(k + 1) % 3]));
            }
            // Every edge strict in one output (away from moved vertices) is in the other.
            if (!std::includes(cgal_edges.begin(), cgal_edges.end(), mine.begin(), mine.end()) ||
                !std::includes(ours_edges.begin(), ours_edges.end(), their.begin(), their.end())) {
                fail("strict edges differ: ours only" + describe(mine, cgal_edges) + "; CGAL only" +
                     describe(their, ours_edges));
            }
        }
    } else if (swap.mesh.triangle_count() != 0) {
        fail("CGAL finds the input collinear, ours has triangles");
    }
    if (!problem.empty()) {
        ++campaign.disagreements;
        ADD_FAILURE() << label << " (seed " << seed << ", " << n << " points, "
                      << in.segments.size() / 2 << " segments): " << problem;
    }
}

gen::PslgInput scaled(gen::PslgInput in, int exponent) {
    for (double& c : in.xy) c = std::ldexp(c, exponent);
    return in;
}

void report(const char* name, const Campaign& c) {
    std::printf(
        "%s: %d cases (%d compared triangle for triangle; %d validity only: 3+ segments crossing "
        "at an "
        "unrepresentable point, where CGAL's output was invalid %d times; %d checked exactly "
        "without CGAL, which crashes on hull segments through vertices), %d disagreements, %llu "
        "added vertices (%llu rounded differently by CGAL), max added-vertex "
        "difference from CGAL %.3g ulps\n",
        name, c.cases, c.unique_cases, c.concurrent, c.cgal_invalid, c.cgal_skipped,
        c.disagreements, static_cast<unsigned long long>(c.added_vertices),
        static_cast<unsigned long long>(c.moved_vertices), c.max_ulps);
}

}  // namespace

TEST(Differential_Cdt2VsCgal, TinyPslgsEnumerated) {
    // Every segment subset of the first 3, 4 and 5 tiny points (8 + 64 + 1024 PSLGs: the
    // cocircular square, its centre on both diagonals, collinear overlaps, crossings at the
    // centre), then samples with 6..8 points (midpoints on the sides, one point outside).
    Campaign campaign;
    const double scale = test_scale();
    const auto stride = static_cast<std::uint64_t>(std::max(1.0, 1.0 / std::max(scale, 1e-6)));
    for (std::uint32_t v = 3; v <= 5; ++v) {
        for (std::uint64_t index = 0; index < gen::tiny_pslg_count(v); index += stride) {
            compare_case(gen::tiny_pslg(v, index), index,
                         "tiny " + std::to_string(v) + "/" + std::to_string(index), campaign);
        }
    }
    std::mt19937_64 rng(2024);
    const int samples = std::max(4, static_cast<int>(150 * scale));
    for (std::uint32_t v = 6; v <= 8; ++v) {
        for (int k = 0; k < samples; ++k) {
            const std::uint64_t index = rng() % gen::tiny_pslg_count(v);
            compare_case(gen::tiny_pslg(v, index), index,
                         "tiny " + std::to_string(v) + "/" + std::to_string(index), campaign);
        }
    }
    report("tiny PSLGs", campaign);
    EXPECT_EQ(campaign.disagreements, 0);
}

TEST(Differential_Cdt2VsCgal, SeededCampaignOverAllPslgDistributions) {
    // Every PSLG distribution, seeds x sizes from 10 to ~600 points, at unit scale and (every
    // third seed) scaled by 2^500 (~3e150) or 2^-500 (~3e-151), exactly.
    Campaign campaign;
    const int seeds = std::max(2, static_cast<int>(80 * test_scale()));
    for (const gen::PslgDistribution d : gen::kAllPslgDistributions) {
        for (int seed = 0; seed < seeds; ++seed) {
            const std::uint32_t n =
                seed % 10 == 9 ? 600u : 10u + static_cast<std::uint32_t>(seed * 37 % 200);
            std::uint32_t segments = 3 + static_cast<std::uint32_t>(seed * 13 % 80);
            if (d == gen::PslgDistribution::Crossing || d == gen::PslgDistribution::NearCollinear) {
                segments = 2 + static_cast<std::uint32_t>(seed % 12);
            }
            gen::PslgInput in =
                gen::generate_pslg(d, n, segments, static_cast<std::uint64_t>(seed));
            std::string label = std::string(gen::pslg_distribution_name(d));
            if (seed % 3 == 1) {
                in = scaled(std::move(in), 500);
                label += " x2^500";
            } else if (seed % 3 == 2 && seed % 2 == 0) {
                in = scaled(std::move(in), -500);
                label += " x2^-500";
            }
            compare_case(in, static_cast<std::uint64_t>(seed), label, campaign,
                         d != gen::PslgDistribution::NearCollinear);
        }
    }
    report("seeded PSLG campaign", campaign);
    EXPECT_EQ(campaign.disagreements, 0);
}
