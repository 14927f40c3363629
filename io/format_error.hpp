// SPDX-License-Identifier: MIT
// FormatError: bad input found while reading a file, located by file name and line number so
// that the message alone is enough to find and fix the offending text.
#pragma once

#include <cstdint>
#include <string>
#include <utility>

#include "base/errors.hpp"

namespace exactmesh::io {

/// A malformed or unreadable file. what() reads "file:line: problem" (or "file: problem" when
/// the problem is not tied to one line, e.g. a file that cannot be opened).
class FormatError : public InputError {
  public:
    FormatError(std::string file, std::uint64_t line, std::string problem,
                SourceLocation where = SourceLocation::current())
        : InputError(compose(file, line, problem), where),
          file_(std::move(file)),
          line_(line),
          problem_(std::move(problem)) {}

    const std::string& file() const noexcept { return file_; }
    /// 1-based line number; 0 when the problem concerns the whole file.
    std::uint64_t line() const noexcept { return line_; }
    const std::string& problem() const noexcept { return problem_; }

  private:
    static std::string compose(const std::string& file, std::uint64_t line,
                               const std::string& problem) {
        if (line == 0) return file + ": " + problem;
        return file + ":" + std::to_string(line) + ": " + problem;
    }

    std::string file_;
    std::uint64_t line_;
    std::string problem_;
};

}  // namespace exactmesh::io
