// SPDX-License-Identifier: MIT
// Region volume bounds as a size (see region_volumes_3d.hpp).
#include "generators/mesh_3d/region_volumes_3d.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

#include "predicates/orient3d.hpp"
#include "triangulation/mesh/mesh3.hpp"

namespace exactmesh::generators {

namespace {

namespace tri = exactmesh::triangulation;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// The bounded tetrahedra (corners copied) with their a_V, filed in a uniform grid over their
/// bounding box. A grid cell is chosen in doubles, a choice of which tetrahedra to test: the
/// cell of a coordinate is monotone in it (correctly rounded operations are), so a point
/// inside a tetrahedron's box falls in a cell of the box's range; containment itself is exact.
class BoundedRegions {
  public:
    explicit BoundedRegions(const tri::ConformingMesh3& recovered) {
        const tri::Tetrahedralization3& mesh = recovered.mesh;
        for (tri::TetIdx t = 0; t < mesh.tet_count() && t < recovered.tet_max_volume.size(); ++t) {
            const double bound = recovered.tet_max_volume[t];
            if (!(bound > 0)) continue;
            Tet tet;
            for (unsigned k = 0; k < 4; ++k) {
                const double* p = mesh.point(mesh.tets[4 * std::size_t{t} + k]);
                std::copy(p, p + 3, tet.corners[k].begin());
            }
            tet.edge = regular_tet_edge_of_volume(bound);
            tets_.push_back(tet);
        }
        if (tets_.empty()) return;
        lo_ = hi_ = tets_[0].corners[0];
        for (const Tet& tet : tets_)
            for (const auto& p : tet.corners)
                for (std::size_t a = 0; a < 3; ++a) {
                    lo_[a] = std::min(lo_[a], p[a]);
                    hi_[a] = std::max(hi_[a], p[a]);
                }
        // About one tetrahedron per cell: a cube root of the count per axis, at most 64;
        // coarser while the lists would hold more than 16 entries per tetrahedron (long
        // slivers of a recovered mesh span many cells: memory would grow as their count
        // times the cells), as BucketGrid2 does in 2D.
        cells_ = std::clamp(static_cast<int>(std::cbrt(static_cast<double>(tets_.size()))), 1, 64);
        const auto range = [&](std::uint32_t i, std::array<int, 3>& from, std::array<int, 3>& to) {
            for (std::size_t a = 0; a < 3; ++a) {
                double tmin = tets_[i].corners[0][a], tmax = tmin;
                for (const auto& p : tets_[i].corners) {
                    tmin = std::min(tmin, p[a]);
                    tmax = std::max(tmax, p[a]);
                }
                from[a] = cell(tmin, a);
                to[a] = cell(tmax, a);
            }
        };
        for (; cells_ > 1; cells_ /= 2) {
            std::uint64_t entries = 0;
            for (std::uint32_t i = 0; i < tets_.size(); ++i) {
                std::array<int, 3> from{}, to{};
                range(i, from, to);
                entries += std::uint64_t(to[0] - from[0] + 1) * std::uint64_t(to[1] - from[1] + 1) *
                           std::uint64_t(to[2] - from[2] + 1);
            }
            if (entries <= 16 * std::uint64_t{tets_.size()} + 4096) break;
        }
        grid_.resize(static_cast<std::size_t>(cells_) * cells_ * cells_);
        for (std::uint32_t i = 0; i < tets_.size(); ++i) {
            std::array<int, 3> from{}, to{};
            range(i, from, to);
            for (int x = from[0]; x <= to[0]; ++x)
                for (int y = from[1]; y <= to[1]; ++y)
                    for (int z = from[2]; z <= to[2]; ++z) grid_[index(x, y, z)].push_back(i);
        }
    }

    bool empty() const { return tets_.empty(); }

    /// The smallest a_V of the bounded tetrahedra holding p (closed); +infinity in none.
    double edge_at(const double* p) const {
        for (std::size_t a = 0; a < 3; ++a)
            if (!(p[a] >= lo_[a] && p[a] <= hi_[a])) return kInfinity;
        double edge = kInfinity;
        for (const std::uint32_t i : grid_[index(cell(p[0], 0), cell(p[1], 1), cell(p[2], 2))]) {
            const Tet& tet = tets_[i];
            if (!(tet.edge < edge) || !contains(tet, p)) continue;
            edge = tet.edge;
        }
        return edge;
    }

  private:
    struct Tet {
        std::array<std::array<double, 3>, 4> corners;
        double edge = kInfinity;
    };

    static bool contains(const Tet& tet, const double* p) {
        for (unsigned k = 0; k < 4; ++k) {
            const unsigned* lf = tri::kFaceVertex[k];
            if (predicates::orient3d(tet.corners[lf[0]].data(), tet.corners[lf[1]].data(),
                                     tet.corners[lf[2]].data(), p) == predicates::Sign::Negative)
                return false;
        }
        return true;
    }

    int cell(double x, std::size_t a) const {
        const double span = hi_[a] - lo_[a];
        if (!(span > 0)) return 0;
        const double t = std::floor((x - lo_[a]) / span * cells_);
        return static_cast<int>(std::clamp(t, 0.0, static_cast<double>(cells_ - 1)));
    }
    std::size_t index(int x, int y, int z) const {
        return (static_cast<std::size_t>(x) * static_cast<std::size_t>(cells_) +
                static_cast<std::size_t>(y)) *
                   static_cast<std::size_t>(cells_) +
               static_cast<std::size_t>(z);
    }

    std::vector<Tet> tets_;
    std::array<double, 3> lo_{}, hi_{};
    int cells_ = 1;
    std::vector<std::vector<std::uint32_t>> grid_;
};

}  // namespace

double regular_tet_edge_of_volume(double volume) {
    if (!(volume > 0)) return kInfinity;
    if (std::isinf(volume)) return kInfinity;
    // V = m 8^e with m in [1, 8): cbrt(6 sqrt(2) m) 2^e, so V times 2^(3k) gives the same bits
    // times 2^k (and 6 sqrt(2) V cannot overflow).
    const int binary = std::ilogb(volume);
    const int e = binary >= 0 ? binary / 3 : -((2 - binary) / 3);
    const double m = std::ldexp(volume, -3 * e);
    return std::ldexp(std::cbrt(8.485281374238570 * m), e);  // 6 sqrt(2)
}

SizeFunction3 size_with_region_volumes_3d(const SizeFunction3& size,
                                          const tri::ConformingMesh3& recovered) {
    auto regions = std::make_shared<const BoundedRegions>(recovered);
    if (regions->empty()) return size;
    return SizeFunction3::analytic(
        [regions, size](double x, double y, double z) {
            const double p[3] = {x, y, z};
            return std::min(size(x, y, z), regions->edge_at(p));
        },
        "min(" + size.describe() + ", the regions' volume bounds as regular tetrahedron edges)");
}

}  // namespace exactmesh::generators
