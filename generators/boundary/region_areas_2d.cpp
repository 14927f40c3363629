// SPDX-License-Identifier: MIT
// Regional maximum areas (see region_areas_2d.hpp).
#include "generators/boundary/region_areas_2d.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <utility>

#include "generators/boundary/domain_boundary_2d.hpp"
#include "predicates/orient2d.hpp"

namespace exactmesh::generators {

namespace tri = exactmesh::triangulation;

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// The region index of a numbered attribute, or SIZE_MAX.
std::size_t region_index(std::span<const double> regions, double numbered_attribute) {
    if (!(numbered_attribute >= 1)) return SIZE_MAX;
    const auto r = static_cast<std::size_t>(numbered_attribute) - 1;
    return r < regions.size() / 4 ? r : SIZE_MAX;
}

/// s_A per triangle of the input's CDT (+infinity outside regions with an area), the smallest
/// about each vertex, and exact point location over it.
class RegionSides {
  public:
    /// `cdt`: the domain's triangulation with region numbers as attributes (MeshDomain2 with
    /// regional areas), kept (shared) for the point location.
    RegionSides(std::span<const double> regions, std::shared_ptr<const tri::Cdt2Result> cdt)
        : cdt_(std::move(cdt)), domain_(cdt_->mesh), locator_(domain_) {
        const tri::Cdt2Result& result = *cdt_;
        side_.assign(domain_.triangle_count(), kInfinity);
        at_vertex_.assign(domain_.vertex_count(), kInfinity);
        for (tri::TriIdx t = 0; t < domain_.triangle_count(); ++t) {
            if (t < result.triangle_attributes.size()) {
                side_[t] = equilateral_side_of_area(
                    region_area_of(regions, result.triangle_attributes[t]));
            }
            for (unsigned k = 0; k < 3; ++k) {
                double& s = at_vertex_[domain_.triangles[3 * t + k]];
                s = std::min(s, side_[t]);
            }
        }
    }

    /// The smallest s_A of the triangles of the CDT that contain (x, y) (closed); +infinity
    /// outside the domain or every region with an area.
    double operator()(double x, double y) const {
        const tri::TriIdx t = locator_.locate(domain_, x, y);
        if (t == tri::kNone) return kInfinity;
        double s = side_[t];
        const double p[2] = {x, y};
        for (unsigned k = 0; k < 3; ++k) {
            const tri::VertIdx v = domain_.triangles[3 * t + k];
            const double* a = domain_.point(v);
            if (a[0] == x && a[1] == y) return std::min(s, at_vertex_[v]);  // every triangle at v
            const double* b = domain_.point(domain_.triangles[3 * t + (k + 1) % 3]);
            const tri::TriIdx n = domain_.neighbors[3 * t + k];
            if (n != tri::kNone && predicates::orient2d(a, b, p) == predicates::Sign::Zero) {
                s = std::min(s, side_[n]);  // on the edge: the triangle across it too
            }
        }
        return s;
    }

  private:
    std::shared_ptr<const tri::Cdt2Result> cdt_;
    const tri::Triangulation2& domain_;  // cdt_->mesh
    DomainLocator2 locator_;
    std::vector<double> side_, at_vertex_;
};

}  // namespace

bool has_region_areas(std::span<const double> regions) {
    for (std::size_t r = 0; r + 3 < regions.size(); r += 4) {
        if (regions[r + 3] > 0) return true;
    }
    return false;
}

std::vector<double> numbered_regions(std::span<const double> regions) {
    std::vector<double> numbered(regions.begin(), regions.end());
    for (std::size_t r = 0; 4 * r + 3 < numbered.size(); ++r) {
        numbered[4 * r + 2] = static_cast<double>(r + 1);
    }
    return numbered;
}

double region_area_of(std::span<const double> regions, double numbered_attribute) {
    const std::size_t r = region_index(regions, numbered_attribute);
    return r == SIZE_MAX ? 0.0 : std::max(0.0, regions[4 * r + 3]);
}

double region_attribute_of(std::span<const double> regions, double numbered_attribute) {
    const std::size_t r = region_index(regions, numbered_attribute);
    return r == SIZE_MAX ? 0.0 : regions[4 * r + 2];
}

double equilateral_side_of_area(double area) {
    if (!(area > 0)) return kInfinity;
    // sqrt first: 4 A would overflow for A above 4.5e307; sqrt(A 4^k) = sqrt(A) 2^k exactly.
    return 2 * (std::sqrt(area) / 1.3160740129524924608);  // 3^(1/4)
}

double triangles_of_side(const double* p, const double* q, const double* r, double side) {
    const double ux = (q[0] - p[0]) / side, uy = (q[1] - p[1]) / side;
    const double vx = (r[0] - p[0]) / side, vy = (r[1] - p[1]) / side;
    const double count = std::fabs(ux * vy - uy * vx) / (2 * 0.4330127018922193);  // sqrt(3) / 4
    return std::isnan(count) ? kInfinity : count;
}

double triangles_of_area(const double* p, const double* q, const double* r, double area) {
    return area > 0 ? triangles_of_side(p, q, r, equilateral_side_of_area(area)) : 0.0;
}

double region_area_triangle_count(const tri::Cdt2Result& domain, std::span<const double> regions) {
    double count = 0;
    const tri::Triangulation2& mesh = domain.mesh;
    for (tri::TriIdx t = 0; t < mesh.triangle_count() && t < domain.triangle_attributes.size();
         ++t) {
        const double area = region_area_of(regions, domain.triangle_attributes[t]);
        if (!(area > 0)) continue;
        count += triangles_of_area(mesh.point(mesh.triangles[3 * t]),
                                   mesh.point(mesh.triangles[3 * t + 1]),
                                   mesh.point(mesh.triangles[3 * t + 2]), area);
    }
    return count;
}

SizeFunction size_with_region_areas(const tri::Pslg& pslg, const SizeFunction& size,
                                    const tri::Cdt2Options& cdt) {
    if (!size.bounded() || !has_region_areas(pslg.regions)) return size;
    return size_with_region_areas(MeshDomain2(pslg, cdt), size);
}

SizeFunction size_with_region_areas(const MeshDomain2& domain, const SizeFunction& size) {
    if (!size.bounded() || !domain.attributes_are_region_numbers()) return size;
    auto sides =
        std::make_shared<const RegionSides>(domain.pslg().regions, domain.shared_triangulation());
    return SizeFunction::analytic(
        [sides, size](double x, double y) { return std::min(size(x, y), (*sides)(x, y)); },
        "min(" + size.describe() + ", the regions' maximum areas as equilateral sizes)");
}

}  // namespace exactmesh::generators
