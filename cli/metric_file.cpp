// SPDX-License-Identifier: MIT
// The metric file (see metric_file.hpp): io's Triangle readers, then the generators' checks.
#include "cli/metric_file.hpp"

#include <string>
#include <system_error>

#include "generators/stretched/metric_background_2d.hpp"
#include "io/format_error.hpp"
#include "io/triangle_format.hpp"

namespace exactmesh::cli {

std::filesystem::path metric_ele_path(const std::filesystem::path& node_path) {
    std::filesystem::path ele = node_path;
    return ele.replace_extension(".ele");
}

generators::MetricField2 read_metric_file(const std::filesystem::path& node_path) {
    io::NodeFile nodes = io::read_node(node_path);
    if (nodes.attribute_count != 3 && nodes.attribute_count != 4) {
        throw io::FormatError(node_path.string(), 0,
                              "a metric file's vertices carry 3 attributes M11 M12 M22 or 4 "
                              "DIR_X DIR_Y SIZE_ALONG ASPECT_RATIO; this one has " +
                                  std::to_string(nodes.attribute_count));
    }
    const generators::MetricFileForm form = nodes.attribute_count == 3
                                                ? generators::MetricFileForm::Matrices
                                                : generators::MetricFileForm::StretchingVectors;
    const std::filesystem::path ele_path = metric_ele_path(node_path);
    std::error_code error;
    if (!std::filesystem::exists(ele_path, error)) {
        throw io::FormatError(node_path.string(), 0,
                              "the metric file's triangles belong in " + ele_path.string() +
                                  ", which does not exist");
    }
    io::EleFile elements = io::read_ele(ele_path, nodes.first_index, nodes.vertex_count());
    const generators::MetricFileSource source{node_path.string(), ele_path.string(),
                                              nodes.first_index, nodes.lines};
    return generators::MetricField2::background_mesh(generators::background_metric_from_file(
        std::move(nodes.xy), form, nodes.attributes, std::move(elements.triangles), source));
}

}  // namespace exactmesh::cli
