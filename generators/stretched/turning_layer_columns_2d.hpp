// SPDX-License-Identifier: MIT
// Structured columns across thin layers that turn (issue 14): the points of a metric field's thin
// layer whose along-direction lines curve so much that the chord of one cell along the layer
// sags by several times the layer's thickness [the structured layers of advancing-layer methods,
// Pirzadeh96 "Three-dimensional unstructured viscous grids by the advancing-layers method", AIAA
// J. 34; George-Borouchaki98 ch. 10 on metrics; the layer's "ridge" as the curve of smallest size
// across]. Such a layer's cells fit only in columns across it lined up from layer to layer (a
// vertex of the next layer a fraction of a cell off a chord's span lies above the chord), which
// unstructured insertion does not find (README, known gaps, metric-delaunay):
//  1. ridges: from samples of the field on a grid over the domain's box, a line search along the
//     metric's direction across (golden section) finds the point of smallest size across; it is
//     kept when it is a strict minimum (the size grows by half within a few sizes on both sides),
//     lies in the domain, and the layer turns there (the chord of one size along sags by more than
//     `sag_ratio` sizes across, the turning sampled half a size along on either side);
//  2. each ridge is traced along the layer (steps of a quarter size along, each point projected
//     back on the ridge by the line search) until it closes on itself, leaves the domain or its
//     aspect ratio falls below `ridge_aspect` (it is followed where it turns less too, so that
//     the columns of one turn and the next stay one structure), then resampled at equal metric
//     spacing (unit along, in the metric at each chord's middle);
//  3. from each of its points a column is traced both ways across the layer, along the field's
//     direction across (midpoint rule), with steps of `layer_spacing` in the geometric mean of
//     the sizes across at their ends, until it leaves the domain or the aspect ratio falls below
//     `stop_aspect`; all columns stop at the first layer where two neighbours stand outside
//     [`spacing_low`, `spacing_high`] along (metric at the middle).
// The points are heuristic placements in doubles (trial points for the metric Delaunay
// insertion, which keeps every exactness rule: in_ellipse cavities, exact orient2d, the spacing
// test). Scale-free: sums of coordinates and lengths, ratios of sizes, unit vectors; a domain and
// its field scaled by 2^k give the points scaled by 2^k. Cost: grid^2 field samples, a line
// search of about 30 samples from each sample that is anisotropic and turning, and O(points)
// samples per ridge. Calls no predicate: inside() decides what lies in the domain.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "generators/stretched/metric_field_2d.hpp"

namespace exactmesh::generators {

struct TurningLayerColumnsOptions2 {
    /// A ridge is structured where the chord of one size along sags by more than this many
    /// sizes across (21 on the curved layer of aspect ratio 1000, 2.1 at 100).
    double sag_ratio = 4;
    /// A ridge is followed while its aspect ratio (size along over size across) is at least this.
    double ridge_aspect = 10;
    /// Metric length across the layer between the points of a column (the quadrilaterals'
    /// diagonals then stay below sqrt 2).
    double layer_spacing = 0.8;
    /// A column ends where the size along is less than this many sizes across.
    double stop_aspect = 3;
    /// Columns end at the first layer where two neighbours are closer or farther than these
    /// (metric length along).
    double spacing_low = 0.75;
    double spacing_high = 1.35;
    /// Samples per side of the domain's box searched for ridges.
    int grid = 32;
};

/// The points of the columns (x0, y0, x1, y1, ...; ridges in the order found, each ridge's
/// columns in order, each column from the ridge outwards), at most max_points of them.
/// `box`: xmin, ymin, xmax, ymax of the domain; `inside(x, y)`: whether a point is in the domain.
/// The field is evaluated at points of the box and near it; a point where it throws InputError is
/// treated as outside.
std::vector<double> turning_layer_columns_2d(const MetricField2& field,
                                             const std::array<double, 4>& box,
                                             const std::function<bool(double, double)>& inside,
                                             const TurningLayerColumnsOptions2& options,
                                             std::uint64_t max_points);

}  // namespace exactmesh::generators
