// SPDX-License-Identifier: MIT
// `exactmesh tetmesh`: a tetrahedral mesh of a 3D domain given as a piecewise linear complex
// (TetGen .poly/.smesh, .off, .stl, or a built-in sample domain): conforming Delaunay boundary
// recovery (triangulation/recovery_3d/boundary_recovery_3d), checked exactly before anything
// is written (check_boundary_conformity_3d: valid positively oriented tetrahedra, every facet and
// segment present). Output: TetGen .node/.ele/.face (every subface with its facet's marker)/
// .neigh, or .msh/.vtu by the output's extension; input vertices keep their numbers, Steiner
// points follow them. After refinement, sliver removal (generators/mesh_3d/sliver_removal_3d)
// unless --no-sliver-removal; --quality then reports the mesh before it (prefixed
// before_sliver_removal_) and after it. --generator frontal replaces Delaunay refinement by
// frontal Delaunay insertion at --size (generators/mesh_3d/frontal_delaunay_3d), followed by
// sliver removal as well. --generator octree meshes by a 2:1 balanced octree at --size
// (generators/mesh_3d/octree_mesh_3d: core leaves cut by templates, the band at the boundary
// meshed by recovery and frontal insertion), followed by sliver removal. Region volume bounds
// of a .poly/.smesh (TetGen's region list) are applied by Delaunay refinement, which then runs
// even without --radius-edge or --max-volume (as TetGen's -a does with region constraints); the
// octree takes them as sizes (the regular tetrahedron's edge) and says how many tetrahedra
// exceed them. Region attributes go to the .ele (TetGen -A's column) from every generator.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "base/counter_table.hpp"
#include "base/errors.hpp"
#include "base/number_text.hpp"
#include "cli/commands.hpp"
#include "cli/expressions.hpp"
#include "cli/options.hpp"
#include "cli/output.hpp"
#include "generators/boundary_3d/sample_domains_3d.hpp"
#include "generators/mesh_3d/delaunay_refinement_3d.hpp"
#include "generators/mesh_3d/frontal_delaunay_3d.hpp"
#include "generators/mesh_3d/octree_mesh_3d.hpp"
#include "generators/mesh_3d/size_conformity_3d.hpp"
#include "generators/mesh_3d/sliver_removal_3d.hpp"
#include "io/gmsh_format.hpp"
#include "io/plc_format.hpp"
#include "io/tetgen_format.hpp"
#include "io/vtk_format.hpp"
#include "predicates/stats.hpp"
#include "predicates/tet_quality_3d.hpp"
#include "triangulation/mesh/mesh3.hpp"
#include "triangulation/mesh/plc_3d.hpp"
#include "triangulation/recovery_3d/boundary_recovery_3d.hpp"
#include "triangulation/recovery_3d/check_boundary_conformity_3d.hpp"
#include "triangulation/recovery_3d/plc_3d.hpp"

namespace exactmesh::cli {

namespace {

namespace fs = std::filesystem;
namespace tri = exactmesh::triangulation;
namespace gen = exactmesh::generators;

struct TetmeshArguments : CommandArguments {
    std::string domain;
    double domain_size = 0;
    std::uint64_t max_steiner = 0;
    double radius_edge = 0;  ///< 0: not given
    double max_volume = 0;   ///< 0: not given
    bool quality = false;
    bool no_sliver_removal = false;
    std::string generator = "delaunay-refinement";
    std::string size;                         ///< empty: not given
    std::optional<double> feature_gradation;  ///< not given: the generators' default, 0.5
};

/// `mesh` (of `plc`, after merge_duplicate_vertices_3d) in the input's numbering: the input's
/// vertices (`input_xyz`) first, merged ones included, then the Steiner points; the
/// tetrahedra's corners renumbered, their neighbours unchanged. Empty when nothing was merged.
tri::Tetrahedralization3 in_input_numbering(const tri::Tetrahedralization3& mesh,
                                            const tri::Plc3& plc,
                                            const std::vector<double>& input_xyz) {
    tri::Tetrahedralization3 out;
    if (plc.input_vertex.empty()) return out;
    out.xyz = input_xyz;
    out.xyz.insert(out.xyz.end(), mesh.xyz.begin() + 3 * std::ptrdiff_t{plc.vertex_count()},
                   mesh.xyz.end());
    out.tets = mesh.tets;
    for (std::uint32_t& v : out.tets) v = plc.to_input_vertex(v);
    out.neighbors = mesh.neighbors;
    return out;
}

/// The faces to write in the .face file: every subface once (a boundary face as seen from
/// outside, an internal facet's from its first tetrahedron), with its facet's marker.
void subfaces_with_markers(const tri::ConformingMesh3& conforming, const tri::Plc3& plc,
                           std::vector<std::uint32_t>& faces, std::vector<int>& markers) {
    auto key = [](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        std::array<std::uint32_t, 3> k{a, b, c};
        std::sort(k.begin(), k.end());
        return (std::uint64_t{k[0]} * 0x9E3779B97F4A7C15ull) ^
               (std::uint64_t{k[1]} * 0xC2B2AE3D27D4EB4Full) ^ k[2];
    };
    std::unordered_multimap<std::uint64_t, std::uint32_t> facet_of;
    const auto& sub = conforming.subfaces;
    for (std::size_t s = 0; s < sub.size(); s += 3)
        facet_of.emplace(key(sub[s], sub[s + 1], sub[s + 2]), static_cast<std::uint32_t>(s / 3));
    const tri::Tetrahedralization3& mesh = conforming.mesh;
    for (tri::TetIdx t = 0; t < mesh.tet_count(); ++t) {
        for (unsigned k = 0; k < 4; ++k) {
            const tri::TetIdx n = mesh.neighbors[4 * std::size_t{t} + k];
            if (n != tri::kNone && n < t) continue;  // written from the first tetrahedron
            const unsigned* lf = tri::kFaceVertex[k];
            const std::uint32_t a = mesh.tets[4 * std::size_t{t} + lf[0]],
                                b = mesh.tets[4 * std::size_t{t} + lf[1]],
                                c = mesh.tets[4 * std::size_t{t} + lf[2]];
            const auto range = facet_of.equal_range(key(a, b, c));
            for (auto it = range.first; it != range.second; ++it) {
                const std::size_t s = 3 * std::size_t{it->second};
                std::array<std::uint32_t, 3> x{sub[s], sub[s + 1], sub[s + 2]}, y{a, b, c};
                std::sort(x.begin(), x.end());
                std::sort(y.begin(), y.end());
                if (x != y) continue;
                faces.insert(faces.end(), {a, b, c});
                markers.push_back(plc.facets[conforming.subface_facet[it->second]].marker);
                break;
            }
        }
    }
}

void run_tetmesh(const TetmeshArguments& arguments) {
    if (arguments.input.empty() == arguments.domain.empty())
        throw InputError(
            "give either an input PLC file (.poly, .smesh, .off, .stl) or --domain "
            "NAME (not both)");
    const fs::path output = arguments.output;
    const OutputFormat format = output_format(output);  // before any work: fail fast
    if (format == OutputFormat::Svg) {
        throw InputError(output.string() +
                         ": .svg pictures are 2D only; write tetrahedra as .ele, .msh or .vtu");
    }
    const std::vector<fs::path> files = output_files(output, format, {".node", ".face", ".neigh"});
    if (!arguments.input.empty()) refuse_to_overwrite_inputs({arguments.input}, files);

    tri::Plc3 plc;
    std::string source;
    if (!arguments.domain.empty()) {
        plc = gen::sample_domain_3d(gen::sample_domain_3d_from_name(arguments.domain),
                                    arguments.domain_size);
        source = "--domain " + arguments.domain;
    } else {
        plc = io::plc_from_file(io::read_plc(arguments.input));
        source = arguments.input;
    }
    // The input's own coordinates: a vertex merged into an earlier one at its point is written
    // back as it was read (-0 stays -0).
    const std::vector<double> input_xyz = plc.xyz;
    // The checks' messages name vertices and facets (with their lines); the file is named here.
    try {
        std::vector<std::string> warnings = tri::prepare_plc_for_meshing_3d(plc);
        for (std::string& warning : warnings) warning = source + ": " + warning;
        print_warnings(warnings);
    } catch (const InputError& error) {
        throw InputError(source + ": " + error.what());
    }
    const std::uint32_t base = plc.first_index;

    // The generator and its size, checked before any work.
    const bool frontal = arguments.generator == "frontal";
    const bool octree = arguments.generator == "octree";
    if (!frontal && !octree && arguments.generator != "delaunay-refinement") {
        throw InputError("--generator '" + arguments.generator +
                         "' is not a 3D generator; the generators are: delaunay-refinement, "
                         "frontal, octree");
    }
    gen::FrontalDelaunay3Options frontal_options;
    gen::OctreeMesh3Options octree_options;
    if (frontal || octree) {
        if (arguments.size.empty())
            throw InputError("--generator " + arguments.generator +
                             " needs --size NUM|EXPR (the target edge length)");
        if (arguments.radius_edge > 0 || arguments.max_volume > 0)
            throw InputError(
                "--radius-edge and --max-volume are Delaunay refinement's bounds; --generator " +
                arguments.generator + " takes --size");
        frontal_options.size = size3_from_option(arguments.size);
        frontal_options.max_steiner_points = arguments.max_steiner;
        octree_options.size = frontal_options.size;
        octree_options.max_steiner_points = arguments.max_steiner;
        if (const std::optional<double> g = arguments.feature_gradation) {
            if (!(*g >= 0) || !std::isfinite(*g))
                throw InputError("--feature-gradation must be a finite number >= 0, not " +
                                 format_number(*g));
            frontal_options.feature_gradation = *g;
            octree_options.feature_gradation = *g;
        }
    } else if (!arguments.size.empty()) {
        throw InputError(
            "--size is for --generator frontal or octree; Delaunay refinement takes --max-volume "
            "(and --radius-edge)");
    } else if (arguments.feature_gradation) {
        throw InputError("--feature-gradation is for --generator frontal or octree");
    }

    tri::BoundaryRecovery3Options options;
    options.max_steiner_points = arguments.max_steiner;
    // Region volume bounds (boundary recovery floods them into the tetrahedra) make refinement
    // run, as a global --max-volume does; frontal insertion follows --size only.
    const bool region_bounds = std::any_of(plc.regions.begin(), plc.regions.end(),
                                           [](const tri::Region3& r) { return r.max_volume > 0; });
    const bool refine = !frontal && !octree &&
                        (arguments.radius_edge > 0 || arguments.max_volume > 0 || region_bounds);
    gen::DelaunayRefinement3Options refinement;
    refinement.radius_edge_bound = arguments.radius_edge > 0 ? arguments.radius_edge : 2.0;
    refinement.max_volume = arguments.max_volume;
    refinement.max_steiner_points = arguments.max_steiner;
    const bool remove_slivers = (refine || frontal || octree) && !arguments.no_sliver_removal;
    gen::SliverRemoval3Options sliver_options;
    sliver_options.radius_edge_bound = refinement.radius_edge_bound;
    sliver_options.max_volume = refinement.max_volume;
    struct Meshed {
        tri::BoundaryRecovery3Result recovery;
        gen::DelaunayRefinement3Counters refinement;
        gen::FrontalDelaunay3Counters frontal;
        gen::SizeFunction3 size;  ///< the size frontal insertion followed (graded), for --quality
        gen::OctreeMesh3Counters octree;
        tri::BoundaryRecovery3Counters octree_band_recovery;  ///< the octree's band
        gen::SliverRemoval3Counters slivers;
        tri::Tetrahedralization3 before_sliver_removal;  ///< kept for --quality only
        double sliver_seconds = 0;  ///< sliver removal's share of construct_seconds
    };
    std::vector<std::string> recovery_warnings;
    auto [result, stats, seconds] = timed_construction([&] {
        return naming_the_input(source, [&] {
            Meshed meshed{tri::boundary_recovery_3d_whole_facets(plc, options, recovery_warnings),
                          {},
                          {},
                          frontal_options.size,
                          {},
                          {},
                          {},
                          {},
                          0};
            if (frontal) {
                gen::FrontalDelaunay3Result meshed_frontal =
                    gen::frontal_delaunay_3d(plc, std::move(meshed.recovery.mesh), frontal_options);
                meshed.recovery.mesh = std::move(meshed_frontal.mesh);
                meshed.frontal = meshed_frontal.counters;
                meshed.size = meshed_frontal.size;
            }
            if (octree) {
                gen::OctreeMesh3Result meshed_octree =
                    gen::octree_mesh_3d(plc, meshed.recovery.mesh, octree_options);
                meshed.recovery.mesh = std::move(meshed_octree.mesh);
                meshed.octree = meshed_octree.counters;
                meshed.octree_band_recovery = meshed_octree.band_recovery;
                meshed.frontal = meshed_octree.band_frontal;
                meshed.size = meshed_octree.size;  // capped by the region volume bounds
            }
            // Refinement hands its working mesh to sliver removal unless --quality wants the
            // mesh in between.
            const bool slivers_in_refinement = refine && remove_slivers && !arguments.quality;
            if (refine) {
                gen::DelaunayRefinement3Options refine_options = refinement;
                if (slivers_in_refinement) refine_options.sliver_removal = sliver_options;
                gen::DelaunayRefinement3Result refined = gen::delaunay_refinement_3d(
                    plc, std::move(meshed.recovery.mesh), refine_options);
                meshed.recovery.mesh = std::move(refined.mesh);
                meshed.refinement = refined.counters;
                meshed.slivers = refined.slivers;
                meshed.sliver_seconds = refined.sliver_seconds;
            }
            if (remove_slivers && !slivers_in_refinement) {
                if (arguments.quality) meshed.before_sliver_removal = meshed.recovery.mesh.mesh;
                const auto start = std::chrono::steady_clock::now();
                gen::SliverRemoval3Result improved =
                    gen::sliver_removal_3d(std::move(meshed.recovery.mesh), sliver_options);
                meshed.sliver_seconds = seconds_since(start);
                meshed.recovery.mesh = std::move(improved.mesh);
                meshed.slivers = improved.counters;
            }
            return meshed;
        });
    });
    const tri::ConformingMesh3& conforming = result.recovery.mesh;
    recovery_warnings.insert(recovery_warnings.end(), result.recovery.warnings.begin(),
                             result.recovery.warnings.end());
    for (std::string& warning : recovery_warnings) warning = source + ": " + warning;
    print_warnings(recovery_warnings);

    // Exact check before anything is written: a failure is a bug, never the input's fault.
    const tri::BoundaryConformityReport3 report =
        tri::check_boundary_conformity_3d(plc, conforming);
    if (!report.ok) {
        throw InternalError(source +
                            ": the mesh fails the exact conformity check: " + report.problem);
    }

    // With refinement: every tetrahedron within the bounds, exactly, except those the
    // small-input-angle rule spares and those whose splitting point the generator had to reject
    // (counted: a point equal to an existing vertex, or a cavity that could not stay valid). A
    // tetrahedron over a bound with no rejected point to explain it is a bug. Sliver removal
    // never raises the count of tetrahedra over the bounds (keep_bounds), so this holds after
    // it too.
    gen::RefinementQuality3 quality;
    std::vector<std::string> warnings;
    if (frontal && region_bounds) {
        warnings.push_back(source +
                           ": the region volume bounds are applied by Delaunay refinement only; "
                           "--generator frontal follows --size and ignores them");
    }
    // The octree takes each region's bound V as a size (the regular tetrahedron's edge), which
    // holds the typical tetrahedron near V but not every one: counted exactly and said.
    std::uint64_t over_region_bounds = 0;
    if (octree && region_bounds) {
        const tri::Tetrahedralization3& m = conforming.mesh;
        for (tri::TetIdx t = 0; t < m.tet_count(); ++t) {
            const double bound = gen::tet_volume_bound_3d(conforming, t, 0);
            if (!(bound > 0)) continue;
            const std::uint32_t* v = &m.tets[4 * std::size_t{t}];
            if (predicates::compare_tet_volume_3d(m.point(v[0]), m.point(v[1]), m.point(v[2]),
                                                  m.point(v[3]),
                                                  bound) == predicates::Sign::Positive)
                ++over_region_bounds;
        }
        if (over_region_bounds != 0) {
            warnings.push_back(source + ": " + std::to_string(over_region_bounds) + " of " +
                               std::to_string(m.tet_count()) +
                               " tetrahedra exceed their region's volume bound: --generator "
                               "octree follows each bound as a size (the edge of the regular "
                               "tetrahedron of that volume); --generator delaunay-refinement "
                               "holds every tetrahedron to it");
        }
    }
    if (refine) {
        quality = gen::check_refinement_quality_3d(conforming, refinement);
        const std::uint64_t over = quality.over_bound + quality.over_volume;
        const std::string text = std::to_string(quality.over_bound) +
                                 " tetrahedra exceed the radius-edge bound and " +
                                 std::to_string(quality.over_volume) + " the volume bound";
        if (over != 0 && result.refinement.rejected_points == 0)
            throw InternalError(source + ": " + text + " after refinement (exact check)");
        if (quality.unresolvable != 0) {
            warnings.push_back(source + ": " + std::to_string(quality.unresolvable) +
                               " tetrahedra over the radius-edge bound were left: each has an "
                               "edge finer than doubles resolve at its place (below 2^-44 of its "
                               "coordinates), where no rounded point can improve it");
        }
        if (over != 0) {
            warnings.push_back(source + ": " + text + " after refinement: " +
                               std::to_string(result.refinement.rejected_points) +
                               " splitting points were rejected");
        }
    }

    EM_ASSERT(conforming.tet_attributes.empty() ||
              conforming.tet_attributes.size() == conforming.mesh.tet_count());
    // In the input's numbering: vertices merged at one point (merge_duplicate_vertices_3d) are
    // written back, unused, and the Steiner points follow them.
    const tri::Tetrahedralization3 renumbered = in_input_numbering(conforming.mesh, plc, input_xyz);
    const tri::Tetrahedralization3& mesh = plc.input_vertex.empty() ? conforming.mesh : renumbered;
    io::OutputSet set;
    switch (format) {
        case OutputFormat::Ele: {
            std::vector<std::uint32_t> faces;
            std::vector<int> markers;
            subfaces_with_markers(conforming, plc, faces, markers);
            for (std::uint32_t& v : faces) v = plc.to_input_vertex(v);
            // Region attributes (a .poly/.smesh with regions; every generator carries them
            // through) as TetGen -A writes them: one column after the corners.
            set.stage(files[0], io::format_tetgen_ele(mesh.tets, base, conforming.tet_attributes));
            set.stage(files[1], io::format_tetgen_node(mesh.xyz, base));
            set.stage(files[2], io::format_tetgen_marked_faces(faces, markers, base));
            set.stage(files[3], io::format_tetgen_neigh(mesh.neighbors, base));
            break;
        }
        case OutputFormat::Msh:
            set.stage(output, io::format_msh_3d(mesh.xyz, mesh.tets));
            break;
        case OutputFormat::Vtu:
            set.stage(output, io::format_vtu_3d(mesh.xyz, mesh.tets, base));
            break;
        case OutputFormat::Svg:
            break;  // refused above
    }
    commit_outputs(set);
    print_warnings(warnings);
    std::cout << "vertices: " << mesh.vertex_count() << '\n'
              << "tetrahedra: " << mesh.tet_count() << '\n';
    if (arguments.quality) {
        if (remove_slivers)
            print_quality_3d(result.before_sliver_removal, "before_sliver_removal_");
        print_quality_3d(mesh);
        if (frontal || octree) {
            // Edge length over the size followed at its midpoint (frontal: --size graded to the
            // input's feature sizes), once per edge.
            const gen::SizeConformity3 c = gen::size_conformity_3d(mesh, result.size);
            const auto precision = std::cout.precision(6);
            std::cout << "size_conformity: min " << c.min << " median " << c.median << " mean "
                      << c.mean << " max " << c.max << " (edge length / size at its midpoint, "
                      << c.edges << " edges, " << 100 * c.within << "% in [0.7, 1.4])\n";
            std::cout.precision(precision);
        }
    }
    if (arguments.stats) {
        auto counters =
            counters_by_name(tri::kBoundaryRecovery3CounterNames, result.recovery.counters);
        if (refine) {
            for (auto& [name, value] :
                 counters_by_name(gen::kDelaunayRefinement3CounterNames, result.refinement))
                counters.emplace_back("refinement_" + name, value);
            counters.emplace_back("spared_small_angle_tets", quality.small_angle);
            counters.emplace_back("spared_unresolvable_tets", quality.unresolvable);
            counters.emplace_back("over_bound_tets", quality.over_bound + quality.over_volume);
        }
        if (frontal) {
            for (auto& [name, value] :
                 counters_by_name(gen::kFrontalDelaunay3CounterNames, result.frontal))
                counters.emplace_back("frontal_" + name, value);
        }
        if (octree) {
            for (auto& [name, value] :
                 counters_by_name(gen::kOctreeMesh3CounterNames, result.octree))
                counters.emplace_back("octree_" + name, value);
            if (region_bounds) counters.emplace_back("over_region_bound_tets", over_region_bounds);
            for (auto& [name, value] :
                 counters_by_name(tri::kBoundaryRecovery3CounterNames, result.octree_band_recovery))
                counters.emplace_back("octree_band_recovery_" + name, value);
            for (auto& [name, value] :
                 counters_by_name(gen::kFrontalDelaunay3CounterNames, result.frontal))
                counters.emplace_back("octree_band_frontal_" + name, value);
        }
        if (remove_slivers) {
            for (auto& [name, value] :
                 counters_by_name(gen::kSliverRemoval3CounterNames, result.slivers))
                counters.emplace_back("sliver_removal_" + name, value);
        }
        print_construction_stats(counters, stats, seconds, 3);
        // Reported apart (issue 15), and included in construct_seconds.
        if (remove_slivers) {
            std::cout << "sliver_removal_seconds: " << std::fixed << std::setprecision(6)
                      << result.sliver_seconds << '\n';
        }
    }
}

}  // namespace

void add_tetmesh_command(CLI::App& app) {
    auto arguments = std::make_shared<TetmeshArguments>();
    CLI::App* command = app.add_subcommand(
        "tetmesh",
        "Tetrahedral mesh of a 3D domain (a piecewise linear complex): conforming Delaunay "
        "boundary recovery, optionally Delaunay refinement, checked exactly");
    command
        ->add_option("input", arguments->input,
                     "The domain's boundary: TetGen .poly or .smesh, .off or .stl")
        ->type_name("IN.poly|IN.smesh|IN.off|IN.stl");
    command
        ->add_option("--domain", arguments->domain,
                     "A built-in domain instead of a file: box-with-hole, ellipsoid, wing")
        ->type_name("NAME");
    command
        ->add_option("--domain-size", arguments->domain_size,
                     "Target edge length of a built-in domain's curved surfaces (default: the "
                     "domain's own)")
        ->check(finite_positive_number());
    add_output_option(*command, arguments->output,
                      "Output; the extension picks the format: .ele (TetGen; .node, .face with "
                      "facet markers and .neigh beside it), .msh (Gmsh 4.1), .vtu (VTK)");
    command
        ->add_option("--max-steiner", arguments->max_steiner,
                     "Most Steiner points of boundary recovery and, separately, of refinement (0: "
                     "100 per input vertex plus 100,000 for recovery, 1,000 per input vertex plus "
                     "10^6 for refinement); past it the command stops with an error")
        ->check(whole_number_at_most(UINT32_MAX));
    command
        ->add_option("--radius-edge", arguments->radius_edge,
                     "Delaunay refinement (generators/mesh_3d/delaunay_refinement_3d): split "
                     "every tetrahedron whose circumradius / shortest edge exceeds B (TetGen "
                     "-q; 2 when only volume bounds are given). Without --radius-edge, "
                     "--max-volume and region volume bounds in the input the mesh is the "
                     "recovered one, unrefined")
        ->type_name("B")
        ->check(finite_positive_number());
    command
        ->add_option("--max-volume", arguments->max_volume,
                     "Delaunay refinement: split every tetrahedron of larger volume (TetGen -a); "
                     "region volume bounds of the input apply too, the smaller of the two")
        ->type_name("V")
        ->check(finite_positive_number());
    command
        ->add_option("--generator", arguments->generator,
                     "The mesh generator after boundary recovery: delaunay-refinement (the "
                     "default; runs when --radius-edge or --max-volume is given) or frontal "
                     "(generators/mesh_3d/frontal_delaunay_3d: Rebay's frontal point placement "
                     "with Bowyer-Watson insertion; needs --size) or octree "
                     "(generators/mesh_3d/octree_mesh_3d: a 2:1 balanced octree at the size, "
                     "core leaves cut by templates, the band at the boundary meshed by recovery "
                     "and frontal insertion; needs --size)")
        ->type_name("NAME");
    command
        ->add_option(
            "--size", arguments->size,
            "--generator frontal or octree: the target edge length, a number or an expression in "
            "x, y, z (muParser: '0.05 + 0.1 * sqrt(x^2 + y^2 + z^2)')")
        ->type_name("NUM|EXPR");
    command
        ->add_option("--feature-gradation", arguments->feature_gradation,
                     "--generator frontal or octree: grade the size down to the input's free "
                     "vertices whose nearest feature (another vertex, a facet) is closer than "
                     "the size / sqrt 2 (and any vertex's closer than the size / 1024): "
                     "min(size, f + G |x - v|) (generators/mesh_3d/feature_size_3d; default "
                     "0.5, 0 = the size as given)")
        ->type_name("G");
    command->add_flag("--no-sliver-removal", arguments->no_sliver_removal,
                      "Keep the refined mesh as Delaunay refinement leaves it: no sliver removal "
                      "(generators/mesh_3d/sliver_removal_3d: MaxMinDihedral edge-face swapping "
                      "keeping subfaces and subsegments, smoothing of interior Steiner points, "
                      "on tetrahedra with a dihedral angle below 15 degrees; on by default after "
                      "refinement)");
    command->add_flag("--quality", arguments->quality,
                      "Print the mesh's quality: dihedral extremes and 10-degree histogram, "
                      "volume-edge, radius-edge (largest, count over 2, histogram of 0.2-wide "
                      "bins up to 4), slivers (after sliver removal; the same before "
                      "it prefixed before_sliver_removal_)");
    add_stats_flag(*command, arguments->stats,
                   "the recovery's and refinement's counters, predicate stages",
                   "the construction alone, without file I/O or the check");
    command->callback([arguments] { run_tetmesh(*arguments); });
}

}  // namespace exactmesh::cli
