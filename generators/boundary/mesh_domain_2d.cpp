// SPDX-License-Identifier: MIT
// The generators' shared domain (see mesh_domain_2d.hpp).
#include "generators/boundary/mesh_domain_2d.hpp"

#include <utility>

#include "generators/boundary/region_areas_2d.hpp"

namespace exactmesh::generators {

namespace tri = exactmesh::triangulation;

tri::Cdt2Options domain_cdt_options(tri::Cdt2Options cdt) {
    cdt.remove_exterior = true;
    if (cdt.recovery == tri::SegmentRecovery::Conforming) cdt.recovery = tri::SegmentRecovery::Swap;
    return cdt;
}

namespace {

/// The edges of the convex hull of the PSLG's vertices (its segments ignored), each once, in
/// the input's numbering: the boundary edges of their Delaunay triangulation (duplicates
/// merged into the first, the hull's collinear vertices on it). Empty when the points are
/// collinear.
std::vector<tri::VertIdx> convex_hull_edges(const tri::Pslg& pslg, tri::Cdt2Options options) {
    tri::validate_pslg(pslg);
    options.remove_exterior = false;
    const tri::Cdt2Result hull =
        tri::constrained_delaunay_2d(tri::Pslg{pslg.xy, {}, {}, {}}, options);
    std::vector<tri::VertIdx> edges;
    const tri::Triangulation2& mesh = hull.mesh;
    for (tri::TriIdx t = 0; t < mesh.triangle_count(); ++t) {
        for (unsigned k = 0; k < 3; ++k) {
            if (mesh.neighbors[3 * std::size_t{t} + k] != tri::kNone) continue;
            edges.push_back(mesh.triangles[3 * std::size_t{t} + k]);
            edges.push_back(mesh.triangles[3 * std::size_t{t} + (k + 1) % 3]);
        }
    }
    return edges;
}

}  // namespace

MeshDomain2::MeshDomain2(const tri::Pslg& pslg, const tri::Cdt2Options& cdt)
    : pslg_(pslg),
      domain_options_(domain_cdt_options(cdt)),
      numbered_(has_region_areas(pslg.regions)) {
    if (pslg.segments.empty()) {
        hull_segments_ = convex_hull_edges(pslg, domain_options_);
        pslg_.segments = hull_segments_;
    }
}

const tri::Cdt2Result& MeshDomain2::triangulation() const {
    return *shared_triangulation();
}

std::shared_ptr<const tri::Cdt2Result> MeshDomain2::shared_triangulation() const {
    if (cdt_ != nullptr) return cdt_;
    // Validated as given first: the numbered copy below replaces the attributes, and a
    // non-finite one must still be reported.
    tri::validate_pslg(pslg_);
    if (numbered_) {
        const std::vector<double> regions = numbered_regions(pslg_.regions);
        cdt_ = std::make_shared<const tri::Cdt2Result>(tri::constrained_delaunay_2d(
            tri::Pslg{pslg_.xy, pslg_.segments, pslg_.holes, regions}, domain_options_));
    } else {
        cdt_ = std::make_shared<const tri::Cdt2Result>(
            tri::constrained_delaunay_2d(pslg_, domain_options_));
    }
    return cdt_;
}

}  // namespace exactmesh::generators
