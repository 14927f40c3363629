// SPDX-License-Identifier: MIT
// Region flood in 3D (see region_flood_3d.hpp).
#include "triangulation/recovery_3d/region_flood_3d.hpp"

#include <algorithm>
#include <utility>

#include "base/number_text.hpp"
#include "predicates/orient3d.hpp"

namespace exactmesh::triangulation {

using predicates::Sign;

FaceSet3 face_set_3d(std::span<const VertIdx> faces) {
    FaceSet3 set;
    set.reserve(faces.size() / 3);
    for (std::size_t f = 0; f + 2 < faces.size(); f += 3)
        set.insert(sorted3(faces[f], faces[f + 1], faces[f + 2]));
    return set;
}

TetIdx locate_closed_tetrahedron_3d(const Tetrahedralization3& mesh, const double* p) {
    for (TetIdx t = 0; t < mesh.tet_count(); ++t) {
        bool in = true;
        for (unsigned k = 0; k < 4 && in; ++k) {
            const unsigned* lf = kFaceVertex[k];
            in = predicates::orient3d(mesh.point(mesh.tets[4 * std::size_t{t} + lf[0]]),
                                      mesh.point(mesh.tets[4 * std::size_t{t} + lf[1]]),
                                      mesh.point(mesh.tets[4 * std::size_t{t} + lf[2]]),
                                      p) != Sign::Negative;
        }
        if (in) return t;
    }
    return kNone;
}

void flood_tetrahedra_3d(const Tetrahedralization3& mesh, const FaceSet3& barrier,
                         std::vector<TetIdx> seeds, std::vector<std::uint8_t>& mark,
                         std::uint8_t value) {
    std::vector<TetIdx>& stack = seeds;
    while (!stack.empty()) {
        const TetIdx t = stack.back();
        stack.pop_back();
        if (mark[t] == value) continue;
        mark[t] = value;
        for (unsigned k = 0; k < 4; ++k) {
            const TetIdx n = mesh.neighbors[4 * std::size_t{t} + k];
            if (n == kNone || mark[n] == value) continue;
            const unsigned* lf = kFaceVertex[k];
            if (barrier.count(sorted3(mesh.tets[4 * std::size_t{t} + lf[0]],
                                      mesh.tets[4 * std::size_t{t} + lf[1]],
                                      mesh.tets[4 * std::size_t{t} + lf[2]])) != 0)
                continue;
            stack.push_back(n);
        }
    }
}

RegionAssignment3 assign_regions_3d(const Plc3& plc, const Tetrahedralization3& mesh,
                                    const FaceSet3& subfaces,
                                    std::span<const std::uint8_t> removed) {
    RegionAssignment3 out;
    if (plc.regions.empty()) return out;
    const TetIdx count = mesh.tet_count();
    const auto in_domain = [&](TetIdx t) { return removed.empty() || removed[t] == 0; };
    // Located once each: the warnings first (in the list's order), then the floods.
    std::vector<TetIdx> seeds(plc.regions.size(), kNone);
    for (std::size_t r = 0; r < plc.regions.size(); ++r) {
        const Region3& region = plc.regions[r];
        const double p[3] = {region.x, region.y, region.z};
        const TetIdx t = locate_closed_tetrahedron_3d(mesh, p);
        if (t != kNone && in_domain(t)) {
            seeds[r] = t;
        } else {
            out.warnings.push_back("region point " + std::to_string(r + plc.first_index) + " " +
                                   format_point(p, 3) +
                                   " lies outside the domain or in a hole: ignored");
        }
    }
    out.attributes.assign(count, 0.0);
    const bool bounded = std::any_of(plc.regions.begin(), plc.regions.end(),
                                     [](const Region3& region) { return region.max_volume > 0; });
    if (bounded) out.max_volumes.assign(count, -1.0);
    std::vector<std::uint8_t> seen(count, 0);
    for (std::size_t r = 0; r < plc.regions.size(); ++r) {
        if (seeds[r] == kNone) continue;
        // A later region point in the same region overrides an earlier one (TetGen's order):
        // each flood starts afresh and writes every tetrahedron it reaches.
        std::fill(seen.begin(), seen.end(), 0);
        flood_tetrahedra_3d(mesh, subfaces, {seeds[r]}, seen, 1);
        for (TetIdx t = 0; t < count; ++t) {
            if (seen[t] == 0) continue;
            out.attributes[t] = plc.regions[r].attribute;
            if (bounded) out.max_volumes[t] = plc.regions[r].max_volume;
        }
    }
    return out;
}

std::vector<std::string> assign_regions_3d(const Plc3& plc, ConformingMesh3& mesh) {
    RegionAssignment3 regions = assign_regions_3d(plc, mesh.mesh, face_set_3d(mesh.subfaces), {});
    mesh.tet_attributes = std::move(regions.attributes);
    mesh.tet_max_volume = std::move(regions.max_volumes);
    return std::move(regions.warnings);
}

}  // namespace exactmesh::triangulation
