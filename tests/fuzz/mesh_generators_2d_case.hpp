// SPDX-License-Identifier: MIT
// One case of fuzz_mesh_generators_2d, decoded once for the target and for the regression
// tests that replay its saved inputs (tests/regressions/issue_11_*): the PSLG (fuzz_pslg.hpp,
// 4-byte header), the generator (byte 1 modulo the registry's size), a uniform size of 2^-(byte
// 2 % 6) times the larger side of the bounding box (and, for a generator that takes a metric, a
// constant stretched metric from the rest of byte 2), and the exact check the generator promises.
// advancing-layers gets layers (first height, growth and 20 layers at most from the rest of byte
// 2; from the rest of byte 1: the truncated O-mesh or advancing layers, quads kept or split) and,
// for a wall, a hole seed at the centroid of the first three points (a loop of segments about it
// becomes a wall); its mixed meshes are checked with check_mixed_mesh_2d (pieces in holes
// exempt, exempt_pieces_in_holes_2d).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "generators/mesh_2d/mesh_generators_2d.hpp"
#include "generators/stretched/advancing_layers_2d.hpp"
#include "tests/fuzz/fuzz_pslg.hpp"
#include "triangulation/checks/check_conforming_2d.hpp"
#include "triangulation/checks/check_constrained_2d.hpp"

namespace exactmesh::fuzz {

inline constexpr std::size_t kMeshGeneratorsMaxPoints = 24;

struct MeshGeneratorCase {
    FuzzPslg input;
    const generators::MeshGenerator2* generator = nullptr;
    generators::MeshOptions2 options;  ///< the size, and the Steiner budget given to decode
    double size = 0;                   ///< the uniform size (unset in options when not finite > 0)
    std::vector<double> holes;         ///< advancing-layers: one seed (see above); else none
    triangulation::Pslg pslg() const { return {input.xy, input.segments, holes, {}}; }
};

/// The case in data, or nothing when the bytes decode to no PSLG with a vertex.
/// @param max_steiner_points the budget (the target gives 1,000; 0: the generator's own).
inline std::optional<MeshGeneratorCase> decode_mesh_generator_case(
    const std::uint8_t* data, std::size_t size, std::uint64_t max_steiner_points) {
    std::optional<FuzzPslg> input = decode_pslg(data, size, 4, kMeshGeneratorsMaxPoints);
    if (!input || input->xy.empty()) return std::nullopt;
    static const auto generators = generators::mesh_generators_2d();
    MeshGeneratorCase c{std::move(*input), &generators[data[1] % generators.size()], {}, 0, {}};
    // The size: 2^-k of the larger side of the bounding box (finite inputs; others are rejected
    // by the generator's validation, whatever the size).
    double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
    const std::vector<double>& xy = c.input.xy;
    for (std::size_t i = 0; i < xy.size() / 2; ++i) {
        x0 = std::min(x0, xy[2 * i]), x1 = std::max(x1, xy[2 * i]);
        y0 = std::min(y0, xy[2 * i + 1]), y1 = std::max(y1, xy[2 * i + 1]);
    }
    const double extent = std::max(x1 - x0, y1 - y0);
    c.size = std::ldexp(std::isfinite(extent) && extent > 0 ? extent : 1.0, -(data[2] % 6));
    c.options.max_steiner_points = max_steiner_points;
    if (std::isfinite(c.size) && c.size > 0) {
        c.options.size = generators::SizeFunction::uniform(c.size);
        // A generator that takes a metric (metric-delaunay) gets a constant stretched one from
        // the rest of byte 2: sizes `size` and size / 2^(k % 7), the first along the angle
        // (k / 7) pi / 7, k = byte 2 / 6.
        if (c.generator->honours.contains(generators::MeshOption::Metric)) {
            const int k = data[2] / 6;
            const double angle = (k / 7) * 3.141592653589793 / 7;
            generators::Metric2 m;
            m.h1 = c.size;
            m.h2 = std::ldexp(c.size, -(k % 7));
            m.c = std::cos(angle);
            m.s = std::sin(angle);
            if (std::isnormal(m.h2)) c.options.metric = generators::MetricField2::uniform(m);
        }
        if (c.generator->name == "advancing-layers") {
            // First height size / 2^(1 + k % 8), growth 1 + (k / 8) / 10, k = byte 2 / 6; the
            // method and the quads from byte 1 / (the registry's size).
            const int k = data[2] / 6;
            const unsigned extra = data[1] / static_cast<unsigned>(generators.size());
            generators::LayerParameters2& layers = c.options.layers;
            layers.first_height = std::ldexp(c.size, -(1 + k % 8));
            layers.growth = 1 + (k / 8) / 10.0;
            layers.max_layers = 20;
            layers.method = extra % 2 == 1 ? generators::LayerMethod2::TruncatedOMesh
                                           : generators::LayerMethod2::AdvancingLayers;
            layers.quads = (extra / 2) % 2 == 1;
            if (!std::isnormal(layers.first_height)) layers.first_height = 0;
            if (xy.size() >= 6) {
                c.holes = {(xy[0] + xy[2] + xy[4]) / 3, (xy[1] + xy[3] + xy[5]) / 3};
                if (!std::isfinite(c.holes[0]) || !std::isfinite(c.holes[1])) c.holes.clear();
            }
        }
    }
    return c;
}

/// The exact check the case's generator promises: constrained Delaunay for the Delaunay ones,
/// a conforming mesh for the others, check_mixed_mesh_2d for a mixed mesh (quads given).
inline triangulation::CheckReport check_mesh_generator_case(
    const MeshGeneratorCase& c, const triangulation::Cdt2Result& mesh,
    std::span<const triangulation::VertIdx> quads = {}) {
    if (!quads.empty()) {
        generators::MixedMeshCheck2 mixed =
            generators::check_mixed_mesh_2d(mesh.mesh.xy, mesh.mesh.triangles, quads, mesh.pieces);
        // A segment sticking into a hole stays a piece, in no cell (the generator's own check
        // exempts it the same way, against the same domain triangulation).
        if (!mixed.missing_pieces.empty()) {
            const generators::MeshDomain2 domain(c.pslg(), c.options.cdt);
            generators::exempt_pieces_in_holes_2d(mixed, domain.triangulation(), mesh.mesh.xy,
                                                  mesh.pieces, mesh.piece_segment);
        }
        triangulation::CheckReport report;
        report.ok = mixed.ok();
        if (!report.ok) report.problem = "mixed mesh: " + mixed.summary();
        return report;
    }
    return c.generator->delaunay
               ? triangulation::check_constrained_delaunay_2d(mesh.mesh, mesh.input_vertex_count,
                                                              c.input.segments, mesh.pieces)
               : triangulation::check_conforming_mesh_2d(mesh.mesh, mesh.input_vertex_count,
                                                         c.input.segments, mesh.pieces);
}

}  // namespace exactmesh::fuzz
