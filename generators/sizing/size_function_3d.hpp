// SPDX-License-Identifier: MIT
// SizeFunction3: a target edge length h(x, y, z) for 3D generators (frontal_delaunay_3d): a
// uniform number, or an analytic function (the command line compiles muParser expressions in
// x, y, z into one, cli/expressions.hpp). The 2D SizeFunction's sources, background meshes and
// quadtrees have no 3D counterpart yet.
#pragma once

#include <cmath>
#include <functional>
#include <string>
#include <utility>

#include "base/errors.hpp"
#include "base/number_text.hpp"

namespace exactmesh::generators {

class SizeFunction3 {
  public:
    /// h everywhere. @throws InputError unless h is finite and > 0.
    static SizeFunction3 uniform(double h) {
        if (!(h > 0) || !std::isfinite(h))
            throw InputError("size: a uniform size must be a finite number > 0, got " +
                             format_number(h));
        SizeFunction3 s;
        s.uniform_ = h;
        s.description_ = "uniform " + format_number(h);
        return s;
    }
    /// f(x, y, z); evaluating it where it is not a finite number > 0 raises InputError.
    static SizeFunction3 analytic(std::function<double(double, double, double)> f,
                                  std::string description) {
        SizeFunction3 s;
        s.function_ = std::move(f);
        s.description_ = std::move(description);
        return s;
    }

    /// The size at (x, y, z). @throws InputError when it is not a finite number > 0.
    double operator()(double x, double y, double z) const {
        if (uniform_ > 0) return uniform_;
        const double h = function_ ? function_(x, y, z) : 0.0;
        if (!(h > 0) || !std::isfinite(h)) {
            throw InputError("size (" + description_ + ") is not a finite number > 0 at (" +
                             format_number(x) + ", " + format_number(y) + ", " + format_number(z) +
                             "): " + format_number(h));
        }
        return h;
    }
    bool is_uniform() const { return uniform_ > 0; }
    bool defined() const { return uniform_ > 0 || static_cast<bool>(function_); }
    const std::string& describe() const { return description_; }

  private:
    double uniform_ = 0;
    std::function<double(double, double, double)> function_;
    std::string description_ = "none";
};

}  // namespace exactmesh::generators
