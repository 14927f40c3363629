// SPDX-License-Identifier: MIT
// The registry of the 2D mesh generators: one adapter per generator from MeshOptions2 to the
// generator's own options.
#include "generators/mesh_2d/mesh_generators_2d.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <string>

#include "base/enum_names.hpp"
#include "base/errors.hpp"
#include "base/number_text.hpp"
#include "generators/boundary/graded_boundary_size_2d.hpp"
#include "generators/boundary/region_areas_2d.hpp"
#include "generators/mesh_2d/advancing_front_2d.hpp"
#include "generators/mesh_2d/advancing_front_delaunay_2d.hpp"
#include "generators/mesh_2d/frontal_delaunay_2d.hpp"
#include "generators/mesh_2d/quadtree_mesh_2d.hpp"
#include "generators/sizing/triangle_subdivision_2d.hpp"
#include "generators/stretched/metric_delaunay_2d.hpp"
#include "generators/stretched/min_max_front_2d.hpp"
#include "generators/stretched/stretched_delaunay_2d.hpp"

namespace exactmesh::generators {

namespace tri = exactmesh::triangulation;

std::vector<std::pair<std::string, std::uint64_t>> counter_list(const RefinementCounters2& c) {
    return counters_by_name(kRefinementCounterNames, c);
}

namespace {

/// The samples of minimum_triangle_count: each checked, counted against a fixed budget of
/// evaluations (about 10 ms of a parsed expression) beyond one pass over the domain.
class SizeSampler {
  public:
    SizeSampler(const SizeFunction& size, double stop_above)
        : size_(size), stop_above_(stop_above) {}

    double at(double x, double y) {
        ++evaluations_;
        const double s = size_(x, y);
        if (!(s > 0) || !std::isfinite(s)) {
            throw InputError("the size function (" + size_.describe() + ") is " + format_number(s) +
                             " at (" + format_number(x) + ", " + format_number(y) +
                             "), inside the domain: a size must be finite and > 0 everywhere "
                             "in the domain");
        }
        return s;
    }

    /// The triangle (p, q, r) at the largest of the sizes sampled at its corners sp, sq, sr
    /// and its centroid; split in four while those differ by more than a factor 2 and the
    /// triangle at the smallest of them would count for at least 2^-12 of the budget: only
    /// such a triangle can move the estimate toward the budget, and splitting every graded
    /// triangle resolved the whole size field (an airfoil's check cost as much as meshing it).
    /// Depth first on an explicit stack (subdivision_sum_2d: recursion made AddressSanitizer's
    /// stack depot grow with every path down the subdivision).
    double triangle(const std::array<double, 2>& p, const std::array<double, 2>& q,
                    const std::array<double, 2>& r, double sp, double sq, double sr) {
        using Point = std::array<double, 2>;
        struct Node {
            std::array<Point, 3> corner;
            std::array<double, 3> size;
        };
        const auto visit = [&](const Node& n, int depth,
                               std::array<Node, 4>& children) -> std::optional<double> {
            const auto& [a, b, c] = n.corner;
            const double sc = at((a[0] + b[0] + c[0]) / 3, (a[1] + b[1] + c[1]) / 3);
            const double lo = std::min({n.size[0], n.size[1], n.size[2], sc});
            const double hi = std::max({n.size[0], n.size[1], n.size[2], sc});
            if (!(hi > 2 * lo && depth < kMaxDepth && evaluations_ < kSplitEvaluations &&
                  total_ <= stop_above_ && count_at(a, b, c, lo) >= 0x1p-12 * stop_above_))
                return count_at(a, b, c, hi);
            const auto mid = [](const Point& u, const Point& v) {
                return Point{0.5 * u[0] + 0.5 * v[0], 0.5 * u[1] + 0.5 * v[1]};
            };
            const Point ab = mid(a, b), bc = mid(b, c), ca = mid(c, a);
            const double sab = at(ab[0], ab[1]), sbc = at(bc[0], bc[1]), sca = at(ca[0], ca[1]);
            children = {
                Node{{a, ab, ca}, {n.size[0], sab, sca}}, Node{{ab, b, bc}, {sab, n.size[1], sbc}},
                Node{{ca, bc, c}, {sca, sbc, n.size[2]}}, Node{{ab, bc, ca}, {sab, sbc, sca}}};
            return std::nullopt;
        };
        return subdivision_sum_2d(Node{{p, q, r}, {sp, sq, sr}}, visit);
    }

    /// Equilateral triangles of side s in (p, q, r) (triangles_of_side: no square of a
    /// coordinate, 2^600 or 2^-600, is formed; an overflow means an enormous count).
    static double count_at(const std::array<double, 2>& p, const std::array<double, 2>& q,
                           const std::array<double, 2>& r, double s) {
        return triangles_of_side(p.data(), q.data(), r.data(), s);
    }

    void add(double count) { total_ += count; }
    double total() const { return total_; }

  private:
    static constexpr std::uint64_t kSplitEvaluations = 1u << 18;
    static constexpr int kMaxDepth = 12;
    const SizeFunction& size_;
    double stop_above_;
    double total_ = 0;
    std::uint64_t evaluations_ = 0;
};

}  // namespace

double minimum_triangle_count(const tri::Triangulation2& domain, const SizeFunction& size,
                              double stop_above) {
    if (!size.bounded()) return 0;
    SizeSampler sampler(size, stop_above);
    // One sample per vertex of a domain triangle, shared by its triangles.
    std::vector<double> at_vertex(domain.vertex_count(), 0);
    for (const tri::VertIdx v : domain.triangles) {
        if (at_vertex[v] == 0) at_vertex[v] = sampler.at(domain.xy[2 * v], domain.xy[2 * v + 1]);
    }
    for (tri::TriIdx t = 0; t < domain.triangle_count() && sampler.total() <= stop_above; ++t) {
        std::array<std::array<double, 2>, 3> corner;
        std::array<double, 3> s;
        for (unsigned k = 0; k < 3; ++k) {
            const tri::VertIdx v = domain.triangles[3 * t + k];
            corner[k] = {domain.xy[2 * v], domain.xy[2 * v + 1]};
            s[k] = at_vertex[v];
        }
        sampler.add(sampler.triangle(corner[0], corner[1], corner[2], s[0], s[1], s[2]));
    }
    return sampler.total();
}

void refuse_sample_domain_size_far_over_budget(SampleDomain sample, const SizeFunction& size) {
    const DomainPslg coarse = sample_domain(sample);
    const MeshDomain2 domain(tri::Pslg{coarse.xy, coarse.segments, coarse.holes, {}});
    MeshOptions2 options;
    options.size = size;
    const double far = 64 * kAutomaticTriangleBudget;
    double estimate = 0;
    try {
        estimate = minimum_triangle_count(domain.triangulation().mesh, size, far);
    } catch (const InputError&) {
        return;  // a size not > 0 somewhere: reported over the domain itself
    }
    if (estimate > far) check_size_budget(domain, options, false);
}

void check_size_budget(const MeshDomain2& domain_of, const MeshOptions2& options,
                       bool hard_budget) {
    const tri::Pslg& pslg = domain_of.pslg();
    const bool areas = has_region_areas(pslg.regions);
    if (!options.size.bounded() && !areas) return;
    // The domain built once, its triangles numbered by region when some region has an area
    // (MeshDomain2). Under Conforming recovery it is the Swap triangulation of the same region:
    // the estimate integrates over the region, so it needs no conforming triangulation of its
    // own (one used to be built here, a second CDT of the input, which could also fail where
    // the domain does not).
    const tri::Cdt2Result& domain = domain_of.triangulation();
    const double inputs = static_cast<double>(pslg.xy.size() / 2);
    const bool given = hard_budget && options.max_steiner_points != 0;
    // A triangulation of V vertices has fewer than 2V triangles.
    const double budget = given ? 2 * (static_cast<double>(options.max_steiner_points) + inputs)
                                : kAutomaticTriangleBudget;
    const double by_size = minimum_triangle_count(domain.mesh, options.size, budget);
    // Both are lower estimates of the count; the larger one is kept (a region's triangles
    // answer to both).
    const double by_area = areas ? region_area_triangle_count(domain, pslg.regions) : 0.0;
    const double estimate = std::max(by_size, by_area);
    if (estimate > budget) {
        const std::string what = by_area > by_size
                                     ? "the regions' maximum areas ask"
                                     : "the size (" + options.size.describe() + ") asks";
        throw InputError(
            what + " for " +
            (estimate > 1e300 ? std::string("far more than 1e300")
                              : "about " + format_approximate(estimate) + " or more") +
            " triangles over the domain, more than the " +
            (given ? "--max-steiner budget of about " + format_approximate(budget) + " triangles"
                   : "automatic budget of " + format_approximate(budget) +
                         " triangles (raise it with --max-steiner)") +
            (by_area > by_size ? (given ? ": give larger maximum areas or raise --max-steiner"
                                        : ": give larger maximum areas")
                               : (given ? ": give a larger size or raise --max-steiner"
                                        : ": give a larger size")));
    }
}

namespace {

void refuse_region_areas(const tri::Pslg& pslg, const MeshOptions2& options,
                         std::string_view generator) {
    for (std::size_t r = 0; 4 * r + 3 < pslg.regions.size(); ++r) {
        if (pslg.regions[4 * r + 3] > 0) {
            throw InputError("region " + std::to_string(r + options.cdt.first_index) +
                             " has a maximum area (" + format_number(pslg.regions[4 * r + 3]) +
                             "): region maximum areas are honoured by delaunay-refinement and "
                             "frontal only, not by " +
                             std::string(generator));
        }
    }
}

MeshRun2 run_delaunay_refinement(const MeshDomain2& domain, const MeshOptions2& options) {
    const tri::Pslg& pslg = domain.pslg();
    check_size_budget(domain, options, true);
    RefinementOptions2 refinement;
    refinement.min_angle = options.min_angle;
    refinement.polish_angle = options.polish_angle;
    refinement.size = options.size;
    refinement.max_steiner_points = options.max_steiner_points;
    refinement.cdt = options.cdt;
    refinement.order = options.refinement_order;
    refinement.threads = options.threads;
    RefinementResult2 result = delaunay_refinement_2d(pslg, refinement);
    if (result.counters.unsplittable > 0) {
        result.mesh.warnings.push_back(
            std::to_string(result.counters.unsplittable) +
            " bad triangles are too small to split in double precision; left as they are");
    }
    MeshRun2 run{std::move(result.mesh), {}, counter_list(result.counters), {}, {}};
    if (result.counters.rounds > 0) run.phase_seconds = phase_list(result.round_seconds);
    return run;
}

/// The options with the size graded down to the domain's fine features (free vertices far
/// closer to another feature than the size: graded_to_fine_features), as the generators that
/// place points at the size follow it; Delaunay refinement needs no such grading.
MeshOptions2 with_fine_features(const MeshDomain2& domain, const MeshOptions2& options) {
    MeshOptions2 graded = options;
    graded.size = graded_to_fine_features(domain, options.size);
    return graded;
}

/// MeshOptions2::max_boundary_points, or the Steiner budget when it is 0.
std::uint64_t boundary_budget(const MeshOptions2& options) {
    return options.max_boundary_points != 0 ? options.max_boundary_points
                                            : options.max_steiner_points;
}

MeshRun2 run_quadtree(const MeshDomain2& domain, const MeshOptions2& given) {
    const MeshOptions2 options = with_fine_features(domain, given);
    check_size_budget(domain, options, true);
    QuadtreeOptions2 quadtree;
    quadtree.size = options.size;
    quadtree.cdt = options.cdt;
    // The shared budget counts Steiner points; a leaf adds about one vertex.
    quadtree.max_leaves = options.max_steiner_points;
    quadtree.max_boundary_points = options.max_boundary_points;
    QuadtreeResult2 result = quadtree_mesh_2d(domain, quadtree);
    return {std::move(result.mesh), {}, counter_list(result.counters), {}, {}};
}

MeshRun2 run_advancing_front(const MeshDomain2& domain, const MeshOptions2& given) {
    const MeshOptions2 options = with_fine_features(domain, given);
    check_size_budget(domain, options, false);
    AdvancingFrontOptions2 front;
    front.size = options.size;
    // The shared budget counts Steiner points; a triangle adds about half a point.
    front.max_triangles =
        std::min(options.max_steiner_points, std::numeric_limits<std::uint64_t>::max() / 2) * 2;
    front.max_boundary_points = boundary_budget(options);
    front.cdt = options.cdt;
    AdvancingFrontResult2 result = advancing_front_2d(domain, front);
    if (result.counters.closure_triangles > 0) {
        result.mesh.warnings.push_back(
            "the triangle budget ran out: " + std::to_string(result.counters.closure_triangles) +
            " triangles close the front by its constrained Delaunay triangulation");
    }
    return {std::move(result.mesh), {}, counter_list(result.counters), {}, {}};
}

MeshRun2 run_advancing_front_delaunay(const MeshDomain2& domain, const MeshOptions2& given) {
    const MeshOptions2 options = with_fine_features(domain, given);
    check_size_budget(domain, options, false);
    AdvancingFrontDelaunayOptions2 front;
    front.size = options.size;
    front.max_new_points = options.max_steiner_points;
    front.max_boundary_points = boundary_budget(options);
    front.cdt = options.cdt;
    AdvancingFrontDelaunayResult2 result = advancing_front_delaunay_2d(domain, front);
    if (result.counters.closure_triangles > 0) {
        result.mesh.warnings.push_back(
            std::to_string(result.counters.closure_front_edges) +
            " front edges were left to the closure (constrained Delaunay, no new points): " +
            std::to_string(result.counters.closure_triangles) + " triangles");
    }
    return {std::move(result.mesh), {}, counter_list(result.counters), {}, {}};
}

MeshRun2 run_frontal_delaunay(const MeshDomain2& domain, const MeshOptions2& given) {
    const MeshOptions2 options = with_fine_features(domain, given);
    check_size_budget(domain, options, true);
    FrontalDelaunayOptions2 frontal;
    frontal.size = options.size;
    frontal.max_steiner_points = options.max_steiner_points;
    frontal.max_boundary_points = options.max_boundary_points;
    frontal.cdt = options.cdt;
    FrontalDelaunayResult2 result = frontal_delaunay_2d(domain, frontal);
    return {std::move(result.mesh), {}, counter_list(result.counters), {}, {}};
}

/// The fill of advancing-layers: frontal Delaunay over the layers' outside.
tri::Cdt2Result frontal_fill(const MeshDomain2& domain, const SizeFunction& size,
                             std::uint64_t max_steiner_points) {
    FrontalDelaunayOptions2 frontal;
    frontal.size = size;
    frontal.max_steiner_points = max_steiner_points;
    return std::move(frontal_delaunay_2d(domain, frontal).mesh);
}

MeshRun2 run_advancing_layers(const MeshDomain2& domain, const MeshOptions2& options) {
    check_size_budget(domain, options, false);
    AdvancingLayersOptions2 layers;
    layers.layers = options.layers;
    layers.size = options.size;
    layers.cdt = options.cdt;
    layers.max_steiner_points = options.max_steiner_points;
    layers.fill = &frontal_fill;
    AdvancingLayersResult2 result = advancing_layers_2d(domain, layers);
    return {std::move(result.mesh), std::move(result.quads), counter_list(result.counters), {}, {}};
}

MeshRun2 run_metric_delaunay(const MeshDomain2& domain, const MeshOptions2& options) {
    MetricDelaunayOptions2 metric;
    if (options.metric) {
        metric.metric = *options.metric;
    } else if (options.size.bounded()) {
        // No metric: the isotropic metric of the size (unit metric length = the size's length,
        // graded to the domain's fine features), under the size budget every generator checks.
        const MeshOptions2 graded = with_fine_features(domain, options);
        check_size_budget(domain, graded, true);
        const SizeFunction size = graded.size;
        metric.metric =
            MetricField2::analytic([size](double x, double y) { return isotropic(size(x, y)); },
                                   "isotropic, the size " + size.describe());
    } else {
        throw InputError(
            "--generator metric-delaunay needs a metric field (--metric 'M11;M12;M22' or a "
            "metric file) or a size (--size): it meshes to unit edge lengths in that metric");
    }
    metric.max_steiner_points = options.max_steiner_points;
    metric.cdt = options.cdt;
    MetricDelaunayResult2 result = metric_delaunay_2d(domain, metric);
    return {std::move(result.mesh), {}, counter_list(result.counters), {}, {}};
}

MeshRun2 run_stretched_delaunay(const MeshDomain2& domain, const MeshOptions2& options) {
    if (!(options.layers.first_height > 0)) {
        // No layers (the registry's loops over every generator; the command requires --layers):
        // nothing is stretched, and the far field alone of stretched_delaunay_2d (quadtree
        // centres kept 0.7 sizes from the boundary's points) can leave slivers beside a boundary
        // piece, so the isotropic metric Delaunay mesh of the size stands in.
        MeshOptions2 isotropic = options;
        if (!isotropic.metric && !isotropic.size.bounded())
            isotropic.size = graded_size_from_boundary(domain);
        return run_metric_delaunay(domain, isotropic);
    }
    check_size_budget(domain, options, true);
    StretchedDelaunayOptions2 stretched;
    stretched.first_height = options.layers.first_height;
    stretched.growth = options.layers.growth;
    stretched.max_layers = static_cast<int>(options.layers.max_layers);
    stretched.far_field_size = options.size;
    stretched.max_points = options.max_steiner_points;
    stretched.wake_length = options.wake_length;
    stretched.staggered_layers = options.staggered_layers;
    StretchedDelaunayResult2 result = stretched_delaunay_2d(domain, stretched);
    return {
        std::move(result.mesh), {}, counter_list(result.counters), std::move(result.metrics), {}};
}

MeshRun2 run_min_max_front(const MeshDomain2& domain, const MeshOptions2& options) {
    check_size_budget(domain, options, false);
    MinMaxFrontResult2 result =
        min_max_front_2d(domain, {.layers = options.layers,
                                  .size = options.size,
                                  .max_steiner_points = options.max_steiner_points});
    return {std::move(result.mesh), {}, counter_list(result.counters), {}, {}};
}

constexpr std::array kGenerators{
    MeshGenerator2{"delaunay-refinement",
                   "Ruppert/Shewchuk: circumcenters of the worst triangles, encroached pieces "
                   "split first; guaranteed minimum angle",
                   true,
                   false,
                   {MeshOption::Size, MeshOption::MinAngle, MeshOption::PolishAngle,
                    MeshOption::MaxSteinerPoints, MeshOption::RegionAttributes,
                    MeshOption::RegionAreas, MeshOption::Threads},
                   &run_delaunay_refinement},
    MeshGenerator2{"quadtree",
                   "Yerry-Shephard/Baehmann: balanced quadtree leaves as 45-45-90 templates, "
                   "the band along the boundary by a refined constrained Delaunay triangulation",
                   false,
                   true,
                   {MeshOption::Size, MeshOption::MaxSteinerPoints},
                   &run_quadtree},
    MeshGenerator2{"advancing-front",
                   "Lo/Peraire/Lohner: shortest front edge first, apex on its median at the local "
                   "size or a nearby front vertex, exact acceptance tests; needs a size",
                   false,
                   true,
                   {MeshOption::Size, MeshOption::MaxSteinerPoints},
                   &run_advancing_front},
    MeshGenerator2{"advancing-front-delaunay",
                   "Mavriplis: shortest front edge first, a point at the circumradius bound, the "
                   "Tanemura-Merriam (Delaunay) choice among nearby front points; needs a size",
                   false,
                   true,
                   {MeshOption::Size, MeshOption::MaxSteinerPoints},
                   &run_advancing_front_delaunay},
    MeshGenerator2{"frontal",
                   "Rebay: points placed from the boundary inwards on the front edges' "
                   "bisectors, inserted by Bowyer-Watson; needs a size",
                   true,
                   true,
                   {MeshOption::Size, MeshOption::MaxSteinerPoints, MeshOption::RegionAttributes,
                    MeshOption::RegionAreas},
                   &run_frontal_delaunay},
    MeshGenerator2{"metric-delaunay",
                   "Borouchaki-George-Hecht: boundary and edges split to unit length in a metric "
                   "field, points inserted by Bowyer-Watson with the exact in-ellipse, then "
                   "in-ellipse swaps; --metric, else the isotropic metric of the size",
                   false,
                   true,
                   {MeshOption::Size, MeshOption::MaxSteinerPoints, MeshOption::Metric},
                   &run_metric_delaunay},
    MeshGenerator2{"advancing-layers",
                   "Pirzadeh/Garimella-Shephard: boundary layers along the walls (hole loops) "
                   "from --layers, stacks stopped exactly at aspect ratio 1 or a collision, the "
                   "rest by frontal from the last layer; --quads keeps the layer quadrilaterals",
                   false,
                   false,
                   {MeshOption::Size, MeshOption::MaxSteinerPoints, MeshOption::Layers},
                   &run_advancing_layers},
    MeshGenerator2{"stretched-delaunay",
                   "Mavriplis: structured O-meshes about each wall from --layers, filtered, a "
                   "stretching per point, the Delaunay triangulation swapped by the exact "
                   "in-ellipse under the smoothed stretching, point smoothing",
                   false,
                   false,
                   {MeshOption::Size, MeshOption::MaxSteinerPoints, MeshOption::Layers},
                   &run_stretched_delaunay},
    MeshGenerator2{"min-max-front",
                   "Marcum: the boundary's constrained Delaunay triangulation, layer points along "
                   "smoothed wall normals (optional --layers), then advancing-front points, each "
                   "inserted by forced triangulation, Delaunay flips and min-max swaps",
                   false,
                   false,
                   {MeshOption::Size, MeshOption::MaxSteinerPoints, MeshOption::Layers},
                   &run_min_max_front},
};

constexpr std::array<EnumName<MeshOption>, 9> kMeshOptionNames{{
    {"--size", MeshOption::Size},
    {"--min-angle", MeshOption::MinAngle},
    {"--polish-angle", MeshOption::PolishAngle},
    {"--max-steiner", MeshOption::MaxSteinerPoints},
    {"regional attributes", MeshOption::RegionAttributes},
    {"region maximum areas", MeshOption::RegionAreas},
    {"--metric", MeshOption::Metric},
    {"--layers", MeshOption::Layers},
    {"--threads", MeshOption::Threads},
}};

}  // namespace

RefinementOrder refinement_order_from_name(std::string_view name, unsigned threads) {
    if (name.empty()) return threads == 1 ? RefinementOrder::WorstFirst : RefinementOrder::Rounds;
    if (name == "worst-first") return RefinementOrder::WorstFirst;
    if (name == "rounds") return RefinementOrder::Rounds;
    throw InputError("refinement order '" + std::string(name) + "' is not worst-first or rounds");
}

std::string_view mesh_option_name(MeshOption option) {
    return name_of(kMeshOptionNames, option, "an option");
}

MeshRun2 MeshGenerator2::run_on_domain(const MeshDomain2& domain,
                                       const MeshOptions2& options) const {
    if (!honours.contains(MeshOption::RegionAreas))
        refuse_region_areas(domain.pslg(), options, name);
    return generate(domain, options);
}

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
