// SPDX-License-Identifier: MIT
// One adaptive run in 2D with any method (see adaptive_run_2d.hpp).
#include "generators/adaptation/adaptive_run_2d.hpp"

#include "base/enum_names.hpp"
#include "base/errors.hpp"
#include "generators/topology/mesh_edges.hpp"

namespace exactmesh::generators {

namespace tri = exactmesh::triangulation;

namespace {

constexpr std::array<EnumName<AdaptMethod2>, 5> kAdaptMethodNames2{{
    {"insertion", AdaptMethod2::Insertion},
    {"h-refinement", AdaptMethod2::HRefinement},
    {"steiner", AdaptMethod2::Steiner},
    {"remesh", AdaptMethod2::Remesh},
    {"local-remesh", AdaptMethod2::LocalRemesh},
}};

}  // namespace

std::string_view adapt_method_name(AdaptMethod2 method) {
    return name_of(kAdaptMethodNames2, method);
}

AdaptMethod2 adapt_method_from_name(std::string_view name) {
    return parse_name(kAdaptMethodNames2, name, "adaptation method");
}

AdaptiveRun2::AdaptiveRun2(const RemeshDomain2& domain, std::vector<Curve2> curves,
                           tri::Cdt2Result initial, const MeshGenerator2& generator,
                           const AnalyticField* field, double t, const AdaptiveRunOptions2& options)
    : domain_(domain), generator_(&generator), field_(field), options_(options), source_{field, t} {
    if (options.method == AdaptMethod2::HRefinement) {
        h_.emplace(HAdaptiveMesh2{HRefinedMesh2(initial.mesh), {}});
        if (field != nullptr) h_->values = sample_field(*field, h_->hierarchy.leaf_mesh().xy, 2, t);
    } else {
        flat_.emplace(make_adaptive_mesh_2d(std::move(initial), domain.pslg.xy,
                                            domain.pslg.segments, domain.pslg.holes,
                                            std::move(curves), domain.segment_curves));
        if (field != nullptr) flat_->values = sample_field(*field, flat_->mesh.xy, 2, t);
    }
    if (options.transient && field != nullptr) {
        options_.adaptation.reference_mean = mean_indicator(
            mesh_edge_indicator(options_.adaptation.indicator, mesh().xy, 2, mesh().triangles,
                                mesh_edges_2d(mesh().triangles), values()));
    }
}

const tri::Triangulation2& AdaptiveRun2::mesh() const {
    return h_ ? h_->hierarchy.leaf_mesh() : flat_->mesh;
}

const std::vector<double>& AdaptiveRun2::values() const {
    return h_ ? h_->values : flat_->values;
}

bool AdaptiveRun2::cycle(double t) {
    source_.t = t;
    const AdaptationOptions& o = options_.adaptation;
    switch (options_.method) {
        case AdaptMethod2::Insertion:
            return insertion_cycle_2d(*flat_, o, source_, insertion_);
        case AdaptMethod2::HRefinement:
            return h_refinement_cycle_2d(*h_, o, source_, h_counters_);
        case AdaptMethod2::Steiner:
            return steiner_restart_cycle_2d(*flat_, o, source_, steiner_);
        case AdaptMethod2::Remesh:
            return remesh_cycle_2d(*flat_, domain_, *generator_, o, source_, remesh_);
        case AdaptMethod2::LocalRemesh:
            return local_remesh_cycle_2d(*flat_, o, source_, local_);
    }
    return false;
}

std::uint64_t AdaptiveRun2::derefine() {
    const AdaptationOptions& o = options_.adaptation;
    const double threshold = options_.derefine_fraction * o.threshold;
    if (options_.method == AdaptMethod2::HRefinement)
        return h_derefinement_pass_2d(*h_, o.indicator, threshold, o.reference_mean, source_,
                                      h_counters_);
    if (options_.method != AdaptMethod2::Insertion) return 0;
    return derefinement_pass_2d(*flat_, {o.indicator, threshold, o.reference_mean}, derefinement_);
}

void AdaptiveRun2::resample(double t) {
    source_.t = t;
    if (field_ == nullptr) return;
    std::vector<double>& v = h_ ? h_->values : flat_->values;
    v = sample_field(*field_, mesh().xy, 2, t);
}

void AdaptiveRun2::set_values(std::vector<double> values) {
    EM_ASSERT(values.size() == mesh().vertex_count());
    (h_ ? h_->values : flat_->values) = std::move(values);
}

void AdaptiveRun2::step(double t, std::uint32_t cycles) {
    resample(t);
    for (int pass = 0; pass < kMaxDerefinementPasses; ++pass)
        if (derefine() == 0) break;
    for (std::uint32_t c = 0; c < cycles; ++c)
        if (!cycle(t)) break;
}

std::string AdaptiveRun2::check(std::span<const double> fixed_xy) const {
    if (h_) {
        const tri::CheckReport report = check_h_refined_mesh_2d(h_->hierarchy);
        return report.ok ? "" : report.problem;
    }
    const bool delaunay = options_.adaptation.movement_sweeps == 0 &&
                          options_.method != AdaptMethod2::LocalRemesh &&
                          (options_.method != AdaptMethod2::Remesh || generator_->delaunay);
    return check_adaptive_mesh_2d(*flat_, fixed_xy, delaunay);
}

std::vector<std::pair<std::string, std::uint64_t>> AdaptiveRun2::counters() const {
    std::vector<std::pair<std::string, std::uint64_t>> named;
    switch (options_.method) {
        case AdaptMethod2::Insertion:
            named = counters_by_name(kInsertionCounterNames2, insertion_);
            break;
        case AdaptMethod2::HRefinement:
            named = counters_by_name(kHAdaptationCounterNames2, h_counters_);
            for (const auto& row :
                 counters_by_name(kHRefinementCounterNames, h_->hierarchy.counters()))
                named.push_back(row);
            break;
        case AdaptMethod2::Steiner:
            named = counters_by_name(kSteinerRestartCounterNames2, steiner_);
            break;
        case AdaptMethod2::Remesh:
            named = counters_by_name(kRemeshCounterNames2, remesh_);
            break;
        case AdaptMethod2::LocalRemesh:
            named = counters_by_name(kLocalRemeshCounterNames2, local_);
            break;
    }
    if (derefinement_.passes > 0)
        for (const auto& [name, value] :
             counters_by_name(kDerefinementCounterNames2, derefinement_))
            named.emplace_back("derefinement_" + name, value);
    return named;
}

tri::Cdt2Result AdaptiveRun2::result() const {
    tri::Cdt2Result result;
    result.mesh = mesh();
    if (h_) {
        result.input_vertex_count = h_->hierarchy.root_vertex_count();
        // The pieces: the leaf mesh's constrained edges, each once.
        const tri::Triangulation2& leaves = result.mesh;
        for (std::size_t t = 0; t < leaves.triangle_count(); ++t)
            for (int k = 0; k < 3; ++k) {
                const tri::VertIdx a = leaves.triangles[3 * t + static_cast<std::size_t>(k)];
                const tri::VertIdx b =
                    leaves.triangles[3 * t + static_cast<std::size_t>((k + 1) % 3)];
                const tri::TriIdx other = leaves.neighbors[3 * t + static_cast<std::size_t>(k)];
                if (leaves.is_constrained(static_cast<tri::TriIdx>(t), k) &&
                    (other == tri::kNone || a < b)) {
                    result.pieces.insert(result.pieces.end(), {a, b});
                    result.piece_segment.push_back(
                        static_cast<std::uint32_t>(result.piece_segment.size()));
                }
            }
        return result;
    }
    result.input_vertex_count = flat_->fixed_vertices;
    for (std::size_t p = 0; p < flat_->pieces.size(); ++p) {
        result.pieces.insert(result.pieces.end(), {flat_->pieces[p].a, flat_->pieces[p].b});
        result.piece_segment.push_back(static_cast<std::uint32_t>(p));
    }
    return result;
}

}  // namespace exactmesh::generators
