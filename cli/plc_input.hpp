// SPDX-License-Identifier: MIT
// A PLC file's content (io::PlcFile, plain data) as the triangulation layer's Plc3. It lives in
// cli/ because only the command (and the Python module) may include both io/ and
// triangulation/ (DESIGN.md's arrows); it is a field-by-field copy, header-only so that every
// subcommand reading a PLC (tetmesh, check) shares it.
#pragma once

#include <utility>

#include "io/plc_format.hpp"
#include "triangulation/recovery_3d/plc_3d.hpp"

namespace exactmesh::cli {

/// The PLC of `file`, numbered as the file numbers its vertices (messages of validate_plc_3d
/// then name the file's vertex and facet numbers).
inline triangulation::Plc3 plc_from_file(io::PlcFile file) {
    triangulation::Plc3 plc;
    plc.xyz = std::move(file.xyz);
    plc.first_index = file.first_index;
    plc.facets.reserve(file.facets.size());
    for (io::PlcFacetRecord& record : file.facets) {
        triangulation::Facet3 facet;
        facet.polygons = std::move(record.polygons);
        facet.holes = std::move(record.holes);
        facet.marker = record.marker;
        plc.facets.push_back(std::move(facet));
    }
    plc.holes = std::move(file.holes);
    for (std::size_t r = 0; r + 4 < file.regions.size(); r += 5) {
        plc.regions.push_back({file.regions[r], file.regions[r + 1], file.regions[r + 2],
                               file.regions[r + 3], file.regions[r + 4]});
    }
    return plc;
}

}  // namespace exactmesh::cli
