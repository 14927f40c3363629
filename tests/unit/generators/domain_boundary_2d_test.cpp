// SPDX-License-Identifier: MIT
// The discretized domain boundary: pieces no longer than a uniform size, the front oriented with
// the domain on its left (exact point-in-domain tests on either side of every front edge), slits
// in both directions, holes outside, the CDT's pieces kept when the size is unbounded, curved
// sample domains; domain_mesh_result assembles a valid mesh; bad input raises InputError. On
// grid lines with rounded crossings one ulp from lattice vertices, a vertex one ulp from a piece,
// and 210 random PSLGs of every distribution at three sizes, the boundary is exactly valid
// (boundary_problem): pieces meet only at shared ends, each CDT piece is a chain, new points in
// the domain, every front edge has a domain triangle on its left.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "base/errors.hpp"
#include "generators/boundary/domain_boundary_2d.hpp"
#include "generators/boundary/sample_domains.hpp"
#include "generators/inputs/pslg_inputs.hpp"
#include "generators/mesh_2d/domain_mesh_2d.hpp"
#include "predicates/orient2d.hpp"
#include "tests/support/pslg_fixtures_2d.hpp"
#include "triangulation/checks/check_conforming_2d.hpp"

namespace gen = exactmesh::generators;
namespace tri = exactmesh::triangulation;

namespace {

using exactmesh::testing::Input;
using exactmesh::testing::square_with_hole_and_slit;

double length(const gen::DomainBoundary2& b, tri::VertIdx u, tri::VertIdx v) {
    return std::hypot(b.xy[2 * v] - b.xy[2 * u], b.xy[2 * v + 1] - b.xy[2 * u + 1]);
}

TEST(DomainBoundary2, PiecesFollowAUniformSizeAndTheFrontHasTheDomainOnItsLeft) {
    const Input in = square_with_hole_and_slit();
    const double h = 0.07;
    const gen::DomainBoundary2 b =
        gen::discretize_domain_boundary(in.pslg(), gen::SizeFunction::uniform(h));
    EXPECT_EQ(b.input_vertex_count, 10u);
    ASSERT_EQ(b.pieces.size() / 2, b.piece_segment.size());
    ASSERT_EQ(b.front.size() / 2, b.front_segment.size());
    // Outer sides (length 1): 15 pieces each (1 / 0.07 = 14.3); hole sides (0.2): 3; slit (0.2): 3.
    EXPECT_EQ(b.pieces.size() / 2, 4u * 15 + 4 * 3 + 3);
    // Every piece is the size or shorter, and no shorter than half of it here.
    for (std::size_t p = 0; p < b.piece_segment.size(); ++p) {
        const double l = length(b, b.pieces[2 * p], b.pieces[2 * p + 1]);
        EXPECT_LE(l, h * (1 + 1e-12));
        EXPECT_GE(l, 0.5 * h);
    }
    // Front: outer and hole pieces once, slit pieces twice.
    EXPECT_EQ(b.front.size() / 2, 4u * 15 + 4 * 3 + 2 * 3);
    std::size_t slit_edges = 0;
    for (std::size_t e = 0; e < b.front_segment.size(); ++e) {
        const double* p = &b.xy[2 * b.front[2 * e]];
        const double* q = &b.xy[2 * b.front[2 * e + 1]];
        const double mx = 0.5 * (p[0] + q[0]), my = 0.5 * (p[1] + q[1]);
        const double nx = -(q[1] - p[1]), ny = q[0] - p[0];  // left normal, |n| = piece length
        EXPECT_TRUE(gen::in_domain(b, mx + 0.1 * nx, my + 0.1 * ny)) << "front edge " << e;
        if (b.front_segment[e] == 8) {
            ++slit_edges;
            EXPECT_TRUE(gen::in_domain(b, mx - 0.1 * nx, my - 0.1 * ny));
        } else {
            EXPECT_FALSE(gen::in_domain(b, mx - 0.1 * nx, my - 0.1 * ny)) << "front edge " << e;
        }
    }
    EXPECT_EQ(slit_edges, 6u);
    EXPECT_FALSE(gen::in_domain(b, 0.5, 0.5));  // the hole
    EXPECT_FALSE(gen::in_domain(b, 1.5, 0.5));  // outside
    EXPECT_TRUE(gen::in_domain(b, 0, 0));       // closed
    EXPECT_TRUE(gen::in_domain(b, 0.2, 0.2));
}

TEST(DomainBoundary2, GradedSizesGiveShorterPiecesWhereTheSizeIsSmall) {
    const Input in = square_with_hole_and_slit();
    const auto size = gen::SizeFunction::sources({{0, 0, 0.01, 0.1, 1}}, {}, 0.2);
    const gen::DomainBoundary2 b = gen::discretize_domain_boundary(in.pslg(), size);
    for (std::size_t p = 0; p < b.piece_segment.size(); ++p) {
        const tri::VertIdx u = b.pieces[2 * p], v = b.pieces[2 * p + 1];
        const double mx = 0.5 * (b.xy[2 * u] + b.xy[2 * v]),
                     my = 0.5 * (b.xy[2 * u + 1] + b.xy[2 * v + 1]);
        // Integral of ds / s at most 1 per piece: the length is at most the largest size along it
        // (the size grows by at most the piece's length times its gradient, 0.1 here).
        EXPECT_LE(length(b, u, v), size(mx, my) * 1.2) << "piece " << p;
    }
    // Near the source corner the pieces are about 0.01.
    double shortest = 1;
    for (std::size_t p = 0; p < b.piece_segment.size(); ++p)
        shortest = std::min(shortest, length(b, b.pieces[2 * p], b.pieces[2 * p + 1]));
    EXPECT_LT(shortest, 0.015);
}

TEST(DomainBoundary2, UnboundedSizeKeepsTheCdtPiecesAndTheResultIsAValidMesh) {
    const Input in = square_with_hole_and_slit();
    const gen::DomainBoundary2 b = gen::discretize_domain_boundary(in.pslg(), gen::SizeFunction());
    EXPECT_EQ(b.xy, b.cdt.mesh.xy);
    EXPECT_EQ(b.pieces, b.cdt.pieces);
    const tri::Cdt2Result r = gen::domain_mesh_result(b, b.xy, b.cdt.mesh.triangles);
    EXPECT_EQ(r.mesh.neighbors, b.cdt.mesh.neighbors);
    EXPECT_EQ(r.mesh.constrained, b.cdt.mesh.constrained);
    const auto report =
        tri::check_conforming_mesh_2d(r.mesh, r.input_vertex_count, in.segments, r.pieces);
    EXPECT_TRUE(report.ok) << report.problem;
    // A repeated directed edge is an internal error.
    std::vector<tri::VertIdx> twice = b.cdt.mesh.triangles;
    twice.insert(twice.end(), twice.begin(), twice.begin() + 3);
    EXPECT_THROW(gen::domain_mesh_result(b, b.xy, twice), exactmesh::InternalError);
}

TEST(DomainBoundary2, SampleDomainsKeepCurvedPointsAndCrossingSegmentsAreSplit) {
    for (const gen::SampleDomain d : gen::kAllSampleDomains) {
        const gen::DomainPslg domain = gen::sample_domain(d);
        const tri::Pslg pslg{domain.xy, domain.segments, domain.holes, {}};
        const gen::DomainBoundary2 b =
            gen::discretize_domain_boundary(pslg, gen::sample_domain_size(d));
        // The curve points are input vertices: kept with their numbers and coordinates.
        for (std::size_t i = 0; i < domain.xy.size(); ++i) EXPECT_EQ(b.xy[i], domain.xy[i]);
        EXPECT_GE(b.front.size(), domain.segments.size());
    }
    // Two crossing segments inside a square: split at their crossing (a warning), front both ways.
    Input in;
    in.xy = {0, 0, 4, 0, 4, 4, 0, 4, 1, 1, 3, 3, 1, 3, 3, 1};
    in.segments = {0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 6, 7};
    const gen::DomainBoundary2 b =
        gen::discretize_domain_boundary(in.pslg(), gen::SizeFunction::uniform(0.5));
    EXPECT_FALSE(b.cdt.warnings.empty());
    EXPECT_GT(b.xy.size() / 2, 8u);
}

using exactmesh::predicates::Sign;

Sign orient(const double* a, const double* b, const double* c) {
    return exactmesh::predicates::orient2d(a, b, c);
}

/// p lies on the closed segment a - b (exact).
bool on_segment(const double* a, const double* b, const double* p) {
    return orient(a, b, p) == Sign::Zero && std::min(a[0], b[0]) <= p[0] &&
           p[0] <= std::max(a[0], b[0]) && std::min(a[1], b[1]) <= p[1] &&
           p[1] <= std::max(a[1], b[1]);
}

/// The closed segments p - q and r - s share a point (exact).
bool segments_meet(const double* p, const double* q, const double* r, const double* s) {
    const Sign o1 = orient(p, q, r), o2 = orient(p, q, s), o3 = orient(r, s, p),
               o4 = orient(r, s, q);
    if (o1 != Sign::Zero && o2 != Sign::Zero && o3 != Sign::Zero && o4 != Sign::Zero)
        return o1 != o2 && o3 != o4;
    return on_segment(p, q, r) || on_segment(p, q, s) || on_segment(r, s, p) || on_segment(r, s, q);
}

/// p in the closed triangle (a, b, c), counter-clockwise (exact).
bool in_closed_triangle(const double* a, const double* b, const double* c, const double* p) {
    return orient(a, b, p) != Sign::Negative && orient(b, c, p) != Sign::Negative &&
           orient(c, a, p) != Sign::Negative;
}

/// Exact validity of a discretized boundary; an empty string when valid, else the first problem:
///  - the pieces form a PSLG: no two vertices at one point, two pieces meet only at a shared
///    end (and then do not overlap);
///  - each piece a - b of the CDT is replaced by one chain of pieces of its segment from a to b
///    through new points only, every boundary piece in exactly one chain, every new point in the
///    domain (in_domain) and in the closed domain triangles beside its CDT piece;
///  - the front holds each chain edge in the direction a -> b when the domain triangle (a, b, c)
///    is on the left of a -> b, the reverse when one is on its right, and nothing else; an edge
///    u -> w in a triangle (a, b, c) has c strictly on its left, so the open triangle (u, w, c),
///    part of the domain, is on its left (a slit's edges may cross from one of its triangles to
///    the other: the domain is on both sides);
///  - every vertex has as many front edges leaving as entering it (closed loops).
std::string boundary_problem(const gen::DomainBoundary2& b) {
    const tri::Triangulation2& mesh = b.cdt.mesh;
    const std::size_t old_vertices = mesh.vertex_count(), vertices = b.xy.size() / 2;
    const std::size_t piece_count = b.pieces.size() / 2;
    if (b.piece_segment.size() != piece_count || b.front_segment.size() != b.front.size() / 2)
        return "field sizes";
    for (std::size_t i = 0; i < mesh.xy.size(); ++i)
        if (b.xy[i] != mesh.xy[i]) return "a CDT vertex moved";
    auto at = [&](tri::VertIdx v) { return &b.xy[2 * std::size_t{v}]; };
    // Distinct points.
    std::vector<tri::VertIdx> used(b.pieces.begin(), b.pieces.end());
    std::sort(used.begin(), used.end());
    used.erase(std::unique(used.begin(), used.end()), used.end());
    std::sort(used.begin(), used.end(), [&](tri::VertIdx u, tri::VertIdx v) {
        return std::pair(at(u)[0], at(u)[1]) < std::pair(at(v)[0], at(v)[1]);
    });
    for (std::size_t i = 0; i + 1 < used.size(); ++i) {
        if (at(used[i])[0] == at(used[i + 1])[0] && at(used[i])[1] == at(used[i + 1])[1])
            return "vertices " + std::to_string(used[i]) + " and " + std::to_string(used[i + 1]) +
                   " coincide";
    }
    // Pairwise: a sweep over the pieces sorted by their smallest x.
    std::vector<std::size_t> order(piece_count);
    for (std::size_t p = 0; p < piece_count; ++p) order[p] = p;
    auto low = [&](std::size_t p) {
        return std::min(at(b.pieces[2 * p])[0], at(b.pieces[2 * p + 1])[0]);
    };
    auto high = [&](std::size_t p) {
        return std::max(at(b.pieces[2 * p])[0], at(b.pieces[2 * p + 1])[0]);
    };
    std::sort(order.begin(), order.end(),
              [&](std::size_t p, std::size_t q) { return low(p) < low(q); });
    for (std::size_t i = 0; i < piece_count; ++i) {
        const std::size_t p = order[i];
        const tri::VertIdx p0 = b.pieces[2 * p], p1 = b.pieces[2 * p + 1];
        for (std::size_t j = i + 1; j < piece_count && low(order[j]) <= high(p); ++j) {
            const std::size_t q = order[j];
            const tri::VertIdx q0 = b.pieces[2 * q], q1 = b.pieces[2 * q + 1];
            const int shared = (p0 == q0) + (p0 == q1) + (p1 == q0) + (p1 == q1);
            bool bad;
            if (shared >= 2) {
                bad = true;
            } else if (shared == 1) {
                const tri::VertIdx x = (p0 == q0 || p0 == q1) ? p1 : p0,
                                   y = (q0 == p0 || q0 == p1) ? q1 : q0;
                bad = on_segment(at(q0), at(q1), at(x)) || on_segment(at(p0), at(p1), at(y));
            } else {
                bad = segments_meet(at(p0), at(p1), at(q0), at(q1));
            }
            if (bad)
                return "pieces " + std::to_string(p0) + " - " + std::to_string(p1) + " and " +
                       std::to_string(q0) + " - " + std::to_string(q1) + " meet";
        }
    }
    // Chains: each CDT piece a - z of segment s is a path of pieces of s from a to z through new
    // points and vertices that end no CDT piece of s (where the chain bends around a sliver).
    std::vector<std::vector<std::size_t>> at_vertex(vertices);
    for (std::size_t p = 0; p < piece_count; ++p) {
        at_vertex[b.pieces[2 * p]].push_back(p);
        at_vertex[b.pieces[2 * p + 1]].push_back(p);
    }
    for (std::size_t v = old_vertices; v < vertices; ++v)
        if (at_vertex[v].size() != 2) return "new point " + std::to_string(v) + " not on 2 pieces";
    std::map<std::pair<tri::VertIdx, tri::VertIdx>, tri::VertIdx> third;  // directed edge -> c
    std::vector<std::vector<tri::TriIdx>> triangles_at(old_vertices);
    for (tri::TriIdx t = 0; t < mesh.triangle_count(); ++t) {
        for (unsigned k = 0; k < 3; ++k) {
            third[{mesh.triangles[3 * t + k], mesh.triangles[3 * t + (k + 1) % 3]}] =
                mesh.triangles[3 * t + (k + 2) % 3];
            triangles_at[mesh.triangles[3 * t + k]].push_back(t);
        }
    }
    std::set<std::pair<tri::VertIdx, std::uint32_t>> piece_ends;  // (vertex, segment)
    for (std::size_t cp = 0; 2 * cp + 1 < b.cdt.pieces.size(); ++cp) {
        piece_ends.insert({b.cdt.pieces[2 * cp], b.cdt.piece_segment[cp]});
        piece_ends.insert({b.cdt.pieces[2 * cp + 1], b.cdt.piece_segment[cp]});
    }
    std::multiset<std::pair<tri::VertIdx, tri::VertIdx>> expected_front;
    std::vector<int> piece_uses(piece_count, 0);
    for (std::size_t cp = 0; 2 * cp + 1 < b.cdt.pieces.size(); ++cp) {
        const tri::VertIdx a = b.cdt.pieces[2 * cp], z = b.cdt.pieces[2 * cp + 1];
        const std::uint32_t segment = b.cdt.piece_segment[cp];
        const std::string name = "CDT piece " + std::to_string(a) + " - " + std::to_string(z);
        // Depth-first search for the path (the pieces of s at a bend vertex: at most a few).
        std::vector<tri::VertIdx> chain;
        std::vector<std::size_t> chain_pieces;
        std::vector<tri::VertIdx> path{a};
        std::vector<std::size_t> path_pieces;
        std::function<bool(tri::VertIdx)> search = [&](tri::VertIdx v) {
            if (v == z) return true;
            if (v != a && v < old_vertices && piece_ends.count({v, segment})) return false;
            for (const std::size_t p : at_vertex[v]) {
                if (b.piece_segment[p] != segment || piece_uses[p] != 0) continue;
                if (std::find(path_pieces.begin(), path_pieces.end(), p) != path_pieces.end())
                    continue;
                const tri::VertIdx w = b.pieces[2 * p] == v ? b.pieces[2 * p + 1] : b.pieces[2 * p];
                if (std::find(path.begin(), path.end(), w) != path.end()) continue;
                path.push_back(w);
                path_pieces.push_back(p);
                if (search(w)) return true;
                path.pop_back();
                path_pieces.pop_back();
            }
            return false;
        };
        if (!search(a)) return name + ": no chain from a to b";
        chain = path;
        chain_pieces = path_pieces;
        for (const std::size_t p : chain_pieces) ++piece_uses[p];
        const auto left = third.find({a, z}), right = third.find({z, a});
        auto in_triangle = [&](tri::TriIdx t, tri::VertIdx v) {
            const tri::VertIdx* c = &mesh.triangles[3 * std::size_t{t}];
            return in_closed_triangle(at(c[0]), at(c[1]), at(c[2]), at(v));
        };
        // The domain on the left of u -> w: a domain triangle at one of the chain's CDT vertices
        // holds u and w, and one of its corners lies strictly on the left.
        auto domain_on_left = [&](tri::VertIdx u, tri::VertIdx w) {
            for (const tri::VertIdx x : chain) {
                if (x >= old_vertices) continue;
                for (const tri::TriIdx t : triangles_at[x]) {
                    if (!in_triangle(t, u) || !in_triangle(t, w)) continue;
                    for (unsigned k = 0; k < 3; ++k)
                        if (orient(at(u), at(w), at(mesh.triangles[3 * std::size_t{t} + k])) ==
                            Sign::Positive)
                            return true;
                }
            }
            return false;
        };
        for (std::size_t k = 1; k + 1 < chain.size(); ++k) {
            const tri::VertIdx v = chain[k];
            if (v >= old_vertices && !gen::in_domain(b, at(v)[0], at(v)[1]))
                return name + ": new point " + std::to_string(v) + " outside the domain";
        }
        const bool slit = left != third.end() && right != third.end();
        for (std::size_t k = 0; k + 1 < chain.size(); ++k) {
            const tri::VertIdx u = chain[k], w = chain[k + 1];
            const std::string edge = std::to_string(u) + " - " + std::to_string(w);
            if (left != third.end()) expected_front.insert({u, w});
            if (right != third.end()) expected_front.insert({w, u});
            if (left == third.end() && right == third.end()) continue;  // outside the domain
            if (!slit) {
                const bool forward = left != third.end();
                if ((forward && !domain_on_left(u, w)) || (!forward && !domain_on_left(w, u)))
                    return name + ": front edge " + edge + " without the domain on its left";
                continue;
            }
            // A slit: its points in its two triangles; an edge within one of them has the
            // triangle's third vertex strictly on its side (an edge may cross from one to the
            // other: the domain is on both sides).
            auto in_left = [&](tri::VertIdx v) {
                return in_closed_triangle(at(a), at(z), at(left->second), at(v));
            };
            auto in_right = [&](tri::VertIdx v) {
                return in_closed_triangle(at(z), at(a), at(right->second), at(v));
            };
            for (const tri::VertIdx v : {u, w})
                if (!in_left(v) && !in_right(v))
                    return name + ": slit point " + std::to_string(v) + " outside its triangles";
            if (in_left(u) && in_left(w) &&
                orient(at(u), at(w), at(left->second)) != Sign::Positive)
                return name + ": slit edge " + edge + " folds over its left triangle";
            if (in_right(u) && in_right(w) &&
                orient(at(u), at(w), at(right->second)) != Sign::Negative)
                return name + ": slit edge " + edge + " folds over its right triangle";
        }
    }
    for (std::size_t p = 0; p < piece_count; ++p)
        if (piece_uses[p] != 1) return "piece " + std::to_string(p) + " in no chain or in two";
    std::multiset<std::pair<tri::VertIdx, tri::VertIdx>> front;
    std::vector<int> balance(vertices, 0);
    for (std::size_t e = 0; 2 * e + 1 < b.front.size(); ++e) {
        front.insert({b.front[2 * e], b.front[2 * e + 1]});
        ++balance[b.front[2 * e]];
        --balance[b.front[2 * e + 1]];
    }
    if (front != expected_front) return "the front is not the chains' directed edges";
    for (std::size_t v = 0; v < vertices; ++v)
        if (balance[v] != 0) return "front vertex " + std::to_string(v) + " unbalanced";
    return "";
}

gen::PslgInput sweep_input(gen::PslgDistribution d, std::uint64_t seed) {
    return gen::generate_pslg(d, 60 + 20 * static_cast<std::uint32_t>(seed % 5), 30, seed);
}

double extent_of(const std::vector<double>& xy) {
    double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
    for (std::size_t i = 0; i + 1 < xy.size(); i += 2) {
        x0 = std::min(x0, xy[i]), x1 = std::max(x1, xy[i]);
        y0 = std::min(y0, xy[i + 1]), y1 = std::max(y1, xy[i + 1]);
    }
    return std::max(x1 - x0, y1 - y0);
}

TEST(DomainBoundary2, GridLinesBesideFeaturesAtTheResolutionOfDoublesStayAValidPslg) {
    // Rounded crossings one ulp from lattice vertices: the seeds whose rounded split points
    // landed on other pieces (the advancing-front-Delaunay generator refused them).
    for (const std::uint64_t seed : {11, 14, 16, 25, 41, 54}) {
        const gen::PslgInput p = sweep_input(gen::PslgDistribution::GridLines, seed);
        const tri::Pslg pslg{p.xy, p.segments, p.holes, {}};
        const gen::DomainBoundary2 b =
            gen::discretize_domain_boundary(pslg, gen::SizeFunction::uniform(extent_of(p.xy) / 30));
        EXPECT_GT(b.xy.size(), b.cdt.mesh.xy.size()) << "seed " << seed;
        EXPECT_EQ(boundary_problem(b), "") << "seed " << seed;
    }
}

TEST(DomainBoundary2, AVertexUlpsFromAPieceBendsItsChain) {
    // Vertex 4 one ulp above the skew side (0, 0) - (1, 0.3), inside the domain: the CDT's
    // triangle beside that side is a sliver one ulp thick, too thin for the split points rounded
    // off the line, so the chain bends at vertex 4 (the sliver left out) and every piece keeps
    // the size. One ulp below it (outside the domain) the pieces stay on the domain's side.
    for (const double y : {std::nextafter(0.15, 1.0), std::nextafter(0.15, 0.0)}) {
        Input in;
        in.xy = {0, 0, 1, 0.3, 1, 1, 0, 1, 0.5, y};
        in.segments = {0, 1, 1, 2, 2, 3, 3, 0};
        const double h = 0.05;
        const gen::DomainBoundary2 b =
            gen::discretize_domain_boundary(in.pslg(), gen::SizeFunction::uniform(h));
        EXPECT_EQ(boundary_problem(b), "") << y;
        bool through_vertex = false;
        double longest = 0;
        for (std::size_t p = 0; p < b.piece_segment.size(); ++p) {
            through_vertex |= b.pieces[2 * p] == 4 || b.pieces[2 * p + 1] == 4;
            longest = std::max(longest, length(b, b.pieces[2 * p], b.pieces[2 * p + 1]));
        }
        EXPECT_EQ(through_vertex, y > 0.15) << y;
        EXPECT_LE(longest, h * (1 + 1e-12)) << y;
        EXPECT_EQ(b.front.size() / 2, b.piece_segment.size());
    }
}

TEST(DomainBoundary2, RandomPslgsGiveValidBoundariesAtEverySize) {
    // Every distribution (crossings, overlaps, duplicates, dangling segments, near-collinear
    // segments ulps apart), ten seeds each, three uniform sizes: 210 PSLGs.
    std::size_t checked = 0;
    for (const auto d : gen::kAllPslgDistributions) {
        for (std::uint64_t seed = 1; seed <= 10; ++seed) {
            const gen::PslgInput p = sweep_input(d, seed);
            const double extent = extent_of(p.xy);
            const tri::Pslg pslg{p.xy, p.segments, p.holes, {}};
            for (const double parts : {8.0, 30.0, 100.0}) {
                const std::string name = std::string(gen::pslg_distribution_name(d)) + " seed " +
                                         std::to_string(seed) + " size extent/" +
                                         std::to_string(static_cast<int>(parts));
                try {
                    const gen::DomainBoundary2 b = gen::discretize_domain_boundary(
                        pslg, gen::SizeFunction::uniform(extent / parts));
                    EXPECT_EQ(boundary_problem(b), "") << name;
                    ++checked;
                } catch (const exactmesh::InputError&) {
                    // Nothing enclosed (chains without a closed loop).
                }
            }
        }
    }
    EXPECT_GT(checked, 150u);
}

TEST(DomainBoundary2, BadInputIsAnInputError) {
    Input nan = square_with_hole_and_slit();
    nan.xy[3] = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(gen::discretize_domain_boundary(nan.pslg(), gen::SizeFunction::uniform(0.1)),
                 exactmesh::InputError);
    Input open;  // a polyline encloses nothing
    open.xy = {0, 0, 1, 0, 1, 1};
    open.segments = {0, 1, 1, 2};
    EXPECT_THROW(gen::discretize_domain_boundary(open.pslg(), gen::SizeFunction::uniform(0.1)),
                 exactmesh::InputError);
    // A size asking for more than 2^30 pieces.
    const Input square = square_with_hole_and_slit();
    EXPECT_THROW(gen::discretize_domain_boundary(square.pslg(), gen::SizeFunction::uniform(1e-12)),
                 exactmesh::InputError);
}

}  // namespace

TEST(DomainBoundary2, SizeFromBoundaryFollowsTheInputSpacing) {
    // The unit square with its bottom side in ten segments of 0.1: the bottom's inner vertices
    // get 0.1, its corners the mean of 0.1 and 1, the top corners 1; linear in between.
    Input in;
    for (int i = 0; i <= 10; ++i) in.xy.insert(in.xy.end(), {0.1 * i, 0.0});
    in.xy.insert(in.xy.end(), {1, 1, 0, 1});
    for (std::uint32_t i = 0; i < 10; ++i) in.segments.insert(in.segments.end(), {i, i + 1});
    in.segments.insert(in.segments.end(), {10, 11, 11, 12, 12, 0});
    const gen::SizeFunction size = gen::size_from_boundary(in.pslg());
    ASSERT_TRUE(size.bounded());
    EXPECT_NEAR(size(0.5, 0), 0.1, 1e-12);
    EXPECT_NEAR(size(0.25, 0), 0.1, 1e-12);
    EXPECT_NEAR(size(0, 0), 0.55, 1e-12);
    EXPECT_NEAR(size(1, 1), 1.0, 1e-12);
    EXPECT_NEAR(size(0.5, 1), 1.0, 1e-12);
    // Inside, between the two: no smaller than the bottom's, no larger than the top's.
    for (double y = 0.05; y < 1; y += 0.1) {
        const double s = size(0.5, y);
        EXPECT_GE(s, 0.1 - 1e-12);
        EXPECT_LE(s, 1.0 + 1e-12);
    }
    // No enclosed region: an InputError.
    Input open;
    open.xy = {0, 0, 1, 0, 1, 1};
    open.segments = {0, 1, 1, 2};
    EXPECT_THROW(gen::size_from_boundary(open.pslg()), exactmesh::InputError);
}

TEST(DomainBoundary2d, APerPieceSizeWithANarrowDeepDipIsRefusedWithoutBisectingForMinutes) {
    // The size is 1 except in a band 1e-4 wide on the bottom side where it is 1e-12, away from
    // the side's ends and middle (the up-front estimate reads those) around one of the adaptive
    // sampling's first samples (x = 20/64): covering the band at a
    // quarter of the size would take 4 10^8 samples; the sampling stops at 2^24 with an error.
    const std::vector<double> xy = {0, 0, 1, 0, 1, 1, 0, 1};
    const std::vector<tri::VertIdx> segments = {0, 1, 1, 2, 2, 3, 3, 0};
    const gen::MeshDomain2 domain(tri::Pslg{xy, segments, {}, {}});
    const gen::SizeFunction dip = gen::SizeFunction::analytic(
        [](double x, double y) { return y == 0 && std::fabs(x - 0.3125) < 5e-5 ? 1e-12 : 1.0; },
        "a narrow dip");
    try {
        gen::discretize_domain_boundary(domain, [&](const double*, const double*) { return dip; });
        FAIL() << "no error";
    } catch (const exactmesh::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("more than 2^24 samples"), std::string::npos)
            << e.what();
    }
}
