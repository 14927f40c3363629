// SPDX-License-Identifier: MIT
// Shared plumbing of the text formats: whole-file reads and checked writes, a line tokenizer
// that keeps line numbers and raw text for error messages, and exact, locale-independent
// number parsing and printing (std::from_chars / std::to_chars, shortest round trip).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace exactmesh::io {

/// The whole file as bytes. Throws FormatError naming the file when it cannot be read.
std::string read_text_file(const std::filesystem::path& path);

/// Replaces the file's content with `text`. Throws FormatError naming the file on failure.
void write_text_file(const std::filesystem::path& path, std::string_view text);

/// Walks a text line by line. '#' starts a comment that runs to the end of the line; blank and
/// comment-only lines are skipped; fields are separated by spaces, tabs and '\r' (so CRLF
/// files read like LF files). Every error it raises names the file and the current line.
class TextLines {
  public:
    TextLines(std::string_view text, std::string file_name);

    /// Advances to the next line holding at least one field; false at the end of the text.
    bool next_data_line();

    const std::vector<std::string_view>& fields() const { return fields_; }
    std::uint64_t line_number() const { return line_number_; }
    const std::string& file_name() const { return file_name_; }

    /// Throws FormatError "file:line: problem".
    [[noreturn]] void fail(const std::string& problem) const;
    /// Throws FormatError "file:line: problem: \"the line as written\"".
    [[noreturn]] void fail_quoting_line(const std::string& problem) const;
    /// Throws FormatError located at the last line of the text (for truncated files).
    [[noreturn]] void fail_at_end(const std::string& problem) const;

    /// A non-negative integer no larger than `max`; `what` names it in messages.
    std::uint64_t parse_unsigned(std::string_view token, std::string_view what,
                                 std::uint64_t max) const;
    /// A signed integer in [min, max].
    std::int64_t parse_signed(std::string_view token, std::string_view what, std::int64_t min,
                              std::int64_t max) const;
    /// A finite double, correctly rounded from its decimal text. Rejects text that is not a
    /// whole number, NaN and infinities, overflow, and non-zero values that underflow to zero.
    double parse_finite_double(std::string_view token, std::string_view what) const;

  private:
    std::string_view text_;
    std::string file_name_;
    std::size_t next_offset_ = 0;
    std::uint64_t line_number_ = 0;
    std::string_view raw_line_;
    std::vector<std::string_view> fields_;
};

/// `text` made printable for a message: quotes and control bytes escaped, long text cut.
std::string printable(std::string_view text, std::size_t max_length = 80);

/// Appends the shortest decimal text that reads back as exactly `value`.
void append_double(std::string& out, double value);
/// Appends `value` with a fixed number of decimals (pictures, not data).
void append_fixed(std::string& out, double value, int decimals);
void append_unsigned(std::string& out, std::uint64_t value);
void append_signed(std::string& out, std::int64_t value);

}  // namespace exactmesh::io
