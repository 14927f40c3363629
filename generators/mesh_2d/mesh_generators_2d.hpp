// SPDX-License-Identifier: MIT
// The registry of the 2D mesh generators (issue 6; STYLE.md "a name registry"): one entry per
// generator, each with its name, a one-line summary, whether its meshes are constrained
// Delaunay, and a function that runs it on a PSLG with the options every generator shares. The
// CLI (`exactmesh mesh --generator NAME`), the benchmarks and the tests that compare generators
// all go through it, so they run the same code with the same options.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "generators/boundary/mesh_domain_2d.hpp"
#include "generators/boundary/sample_domains.hpp"
#include "generators/mesh_2d/delaunay_refinement_2d.hpp"
#include "generators/sizing/size_function.hpp"
#include "generators/stretched/advancing_layers_2d.hpp"
#include "generators/stretched/metric_field_2d.hpp"
#include "triangulation/constrained/constrained_2d.hpp"

namespace exactmesh::generators {

/// What every generator is given. A generator that needs a size raises InputError when `size`
/// is unbounded; one without an angle criterion ignores `min_angle`.
struct MeshOptions2 {
    SizeFunction size;
    double min_angle = kGuaranteedMinAngle;  ///< degrees (Delaunay refinement)
    double polish_angle = -1;  ///< Delaunay refinement's polish (RefinementOptions2), -1: automatic
    std::uint64_t max_steiner_points = 0;  ///< 0: the generator's automatic budget
    /// The most new boundary points a generator that splits the boundary to the size before
    /// meshing (quadtree, both advancing fronts, frontal) may place, refused as the boundary is
    /// sampled (0: max_steiner_points). Global remeshing sets it below its generator's Steiner
    /// budget: each boundary sample is a size evaluation.
    std::uint64_t max_boundary_points = 0;
    triangulation::Cdt2Options cdt;  ///< numbering, recovery of the initial CDT
    /// The metric field of the stretched generators (issue 14: --metric); none otherwise.
    std::optional<MetricField2> metric;
    /// The boundary layers (advancing-layers only: --layers, --quads).
    LayerParameters2 layers;
    /// The wake behind each trailing edge, in chords (stretched-delaunay only: --wake); 0: none.
    double wake_length = 0;
    /// Staggered O-mesh layers (stretched-delaunay only: --staggered-layers).
    bool staggered_layers = false;
    /// Delaunay refinement's order and threads (RefinementOptions2; --refine-order, --threads).
    RefinementOrder refinement_order = RefinementOrder::WorstFirst;
    unsigned threads = 1;
};

/// A generator's mesh (caller's numbering, pieces, warnings) and its work counters in the order
/// `--stats` prints them.
struct MeshRun2 {
    triangulation::Cdt2Result mesh;
    /// 4·#Q quadrilaterals, counter-clockwise (a mixed mesh: advancing-layers with --quads),
    /// beside mesh.mesh.triangles and numbered like them; empty for a triangle mesh.
    std::vector<triangulation::VertIdx> quads;
    std::vector<std::pair<std::string, std::uint64_t>> counters;
    /// #V: the metric each vertex was meshed to, when the generator makes its own (stretched
    /// Delaunay: the smoothed stretching of its structured cells); empty otherwise.
    std::vector<Metric2> vertex_metrics;
    /// Seconds of the generator's phases, named (`--stats` prints them after the counters);
    /// empty when it times none.
    std::vector<std::pair<std::string, double>> phase_seconds;
};

/// The options and input features a generator may honour (MeshGenerator2::honours). A caller
/// that is given one the generator ignores says so (`exactmesh mesh` warns, or refuses where the
/// README documents a refusal) instead of dropping it silently.
enum class MeshOption : std::uint32_t {
    Size = 1u << 0,              ///< MeshOptions2::size
    MinAngle = 1u << 1,          ///< MeshOptions2::min_angle (--min-angle)
    PolishAngle = 1u << 2,       ///< MeshOptions2::polish_angle (--polish-angle)
    MaxSteinerPoints = 1u << 3,  ///< MeshOptions2::max_steiner_points (--max-steiner)
    RegionAttributes = 1u << 4,  ///< the regions' attributes, carried to the mesh's triangles
    RegionAreas = 1u << 5,       ///< the regions' maximum areas (the 4th number, > 0)
    Metric = 1u << 6,            ///< MeshOptions2::metric (--metric)
    Layers = 1u << 7,            ///< MeshOptions2::layers (--layers, --quads)
    Threads = 1u << 8,           ///< MeshOptions2::threads other than 1 (--threads)
};

/// A set of MeshOption.
class MeshOptionSet {
  public:
    constexpr MeshOptionSet() = default;
    constexpr MeshOptionSet(std::initializer_list<MeshOption> options) {
        for (const MeshOption o : options) bits_ |= static_cast<std::uint32_t>(o);
    }
    constexpr bool contains(MeshOption o) const {
        return (bits_ & static_cast<std::uint32_t>(o)) != 0;
    }

  private:
    std::uint32_t bits_ = 0;
};

/// How a warning or an error names an option ("--min-angle", "regional attributes").
std::string_view mesh_option_name(MeshOption option);

struct MeshGenerator2 {
    std::string_view name;     ///< "delaunay-refinement", as the CLI spells it
    std::string_view summary;  ///< one line for --help
    bool delaunay;             ///< meshes are constrained Delaunay (else only conforming)
    bool needs_size;           ///< an unbounded size is an InputError
    /// The options it honours; it ignores the others. One that does not honour RegionAreas
    /// raises InputError on a PSLG with a regional maximum area (it carries no regions).
    MeshOptionSet honours;
    /// The generator itself, over the domain (run_on_domain refuses what it cannot honour first).
    MeshRun2 (*generate)(const MeshDomain2& domain, const MeshOptions2& options);

    /// Runs it over the domain built once (the same object for the caller's other steps: the
    /// graded default size, graded_size_from_boundary(domain)).
    /// @throws InputError on a regional maximum area it does not honour, and as `generate`.
    MeshRun2 run_on_domain(const MeshDomain2& domain, const MeshOptions2& options) const;

    /// Runs it on a PSLG, the domain built inside (for one-off callers: tests, benchmarks).
    MeshRun2 run(const triangulation::Pslg& pslg, const MeshOptions2& options) const {
        const MeshDomain2 domain(pslg, options.cdt);
        return run_on_domain(domain, options);
    }
};

/// Every generator, in the order the CLI lists them.
std::span<const MeshGenerator2> mesh_generators_2d();

/// @throws InputError naming the unknown generator and the known ones.
const MeshGenerator2& find_mesh_generator_2d(std::string_view name);

/// A lower estimate of the number of triangles a mesh of the domain at `size` has: the integral
/// of 1 / s^2 over the domain (the triangles of its constrained Delaunay triangulation
/// `domain`) divided by the area of the equilateral triangle of edge 1 (sqrt(3) / 4), each
/// triangle taken at the largest size sampled at its corners and centroid (split in four, up
/// to a fixed number of samples, where those vary by more than 2). Computed in units of the
/// size, so no square of a coordinate overflows or underflows; +infinity when the count
/// overflows. Sampling stops once the estimate exceeds `stop_above`.
/// @throws InputError naming the size function and the point where a sample is 0, negative,
///         NaN or infinite.
double minimum_triangle_count(const triangulation::Triangulation2& domain, const SizeFunction& size,
                              double stop_above);

/// The budget every generator of the registry checks before meshing (issue 11): with a size,
/// the minimum_triangle_count over the domain (and with regional maximum areas, the
/// region_area_triangle_count, whichever is larger) must stay within 2^26 triangles (automatic
/// budget) or, for the generators whose budget is a hard limit (Delaunay refinement, quadtree,
/// frontal), within the triangles options.max_steiner_points Steiner points can make.
/// Over the domain built once (MeshDomain2::triangulation, whatever options.cdt's recovery).
/// @throws InputError naming the size, the estimate and the budget, at once.
void check_size_budget(const MeshDomain2& domain, const MeshOptions2& options, bool hard_budget);

/// A built-in domain with a size (the command's --domain with --size, the Python module's
/// mesh(domain=, size=)): the curves are discretized by that size before the size budget is
/// checked over the domain's CDT, so a size far below what the budget allows (1e-7 on naca0012:
/// 2·10^7 boundary points) ran for minutes and gigabytes before its error. This checks the
/// budget first over the domain discretized by its own size, and refuses (with
/// check_size_budget's message, its estimate over that domain) only beyond 64 times the
/// automatic budget: far beyond what the two discretizations' areas can change. Anything else
/// (a size within that, or one that is not > 0 somewhere) is left to the check over the domain
/// itself. Call it only without an explicit Steiner-point budget (the automatic one).
/// @throws InputError from check_size_budget.
void refuse_sample_domain_size_far_over_budget(SampleDomain sample, const SizeFunction& size);

/// The automatic triangle budget of check_size_budget.
inline constexpr double kAutomaticTriangleBudget = 0x1p26;

/// The refinement order a caller's name asks for ("worst-first", "rounds"), or for "" the
/// default for `threads`: worst-first on one thread, rounds on more (the command's
/// --refine-order, the Python module's refine_order).
/// @throws InputError naming an unknown order.
RefinementOrder refinement_order_from_name(std::string_view name, unsigned threads);

/// The counters of a Delaunay refinement run, named as `exactmesh mesh --stats` prints them.
std::vector<std::pair<std::string, std::uint64_t>> counter_list(const RefinementCounters2& c);

}  // namespace exactmesh::generators
