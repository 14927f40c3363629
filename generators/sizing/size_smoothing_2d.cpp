// SPDX-License-Identifier: MIT
// Smoothed size grid (see size_smoothing_2d.hpp).
#include "generators/sizing/size_smoothing_2d.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <queue>
#include <string>
#include <utility>

#include "base/errors.hpp"
#include "base/number_text.hpp"

namespace exactmesh::generators {

namespace {

/// H(v) in place: the largest grid function <= v with |H_i - H_j| <= g |x_i - x_j| for the
/// grid neighbours j of i in a 16-neighbour stencil (the 4 axis neighbours, the 4 diagonal ones
/// and the 8 knight moves: the cones of H are then 16-gons within 2.7% of round, where the 4
/// axis neighbours alone give diamonds with kinks along the axes [Borgefors86: "Distance
/// transformations in digital images", CVGIP 34]). Dijkstra from the smallest values: a node's
/// value is final when it leaves the queue, and then bounds its neighbours by value + g h.
void limit_gradient(std::vector<double>& v, std::uint32_t nx, std::uint32_t ny, double hx,
                    double hy, double g) {
    if (!std::isfinite(g)) return;
    struct Step {
        int di, dj;
        double rise;
    };
    std::vector<Step> stencil;
    for (int dj = -2; dj <= 2; ++dj) {
        for (int di = -2; di <= 2; ++di) {
            const int a = std::abs(di), b = std::abs(dj);
            if ((a == 0 && b == 0) || a + b > 3 || (a == 2 && b != 1) || (b == 2 && a != 1))
                continue;
            stencil.push_back({di, dj, g * std::hypot(di * hx, dj * hy)});
        }
    }
    const std::size_t n = v.size();
    using Entry = std::pair<double, std::size_t>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
    for (std::size_t k = 0; k < n; ++k) queue.push({v[k], k});
    std::vector<char> done(n, 0);
    while (!queue.empty()) {
        const auto [value, k] = queue.top();
        queue.pop();
        if (done[k] || value != v[k]) continue;
        done[k] = 1;
        const auto i = static_cast<std::int64_t>(k % nx), j = static_cast<std::int64_t>(k / nx);
        for (const Step& step : stencil) {
            const std::int64_t mi = i + step.di, mj = j + step.dj;
            if (mi < 0 || mj < 0 || mi >= nx || mj >= ny) continue;
            const auto m = static_cast<std::size_t>(mi + std::int64_t{nx} * mj);
            const double bound = value + step.rise;
            if (!done[m] && bound < v[m]) {
                v[m] = bound;
                queue.push({bound, m});
            }
        }
    }
}

}  // namespace

double smoothing_iterations_estimate(std::uint32_t nx, std::uint32_t ny, double hx, double hy,
                                     double length, double residual) {
    // Conjugate gradients reduce the residual by `residual` within about
    // sqrt(kappa) ln(2 / residual) / 2 iterations [Saad03 §6.11], kappa <= 1 + 4 L^2 (1/hx^2 +
    // 1/hy^2) for I + L^2 A; for long lengths the pinned minima bound it by the grid's extent
    // instead (measured: about 5 (nx + ny) at residual 1e-10, taken twice).
    const double rx = length / hx, ry = length / hy;
    const double kappa = 1 + 4 * (rx * rx + ry * ry);
    const double digits = std::log(2 / residual);
    const double by_condition = 0.5 * std::sqrt(kappa) * digits;
    const double by_extent = 0.44 * (static_cast<double>(nx) + static_cast<double>(ny)) * digits;
    const double estimate = std::min(by_condition, by_extent);
    return std::isfinite(estimate) ? estimate : by_extent;
}

SmoothedSizeGrid2::SmoothedSizeGrid2(const std::function<double(double, double)>& field,
                                     const SizeBox& box, const SmoothingOptions& options)
    : box_(box), nx_(options.nx), ny_(options.ny) {
    if (!(std::isfinite(box.x0) && std::isfinite(box.y0) && std::isfinite(box.x1) &&
          std::isfinite(box.y1) && box.x0 < box.x1 && box.y0 < box.y1 &&
          std::isfinite(box.x1 - box.x0) && std::isfinite(box.y1 - box.y0))) {
        throw InputError("size smoothing: the box must be finite with x0 < x1 and y0 < y1");
    }
    if (nx_ < 2 || ny_ < 2 || std::uint64_t{nx_} * ny_ > kMaxSmoothingNodes) {
        throw InputError(
            "size smoothing: the grid must have at least 2 nodes each way and at most " +
            std::to_string(kMaxSmoothingNodes) +
            " nodes in all (1024 x 1024; a larger grid takes minutes) (got " + std::to_string(nx_) +
            " x " + std::to_string(ny_) + " = " + std::to_string(std::uint64_t{nx_} * ny_) + ")");
    }
    if (!(options.gradation > 0) || std::isnan(options.gradation)) {
        throw InputError("size smoothing: the gradation must be > 0 (got " +
                         format_number(options.gradation) + ")");
    }
    if (!(options.length >= 0 && std::isfinite(options.length))) {
        throw InputError("size smoothing: the length must be a finite number >= 0 (got " +
                         format_number(options.length) + ")");
    }
    if (!(options.residual > 0 && options.residual < 1)) {
        throw InputError("size smoothing: the residual must be in (0, 1) (got " +
                         format_number(options.residual) + ")");
    }
    hx_ = (box.x1 - box.x0) / (nx_ - 1);
    hy_ = (box.y1 - box.y0) / (ny_ - 1);
    gradation_ = options.gradation;
    length_ = options.length > 0 ? options.length : 2 * std::max(hx_, hy_);
    const std::size_t n = std::size_t{nx_} * ny_;
    // The solve's work before any of it is done: refused at once when too long.
    const double iterations =
        smoothing_iterations_estimate(nx_, ny_, hx_, hy_, length_, options.residual);
    if (iterations * static_cast<double>(n) > kMaxSmoothingWork) {
        throw InputError(
            "size smoothing: the solve on " + std::to_string(nx_) + " x " + std::to_string(ny_) +
            " nodes (cells " + format_number(hx_) + " x " + format_number(hy_) + ", length " +
            format_number(length_) + ") would take about " +
            std::to_string(static_cast<std::uint64_t>(iterations)) +
            " conjugate gradient iterations, " +
            std::to_string(static_cast<std::uint64_t>(iterations * static_cast<double>(n))) +
            " node-iterations, more than the cap of 2^29 (seconds of work): use fewer nodes, "
            "cells closer to square, or a shorter length");
    }
    auto node_x = [&](std::uint32_t i) { return i + 1 == nx_ ? box.x1 : box.x0 + hx_ * i; };
    auto node_y = [&](std::uint32_t j) { return j + 1 == ny_ ? box.y1 : box.y0 + hy_ * j; };

    raw_.resize(n);
    for (std::uint32_t j = 0; j < ny_; ++j) {
        for (std::uint32_t i = 0; i < nx_; ++i) {
            const double s = field(node_x(i), node_y(j));
            if (!(std::isfinite(s) && s > 0)) {
                throw InputError("size smoothing: the size field is " + format_number(s) + " at (" +
                                 format_number(node_x(i)) + ", " + format_number(node_y(j)) +
                                 "); it must be finite and > 0 in the box");
            }
            raw_[i + std::size_t{nx_} * j] = s;
        }
    }

    // 1. The gradient limit.
    limited_ = raw_;
    limit_gradient(limited_, nx_, ny_, hx_, hy_, gradation_);

    // 2. The pins: local minima of s1 along the grid (not on a plateau).
    pinned_.assign(n, 0);
    if (options.pin_minima) {
        for (std::size_t j = 0; j < ny_; ++j) {
            for (std::size_t i = 0; i < nx_; ++i) {
                const std::size_t k = i + std::size_t{nx_} * j;
                bool lowest = true, below_one = false;
                auto compare = [&](std::size_t m) {
                    lowest = lowest && limited_[k] <= limited_[m];
                    below_one = below_one || limited_[k] < limited_[m];
                };
                if (i > 0) compare(k - 1);
                if (i + 1 < nx_) compare(k + 1);
                if (j > 0) compare(k - nx_);
                if (j + 1 < ny_) compare(k + nx_);
                pinned_[k] = lowest && below_one ? 1 : 0;
            }
        }
    }

    // 3. (I + L^2 A) s = s1 at the free nodes, s = s1 at the pinned ones, A the graph
    // Laplacian of the grid with weights 1/hx^2 and 1/hy^2 (zero flux at the sides: a missing
    // neighbour is no term). The pinned values go to the right-hand side, the pinned rows are
    // the identity: symmetric positive definite.
    const double wx = length_ * length_ / (hx_ * hx_), wy = length_ * length_ / (hy_ * hy_);
    auto for_neighbours = [&](std::size_t k, auto&& f) {
        const std::size_t i = k % nx_, j = k / nx_;
        if (i > 0) f(k - 1, wx);
        if (i + 1 < nx_) f(k + 1, wx);
        if (j > 0) f(k - nx_, wy);
        if (j + 1 < ny_) f(k + nx_, wy);
    };
    auto apply = [&](const std::vector<double>& v, std::vector<double>& out) {
        for (std::size_t k = 0; k < n; ++k) {
            double r = v[k];
            if (!pinned_[k]) {
                for_neighbours(k, [&](std::size_t m, double w) {
                    r += w * (v[k] - (pinned_[m] ? 0.0 : v[m]));
                });
            }
            out[k] = r;
        }
    };
    auto dot = [](const std::vector<double>& a, const std::vector<double>& b) {
        double sum = 0;
        for (std::size_t k = 0; k < a.size(); ++k) sum += a[k] * b[k];
        return sum;
    };
    std::vector<double> b(limited_);
    for (std::size_t k = 0; k < n; ++k) {
        if (!pinned_[k]) {
            for_neighbours(
                k, [&](std::size_t m, double w) { b[k] += pinned_[m] ? w * limited_[m] : 0.0; });
        }
    }
    values_ = limited_;
    std::vector<double> r(n), p(n), q(n);
    apply(values_, q);
    for (std::size_t k = 0; k < n; ++k) r[k] = b[k] - q[k];
    p = r;
    const double norm_b = std::sqrt(dot(b, b));
    double rr = dot(r, r);
    // The estimate above with a margin of 4 (it was within a factor 2.5 of every measured
    // count); past it the solve stops with GeometryError instead of running on.
    const std::uint64_t budget = std::min<std::uint64_t>(
        10 * std::uint64_t{n} + 100, static_cast<std::uint64_t>(4 * iterations) + 100);
    std::uint64_t iteration = 0;
    while (std::sqrt(rr) > options.residual * norm_b) {
        if (iteration++ >= budget) {
            throw GeometryError(
                "size smoothing: conjugate gradients reached only a relative residual of " +
                format_number(std::sqrt(rr) / norm_b) + " after " + std::to_string(budget) +
                " iterations (asked " + format_number(options.residual) + ")");
        }
        apply(p, q);
        const double alpha = rr / dot(p, q);
        for (std::size_t k = 0; k < n; ++k) values_[k] += alpha * p[k], r[k] -= alpha * q[k];
        const double next = dot(r, r);
        const double beta = next / rr;
        rr = next;
        for (std::size_t k = 0; k < n; ++k) p[k] = r[k] + beta * p[k];
    }
    iterations_ = static_cast<int>(iteration);
    residual_ = std::sqrt(rr) / norm_b;
    const auto [lo, hi] = std::minmax_element(limited_.begin(), limited_.end());
    for (std::size_t k = 0; k < n; ++k)
        values_[k] = pinned_[k] ? limited_[k] : std::clamp(values_[k], *lo, *hi);

    // 4. The gradient limit again (the dips at the pins).
    limit_gradient(values_, nx_, ny_, hx_, hy_, gradation_);
}

std::size_t SmoothedSizeGrid2::pinned_count() const {
    return static_cast<std::size_t>(std::count(pinned_.begin(), pinned_.end(), 1));
}

double SmoothedSizeGrid2::operator()(double x, double y) const {
    double fx = (std::clamp(x, box_.x0, box_.x1) - box_.x0) / hx_;
    double fy = (std::clamp(y, box_.y0, box_.y1) - box_.y0) / hy_;
    fx = fx >= 0 ? fx : 0, fy = fy >= 0 ? fy : 0;  // NaN -> 0
    const auto i = std::min(static_cast<std::uint32_t>(fx), nx_ - 2);
    const auto j = std::min(static_cast<std::uint32_t>(fy), ny_ - 2);
    const double u = std::clamp(fx - i, 0.0, 1.0), v = std::clamp(fy - j, 0.0, 1.0);
    const double* row = values_.data() + i + std::size_t{nx_} * j;
    const double* above = row + nx_;
    return (1 - v) * ((1 - u) * row[0] + u * row[1]) + v * ((1 - u) * above[0] + u * above[1]);
}

}  // namespace exactmesh::generators
