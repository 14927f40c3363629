// SPDX-License-Identifier: MIT
// Python bindings of the exact predicates, vectorized over rows: orient2d, incircle, orient3d,
// insphere and in_ellipse take arrays of points of shape (N, 2) or (N, 3) (or one point,
// shape (2,) or (3,), used for every row) and return the N exact signs as int8 (-1, 0, 1).
// Wiring only: the signs are predicates/' own, filter first, exact last.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "predicates/in_ellipse.hpp"
#include "predicates/incircle.hpp"
#include "predicates/insphere.hpp"
#include "predicates/orient2d.hpp"
#include "predicates/orient3d.hpp"
#include "python/bindings.hpp"
#include "python/numpy_arrays.hpp"

namespace exactmesh::python {

namespace pr = exactmesh::predicates;
using namespace pybind11::literals;

namespace {

/// One argument of a vectorized predicate: `columns` doubles per row, or a single row shared
/// by every row (stride 0).
struct Rows {
    const double* data = nullptr;
    std::size_t stride = 0;  ///< doubles between rows: columns, or 0 for a broadcast point
    std::size_t count = 0;   ///< rows, or 1 for a broadcast point
};

Rows rows(const CoordinateArray& array, std::size_t columns, const std::string& what) {
    const py::ssize_t k = static_cast<py::ssize_t>(columns);
    if (array.ndim() == 1 && array.shape(0) == k) return {array.data(), 0, 1};
    if (array.ndim() == 2 && array.shape(1) == k) {
        return {array.data(), columns, static_cast<std::size_t>(array.shape(0))};
    }
    throw InputError(what + ": expected shape (N, " + std::to_string(columns) + ") or (" +
                     std::to_string(columns) + ",)");
}

/// The rows' common count (broadcast points excluded), every coordinate checked finite: the
/// predicates' exact stages are defined on finite doubles only.
std::size_t common_count(const std::vector<std::pair<Rows, std::string>>& arguments,
                         std::size_t columns) {
    std::size_t n = 1;
    bool any_rows = false;
    for (const auto& [r, what] : arguments) {
        if (r.stride == 0) continue;
        if (any_rows && r.count != n) {
            throw InputError(what + ": " + std::to_string(r.count) + " rows, the others " +
                             std::to_string(n));
        }
        n = r.count;
        any_rows = true;
    }
    for (const auto& [r, what] : arguments) {
        const std::size_t values = r.stride == 0 ? columns : r.count * columns;
        for (std::size_t i = 0; i < values; ++i) {
            if (!std::isfinite(r.data[i])) {
                throw InputError(what + "[" + std::to_string(i / columns) +
                                 "]: coordinate is not finite");
            }
        }
    }
    return any_rows ? n : 1;
}

template <std::size_t Arity, class Predicate>
py::array_t<std::int8_t> vectorized(const std::array<const CoordinateArray*, Arity>& arrays,
                                    std::size_t columns, Predicate predicate) {
    static constexpr const char* kNames[] = {"a", "b", "c", "d", "e", "metric"};
    std::vector<std::pair<Rows, std::string>> arguments;
    for (std::size_t i = 0; i < Arity; ++i) {
        arguments.emplace_back(rows(*arrays[i], columns, kNames[i]), kNames[i]);
    }
    const std::size_t n = common_count(arguments, columns);
    std::vector<std::int8_t> signs(n);
    {
        py::gil_scoped_release release;
        std::array<const double*, Arity> p{};
        for (std::size_t row = 0; row < n; ++row) {
            for (std::size_t i = 0; i < Arity; ++i)
                p[i] = arguments[i].first.data + row * arguments[i].first.stride;
            signs[row] = static_cast<std::int8_t>(pr::to_int(predicate(p)));
        }
    }
    auto* owner = new std::vector<std::int8_t>(std::move(signs));
    py::capsule free_owner(owner,
                           [](void* q) { delete static_cast<std::vector<std::int8_t>*>(q); });
    return py::array_t<std::int8_t>({static_cast<py::ssize_t>(owner->size())}, owner->data(),
                                    free_owner);
}

}  // namespace

void bind_predicates(py::module_& m) {
    m.def(
        "orient2d",
        [](const CoordinateArray& a, const CoordinateArray& b, const CoordinateArray& c) {
            return vectorized<3>({&a, &b, &c}, 2,
                                 [](const auto& p) { return pr::orient2d(p[0], p[1], p[2]); });
        },
        "a"_a, "b"_a, "c"_a,
        "Exact sign of the orientation of (a, b, c): 1 counter-clockwise, -1 clockwise, 0 "
        "collinear. Arrays of shape (N, 2) (or (2,), one point for every row); int8 (N,).");
    m.def(
        "incircle",
        [](const CoordinateArray& a, const CoordinateArray& b, const CoordinateArray& c,
           const CoordinateArray& d) {
            return vectorized<4>({&a, &b, &c, &d}, 2, [](const auto& p) {
                return pr::incircle(p[0], p[1], p[2], p[3]);
            });
        },
        "a"_a, "b"_a, "c"_a, "d"_a,
        "Exact sign of incircle: 1 when d lies inside the circle through a, b, c (given "
        "counter-clockwise), -1 outside, 0 on it.");
    m.def(
        "orient3d",
        [](const CoordinateArray& a, const CoordinateArray& b, const CoordinateArray& c,
           const CoordinateArray& d) {
            return vectorized<4>({&a, &b, &c, &d}, 3, [](const auto& p) {
                return pr::orient3d(p[0], p[1], p[2], p[3]);
            });
        },
        "a"_a, "b"_a, "c"_a, "d"_a,
        "Exact sign of orient3d (Shewchuk's convention: 1 when d lies below the plane of a, b, c "
        "seen counter-clockwise from above), 0 coplanar. Arrays of shape (N, 3) or (3,).");
    m.def(
        "insphere",
        [](const CoordinateArray& a, const CoordinateArray& b, const CoordinateArray& c,
           const CoordinateArray& d, const CoordinateArray& e) {
            return vectorized<5>({&a, &b, &c, &d, &e}, 3, [](const auto& p) {
                return pr::insphere(p[0], p[1], p[2], p[3], p[4]);
            });
        },
        "a"_a, "b"_a, "c"_a, "d"_a, "e"_a,
        "Exact sign of insphere: 1 when e lies inside the sphere through a, b, c, d (with "
        "orient3d(a, b, c, d) > 0), -1 outside, 0 on it.");
    m.def(
        "in_ellipse",
        [](const CoordinateArray& a, const CoordinateArray& b, const CoordinateArray& c,
           const CoordinateArray& d, const CoordinateArray& metric) {
            const Rows mr = rows(metric, 3, "metric");
            if (mr.stride != 0) throw InputError("metric: expected one metric, shape (3,)");
            for (std::size_t i = 0; i < 3; ++i) {
                if (!std::isfinite(mr.data[i])) throw InputError("metric: entry is not finite");
            }
            return vectorized<4>({&a, &b, &c, &d}, 2, [mr](const auto& p) {
                return pr::in_ellipse(p[0], p[1], p[2], p[3], mr.data);
            });
        },
        "a"_a, "b"_a, "c"_a, "d"_a, "metric"_a,
        "Exact sign of incircle in the plane mapped by the symmetric metric M = [[m11, m12], "
        "[m12, m22]] given as metric = (m11, m12, m22): 1 when d lies inside the ellipse through "
        "a, b, c. One metric (shape (3,)) for every row.");
}

}  // namespace exactmesh::python
