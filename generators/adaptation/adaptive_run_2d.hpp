// SPDX-License-Identifier: MIT
// One adaptive run in 2D with any method (issue 13): the driver `exactmesh adapt`, the
// benchmarks and the tests share, so that each runs a method the same way.
//  - Methods: insertion (Delaunay point insertion, insertion_adaptation_2d), h-refinement
//    (red-green with history, h_adaptation_2d), steiner (Steiner restart), remesh (global
//    remeshing by a registry generator) and local-remesh (voids refilled by the advancing front).
//  - A cycle refines at time t; a derefinement pass coarsens (insertion: constrained Delaunay
//    vertex removal; h-refinement: by the history; the others coarsen through their size field
//    and have none).
//  - A transient step: the field at the new time, derefinement passes until one removes nothing
//    (at most kMaxDerefinementPasses), then refinement cycles until one changes nothing (at most
//    `cycles`). A transient run fixes its thresholds to the first mesh's mean indicator
//    (AdaptationOptions::reference_mean), and derefines where every edge is below
//    derefine_fraction × threshold × that mean: a fraction below 1/4, so that a removal, which
//    about doubles the edges at its place (a second difference four times), is not refined
//    again at once.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "generators/adaptation/adaptive_mesh_2d.hpp"
#include "generators/adaptation/adaptive_remeshing_2d.hpp"
#include "generators/adaptation/derefinement_2d.hpp"
#include "generators/adaptation/h_adaptation_2d.hpp"
#include "generators/adaptation/insertion_adaptation_2d.hpp"
#include "generators/adaptation/steiner_restart_2d.hpp"
#include "generators/mesh_2d/mesh_generators_2d.hpp"

namespace exactmesh::generators {

enum class AdaptMethod2 { Insertion, HRefinement, Steiner, Remesh, LocalRemesh };

inline constexpr AdaptMethod2 kAllAdaptMethods2[] = {
    AdaptMethod2::Insertion, AdaptMethod2::HRefinement, AdaptMethod2::Steiner, AdaptMethod2::Remesh,
    AdaptMethod2::LocalRemesh};

/// "insertion", "h-refinement", "steiner", "remesh", "local-remesh".
std::string_view adapt_method_name(AdaptMethod2 method);
/// @throws InputError naming the unknown method and the known ones.
AdaptMethod2 adapt_method_from_name(std::string_view name);

/// Derefinement passes per transient step at most.
inline constexpr int kMaxDerefinementPasses = 64;

struct AdaptiveRunOptions2 {
    AdaptMethod2 method = AdaptMethod2::Insertion;
    AdaptationOptions adaptation;
    double derefine_fraction = 0.1;  ///< see the header comment
    bool transient = false;          ///< fix the thresholds to the first mesh's mean
};

class AdaptiveRun2 {
  public:
    /// `domain` (its arrays must outlive the run): the PSLG the initial mesh was made of, its
    /// options and its segments' curves; `curves` the domain's curves; `initial` a generator's
    /// mesh of it; `generator` the registry generator remesh regenerates with.
    /// @throws InputError as sample_field.
    AdaptiveRun2(const RemeshDomain2& domain, std::vector<Curve2> curves,
                 triangulation::Cdt2Result initial, const MeshGenerator2& generator,
                 const AnalyticField* field, double t, const AdaptiveRunOptions2& options);

    /// One refinement cycle at time t; false when the method changed nothing.
    bool cycle(double t);
    /// One derefinement pass; the vertices (h-refinement: triangles) removed.
    std::uint64_t derefine();
    /// The analytic field at time t on the current mesh.
    void resample(double t);
    /// The field at the current mesh's vertices from the caller (a field file, no analytic
    /// field); the methods carry it to new meshes by transfer.
    /// @pre values.size() == mesh().vertex_count()
    void set_values(std::vector<double> values);
    /// A transient step (see the header comment).
    void step(double t, std::uint32_t cycles);

    const triangulation::Triangulation2& mesh() const;
    const std::vector<double>& values() const;
    const AdaptationOptions& adaptation() const { return options_.adaptation; }

    /// The exact check of the current mesh ("" when it passes): check_h_refined_mesh_2d for
    /// h-refinement, else check_adaptive_mesh_2d (constrained Delaunay unless the method or a
    /// movement leaves the connectivity non-Delaunay).
    std::string check(std::span<const double> fixed_xy) const;
    /// The counters of the method (and of the derefinement when it ran), in --stats order.
    std::vector<std::pair<std::string, std::uint64_t>> counters() const;
    /// The mesh as a constrained result (pieces, input vertex count) for the writers.
    triangulation::Cdt2Result result() const;

  private:
    RemeshDomain2 domain_;
    const MeshGenerator2* generator_;
    const AnalyticField* field_;
    AdaptiveRunOptions2 options_;
    FieldSource source_;
    std::optional<AdaptiveMesh2> flat_;
    std::optional<HAdaptiveMesh2> h_;
    InsertionCounters2 insertion_;
    HAdaptationCounters2 h_counters_;
    SteinerRestartCounters2 steiner_;
    RemeshCounters2 remesh_;
    LocalRemeshCounters2 local_;
    DerefinementCounters2 derefinement_;
};

}  // namespace exactmesh::generators
