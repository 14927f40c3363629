// SPDX-License-Identifier: MIT
// The exception hierarchy shared by every layer (the bottom layer owns it so all can throw it).
#pragma once

#include <cstdint>
#include <source_location>
#include <stdexcept>
#include <string>

namespace exactmesh {

/// Base of every exactmesh exception; carries where it was raised.
class Error : public std::runtime_error {
public:
    explicit Error(const std::string& what,
                   std::source_location where = std::source_location::current())
        : std::runtime_error(what), where_(where) {}
    const std::source_location& where() const noexcept { return where_; }

private:
    std::source_location where_;
};

/// Bad input: names the file, line and value when they are known.
class InputError : public Error {
public:
    using Error::Error;
};

/// A coordinate is NaN or infinite.
class NonFiniteCoordinate : public InputError {
public:
    NonFiniteCoordinate(const std::string& what, std::uint32_t vertex,
                        std::source_location where = std::source_location::current())
        : InputError(what, where), vertex_(vertex) {}
    std::uint32_t vertex() const noexcept { return vertex_; }

private:
    std::uint32_t vertex_;
};

/// A construction (circumcenter, intersection) that has no finite answer.
class GeometryError : public Error {
public:
    using Error::Error;
};

/// A broken internal invariant: a bug in exactmesh, never the caller's fault.
class InternalError : public Error {
public:
    using Error::Error;
};

}  // namespace exactmesh

/// Always-on O(1) invariant check; throws exactmesh::InternalError naming the condition.
#define EM_ASSERT(cond)                                                           \
    do {                                                                          \
        if (!(cond)) throw ::exactmesh::InternalError("assertion failed: " #cond); \
    } while (false)
