// SPDX-License-Identifier: MIT
// The formatters of doubles in messages, for every layer: format_number and format_point give
// the shortest text that reads back as exactly the value (std::to_chars), so 1e-300 prints as
// "1e-300" and never as 300 digits of fixed point (std::to_string's %f), and NaN as "NaN"
// (never "-nan"); format_approximate gives an estimate to a few significant digits; format_fixed
// a report's column, median_of a report's median.
#pragma once

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <string>
#include <vector>

namespace exactmesh {

/// `value` for a message: shortest round trip; "NaN", "infinity" or "-infinity" when not finite.
inline std::string format_number(double value) {
    if (std::isnan(value)) return "NaN";
    if (std::isinf(value)) return value > 0 ? "infinity" : "-infinity";
    char text[32];
    const auto result = std::to_chars(text, text + sizeof text, value);
    return std::string(text, result.ptr);
}

/// An estimate for a message, to `digits` significant digits ("about 5e+11 triangles"): where
/// the value is itself approximate, its last digits would claim a precision it does not have.
inline std::string format_approximate(double value, int digits = 6) {
    if (!std::isfinite(value)) return format_number(value);
    char text[40];
    std::snprintf(text, sizeof text, "%.*g", digits, value);
    return text;
}

/// `digits` digits after the point ("%.6f"), for reports whose columns line up (quality reports).
inline std::string format_fixed(double value, int digits = 6) {
    char text[64];
    std::snprintf(text, sizeof text, "%.*f", digits, value);
    return text;
}

/// The median of values (the upper one of an even count; 0 when empty); reorders values.
inline double median_of(std::vector<double>& values) {
    if (values.empty()) return 0;
    const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
    std::nth_element(values.begin(), middle, values.end());
    return *middle;
}

/// "(x, y)" or "(x, y, z)": the first `dimension` coordinates of p, each as format_number.
inline std::string format_point(const double* p, int dimension = 2) {
    std::string text = "(";
    for (int k = 0; k < dimension; ++k) text += (k == 0 ? "" : ", ") + format_number(p[k]);
    return text + ")";
}

}  // namespace exactmesh
