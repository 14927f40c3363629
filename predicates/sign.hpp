// SPDX-License-Identifier: MIT
// The result type of every predicate: the sign of an exact determinant.
#pragma once

namespace exactmesh::predicates {

enum class Sign : int { Negative = -1, Zero = 0, Positive = 1 };

constexpr Sign operator-(Sign s) {
    return static_cast<Sign>(-static_cast<int>(s));
}

constexpr Sign operator*(Sign a, Sign b) {
    return static_cast<Sign>(static_cast<int>(a) * static_cast<int>(b));
}

/// Sign of a double; NaN maps to Zero (callers never pass NaN here).
constexpr Sign sign_of(double x) {
    return x > 0.0 ? Sign::Positive : (x < 0.0 ? Sign::Negative : Sign::Zero);
}

constexpr int to_int(Sign s) {
    return static_cast<int>(s);
}

}  // namespace exactmesh::predicates
