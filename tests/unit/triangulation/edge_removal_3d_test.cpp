// SPDX-License-Identifier: MIT
// Tests of triangulation/modification/edge_removal_3d: the ring around a long edge is replaced
// by the best triangulation of its link (checked against every triangulation of the polygon),
// the mesh stays valid and fills the same volume, locks and rings past 7 are respected, and the
// choice is the same at 2^+-600.
#include "triangulation/modification/edge_removal_3d.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "predicates/angle_comparisons_3d.hpp"
#include "predicates/orient3d.hpp"
#include "triangulation/checks/check_topology_3d.hpp"
#include "triangulation/mesh/flip_3d.hpp"

namespace tri = exactmesh::triangulation;
namespace pred = exactmesh::predicates;

namespace {

/// Edge 0-1 from about (0, 0, -h) to (0, 0, h) with the n tetrahedra around it, its link a ring
/// of n points near the unit circle (angles and heights jittered, the edge's ends moved by up to
/// `jitter`), scaled by 2^exponent. Empty when the jitter made some ring tetrahedron turn.
std::optional<tri::TetMesh3> ring_around_an_edge(unsigned n, double h, double jitter, int exponent,
                                                 unsigned seed = 1) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(-1, 1);
    std::vector<double> xyz{jitter * unit(rng), jitter * unit(rng), -h,
                            jitter * unit(rng), jitter * unit(rng), h * (1 + jitter * unit(rng))};
    for (unsigned i = 0; i < n; ++i) {
        const double angle = 2 * M_PI * (i + 0.3 * unit(rng)) / n;
        const double radius = 1 + jitter * unit(rng);
        xyz.insert(xyz.end(),
                   {radius * std::cos(angle), radius * std::sin(angle), jitter * unit(rng)});
    }
    for (double& x : xyz) x = std::ldexp(x, exponent);
    tri::Tetrahedralization3 mesh;
    pred::Sign first = pred::Sign::Zero;
    for (unsigned i = 0; i < n; ++i) {
        std::array<tri::VertIdx, 4> t{0, 1, 2 + i, 2 + (i + 1) % n};
        const pred::Sign s =
            pred::orient3d(&xyz[3 * t[0]], &xyz[3 * t[1]], &xyz[3 * t[2]], &xyz[3 * t[3]]);
        if (i == 0) first = s;
        if (s == pred::Sign::Zero || s != first) return std::nullopt;
        if (s == pred::Sign::Negative) std::swap(t[2], t[3]);
        mesh.tets.insert(mesh.tets.end(), t.begin(), t.end());
    }
    mesh.xyz = xyz;
    return tri::make_tet_mesh_3d(mesh);
}

/// The edge's half-length and the jitter of seed s in the random rings below.
double half_length(unsigned seed) {
    return std::ldexp(1.0, static_cast<int>(seed % 7) - 4);
}
double jitter_of(unsigned seed) {
    return (seed % 3 + 1) * 0.15;
}

/// The ring of n of the first seed (from 1) that is valid and, with `improvable`, has a removal
/// under MaxMinDihedral; scaled by 2^exponent.
tri::TetMesh3 first_ring(unsigned n, bool improvable, int exponent) {
    for (unsigned seed = 1;; ++seed) {
        std::optional<tri::TetMesh3> mesh =
            ring_around_an_edge(n, half_length(seed), jitter_of(seed), 0, seed);
        if (!mesh) continue;
        tri::FlipPlan3 plan;
        if (improvable &&
            !tri::plan_edge_removal_3d(*mesh, 0, 0, 1, tri::SwapCriterion3::MaxMinDihedral, plan))
            continue;
        return *ring_around_an_edge(n, half_length(seed), jitter_of(seed), exponent, seed);
    }
}

double smallest_angle(const tri::TetMesh3& mesh, const tri::Tet& t) {
    const pred::TetCorners p{mesh.point(t[0]), mesh.point(t[1]), mesh.point(t[2]),
                             mesh.point(t[3])};
    return static_cast<double>(pred::dihedral_radians(pred::smallest_dihedral(p)));
}

double six_volume(const tri::TetMesh3& mesh, const tri::Tet& t) {
    const double *a = mesh.point(t[0]), *b = mesh.point(t[1]), *c = mesh.point(t[2]),
                 *d = mesh.point(t[3]);
    double u[3], v[3], w[3];
    for (int k = 0; k < 3; ++k) {
        u[k] = a[k] - d[k];
        v[k] = b[k] - d[k];
        w[k] = c[k] - d[k];
    }
    return u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
           u[2] * (v[0] * w[1] - v[1] * w[0]);
}

/// The best smallest angle over every triangulation of the polygon ring[0..n-1] (each triangle
/// i < j < k giving (r_i, r_j, r_k, b) and (r_i, r_k, r_j, a)), in doubles; -1 when none has
/// every tetrahedron positive.
double brute_force_best(const tri::TetMesh3& mesh, const std::vector<tri::VertIdx>& r,
                        tri::VertIdx a, tri::VertIdx b) {
    std::function<double(unsigned, unsigned)> best = [&](unsigned i, unsigned k) -> double {
        if (k < i + 2) return INFINITY;
        double result = -1;
        for (unsigned j = i + 1; j < k; ++j) {
            const tri::Tet lower{r[i], r[j], r[k], b}, upper{r[i], r[k], r[j], a};
            const auto positive = [&](const tri::Tet& t) {
                return pred::orient3d(mesh.point(t[0]), mesh.point(t[1]), mesh.point(t[2]),
                                      mesh.point(t[3])) == pred::Sign::Positive;
            };
            if (!positive(lower) || !positive(upper)) continue;
            const double left = best(i, j), right = best(j, k);
            if (left < 0 || right < 0) continue;
            result = std::max(result, std::min({left, right, smallest_angle(mesh, lower),
                                                smallest_angle(mesh, upper)}));
        }
        return result;
    };
    return best(0, static_cast<unsigned>(r.size()) - 1);
}

/// The ring's link in plan order: r_0, r_1 from the first ring tetrahedron, then around.
std::vector<tri::VertIdx> oriented_link(const tri::TetMesh3& mesh, unsigned n) {
    // ring_around_an_edge's link is 2 .. n + 1 around the edge, one way or the other.
    std::vector<tri::VertIdx> r;
    for (unsigned i = 0; i < n; ++i) r.push_back(2 + i);
    if (pred::orient3d(mesh.point(0), mesh.point(1), mesh.point(r[0]), mesh.point(r[1])) !=
        pred::Sign::Positive)
        std::reverse(r.begin(), r.end());
    return r;
}

void expect_valid(const tri::TetMesh3& mesh) {
    const tri::TopologyReport3 report = tri::check_topology_3d(tri::to_tetrahedralization_3d(mesh));
    EXPECT_TRUE(report.ok) << report.problem;
}

}  // namespace

TEST(Triangulation_EdgeRemoval3, TheBestTriangulationOfTheRingIsChosen) {
    // Random rings around an edge, short to long, regular to skewed: whenever some
    // triangulation of the link beats the worst ring tetrahedron, the removal is planned with
    // the best one (every triangulation of the polygon tried in doubles), made, and leaves a
    // valid mesh of the same volume without the edge; otherwise none is planned.
    for (unsigned n = 3; n <= tri::kMaxEdgeRemovalRing; ++n) {
        unsigned planned = 0, refused = 0;
        for (unsigned seed = 1; seed <= 300; ++seed) {
            std::optional<tri::TetMesh3> made =
                ring_around_an_edge(n, half_length(seed), jitter_of(seed), 0, seed);
            if (!made) continue;
            tri::TetMesh3& mesh = *made;
            SCOPED_TRACE("n " + std::to_string(n) + " seed " + std::to_string(seed));
            double old_smallest = INFINITY, volume = 0;
            for (tri::TetIdx t = 0; t < mesh.tet_slots(); ++t) {
                old_smallest = std::min(old_smallest, smallest_angle(mesh, mesh.tet(t)));
                volume += six_volume(mesh, mesh.tet(t));
            }
            const double best = brute_force_best(mesh, oriented_link(mesh, n), 0, 1);
            tri::FlipPlan3 plan;
            if (!tri::plan_edge_removal_3d(mesh, 0, 0, 1, tri::SwapCriterion3::MaxMinDihedral,
                                           plan)) {
                EXPECT_LE(best, old_smallest * (1 + 1e-12));
                ++refused;
                continue;
            }
            ++planned;
            EXPECT_EQ(plan.kind, tri::FlipKind3::EdgeRemoval);
            EXPECT_EQ(plan.old_count, n);
            ASSERT_EQ(plan.made_count, 2 * (n - 2));
            double made_smallest = INFINITY;
            for (unsigned i = 0; i < plan.made_count; ++i)
                made_smallest = std::min(made_smallest, smallest_angle(mesh, plan.made[i]));
            EXPECT_GT(made_smallest, old_smallest);
            EXPECT_NEAR(made_smallest, best, 1e-12);

            const tri::EdgeRemovalCounters counters = tri::remove_edges_3d(
                mesh, tri::SwapCriterion3::MaxMinDihedral, std::vector<tri::TetIdx>{0}, {});
            EXPECT_EQ(counters.removals, 1u);
            expect_valid(mesh);
            double after = 0;
            for (tri::TetIdx t = 0; t < mesh.tet_slots(); ++t) {
                if (mesh.is_dead(t)) continue;
                const tri::Tet tet = mesh.tet(t);
                EXPECT_FALSE(std::count(tet.begin(), tet.end(), 0u) == 1 &&
                             std::count(tet.begin(), tet.end(), 1u) == 1);  // edge 0-1 gone
                after += six_volume(mesh, tet);
            }
            EXPECT_NEAR(after, volume, 1e-12 * volume);
        }
        EXPECT_GE(planned, 10u) << n;
        EXPECT_GE(refused, 10u) << n;
    }
}

TEST(Triangulation_EdgeRemoval3, EveryCriterionImprovesItsOwnQuality) {
    // Every new tetrahedron strictly beats the worst old one, exactly: a larger volume-edge
    // quality, or a largest dihedral angle below the old largest.
    for (const auto criterion :
         {tri::SwapCriterion3::MinMaxDihedral, tri::SwapCriterion3::VolumeEdge}) {
        tri::TetMesh3 mesh = first_ring(6, true, 0);
        const auto corners = [&](const tri::Tet& t) {
            return pred::TetCorners{mesh.point(t[0]), mesh.point(t[1]), mesh.point(t[2]),
                                    mesh.point(t[3])};
        };
        pred::TetCorners worst_tet = corners(mesh.tet(0));
        pred::Dihedral widest = pred::largest_dihedral(worst_tet);
        for (tri::TetIdx t = 1; t < mesh.tet_slots(); ++t) {
            const pred::TetCorners c = corners(mesh.tet(t));
            if (pred::compare_volume_edge(c, worst_tet) == pred::Sign::Negative) worst_tet = c;
            const pred::Dihedral d = pred::largest_dihedral(c);
            if (pred::compare_dihedral(d, widest) == pred::Sign::Positive) widest = d;
        }
        tri::FlipPlan3 plan;
        ASSERT_TRUE(tri::plan_edge_removal_3d(mesh, 0, 0, 1, criterion, plan));
        for (unsigned i = 0; i < plan.made_count; ++i) {
            const pred::TetCorners made = corners(plan.made[i]);
            EXPECT_EQ(pred::orient3d(made[0], made[1], made[2], made[3]), pred::Sign::Positive);
            if (criterion == tri::SwapCriterion3::VolumeEdge) {
                EXPECT_EQ(pred::compare_volume_edge(made, worst_tet), pred::Sign::Positive) << i;
            } else {
                EXPECT_TRUE(pred::every_dihedral_compares(made, widest, pred::Sign::Negative)) << i;
            }
        }
        EXPECT_EQ(tri::remove_edges_3d(mesh, criterion, std::vector<tri::TetIdx>{0}, {}).removals,
                  1u);
        expect_valid(mesh);
    }
}

TEST(Triangulation_EdgeRemoval3, TheSameChoiceAtEveryScale) {
    for (unsigned n = 4; n <= tri::kMaxEdgeRemovalRing; ++n) {
        const tri::TetMesh3 plain = first_ring(n, true, 0);
        tri::FlipPlan3 expected;
        ASSERT_TRUE(tri::plan_edge_removal_3d(plain, 0, 0, 1, tri::SwapCriterion3::MaxMinDihedral,
                                              expected));
        for (const int e : {600, -600}) {
            const tri::TetMesh3 scaled = first_ring(n, true, e);
            tri::FlipPlan3 plan;
            ASSERT_TRUE(tri::plan_edge_removal_3d(scaled, 0, 0, 1,
                                                  tri::SwapCriterion3::MaxMinDihedral, plan));
            ASSERT_EQ(plan.made_count, expected.made_count) << e;
            for (unsigned i = 0; i < plan.made_count; ++i)
                EXPECT_EQ(plan.made[i], expected.made[i]) << e;
        }
    }
}

TEST(Triangulation_EdgeRemoval3, LocksVetoesRingsPastSevenAndBoundaryEdgesAreLeft) {
    // A locked edge is not tried; a locked face around it refuses the removal.
    tri::TetMesh3 mesh = first_ring(5, true, 0);
    tri::SwapLocks3 edge_lock;
    edge_lock.add_edge(1, 0);
    edge_lock.finish();
    tri::SwapConstraints3 constraints;
    constraints.locks = &edge_lock;
    std::vector<tri::TetIdx> all;
    for (tri::TetIdx t = 0; t < mesh.tet_slots(); ++t) all.push_back(t);
    tri::EdgeRemovalCounters c =
        tri::remove_edges_3d(mesh, tri::SwapCriterion3::MaxMinDihedral, all, constraints);
    EXPECT_EQ(c.removals, 0u);
    tri::SwapLocks3 face_lock;
    face_lock.add_face(0, 1, 2);
    face_lock.finish();
    constraints.locks = &face_lock;
    c = tri::remove_edges_3d(mesh, tri::SwapCriterion3::MaxMinDihedral, all, constraints);
    EXPECT_EQ(c.removals, 0u);
    EXPECT_GE(c.locked, 1u);
    // The caller's veto.
    constraints.locks = nullptr;
    constraints.accept = [](const tri::FlipPlan3&) { return false; };
    c = tri::remove_edges_3d(mesh, tri::SwapCriterion3::MaxMinDihedral, all, constraints);
    EXPECT_EQ(c.removals, 0u);
    EXPECT_GE(c.vetoed, 1u);
    // Eight around the edge: not planned.
    const tri::TetMesh3 eight = first_ring(8, false, 0);
    tri::FlipPlan3 plan;
    EXPECT_FALSE(
        tri::plan_edge_removal_3d(eight, 0, 0, 1, tri::SwapCriterion3::MaxMinDihedral, plan));
    // An edge on the domain boundary (an open ring): edge 2-3 lies on the hull, in tetrahedron 0.
    EXPECT_FALSE(
        tri::plan_edge_removal_3d(mesh, 0, 2, 3, tri::SwapCriterion3::MaxMinDihedral, plan));
}
