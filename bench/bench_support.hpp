// SPDX-License-Identifier: MIT
// What the benchmark binaries share: the pinned seeds of their inputs, the heap regime of the
// constructions they time, the context lines of their JSON (build type, compiler, peak memory
// rule), the thread counts and sizes of the strong-scaling rows, peer programs run as processes
// with their peak memory (run_shell_command) and the run of Google Benchmark that ends their
// main().
#pragma once

#include <benchmark/benchmark.h>
#include <malloc.h>    // mallopt, malloc_trim: the heap regime
#include <spawn.h>     // posix_spawn: peers run as processes
#include <sys/wait.h>  // waitpid
#include <unistd.h>    // environ, access, unlink

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#if defined(EXACTMESH_WITH_CGAL)
#include <CGAL/version.h>
#endif

#ifndef EXACTMESH_BENCH_BUILD_TYPE
#define EXACTMESH_BENCH_BUILD_TYPE "unknown"
#endif

namespace exactmesh::bench {

/// Pinned seeds: the generated input of every (workload, n), and the random/BRIO shuffles.
inline constexpr std::uint64_t kInputSeed = 20240601;
inline constexpr std::uint64_t kOrderSeed = 1;

/// The heap regime of the timed constructions. Warm (default): malloc never returns memory to
/// the kernel (no mmap for large blocks, no trimming), so every construction reuses resident
/// pages, whatever ran before it. Cold (EXACTMESH_BENCH_COLD_HEAP=1): the heap is trimmed after
/// each construction (timer paused) and large blocks are mmapped, so each construction pays
/// its page faults, as a one-shot run does. Without fixing one or the other, glibc's adaptive
/// mmap/trim thresholds made the regime depend on the benchmarks run before: on the reference
/// VM, where a page fault is expensive, the same construction measured 1x or 2x.
inline bool cold_heap() {
    static const bool value = [] {
        const char* text = std::getenv("EXACTMESH_BENCH_COLD_HEAP");
        return text != nullptr && std::string_view(text) == "1";
    }();
    return value;
}

/// Sets the regime (see cold_heap) before any benchmark runs.
inline void set_heap_regime() {
    if (cold_heap()) return;
    mallopt(M_MMAP_MAX, 0);
    mallopt(M_TRIM_THRESHOLD, std::numeric_limits<int>::max());
}

/// Called with the timer paused after each construction is destroyed.
inline void after_construction() {
    if (cold_heap()) malloc_trim(0);
}

/// The context line that says how peak_bytes counters are measured (bench/heap_accounting.cpp).
inline void add_peak_memory_context() {
    benchmark::AddCustomContext("exactmesh_peak_memory",
                                "peak live heap bytes (operator new, malloc_usable_size)");
}

struct ProcessRun {
    bool ok = false;           ///< started, and exited with status 0
    double max_rss_bytes = 0;  ///< the command's largest resident set; 0 without /usr/bin/time
};

/// Runs `command` through /bin/sh (a peer program) under GNU time (/usr/bin/time -f %M, Debian
/// package `time`), which reports the largest resident set of what it waited for. Not wait4 on
/// our own child, nor getrusage(RUSAGE_CHILDREN): a child started by posix_spawn or fork from
/// this process inherits our peak resident set into its own at exec (the kernel keeps the larger
/// of the old and new image's), so every peer would read at least the benchmark's own peak;
/// /usr/bin/time is a fresh small image, so what it reports is the peer's. Without
/// /usr/bin/time the command runs alone and max_rss_bytes stays 0.
inline ProcessRun run_shell_command(const std::string& command) {
    char rss_file[] = "/tmp/exactmesh_bench_rss_XXXXXX";
    const int fd = mkstemp(rss_file);
    const bool timed = fd >= 0 && access("/usr/bin/time", X_OK) == 0;
    if (fd >= 0) close(fd);
    std::vector<std::string> words = {"/bin/sh", "-c", command};
    if (timed) words.insert(words.begin(), {"/usr/bin/time", "-f", "%M", "-o", rss_file});
    std::vector<char*> argv;
    for (std::string& word : words) argv.push_back(word.data());
    argv.push_back(nullptr);
    ProcessRun run;
    pid_t pid = 0;
    if (posix_spawn(&pid, argv[0], nullptr, nullptr, argv.data(), environ) == 0) {
        int status = 0;
        if (waitpid(pid, &status, 0) == pid) run.ok = WIFEXITED(status) && WEXITSTATUS(status) == 0;
    }
    if (timed) {
        // The last line is the number; a failed command adds "Command exited ..." before it.
        std::ifstream text(rss_file);
        std::string line, last;
        while (std::getline(text, line))
            if (!line.empty()) last = line;
        if (!last.empty() && last.find_first_not_of("0123456789") == std::string::npos)
            run.max_rss_bytes = std::stod(last) * 1024.0;
    }
    if (fd >= 0) unlink(rss_file);
    return run;
}

/// The context line naming the compiler and its version.
inline void add_compiler_context() {
#if defined(__clang__)
    benchmark::AddCustomContext("exactmesh_compiler", "clang " __clang_version__);
#elif defined(__GNUC__)
    benchmark::AddCustomContext("exactmesh_compiler", "gcc " __VERSION__);
#endif
}

/// The context line naming the CGAL version compared against (none without EXACTMESH_WITH_CGAL).
inline void add_cgal_context() {
#if defined(EXACTMESH_WITH_CGAL)
    benchmark::AddCustomContext("exactmesh_cgal", CGAL_VERSION_STR);
#endif
}

/// The largest thread count of the strong-scaling rows (issue 17): EXACTMESH_BENCH_MAX_THREADS
/// when set (clamped to 1..256; more threads than cores oversubscribes them, on purpose or not),
/// else std::thread::hardware_concurrency() (1 when it is unknown). The rows run T = 1 .. this.
inline unsigned max_bench_threads() {
    static const unsigned value = [] {
        long threads = static_cast<long>(std::thread::hardware_concurrency());
        if (const char* text = std::getenv("EXACTMESH_BENCH_MAX_THREADS")) {
            threads = std::atol(text);
        }
        return static_cast<unsigned>(std::clamp(threads, 1L, 256L));
    }();
    return value;
}

/// The sizes of the strong-scaling rows: 10^5, 10^6 and 10^7 points, those not above
/// `max_points` (empty below 10^5: then the rows are not registered).
inline std::vector<std::int64_t> scaling_sizes(std::int64_t max_points) {
    std::vector<std::int64_t> out;
    for (std::int64_t n = 100000; n <= 10000000 && n <= max_points; n *= 10) out.push_back(n);
    return out;
}

/// The context line giving the largest thread count of the scaling rows (max_bench_threads).
inline void add_threads_context() {
    benchmark::AddCustomContext("exactmesh_max_threads", std::to_string(max_bench_threads()));
}

/// The rest of main(): Google Benchmark reads its flags from the command line (an unrecognized
/// one ends the run with status 1), runs the benchmarks they select and shuts down.
inline int run_benchmarks(int argc, char** argv) {
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}

/// run_benchmarks with a short default min_time, --benchmark_min_time=0.1, placed before the
/// command line's flags so that those come later and win.
inline int run_benchmarks_with_default_min_time(int argc, char** argv) {
    static char min_time[] = "--benchmark_min_time=0.1";
    std::vector<char*> args(argv, argv + argc);
    args.insert(args.begin() + 1, min_time);
    return run_benchmarks(static_cast<int>(args.size()), args.data());
}

}  // namespace exactmesh::bench
