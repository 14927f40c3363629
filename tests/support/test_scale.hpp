// SPDX-License-Identifier: MIT
// EXACTMESH_TEST_SCALE: a positive float (default 1; anything else reads as 1) by which the
// seeded campaigns and random suites scale their case counts, so that a sanitizer build can run
// fewer (scripts/test passes 0.02). Test support.
#pragma once

#include <cmath>
#include <cstdlib>

namespace exactmesh::testing {

inline double test_scale() {
    const char* text = std::getenv("EXACTMESH_TEST_SCALE");
    if (text == nullptr || *text == '\0') return 1.0;
    char* end = nullptr;
    const double s = std::strtod(text, &end);
    return (end != text && std::isfinite(s) && s > 0.0) ? s : 1.0;
}

}  // namespace exactmesh::testing
