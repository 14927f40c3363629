// SPDX-License-Identifier: MIT
// A PLC file's content as a triangulation::Plc3, for tests and fuzz targets: the same copy as
// cli/plc_input.hpp, which tests/ may not include (cmake/CheckLayering.cmake).
#pragma once

#include <utility>

#include "io/plc_format.hpp"
#include "triangulation/recovery_3d/plc_3d.hpp"

namespace exactmesh::testing {

inline triangulation::Plc3 plc_from_file(io::PlcFile file) {
    triangulation::Plc3 plc;
    plc.xyz = std::move(file.xyz);
    plc.first_index = file.first_index;
    for (io::PlcFacetRecord& record : file.facets) {
        plc.facets.push_back({std::move(record.polygons), std::move(record.holes), record.marker});
    }
    plc.holes = std::move(file.holes);
    for (std::size_t r = 0; r + 4 < file.regions.size(); r += 5) {
        plc.regions.push_back({file.regions[r], file.regions[r + 1], file.regions[r + 2],
                               file.regions[r + 3], file.regions[r + 4]});
    }
    return plc;
}

}  // namespace exactmesh::testing
