// SPDX-License-Identifier: MIT
// Smoothed size grid (see size_smoothing_2d.hpp).
#include "generators/size_smoothing_2d.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <queue>
#include <string>
#include <utility>

#include "predicates/errors.hpp"

namespace exactmesh::generators {

namespace {

std::string number_text(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", value);
    return text;
}

}  // namespace

SmoothedSizeGrid2::SmoothedSizeGrid2(const std::function<double(double, double)>& field,
                                     const SizeBox& box, const SmoothingOptions& options)
    : box_(box), nx_(options.nx), ny_(options.ny) {
    if (!(std::isfinite(box.x0) && std::isfinite(box.y0) && std::isfinite(box.x1) &&
          std::isfinite(box.y1) && box.x0 < box.x1 && box.y0 < box.y1 &&
          std::isfinite(box.x1 - box.x0) && std::isfinite(box.y1 - box.y0))) {
        throw InputError("size smoothing: the box must be finite with x0 < x1 and y0 < y1");
    }
    if (nx_ < 2 || ny_ < 2 || std::uint64_t{nx_} * ny_ > (std::uint64_t{1} << 26)) {
        throw InputError(
            "size smoothing: the grid must have 2 to 2^26 nodes, at least 2 each way (got " +
            std::to_string(nx_) + " x " + std::to_string(ny_) + ")");
    }
    if (!(options.gradation > 0) || std::isnan(options.gradation)) {
        throw InputError("size smoothing: the gradation must be > 0 (got " +
                         number_text(options.gradation) + ")");
    }
    if (!(options.length >= 0 && std::isfinite(options.length))) {
        throw InputError("size smoothing: the length must be a finite number >= 0 (got " +
                         number_text(options.length) + ")");
    }
    if (!(options.residual > 0 && options.residual < 1)) {
        throw InputError("size smoothing: the residual must be in (0, 1) (got " +
                         number_text(options.residual) + ")");
    }
    hx_ = (box.x1 - box.x0) / (nx_ - 1);
    hy_ = (box.y1 - box.y0) / (ny_ - 1);
    gradation_ = options.gradation;
    length_ = options.length > 0 ? options.length : 2 * std::max(hx_, hy_);
    const std::size_t n = std::size_t{nx_} * ny_;
    auto node_x = [&](std::uint32_t i) { return i + 1 == nx_ ? box.x1 : box.x0 + hx_ * i; };
    auto node_y = [&](std::uint32_t j) { return j + 1 == ny_ ? box.y1 : box.y0 + hy_ * j; };

    raw_.resize(n);
    for (std::uint32_t j = 0; j < ny_; ++j) {
        for (std::uint32_t i = 0; i < nx_; ++i) {
            const double s = field(node_x(i), node_y(j));
            if (!(std::isfinite(s) && s > 0)) {
                throw InputError("size smoothing: the size field is " + number_text(s) + " at (" +
                                 number_text(node_x(i)) + ", " + number_text(node_y(j)) +
                                 "); it must be finite and > 0 in the box");
            }
            raw_[i + std::size_t{nx_} * j] = s;
        }
    }

    // 1. The gradient limit: Dijkstra from the smallest values; a node's value is final when
    // it leaves the queue, and then bounds its neighbours by value + g h.
    limited_ = raw_;
    if (std::isfinite(gradation_)) {
        using Entry = std::pair<double, std::size_t>;
        std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
        for (std::size_t k = 0; k < n; ++k) queue.push({limited_[k], k});
        std::vector<char> done(n, 0);
        while (!queue.empty()) {
            const auto [value, k] = queue.top();
            queue.pop();
            if (done[k] || value != limited_[k]) continue;
            done[k] = 1;
            const std::size_t i = k % nx_, j = k / nx_;
            auto relax = [&](std::size_t m, double h) {
                const double bound = value + gradation_ * h;
                if (!done[m] && bound < limited_[m]) {
                    limited_[m] = bound;
                    queue.push({bound, m});
                }
            };
            if (i > 0) relax(k - 1, hx_);
            if (i + 1 < nx_) relax(k + 1, hx_);
            if (j > 0) relax(k - nx_, hy_);
            if (j + 1 < ny_) relax(k + nx_, hy_);
        }
    }

    // 2. (I + L^2 A) s = s1, A the graph Laplacian of the grid with weights 1/hx^2 and 1/hy^2
    // (zero flux at the sides: a missing neighbour is no term): symmetric positive definite.
    const double wx = length_ * length_ / (hx_ * hx_), wy = length_ * length_ / (hy_ * hy_);
    auto apply = [&](const std::vector<double>& v, std::vector<double>& out) {
        for (std::size_t j = 0; j < ny_; ++j) {
            for (std::size_t i = 0; i < nx_; ++i) {
                const std::size_t k = i + nx_ * j;
                double r = v[k];
                if (i > 0) r += wx * (v[k] - v[k - 1]);
                if (i + 1 < nx_) r += wx * (v[k] - v[k + 1]);
                if (j > 0) r += wy * (v[k] - v[k - nx_]);
                if (j + 1 < ny_) r += wy * (v[k] - v[k + nx_]);
                out[k] = r;
            }
        }
    };
    auto dot = [](const std::vector<double>& a, const std::vector<double>& b) {
        double sum = 0;
        for (std::size_t k = 0; k < a.size(); ++k) sum += a[k] * b[k];
        return sum;
    };
    values_ = limited_;
    std::vector<double> r(n), p(n), q(n);
    apply(values_, q);
    for (std::size_t k = 0; k < n; ++k) r[k] = limited_[k] - q[k];
    p = r;
    const double norm_b = std::sqrt(dot(limited_, limited_));
    double rr = dot(r, r);
    const std::uint64_t budget = 10 * std::uint64_t{n} + 100;
    std::uint64_t iteration = 0;
    while (std::sqrt(rr) > options.residual * norm_b) {
        if (iteration++ >= budget) {
            throw GeometryError(
                "size smoothing: conjugate gradients reached only a relative residual of " +
                number_text(std::sqrt(rr) / norm_b) + " after " + std::to_string(budget) +
                " iterations (asked " + number_text(options.residual) + ")");
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
    for (double& v : values_) v = std::clamp(v, *lo, *hi);
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
