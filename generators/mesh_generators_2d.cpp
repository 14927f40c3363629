// SPDX-License-Identifier: MIT
// The registry of the 2D mesh generators: one adapter per generator from MeshOptions2 to the
// generator's own options.
#include "generators/mesh_generators_2d.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <string>

#include "generators/advancing_front_2d.hpp"
#include "generators/advancing_front_delaunay_2d.hpp"
#include "generators/frontal_delaunay_2d.hpp"
#include "generators/quadtree_mesh_2d.hpp"
#include "predicates/errors.hpp"

namespace exactmesh::generators {

namespace tri = exactmesh::triangulation;

std::vector<std::pair<std::string, std::uint64_t>> counter_list(const RefinementCounters2& c) {
    return {{"steiner_points", c.steiner_points()},
            {"circumcenters", c.circumcenters},
            {"segment_splits", c.segment_splits},
            {"shell_splits", c.shell_splits},
            {"segment_bends", c.segment_bends},
            {"rejected_circumcenters", c.rejected_circumcenters},
            {"bad_triangles_queued", c.bad_triangles},
            {"small_angle_skips", c.small_angle_skips},
            {"unsplittable", c.unsplittable},
            {"cavity_triangles", c.cavity_triangles},
            {"delaunay_flips", c.flips},
            {"circumcenter_exact_path", c.circumcenter_exact},
            {"orient_calls", c.orient_calls},
            {"incircle_calls", c.incircle_calls},
            {"encroachment_tests", c.encroachment_tests},
            {"polish_points", c.polish_points},
            {"polish_stopped", c.polish_stopped}};
}

namespace {

MeshRun2 run_delaunay_refinement(const tri::Pslg& pslg, const MeshOptions2& options) {
    RefinementOptions2 refinement;
    refinement.min_angle = options.min_angle;
    refinement.polish_angle = options.polish_angle;
    refinement.size = options.size;
    refinement.max_steiner_points = options.max_steiner_points;
    refinement.cdt = options.cdt;
    RefinementResult2 result = delaunay_refinement_2d(pslg, refinement);
    if (result.counters.unsplittable > 0) {
        result.mesh.warnings.push_back(
            std::to_string(result.counters.unsplittable) +
            " bad triangles are too small to split in double precision; left as they are");
    }
    return {std::move(result.mesh), counter_list(result.counters)};
}

MeshRun2 run_quadtree(const tri::Pslg& pslg, const MeshOptions2& options) {
    QuadtreeOptions2 quadtree;
    quadtree.size = options.size;
    quadtree.cdt = options.cdt;
    // The shared budget counts Steiner points; a leaf adds about one vertex.
    quadtree.max_leaves = options.max_steiner_points;
    QuadtreeResult2 result = quadtree_mesh_2d(pslg, quadtree);
    return {std::move(result.mesh), counter_list(result.counters)};
}

MeshRun2 run_advancing_front(const tri::Pslg& pslg, const MeshOptions2& options) {
    AdvancingFrontOptions2 front;
    front.size = options.size;
    // The shared budget counts Steiner points; a triangle adds about half a point.
    front.max_triangles =
        std::min(options.max_steiner_points, std::numeric_limits<std::uint64_t>::max() / 2) * 2;
    front.cdt = options.cdt;
    AdvancingFrontResult2 result = advancing_front_2d(pslg, front);
    if (result.counters.closure_triangles > 0) {
        result.mesh.warnings.push_back(
            "the triangle budget ran out: " + std::to_string(result.counters.closure_triangles) +
            " triangles close the front by its constrained Delaunay triangulation");
    }
    return {std::move(result.mesh), counter_list(result.counters)};
}

MeshRun2 run_advancing_front_delaunay(const tri::Pslg& pslg, const MeshOptions2& options) {
    AdvancingFrontDelaunayOptions2 front;
    front.size = options.size;
    front.max_new_points = options.max_steiner_points;
    front.cdt = options.cdt;
    AdvancingFrontDelaunayResult2 result = advancing_front_delaunay_2d(pslg, front);
    if (result.counters.closure_triangles > 0) {
        result.mesh.warnings.push_back(
            std::to_string(result.counters.closure_front_edges) +
            " front edges were left to the closure (constrained Delaunay, no new points): " +
            std::to_string(result.counters.closure_triangles) + " triangles");
    }
    return {std::move(result.mesh), counter_list(result.counters)};
}

MeshRun2 run_frontal_delaunay(const tri::Pslg& pslg, const MeshOptions2& options) {
    FrontalDelaunayOptions2 frontal;
    frontal.size = options.size;
    frontal.max_steiner_points = options.max_steiner_points;
    frontal.cdt = options.cdt;
    FrontalDelaunayResult2 result = frontal_delaunay_2d(pslg, frontal);
    return {std::move(result.mesh), counter_list(result.counters)};
}

constexpr std::array kGenerators{
    MeshGenerator2{"delaunay-refinement",
                   "Ruppert/Shewchuk: circumcenters of the worst triangles, encroached pieces "
                   "split first; guaranteed minimum angle",
                   true, false, &run_delaunay_refinement},
    MeshGenerator2{"quadtree",
                   "Yerry-Shephard/Baehmann: balanced quadtree leaves as 45-45-90 templates, "
                   "the band along the boundary by a refined constrained Delaunay triangulation",
                   false, true, &run_quadtree},
    MeshGenerator2{"advancing-front",
                   "Lo/Peraire/Lohner: shortest front edge first, apex on its median at the local "
                   "size or a nearby front vertex, exact acceptance tests; needs a size",
                   false, true, &run_advancing_front},
    MeshGenerator2{"advancing-front-delaunay",
                   "Mavriplis: shortest front edge first, a point at the circumradius bound, the "
                   "Tanemura-Merriam (Delaunay) choice among nearby front points; needs a size",
                   false, true, &run_advancing_front_delaunay},
    MeshGenerator2{"frontal",
                   "Rebay: points placed from the boundary inwards on the front edges' "
                   "bisectors, inserted by Bowyer-Watson; needs a size",
                   true, true, &run_frontal_delaunay},
};

}  // namespace

std::span<const MeshGenerator2> mesh_generators_2d() {
    return kGenerators;
}

const MeshGenerator2& find_mesh_generator_2d(std::string_view name) {
    for (const MeshGenerator2& g : kGenerators) {
        if (g.name == name) return g;
    }
    std::string known;
    for (const MeshGenerator2& g : kGenerators) {
        known += known.empty() ? "" : ", ";
        known += g.name;
    }
    throw InputError("unknown generator '" + std::string(name) + "' (known: " + known + ")");
}

}  // namespace exactmesh::generators
