// SPDX-License-Identifier: MIT
// Reading, tokenizing and number conversion shared by the io/ text formats (see text_file.hpp).
#include "io/text_file.hpp"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
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

std::string read_text_file(const std::filesystem::path& path) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) {
        throw FormatError(path.string(), 0, "is a directory, expected a file");
    }
    errno = 0;
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        const int error = errno;
        throw FormatError(path.string(), 0,
                          std::string("cannot open for reading: ") +
                              (error != 0 ? std::strerror(error) : "unknown error"));
    }
    std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    if (in.bad()) throw FormatError(path.string(), 0, "read error");
    return text;
}

void write_text_file(const std::filesystem::path& path, std::string_view text) {
    errno = 0;
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    if (!out) {
        const int error = errno;
        throw FormatError(path.string(), 0,
                          std::string("cannot open for writing: ") +
                              (error != 0 ? std::strerror(error) : "unknown error"));
    }
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
    out.close();
    if (!out) throw FormatError(path.string(), 0, "write error (disk full?)");
}

TextLines::TextLines(std::string_view text, std::string file_name)
    : text_(text), file_name_(std::move(file_name)) {}

bool TextLines::next_data_line() {
    while (next_offset_ < text_.size()) {
        const std::size_t end = std::min(text_.find('\n', next_offset_), text_.size());
        std::string_view line = text_.substr(next_offset_, end - next_offset_);
        next_offset_ = end + 1;
        ++line_number_;
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
    // The last line of the text, counting a final line without its newline.
    std::uint64_t lines = 0;
    for (const char c : text_) lines += c == '\n' ? 1 : 0;
    if (!text_.empty() && text_.back() != '\n') ++lines;
    throw FormatError(file_name_, lines == 0 ? 1 : lines, problem);
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

}  // namespace exactmesh::io
