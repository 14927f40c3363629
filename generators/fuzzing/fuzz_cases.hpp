// SPDX-License-Identifier: MIT
// What every fuzzing driver shares (both modes of `exactmesh fuzz`, exactmesh.fuzz in Python):
// the case random numbers, the case sizes, the delta-debugging minimizer [Zeller, Hildebrandt
// 2002, ddmin] over any list of removable units (points, or vertices and segments) and the
// progress line.
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <iomanip>
#include <numeric>
#include <span>
#include <sstream>
#include <string>
#include <vector>

namespace exactmesh::generators {

using FuzzClock = std::chrono::steady_clock;

/// splitmix64 [Steele, Lea, Flood 2014]: one 64-bit state, good enough to pick case shapes.
class CaseRandom {
  public:
    explicit CaseRandom(std::uint64_t seed) : state_(seed) {}
    std::uint64_t next() {
        std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    /// Uniform in [lo, hi].
    std::uint32_t between(std::uint32_t lo, std::uint32_t hi) {
        return lo + static_cast<std::uint32_t>(next() % (std::uint64_t{hi} - lo + 1));
    }
    double unit() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

  private:
    std::uint64_t state_;
};

/// A case size: mostly small (skewed towards the smallest, where degeneracies are dense and the
/// naive oracle runs), then medium (up to 300), one case in 20 large (log-uniform up to
/// `largest`, at least 300).
inline std::uint32_t case_size(CaseRandom& random, std::uint32_t small_max, std::uint32_t largest) {
    const std::uint64_t size_class = random.next() % 20;
    if (size_class < 9) {
        const double u = random.unit();
        return 3 + static_cast<std::uint32_t>(static_cast<double>(small_max - 2) * u * u);
    }
    if (size_class < 18) return random.between(small_max + 1, 300);
    largest = std::max<std::uint32_t>(largest, 300);
    return static_cast<std::uint32_t>(
        std::lround(300.0 * std::pow(static_cast<double>(largest) / 300.0, random.unit())));
}

struct DdminResult {
    std::vector<std::size_t> kept;  ///< the units left, increasing
    std::size_t evaluations = 0;
    bool complete = true;  ///< false when the time budget ran out first
};

/// ddmin over `units` removable units: removes chunks of n/2, n/4, ..., 1 units while
/// `still_fails(kept units)` holds; ends 1-minimal (no single unit can go) unless `give_up` comes
/// first. `still_fails` is the oracle: the same failure as the one being minimized.
inline DdminResult ddmin(std::size_t units,
                         const std::function<bool(std::span<const std::size_t>)>& still_fails,
                         FuzzClock::time_point give_up) {
    DdminResult out;
    std::vector<std::size_t> kept(units);
    std::iota(kept.begin(), kept.end(), std::size_t{0});
    std::size_t chunk = std::max<std::size_t>(units / 2, 1);
    for (;;) {
        bool removed = false;
        for (std::size_t start = 0; start < kept.size() && kept.size() > 1;) {
            if (FuzzClock::now() > give_up) {
                out.complete = false;
                out.kept = std::move(kept);
                return out;
            }
            const std::size_t stop = std::min(kept.size(), start + chunk);
            std::vector<std::size_t> candidate;
            candidate.reserve(kept.size() - (stop - start));
            candidate.insert(candidate.end(), kept.begin(),
                             kept.begin() + static_cast<std::ptrdiff_t>(start));
            candidate.insert(candidate.end(), kept.begin() + static_cast<std::ptrdiff_t>(stop),
                             kept.end());
            ++out.evaluations;
            if (still_fails(candidate)) {
                kept = std::move(candidate);
                removed = true;
            } else {
                start = stop;
            }
        }
        if (!removed) {
            if (chunk == 1) break;
            chunk /= 2;
        } else {
            chunk = std::max<std::size_t>(std::min(chunk, kept.size() / 2), 1);
        }
    }
    out.kept = std::move(kept);
    return out;
}

/// The coordinates of the kept units, `dimension` doubles each.
inline std::vector<double> kept_coordinates(std::span<const double> coordinates,
                                            std::span<const std::size_t> kept,
                                            std::size_t dimension) {
    std::vector<double> out;
    out.reserve(kept.size() * dimension);
    for (const std::size_t unit : kept) {
        for (std::size_t d = 0; d < dimension; ++d)
            out.push_back(coordinates[dimension * unit + d]);
    }
    return out;
}

inline std::string format_seconds(double seconds) {
    std::ostringstream text;
    text << std::fixed << std::setprecision(1) << seconds << " s";
    return text.str();
}

/// A progress line at most every `interval` (issue 16, "Long runs"): a long run says
/// what is done and what remains; `quiet` turns it off.
class ProgressLine {
  public:
    explicit ProgressLine(bool quiet, std::chrono::milliseconds interval = std::chrono::seconds(2))
        : quiet_(quiet), interval_(interval), start_(FuzzClock::now()), last_(start_) {}
    /// True when a line is due now (and then the next one is due an interval later).
    bool due() {
        if (quiet_) return false;
        const auto now = FuzzClock::now();
        if (now - last_ < interval_) return false;
        last_ = now;
        return true;
    }
    double elapsed_seconds() const {
        return std::chrono::duration<double>(FuzzClock::now() - start_).count();
    }

  private:
    bool quiet_;
    std::chrono::milliseconds interval_;
    FuzzClock::time_point start_, last_;
};

}  // namespace exactmesh::generators
