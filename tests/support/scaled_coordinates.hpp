// SPDX-License-Identifier: MIT
// The scale-invariance assertion the adaptation tests share: a mesh built from input scaled by
// 2^k has the reference's coordinates times 2^k, bit for bit. Test support.
#pragma once

#include <cmath>
#include <cstddef>
#include <span>

#include <gtest/gtest.h>

namespace exactmesh::testing {

// Success when `actual` has reference's size and actual[i] == ldexp(reference[i], k) for every
// i; else names the sizes or the first coordinate that differs.
inline ::testing::AssertionResult coordinates_scaled_by(std::span<const double> actual,
                                                        std::span<const double> reference, int k) {
    if (actual.size() != reference.size())
        return ::testing::AssertionFailure() << "2^" << k << ": " << actual.size() << " vs "
                                             << reference.size() << " coordinates";
    for (std::size_t i = 0; i < reference.size(); ++i)
        if (actual[i] != std::ldexp(reference[i], k))
            return ::testing::AssertionFailure()
                   << "2^" << k << " coordinate " << i << ": " << actual[i] << " vs "
                   << std::ldexp(reference[i], k);
    return ::testing::AssertionSuccess();
}

}  // namespace exactmesh::testing
