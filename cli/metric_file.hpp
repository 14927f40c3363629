// SPDX-License-Identifier: MIT
// The metric file of `--metric FILE` [issue 14]: a Triangle .node file whose vertices carry
// either 3 attributes M11 M12 M22 (a symmetric positive definite matrix per vertex) or 4
// attributes DIR_X DIR_Y SIZE_ALONG ASPECT_RATIO (a stretching vector: size SIZE_ALONG along the
// direction, SIZE_ALONG / ASPECT_RATIO across it), and the
// .ele file of the same name beside it (its triangles, counter-clockwise). The field is the
// background metric mesh of generators/stretched/metric_background_2d.hpp: log-Euclidean
// linear inside the triangles, the nearest boundary point's value outside.
#pragma once

#include <filesystem>

#include "generators/stretched/metric_field_2d.hpp"

namespace exactmesh::cli {

/// The .ele file a metric .node names: the same path with the extension .ele.
std::filesystem::path metric_ele_path(const std::filesystem::path& node_path);

/// Reads `node_path` and its .ele.
/// @throws io::FormatError "file:line: problem" for malformed files or vertices with neither 3
///         nor 4 attributes ("file: ..."), InputError "file:line: vertex N: metric
///         (M11, M12, M22) = (...) is not positive definite ..." for a bad matrix, "file.ele:
///         background mesh: triangle T: ..." for a bad triangle (T 0-based).
generators::MetricField2 read_metric_file(const std::filesystem::path& node_path);

}  // namespace exactmesh::cli
