// SPDX-License-Identifier: MIT
// Shared plumbing of the text formats: streamed line reading (bounded lines, so /dev/zero or a
// sparse 3 GB file fails on its first line instead of filling memory), all-or-nothing writes
// (a temporary file beside each target, renamed into place once the whole set is written), a
// line tokenizer that keeps line numbers and raw text for error messages, and exact,
// locale-independent number parsing and printing (std::from_chars / std::to_chars, shortest
// round trip).
#pragma once

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace exactmesh::io {

/// The longest line the readers accept: a .node line with thousands of attributes fits, and a
/// file without line breaks (/dev/zero, a binary file) fails after reading this much.
inline constexpr std::size_t kMaxLineBytes = std::size_t{1} << 20;

/// The most records a header's count may make a reader reserve room for before they are read:
/// a header that promises 2^31 records allocates nothing until the records actually come.
inline constexpr std::size_t kMaxReservedRecords = std::size_t{1} << 16;

/// The whole file as bytes (at most `max_bytes`: longer files fail without being read whole).
/// Throws FormatError naming the file when it cannot be read or is too long.
std::string read_text_file(const std::filesystem::path& path,
                           std::size_t max_bytes = std::size_t{1} << 30);

/// Replaces the file's content with `text`, all or nothing: see OutputSet (a set of one).
/// Throws FormatError naming the file on failure; the old file is then left untouched.
void write_text_file(const std::filesystem::path& path, std::string_view text);

/// Writes a set of files all or nothing. stage() writes each text to a new temporary file in
/// the target's directory (following links to the real target), checking every write and the
/// close; commit() renames them all into place only when every one was staged. A failure (a
/// companion that cannot be created, a full disk) throws FormatError naming the file and leaves
/// every previous output byte-identical; the destructor removes the temporaries of a set never
/// committed. Targets that exist and are not regular files (/dev/null, /dev/full, a pipe) are
/// written directly, after every regular file of the set has been staged.
class OutputSet {
  public:
    OutputSet() = default;
    OutputSet(const OutputSet&) = delete;
    OutputSet& operator=(const OutputSet&) = delete;
    ~OutputSet();

    void stage(const std::filesystem::path& target, std::string_view text);
    /// Renames every staged file into place. Throws FormatError when a rename fails.
    void commit();
    /// The targets staged so far, in order (as given).
    const std::vector<std::filesystem::path>& targets() const { return targets_; }

  private:
    struct Staged {
        std::filesystem::path target;     ///< where the file goes (links followed)
        std::filesystem::path temporary;  ///< empty for a direct (non-regular) target
        std::string direct_text;          ///< the text of a direct target, written at commit
        std::string shown;                ///< the target's name as given, for messages
    };
    std::vector<Staged> staged_;
    std::vector<std::filesystem::path> targets_;
    bool committed_ = false;
};

/// Walks a text line by line. '#' starts a comment that runs to the end of the line; blank and
/// comment-only lines are skipped; fields are separated by spaces, tabs and '\r' (so CRLF
/// files read like LF files); a UTF-8 byte order mark at the start is skipped. A NUL byte or a
/// line longer than kMaxLineBytes is an error at once. Every error it raises names the file and
/// the current line.
class TextLines {
  public:
    /// Lines of a text in memory; `file_name` is used in messages.
    TextLines(std::string_view text, std::string file_name);
    /// Lines streamed from a file: never more than one line (and a read buffer) in memory.
    /// @throws FormatError naming the file when it cannot be opened or is a directory.
    explicit TextLines(const std::filesystem::path& path);

    /// Advances to the next line holding at least one field; false at the end of the text.
    bool next_data_line();

    const std::vector<std::string_view>& fields() const { return fields_; }
    std::uint64_t line_number() const { return line_number_; }
    const std::string& file_name() const { return file_name_; }

    /// Throws FormatError "file:line: problem".
    [[noreturn]] void fail(const std::string& problem) const;
    /// Throws FormatError "file:line: problem: \"the line as written\"".
    [[noreturn]] void fail_quoting_line(const std::string& problem) const;
    /// Throws FormatError located at the last line of the text (for truncated files); call
    /// after next_data_line() returned false.
    [[noreturn]] void fail_at_end(const std::string& problem) const;

    /// What a reader may reserve for `announced` records of at least `min_record_bytes` each:
    /// never more than the rest of the input could hold, nor kMaxReservedRecords.
    std::size_t plausible_records(std::uint64_t announced, std::size_t min_record_bytes) const;

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
    struct CloseFile {
        void operator()(std::FILE* file) const { std::fclose(file); }
    };
    /// The next raw line (without its '\n'); false at the end of the input.
    bool next_raw_line(std::string_view& line);
    /// Streamed input: appends up to one chunk to buffer_; false at the end of the file.
    bool read_chunk();

    std::string_view text_;  ///< the text in memory, or the unread part of buffer_ when streaming
    std::unique_ptr<std::FILE, CloseFile> file_;
    std::string buffer_;
    std::size_t buffer_offset_ = 0;
    std::uint64_t size_hint_ = 0;  ///< bytes of the whole input (0 when unknown)
    bool at_file_end_ = false;
    std::string file_name_;
    std::size_t next_offset_ = 0;
    std::uint64_t line_number_ = 0;
    std::string_view raw_line_;
    std::vector<std::string_view> fields_;
};

/// Whether `path` ends in `extension` (".node"), in any letter case: .NODE and .Poly are read
/// like .node and .poly, as the outputs' extensions already were.
bool has_extension(const std::filesystem::path& path, std::string_view extension);

/// `text` made printable for a message: quotes and control bytes escaped, long text cut.
std::string printable(std::string_view text, std::size_t max_length = 80);

/// Appends the shortest decimal text that reads back as exactly `value`.
void append_double(std::string& out, double value);
/// Appends `value` with a fixed number of decimals (pictures, not data).
void append_fixed(std::string& out, double value, int decimals);
void append_unsigned(std::string& out, std::uint64_t value);
void append_signed(std::string& out, std::int64_t value);
/// Appends a line "x y z" per point of `coordinates` (`dimension` values per point, 2 or 3;
/// z = 0 appended in 2D), as the 3D point lists of Gmsh and VTK want them.
void append_points_3d(std::string& out, std::span<const double> coordinates, unsigned dimension);

}  // namespace exactmesh::io
