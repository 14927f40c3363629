// SPDX-License-Identifier: MIT
// Elliptic smoothing of a size field on a background grid (issue 6, "an elliptic (Laplace/
// Poisson) smoothing of a source field on a background grid"): the field s0 (e.g. point and
// line sources, whose min, sum and cap have kinks and may grow faster than a mesh can grade)
// sampled at the nodes of an NX x NY grid over a box, then
//  1. gradient-limited: s1 = H(s0), H(f) the largest grid function <= f with
//     |H_i - H_j| <= g |x_i - x_j| for the nodes j of a 16-neighbour stencil about i (axis,
//     diagonal and knight moves: round cones, where 4 neighbours give diamonds), by Dijkstra's
//     order from the smallest value [Borouchaki-Hecht-Frey97: "Mesh gradation control", IJNME
//     43; Borgefors86 for the stencil];
//  2. smoothed: s2 solves the screened Poisson equation s - L^2 Lap_h s = s1 (5-point
//     Laplacian, zero flux at the box's sides) with s2 = s1 (Dirichlet) at the nodes where s1
//     has a local minimum (<= its grid neighbours, < one of them: where a source dominates), by
//     conjugate gradients to a stated residual [Saad03 §6.7]; kinks of s1 are rounded over a
//     length about L;
//  3. s = H(s2): a pinned minimum may leave a dip steeper than g, which this limits again
//     (elsewhere s2's axis slopes are already at most g, see below);
//  4. bilinear between the nodes; outside the box, the value at the nearest point of the box.
// Guarantees (proofs/invariants/size_fields_2d.md): |s_i - s_j| <= g h_ij on every grid edge
// (step 3, up to one rounding), so |ds/dx| <= g and |ds/dy| <= g in every cell and
// |grad s| <= sqrt(2) g; min s0 <= s <= max s0 (H only lowers and never below the smallest
// value; the smoothing is an M-matrix system with unit row sums, clamped to s1's range against
// the residual); s <= s0 at the pinned minima (the mesh is never coarser than asked at a
// source). Without pins, the x-differences of s2 solve the same kind of system with those of s1
// as right-hand side (zero flux makes the operators commute), so s2 keeps s1's axis-slope bound.
// Cost: N = NX · NY field evaluations, O(N log N) for H, O(N sqrt(kappa)) for the solve with
// kappa <= 1 + 8 L^2 / h^2; a query O(1). Bounded before any work (issue 11: `smooth 4096 4096`
// took minutes, and so did 16384 x 64 over a square, its cells 256:1): N <= 2^20 and the
// estimated solve at most 2^29 node-iterations, else InputError. Predicates: none (a size field, no
// combinatorics).
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "generators/sizing/size_function.hpp"

namespace exactmesh::generators {

/// The most grid nodes (1024 x 1024: measured 1.3 s to build with the default length, where
/// 2048 x 2048 took 7 s and 4096 x 4096 minutes).
inline constexpr std::uint64_t kMaxSmoothingNodes = std::uint64_t{1} << 20;
/// The most work of the solve: estimated iterations (smoothing_iterations_estimate) times nodes,
/// about 3.5 s at the 1.5e8 node-iterations per second measured (2048 x 64 over a unit box, its
/// cells 32:1: 1.2 s; refused: 4096 x 256, cells 16:1, 7.7 s, and 1024 x 1024 with length 10,
/// 53 s).
inline constexpr double kMaxSmoothingWork = 0x1p29;

/// The conjugate gradient iterations the solve is expected to need on an nx x ny grid of
/// spacings hx, hy with smoothing length `length` to reach `residual` (an upper estimate).
double smoothing_iterations_estimate(std::uint32_t nx, std::uint32_t ny, double hx, double hy,
                                     double length, double residual);

class SmoothedSizeGrid2 {
  public:
    /// @param field finite and > 0 at every node of the grid over `box`.
    /// @throws InputError on a bad box, options or field value, more than kMaxSmoothingNodes
    ///         nodes, or an estimated solve above kMaxSmoothingWork; GeometryError when
    ///         conjugate gradients miss options.residual within 4 times the estimated
    ///         iterations + 100 (at most 10 N + 100).
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
    /// NX · NY node values, row by row (node (i, j) at i + NX j): the final field s, the raw
    /// field s0 and the gradient-limited s1; pinned(k): node k kept s1 in the smoothing.
    const std::vector<double>& values() const { return values_; }
    const std::vector<double>& raw_values() const { return raw_; }
    const std::vector<double>& limited_values() const { return limited_; }
    bool pinned(std::size_t k) const { return pinned_[k] != 0; }
    std::size_t pinned_count() const;
    int iterations() const { return iterations_; }  ///< conjugate gradient iterations
    double residual() const { return residual_; }   ///< the final ||r||_2 / ||b||_2

  private:
    SizeBox box_;
    std::uint32_t nx_ = 2, ny_ = 2;
    double hx_ = 1, hy_ = 1, gradation_ = 0, length_ = 0;
    std::vector<double> values_, raw_, limited_;
    std::vector<char> pinned_;
    int iterations_ = 0;
    double residual_ = 0;
};

}  // namespace exactmesh::generators
