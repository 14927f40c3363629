// SPDX-License-Identifier: MIT
// Overflow and underflow: coordinates whose products (or differences) leave the double range
// must still get the exact sign (DESIGN.md: "detected, never silently wrong"), the filters must
// abstain or be right at their guard boundaries (filter_constants.hpp), and NaN or infinity must
// raise exactmesh::GeometryError rather than return a sign.
#include <gtest/gtest.h>

#include <array>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "base/errors.hpp"
#include "predicates/exact_reference.hpp"
#include "predicates/filter_constants.hpp"
#include "predicates/incircle.hpp"
#include "predicates/insphere.hpp"
#include "predicates/orient2d.hpp"
#include "predicates/orient3d.hpp"
#include "predicates/sos.hpp"
#include "tests/support/predicate_calls.hpp"
#include "tests/support/uniform_draws.hpp"

namespace pr = exactmesh::predicates;
using pr::Sign;

namespace {

using Rng = std::mt19937_64;
constexpr double kMax = DBL_MAX;
constexpr double kTrueMin = 0x1p-1074;  // the smallest subnormal
constexpr double kInf = std::numeric_limits<double>::infinity();

/// One predicate: its arity, dimension and every stage, over a flat array of coordinates.
struct Predicate {
    const char* name;
    int points, dims;
    Sign (*adaptive)(const double*);
    Sign (*exact)(const double*);
    std::optional<Sign> (*filter)(const double*);
    Sign (*reference)(const double*);
    double (*fast)(const double*);
};

/// The Predicate of N points in D dimensions with these stages (as EM_TEST_STAGES lists
/// them).
template <std::size_t N, std::size_t D, auto Adaptive, auto Exact, auto Filter, auto Reference,
          auto /*ReferenceDifferences*/, auto Fast>
Predicate make_predicate(const char* name) {
    using exactmesh::testing::call_on_flat;
    return {name,
            N,
            D,
            [](const double* x) { return call_on_flat<N, D>(Adaptive, x); },
            [](const double* x) { return call_on_flat<N, D>(Exact, x); },
            [](const double* x) { return call_on_flat<N, D>(Filter, x); },
            [](const double* x) { return call_on_flat<N, D>(Reference, x); },
            [](const double* x) { return call_on_flat<N, D>(Fast, x); }};
}

const Predicate kOrient2d = make_predicate<3, 2, EM_TEST_STAGES(orient2d)>("orient2d");
const Predicate kIncircle = make_predicate<4, 2, EM_TEST_STAGES(incircle)>("incircle");
const Predicate kOrient3d = make_predicate<4, 3, EM_TEST_STAGES(orient3d)>("orient3d");
const Predicate kInsphere = make_predicate<5, 3, EM_TEST_STAGES(insphere)>("insphere");

const std::array<const Predicate*, 4> kAll = {&kOrient2d, &kIncircle, &kOrient3d, &kInsphere};

std::string describe(const Predicate& p, const std::vector<double>& x) {
    std::string s = std::string(p.name) + "(";
    char buffer[40];
    for (std::size_t i = 0; i < x.size(); ++i) {
        std::snprintf(buffer, sizeof buffer, "%s%a", i == 0 ? "" : ", ", x[i]);
        s += buffer;
    }
    return s + ")";
}

/// Compares every stage with the reference on one case; counts cases the double baseline
/// gets wrong (or cannot represent), which shows the inputs are hard.
struct Checker {
    long cases = 0, zeros = 0, fast_wrong = 0, failures = 0;
    std::string text;

    void check(const Predicate& p, const std::vector<double>& x) {
        ++cases;
        const Sign ref = p.reference(x.data());
        if (ref == Sign::Zero) ++zeros;
        const double fast = p.fast(x.data());
        if (std::isnan(fast) || pr::sign_of(fast) != ref) ++fast_wrong;
        auto fail = [&](const char* what, Sign got) {
            if (failures++ < 10) {
                text += std::string(what) + " gave " + std::to_string(pr::to_int(got)) +
                        ", reference " + std::to_string(pr::to_int(ref)) + " for " +
                        describe(p, x) + "\n";
            }
        };
        const Sign adaptive = p.adaptive(x.data());
        if (adaptive != ref) fail("adaptive", adaptive);
        const Sign exact = p.exact(x.data());
        if (exact != ref) fail("exact", exact);
        if (const std::optional<Sign> f = p.filter(x.data()); f && *f != ref) fail("filter", *f);
    }

    void expect_clean(const char* what) const {
        EXPECT_EQ(failures, 0) << what << ": " << failures << " disagreements:\n" << text;
    }
};

using exactmesh::testing::uniform;
using exactmesh::testing::uniform_int;

double random_sign(Rng& rng, double x) {
    return (rng() & 1u) != 0u ? x : -x;
}

/// Exactly degenerate integer tuples (collinear, cocircular, coplanar, cospherical), which
/// `scale` then moves to any magnitude with a power of two.
std::vector<double> degenerate_tuple(const Predicate& p, Rng& rng) {
    std::vector<double> x;
    if (p.dims == 2) {
        // Points of the circle x^2 + y^2 = 25 for incircle, of the line y = 2x - 3 for orient2d.
        static const std::array<std::array<int, 2>, 12> circle = {{{5, 0},
                                                                   {4, 3},
                                                                   {3, 4},
                                                                   {0, 5},
                                                                   {-3, 4},
                                                                   {-4, 3},
                                                                   {-5, 0},
                                                                   {-4, -3},
                                                                   {-3, -4},
                                                                   {0, -5},
                                                                   {3, -4},
                                                                   {4, -3}}};
        for (int i = 0; i < p.points; ++i) {
            if (p.points == 4) {
                const auto& q = circle[static_cast<std::size_t>(uniform_int(rng, 0, 11))];
                x.push_back(q[0]);
                x.push_back(q[1]);
            } else {
                const int t = uniform_int(rng, -20, 20);
                x.push_back(t);
                x.push_back(2 * t - 3);
            }
        }
    } else {
        // Points of the sphere of radius 3 for insphere, of the plane x + 2y - z = 1 for orient3d.
        static const std::array<std::array<int, 3>, 6> base = {
            {{1, 2, 2}, {2, 1, 2}, {2, 2, 1}, {3, 0, 0}, {0, 3, 0}, {0, 0, 3}}};
        for (int i = 0; i < p.points; ++i) {
            if (p.points == 5) {
                const auto& q = base[static_cast<std::size_t>(uniform_int(rng, 0, 5))];
                for (int k = 0; k < 3; ++k)
                    x.push_back(random_sign(rng, q[static_cast<std::size_t>(k)]));
            } else {
                const int s = uniform_int(rng, -9, 9), t = uniform_int(rng, -9, 9);
                x.push_back(s);
                x.push_back(t);
                x.push_back(s + 2 * t - 1);
            }
        }
    }
    return x;
}

std::vector<double> scale(std::vector<double> x, int k) {
    for (double& v : x) v = std::ldexp(v, k);
    return x;
}

/// `count` tuples of p, case c with every coordinate coordinate(c) with a random sign.
template <class Coordinate>
void check_random_tuples(Checker& checker, const Predicate& p, Rng& rng, int count,
                         Coordinate coordinate) {
    const auto n = static_cast<std::size_t>(p.points * p.dims);
    for (int c = 0; c < count; ++c) {
        std::vector<double> x(n);
        for (double& v : x) v = random_sign(rng, coordinate(c));
        checker.check(p, x);
    }
}

/// Moves one random coordinate of x by one ulp, up or down.
void nudge_one_coordinate(std::vector<double>& x, Rng& rng, bool up) {
    double& v = x[static_cast<std::size_t>(uniform_int(rng, 0, static_cast<int>(x.size()) - 1))];
    v = std::nextafter(v, up ? kInf : -kInf);
}

/// 600 exactly degenerate tuples of p, each scaled by 2^exponent(), then one coordinate of it
/// moved by an ulp (up on odd cases).
template <class Exponent>
void check_scaled_degenerate(Checker& checker, const Predicate& p, Rng& rng, Exponent exponent) {
    for (int c = 0; c < 600; ++c) {
        std::vector<double> x = scale(degenerate_tuple(p, rng), exponent());
        checker.check(p, x);
        nudge_one_coordinate(x, rng, (c % 2) != 0);
        checker.check(p, x);
    }
}

}  // namespace

TEST(Predicates_Overflow, HugeCoordinatesWhoseProductsOverflowGetExactSigns) {
    Rng rng(41);
    for (const Predicate* p : kAll) {
        Checker checker;
        check_random_tuples(checker, *p, rng, 3000, [&](int) {
            // 1e160..1e308 (up to DBL_MAX itself).
            const int e = uniform_int(rng, 160, 308);
            return e == 308 ? uniform(rng, 1.0, 1.7976931348623157) * 1e308
                            : uniform(rng, 1.0, 10.0) * std::pow(10.0, e);
        });
        // Exactly degenerate tuples scaled to the top of the range, and 1-ulp perturbations.
        check_scaled_degenerate(checker, *p, rng, [&] { return uniform_int(rng, 530, 1017); });
        EXPECT_GT(checker.zeros, 500) << p->name;
        EXPECT_GT(checker.fast_wrong, 1000) << p->name << ": the plain double baseline overflows";
        checker.expect_clean(p->name);
    }
}

TEST(Predicates_Overflow, DifferencesThatOverflowGetExactSigns) {
    // Coordinates near +-DBL_MAX whose differences overflow: a - c = 2 DBL_MAX is not a double.
    const double h = kMax, q = kMax / 2, e = std::nextafter(kMax, 0.0);
    Checker checker;
    std::vector<std::vector<double>> cases2 = {
        {h, h, -h, -h, 0, 0},         // collinear through the origin
        {h, h, -h, -h, 0, kTrueMin},  // off the line by the smallest subnormal
        {h, h, -h, -h, kTrueMin, 0}, {h, -h, -h, h, q, -q},  // collinear
        {h, -h, -h, h, q, -e / 2},   {h, 1, -h, 0, 0, 0.5},  // a - b overflows
        {-h, -h, h, -h, e, h},       {h, e, -e, -h, 0, 0},
    };
    for (const auto& x : cases2) checker.check(kOrient2d, x);
    std::vector<std::vector<double>> cases_incircle = {
        {h, 0, 0, h, -h, 0, 0, -h},        // cocircular about the origin, radius DBL_MAX
        {h, 0, 0, h, -h, 0, 0, -e},        // d inside by one ulp
        {h, 0, 0, h, -h, 0, kTrueMin, 0},  // d at the center: inside
        {q, 0, 0, q, -q, 0, 0, -q},
        {h, h, -h, h, -h, -h, h, -h},  // square corners: cocircular
        {h, h, -h, h, -h, -h, e, -e},
    };
    for (const auto& x : cases_incircle) checker.check(kIncircle, x);
    std::vector<std::vector<double>> cases3 = {
        {h, 0, 0, 0, h, 0, 0, 0, h, -h, -h, -h},
        {h, 0, 0, 0, h, 0, -h, -h, 0, 0, 0, 0},  // coplanar: z = 0
        {h, 0, 0, 0, h, 0, -h, -h, 0, 0, 0, kTrueMin},
        {h, h, h, -h, -h, -h, h, -h, 0, -h, h, 0},
    };
    for (const auto& x : cases3) checker.check(kOrient3d, x);
    std::vector<std::vector<double>> cases_insphere = {
        {h, 0, 0, 0, h, 0, 0, 0, h, -h, 0, 0, 0, -h, 0},  // cospherical, radius DBL_MAX
        {h, 0, 0, 0, h, 0, 0, 0, h, -h, 0, 0, 0, -e, 0},
        {h, 0, 0, 0, h, 0, 0, 0, h, -h, 0, 0, 0, 0, kTrueMin},
        {h, h, h, -h, h, h, h, -h, h, h, h, -h, -h, -h, -h},  // cube corners: cospherical
        {h, h, h, -h, h, h, h, -h, h, h, h, -h, -e, -e, -e},
    };
    for (const auto& x : cases_insphere) checker.check(kInsphere, x);
    EXPECT_GE(checker.zeros, 6);
    checker.expect_clean("differences near DBL_MAX");
}

TEST(Predicates_Overflow, TinyAndSubnormalCoordinatesWhoseProductsUnderflowGetExactSigns) {
    Rng rng(42);
    for (const Predicate* p : kAll) {
        Checker checker;
        check_random_tuples(checker, *p, rng, 3000, [&](int c) {
            double v = 0.0;
            switch (c % 3) {
                case 0:  // 1e-160..1e-320: products underflow, the smallest are subnormal
                    v = uniform(rng, 1.0, 10.0) * std::pow(10.0, -uniform_int(rng, 160, 307));
                    if (uniform_int(rng, 0, 3) == 0)
                        v = std::ldexp(uniform(rng, 1.0, 2.0), -uniform_int(rng, 1023, 1063));
                    break;
                case 1:  // any subnormal
                    v = std::ldexp(static_cast<double>(rng() >> 12), -1074);
                    break;
                default:  // subnormal integers: exact degeneracies below the normal range
                    v = uniform_int(rng, -4, 4) * kTrueMin;
                    break;
            }
            return v;
        });
        check_scaled_degenerate(checker, *p, rng, [&] { return -uniform_int(rng, 540, 1074); });
        // Tiny but nondegenerate: the double evaluation underflows to zero or loses the sign.
        EXPECT_GT(checker.fast_wrong, 200) << p->name;
        EXPECT_GT(checker.zeros, 200) << p->name;
        checker.expect_clean(p->name);
    }
}

TEST(Predicates_Overflow, MixedHugeAndSubnormalCoordinatesGetExactSigns) {
    Rng rng(43);
    for (const Predicate* p : kAll) {
        Checker checker;
        check_random_tuples(checker, *p, rng, 2000, [&](int) {
            switch (uniform_int(rng, 0, 4)) {
                case 0:
                    return uniform(rng, 0.5, 1.0) * kMax;
                case 1:
                    return std::ldexp(static_cast<double>(rng() >> 12), -1074);
                case 2:
                    return uniform_int(rng, -2, 2) * kTrueMin;
                case 3:
                    return std::ldexp(uniform(rng, 1.0, 2.0), uniform_int(rng, -1022, 1023));
                default:
                    return 0.0;
            }
        });
        checker.expect_clean(p->name);
    }
}

// Every predicate is homogeneous in the coordinates, so scaling a tuple by 2^k (exactly) keeps
// its sign; out of the expansion-safe range the exact stages scale by a power of two
// (detail::rescale_into_safe_range) instead of calling GMP. Random, near-degenerate and exactly
// degenerate tuples at 2^k for k across the whole exponent range (where the scaling is exact):
// the same sign as at 2^0, the reference's sign, from every stage.
TEST(Predicates_Overflow, ScalingByAPowerOfTwoKeepsEverySign) {
    Rng rng(44);
    for (const Predicate* p : kAll) {
        Checker checker;
        const std::size_t n = static_cast<std::size_t>(p->points * p->dims);
        for (int c = 0; c < 1500; ++c) {
            std::vector<double> x(n);
            if (c % 3 == 0) {
                x = degenerate_tuple(*p, rng);
            } else {
                for (double& v : x) v = uniform(rng, -1.0, 1.0);
                if (c % 3 == 2) {  // one coordinate nudged off an exact degeneracy
                    x = degenerate_tuple(*p, rng);
                    nudge_one_coordinate(x, rng, (c % 2) != 0);
                }
            }
            const Sign at_one = p->reference(x.data());
            for (const int k : {-1000, -600, -300, -200, -60, 60, 200, 300, 600, 1000}) {
                const std::vector<double> y = scale(x, k);
                bool exact = true;  // no bit lost to the subnormal range, no overflow
                for (std::size_t i = 0; i < n; ++i) exact = exact && std::ldexp(y[i], -k) == x[i];
                if (!exact) continue;
                EXPECT_EQ(p->adaptive(y.data()), at_one) << describe(*p, y);
                checker.check(*p, y);
            }
        }
        EXPECT_GT(checker.cases, 10000) << p->name;
        EXPECT_GT(checker.zeros, 2000) << p->name;
        checker.expect_clean(p->name);
    }
}

// The filters are certified only inside [*_filter_min, *_filter_max] (filter_constants.hpp):
// near-degenerate tuples whose largest coordinate difference sits just inside and just outside
// each guard must still come out exact, whichever stage answers.
TEST(Predicates_Overflow, FilterGuardBoundariesAreExact) {
    struct Guard {
        const Predicate* predicate;
        double min, max;
    };
    const std::array<Guard, 4> guards = {
        {{&kOrient2d, pr::orient2d_filter_min, pr::orient2d_filter_max},
         {&kIncircle, pr::incircle_filter_min, pr::incircle_filter_max},
         {&kOrient3d, pr::orient3d_filter_min, pr::orient3d_filter_max},
         {&kInsphere, pr::insphere_filter_min, pr::insphere_filter_max}}};
    Rng rng(44);
    for (const Guard& g : guards) {
        Checker checker;
        long certified = 0;
        for (const double bound : {g.min, g.max}) {
            const int k = std::ilogb(bound);
            for (int c = 0; c < 400; ++c) {
                // A degenerate integer tuple (coordinates up to ~20, i.e. 2^4) scaled so that
                // its spread straddles the guard, then random and ulp-sized moves.
                std::vector<double> x = scale(degenerate_tuple(*g.predicate, rng), k - 5 + c % 11);
                checker.check(*g.predicate, x);
                for (double& v : x)
                    v = std::nextafter(v, uniform_int(rng, 0, 1) == 0 ? kInf : -kInf);
                checker.check(*g.predicate, x);
                for (double& v : x) v += std::ldexp(uniform(rng, -1.0, 1.0), k - 3);
                checker.check(*g.predicate, x);
                if (g.predicate->filter(x.data())) ++certified;
            }
        }
        EXPECT_GT(certified, 0) << g.predicate->name
                                << ": the filter should answer inside its range";
        checker.expect_clean(g.predicate->name);
    }
}

TEST(Predicates_Overflow, NonFiniteCoordinatesThrowGeometryError) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (const Predicate* p : kAll) {
        const std::size_t n = static_cast<std::size_t>(p->points * p->dims);
        for (std::size_t i = 0; i < n; ++i) {
            for (const double bad : {nan, kInf, -kInf}) {
                // Every position, in a tuple that is otherwise degenerate and in a generic one.
                for (const bool generic : {false, true}) {
                    std::vector<double> x(n);
                    for (std::size_t j = 0; j < n; ++j) {
                        x[j] = generic ? static_cast<double>((j * 7 + 3) % 11) - 5.0 : 1.0;
                    }
                    x[i] = bad;
                    EXPECT_THROW(p->adaptive(x.data()), exactmesh::GeometryError)
                        << describe(*p, x);
                    EXPECT_THROW(p->exact(x.data()), exactmesh::GeometryError) << describe(*p, x);
                    EXPECT_FALSE(p->filter(x.data()).has_value())
                        << "the filter must abstain on " << describe(*p, x);
                    EXPECT_THROW(p->reference(x.data()), exactmesh::GeometryError)
                        << describe(*p, x);
                }
            }
        }
    }
    // The perturbed predicates go through the same checks.
    const double a[3] = {0, 0, 0}, b[3] = {1, 0, 0}, c[3] = {0, 1, 0}, d[3] = {0, 0, 1};
    const double bad[3] = {nan, 0, 0};
    EXPECT_THROW(pr::orient2d_sos(a, b, bad, 0, 1, 2), exactmesh::GeometryError);
    EXPECT_THROW(pr::incircle_sos(a, b, c, bad, 0, 1, 2, 3), exactmesh::GeometryError);
    EXPECT_THROW(pr::insphere_sos(a, b, c, d, bad, 0, 1, 2, 3, 4), exactmesh::GeometryError);
}
