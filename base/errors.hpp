// SPDX-License-Identifier: MIT
// The exception hierarchy shared by every layer (base/: every layer may include it).
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

namespace exactmesh {

/// Where an exception was raised: std::source_location's interface from the compilers'
/// builtins, on every compiler. (std::source_location where the library had it, GCC 12, and this
/// struct where not, clang 14 with libstdc++ 12, gave exactmesh::Error two layouts: a library
/// built by one compiler and a caller built by the other disagreed on the exception object.)
struct SourceLocation {
    const char* file = "";
    const char* function = "";
    unsigned line_number = 0;
    static constexpr SourceLocation current(const char* f = __builtin_FILE(),
                                            const char* fn = __builtin_FUNCTION(),
                                            unsigned l = __builtin_LINE()) noexcept {
        SourceLocation s;
        s.file = f;
        s.function = fn;
        s.line_number = l;
        return s;
    }
    constexpr const char* file_name() const noexcept { return file; }
    constexpr const char* function_name() const noexcept { return function; }
    constexpr unsigned line() const noexcept { return line_number; }
};

/// Base of every exactmesh exception; carries where it was raised.
class Error : public std::runtime_error {
  public:
    explicit Error(const std::string& what, SourceLocation where = SourceLocation::current())
        : std::runtime_error(what), where_(where) {}
    const SourceLocation& where() const noexcept { return where_; }

  private:
    SourceLocation where_;
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
                        SourceLocation where = SourceLocation::current())
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
#define EM_ASSERT(cond)                                                            \
    do {                                                                           \
        if (!(cond)) throw ::exactmesh::InternalError("assertion failed: " #cond); \
    } while (false)
