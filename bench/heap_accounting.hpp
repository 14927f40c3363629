// SPDX-License-Identifier: MIT
// Peak live heap bytes of one construction, the same rule for ours and CGAL's: heap_accounting.cpp
// replaces every operator new/delete of the benchmark binary that links it (see its comment).
#pragma once

#include <cstddef>

namespace exactmesh::bench {

/// Starts a peak-heap measurement: returns the live bytes now, the base of the growth.
std::size_t start_heap_measurement();

/// The peak live bytes since start_heap_measurement() returned `before`, minus `before`.
double heap_growth_since(std::size_t before);

}  // namespace exactmesh::bench
