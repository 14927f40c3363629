// SPDX-License-Identifier: MIT
// Metric smoothing (see metric_smoothing_2d.hpp).
#include "generators/stretched/metric_smoothing_2d.hpp"

#include <cmath>
#include <string>

#include "base/errors.hpp"
#include "base/number_text.hpp"
#include "generators/topology/mesh_edges.hpp"

namespace exactmesh::generators {

namespace {

void check_weight(double weight, const std::string& what) {
    if (!(weight >= 0 && weight <= 1))
        throw InputError("metric smoothing: " + what + " " + format_number(weight) +
                         " is not in [0, 1]");
}

}  // namespace

void smooth_vertex_metrics(const triangulation::Triangulation2& mesh, std::vector<Metric2>& metrics,
                           int passes, double weight, std::span<const double> vertex_weights) {
    const std::size_t vertices = mesh.vertex_count();
    if (metrics.size() != vertices) {
        throw InputError("metric smoothing: " + std::to_string(vertices) + " vertices but " +
                         std::to_string(metrics.size()) + " metrics");
    }
    if (passes < 0)
        throw InputError("metric smoothing: negative pass count " + std::to_string(passes));
    if (vertex_weights.empty()) {
        check_weight(weight, "weight");
    } else {
        if (vertex_weights.size() != vertices) {
            throw InputError("metric smoothing: " + std::to_string(vertices) + " vertices but " +
                             std::to_string(vertex_weights.size()) + " vertex weights");
        }
        for (std::size_t v = 0; v < vertices; ++v)
            check_weight(vertex_weights[v], "weight of vertex " + std::to_string(v));
    }
    // The neighbours of each vertex (CSR) from the edge list.
    const std::vector<triangulation::VertIdx> edges = mesh_edges_2d(mesh.triangles);
    std::vector<std::size_t> start(vertices + 1, 0);
    for (const triangulation::VertIdx v : edges) ++start[v + 1];
    for (std::size_t v = 0; v < vertices; ++v) start[v + 1] += start[v];
    std::vector<triangulation::VertIdx> neighbours(edges.size());
    std::vector<std::size_t> fill(start.begin(), start.end() - 1);
    for (std::size_t e = 0; e + 1 < edges.size(); e += 2) {
        neighbours[fill[edges[e]]++] = edges[e + 1];
        neighbours[fill[edges[e + 1]]++] = edges[e];
    }
    std::vector<Metric2> previous;
    std::vector<Metric2> star;
    std::vector<double> star_weights;
    for (int pass = 0; pass < passes; ++pass) {
        previous = metrics;
        for (std::size_t v = 0; v < vertices; ++v) {
            const std::size_t degree = start[v + 1] - start[v];
            const double w = vertex_weights.empty() ? weight : vertex_weights[v];
            if (degree == 0 || w == 0) continue;
            star.assign(1, previous[v]);
            star_weights.assign(1, 1.0 - w);
            for (std::size_t k = start[v]; k < start[v + 1]; ++k) {
                star.push_back(previous[neighbours[k]]);
                star_weights.push_back(w / static_cast<double>(degree));
            }
            metrics[v] = log_euclidean_mean(star, star_weights);
        }
    }
}

}  // namespace exactmesh::generators
