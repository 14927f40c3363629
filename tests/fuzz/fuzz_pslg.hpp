// SPDX-License-Identifier: MIT
// Shared decoding of fuzz bytes into a PSLG (points and segments) for the 2D triangulation and
// mesh-generator fuzz targets, and their failure report. Test support.
//
// Input layout (`header` bytes, then segments, then coordinates):
//   byte 0               the mode (byte % 3): 0 raw doubles, bit for bit (any pattern: NaN, inf,
//                        subnormal); 1 lattice integers -4..4 (bits % 9 - 4), exactly collinear
//                        and cocircular everywhere; 2 a lattice 16..24 (bits % 9 + 16) moved by
//                        -2..2 ulps ((bits >> 8) % 5 - 2)
//   bytes 1..header-2    the target's own parameters (read by the target)
//   byte header-1        the segment count (byte % 32)
//   2 bytes per segment  endpoint indices, each taken modulo the point count
//   8 bytes per value    the coordinates, x then y (at most 2 * max_points values, an odd last
//                        one dropped; trailing bytes short of 8 ignored)
// Too short for the header or the segment bytes: no input.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <optional>
#include <vector>

#include "triangulation/mesh/mesh2.hpp"

namespace exactmesh::fuzz {

struct FuzzPslg {
    std::vector<double> xy;                        ///< 2·#V coordinates
    std::vector<triangulation::VertIdx> segments;  ///< 2·#S indices (empty without points)
};

/// The PSLG of `data` by the layout above, whose first `header` bytes (at least 2) hold the mode,
/// the target's parameters and the segment count; nullopt when too short.
inline std::optional<FuzzPslg> decode_pslg(const std::uint8_t* data, std::size_t size,
                                           std::size_t header, std::size_t max_points) {
    if (size < header) return std::nullopt;
    const std::uint8_t mode = data[0] % 3;
    const std::size_t segment_count = data[header - 1] % 32;
    std::size_t at = header;
    if (size < at + 2 * segment_count) return std::nullopt;
    const std::vector<std::uint8_t> ends(data + at, data + at + 2 * segment_count);
    at += 2 * segment_count;
    FuzzPslg out;
    const std::size_t doubles = std::min((size - at) / 8, 2 * max_points) & ~std::size_t{1};
    out.xy.resize(doubles);
    if (doubles > 0) std::memcpy(out.xy.data(), data + at, doubles * sizeof(double));
    for (double& v : out.xy) {
        std::uint64_t bits;
        std::memcpy(&bits, &v, sizeof bits);
        if (mode == 1) v = static_cast<double>(static_cast<int>(bits % 9) - 4);
        if (mode == 2) {
            v = static_cast<double>(bits % 9) + 16;
            for (int k = static_cast<int>((bits >> 8) % 5) - 2; k != 0; k += k > 0 ? -1 : 1) {
                v = std::nextafter(v, k > 0 ? INFINITY : -INFINITY);
            }
        }
    }
    const std::size_t n = out.xy.size() / 2;
    if (n > 0) {
        for (const std::uint8_t e : ends)
            out.segments.push_back(static_cast<triangulation::VertIdx>(e % n));
    }
    return out;
}

/// Prints the heading (printf `format`, ending where "points" begins), the points in hex
/// floating point and the segments to stderr, then traps.
[[noreturn]] inline void __attribute__((format(printf, 3, 4)))
fail_pslg(const std::vector<double>& xy, const std::vector<triangulation::VertIdx>& segments,
          const char* format, ...) {
    std::va_list args;
    va_start(args, format);
    std::vfprintf(stderr, format, args);
    va_end(args);
    std::fprintf(stderr, "points (%zu):", xy.size() / 2);
    for (std::size_t i = 0; i + 1 < xy.size(); i += 2)
        std::fprintf(stderr, " (%a, %a)", xy[i], xy[i + 1]);
    std::fprintf(stderr, "\nsegments:");
    for (std::size_t s = 0; s + 1 < segments.size(); s += 2)
        std::fprintf(stderr, " %u-%u", segments[s], segments[s + 1]);
    std::fprintf(stderr, "\n");
    __builtin_trap();
}

}  // namespace exactmesh::fuzz
