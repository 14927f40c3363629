// SPDX-License-Identifier: MIT
// Sample domains: closed loops whose segments never cross (exact orient2d), holes inside their
// loops, curve points on their curves (the NACA formulas), the three-element layout with its
// elements apart by at least 0.005, refined spacing under a smaller size, unknown names refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include "base/errors.hpp"
#include "generators/boundary/sample_domains.hpp"
#include "predicates/orient2d.hpp"
#include "tests/support/mesh_checks_2d.hpp"

namespace em = exactmesh;
namespace gen = exactmesh::generators;
using em::predicates::Sign;

namespace {

/// Proper crossing or touching of two segments that share no endpoint (exact).
bool segments_meet(const double* a, const double* b, const double* c, const double* d) {
    const Sign s1 = em::predicates::orient2d(a, b, c), s2 = em::predicates::orient2d(a, b, d);
    const Sign s3 = em::predicates::orient2d(c, d, a), s4 = em::predicates::orient2d(c, d, b);
    if (s1 != Sign::Zero && s1 == s2) return false;
    if (s3 != Sign::Zero && s3 == s4) return false;
    if (s1 == Sign::Zero && s2 == Sign::Zero) {  // collinear: overlapping boxes
        return std::max(std::min(a[0], b[0]), std::min(c[0], d[0])) <=
                   std::min(std::max(a[0], b[0]), std::max(c[0], d[0])) &&
               std::max(std::min(a[1], b[1]), std::min(c[1], d[1])) <=
                   std::min(std::max(a[1], b[1]), std::max(c[1], d[1]));
    }
    return true;
}

/// The loop (connected component of segments) of each vertex.
std::vector<int> loops_of(const gen::DomainPslg& d) {
    const std::size_t n = d.xy.size() / 2;
    std::vector<int> loop(n, -1);
    std::vector<std::vector<std::uint32_t>> adjacent(n);
    for (std::size_t s = 0; s < d.segments.size(); s += 2) {
        adjacent[d.segments[s]].push_back(d.segments[s + 1]);
        adjacent[d.segments[s + 1]].push_back(d.segments[s]);
    }
    int count = 0;
    for (std::size_t v = 0; v < n; ++v) {
        if (loop[v] >= 0) continue;
        std::vector<std::uint32_t> stack{static_cast<std::uint32_t>(v)};
        loop[v] = count;
        while (!stack.empty()) {
            const std::uint32_t u = stack.back();
            stack.pop_back();
            for (const std::uint32_t w : adjacent[u]) {
                if (loop[w] < 0) loop[w] = count, stack.push_back(w);
            }
        }
        ++count;
    }
    return loop;
}

}  // namespace

TEST(Generators_SampleDomains, ClosedLoopsThatNeverCrossWithHolesInside) {
    for (const gen::SampleDomain d : gen::kAllSampleDomains) {
        const std::string name(gen::sample_domain_name(d));
        EXPECT_EQ(gen::sample_domain_from_name(name), d);
        const gen::DomainPslg pslg = gen::sample_domain(d);
        // Every vertex on exactly two segments: closed loops.
        std::map<std::uint32_t, int> degree;
        for (const std::uint32_t v : pslg.segments) ++degree[v];
        EXPECT_EQ(degree.size(), pslg.xy.size() / 2) << name;
        for (const auto& [v, k] : degree) EXPECT_EQ(k, 2) << name << " vertex " << v;
        // No two segments meet except at a shared endpoint.
        const std::size_t count = pslg.segments.size() / 2;
        for (std::size_t s = 0; s < count; ++s) {
            for (std::size_t t = s + 1; t < count; ++t) {
                const std::uint32_t a = pslg.segments[2 * s], b = pslg.segments[2 * s + 1];
                const std::uint32_t c = pslg.segments[2 * t], e = pslg.segments[2 * t + 1];
                if (a == c || a == e || b == c || b == e) continue;
                ASSERT_FALSE(segments_meet(&pslg.xy[2 * a], &pslg.xy[2 * b], &pslg.xy[2 * c],
                                           &pslg.xy[2 * e]))
                    << name << ": segments " << s << " and " << t;
            }
        }
        // Each hole point lies outside the region the segments enclose (even-odd): in a hole.
        for (std::size_t h = 0; h < pslg.holes.size(); h += 2) {
            EXPECT_FALSE(em::testing::inside_by_segments(pslg.holes[h], pslg.holes[h + 1], pslg.xy,
                                                         pslg.segments))
                << name << " hole " << h / 2;
        }
    }
    EXPECT_THROW(gen::sample_domain_from_name("moon"), em::InputError);
}

TEST(Generators_SampleDomains, NacaPointsLieOnTheirSurfaces) {
    // Symmetric sections: the 4-digit point is (x, +-y_t(x)).
    for (const double beta : {0.1, 0.7, 1.3, 2.9}) {
        const double x = 0.5 * (1 + std::cos(beta));
        const auto upper = gen::naca4_point(0, 0, 0.12, beta, true);
        const auto lower = gen::naca4_point(0, 0, 0.12, beta, false);
        EXPECT_DOUBLE_EQ(upper[0], x);
        EXPECT_DOUBLE_EQ(upper[1], gen::naca_thickness(0.12, x));
        EXPECT_DOUBLE_EQ(lower[1], -gen::naca_thickness(0.12, x));
    }
    // NACA 4412: the mean of the two surfaces at the station of maximum camber is near 0.04 high.
    const double beta = std::acos(2 * 0.4 - 1);
    const auto u = gen::naca4_point(0.04, 0.4, 0.12, beta, true),
               l = gen::naca4_point(0.04, 0.4, 0.12, beta, false);
    EXPECT_NEAR(0.5 * (u[1] + l[1]), 0.04, 1e-12);
    EXPECT_NEAR(u[1] - l[1], 2 * gen::naca_thickness(0.12, 0.4), 1e-12);
    // Closed edges exactly.
    EXPECT_EQ(gen::naca4_point(0.04, 0.4, 0.12, 0.0, true), (std::array<double, 2>{1.0, 0.0}));
    EXPECT_EQ(gen::naca4_point(0.04, 0.4, 0.12, std::numbers::pi, false),
              (std::array<double, 2>{0.0, 0.0}));
}

TEST(Generators_SampleDomains, ThreeElementsApartAndFinerUnderASmallerSize) {
    const gen::DomainPslg pslg = gen::sample_domain(gen::SampleDomain::ThreeElement);
    const std::vector<int> loop = loops_of(pslg);
    ASSERT_EQ(*std::max_element(loop.begin(), loop.end()), 3);  // box, slat, main, flap
    ASSERT_EQ(pslg.holes.size(), 6u);
    // The smallest distance between vertices of different elements (loops 1..3) is a lower bound
    // check of the gaps (the vertices are 0.004 apart along the surfaces).
    double gap = INFINITY;
    for (std::size_t v = 0; v < loop.size(); ++v) {
        for (std::size_t w = v + 1; w < loop.size(); ++w) {
            if (loop[v] == 0 || loop[w] == 0 || loop[v] == loop[w]) continue;
            gap = std::min(gap, std::hypot(pslg.xy[2 * v] - pslg.xy[2 * w],
                                           pslg.xy[2 * v + 1] - pslg.xy[2 * w + 1]));
        }
    }
    EXPECT_GT(gap, 0.005);
    EXPECT_LT(gap, 0.05);
    const gen::DomainPslg finer =
        gen::sample_domain(gen::SampleDomain::ThreeElement, gen::SizeFunction::uniform(0.002));
    EXPECT_GT(finer.xy.size(), 2 * pslg.xy.size());
}

// Issue 13: each curved segment records its curve piece; its ends are the curve at u0 and u1
// (bit for bit, but for the ends a loop writes exactly: (1, 0) and (0, 0) of the NACA 0012).
TEST(Generators_SampleDomains, CurvedSegmentsRecordTheirCurvePiece) {
    for (const gen::SampleDomain d : gen::kAllSampleDomains) {
        const gen::DomainPslg pslg = gen::sample_domain(d);
        const std::string name(gen::sample_domain_name(d));
        ASSERT_EQ(pslg.segment_curves.size(), pslg.segments.size() / 2) << name;
        std::size_t curved = 0, exact = 0;
        for (std::size_t s = 0; s < pslg.segment_curves.size(); ++s) {
            const gen::SegmentCurve& c = pslg.segment_curves[s];
            if (c.curve == gen::kStraightSide) continue;
            ASSERT_LT(c.curve, pslg.curves.size()) << name;
            ++curved;
            for (const auto& [v, u] : {std::pair{pslg.segments[2 * s], c.u0},
                                       std::pair{pslg.segments[2 * s + 1], c.u1}}) {
                const std::array<double, 2> p = pslg.curves[c.curve](u);
                EXPECT_NEAR(p[0], pslg.xy[2 * v], 1e-12) << name << " segment " << s;
                EXPECT_NEAR(p[1], pslg.xy[2 * v + 1], 1e-12) << name << " segment " << s;
                exact += p[0] == pslg.xy[2 * v] && p[1] == pslg.xy[2 * v + 1] ? 1 : 0;
            }
        }
        EXPECT_GT(curved, 16u) << name;
        EXPECT_GE(exact + 4, 2 * curved) << name;
    }
}
