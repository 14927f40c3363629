// SPDX-License-Identifier: MIT
// Reading, tokenizing and number conversion shared by the io/ text formats (see text_file.hpp).
#include "io/text_file.hpp"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <system_error>

#include "io/format_error.hpp"

namespace exactmesh::io {

namespace {

bool is_blank(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

std::string quoted(std::string_view token) {
    // Built by appending: `"'" + std::string&&` trips GCC 12's -Wrestrict false positive.
    std::string out(1, '\'');
    out += printable(token, 40);
    out += '\'';
    return out;
}

/// from_chars accepts neither a leading '+' nor leading blanks; Triangle's files may carry '+'.
std::string_view without_plus(std::string_view token) {
    if (token.size() > 1 && token[0] == '+' && token[1] != '-' && token[1] != '+') {
        return token.substr(1);
    }
    return token;
}

/// For text that from_chars reports out of range: true when its magnitude is huge (overflow),
/// false when tiny (underflow). Reads the decimal exponent of the first non-zero digit.
bool decimal_text_is_huge(std::string_view token) {
    std::size_t i = 0;
    if (i < token.size() && (token[i] == '-' || token[i] == '+')) ++i;
    long long digits_before_point = 0;
    long long leading_fraction_zeros = 0;
    bool seen_point = false, seen_nonzero = false;
    for (; i < token.size() && token[i] != 'e' && token[i] != 'E'; ++i) {
        const char c = token[i];
        if (c == '.') {
            seen_point = true;
        } else if (!seen_nonzero) {
            if (c != '0') {
                seen_nonzero = true;
                if (!seen_point) digits_before_point = 1;
            } else if (seen_point) {
                ++leading_fraction_zeros;
            }
        } else if (!seen_point) {
            ++digits_before_point;
        }
    }
    long long exponent = 0;
    if (i < token.size()) {
        std::string_view text = token.substr(i + 1);
        bool negative = false;
        if (!text.empty() && (text[0] == '-' || text[0] == '+')) {
            negative = text[0] == '-';
            text.remove_prefix(1);
        }
        for (const char c : text) {
            if (c < '0' || c > '9') break;
            exponent = std::min(exponent * 10 + (c - '0'), 1000000000LL);
        }
        if (negative) exponent = -exponent;
    }
    // value = 0.d1d2... * 10^magnitude
    const long long magnitude = digits_before_point > 0 ? digits_before_point + exponent
                                                        : exponent - leading_fraction_zeros;
    return magnitude > 0;
}

}  // namespace

std::string read_text_file(const std::filesystem::path& path, std::size_t max_bytes) {
    TextLines probe(path);  // the same open errors as the streamed readers
    (void)probe;
    std::error_code ec;
    const auto size = std::filesystem::file_size(path, ec);
    if (!ec && size > max_bytes) {
        throw FormatError(path.string(), 0,
                          "is " + std::to_string(size) + " bytes long, more than the " +
                              std::to_string(max_bytes) + " this file may hold");
    }
    errno = 0;
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> in(std::fopen(path.c_str(), "rb"),
                                                       &std::fclose);
    if (!in) {
        throw FormatError(path.string(), 0,
                          std::string("cannot open for reading: ") + std::strerror(errno));
    }
    std::string text;
    char chunk[1 << 16];
    for (;;) {
        const std::size_t got = std::fread(chunk, 1, sizeof chunk, in.get());
        // A device or pipe has no size: stop at the limit as we read it.
        if (text.size() + got > max_bytes) {
            throw FormatError(
                path.string(), 0,
                "is longer than the " + std::to_string(max_bytes) + " bytes this file may hold");
        }
        text.append(chunk, got);
        if (got < sizeof chunk) break;
    }
    if (std::ferror(in.get())) throw FormatError(path.string(), 0, "read error");
    return text;
}

void write_text_file(const std::filesystem::path& path, std::string_view text) {
    OutputSet set;
    set.stage(path, text);
    set.commit();
}

namespace {

std::string system_message(int error) {
    return error != 0 ? std::strerror(error) : "unknown error";
}

/// Writes `text` to an open file and closes it, checking every step (a full disk shows in the
/// write, the flush or the close). Returns 0 or the errno of the first failure.
int write_and_close(std::FILE* file, std::string_view text) {
    errno = 0;
    int error = 0;
    if (!text.empty() && std::fwrite(text.data(), 1, text.size(), file) != text.size())
        error = errno;
    if (error == 0 && std::fflush(file) != 0) error = errno;
    if (std::fclose(file) != 0 && error == 0) error = errno;
    if (error == 0 && errno != 0 && std::ferror(file) != 0) error = errno;
    return error;
}

}  // namespace

OutputSet::~OutputSet() {
    if (committed_) return;
    for (const Staged& file : staged_) {
        std::error_code ignored;
        if (!file.temporary.empty()) std::filesystem::remove(file.temporary, ignored);
    }
}

void OutputSet::stage(const std::filesystem::path& target, std::string_view text) {
    namespace fs = std::filesystem;
    static std::atomic<std::uint64_t> counter{0};
    Staged file;
    file.shown = target.string();
    targets_.push_back(target);
    std::error_code ec;
    // Through a link, write beside the file it names and rename onto that file: renaming onto
    // the link itself would replace the link with a copy.
    file.target = fs::is_symlink(target, ec) ? fs::weakly_canonical(target, ec) : target;
    if (ec) file.target = target;
    const fs::file_status status = fs::status(file.target, ec);
    if (fs::is_directory(status))
        throw FormatError(file.shown, 0, "is a directory, cannot write the output there");
    if (fs::exists(status) && !fs::is_regular_file(status)) {
        // A device or a pipe cannot be replaced by a rename (and /dev/null must stay a device).
        file.direct_text = std::string(text);
        staged_.push_back(std::move(file));
        return;
    }
    const fs::path directory = file.target.parent_path();
    // Built by appending: `"." + std::string&&` trips GCC 12's -Wrestrict false positive.
    std::string name(1, '.');
    name += file.target.filename().string();
    name += ".exactmesh-";
    name += std::to_string(::getpid());
    name += '-';
    name += std::to_string(counter++);
    name += ".tmp";
    file.temporary = directory.empty() ? fs::path(name) : directory / name;
    errno = 0;
    std::FILE* out = std::fopen(file.temporary.c_str(), "wbx");
    if (out == nullptr) {
        const int error = errno;
        throw FormatError(file.shown, 0,
                          "cannot open for writing: " + system_message(error) +
                              " (creating a temporary file in " +
                              (directory.empty() ? std::string(".") : directory.string()) + ")");
    }
    staged_.push_back(file);  // from here the destructor removes the temporary on failure
    if (const int error = write_and_close(out, text); error != 0) {
        throw FormatError(file.shown, 0,
                          "write error: " + system_message(error) + " (the old file is unchanged)");
    }
    if (fs::is_regular_file(status)) {
        // Keep the old file's permissions (a replaced file keeps its mode, as an editor does).
        fs::permissions(file.temporary, status.permissions(), fs::perm_options::replace, ec);
    }
}

void OutputSet::commit() {
    for (const Staged& file : staged_) {
        if (!file.temporary.empty()) continue;
        errno = 0;
        std::FILE* out = std::fopen(file.target.c_str(), "wb");
        if (out == nullptr) {
            const int error = errno;
            throw FormatError(file.shown, 0, "cannot open for writing: " + system_message(error));
        }
        if (const int error = write_and_close(out, file.direct_text); error != 0) {
            throw FormatError(file.shown, 0, "write error: " + system_message(error));
        }
    }
    for (const Staged& file : staged_) {
        if (file.temporary.empty()) continue;
        std::error_code ec;
        std::filesystem::rename(file.temporary, file.target, ec);
        if (ec)
            throw FormatError(file.shown, 0,
                              "cannot move the finished file into place: " + ec.message());
    }
    committed_ = true;
}

TextLines::TextLines(std::string_view text, std::string file_name)
    : text_(text), size_hint_(text.size()), file_name_(std::move(file_name)) {}

TextLines::TextLines(const std::filesystem::path& path) : file_name_(path.string()) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) {
        throw FormatError(file_name_, 0, "is a directory, expected a file");
    }
    errno = 0;
    file_.reset(std::fopen(path.c_str(), "rb"));
    if (!file_) {
        const int error = errno;
        throw FormatError(file_name_, 0, "cannot open for reading: " + system_message(error));
    }
    const auto size = std::filesystem::file_size(path, ec);
    size_hint_ = ec ? 0 : size;
}

bool TextLines::read_chunk() {
    if (at_file_end_) return false;
    constexpr std::size_t kChunk = std::size_t{1} << 16;
    const std::size_t old_size = buffer_.size();
    buffer_.resize(old_size + kChunk);
    const std::size_t got = std::fread(buffer_.data() + old_size, 1, kChunk, file_.get());
    buffer_.resize(old_size + got);
    if (got < kChunk) {
        if (std::ferror(file_.get())) fail("read error after this line");
        at_file_end_ = true;
    }
    return got > 0;
}

bool TextLines::next_raw_line(std::string_view& line) {
    if (!file_) {
        if (next_offset_ >= text_.size()) return false;
        const std::size_t end = std::min(text_.find('\n', next_offset_), text_.size());
        line = text_.substr(next_offset_, end - next_offset_);
        next_offset_ = end + 1;
        return true;
    }
    std::size_t scanned = buffer_offset_;
    for (;;) {
        const std::size_t end = buffer_.find('\n', scanned);
        if (end != std::string::npos) {
            line = std::string_view(buffer_).substr(buffer_offset_, end - buffer_offset_);
            buffer_offset_ = end + 1;
            return true;
        }
        if (buffer_.size() - buffer_offset_ > kMaxLineBytes) {
            line = std::string_view(buffer_).substr(buffer_offset_);  // the caller reports it
            return true;
        }
        buffer_.erase(0, buffer_offset_);
        buffer_offset_ = 0;
        scanned = buffer_.size();
        if (!read_chunk()) {
            if (buffer_.empty()) return false;
            line = buffer_;
            buffer_offset_ = buffer_.size();
            return true;
        }
    }
}

bool TextLines::next_data_line() {
    std::string_view line;
    while (next_raw_line(line)) {
        ++line_number_;
        if (const auto nul = line.find('\0'); nul != std::string_view::npos) {
            fail("a NUL byte at column " + std::to_string(nul + 1) +
                 " (binary data, not a text mesh file)");
        }
        if (line.size() > kMaxLineBytes) {
            fail("line longer than " + std::to_string(kMaxLineBytes) +
                 " bytes (not a text mesh file?)");
        }
        if (line_number_ == 1 && line.substr(0, 3) == "\xEF\xBB\xBF")
            line.remove_prefix(3);  // UTF-8 BOM
        raw_line_ = line;
        const std::size_t comment = line.find('#');
        if (comment != std::string_view::npos) line = line.substr(0, comment);
        fields_.clear();
        std::size_t i = 0;
        while (i < line.size()) {
            while (i < line.size() && is_blank(line[i])) ++i;
            const std::size_t start = i;
            while (i < line.size() && !is_blank(line[i])) ++i;
            if (i > start) fields_.push_back(line.substr(start, i - start));
        }
        if (!fields_.empty()) return true;
    }
    fields_.clear();
    return false;
}

void TextLines::fail(const std::string& problem) const {
    throw FormatError(file_name_, line_number_ == 0 ? 1 : line_number_, problem);
}

void TextLines::fail_quoting_line(const std::string& problem) const {
    std::string_view shown = raw_line_;
    while (!shown.empty() && is_blank(shown.back())) shown.remove_suffix(1);
    while (!shown.empty() && is_blank(shown.front())) shown.remove_prefix(1);
    fail(problem + ": \"" + printable(shown) + "\"");
}

void TextLines::fail_at_end(const std::string& problem) const {
    // At the end, line_number_ counts every line, a final one without its newline included.
    throw FormatError(file_name_, line_number_ == 0 ? 1 : line_number_, problem);
}

std::size_t TextLines::plausible_records(std::uint64_t announced,
                                         std::size_t min_record_bytes) const {
    return static_cast<std::size_t>(std::min<std::uint64_t>(
        {announced, size_hint_ / min_record_bytes, std::uint64_t{kMaxReservedRecords}}));
}

std::uint64_t TextLines::parse_unsigned(std::string_view token, std::string_view what,
                                        std::uint64_t max) const {
    const std::string_view digits = without_plus(token);
    std::uint64_t value = 0;
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (ec == std::errc::result_out_of_range ||
        (ec == std::errc{} && end == digits.data() + digits.size() && value > max)) {
        fail(std::string(what) + " " + quoted(token) + " is too large (at most " +
             std::to_string(max) + ")");
    }
    if (ec != std::errc{} || end != digits.data() + digits.size()) {
        if (!digits.empty() && digits[0] == '-') {
            std::int64_t negative = 0;
            const auto parsed =
                std::from_chars(digits.data(), digits.data() + digits.size(), negative);
            if (parsed.ec == std::errc{} && parsed.ptr == digits.data() + digits.size()) {
                fail(std::string(what) + " " + quoted(token) + " is negative");
            }
        }
        fail(std::string(what) + " " + quoted(token) + " is not a non-negative integer");
    }
    return value;
}

std::int64_t TextLines::parse_signed(std::string_view token, std::string_view what,
                                     std::int64_t min, std::int64_t max) const {
    const std::string_view digits = without_plus(token);
    std::int64_t value = 0;
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    const bool whole = end == digits.data() + digits.size();
    if (ec == std::errc::result_out_of_range ||
        (ec == std::errc{} && whole && (value < min || value > max))) {
        fail(std::string(what) + " " + quoted(token) + " is out of range [" + std::to_string(min) +
             ", " + std::to_string(max) + "]");
    }
    if (ec != std::errc{} || !whole) {
        fail(std::string(what) + " " + quoted(token) + " is not an integer");
    }
    return value;
}

double TextLines::parse_finite_double(std::string_view token, std::string_view what) const {
    const std::string_view text = without_plus(token);
    double value = 0.0;
    const auto [end, ec] =
        std::from_chars(text.data(), text.data() + text.size(), value, std::chars_format::general);
    const bool whole = end == text.data() + text.size();
    if (ec == std::errc::result_out_of_range && whole) {
        if (decimal_text_is_huge(text)) {
            fail(std::string(what) + " " + quoted(token) + " overflows a double");
        }
        fail(std::string(what) + " " + quoted(token) +
             " underflows to zero in a double (write 0 if zero is meant)");
    }
    if (ec != std::errc{} || !whole) {
        fail(std::string(what) + " " + quoted(token) + " is not a number");
    }
    if (!std::isfinite(value)) fail("non-finite " + std::string(what) + " " + quoted(token));
    return value;
}

bool has_extension(const std::filesystem::path& path, std::string_view extension) {
    const std::string actual = path.extension().string();
    return actual.size() == extension.size() &&
           std::equal(actual.begin(), actual.end(), extension.begin(), [](char a, char b) {
               const auto lower = [](char c) {
                   return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c;
               };
               return lower(a) == lower(b);
           });
}

std::string printable(std::string_view text, std::size_t max_length) {
    static constexpr char kHex[] = "0123456789abcdef";
    std::string out;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (out.size() >= max_length) {
            out += "...";
            break;
        }
        const auto c = static_cast<unsigned char>(text[i]);
        if (c == '"' || c == '\\') {
            out += '\\';
            out += static_cast<char>(c);
        } else if (c == '\t') {
            out += "\\t";
        } else if (c == '\r') {
            out += "\\r";
        } else if (c < 0x20 || c >= 0x7f) {
            out += "\\x";
            out += kHex[c >> 4];
            out += kHex[c & 0xF];
        } else {
            out += static_cast<char>(c);
        }
    }
    return out;
}

void append_double(std::string& out, double value) {
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    out.append(buffer, result.ptr);
}

void append_fixed(std::string& out, double value, int decimals) {
    char buffer[400];
    const auto result =
        std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed, decimals);
    out.append(buffer, result.ptr);
}

void append_unsigned(std::string& out, std::uint64_t value) {
    char buffer[24];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    out.append(buffer, result.ptr);
}

void append_signed(std::string& out, std::int64_t value) {
    char buffer[24];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    out.append(buffer, result.ptr);
}

void append_points_3d(std::string& out, std::span<const double> coordinates, unsigned dimension) {
    const std::size_t points = coordinates.size() / dimension;
    for (std::size_t v = 0; v < points; ++v) {
        for (unsigned c = 0; c < dimension; ++c) {
            if (c > 0) out += ' ';
            append_double(out, coordinates[dimension * v + c]);
        }
        out += dimension == 2 ? " 0\n" : "\n";
    }
}

}  // namespace exactmesh::io
