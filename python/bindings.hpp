// SPDX-License-Identifier: MIT
// The parts of the `exactmesh._exactmesh` extension module, one file per layer they wire.
#pragma once

#include <pybind11/pybind11.h>

#include <vector>

#include "triangulation/constrained/constrained_2d.hpp"

namespace exactmesh::python {

void bind_predicates(pybind11::module_& m);
void bind_triangulation(pybind11::module_& m);
void bind_generators(pybind11::module_& m);
void bind_fuzzing(pybind11::module_& m);

/// A thread count as the command's --threads takes it (0: every core), returned.
/// @throws InputError above triangulation::kMaxThreads.
unsigned checked_threads(unsigned threads);

/// A constrained triangulation (cdt(), mesh()) as a dict of numpy arrays that take over its
/// vectors: points, triangles, neighbors, input_vertex_count, merged_into, pieces,
/// piece_segment, quads (4 per row, empty for a triangle mesh), warnings, counters.
pybind11::dict constrained_result_dict(triangulation::Cdt2Result&& result,
                                       std::vector<triangulation::VertIdx>&& quads);

}  // namespace exactmesh::python
