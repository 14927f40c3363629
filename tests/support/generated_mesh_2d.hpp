// SPDX-License-Identifier: MIT
// A 2D generator's result checked the way every generator test checks it: check_quality_mesh
// (mesh_checks_2d.hpp) of its mesh against the input (check_mesh_of_input), with edge-to-size
// ratios when the size is bounded, and its quality report; and the random-PSLG sweep the Delaunay
// generators share (every run a constrained Delaunay mesh, InputError, or GeometryError on
// grid-lines only). Test support for tests/unit/generators, not a library algorithm.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <utility>

#include <gtest/gtest.h>

#include "base/errors.hpp"
#include "generators/inputs/pslg_inputs.hpp"
#include "generators/mesh_2d/quality_2d.hpp"
#include "generators/sizing/size_function.hpp"
#include "tests/support/mesh_checks_2d.hpp"
#include "tests/support/pslg_fixtures_2d.hpp"
#include "triangulation/checks/check_constrained_2d.hpp"

namespace exactmesh::testing {

/// A generator's result (any with a triangulation::Cdt2Result `mesh`), the exact checks of its
/// mesh and its quality report.
template <class Result>
struct GeneratedMesh2 {
    Result result;
    MeshCheck check;
    generators::QualityReport2 quality;
};

/// check_quality_mesh of a generator's mesh `m` of the input `in` (`delaunay`, `size` and
/// `closed_loops` as it takes them).
inline MeshCheck check_mesh_of_input(const triangulation::Cdt2Result& m, const Input& in,
                                     bool delaunay,
                                     const std::function<double(double, double)>& size = {},
                                     bool closed_loops = true) {
    return check_quality_mesh(m.mesh, m.input_vertex_count, in.xy, in.segments, m.pieces, size,
                              closed_loops, delaunay);
}

/// `result`, generated from `in` with `size`, checked by check_mesh_of_input (size ratios only
/// for a bounded size) and its quality reported.
template <class Result>
GeneratedMesh2<Result> check_generated_mesh(Result result, const Input& in,
                                            const generators::SizeFunction& size, bool closed_loops,
                                            bool delaunay) {
    GeneratedMesh2<Result> g{std::move(result), {}, {}};
    const triangulation::Cdt2Result& m = g.result.mesh;
    std::function<double(double, double)> ratio_size;
    if (size.bounded()) ratio_size = [&size](double x, double y) { return size(x, y); };
    g.check = check_mesh_of_input(m, in, delaunay, ratio_size, closed_loops);
    g.quality = generators::quality_report_2d(m.mesh.xy, m.mesh.triangles, size);
    return g;
}

/// The constrained Delaunay test distributions (60 vertices, 30 segments, seeds 1 to 3) through
/// `generate` (an Input to a generator's result, or nothing to skip the input): every mesh is
/// exactly constrained Delaunay; a run may end in InputError (nothing enclosed), or in
/// GeometryError on grid-lines only (features at the resolution of doubles). More than 10 meshed.
template <class Generate>
void expect_random_pslgs_constrained_delaunay(const Generate& generate) {
    std::size_t meshed = 0;
    for (const auto d : generators::kAllPslgDistributions) {
        for (std::uint64_t seed = 1; seed <= 3; ++seed) {
            const generators::PslgInput p = generators::generate_pslg(d, 60, 30, seed);
            const Input in{p.xy, p.segments, p.holes, {}};
            try {
                const auto result = generate(in);
                if (!result) continue;
                const auto report = triangulation::check_constrained_delaunay_2d(
                    result->mesh.mesh, result->mesh.input_vertex_count, in.segments,
                    result->mesh.pieces);
                EXPECT_TRUE(report.ok) << generators::pslg_distribution_name(d) << " seed " << seed
                                       << ": " << report.problem;
                ++meshed;
            } catch (const InputError&) {
            } catch (const GeometryError& error) {
                EXPECT_EQ(d, generators::PslgDistribution::GridLines)
                    << seed << ": " << error.what();
            }
        }
    }
    EXPECT_GT(meshed, 10u);
}

}  // namespace exactmesh::testing
