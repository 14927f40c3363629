// SPDX-License-Identifier: MIT
// Elliptic smoothing of a size field on a background grid (issue 6, "an elliptic (Laplace/
// Poisson) smoothing of a source field on a background grid"): the field s0 (e.g. point and
// line sources, whose sum and cap have kinks and may grow faster than a mesh can grade) sampled
// at the nodes of an NX x NY grid over a box, then
//  1. gradient-limited: s1 = the largest grid function <= s0 with |s1_i - s1_j| <= g h_ij for
//     grid neighbours i, j (h_ij the spacing), by Dijkstra's order from the smallest value
//     [Borouchaki-Hecht-Frey97: "Mesh gradation control", IJNME 43; the H-correction];
//  2. smoothed: s solves the screened Poisson equation s - L^2 Lap_h s = s1 (the 5-point
//     Laplacian with zero flux at the box's sides) by conjugate gradients to a stated residual
//     [Saad03 §6.7], so kinks of s1 are rounded over a length about L;
//  3. bilinear between the nodes; outside the box, the value at the nearest point of the box.
// Invariants (exact solution; the solver's residual perturbs them by about that much, and the
// nodes are clamped to the range exactly): min s0 <= s <= max s0 over the nodes, since
// (I - L^2 Lap_h) is an M-matrix with unit row sums; |ds/dx| <= g and |ds/dy| <= g in every
// cell (so |grad s| <= sqrt(2) g), since the x-differences of s solve the same kind of system
// with the x-differences of s1 as right-hand side (and likewise in y).
// Cost: N = NX · NY field evaluations, O(N log N) for step 1, O(N sqrt(kappa)) for step 2 with
// kappa <= 1 + 8 L^2 / h^2; a query O(1). Predicates: none (a size field, no combinatorics).
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "generators/size_function.hpp"

namespace exactmesh::generators {

class SmoothedSizeGrid2 {
  public:
    /// @param field finite and > 0 at every node of the grid over `box`.
    /// @throws InputError on a bad box, options or field value; GeometryError when conjugate
    ///         gradients miss options.residual within 10 N + 100 iterations.
    SmoothedSizeGrid2(const std::function<double(double, double)>& field, const SizeBox& box,
                      const SmoothingOptions& options = {});

    /// Bilinear between the nodes, (x, y) clamped to the box first.
    double operator()(double x, double y) const;

    std::uint32_t nx() const { return nx_; }
    std::uint32_t ny() const { return ny_; }
    double hx() const { return hx_; }
    double hy() const { return hy_; }
    double gradation() const { return gradation_; }
    double length() const { return length_; }
    const SizeBox& box() const { return box_; }
    /// NX · NY node values, row by row (node (i, j) at i + NX j): the smoothed field, the raw
    /// field s0 and the gradient-limited s1.
    const std::vector<double>& values() const { return values_; }
    const std::vector<double>& raw_values() const { return raw_; }
    const std::vector<double>& limited_values() const { return limited_; }
    int iterations() const { return iterations_; }  ///< conjugate gradient iterations
    double residual() const { return residual_; }   ///< the final ||r||_2 / ||b||_2

  private:
    SizeBox box_;
    std::uint32_t nx_ = 2, ny_ = 2;
    double hx_ = 1, hy_ = 1, gradation_ = 0, length_ = 0;
    std::vector<double> values_, raw_, limited_;
    int iterations_ = 0;
    double residual_ = 0;
};

}  // namespace exactmesh::generators
