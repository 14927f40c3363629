// SPDX-License-Identifier: MIT
// Fuzz shards: parsing, summary files, local child processes, merging (see fuzz_shards.hpp).
#include "cli/fuzz_shards.hpp"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <iomanip>
#include <set>
#include <sstream>
#include <system_error>

#include "base/errors.hpp"
#include "cli/commands.hpp"
#include "io/text_file.hpp"

namespace exactmesh::cli {

namespace fs = std::filesystem;

namespace {

/// A whole number in [0, limit], all of `text`; false otherwise.
bool parse_count(const std::string& text, std::uint64_t limit, std::uint64_t& value) {
    if (text.empty() || text.size() > 20 ||
        !std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; }))
        return false;
    value = std::strtoull(text.c_str(), nullptr, 10);
    return value <= limit;
}

std::string number_text(double value) {
    std::ostringstream text;
    if (value == std::floor(value) && std::fabs(value) < 1e18)
        text << static_cast<long long>(value);
    else
        text << std::setprecision(10) << value;
    return text.str();
}

/// Keys merged by the smallest or the largest value; every other number is summed.
bool merged_by_min(const std::string& key) {
    return key == "first_seed";
}
bool merged_by_max(const std::string& key) {
    return key == "last_seed" || key == "seconds";
}

}  // namespace

FuzzShard parse_fuzz_shard(const std::string& text) {
    const std::size_t slash = text.find('/');
    FuzzShard shard;
    if (slash == std::string::npos ||
        !parse_count(text.substr(0, slash), kMaxFuzzShards, shard.index) ||
        !parse_count(text.substr(slash + 1), kMaxFuzzShards, shard.count) || shard.count == 0 ||
        shard.index >= shard.count) {
        throw InputError("--shard " + text + ": expected I/N with 0 <= I < N <= " +
                         std::to_string(kMaxFuzzShards) + " (e.g. 0/4 .. 3/4)");
    }
    return shard;
}

void write_fuzz_shard_summary(const fs::path& dir, const FuzzShardSummary& summary) {
    std::ostringstream text;
    text << "# exactmesh fuzz shard summary (merged by exactmesh fuzz --merge)\n"
         << "kind " << summary.kind << '\n'
         << "shard " << summary.shard << '\n';
    for (const auto& [key, value] : summary.numbers)
        text << key << ' ' << number_text(value) << '\n';
    // All or nothing (a temporary file renamed into place): a merge never reads half a summary.
    io::write_text_file(dir / kFuzzSummaryFile, text.str());
}

FuzzShardSummary read_fuzz_shard_summary(const fs::path& dir) {
    const fs::path file = dir / kFuzzSummaryFile;
    std::error_code error;
    if (!fs::is_regular_file(file, error)) {
        throw InputError(file.string() +
                         ": no shard summary (not a folder written by exactmesh fuzz --shard, or "
                         "the shard did not finish)");
    }
    std::istringstream lines(io::read_text_file(file.string(), std::size_t{1} << 20));
    FuzzShardSummary summary;
    std::string line;
    for (std::size_t number = 1; std::getline(lines, line); ++number) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream words(line);
        std::string key, value, extra;
        words >> key >> value;
        if (key.empty() || value.empty() || (words >> extra)) {
            throw InputError(file.string() + ":" + std::to_string(number) + ": '" + line +
                             "': expected 'KEY VALUE'");
        }
        if (key == "kind") {
            summary.kind = value;
        } else if (key == "shard") {
            summary.shard = value;
        } else {
            char* end = nullptr;
            errno = 0;
            const double number_value = std::strtod(value.c_str(), &end);
            if (end != value.c_str() + value.size() || errno != 0 || !std::isfinite(number_value) ||
                number_value < 0) {
                throw InputError(file.string() + ":" + std::to_string(number) + ": " + key + " '" +
                                 value + "': not a number >= 0");
            }
            summary.numbers[key] = number_value;
        }
    }
    if (summary.kind.empty() || !summary.numbers.contains("cases") ||
        !summary.numbers.contains("bad")) {
        throw InputError(file.string() + ": incomplete shard summary (needs kind, cases, bad)");
    }
    return summary;
}

std::vector<int> run_fuzz_shard_processes(const std::vector<std::string>& arguments, unsigned jobs,
                                          const fs::path& out) {
    std::vector<pid_t> children;
    for (unsigned i = 0; i < jobs; ++i) {
        const fs::path folder = out / ("shard-" + std::to_string(i));
        std::error_code error;
        fs::create_directories(folder, error);
        if (error) {
            throw InputError(folder.string() + ": cannot create the shard folder (" +
                             error.message() + ")");
        }
        std::vector<std::string> words = arguments;
        words.insert(words.end(), {"--shard", std::to_string(i) + "/" + std::to_string(jobs),
                                   "--out", folder.string(), "--quiet"});
        const std::string log = (folder / "fuzz.log").string();
        std::vector<char*> argv;
        for (std::string& word : words) argv.push_back(word.data());
        argv.push_back(nullptr);
        const pid_t pid = fork();
        if (pid < 0)
            throw InternalError("fuzz --jobs: fork failed: " + std::string(strerror(errno)));
        if (pid == 0) {
            const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
            if (fd < 0) _exit(kExitInternalError);
            dup2(fd, 1);
            dup2(fd, 2);
            close(fd);
            execv("/proc/self/exe", argv.data());
            _exit(kExitInternalError);
        }
        children.push_back(pid);
    }
    std::vector<int> statuses;
    for (const pid_t pid : children) {
        int status = 0;
        while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
        }
        statuses.push_back(WIFEXITED(status)     ? WEXITSTATUS(status)
                           : WIFSIGNALED(status) ? 128 + WTERMSIG(status)
                                                 : kExitInternalError);
    }
    return statuses;
}

int merge_fuzz_shards(const std::vector<fs::path>& folders, const fs::path& out,
                      std::ostream& report) {
    if (folders.empty()) throw InputError("fuzz --merge: no shard folders given");
    FuzzShardSummary merged;
    std::set<std::string> shards;
    std::vector<fs::path> failures;
    std::error_code error;
    fs::create_directories(out, error);
    for (const fs::path& folder : folders) {
        const FuzzShardSummary summary = read_fuzz_shard_summary(folder);
        if (merged.kind.empty()) merged.kind = summary.kind;
        if (summary.kind != merged.kind) {
            throw InputError((folder / kFuzzSummaryFile).string() + ": kind " + summary.kind +
                             ", but " + (folders.front() / kFuzzSummaryFile).string() + " is " +
                             merged.kind + ": shards of different campaigns");
        }
        if (!shards.insert(summary.shard).second) {
            throw InputError((folder / kFuzzSummaryFile).string() + ": shard " + summary.shard +
                             " given twice");
        }
        for (const auto& [key, value] : summary.numbers) {
            auto [at, fresh] = merged.numbers.try_emplace(key, value);
            if (fresh) continue;
            if (merged_by_min(key))
                at->second = std::min(at->second, value);
            else if (merged_by_max(key))
                at->second = std::max(at->second, value);
            else
                at->second += value;
        }
        for (const fs::directory_entry& entry : fs::directory_iterator(folder)) {
            const std::string name = entry.path().filename().string();
            if (name.rfind("fuzz-failure-", 0) != 0) continue;
            const fs::path target = out / name;
            if (!fs::equivalent(entry.path(), target, error))
                fs::copy_file(entry.path(), target, fs::copy_options::skip_existing, error);
            if (error) {
                throw InputError(target.string() + ": cannot copy the failure file (" +
                                 error.message() + ")");
            }
            failures.push_back(target);
        }
    }
    merged.shard = std::to_string(shards.size()) + "-shards";
    report << "fuzz: merged " << shards.size() << " shards (" << merged.kind << "): cases "
           << number_text(merged.numbers["cases"]) << ", bad "
           << number_text(merged.numbers["bad"]);
    for (const auto& [key, value] : merged.numbers)
        if (key != "cases" && key != "bad") report << ", " << key << ' ' << number_text(value);
    report << '\n';
    std::sort(failures.begin(), failures.end());
    for (const fs::path& file : failures) report << "fuzz: failure file " << file.string() << '\n';
    return merged.numbers["bad"] > 0 ? kExitCheckFailed : kExitSuccess;
}

}  // namespace exactmesh::cli
