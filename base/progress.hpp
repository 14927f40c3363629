// SPDX-License-Identifier: MIT
// Progress of long constructions (issue 16, "Long runs"): a hook carried in the options structs
// (Delaunay2Options, Delaunay3Options, Cdt2Options, and through them the mesh generators) that
// an algorithm calls every 2^14 units of work, so that a command can print a line every few
// seconds. The library never prints; what the hook does is the caller's.
#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <utility>

namespace exactmesh {

/// The caller's hook: `report(done, total, what)`, with `total` an estimate of the units the
/// whole run takes (0: unknown; `done` may pass an estimate) and `what` naming the unit and the
/// work ("points inserted"). Empty: nothing is reported. The hook must not throw.
struct Progress {
    std::function<void(std::uint64_t done, std::uint64_t total, const char* what)> report;

    explicit operator bool() const { return static_cast<bool>(report); }
};

/// One loop's count of work done, calling the hook (if any) every 2^kProgressShift units. The
/// per-unit cost is one increment, one mask and one branch (never taken without a hook: the
/// mask is then all ones and the count never wraps), so the hot loops keep it unconditionally.
class ProgressCounter {
  public:
    static constexpr unsigned kProgressShift = 14;

    ProgressCounter() = default;
    /// Counts for `progress` (copied: the options may not outlive the counter), `total` units
    /// expected (0: unknown).
    ProgressCounter(Progress progress, std::uint64_t total, const char* what)
        : progress_(std::move(progress)), total_(total), what_(what) {
        if (progress_) mask_ = (std::uint64_t{1} << kProgressShift) - 1;
    }

    /// One unit done.
    void tick() {
        if ((++done_ & mask_) == 0) [[unlikely]]
            progress_.report(done_, total_, what_);
    }
    /// Units done so far.
    std::uint64_t done() const { return done_; }

  private:
    Progress progress_;
    std::uint64_t done_ = 0;
    std::uint64_t mask_ = std::numeric_limits<std::uint64_t>::max();
    std::uint64_t total_ = 0;
    const char* what_ = "";
};

}  // namespace exactmesh
