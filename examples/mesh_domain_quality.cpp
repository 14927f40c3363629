// SPDX-License-Identifier: MIT
// Example: a quality mesh of a built-in domain (the NACA 0012 airfoil in its far field, or the
// domain named on the command line) by Delaunay refinement at 30 degrees, checked exactly, and
// its quality report.
#include <exactmesh/base/errors.hpp>
#include <exactmesh/generators/boundary/sample_domains.hpp>
#include <exactmesh/generators/mesh_2d/mesh_generators_2d.hpp>
#include <exactmesh/generators/mesh_2d/quality_2d.hpp>
#include <exactmesh/triangulation/checks/check_constrained_2d.hpp>

#include <iostream>
#include <string>

int main(int argc, char** argv) {
    namespace gen = exactmesh::generators;
    namespace tri = exactmesh::triangulation;
    try {
        const gen::SampleDomain which =
            gen::sample_domain_from_name(argc > 1 ? argv[1] : "naca0012");
        const gen::DomainPslg domain = gen::sample_domain(which);
        gen::MeshOptions2 options;
        options.min_angle = 30;
        const gen::MeshRun2 run =
            gen::find_mesh_generator_2d("delaunay-refinement")
                .run(tri::Pslg{domain.xy, domain.segments, domain.holes, {}}, options);
        // Delaunay refinement's meshes are constrained Delaunay: checked exactly against the
        // domain's segments (Chew's definition, every segment present as a chain of pieces).
        const tri::CheckReport check = tri::check_constrained_delaunay_2d(
            run.mesh.mesh, run.mesh.input_vertex_count, domain.segments, run.mesh.pieces);
        std::cout << gen::quality_report_text(
                         gen::quality_report_2d(run.mesh.mesh.xy, run.mesh.mesh.triangles))
                  << "check: " << (check.ok ? "ok" : check.problem) << '\n';
        return check.ok ? 0 : 1;
    } catch (const exactmesh::InputError& error) {
        std::cerr << "bad input: " << error.what() << '\n';
        return 2;
    }
}
