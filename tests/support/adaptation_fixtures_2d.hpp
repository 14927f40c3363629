// SPDX-License-Identifier: MIT
// The starting meshes and the field the 2D adaptation tests share: a sample domain scaled and
// meshed by Delaunay refinement (as it is, or as an adaptive state), and the moving tanh front.
// Test support for tests/unit/generators, not a library algorithm.
#pragma once

#include <cmath>
#include <span>
#include <utility>
#include <vector>

#include "generators/adaptation/adaptive_mesh_2d.hpp"
#include "generators/adaptation/vertex_field.hpp"
#include "generators/boundary/sample_domains.hpp"
#include "generators/mesh_2d/mesh_generators_2d.hpp"

namespace exactmesh::testing {

struct SampleDomainMesh {
    generators::DomainPslg domain;
    triangulation::Cdt2Result mesh;
};

// Sample domain d (sized by its own size function, or uniformly when size > 0), every
// coordinate times `scale`, meshed by Delaunay refinement (the size scaled too).
inline SampleDomainMesh sample_domain_mesh(generators::SampleDomain d, double scale = 1.0,
                                           double size = 0) {
    SampleDomainMesh r;
    const generators::SizeFunction s =
        size > 0 ? generators::SizeFunction::uniform(size) : generators::sample_domain_size(d);
    r.domain = generators::sample_domain(d, s);
    for (double& c : r.domain.xy) c *= scale;
    for (double& c : r.domain.holes) c *= scale;
    generators::MeshOptions2 options;
    options.size =
        size > 0 ? generators::SizeFunction::uniform(size * scale) : generators::SizeFunction();
    r.mesh = generators::find_mesh_generator_2d("delaunay-refinement")
                 .run({r.domain.xy, r.domain.segments, r.domain.holes, {}}, options)
                 .mesh;
    return r;
}

struct SampleDomainState {
    generators::DomainPslg domain;
    generators::AdaptiveMesh2 state;
};

// sample_domain_mesh as an adaptive state with the domain's curves (none when `curves` is
// false), the field sampled at t = 0.
inline SampleDomainState sample_domain_state(generators::SampleDomain d,
                                             const generators::AnalyticField& field, double scale,
                                             double size, bool curves) {
    SampleDomainMesh m = sample_domain_mesh(d, scale, size);
    SampleDomainState r;
    r.domain = std::move(m.domain);
    r.state = generators::make_adaptive_mesh_2d(
        std::move(m.mesh), r.domain.xy, r.domain.segments, r.domain.holes,
        curves ? r.domain.curves : std::vector<generators::Curve2>{},
        curves ? std::span<const generators::SegmentCurve>(r.domain.segment_curves)
               : std::span<const generators::SegmentCurve>{});
    r.state.values = generators::sample_field(field, r.state.mesh.xy, 2, 0);
    return r;
}

// A steep front (tanh of 25 × the distance to a line) moving with t, on coordinates / scale.
inline generators::AnalyticField front_field(double scale = 1.0) {
    return {"front", [scale](double x, double y, double, double t) {
                return std::tanh(25 * (x / scale + 0.5 * y / scale - 0.6 - 0.3 * t));
            }};
}

}  // namespace exactmesh::testing
