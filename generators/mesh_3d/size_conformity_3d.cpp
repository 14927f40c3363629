// SPDX-License-Identifier: MIT
#include "generators/mesh_3d/size_conformity_3d.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "triangulation/mesh/vertex_keys_3d.hpp"

namespace exactmesh::generators {

SizeConformity3 size_conformity_3d(const triangulation::Tetrahedralization3& mesh,
                                   const SizeFunction3& size) {
    std::vector<std::uint64_t> keys;
    keys.reserve(6 * std::size_t{mesh.tet_count()});
    for (std::size_t t = 0; 4 * t < mesh.tets.size(); ++t) {
        const triangulation::VertIdx* v = &mesh.tets[4 * t];
        for (unsigned i = 0; i < 4; ++i)
            for (unsigned j = i + 1; j < 4; ++j)
                keys.push_back(triangulation::edge_key(v[i], v[j]));
    }
    std::sort(keys.begin(), keys.end());
    keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
    SizeConformity3 r;
    r.edges = keys.size();
    if (keys.empty()) return r;
    std::vector<double> ratios;
    ratios.reserve(keys.size());
    double sum = 0;
    std::uint64_t within = 0;
    for (const std::uint64_t key : keys) {
        const double* a = mesh.point(static_cast<triangulation::VertIdx>(key >> 32));
        const double* b = mesh.point(static_cast<triangulation::VertIdx>(key & 0xFFFFFFFFu));
        const double h = size(a[0] / 2 + b[0] / 2, a[1] / 2 + b[1] / 2, a[2] / 2 + b[2] / 2);
        const double ratio = std::hypot(b[0] - a[0], b[1] - a[1], b[2] - a[2]) / h;
        ratios.push_back(ratio);
        sum += ratio;
        within += ratio >= 0.7 && ratio <= 1.4 ? 1 : 0;
    }
    r.mean = sum / static_cast<double>(ratios.size());
    r.within = static_cast<double>(within) / static_cast<double>(ratios.size());
    std::sort(ratios.begin(), ratios.end());
    r.min = ratios.front();
    r.max = ratios.back();
    r.median = ratios[ratios.size() / 2];
    return r;
}

}  // namespace exactmesh::generators
