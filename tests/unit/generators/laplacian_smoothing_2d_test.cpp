// SPDX-License-Identifier: MIT
// Laplacian smoothing: on refined sample-domain meshes the result stays a valid constrained
// Delaunay mesh of the domain (exact check) with the boundary and input vertices unmoved and a
// better mean quality; without re-swapping it stays a valid (folded nowhere) mesh; on random star
// polygons a move is undone exactly when the centroid would invert a triangle (decided
// independently); a bad relaxation is an InputError.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "base/errors.hpp"
#include "generators/boundary/sample_domains.hpp"
#include "generators/mesh_2d/delaunay_refinement_2d.hpp"
#include "generators/mesh_2d/laplacian_smoothing_2d.hpp"
#include "generators/mesh_2d/quality_2d.hpp"
#include "predicates/orient2d.hpp"
#include "tests/support/mesh_checks_2d.hpp"

namespace em = exactmesh;
namespace gen = exactmesh::generators;
namespace tri = exactmesh::triangulation;

namespace {

struct Refined {
    gen::DomainPslg domain;
    tri::Cdt2Result mesh;
};

Refined refined(gen::SampleDomain d) {
    Refined r;
    const gen::SizeFunction size = gen::sample_domain_size(d);
    r.domain = gen::sample_domain(d, size);
    gen::RefinementOptions2 options;
    options.size = size;
    r.mesh =
        gen::delaunay_refinement_2d({r.domain.xy, r.domain.segments, r.domain.holes, {}}, options)
            .mesh;
    return r;
}

}  // namespace

TEST(Generators_LaplacianSmoothing, SampleDomainsStayValidDelaunayAndImproveMeanQuality) {
    for (const gen::SampleDomain d : gen::kAllSampleDomains) {
        Refined r = refined(d);
        tri::Triangulation2& m = r.mesh.mesh;
        const std::vector<double> before = m.xy;
        const gen::QualityReport2 q0 = gen::quality_report_2d(m.xy, m.triangles);
        gen::SmoothingOptions2 options;
        options.iterations = 3;
        const gen::SmoothingCounters2 c =
            gen::laplacian_smoothing_2d(m, r.mesh.input_vertex_count, options);
        const std::string name(gen::sample_domain_name(d));
        EXPECT_EQ(c.sweeps, 3u);
        EXPECT_GT(c.moves, 0u) << name;
        const auto check = em::testing::check_quality_mesh(
            m, r.mesh.input_vertex_count, r.domain.xy, r.domain.segments, r.mesh.pieces);
        ASSERT_TRUE(check.ok) << name << ": " << check.problem;
        // Input vertices and every vertex of a piece keep their coordinates.
        for (std::uint32_t v = 0; v < r.mesh.input_vertex_count; ++v) {
            EXPECT_EQ(m.xy[2 * v], before[2 * v]);
            EXPECT_EQ(m.xy[2 * v + 1], before[2 * v + 1]);
        }
        for (const tri::VertIdx v : r.mesh.pieces) {
            EXPECT_EQ(m.xy[2 * v], before[2 * v]);
            EXPECT_EQ(m.xy[2 * v + 1], before[2 * v + 1]);
        }
        const gen::QualityReport2 q1 = gen::quality_report_2d(m.xy, m.triangles);
        EXPECT_GT(q1.mean_min_angle, q0.mean_min_angle) << name;
        EXPECT_EQ(q1.triangles, q0.triangles) << name;  // swaps keep the count
    }
}

TEST(Generators_LaplacianSmoothing, WithoutSwappingTheMeshStaysValid) {
    Refined r = refined(gen::SampleDomain::Key);
    gen::SmoothingOptions2 options;
    options.iterations = 5;
    options.delaunay_swap = false;
    const auto c = gen::laplacian_smoothing_2d(r.mesh.mesh, r.mesh.input_vertex_count, options);
    EXPECT_EQ(c.swaps, 0u);
    const auto check =
        em::testing::check_quality_mesh(r.mesh.mesh, r.mesh.input_vertex_count, r.domain.xy,
                                        r.domain.segments, r.mesh.pieces, {}, true, false);
    ASSERT_TRUE(check.ok) << check.problem;
}

TEST(Generators_LaplacianSmoothing, AMoveIsUndoneExactlyWhenTheCentroidWouldInvertTheStar) {
    // Random star polygons about a free centre vertex (index 0 of the star's mesh, after the
    // fixed ring): the centroid of a non-convex star may lie outside its kernel.
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> radius(0.05, 1.0), jitter(-0.4, 0.4);
    int undone = 0, moved = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        const int k = 3 + static_cast<int>(random() % 6);
        tri::Triangulation2 m;
        for (int i = 0; i < k; ++i) {
            const double a = 2 * std::numbers::pi * (i + 0.5 + jitter(random)) / k,
                         r = radius(random);
            m.xy.insert(m.xy.end(), {r * std::cos(a), r * std::sin(a)});
        }
        m.xy.insert(m.xy.end(), {0.0, 0.0});
        const auto c = static_cast<tri::VertIdx>(k);
        bool valid = true;
        for (int i = 0; i < k; ++i) {
            const auto a = static_cast<tri::VertIdx>(i), b = static_cast<tri::VertIdx>((i + 1) % k);
            m.triangles.insert(m.triangles.end(), {c, a, b});
            valid &= em::predicates::orient2d(m.point(c), m.point(a), m.point(b)) ==
                     em::predicates::Sign::Positive;
        }
        if (!valid) continue;  // the centre is not in the kernel: not a mesh
        m.neighbors.assign(m.triangles.size(), tri::kNone);
        for (int i = 0; i < k; ++i) {
            m.neighbors[3 * static_cast<std::size_t>(i)] =
                static_cast<tri::TriIdx>((i + k - 1) % k);
            m.neighbors[3 * static_cast<std::size_t>(i) + 2] =
                static_cast<tri::TriIdx>((i + 1) % k);
        }
        // Independently: would the centroid invert a triangle?
        double sx = 0, sy = 0;
        for (int i = 0; i < k; ++i)
            sx += m.xy[2 * static_cast<std::size_t>(i)],
                sy += m.xy[2 * static_cast<std::size_t>(i) + 1];
        const double centroid[2] = {0.0 + 1.0 * (sx / k - 0.0), 0.0 + 1.0 * (sy / k - 0.0)};
        bool inverts = false;
        for (int i = 0; i < k; ++i) {
            inverts |= em::predicates::orient2d(centroid, m.point(static_cast<tri::VertIdx>(i)),
                                                m.point(static_cast<tri::VertIdx>((i + 1) % k))) !=
                       em::predicates::Sign::Positive;
        }
        gen::SmoothingOptions2 options;
        options.delaunay_swap = false;
        const auto counters = gen::laplacian_smoothing_2d(m, 0, options);
        EXPECT_EQ(counters.free_vertices, 1u);
        EXPECT_EQ(counters.undone, inverts ? 1u : 0u) << trial;
        if (inverts) {
            ++undone;
            EXPECT_EQ(m.xy[2 * c], 0.0);
            EXPECT_EQ(m.xy[2 * c + 1], 0.0);
        } else {
            ++moved;
            EXPECT_EQ(m.xy[2 * c], centroid[0]);
            EXPECT_EQ(m.xy[2 * c + 1], centroid[1]);
        }
    }
    EXPECT_GT(undone, 10);  // both outcomes are exercised
    EXPECT_GT(moved, 100);
}

TEST(Generators_LaplacianSmoothing, BadRelaxationIsAnInputError) {
    tri::Triangulation2 m;
    for (const double omega : {0.0, -1.0, 1.5, std::nan("")}) {
        gen::SmoothingOptions2 options;
        options.relaxation = omega;
        EXPECT_THROW(gen::laplacian_smoothing_2d(m, 0, options), em::InputError) << omega;
    }
}
