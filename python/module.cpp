// SPDX-License-Identifier: MIT
// The extension module exactmesh._exactmesh (pybind11): the exceptions, then each layer's
// bindings. The Python package exactmesh (python/exactmesh/__init__.py) is the public face.
#include <pybind11/pybind11.h>

#include "base/errors.hpp"
#include "base/version.hpp"
#include "python/bindings.hpp"

PYBIND11_MODULE(_exactmesh, m) {
    namespace py = pybind11;
    m.doc() =
        "exactmesh: exact predicates, Delaunay and constrained triangulations, mesh "
        "generators (the C++ core; use the package `exactmesh`)";
    m.attr("__version__") = exactmesh::kVersion;
    // Bad input and impossible constructions are ValueErrors, with the command's message;
    // InternalError (a bug in exactmesh) a RuntimeError. Translators are tried newest first,
    // so the base class goes first.
    static py::exception<exactmesh::Error> error(m, "Error", PyExc_RuntimeError);
    static py::exception<exactmesh::InternalError> internal(m, "InternalError", error.ptr());
    static py::exception<exactmesh::InputError> input(m, "InputError", PyExc_ValueError);
    static py::exception<exactmesh::GeometryError> geometry(m, "GeometryError", PyExc_ValueError);
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const exactmesh::InputError& e) {
            input(e.what());
        } catch (const exactmesh::GeometryError& e) {
            geometry(e.what());
        } catch (const exactmesh::InternalError& e) {
            internal(e.what());
        } catch (const exactmesh::Error& e) {
            error(e.what());
        }
    });
    exactmesh::python::bind_predicates(m);
    exactmesh::python::bind_triangulation(m);
    exactmesh::python::bind_generators(m);
    exactmesh::python::bind_fuzzing(m);
}
