// SPDX-License-Identifier: MIT
// The domain of a PSLG as the 2D mesh generators start from it (issue 12): its constrained
// Delaunay triangulation, exterior and holes removed, built once per run and shared by every
// step that needs it (the size budget of the registry, the graded default size, the boundary's
// discretization, the regions' maximum areas), where each step used to rebuild it.
#pragma once

#include <memory>
#include <vector>

#include "triangulation/constrained/constrained_2d.hpp"

namespace exactmesh::generators {

/// The caller's options for a constrained triangulation the generators build of the domain (or
/// of a part of it: the quadtree's band, a front's closure), exterior removed: Swap recovery
/// where the caller asked for Conforming (the generators need the domain's segments, not a
/// conforming triangulation of them).
triangulation::Cdt2Options domain_cdt_options(triangulation::Cdt2Options cdt);

class MeshDomain2 {
  public:
    /// Keeps `pslg` (its spans: the caller's arrays must outlive the domain) and `cdt`, and
    /// builds nothing yet: a run that needs no domain (Delaunay refinement without a size)
    /// pays for none. A PSLG without segments is its convex hull, as Triangle and `cdt` take
    /// it: the hull's edges become its segments here (the one Delaunay triangulation built
    /// then), so every generator meshes the same domain (some had meshed the hull, others
    /// had refused the PSLG as enclosing no region). Collinear points keep no segment.
    /// @throws InputError as validate_pslg when the PSLG has no segments.
    explicit MeshDomain2(const triangulation::Pslg& pslg,
                         const triangulation::Cdt2Options& cdt = {});
    MeshDomain2(const MeshDomain2&) = delete;
    MeshDomain2& operator=(const MeshDomain2&) = delete;

    const triangulation::Pslg& pslg() const { return pslg_; }
    /// The options the domain is built with: the caller's, exterior removed, and Swap where the
    /// caller asked for Conforming (the domain, not a conforming triangulation of it).
    const triangulation::Cdt2Options& domain_options() const { return domain_options_; }

    /// constrained_delaunay_2d of the PSLG with domain_options(), built on the first call (the
    /// PSLG validated first, as given), then the same object. When some region has a maximum
    /// area (has_region_areas), the triangles' attributes are region numbers
    /// (numbered_regions: what the budget and the regional sizes need); the triangles, pieces
    /// and warnings are those of the PSLG as given.
    /// @throws InputError as constrained_delaunay_2d (again on each call until one succeeds).
    const triangulation::Cdt2Result& triangulation() const;
    /// The same, shared with a size function that outlives the domain.
    std::shared_ptr<const triangulation::Cdt2Result> shared_triangulation() const;

    /// True when the triangulation's attributes are region numbers (some region has an area).
    bool attributes_are_region_numbers() const { return numbered_; }
    bool built() const { return cdt_ != nullptr; }
    /// True when the PSLG had no segments and its convex hull's edges are its segments.
    bool hull_segments() const { return !hull_segments_.empty(); }

  private:
    std::vector<triangulation::VertIdx> hull_segments_;  ///< pslg_.segments' storage then
    triangulation::Pslg pslg_;
    triangulation::Cdt2Options domain_options_;
    bool numbered_ = false;
    // Built lazily by a const accessor: the generators take the domain as const, and only the
    // first step that needs it builds it.
    mutable std::shared_ptr<const triangulation::Cdt2Result> cdt_;
};

}  // namespace exactmesh::generators
