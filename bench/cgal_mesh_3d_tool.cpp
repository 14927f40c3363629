// SPDX-License-Identifier: MIT
// cgal_mesh_3d: CGAL's Mesh_3 as the peer of bench/tetmesh_bench on the same PLC (a TetGen .poly,
// .smesh, .off or .stl, as `exactmesh tetmesh` reads it), written as .node/.ele in exactmesh's
// orientation. Peer tooling only (bench/): CGAL never runs inside exactmesh's algorithms, and it
// is a separate program so that Mesh_3's long compile is paid by this target alone.
//   cgal_mesh_3d IN OUT --cell-size C [--radius-edge B] [--facet-size F] [--facet-angle A]
//                [--facet-distance D] [--edge-size E] [--feature-angle DEG] [--optimize]
// The domain: the PLC's facets triangulated in their planes (triangulate_facets_3d: the PLC's
// own vertices, no Steiner point) as one polygon soup, oriented to bound a volume and made a
// Polyhedron_3, then Polyhedral_mesh_domain_with_features_3 with detect_features(DEG, default
// 60): the sharp edges (the box's and the cavity's edges, the wing's trailing edge and its
// junctions with the walls) are protected by Mesh_3's balls, so they are in the mesh as they
// are in ours; Polyhedral_mesh_domain_3 without features would round them off. The inside test
// is Mesh_3's ray parity, so a cavity (a second closed component) is a hole, as the .poly's
// hole point makes it for us.
// Criteria: cell_radius_edge_ratio B (default 2), cell_size C, facet_size F (default C),
// facet_angle A (default 25), facet_distance D (default C / 10: the PLC is piecewise planar,
// so it only bounds how far curved-looking faceted parts may be cut), edge_size E (default C).
// No Lloyd, no ODT; perturb and exude only with --optimize (after the refinement, each timed).
// Prints `domain_seconds`, `refine_seconds` (make_mesh_3: protection and refinement),
// `perturb_seconds`, `exude_seconds` (0 without --optimize), all process CPU time, and `tets`.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_polyhedron_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polyhedral_mesh_domain_with_features_3.h>
#include <CGAL/exude_mesh_3.h>
#include <CGAL/make_mesh_3.h>
#include <CGAL/perturb_mesh_3.h>
#include <time.h>  // clock_gettime: process CPU time, as Gmsh and TetGen report theirs

#include <cstdio>
#include <exception>
#include <map>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "io/plc_format.hpp"
#include "io/tetgen_format.hpp"
#include "predicates/orient3d.hpp"
#include "triangulation/recovery_3d/plc_3d.hpp"

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Polyhedron = CGAL::Mesh_polyhedron_3<Kernel>::type;
using Domain = CGAL::Polyhedral_mesh_domain_with_features_3<Kernel>;
using Tr = CGAL::Mesh_triangulation_3<Domain, CGAL::Default, CGAL::Sequential_tag>::type;
using C3t3 = CGAL::Mesh_complex_3_in_triangulation_3<Tr, Domain::Corner_index, Domain::Curve_index>;
using Criteria = CGAL::Mesh_criteria_3<Tr>;

namespace tri = exactmesh::triangulation;
namespace pmp = CGAL::Polygon_mesh_processing;

double cpu_seconds() {
    timespec now{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
    return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

/// The PLC's triangulated facets as a closed Polyhedron_3, oriented to bound its volume.
Polyhedron surface_of(const tri::Plc3& plc) {
    const tri::SurfaceTriangles3 surface = tri::validate_plc_3d(plc);
    tri::check_surface_closed_3d(plc, surface);
    std::vector<Kernel::Point_3> points;
    for (std::uint32_t v = 0; v < plc.vertex_count(); ++v)
        points.emplace_back(plc.point(v)[0], plc.point(v)[1], plc.point(v)[2]);
    std::vector<std::vector<std::size_t>> polygons;
    for (std::size_t t = 0; t + 2 < surface.triangles.size(); t += 3)
        polygons.push_back(
            {surface.triangles[t], surface.triangles[t + 1], surface.triangles[t + 2]});
    if (!pmp::orient_polygon_soup(points, polygons))
        throw std::runtime_error("the PLC's surface is not an orientable 2-manifold");
    Polyhedron polyhedron;
    pmp::polygon_soup_to_polygon_mesh(points, polygons, polyhedron);
    if (!CGAL::is_closed(polyhedron)) throw std::runtime_error("the PLC's surface is not closed");
    pmp::orient_to_bound_a_volume(polyhedron);
    return polyhedron;
}

struct Arguments {
    std::string in, out;
    double cell_size = 0, radius_edge = 2, facet_size = 0, facet_angle = 25, facet_distance = 0,
           edge_size = 0, feature_angle = 60;
    bool optimize = false;
};

Arguments parse(int argc, char** argv) {
    Arguments a;
    std::vector<std::string> positional;
    for (int i = 1; i < argc; ++i) {
        const std::string_view arg = argv[i];
        auto number = [&] {
            if (i + 1 >= argc) throw std::invalid_argument(std::string(arg) + " needs a number");
            return std::stod(argv[++i]);
        };
        if (arg == "--cell-size")
            a.cell_size = number();
        else if (arg == "--radius-edge")
            a.radius_edge = number();
        else if (arg == "--facet-size")
            a.facet_size = number();
        else if (arg == "--facet-angle")
            a.facet_angle = number();
        else if (arg == "--facet-distance")
            a.facet_distance = number();
        else if (arg == "--edge-size")
            a.edge_size = number();
        else if (arg == "--feature-angle")
            a.feature_angle = number();
        else if (arg == "--optimize")
            a.optimize = true;
        else if (arg.starts_with("--"))
            throw std::invalid_argument("unknown option " + std::string(arg));
        else
            positional.emplace_back(arg);
    }
    if (positional.size() != 2 || !(a.cell_size > 0))
        throw std::invalid_argument(
            "usage: cgal_mesh_3d IN OUT --cell-size C [--radius-edge B] [--facet-size F] "
            "[--facet-angle A] [--facet-distance D] [--edge-size E] [--feature-angle DEG] "
            "[--optimize]");
    a.in = positional[0];
    a.out = positional[1];
    if (a.facet_size <= 0) a.facet_size = a.cell_size;
    if (a.facet_distance <= 0) a.facet_distance = a.cell_size / 10;
    if (a.edge_size <= 0) a.edge_size = a.cell_size;
    return a;
}

/// The cells in the complex as a .node/.ele pair, each tetrahedron positive by exactmesh's
/// orient3d (Mesh_3's cells are positive in CGAL's convention; the exact test settles it).
std::size_t write_mesh(const C3t3& c3t3, const std::string& out) {
    std::map<Tr::Vertex_handle, std::uint32_t> index;
    std::vector<double> xyz;
    std::vector<std::uint32_t> tets;
    for (auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c) {
        std::uint32_t corner[4];
        for (int k = 0; k < 4; ++k) {
            const auto [at, added] =
                index.emplace(c->vertex(k), static_cast<std::uint32_t>(xyz.size() / 3));
            if (added) {
                const auto& p = c->vertex(k)->point().point();
                xyz.insert(xyz.end(), {p.x(), p.y(), p.z()});
            }
            corner[k] = at->second;
        }
        const double* p[4] = {&xyz[3 * corner[0]], &xyz[3 * corner[1]], &xyz[3 * corner[2]],
                              &xyz[3 * corner[3]]};
        if (exactmesh::predicates::orient3d(p[0], p[1], p[2], p[3]) ==
            exactmesh::predicates::Sign::Negative)
            std::swap(corner[2], corner[3]);
        tets.insert(tets.end(), corner, corner + 4);
    }
    exactmesh::io::write_tetgen_node(out + ".node", xyz, 0);
    exactmesh::io::write_tetgen_ele(out + ".ele", tets, 0);
    return tets.size() / 4;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        const Arguments a = parse(argc, argv);
        const tri::Plc3 plc = exactmesh::io::plc_from_file(exactmesh::io::read_plc(a.in));
        const Polyhedron polyhedron = surface_of(plc);

        double start = cpu_seconds();
        Domain domain(polyhedron);
        domain.detect_features(a.feature_angle);
        const double domain_seconds = cpu_seconds() - start;

        namespace params = CGAL::parameters;
        const Criteria criteria(
            params::edge_size = a.edge_size, params::facet_angle = a.facet_angle,
            params::facet_size = a.facet_size, params::facet_distance = a.facet_distance,
            params::cell_radius_edge_ratio = a.radius_edge, params::cell_size = a.cell_size);
        start = cpu_seconds();
        C3t3 c3t3 = CGAL::make_mesh_3<C3t3>(domain, criteria, params::no_lloyd(), params::no_odt(),
                                            params::no_perturb(), params::no_exude());
        const double refine_seconds = cpu_seconds() - start;

        double perturb_seconds = 0, exude_seconds = 0;
        if (a.optimize) {
            // CGAL's defaults of make_mesh_3 (no time limit, its default sliver bounds), run as
            // its own steps so that their time is reported apart from the refinement's.
            start = cpu_seconds();
            CGAL::perturb_mesh_3(c3t3, domain);
            perturb_seconds = cpu_seconds() - start;
            start = cpu_seconds();
            CGAL::exude_mesh_3(c3t3);
            exude_seconds = cpu_seconds() - start;
        }
        const std::size_t tets = write_mesh(c3t3, a.out);
        std::printf(
            "domain_seconds: %.6f\nrefine_seconds: %.6f\nperturb_seconds: %.6f\n"
            "exude_seconds: %.6f\ntets: %zu\n",
            domain_seconds, refine_seconds, perturb_seconds, exude_seconds, tets);
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "cgal_mesh_3d: %s\n", e.what());
        return 2;
    }
}
