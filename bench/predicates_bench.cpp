// SPDX-License-Identifier: MIT
// Predicate benchmarks: the plain double determinant (branching and branch-free), exactmesh's
// adaptive predicates, their exact stages alone and CGAL's Epick kernel, each over the same
// streamed query tuples in the same loop [Shewchuk97 §4]; plus two_product, Dekker vs std::fma.
//
// Names: BM_<predicate>/<variant>/<workload>, BM_within_rounding/<variant>/near_origin and
// BM_two_product/<variant>. Every benchmark
// reports the counter ns_per_call (CPU time per predicate call); scripts/predicate_ratios.py
// turns the JSON into the README's ratio table.
//
// Two measurement traps (STYLE.md) shape this file:
//  - each workload holds at least 2^22 tuples drawn once with a pinned seed and streamed in order,
//    a chunk per benchmark iteration, so the branch predictor cannot learn the signs;
//  - plain_branch runs the plain determinant in the same loop that branches on its sign, which
//    is the fair baseline for a filtered predicate; plain_branchfree only sums the determinants.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "base/enum_names.hpp"
#include "bench/bench_support.hpp"
#include "predicates/exact_reference.hpp"
#include "predicates/expansion.hpp"
#include "predicates/in_ellipse.hpp"
#include "predicates/incircle.hpp"
#include "predicates/insphere.hpp"
#include "predicates/orient2d.hpp"
#include "predicates/orient3d.hpp"
#include "predicates/sign.hpp"
#include "predicates/within_rounding_of_segment.hpp"

#if defined(EXACTMESH_WITH_CGAL)
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#endif

namespace {

namespace pred = exactmesh::predicates;
using pred::Sign;

// Tuples per benchmark iteration. Large enough to amortise the loop bookkeeping, small enough
// that the slow exact variants still run many iterations within min_time.
constexpr std::size_t kChunk = std::size_t{1} << 12;

/// Tuples per workload: 2^22 unless EXACTMESH_BENCH_LOG2_TUPLES says otherwise. Smaller values
/// exist only to demonstrate the predictor trap (STYLE.md); reports use the default.
std::size_t tuple_count() {
    static const std::size_t count = [] {
        int log2_tuples = 22;
        if (const char* text = std::getenv("EXACTMESH_BENCH_LOG2_TUPLES")) {
            log2_tuples = std::atoi(text);
        }
        if (log2_tuples < 12) log2_tuples = 12;  // at least one chunk
        if (log2_tuples > 24) log2_tuples = 24;
        return std::size_t{1} << log2_tuples;
    }();
    return count;
}

enum class Predicate { orient2d, incircle, orient3d, insphere, in_ellipse };
enum class Workload { random, near_degenerate };

constexpr int points_per_tuple(Predicate p) {
    switch (p) {
        case Predicate::orient2d:
            return 3;
        case Predicate::incircle:
            return 4;
        case Predicate::orient3d:
            return 4;
        case Predicate::insphere:
            return 5;
        case Predicate::in_ellipse:
            return 4;
    }
    return 0;
}

constexpr int dimension(Predicate p) {
    return p == Predicate::orient3d || p == Predicate::insphere ? 3 : 2;
}

/// Doubles per tuple: the points, then in_ellipse's metric {M11, M12, M22}.
constexpr int tuple_doubles(Predicate p) {
    return points_per_tuple(p) * dimension(p) + (p == Predicate::in_ellipse ? 3 : 0);
}

constexpr std::array<exactmesh::EnumName<Predicate>, 5> kPredicateNames{{
    {"orient2d", Predicate::orient2d},
    {"incircle", Predicate::incircle},
    {"orient3d", Predicate::orient3d},
    {"insphere", Predicate::insphere},
    {"in_ellipse", Predicate::in_ellipse},
}};

const char* name_of(Predicate p) {
    return exactmesh::name_of(kPredicateNames, p).data();  // the names are literals
}

const char* name_of(Workload w) {
    return w == Workload::random ? "random" : "near_degenerate";
}

// ---------------------------------------------------------------------------------------------
// Inputs: deterministic across platforms (our own mapping from 64 random bits to a double).

class Random {
  public:
    explicit Random(std::uint64_t seed) : engine_(seed) {}
    /// Uniform in [0, 1), 53 random bits.
    double unit() { return static_cast<double>(engine_() >> 11) * 0x1p-53; }
    double uniform(double lo, double hi) { return lo + (hi - lo) * unit(); }
    /// Uniform integer in [-k, k].
    int offset(int k) {
        return static_cast<int>(engine_() % static_cast<std::uint64_t>(2 * k + 1)) - k;
    }

  private:
    std::mt19937_64 engine_;
};

/// x moved by `ulps` representable doubles (towards +inf when positive).
double nudge(double x, int ulps) {
    const double direction = ulps > 0 ? INFINITY : -INFINITY;
    for (int i = 0; i < std::abs(ulps); ++i) x = std::nextafter(x, direction);
    return x;
}

/// A random unit vector in the plane or in space.
template <int Dim>
std::array<double, Dim> random_direction(Random& rng) {
    for (;;) {
        std::array<double, Dim> v;
        double norm2 = 0.0;
        for (double& x : v) {
            x = rng.uniform(-1.0, 1.0);
            norm2 += x * x;
        }
        if (norm2 > 0.01 && norm2 <= 1.0) {
            for (double& x : v) x /= std::sqrt(norm2);
            return v;
        }
    }
}

/// The classic near-collinear grid, a = (0.5 + i ulp, 0.5 + j ulp) against b = (12, 12),
/// c = (24, 24), generalised: a random base point p in [0,1)^2, b and c rounded on a random line
/// through p at distances in [4, 16) and [16, 48), and a = p moved by up to 64 ulps per
/// coordinate, which spans the band where the rounded line passes.
void near_collinear(Random& rng, double* t) {
    const double px = rng.unit(), py = rng.unit();
    const std::array<double, 2> u = random_direction<2>(rng);
    const double sb = rng.uniform(4.0, 16.0), sc = rng.uniform(16.0, 48.0);
    t[0] = nudge(px, rng.offset(64));
    t[1] = nudge(py, rng.offset(64));
    t[2] = px + sb * u[0];
    t[3] = py + sb * u[1];
    t[4] = px + sc * u[0];
    t[5] = py + sc * u[1];
}

/// Four points on one circle, each rounded to doubles: near-cocircular.
void near_cocircular(Random& rng, double* t) {
    const double cx = rng.unit(), cy = rng.unit(), r = rng.uniform(0.05, 0.5);
    for (int p = 0; p < 4; ++p) {
        const double angle = rng.uniform(0.0, 2.0 * std::numbers::pi);
        t[2 * p] = cx + r * std::cos(angle);
        t[2 * p + 1] = cy + r * std::sin(angle);
    }
}

/// A random SPD metric {M11, M12, M22}: a random direction, sizes 1 and 10^-k, k uniform in
/// [0, 3] (aspect ratios up to 10^3).
void random_metric(Random& rng, double* m) {
    const double theta = rng.uniform(0.0, std::numbers::pi);
    const double c = std::cos(theta), s = std::sin(theta);
    const double h2 = std::pow(10.0, -rng.uniform(0.0, 3.0));
    const double l1 = 1.0, l2 = 1.0 / (h2 * h2);
    m[0] = c * c * l1 + s * s * l2;
    m[1] = c * s * (l1 - l2);
    m[2] = s * s * l1 + c * c * l2;
}

/// Four points on one ellipse (random centre, direction, sizes r and r 10^-k, k in [0, 3]), each
/// rounded to doubles, and that ellipse's metric: near-ellipse-cocircular.
void near_coelliptic(Random& rng, double* t) {
    const double cx = rng.unit(), cy = rng.unit(), r = rng.uniform(0.05, 0.5);
    const double theta = rng.uniform(0.0, std::numbers::pi);
    const double c = std::cos(theta), s = std::sin(theta);
    const double h1 = r, h2 = r * std::pow(10.0, -rng.uniform(0.0, 3.0));
    for (int p = 0; p < 4; ++p) {
        const double angle = rng.uniform(0.0, 2.0 * std::numbers::pi);
        const double u = h1 * std::cos(angle), v = h2 * std::sin(angle);
        t[2 * p] = cx + c * u - s * v;
        t[2 * p + 1] = cy + s * u + c * v;
    }
    const double l1 = 1.0 / (h1 * h1), l2 = 1.0 / (h2 * h2);
    t[8] = c * c * l1 + s * s * l2;
    t[9] = c * s * (l1 - l2);
    t[10] = s * s * l1 + c * c * l2;
}

/// The same in space: a, b, c rounded on a random plane through p in [0,1)^3 at distances in
/// [4, 48), and d = p moved by up to 64 ulps per coordinate.
void near_coplanar(Random& rng, double* t) {
    const double p[3] = {rng.unit(), rng.unit(), rng.unit()};
    const std::array<double, 3> u = random_direction<3>(rng);
    const std::array<double, 3> v = random_direction<3>(rng);
    for (int q = 0; q < 3; ++q) {
        const double su = rng.uniform(-48.0, 48.0), sv = rng.uniform(-48.0, 48.0);
        for (int k = 0; k < 3; ++k) t[3 * q + k] = p[k] + su * u[k] + sv * v[k];
    }
    for (int k = 0; k < 3; ++k) t[9 + k] = nudge(p[k], rng.offset(64));
}

/// Five points on one sphere, each rounded to doubles: near-cospherical.
void near_cospherical(Random& rng, double* t) {
    const double cx = rng.unit(), cy = rng.unit(), cz = rng.unit(), r = rng.uniform(0.05, 0.5);
    for (int p = 0; p < 5; ++p) {
        const double z = rng.uniform(-1.0, 1.0);
        const double angle = rng.uniform(0.0, 2.0 * std::numbers::pi);
        const double rho = std::sqrt(1.0 - z * z);
        t[3 * p] = cx + r * rho * std::cos(angle);
        t[3 * p + 1] = cy + r * rho * std::sin(angle);
        t[3 * p + 2] = cz + r * z;
    }
}

#if defined(EXACTMESH_WITH_CGAL)
using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using CgalPoint2 = Epick::Point_2;
using CgalPoint3 = Epick::Point_3;
#endif

/// One workload's tuples, flat: tuple i occupies doubles [i * stride, (i + 1) * stride).
struct Stream {
    Predicate predicate;
    Workload workload;
    std::size_t count = 0;
    std::size_t stride = 0;
    std::vector<double> coordinates;
    double plain_wrong_fraction = -1.0;  // measured on first use (plain_branch), -1 before
#if defined(EXACTMESH_WITH_CGAL)
    // The same tuples as CGAL points, laid out like `coordinates` (filled on first use).
    std::vector<CgalPoint2> points2;
    std::vector<CgalPoint3> points3;
    bool cgal_checked = false;
    std::string cgal_error;  // non-empty when CGAL's signs disagree with ours
#endif
};

/// The tuples of (p, w). Only the latest workload is kept: the largest (insphere, with its CGAL
/// copy) needs about 1 GB, and benchmarks are registered grouped by workload.
Stream& stream_for(Predicate p, Workload w) {
    static std::unique_ptr<Stream> current;
    if (current && current->predicate == p && current->workload == w) return *current;
    current.reset();  // free the previous workload before allocating the next
    auto stream = std::make_unique<Stream>();
    stream->predicate = p;
    stream->workload = w;
    stream->count = tuple_count();
    stream->stride = static_cast<std::size_t>(tuple_doubles(p));
    stream->coordinates.resize(stream->count * stream->stride);
    // Pinned seeds, a different one per (predicate, workload).
    Random rng(0x5eed0000u + 16u * static_cast<unsigned>(p) + static_cast<unsigned>(w));
    double* t = stream->coordinates.data();
    for (std::size_t i = 0; i < stream->count; ++i, t += stream->stride) {
        if (w == Workload::random) {
            const std::size_t points = static_cast<std::size_t>(points_per_tuple(p) * dimension(p));
            for (std::size_t k = 0; k < points; ++k) t[k] = rng.unit();
            if (p == Predicate::in_ellipse) random_metric(rng, t + points);
            continue;
        }
        switch (p) {
            case Predicate::orient2d:
                near_collinear(rng, t);
                break;
            case Predicate::incircle:
                near_cocircular(rng, t);
                break;
            case Predicate::orient3d:
                near_coplanar(rng, t);
                break;
            case Predicate::insphere:
                near_cospherical(rng, t);
                break;
            case Predicate::in_ellipse:
                near_coelliptic(rng, t);
                break;
        }
    }
    current = std::move(stream);
    return *current;
}

// ---------------------------------------------------------------------------------------------
// The predicates under test, each reading one tuple (point k at t + k * dimension).

template <Predicate P>
double plain_determinant(const double* t) noexcept {
    if constexpr (P == Predicate::orient2d) return pred::orient2d_fast(t, t + 2, t + 4);
    if constexpr (P == Predicate::incircle) return pred::incircle_fast(t, t + 2, t + 4, t + 6);
    if constexpr (P == Predicate::orient3d) return pred::orient3d_fast(t, t + 3, t + 6, t + 9);
    if constexpr (P == Predicate::insphere) {
        return pred::insphere_fast(t, t + 3, t + 6, t + 9, t + 12);
    }
    if constexpr (P == Predicate::in_ellipse) {
        return pred::in_ellipse_fast(t, t + 2, t + 4, t + 6, t + 8);
    }
}

template <Predicate P>
Sign adaptive(const double* t) {
    if constexpr (P == Predicate::orient2d) return pred::orient2d(t, t + 2, t + 4);
    if constexpr (P == Predicate::incircle) return pred::incircle(t, t + 2, t + 4, t + 6);
    if constexpr (P == Predicate::orient3d) return pred::orient3d(t, t + 3, t + 6, t + 9);
    if constexpr (P == Predicate::insphere) return pred::insphere(t, t + 3, t + 6, t + 9, t + 12);
    if constexpr (P == Predicate::in_ellipse)
        return pred::in_ellipse(t, t + 2, t + 4, t + 6, t + 8);
}

template <Predicate P>
Sign exact_stage(const double* t) {
    if constexpr (P == Predicate::orient2d) return pred::orient2d_exact(t, t + 2, t + 4);
    if constexpr (P == Predicate::incircle) return pred::incircle_exact(t, t + 2, t + 4, t + 6);
    if constexpr (P == Predicate::orient3d) return pred::orient3d_exact(t, t + 3, t + 6, t + 9);
    if constexpr (P == Predicate::insphere) {
        return pred::insphere_exact(t, t + 3, t + 6, t + 9, t + 12);
    }
    if constexpr (P == Predicate::in_ellipse) {
        return pred::in_ellipse_exact(t, t + 2, t + 4, t + 6, t + 8);
    }
}

#if defined(EXACTMESH_WITH_CGAL)
/// CGAL's answer in our convention. orient2d and incircle agree with CGAL's orientation and
/// side_of_oriented_circle. CGAL's 3D orientation is sign det[q-p, r-p, s-p], positive when s
/// lies above the counter-clockwise plane p, q, r, while Shewchuk's orient3d is positive below:
/// hence the minus. side_of_oriented_sphere is positive inside when CGAL's orientation is
/// positive, insphere when ours is: minus again. check_cgal_signs confirms this on the data.
template <Predicate P>
Sign cgal_sign(const void* tuple) {
    if constexpr (dimension(P) == 2) {
        const auto* q = static_cast<const CgalPoint2*>(tuple);
        if constexpr (P == Predicate::orient2d) {
            return static_cast<Sign>(static_cast<int>(CGAL::orientation(q[0], q[1], q[2])));
        } else {
            return static_cast<Sign>(
                static_cast<int>(CGAL::side_of_oriented_circle(q[0], q[1], q[2], q[3])));
        }
    } else {
        const auto* q = static_cast<const CgalPoint3*>(tuple);
        if constexpr (P == Predicate::orient3d) {
            return -static_cast<Sign>(static_cast<int>(CGAL::orientation(q[0], q[1], q[2], q[3])));
        } else {
            return -static_cast<Sign>(
                static_cast<int>(CGAL::side_of_oriented_sphere(q[0], q[1], q[2], q[3], q[4])));
        }
    }
}

/// Converts the stream to CGAL points once, then compares CGAL's signs with exactmesh's on a
/// sample of tuples (outside any timed region); a disagreement is kept in s.cgal_error.
template <Predicate P>
void prepare_cgal(Stream& s) {
    constexpr int dim = dimension(P);
    constexpr auto n = static_cast<std::size_t>(points_per_tuple(P));
    if constexpr (dim == 2) {
        if (s.points2.empty()) {
            s.points2.reserve(s.count * n);
            for (std::size_t i = 0; i < s.count * n; ++i) {
                s.points2.emplace_back(s.coordinates[2 * i], s.coordinates[2 * i + 1]);
            }
        }
    } else {
        if (s.points3.empty()) {
            s.points3.reserve(s.count * n);
            for (std::size_t i = 0; i < s.count * n; ++i) {
                s.points3.emplace_back(s.coordinates[3 * i], s.coordinates[3 * i + 1],
                                       s.coordinates[3 * i + 2]);
            }
        }
    }
    if (s.cgal_checked) return;
    s.cgal_checked = true;
    constexpr std::size_t kSample = 4096;
    for (std::size_t i = 0; i < kSample && i < s.count; ++i) {
        const Sign ours = adaptive<P>(s.coordinates.data() + i * s.stride);
        const void* tuple = dim == 2 ? static_cast<const void*>(s.points2.data() + i * n)
                                     : static_cast<const void*>(s.points3.data() + i * n);
        const Sign theirs = cgal_sign<P>(tuple);
        if (ours != theirs) {
            s.cgal_error = std::string("CGAL disagrees with exactmesh on ") + name_of(P) + "/" +
                           name_of(s.workload) + " tuple " + std::to_string(i) + ": exactmesh " +
                           std::to_string(pred::to_int(ours)) + ", CGAL (converted) " +
                           std::to_string(pred::to_int(theirs));
            return;
        }
    }
}
#endif

// ---------------------------------------------------------------------------------------------
// The loops. All variants of a workload read the same tuples in the same order: chunk after
// chunk from the start of the stream, wrapping around at its end.

/// Keeps the sign test a real conditional branch: an empty volatile asm that claims to change
/// `counter` must stay on its own path, so the compiler cannot turn the branch into a cmov or a
/// setcc (which no caller that walks or flips on the sign could do either).
inline void count_on_this_path(std::uint64_t& counter) {
    ++counter;
    __asm__ __volatile__("" : "+r"(counter));
}

void report(benchmark::State& state) {
    const auto calls = static_cast<double>(state.iterations()) * static_cast<double>(kChunk);
    state.SetItemsProcessed(static_cast<std::int64_t>(calls));
    // kIsRate divides by the CPU time, kInvert turns calls/s into s/call; the 1e-9 makes it ns.
    state.counters["ns_per_call"] =
        benchmark::Counter(calls * 1e-9, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

/// The loop every caller has: compute a sign, then branch on it.
template <class Element, class SignOf>
void branching_loop(benchmark::State& state, const Element* base, std::size_t stride,
                    std::size_t count, SignOf sign_of_tuple) {
    std::uint64_t positive = 0, negative = 0, zero = 0;
    std::size_t cursor = 0;
    for (auto _ : state) {
        const Element* t = base + cursor * stride;
        for (std::size_t i = 0; i < kChunk; ++i, t += stride) {
            const Sign s = sign_of_tuple(t);
            if (s == Sign::Positive) {
                count_on_this_path(positive);
            } else if (s == Sign::Negative) {
                count_on_this_path(negative);
            } else {
                count_on_this_path(zero);
            }
        }
        cursor += kChunk;
        if (cursor == count) cursor = 0;
    }
    benchmark::DoNotOptimize(positive + negative + zero);
    report(state);
    const double total = static_cast<double>(positive + negative + zero);
    if (total > 0) state.counters["zero_fraction"] = static_cast<double>(zero) / total;
}

/// The plain determinants summed without a branch; four sums break the addition chain.
template <Predicate P>
void branchfree_loop(benchmark::State& state, const Stream& s) {
    std::array<double, 4> sums{};
    std::size_t cursor = 0;
    for (auto _ : state) {
        const double* t = s.coordinates.data() + cursor * s.stride;
        for (std::size_t i = 0; i < kChunk; i += 4, t += 4 * s.stride) {
            sums[0] += plain_determinant<P>(t);
            sums[1] += plain_determinant<P>(t + s.stride);
            sums[2] += plain_determinant<P>(t + 2 * s.stride);
            sums[3] += plain_determinant<P>(t + 3 * s.stride);
        }
        cursor += kChunk;
        if (cursor == s.count) cursor = 0;
    }
    benchmark::DoNotOptimize(sums);
    report(state);
}

/// How often the plain determinant's sign is wrong, on a sample (outside any timed region).
template <Predicate P>
double plain_wrong_fraction(Stream& s) {
    if (s.plain_wrong_fraction < 0.0) {
        const std::size_t sample = std::min<std::size_t>(s.count, std::size_t{1} << 16);
        std::size_t wrong = 0;
        for (std::size_t i = 0; i < sample; ++i) {
            const double* t = s.coordinates.data() + i * s.stride;
            if (pred::sign_of(plain_determinant<P>(t)) != adaptive<P>(t)) ++wrong;
        }
        s.plain_wrong_fraction = static_cast<double>(wrong) / static_cast<double>(sample);
    }
    return s.plain_wrong_fraction;
}

template <Predicate P>
void bm_plain_branch(benchmark::State& state, Workload w) {
    Stream& s = stream_for(P, w);
    const double wrong = plain_wrong_fraction<P>(s);
    branching_loop(state, s.coordinates.data(), s.stride, s.count,
                   [](const double* t) { return pred::sign_of(plain_determinant<P>(t)); });
    state.counters["wrong_sign_fraction"] = wrong;
}

template <Predicate P>
void bm_plain_branchfree(benchmark::State& state, Workload w) {
    branchfree_loop<P>(state, stream_for(P, w));
}

template <Predicate P>
void bm_exactmesh(benchmark::State& state, Workload w) {
    const Stream& s = stream_for(P, w);
    branching_loop(state, s.coordinates.data(), s.stride, s.count,
                   [](const double* t) { return adaptive<P>(t); });
}

template <Predicate P>
void bm_exactmesh_exact(benchmark::State& state, Workload w) {
    const Stream& s = stream_for(P, w);
    branching_loop(state, s.coordinates.data(), s.stride, s.count,
                   [](const double* t) { return exact_stage<P>(t); });
}

#if defined(EXACTMESH_WITH_CGAL)
template <Predicate P>
void bm_cgal_epick(benchmark::State& state, Workload w) {
    Stream& s = stream_for(P, w);
    prepare_cgal<P>(s);
    if (!s.cgal_error.empty()) {
        state.SkipWithError(s.cgal_error.c_str());
        return;
    }
    constexpr auto n = static_cast<std::size_t>(points_per_tuple(P));
    if constexpr (dimension(P) == 2) {
        branching_loop(state, s.points2.data(), n, s.count,
                       [](const CgalPoint2* t) { return cgal_sign<P>(t); });
    } else {
        branching_loop(state, s.points3.data(), n, s.count,
                       [](const CgalPoint3* t) { return cgal_sign<P>(t); });
    }
}
#endif

// ---------------------------------------------------------------------------------------------
// two_product: Dekker/Veltkamp splitting against std::fma, which without -mfma is a call into
// libm. Both are branch-free, so a cache-resident array (2^12 pairs, 64 KiB) measures the
// arithmetic rather than memory bandwidth; there is no branch for a predictor to learn.

const std::vector<double>& product_operands() {
    static const std::vector<double> operands = [] {
        std::vector<double> v(2 * kChunk);
        Random rng(0x5eed7700u);
        for (double& x : v) x = std::ldexp(rng.uniform(1.0, 2.0), rng.offset(30));
        return v;
    }();
    return operands;
}

inline double dekker_tail(double a, double b, double x) noexcept {
    double a_hi, a_lo, b_hi, b_lo;
    pred::split(a, a_hi, a_lo);
    pred::split(b, b_hi, b_lo);
    const double err1 = x - a_hi * b_hi;
    const double err2 = err1 - a_lo * b_hi;
    const double err3 = err2 - a_hi * b_lo;
    return a_lo * b_lo - err3;
}

inline double fma_tail(double a, double b, double x) noexcept {
    return std::fma(a, b, -x);
}

template <double (*Tail)(double, double, double) noexcept>
void bm_two_product(benchmark::State& state) {
    const std::vector<double>& v = product_operands();
    std::array<double, 4> heads{}, tails{};
    for (auto _ : state) {
        for (std::size_t i = 0; i < 2 * kChunk; i += 8) {
            for (std::size_t j = 0; j < 4; ++j) {
                const double a = v[i + 2 * j], b = v[i + 2 * j + 1];
                const double x = a * b;
                heads[j] += x;
                tails[j] += Tail(a, b, x);
            }
        }
    }
    benchmark::DoNotOptimize(heads);
    benchmark::DoNotOptimize(tails);
    report(state);
}

// ---------------------------------------------------------------------------------------------
// within_rounding_of_segment where its filter cannot decide: a vertex w far smaller than the
// ends of a segment whose line passes through the origin, a few ulps off it (a crossing or split
// point near the origin, coordinates from 2^-990 to 2^990). Rows: the predicate, its exact stage
// alone (GMP integers on one power-of-two scale) and the rational GMP reference
// (predicates/exact_reference), 2^14 cases streamed in order.

const std::vector<std::array<double, 6>>& within_cases() {
    static const std::vector<std::array<double, 6>> cases = [] {
        std::vector<std::array<double, 6>> v;
        Random rng(0x71791u);
        while (v.size() < (std::size_t{1} << 14)) {
            const double big = std::ldexp(1.0, rng.offset(990));
            const double small = big * std::ldexp(1.0, -20 - static_cast<int>(rng.uniform(0, 880)));
            const double ax = -big * rng.uniform(0.5, 1), ay = -big * rng.uniform(0.5, 1);
            const double k = std::ldexp(1.0, rng.offset(3));
            const double r = rng.uniform(-1, 1) * small / big;
            const std::array<double, 6> c{ax * r, nudge(ay * r, rng.offset(3)), ax, ay, -k * ax,
                                          -k * ay};
            if (!pred::within_rounding_of_segment_filter(c.data(), c.data() + 2, c.data() + 4))
                v.push_back(c);
        }
        return v;
    }();
    return cases;
}

template <bool (*Within)(const double*, const double*, const double*)>
void bm_within(benchmark::State& state) {
    const std::vector<std::array<double, 6>>& cases = within_cases();
    std::size_t cursor = 0, inside = 0;
    for (auto _ : state) {
        for (std::size_t i = 0; i < kChunk; ++i) {
            const double* c = cases[cursor + i].data();
            inside += Within(c, c + 2, c + 4) ? 1 : 0;
        }
        cursor += kChunk;
        if (cursor == cases.size()) cursor = 0;
    }
    benchmark::DoNotOptimize(inside);
    report(state);
}

// ---------------------------------------------------------------------------------------------

template <Predicate P>
void register_predicate() {
    for (const Workload w : {Workload::random, Workload::near_degenerate}) {
        const std::string prefix = std::string("BM_") + name_of(P) + "/";
        const std::string suffix = std::string("/") + name_of(w);
        auto add = [&](const char* variant, void (*fn)(benchmark::State&, Workload)) {
            benchmark::RegisterBenchmark((prefix + variant + suffix).c_str(), fn, w)
                ->Unit(benchmark::kNanosecond);
        };
        add("plain_branch", &bm_plain_branch<P>);
        add("plain_branchfree", &bm_plain_branchfree<P>);
        add("exactmesh", &bm_exactmesh<P>);
        if (w == Workload::near_degenerate) add("exactmesh_exact", &bm_exactmesh_exact<P>);
#if defined(EXACTMESH_WITH_CGAL)
        // CGAL has no in-ellipse predicate: that row has no peer.
        if constexpr (P != Predicate::in_ellipse) add("cgal_epick", &bm_cgal_epick<P>);
#endif
    }
}

}  // namespace

int main(int argc, char** argv) {
    register_predicate<Predicate::orient2d>();
    register_predicate<Predicate::incircle>();
    register_predicate<Predicate::orient3d>();
    register_predicate<Predicate::insphere>();
    register_predicate<Predicate::in_ellipse>();
    benchmark::RegisterBenchmark("BM_within_rounding/exactmesh/near_origin",
                                 &bm_within<&pred::within_rounding_of_segment>)
        ->Unit(benchmark::kNanosecond);
    benchmark::RegisterBenchmark("BM_within_rounding/exactmesh_exact/near_origin",
                                 &bm_within<&pred::within_rounding_of_segment_exact>)
        ->Unit(benchmark::kNanosecond);
    benchmark::RegisterBenchmark("BM_within_rounding/gmp_rationals/near_origin",
                                 &bm_within<&pred::reference::within_rounding_of_segment>)
        ->Unit(benchmark::kNanosecond);
    benchmark::RegisterBenchmark("BM_two_product/dekker", &bm_two_product<&dekker_tail>)
        ->Unit(benchmark::kNanosecond);
    benchmark::RegisterBenchmark("BM_two_product/fma", &bm_two_product<&fma_tail>)
        ->Unit(benchmark::kNanosecond);

    benchmark::AddCustomContext("exactmesh_build_type", EXACTMESH_BENCH_BUILD_TYPE);
    benchmark::AddCustomContext("exactmesh_tuples_per_workload", std::to_string(tuple_count()));
    benchmark::AddCustomContext("exactmesh_tuples_per_iteration", std::to_string(kChunk));
#if defined(EXACTMESH_USE_FMA_TWO_PRODUCT)
    benchmark::AddCustomContext("exactmesh_two_product", "fma");
#else
    benchmark::AddCustomContext("exactmesh_two_product", "dekker");
#endif
    exactmesh::bench::add_compiler_context();
    exactmesh::bench::add_cgal_context();

    // A default min_time that keeps 5 repetitions of the whole suite within about three minutes.
    return exactmesh::bench::run_benchmarks_with_default_min_time(argc, argv);
}
