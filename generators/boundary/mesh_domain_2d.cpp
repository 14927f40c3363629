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

MeshDomain2::MeshDomain2(const tri::Pslg& pslg, const tri::Cdt2Options& cdt)
    : pslg_(pslg),
      domain_options_(domain_cdt_options(cdt)),
      numbered_(has_region_areas(pslg.regions)) {}

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
