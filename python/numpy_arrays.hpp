// SPDX-License-Identifier: MIT
// Between numpy arrays and the flat arrays of the C++ layers, copying only where the layout
// demands it: float64 C-contiguous inputs are read in place (pybind11's forcecast converts
// anything else once), and results hand their std::vector to numpy, owned by a capsule.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "base/errors.hpp"

namespace exactmesh::python {

namespace py = pybind11;

/// A float64 array of shape (N, columns), read in place when it is one already.
using CoordinateArray = py::array_t<double, py::array::c_style | py::array::forcecast>;
/// An integer array of shape (N, columns): indices, checked and narrowed to 32 bits.
using IndexArray = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>;

/// The coordinates of `array` as a flat span (x0 y0 [z0] x1 ...).
/// @throws InputError (ValueError in Python) naming `what` when its shape is not (N, columns).
inline std::span<const double> coordinates(const CoordinateArray& array, py::ssize_t columns,
                                           const std::string& what) {
    if (array.ndim() != 2 || array.shape(1) != columns) {
        std::string shape = "(";
        for (py::ssize_t i = 0; i < array.ndim(); ++i)
            shape += (i ? ", " : "") + std::to_string(array.shape(i));
        throw InputError(what + ": expected an array of shape (N, " + std::to_string(columns) +
                         "), got shape " + shape + (array.ndim() == 1 ? ",)" : ")"));
    }
    return {array.data(), static_cast<std::size_t>(array.size())};
}

/// The indices of `array` (shape (N, columns), or empty/None for none) as 32-bit vertex
/// indices, each checked to lie in [0, limit).
/// @throws InputError naming `what`, the row and the value.
inline std::vector<std::uint32_t> indices(const IndexArray& array, py::ssize_t columns,
                                          std::uint64_t limit, const std::string& what) {
    if (array.size() == 0) return {};
    if (array.ndim() != 2 || array.shape(1) != columns) {
        throw InputError(what + ": expected an integer array of shape (N, " +
                         std::to_string(columns) + ")");
    }
    std::vector<std::uint32_t> out(static_cast<std::size_t>(array.size()));
    const std::int64_t* data = array.data();
    for (std::size_t i = 0; i < out.size(); ++i) {
        if (data[i] < 0 || static_cast<std::uint64_t>(data[i]) >= limit) {
            throw InputError(what + "[" + std::to_string(i / columns) + "]: index " +
                             std::to_string(data[i]) + " outside [0, " + std::to_string(limit) +
                             ")");
        }
        out[i] = static_cast<std::uint32_t>(data[i]);
    }
    return out;
}

/// `values` as a numpy array of shape (size / columns, columns) that owns the vector's storage
/// (no copy). Needs the GIL.
template <class T>
py::array_t<T> to_numpy(std::vector<T>&& values, py::ssize_t columns) {
    auto* owner = new std::vector<T>(std::move(values));
    py::capsule free_owner(owner, [](void* p) { delete static_cast<std::vector<T>*>(p); });
    const py::ssize_t rows = static_cast<py::ssize_t>(owner->size()) / columns;
    return py::array_t<T>({rows, columns}, owner->data(), free_owner);
}

/// 32-bit vertex or cell indices as int32 numpy arrays, without a copy: the layers' "none"
/// (0xFFFFFFFF, a hull side) reads as -1, scipy.spatial.Delaunay's convention. Every index is
/// below 2^30 (kMaxPoints, kMaxTetSlots), so no valid one turns negative.
inline py::array_t<std::int32_t> indices_to_numpy(std::vector<std::uint32_t>&& values,
                                                  py::ssize_t columns) {
    static_assert(sizeof(std::int32_t) == sizeof(std::uint32_t));
    auto* owner = new std::vector<std::uint32_t>(std::move(values));
    py::capsule free_owner(owner,
                           [](void* p) { delete static_cast<std::vector<std::uint32_t>*>(p); });
    const py::ssize_t rows = static_cast<py::ssize_t>(owner->size()) / columns;
    return py::array_t<std::int32_t>(
        {rows, columns}, reinterpret_cast<const std::int32_t*>(owner->data()), free_owner);
}

/// Counter tables (name, value) as a dict.
template <class Table, class Counters>
py::dict counters_dict(const Table& names, const Counters& counters) {
    py::dict d;
    for (const auto& entry : names) d[py::str(std::string(entry.name))] = entry.read(counters);
    return d;
}

}  // namespace exactmesh::python
