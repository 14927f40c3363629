// SPDX-License-Identifier: MIT
// Issue 11, crossings: every vertex where two input segments cross is the correctly rounded
// intersection of the two INPUT segments (not of pieces already bent by earlier roundings), in
// every recovery and at every scale; each segment stays a chain of pieces; the exact check passes.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <random>
#include <set>
#include <span>
#include <string>
#include <vector>

#include "base/errors.hpp"
#include "predicates/constructions.hpp"
#include "predicates/orient2d.hpp"
#include "triangulation/checks/check_constrained_2d.hpp"
#include "triangulation/constrained/constrained_2d.hpp"
#include "triangulation/constrained/constrained_triangulation_2d.hpp"

namespace tri = exactmesh::triangulation;
namespace pred = exactmesh::predicates;

namespace {

struct Pslg {
    std::vector<double> xy;
    std::vector<tri::VertIdx> segments;
    tri::Pslg view() const { return {xy, segments, {}, {}}; }
};

/// `count` long segments with random double endpoints on opposite sides of the unit square
/// (so that most pairs cross, at generic points), then every coordinate scaled by `scale` and
/// shifted by `shift` (both exact for the powers of two used, and the shift chosen so that the
/// segments keep their shape up to rounding of the endpoints alone).
Pslg long_segments(std::uint32_t seed, int count, double scale, double shift) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    Pslg p;
    for (int s = 0; s < count; ++s) {
        double x0, y0, x1, y1;
        if (s % 2 == 0) {
            x0 = 0.0 + 0.01 * unit(rng), y0 = unit(rng), x1 = 1.0 - 0.01 * unit(rng),
            y1 = unit(rng);
        } else {
            x0 = unit(rng), y0 = 0.0 + 0.01 * unit(rng), x1 = unit(rng),
            y1 = 1.0 - 0.01 * unit(rng);
        }
        for (const double c : {x0, y0, x1, y1}) p.xy.push_back(c * scale + shift);
        p.segments.push_back(2 * static_cast<tri::VertIdx>(s));
        p.segments.push_back(2 * static_cast<tri::VertIdx>(s) + 1);
    }
    return p;
}

/// ulps between two doubles of the same sign (0 when equal).
std::uint64_t ulps(double a, double b) {
    if (a == b) return 0;
    std::uint64_t n = 0;
    while (a != b && n < 1000000) {
        a = std::nextafter(a, b);
        ++n;
    }
    return n;
}

struct CrossingReport {
    std::size_t crossings = 0;  ///< added vertices on the chains of two crossing segments
    std::size_t wrong = 0;      ///< of those, not the correctly rounded input intersection
    std::uint64_t worst_ulps = 0;
    std::size_t shared_without_crossing =
        0;  ///< added vertices shared by segments that do not cross
    std::string first_problem;
};

/// Every added vertex on the pieces of two input segments that cross: it must be
/// segment_intersection_exact of the two. Pieces of one segment must form a chain.
CrossingReport crossings(const Pslg& in, const tri::Cdt2Result& r) {
    CrossingReport report;
    const std::size_t segments = in.segments.size() / 2;
    std::vector<std::set<tri::VertIdx>> on_segment(segments);
    std::vector<std::map<tri::VertIdx, int>> degree(segments);
    for (std::size_t p = 0; p < r.piece_segment.size(); ++p) {
        const std::uint32_t s = r.piece_segment[p];
        for (const tri::VertIdx v : {r.pieces[2 * p], r.pieces[2 * p + 1]}) {
            on_segment[s].insert(v);
            ++degree[s][v];
        }
    }
    // A chain: its two ends have degree 1, every other vertex degree 2.
    for (std::size_t s = 0; s < segments; ++s) {
        const tri::VertIdx a = r.merged_into[in.segments[2 * s]],
                           b = r.merged_into[in.segments[2 * s + 1]];
        for (const auto& [v, d] : degree[s]) {
            const int expected = v == a || v == b ? 1 : 2;
            if (d != expected && report.first_problem.empty()) {
                report.first_problem = "segment " + std::to_string(s) + ": vertex " +
                                       std::to_string(v) + " has " + std::to_string(d) + " pieces";
            }
        }
        if ((degree[s].count(a) == 0 || degree[s].count(b) == 0) && report.first_problem.empty()) {
            report.first_problem = "segment " + std::to_string(s) + " has no piece at an end";
        }
    }
    std::map<tri::VertIdx, std::vector<std::uint32_t>> segments_at;
    for (std::uint32_t s = 0; s < segments; ++s) {
        for (const tri::VertIdx v : on_segment[s]) {
            if (v >= r.input_vertex_count) segments_at[v].push_back(s);
        }
    }
    for (const auto& [v, list] : segments_at) {
        for (std::size_t i = 0; i < list.size(); ++i) {
            for (std::size_t j = i + 1; j < list.size(); ++j) {
                const double* a = &in.xy[2 * in.segments[2 * list[i]]];
                const double* b = &in.xy[2 * in.segments[2 * list[i] + 1]];
                const double* c = &in.xy[2 * in.segments[2 * list[j]]];
                const double* d = &in.xy[2 * in.segments[2 * list[j] + 1]];
                const pred::Sign sa = pred::orient2d(c, d, a), sb = pred::orient2d(c, d, b);
                const pred::Sign sc = pred::orient2d(a, b, c), sd = pred::orient2d(a, b, d);
                if (sa == sb || sc == sd) {
                    ++report.shared_without_crossing;
                    continue;
                }
                ++report.crossings;
                const auto exact = pred::segment_intersection_exact(a, b, c, d);
                const double* got = &r.mesh.xy[2 * v];
                if (got[0] != exact[0] || got[1] != exact[1]) {
                    ++report.wrong;
                    report.worst_ulps = std::max(
                        {report.worst_ulps, ulps(got[0], exact[0]), ulps(got[1], exact[1])});
                }
            }
        }
    }
    return report;
}

struct Scale {
    const char* name;
    double scale, shift;
};

}  // namespace

TEST(Issue11, issue_11_crossings) {
    // Long segments crossing at hundreds of generic points, at 1, 2^600, 2^-600 and near 1e182
    // (where the determinants' products overflow the double range) and with a shift that mixes
    // scales. Release: about a second in all.
    const Scale scales[] = {{"unit", 1.0, 0.0},
                            {"2^600", std::ldexp(1.0, 600), 0.0},
                            {"2^-600", std::ldexp(1.0, -600), 0.0},
                            {"1e182", std::ldexp(1.0, 600), 1e182},
                            {"mixed", 1e-150, 3e-151}};
    const tri::SegmentRecovery recoveries[] = {
        tri::SegmentRecovery::Swap, tri::SegmentRecovery::Cavity, tri::SegmentRecovery::Conforming};
    for (const std::uint32_t seed : {1u, 2u, 3u}) {
        for (const Scale& scale : scales) {
            const Pslg in = long_segments(seed, 48, scale.scale, scale.shift);
            std::size_t swap_crossings = 0;
            for (const tri::SegmentRecovery recovery : recoveries) {
                const std::string label = std::string(scale.name) + " seed " +
                                          std::to_string(seed) + " " +
                                          tri::segment_recovery_name(recovery);
                tri::Cdt2Options options;
                options.recovery = recovery;
                options.remove_exterior = false;
                const tri::Cdt2Result r = tri::constrained_delaunay_2d(in.view(), options);
                const auto check =
                    tri::check_constrained_delaunay_2d(r.mesh, r.input_vertex_count, in.segments);
                EXPECT_TRUE(check.ok) << label << ": " << check.problem;
                const CrossingReport report = crossings(in, r);
                // Generic crossings: no piece meets another where their input segments do not
                // cross.
                EXPECT_EQ(r.counters.bent_crossings, 0u) << label;
                EXPECT_TRUE(report.first_problem.empty()) << label << ": " << report.first_problem;
                EXPECT_EQ(report.wrong, 0u)
                    << label << ": " << report.wrong << " of " << report.crossings
                    << " crossings not correctly rounded, worst " << report.worst_ulps << " ulps";
                EXPECT_EQ(report.shared_without_crossing, 0u) << label;
                EXPECT_GT(report.crossings, 200u) << label;
                if (recovery == tri::SegmentRecovery::Swap) swap_crossings = report.crossings;
                if (recovery == tri::SegmentRecovery::Cavity) {
                    EXPECT_EQ(report.crossings, swap_crossings) << label;
                }
            }
        }
    }
}

TEST(Issue11, issue_11_crossings_near_one_point) {
    // A pencil: segments through points within a few ulps of one centre, so that their rounded
    // crossings coincide or lie beyond each other's pieces, and pieces bent by one rounding cross
    // where their input segments do not (the second rule of crossing_point, in
    // cdt_segment_recovery_2d.cpp). Every recovery must end with a valid constrained
    // triangulation (the exact check follows each segment's chain), swap and cavity with the same
    // triangles and vertices.
    std::uint64_t bent = 0;
    for (const std::uint32_t seed : {1u, 2u, 3u, 4u}) {
        for (const double scale : {1.0, std::ldexp(1.0, 600), std::ldexp(1.0, -600)}) {
            std::mt19937_64 rng(seed);
            std::uniform_real_distribution<double> angle(0.0, 3.14159);
            Pslg in;
            for (int s = 0; s < 24; ++s) {
                const double t = angle(rng);
                double cx = 1.0 / 3.0;
                const double cy = 2.0 / 7.0;
                for (int k = 0; k < s % 5; ++k) cx = std::nextafter(cx, 1.0);
                const double dx = std::cos(t), dy = std::sin(t);
                for (const double c : {cx - dx, cy - dy, cx + dx, cy + dy})
                    in.xy.push_back(c * scale);
                in.segments.push_back(2 * static_cast<tri::VertIdx>(s));
                in.segments.push_back(2 * static_cast<tri::VertIdx>(s) + 1);
            }
            std::vector<double> swap_xy;
            std::set<std::array<tri::VertIdx, 3>> swap_triangles;
            for (const tri::SegmentRecovery recovery :
                 {tri::SegmentRecovery::Swap, tri::SegmentRecovery::Cavity,
                  tri::SegmentRecovery::Conforming}) {
                const std::string label = "seed " + std::to_string(seed) + " scale 2^" +
                                          std::to_string(std::ilogb(scale)) + " " +
                                          tri::segment_recovery_name(recovery);
                tri::Cdt2Options options;
                options.recovery = recovery;
                options.remove_exterior = false;
                tri::Cdt2Result r;
                try {
                    r = tri::constrained_delaunay_2d(in.view(), options);
                } catch (const exactmesh::GeometryError& error) {
                    // Conforming may need pieces shorter than doubles resolve near the centre:
                    // then one clear error. Swap and cavity never stop.
                    EXPECT_EQ(recovery, tri::SegmentRecovery::Conforming)
                        << label << ": " << error.what();
                    const std::string what = error.what();
                    EXPECT_TRUE(what.find("too short to split") != std::string::npos ||
                                what.find("finer than double precision") != std::string::npos ||
                                what.find("splits; stopped") != std::string::npos)
                        << label << ": " << what;
                    continue;
                }
                const auto check =
                    tri::check_constrained_delaunay_2d(r.mesh, r.input_vertex_count, in.segments);
                EXPECT_TRUE(check.ok) << label << ": " << check.problem;
                bent += r.counters.bent_crossings;
                std::set<std::array<tri::VertIdx, 3>> triangles;
                for (std::size_t t = 0; t < r.mesh.triangles.size(); t += 3) {
                    std::array<tri::VertIdx, 3> v{r.mesh.triangles[t], r.mesh.triangles[t + 1],
                                                  r.mesh.triangles[t + 2]};
                    std::rotate(v.begin(), std::min_element(v.begin(), v.end()), v.end());
                    triangles.insert(v);
                }
                if (recovery == tri::SegmentRecovery::Swap) {
                    swap_xy = r.mesh.xy;
                    swap_triangles = triangles;
                } else if (recovery == tri::SegmentRecovery::Cavity) {
                    EXPECT_EQ(r.mesh.xy, swap_xy) << label;
                    EXPECT_TRUE(triangles == swap_triangles) << label;
                }
            }
        }
    }
    EXPECT_GT(bent, 0u);  // the second rule was exercised
}
