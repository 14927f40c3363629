// SPDX-License-Identifier: MIT
// cgal_mesh_2d: CGAL's 2D Delaunay refinement (bench/cgal_mesh_2d.hpp, the peer of mesh_bench) on
// a Triangle .poly, written as .node/.ele, so that scripts/picture_panels.py can draw CGAL's mesh
// beside ours on the same boundary, size and angle bound. Peer tooling only (bench/): CGAL never
// runs inside exactmesh's algorithms.
//   cgal_mesh_2d IN.poly SIZE_FILE MIN_ANGLE_DEGREES OUT   (writes OUT.node, OUT.ele; 0-based)
//   [--domain NAME]: hole points from the sample domain NAME (a mesh's .poly lists none)
#include <cstdio>
#include <exception>
#include <fstream>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "bench/cgal_mesh_2d.hpp"
#include "generators/boundary/sample_domains.hpp"
#include "generators/sizing/size_function.hpp"
#include "io/triangle_format.hpp"

namespace {

namespace gen = exactmesh::generators;
namespace io = exactmesh::io;

int usage() {
    std::fputs("usage: cgal_mesh_2d IN.poly SIZE_FILE MIN_ANGLE_DEGREES OUT [--domain NAME]\n",
               stderr);
    return 2;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 5 && argc != 7) return usage();
    try {
        const io::PolyFile poly = io::read_poly(argv[1]);
        std::ifstream size_file(argv[2]);
        if (!size_file) throw std::runtime_error(std::string("cannot read ") + argv[2]);
        std::stringstream text;
        text << size_file.rdbuf();
        const gen::SizeFunction size = gen::parse_size_sources(text.str(), argv[2]);
        const double min_angle = std::stod(argv[3]);
        std::vector<double> holes = poly.holes;
        if (argc == 7) {
            if (std::string_view(argv[5]) != "--domain") return usage();
            const gen::DomainPslg domain =
                gen::sample_domain(gen::sample_domain_from_name(argv[6]), size);
            holes.insert(holes.end(), domain.holes.begin(), domain.holes.end());
        }
        const auto mesh = exactmesh::testing::cgal_delaunay_mesh_2d(poly.vertices.xy, poly.segments,
                                                                    holes, min_angle, size);
        std::vector<std::uint32_t> pieces;
        const auto flat = exactmesh::testing::cgal_mesh_triangulation(mesh, pieces);
        io::NodeFile nodes;
        nodes.xy = flat.xy;
        const std::string out = argv[4];
        io::write_node(out + ".node", nodes);
        io::write_ele(out + ".ele", flat.triangles, 0);
        std::printf("triangles: %zu\n", flat.triangles.size() / 3);
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "cgal_mesh_2d: %s\n", e.what());
        return 2;
    }
}
