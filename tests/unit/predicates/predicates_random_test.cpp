// SPDX-License-Identifier: MIT
// The four adaptive predicates, their _exact stages and their _filter stages against the GMP
// reference (predicates/exact_reference.*): a million random cases each, then suites of exact
// degeneracies, ulp perturbations and extreme magnitudes [Shewchuk97 §4; robust-predicates].
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "predicates/exact_reference.hpp"
#include "predicates/incircle.hpp"
#include "predicates/insphere.hpp"
#include "predicates/orient2d.hpp"
#include "predicates/orient3d.hpp"
#include "tests/support/predicate_calls.hpp"
#include "tests/support/test_scale.hpp"
#include "tests/support/uniform_draws.hpp"

namespace pr = exactmesh::predicates;
using pr::Sign;

namespace {

// ---------------------------------------------------------------------------------------------
// Case counts. EXACTMESH_TEST_SCALE (a positive float, default 1) scales the sampled counts, so
// that a sanitizer build can run fewer; at 1 every predicate sees at least 10^6 random cases.

using exactmesh::testing::test_scale;

long scaled(long count) {
    return std::max(1L, static_cast<long>(std::ceil(static_cast<double>(count) * test_scale())));
}

constexpr long kRandomCasesPerDistribution = 250000;  // four distributions: 10^6 per predicate
constexpr double kInfinity = std::numeric_limits<double>::infinity();

// ---------------------------------------------------------------------------------------------
// The predicates under test, each with its stages and both reference forms.

using Args = const double* const*;
using exactmesh::testing::call_on_points;

/// The stages of the predicate `Label` of Points points in Dims dimensions (in the order of
/// EM_TEST_STAGES), over pointers to its points.
template <exactmesh::testing::Name Label, int Points, int Dims, auto Full, auto Exact, auto Filter,
          auto ReferenceRaw, auto Reference, auto Fast>
struct Stages {
    static constexpr const char* kName = Label.text;
    static constexpr int kPoints = Points, kDims = Dims;
    static Sign full(Args p) { return call_on_points<Points>(Full, p); }
    static Sign exact(Args p) { return call_on_points<Points>(Exact, p); }
    static std::optional<Sign> filter(Args p) { return call_on_points<Points>(Filter, p); }
    static Sign reference(Args p) { return call_on_points<Points>(Reference, p); }
    static Sign reference_raw(Args p) { return call_on_points<Points>(ReferenceRaw, p); }
};

using Orient2d = Stages<"orient2d", 3, 2, EM_TEST_STAGES(orient2d)>;
using Orient3d = Stages<"orient3d", 4, 3, EM_TEST_STAGES(orient3d)>;
using Incircle = Stages<"incircle", 4, 2, EM_TEST_STAGES(incircle)>;
using Insphere = Stages<"insphere", 5, 3, EM_TEST_STAGES(insphere)>;

// ---------------------------------------------------------------------------------------------
// The harness: every case is compared with the reference through the adaptive predicate, the
// filter (which may abstain but never disagree) and, at a chosen rate, the _exact stage and the
// raw-coordinate form of the reference.

enum class Expect { Any, Zero };

template <class P>
class Harness {
  public:
    static constexpr int kCoords = P::kPoints * P::kDims;
    using Case = std::array<double, kCoords>;

    /// exact_every: check P::exact on every k-th case; raw_every: check the raw reference too.
    void begin_suite(std::string name, long exact_every, long raw_every) {
        suite_ = std::move(name);
        exact_every_ = exact_every;
        raw_every_ = raw_every;
        suite_cases_ = suite_zeros_ = suite_filtered_ = suite_exact_ = suite_raw_ = 0;
        suite_start_ = std::chrono::steady_clock::now();
    }

    void end_suite() {
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - suite_start_).count();
        std::printf(
            "  %-9s %-52s %7ld cases, %5.1f%% zero, %5.1f%% filtered, %7ld exact, %5ld raw, %5.2f "
            "s\n",
            P::kName, suite_.c_str(), suite_cases_,
            100.0 * static_cast<double>(suite_zeros_) /
                static_cast<double>(std::max(1L, suite_cases_)),
            100.0 * static_cast<double>(suite_filtered_) /
                static_cast<double>(std::max(1L, suite_cases_)),
            suite_exact_, suite_raw_, seconds);
        total_cases_ += suite_cases_;
    }

    void check(const Case& c, Expect expect = Expect::Any) {
        const double* p[P::kPoints];
        for (int i = 0; i < P::kPoints; ++i) p[i] = c.data() + i * P::kDims;
        const Sign ref = P::reference(p);
        ++suite_cases_;
        if (ref == Sign::Zero) ++suite_zeros_;
        if (expect == Expect::Zero && ref != Sign::Zero)
            fail(c, "reference (an exact zero)", ref, ref);
        const Sign full = P::full(p);
        if (full != ref) fail(c, P::kName, full, ref);
        if (const std::optional<Sign> f = P::filter(p)) {
            ++suite_filtered_;
            if (*f != ref) fail(c, "filter", *f, ref);
        }
        if (exact_every_ > 0 && suite_cases_ % exact_every_ == 0) {
            ++suite_exact_;
            const Sign e = P::exact(p);
            if (e != ref) fail(c, "exact", e, ref);
        }
        if (raw_every_ > 0 && suite_cases_ % raw_every_ == 0) {
            ++suite_raw_;
            const Sign raw = P::reference_raw(p);
            if (raw != ref) fail(c, "raw-form reference vs difference form", raw, ref);
        }
    }

    long total_cases() const { return total_cases_; }

    void expect_no_disagreement() const {
        std::string text;
        for (const std::string& m : messages_) text += m + "\n";
        EXPECT_EQ(failures_, 0) << failures_ << " disagreements; the first ones:\n" << text;
    }

  private:
    void fail(const Case& c, const char* what, Sign got, Sign expected) {
        ++failures_;
        if (messages_.size() >= 12) return;
        std::string m = "[" + suite_ + "] " + what + " gave " + std::to_string(pr::to_int(got)) +
                        ", reference " + std::to_string(pr::to_int(expected)) + " for " + P::kName +
                        "(";
        char buffer[64];
        for (int i = 0; i < kCoords; ++i) {
            std::snprintf(buffer, sizeof buffer, "%s%a", i == 0 ? "" : ", ",
                          c[static_cast<std::size_t>(i)]);
            m += buffer;
        }
        messages_.push_back(m + ")");
    }

    std::string suite_;
    long exact_every_ = 1, raw_every_ = 0;
    long suite_cases_ = 0, suite_zeros_ = 0, suite_filtered_ = 0, suite_exact_ = 0, suite_raw_ = 0;
    std::chrono::steady_clock::time_point suite_start_;
    long total_cases_ = 0;
    long failures_ = 0;
    std::vector<std::string> messages_;
};

// ---------------------------------------------------------------------------------------------
// Random distributions.

using Rng = std::mt19937_64;

using exactmesh::testing::uniform;
using exactmesh::testing::uniform_int;

/// +-[1,2) * 2^e with e uniform in [lo, hi]: magnitudes spread over many binades.
double mixed_magnitude(Rng& rng, int lo, int hi) {
    const double m = std::ldexp(uniform(rng, 1.0, 2.0), uniform_int(rng, lo, hi));
    return (rng() & 1u) != 0u ? m : -m;
}

/// +-[1,10) * 10^e with e uniform in [lo, hi].
double decimal_magnitude(Rng& rng, int lo, int hi) {
    const double m = uniform(rng, 1.0, 10.0) * std::pow(10.0, uniform_int(rng, lo, hi));
    return (rng() & 1u) != 0u ? m : -m;
}

/// A random subnormal (or zero) double with either sign.
double subnormal(Rng& rng) {
    const auto mantissa = static_cast<double>(rng() >> 12);  // < 2^52: below the normal range
    const double x = std::ldexp(mantissa, -1074);
    return (rng() & 1u) != 0u ? x : -x;
}

/// Points of a nearly degenerate configuration of P, rounded to doubles: c on the line ab,
/// d on the circle through a, b, c, d on the plane abc, e on the sphere. The results are then
/// scaled by a power of two and translated far away, so that the differences are inexact.
template <class P>
void near_degenerate(Rng& rng, typename Harness<P>::Case& c) {
    constexpr int kDims = P::kDims;
    if constexpr (P::kPoints == 3 || (P::kPoints == 4 && kDims == 3)) {
        // The last point is an affine combination of the others.
        for (int i = 0; i < (P::kPoints - 1) * kDims; ++i) c[i] = uniform(rng, -1.0, 1.0);
        const double s = uniform(rng, -2.0, 2.0), t = uniform(rng, -2.0, 2.0);
        const int last = (P::kPoints - 1) * kDims;
        for (int k = 0; k < kDims; ++k) {
            double v = c[k] + s * (c[kDims + k] - c[k]);
            if (P::kPoints == 4) v += t * (c[2 * kDims + k] - c[k]);
            c[last + k] = v;
        }
    } else {
        // Every point on one circle or sphere.
        const double r = uniform(rng, 0.1, 1.0);
        double center[3];
        for (double& x : center) x = uniform(rng, -1.0, 1.0);
        std::normal_distribution<double> gauss;
        for (int i = 0; i < P::kPoints; ++i) {
            double u[3] = {gauss(rng), gauss(rng), kDims == 3 ? gauss(rng) : 0.0};
            const double norm = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
            for (int k = 0; k < kDims; ++k) c[i * kDims + k] = center[k] + r * u[k] / norm;
        }
    }
    const int e = uniform_int(rng, -30, 30);
    double offset[3];
    for (double& x : offset) x = std::ldexp(uniform(rng, -1.0, 1.0), uniform_int(rng, 0, 30));
    for (int i = 0; i < P::kPoints * kDims; ++i) c[i] = std::ldexp(c[i], e) + offset[i % kDims];
}

/// One suite of `count` random cases, each made by fill(case).
template <class P, class Fill>
void run_random_suite(Harness<P>& h, const std::string& name, long exact_every, long raw_every,
                      long count, Fill fill) {
    typename Harness<P>::Case c;
    h.begin_suite(name, exact_every, raw_every);
    for (long i = 0; i < count; ++i) {
        fill(c);
        h.check(c);
    }
    h.end_suite();
}

/// A filler that draws every coordinate of a case from coordinate().
template <class Coordinate>
auto each_coordinate(Coordinate coordinate) {
    return [coordinate](auto& c) mutable {
        for (double& x : c) x = coordinate();
    };
}

template <class P>
void run_random(Harness<P>& h, std::uint64_t seed) {
    Rng rng(seed);
    const long n = scaled(kRandomCasesPerDistribution);
    // _exact on every 4th random case (it is checked on every degenerate case below); the raw
    // reference on ~10^4 cases overall, to tie the fast difference form to the raw definition.
    const long exact_every = 4, raw_every = 100;

    run_random_suite(h, "random: uniform in [-1,1]", exact_every, raw_every, n,
                     each_coordinate([&] { return uniform(rng, -1.0, 1.0); }));
    run_random_suite(
        h, "random: integers in [0, 2^20]", exact_every, raw_every, n,
        each_coordinate([&] { return static_cast<double>(uniform_int(rng, 0, 1 << 20)); }));
    run_random_suite(h, "random: mixed magnitudes 2^-60..2^60", exact_every, raw_every, n,
                     each_coordinate([&] { return mixed_magnitude(rng, -60, 60); }));
    run_random_suite(h, "random: near-degenerate, rounded, translated", exact_every, raw_every, n,
                     [&](typename Harness<P>::Case& c) { near_degenerate<P>(rng, c); });
}

// ---------------------------------------------------------------------------------------------
// Exact degenerate configurations: integer point sets, then scaled exactly.

using Point = std::array<double, 3>;
using PointSet = std::vector<Point>;

/// Collinear integer points c + t*u, t in -3..3.
std::vector<PointSet> collinear_sets() {
    const std::array<std::array<int, 2>, 6> directions = {
        {{1, 0}, {0, 1}, {1, 1}, {1, -1}, {3, 7}, {-5, 2}}};
    const std::array<std::array<int, 2>, 2> offsets = {{{0, 0}, {7, -4}}};
    std::vector<PointSet> sets;
    for (const auto& u : directions) {
        for (const auto& o : offsets) {
            PointSet s;
            for (int t = -3; t <= 3; ++t)
                s.push_back({double(o[0] + t * u[0]), double(o[1] + t * u[1]), 0.0});
            sets.push_back(s);
        }
    }
    return sets;
}

/// Coplanar integer points c + s*u + t*v, s, t in -2..2.
std::vector<PointSet> coplanar_sets() {
    const std::array<std::array<std::array<int, 3>, 2>, 3> planes = {
        {{{{1, 0, 0}, {0, 1, 0}}}, {{{1, 2, 3}, {-2, 0, 1}}}, {{{5, -3, 0}, {1, 1, 7}}}}};
    const std::array<std::array<int, 3>, 2> offsets = {{{0, 0, 0}, {3, -8, 5}}};
    std::vector<PointSet> sets;
    for (const auto& plane : planes) {
        for (const auto& o : offsets) {
            PointSet s;
            for (int a = -2; a <= 2; ++a) {
                for (int b = -2; b <= 2; ++b) {
                    Point p{};
                    for (int k = 0; k < 3; ++k)
                        p[k] = double(o[k] + a * plane[0][k] + b * plane[1][k]);
                    s.push_back(p);
                }
            }
            sets.push_back(s);
        }
    }
    return sets;
}

/// Every lattice point on the circle of radius r about an integer center: r = 5, 25, 65 carry
/// the Pythagorean triples (3,4,5), (7,24,25), (15,20,25), (16,63,65), (33,56,65), (25,60,65)...
std::vector<PointSet> cocircular_sets() {
    const std::array<int, 3> radii = {5, 25, 65};
    const std::array<std::array<int, 2>, 3> centers = {{{0, 0}, {1, -2}, {1000, 7}}};
    std::vector<PointSet> sets;
    for (const int r : radii) {
        for (const auto& c : centers) {
            PointSet s;
            for (int x = -r; x <= r; ++x) {
                for (int y = -r; y <= r; ++y) {
                    if (x * x + y * y == r * r)
                        s.push_back({double(c[0] + x), double(c[1] + y), 0.0});
                }
            }
            sets.push_back(s);
        }
    }
    return sets;
}

/// Every lattice point on the sphere of radius r: r = 3 (1,2,2), r = 9 (1,4,8), (4,4,7), (3,6,6).
std::vector<PointSet> cospherical_sets() {
    const std::array<int, 2> radii = {3, 9};
    const std::array<std::array<int, 3>, 2> centers = {{{0, 0, 0}, {-5, 2, 11}}};
    std::vector<PointSet> sets;
    for (const int r : radii) {
        for (const auto& c : centers) {
            PointSet s;
            for (int x = -r; x <= r; ++x) {
                for (int y = -r; y <= r; ++y) {
                    for (int z = -r; z <= r; ++z) {
                        if (x * x + y * y + z * z == r * r) {
                            s.push_back({double(c[0] + x), double(c[1] + y), double(c[2] + z)});
                        }
                    }
                }
            }
            sets.push_back(s);
        }
    }
    return sets;
}

/// x * 2^k when that is exact (a finite double that scales back to x), else nullopt.
std::optional<double> scale_exactly(double x, int k) {
    const double y = std::ldexp(x, k);
    if (!std::isfinite(y) || std::ldexp(y, -k) != x) return std::nullopt;
    return y;
}

/// The set multiplied by odd * 2^k when every coordinate stays exact.
std::optional<PointSet> scaled_set(const PointSet& s, double odd, int k) {
    PointSet out = s;
    for (Point& p : out) {
        for (double& x : p) {
            const std::optional<double> y = scale_exactly(x * odd, k);  // x * odd: small integers
            if (!y) return std::nullopt;
            x = *y;
        }
    }
    return out;
}

/// Powers of two from the subnormal range to near overflow, and odd multipliers.
constexpr std::array<int, 16> kScaleExponents = {-1074, -1040, -1000, -700, -520, -300, -160, -60,
                                                 0,     40,    160,   300,  520,  700,  900,  1000};
constexpr std::array<double, 4> kOddMultipliers = {1.0, 3.0, 1025.0, 65537.0};

template <class P>
typename Harness<P>::Case tuple_case(const PointSet& s, const std::array<std::size_t, 5>& idx) {
    typename Harness<P>::Case c;
    for (int i = 0; i < P::kPoints; ++i) {
        for (int k = 0; k < P::kDims; ++k)
            c[i * P::kDims + k] = s[idx[static_cast<std::size_t>(i)]][k];
    }
    return c;
}

/// The indices of the points of s, in order.
std::vector<std::size_t> identity_order(const PointSet& s) {
    std::vector<std::size_t> order(s.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    return order;
}

/// A tuple of P::kPoints distinct points of s: the first ones of `order` (indices into s) after
/// shuffling it.
template <class P>
typename Harness<P>::Case random_tuple(const PointSet& s, std::vector<std::size_t>& order,
                                       Rng& rng) {
    std::shuffle(order.begin(), order.end(), rng);
    std::array<std::size_t, 5> idx{};
    std::copy_n(order.begin(), P::kPoints, idx.begin());
    return tuple_case<P>(s, idx);
}

/// Random tuples of distinct points from each exactly degenerate set, at every exact scale: the
/// predicate must be exactly Zero. Then every coordinate of a few tuples moved by 1..4 ulps
/// each way, which must match the reference (mostly nonzero, of either sign).
template <class P>
void run_exact_configurations(Harness<P>& h, Rng& rng, const std::string& name,
                              const std::vector<PointSet>& sets, long tuples_per_set,
                              long ulp_tuples_per_set) {
    std::vector<PointSet> scaled_sets;
    for (const PointSet& s : sets) {
        for (const int k : kScaleExponents) {
            for (const double odd : kOddMultipliers) {
                if (std::optional<PointSet> t = scaled_set(s, odd, k)) scaled_sets.push_back(*t);
            }
        }
    }
    h.begin_suite(name + ": exact zeros at all scales", 1, 8);
    for (const PointSet& s : scaled_sets) {
        std::vector<std::size_t> order = identity_order(s);
        for (long t = 0; t < tuples_per_set; ++t) {
            h.check(random_tuple<P>(s, order, rng), Expect::Zero);
        }
    }
    h.end_suite();
    if (ulp_tuples_per_set == 0) return;

    h.begin_suite(name + ": one coordinate moved 1..4 ulps", 1, 8);
    for (const PointSet& s : scaled_sets) {
        std::vector<std::size_t> order = identity_order(s);
        for (long t = 0; t < ulp_tuples_per_set; ++t) {
            const typename Harness<P>::Case base = random_tuple<P>(s, order, rng);
            for (int i = 0; i < P::kPoints * P::kDims; ++i) {
                for (const double direction : {-kInfinity, kInfinity}) {
                    typename Harness<P>::Case c = base;
                    for (int steps = 1; steps <= 4; ++steps) {
                        c[i] = std::nextafter(c[i], direction);
                        h.check(c);
                    }
                }
            }
        }
    }
    h.end_suite();
}

/// Tuples drawn from an integer grid {lo..hi}^dims (many exact zeros and repeated points),
/// scaled by 2^k; `count` random tuples, or every tuple when count is 0.
template <class P>
void run_grid(Harness<P>& h, Rng& rng, int lo, int hi, int k, long count) {
    const int side = hi - lo + 1;
    long points = 1;
    for (int d = 0; d < P::kDims; ++d) points *= side;
    auto coordinate = [&](long point, int dim) {
        for (int d = 0; d < dim; ++d) point /= side;
        return std::ldexp(static_cast<double>(lo + static_cast<int>(point % side)), k);
    };
    char name[96];
    std::snprintf(name, sizeof name, "integer grid [%d,%d]^%d * 2^%d%s", lo, hi, P::kDims, k,
                  count == 0 ? ", all tuples" : "");
    h.begin_suite(name, 1, 16);
    typename Harness<P>::Case c;
    auto fill = [&](const std::array<long, 5>& pt) {
        for (int i = 0; i < P::kPoints; ++i) {
            for (int d = 0; d < P::kDims; ++d) c[i * P::kDims + d] = coordinate(pt[i], d);
        }
        h.check(c);
    };
    if (count == 0) {
        long total = 1;
        for (int i = 0; i < P::kPoints; ++i) total *= points;
        for (long n = 0; n < total; ++n) {
            std::array<long, 5> pt{};
            long rest = n;
            for (int i = 0; i < P::kPoints; ++i) {
                pt[i] = rest % points;
                rest /= points;
            }
            fill(pt);
        }
    } else {
        std::uniform_int_distribution<long> pick(0, points - 1);
        for (long n = 0; n < count; ++n) {
            std::array<long, 5> pt{};
            for (int i = 0; i < P::kPoints; ++i) pt[i] = pick(rng);
            fill(pt);
        }
    }
    h.end_suite();
}

/// Random coordinates at extreme magnitudes: huge, tiny, both mixed in one case, subnormal,
/// and small subnormal integers (exact degeneracies below the normal range).
template <class P>
void run_extreme_magnitudes(Harness<P>& h, Rng& rng, long count) {
    run_random_suite(h, "random huge: |x| in 1e150..1e300", 1, 8, count,
                     each_coordinate([&] { return decimal_magnitude(rng, 150, 299); }));
    run_random_suite(h, "random tiny: |x| in 1e-300..1e-150", 1, 8, count,
                     each_coordinate([&] { return decimal_magnitude(rng, -300, -150); }));
    run_random_suite(h, "random mixed huge, tiny, unit, zero", 1, 8, count, each_coordinate([&] {
                         switch (uniform_int(rng, 0, 3)) {
                             case 0:
                                 return decimal_magnitude(rng, 150, 299);
                             case 1:
                                 return decimal_magnitude(rng, -300, -150);
                             case 2:
                                 return uniform(rng, -1.0, 1.0);
                             default:
                                 return 0.0;
                         }
                     }));
    run_random_suite(h, "random subnormals", 1, 8, count,
                     each_coordinate([&] { return subnormal(rng); }));
    run_random_suite(h, "random subnormal integers k * 2^-1074, |k| <= 3", 1, 8, count,
                     each_coordinate([&] {
                         return std::ldexp(static_cast<double>(uniform_int(rng, -3, 3)), -1074);
                     }));
}

/// The near-degenerate lattices: one point walked over a square grid of ulp offsets around a
/// point of an exactly degenerate configuration, at scale 2^k. `base` is the degenerate case;
/// coordinates `ix` and `iy` of it move by i * step_x and j * step_y for i, j in [lo, hi] (the
/// steps are multiples of the ulp there, so every walked value is exact).
template <class P>
void run_ulp_lattice(Harness<P>& h, const char* name, typename Harness<P>::Case base, int ix,
                     double step_x, int iy, double step_y, int lo, int hi, int k) {
    char label[96];
    std::snprintf(label, sizeof label, "%s, scale 2^%d", name, k);
    h.begin_suite(label, 1, 64);
    for (double& x : base) x = std::ldexp(x, k);
    const double x0 = base[ix], y0 = base[iy];
    for (int i = lo; i <= hi; ++i) {
        for (int j = lo; j <= hi; ++j) {
            typename Harness<P>::Case c = base;
            c[ix] = x0 + std::ldexp(i * step_x, k);  // exact: a multiple of the ulp near x0
            c[iy] = y0 + std::ldexp(j * step_y, k);
            h.check(c);
        }
    }
    h.end_suite();
}

}  // namespace

TEST(Predicates_Orient2d, AgreesWithGmpOnRandomAndDegenerateInputs) {
    Harness<Orient2d> h;
    run_random(h, 0x2d2d2d2dULL);
    Rng rng(2);
    run_grid(h, rng, -3, 3, 0, 0);  // all 7^6 ordered triples of a 7x7 grid
    run_grid(h, rng, -5, 5, -1074, scaled(20000));
    run_grid(h, rng, -5, 5, 1000, scaled(20000));
    run_exact_configurations(h, rng, "collinear", collinear_sets(), 40, 2);
    // The classic: a = (0.5 + i 2^-53, 0.5 + j 2^-53) against b = (12, 12), c = (24, 24).
    const Harness<Orient2d>::Case line = {0.5, 0.5, 12.0, 12.0, 24.0, 24.0};
    for (const int k : {0, -1000, 900}) {
        run_ulp_lattice(h, "near-collinear 256x256 ulp lattice", line, 0, 0x1p-53, 1, 0x1p-53, 0,
                        255, k);
    }
    run_extreme_magnitudes(h, rng, scaled(20000));
    std::printf("  orient2d total: %ld cases\n", h.total_cases());
    h.expect_no_disagreement();
}

TEST(Predicates_Incircle, AgreesWithGmpOnRandomAndDegenerateInputs) {
    Harness<Incircle> h;
    run_random(h, 0x1c1c1c1cULL);
    Rng rng(3);
    run_grid(h, rng, -1, 2, 0, 0);  // all 16^4 ordered quadruples of a 4x4 grid
    run_grid(h, rng, -4, 4, 0, scaled(100000));
    run_grid(h, rng, -4, 4, -1074, scaled(10000));
    run_grid(h, rng, -4, 4, 1000, scaled(10000));
    run_exact_configurations(h, rng, "cocircular", cocircular_sets(), 20, 1);
    run_exact_configurations(h, rng, "collinear", collinear_sets(), 10, 1);
    // a walked around (-4, 3) on the circle x^2 + y^2 = 25 through b, c, d.
    const Harness<Incircle>::Case circle = {-4.0, 3.0, 5.0, 0.0, 0.0, 5.0, -3.0, -4.0};
    for (const int k : {0, -500, 500}) {
        run_ulp_lattice(h, "near-cocircular 128x128 ulp lattice", circle, 0, 0x1p-50, 1, 0x1p-51,
                        -64, 63, k);
    }
    run_extreme_magnitudes(h, rng, scaled(20000));
    std::printf("  incircle total: %ld cases\n", h.total_cases());
    h.expect_no_disagreement();
}

TEST(Predicates_Orient3d, AgreesWithGmpOnRandomAndDegenerateInputs) {
    Harness<Orient3d> h;
    run_random(h, 0x3d3d3d3dULL);
    Rng rng(4);
    run_grid(h, rng, -1, 1, 0, scaled(150000));
    run_grid(h, rng, 0, 3, 0, scaled(100000));
    run_grid(h, rng, -2, 2, -1074, scaled(10000));
    run_grid(h, rng, -2, 2, 1000, scaled(10000));
    run_exact_configurations(h, rng, "coplanar", coplanar_sets(), 20, 1);
    // a walked around (0.5, 0.5, 0.5) on the plane x = z through b, c, d.
    const Harness<Orient3d>::Case plane = {0.5,  0.5,  0.5,  12.0, 12.0, 12.0,
                                           24.0, 24.0, 24.0, 1.0,  0.0,  1.0};
    for (const int k : {0, -600, 600}) {
        run_ulp_lattice(h, "near-coplanar 128x128 ulp lattice", plane, 0, 0x1p-53, 1, 0x1p-53, 0,
                        127, k);
    }
    run_extreme_magnitudes(h, rng, scaled(10000));
    std::printf("  orient3d total: %ld cases\n", h.total_cases());
    h.expect_no_disagreement();
}

TEST(Predicates_Insphere, AgreesWithGmpOnRandomAndDegenerateInputs) {
    Harness<Insphere> h;
    run_random(h, 0x5f5f5f5fULL);
    Rng rng(5);
    run_grid(h, rng, -1, 1, 0, scaled(50000));
    run_grid(h, rng, 0, 3, 0, scaled(50000));
    run_grid(h, rng, -2, 2, -1074, scaled(5000));
    run_grid(h, rng, -2, 2, 1000, scaled(5000));
    run_exact_configurations(h, rng, "cospherical", cospherical_sets(), 10, 1);
    run_exact_configurations(h, rng, "coplanar", coplanar_sets(), 5, 0);
    // a walked around (1, 4, 8) on the sphere of radius 9 through b, c, d, e.
    const Harness<Insphere>::Case sphere = {1.0, 4.0,  8.0, 9.0, 0.0, 0.0,  0.0, 9.0,
                                            0.0, -4.0, 4.0, 7.0, 8.0, -1.0, 4.0};
    for (const int k : {0, -400, 400}) {
        run_ulp_lattice(h, "near-cospherical 64x64 ulp lattice", sphere, 0, 0x1p-52, 1, 0x1p-50,
                        -32, 31, k);
    }
    run_extreme_magnitudes(h, rng, scaled(5000));
    std::printf("  insphere total: %ld cases\n", h.total_cases());
    h.expect_no_disagreement();
}

TEST(Predicates_AdaptiveStages, TinyPermanentsInsideTheSafeRangeAgreeWithGmp) {
    // Coordinates that are few-bit integers or 53-bit ones (their differences rounded) times
    // the smallest power of two the expansion-safe range admits for the predicate's degree
    // (2^-537, 2^-358, 2^-268, 2^-214): the stages B, C and two-term run on them directly, and
    // their error bounds (a constant near 2^-50 or 2^-100 times a permanent down to 2^-1070)
    // fall below 2^-1022, where their rounding is no longer relative (certified() refuses them
    // since 2026-12-06). Every sign against the rational reference, ties included.
    std::mt19937_64 rng(29);
    const auto coordinate = [&](int degree) {
        const int lowest = -(1074 / degree);
        double x = 0;
        switch (rng() % 4) {
            case 0:
                x = static_cast<double>(static_cast<int>(rng() % 9) - 4);
                break;  // grid
            case 1:
                x = 0x1p53 - static_cast<double>(1 + 2 * (rng() % 8));
                break;  // 53 bits
            case 2:
                x = -static_cast<double>(1 + rng() % 3);
                break;
            default:
                x = 0x1p52 + static_cast<double>(rng() % 16);
                break;
        }
        return std::ldexp(x, lowest);
    };
    int zeros = 0;
    for (int n = 0; n < 20000; ++n) {
        double p2[4][2], p3[5][3];
        for (auto& p : p2)
            for (double& x : p) x = coordinate(n % 2 == 0 ? 2 : 4);
        for (auto& p : p3)
            for (double& x : p) x = coordinate(n % 2 == 0 ? 3 : 5);
        if (n % 2 == 0) {
            ASSERT_EQ(pr::orient2d(p2[0], p2[1], p2[2]),
                      pr::reference::orient2d(p2[0], p2[1], p2[2]))
                << n;
            ASSERT_EQ(pr::orient3d(p3[0], p3[1], p3[2], p3[3]),
                      pr::reference::orient3d(p3[0], p3[1], p3[2], p3[3]))
                << n;
        } else {
            const Sign in = pr::incircle(p2[0], p2[1], p2[2], p2[3]);
            ASSERT_EQ(in, pr::reference::incircle(p2[0], p2[1], p2[2], p2[3])) << n;
            zeros += in == Sign::Zero;
            ASSERT_EQ(pr::insphere(p3[0], p3[1], p3[2], p3[3], p3[4]),
                      pr::reference::insphere(p3[0], p3[1], p3[2], p3[3], p3[4]))
                << n;
        }
    }
    EXPECT_GT(zeros, 0);
}

// insphere's exact stages on cospherical sets whose differences do not round exactly: an
// extruded strip's six corners (three points of a circle in xy, arbitrary doubles, at two
// heights) lie on one sphere, as on the sample wing; each fifth point also moved by an ulp
// either way, and the set shifted so that coordinates span 0 to 2^-300 (past the integer
// stage's 192-bit span: the raw expansion decides those), every answer against GMP.
TEST(Predicates_Insphere, CosphericalStripCornersAgreeWithRationals) {
    std::mt19937_64 rng(1515);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    int zeros = 0;
    for (int n = 0; n < 4000; ++n) {
        const double z[2] = {std::ldexp(unit(rng), -3), 0.75 + 0.125 * unit(rng)};
        double xy[3][2];
        for (auto& p : xy)
            for (double& x : p) x = unit(rng);
        double p[6][3];
        for (int i = 0; i < 6; ++i) {
            p[i][0] = xy[i % 3][0];
            p[i][1] = xy[i % 3][1];
            p[i][2] = z[i / 3];
        }
        if (n % 4 == 1) p[5][n % 3] = std::nextafter(p[5][n % 3], n % 2 == 0 ? 2.0 : -2.0);
        if (n % 4 == 3) {
            for (auto& q : p) q[0] = std::ldexp(q[0], -300);
        }
        const double *a = p[n % 6], *b = p[(n + 1) % 6], *c = p[(n + 2) % 6];
        const double *d = p[(n + 3) % 6], *e = p[(n + 5) % 6];
        const Sign s = pr::insphere(a, b, c, d, e);
        ASSERT_EQ(s, pr::reference::insphere(a, b, c, d, e)) << n;
        zeros += s == Sign::Zero;
    }
    EXPECT_GT(zeros, 0);
}

/// Case n of the insphere filter comparisons: five points, random in [-1, 1]^3 or on the unit
/// sphere up to rounding and then nudged by ulps (the determinant near the filter's bound: a
/// rounding that differed would show), a third of them scaled by 2^-520 .. 2^520 (at and past
/// the filter's guards), and every 97th with a non-finite or extreme coordinate.
void draw_insphere_filter_case(std::mt19937_64& rng, int n, double (&p)[5][3]) {
    constexpr std::size_t N = 5, D = 3;
    std::uniform_real_distribution<double> unit(-1.0, 1.0), angle(0.0, 6.283185307179586);
    std::uniform_int_distribution<int> exponent(-520, 520);
    const double specials[] = {INFINITY, -INFINITY, NAN, 0x1p1000, 0x1p-1070};
    const int scale = n % 3 == 0 ? exponent(rng) : 0;
    if (n % 2 == 0) {
        for (auto& q : p)
            for (double& x : q) x = std::ldexp(unit(rng), scale);
    } else {
        for (auto& q : p) {
            const double t = angle(rng), u = unit(rng), r = std::sqrt(1 - u * u);
            const double s[3] = {r * std::cos(t), r * std::sin(t), u};
            for (std::size_t k = 0; k < 3; ++k) q[k] = std::ldexp(s[k], scale);
        }
        for (int k = 0; k < n % 4; ++k) {
            double& x = p[static_cast<std::size_t>(n + k) % N][static_cast<std::size_t>(k) % D];
            x = std::nextafter(x, k % 2 == 0 ? 4.0 : -4.0);
        }
    }
    if (n % 97 == 0) {
        p[static_cast<std::size_t>(n) % N][static_cast<std::size_t>(n) % D] =
            specials[static_cast<std::size_t>(n / 97) % 5];
    }
}

TEST(Predicates_Insphere, FilterDecidesAsItsScalarForm) {
    // The SSE2 form against the scalar one: the same answer everywhere.
    std::mt19937_64 rng(4646);
    int decided = 0, refused = 0;
    for (int n = 0; n < 400000; ++n) {
        double p[5][3];
        draw_insphere_filter_case(rng, n, p);
        const auto fast = pr::insphere_filter(p[0], p[1], p[2], p[3], p[4]);
        ASSERT_EQ(fast, pr::insphere_filter_scalar(p[0], p[1], p[2], p[3], p[4])) << n;
        ++(fast ? decided : refused);
    }
    EXPECT_GT(decided, 100000);
    EXPECT_GT(refused, 1000);
}

TEST(Predicates_Insphere, PairFilterDecidesAsTwoScalarForms) {
    // insphere_filter_pair against insphere_filter_scalar lane by lane: each case paired with
    // the previous one (another sphere and scale, the same fifth point), so a lane that mixed
    // its operands with the other's would show, in both lane orders; and paired with itself.
    std::mt19937_64 rng(4747);
    double previous[5][3] = {};
    int decided = 0, refused = 0;
    for (int n = 0; n < 400000; ++n) {
        double p[5][3];
        draw_insphere_filter_case(rng, n, p);
        const double* e = p[4];
        const auto first = pr::insphere_filter_scalar(p[0], p[1], p[2], p[3], e);
        const auto second =
            pr::insphere_filter_scalar(previous[0], previous[1], previous[2], previous[3], e);
        const auto paired = pr::insphere_filter_pair(p[0], p[1], p[2], p[3], previous[0],
                                                     previous[1], previous[2], previous[3], e);
        ASSERT_EQ(paired[0], first) << n;
        ASSERT_EQ(paired[1], second) << n;
        const auto swapped = pr::insphere_filter_pair(previous[0], previous[1], previous[2],
                                                      previous[3], p[0], p[1], p[2], p[3], e);
        ASSERT_EQ(swapped[0], second) << n;
        ASSERT_EQ(swapped[1], first) << n;
        const auto itself =
            pr::insphere_filter_pair(p[0], p[1], p[2], p[3], p[0], p[1], p[2], p[3], e);
        ASSERT_EQ(itself[0], first) << n;
        ASSERT_EQ(itself[1], first) << n;
        ++(first ? decided : refused);
        for (std::size_t i = 0; i < 5; ++i)
            for (std::size_t k = 0; k < 3; ++k) previous[i][k] = p[i][k];
    }
    EXPECT_GT(decided, 100000);
    EXPECT_GT(refused, 1000);
}
