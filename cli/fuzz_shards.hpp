// SPDX-License-Identifier: MIT
// `exactmesh fuzz` on every core and on many machines [issue 17]: a campaign split into
// independent seeded shards. Shard I of N (`--shard I/N`) runs the case seeds seed + I,
// seed + I + N, seed + I + 2N, ...: the shards' seeds are disjoint and together they are the
// campaign's seeds seed, seed + 1, ... (with --count C, the C cases split between them). A shard
// saves its failures in its own folder (--out) and writes there fuzz-summary.txt, its counts
// (all or nothing: io::write_text_file).
// `--jobs N` runs the N shards as child processes of this program, each in OUT/shard-I with its
// output in OUT/shard-I/fuzz.log, waits for them and merges them; `--merge DIR...` merges shard
// folders made anywhere (other machines, a batch system's array jobs) into --out: the counts
// summed, the failure files copied, one summary printed. Nothing of ours runs between machines:
// any scheduler that can start `exactmesh fuzz --shard I/N` and copy a folder back will do.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <ostream>
#include <string>
#include <vector>

namespace exactmesh::cli {

struct FuzzShard {
    std::uint64_t index = 0;  ///< I in [0, count)
    std::uint64_t count = 1;  ///< N >= 1

    /// The first case seed of this shard in a campaign starting at `seed`.
    std::uint64_t first_seed(std::uint64_t seed) const { return seed + index; }
    /// Of `total` cases (seeds seed .. seed + total - 1), how many are this shard's.
    std::uint64_t share(std::uint64_t total) const {
        return total > index ? (total - index + count - 1) / count : 0;
    }
};

/// The most shards of one campaign, and the most local jobs.
inline constexpr std::uint64_t kMaxFuzzShards = 1000000;
inline constexpr unsigned kMaxFuzzJobs = 256;

/// "I/N" with 0 <= I < N <= kMaxFuzzShards. @throws InputError naming the text.
FuzzShard parse_fuzz_shard(const std::string& text);

/// A shard's counts, as fuzz-summary.txt holds them: `kind` (campaign, points2d, pslg or
/// points3d), `shard` ("I/N"), and numbers by name: cases, bad (failures, crashes and time-outs)
/// and the mode's own counters (points; passed, refused, failed, crashed, timed_out), seeds
/// first_seed and last_seed, seconds.
struct FuzzShardSummary {
    std::string kind;
    std::string shard;
    std::map<std::string, double> numbers;
};

/// The summary file's name in a shard folder.
inline constexpr const char* kFuzzSummaryFile = "fuzz-summary.txt";

/// Writes `summary` to dir/fuzz-summary.txt ("key value" lines).
void write_fuzz_shard_summary(const std::filesystem::path& dir, const FuzzShardSummary& summary);
/// Reads dir/fuzz-summary.txt. @throws InputError "file:line: ..." for a missing or malformed file.
FuzzShardSummary read_fuzz_shard_summary(const std::filesystem::path& dir);

/// Runs this program (/proc/self/exe) `jobs` times at once, child I with `arguments` followed by
/// `--shard I/jobs --out OUT/shard-I --quiet`, its stdout and stderr in OUT/shard-I/fuzz.log.
/// Returns each child's exit status (128 + the signal when one killed it).
std::vector<int> run_fuzz_shard_processes(const std::vector<std::string>& arguments, unsigned jobs,
                                          const std::filesystem::path& out);

/// Merges the summaries of `folders` (all of one kind) into one, copies their fuzz-failure-*
/// files into `out` (a file already there is kept), prints the merged summary and the failure
/// files to `report`. Returns kExitCheckFailed when any shard found a failure, else kExitSuccess.
/// @throws InputError for a folder without a readable summary or shards of different kinds.
int merge_fuzz_shards(const std::vector<std::filesystem::path>& folders,
                      const std::filesystem::path& out, std::ostream& report);

}  // namespace exactmesh::cli
