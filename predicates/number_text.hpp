// SPDX-License-Identifier: MIT
// format_number: the one formatter of doubles in messages, for every layer. The shortest text
// that reads back as exactly the value (std::to_chars), so 1e-300 prints as "1e-300" and
// never as 300 digits of fixed point (std::to_string's %f), and NaN as "NaN" (never "-nan").
#pragma once

#include <charconv>
#include <cmath>
#include <string>

namespace exactmesh {

/// `value` for a message: shortest round trip; "NaN", "infinity" or "-infinity" when not finite.
inline std::string format_number(double value) {
    if (std::isnan(value)) return "NaN";
    if (std::isinf(value)) return value > 0 ? "infinity" : "-infinity";
    char text[32];
    const auto result = std::to_chars(text, text + sizeof text, value);
    return std::string(text, result.ptr);
}

}  // namespace exactmesh
