// SPDX-License-Identifier: MIT
// Issue 11, the advancing front's slow fuzz unit (was tests/data/fuzz/slow/): a quadrilateral 1
// wide and 3e231 tall with both diagonals as segments (x of the far corners 3.6e-304 and 3.1e-322),
// replayed as fuzz_mesh_generators_2d runs it (1,000 Steiner points) and with the generator's
// default budget. It took 1 s and 38 s (release) when the front's placement squared differences
// of 1e230: the projection onto a front edge overflowed (t = inf / inf = NaN, or 0 with an
// infinite distance), no edge-distance test ever rejected a new point, so points went anywhere
// near the front and it ran away (2,000-4,000 new points, none reused) until its budget closed
// it by a CDT whose swap recovery is quadratic, in GMP here (scaling that projection alone made
// the old code fast).
// Since the placement works on differences scaled by the root square's power of two (the scale
// invariance fix), the front meshes it in under 100 triangles, without a closure, in ~30 ms.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "generators/mesh_generators_2d.hpp"
#include "predicates/errors.hpp"
#include "tests/fuzz/fuzz_pslg.hpp"
#include "triangulation/check_conforming_2d.hpp"
#include "triangulation/check_constrained_2d.hpp"

namespace gen = exactmesh::generators;
namespace tri = exactmesh::triangulation;

namespace {

std::vector<std::uint8_t> read_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

struct Replay {
    std::string generator;
    bool meshed = false;
    std::string error;  ///< the GeometryError or InputError, when not meshed
    tri::CheckReport check;
    std::size_t triangles = 0;
    std::uint64_t closure_runs = 0;  ///< the advancing front's counter
};

/// One input of fuzz_mesh_generators_2d, run as the target runs it (the same size); `budget` is
/// the Steiner budget (the target's 1,000, or 0 for the generator's automatic one).
Replay replay(const std::string& name, std::uint64_t budget) {
    const std::vector<std::uint8_t> data =
        read_file(std::string(EXACTMESH_SOURCE_DIR) + "/tests/data/fuzz/" + name);
    EXPECT_FALSE(data.empty()) << name;
    Replay r;
    const auto input = exactmesh::fuzz::decode_pslg(data.data(), data.size(), 4, 24);
    if (!input) return r;
    const auto generators = gen::mesh_generators_2d();
    const gen::MeshGenerator2& generator = generators[data[1] % generators.size()];
    r.generator = generator.name;
    double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
    for (std::size_t i = 0; i < input->xy.size() / 2; ++i) {
        x0 = std::min(x0, input->xy[2 * i]), x1 = std::max(x1, input->xy[2 * i]);
        y0 = std::min(y0, input->xy[2 * i + 1]), y1 = std::max(y1, input->xy[2 * i + 1]);
    }
    const double extent = std::max(x1 - x0, y1 - y0);
    const double h = std::ldexp(std::isfinite(extent) && extent > 0 ? extent : 1.0, -(data[2] % 6));
    gen::MeshOptions2 options;
    options.max_steiner_points = budget;
    if (std::isfinite(h) && h > 0) options.size = gen::SizeFunction::uniform(h);
    try {
        const gen::MeshRun2 run =
            generator.run(tri::Pslg{input->xy, input->segments, {}, {}}, options);
        r.meshed = true;
        r.triangles = run.mesh.mesh.triangle_count();
        for (const auto& [key, value] : run.counters) {
            if (key == "closure_runs") r.closure_runs = value;
        }
        r.check =
            generator.delaunay
                ? tri::check_constrained_delaunay_2d(run.mesh.mesh, run.mesh.input_vertex_count,
                                                     input->segments, run.mesh.pieces)
                : tri::check_conforming_mesh_2d(run.mesh.mesh, run.mesh.input_vertex_count,
                                                input->segments, run.mesh.pieces);
    } catch (const exactmesh::GeometryError& e) {
        r.error = e.what();
    } catch (const exactmesh::InputError& e) {
        r.error = e.what();
    }
    return r;
}

}  // namespace

TEST(Issue11, issue_11_sliver) {
    // Kept fast (well under a second in release) as the hang test of this input: both budgets
    // mesh it without running out, so the front is never closed by the CDT.
    for (const std::uint64_t budget : {std::uint64_t{1000}, std::uint64_t{0}}) {
        const Replay r = replay("mesh_generators_2d_advancing_front_wide_sliver.bin", budget);
        EXPECT_EQ(r.generator, "advancing-front");
        ASSERT_TRUE(r.meshed) << r.error;
        EXPECT_TRUE(r.check.ok) << r.check.problem;
        EXPECT_GT(r.triangles, 0U);
        EXPECT_EQ(r.closure_runs, 0U) << "budget " << budget;
    }
}
