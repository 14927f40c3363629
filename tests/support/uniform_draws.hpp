// SPDX-License-Identifier: MIT
// Uniform draws from a seeded std::mt19937_64, shared by the randomized predicate tests so that
// each names its distributions, not the standard library's. Test support.
#pragma once

#include <random>

namespace exactmesh::testing {

/// A double uniform in [lo, hi).
inline double uniform(std::mt19937_64& rng, double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(rng);
}

/// An int uniform in [lo, hi].
inline int uniform_int(std::mt19937_64& rng, int lo, int hi) {
    return std::uniform_int_distribution<int>(lo, hi)(rng);
}

}  // namespace exactmesh::testing
