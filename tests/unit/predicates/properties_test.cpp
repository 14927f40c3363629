// SPDX-License-Identifier: MIT
// Algebraic properties of the predicates: antisymmetry under argument permutations (they are
// determinants), and the symbolic perturbations of sos.hpp [EdelsbrunnerMücke90;
// DevillersTeillaud11] checked against their definitions in predicates/exact_reference.*:
// never Zero where proofs/invariants/symbolic_perturbation.md says so, equal to the unperturbed
// sign when that is nonzero, antisymmetric when indices travel with the points.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <limits>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include "predicates/exact_reference.hpp"
#include "predicates/incircle.hpp"
#include "predicates/insphere.hpp"
#include "predicates/orient2d.hpp"
#include "predicates/orient3d.hpp"
#include "predicates/sos.hpp"
#include "tests/support/uniform_draws.hpp"

namespace pr = exactmesh::predicates;
using pr::Sign;

namespace {

using Rng = std::mt19937_64;
using Point = std::array<double, 3>;  // z is ignored by the 2D predicates
using Tuple = std::vector<Point>;     // the arguments of one call, in order
using Indices = std::vector<std::uint32_t>;

using PointPredicate = std::function<Sign(const std::vector<const double*>&)>;
using IndexedPredicate = std::function<Sign(const std::vector<const double*>&, const Indices&)>;

std::vector<const double*> pointers(const Tuple& t) {
    std::vector<const double*> p;
    for (const Point& q : t) p.push_back(q.data());
    return p;
}

/// +1 for an even permutation, -1 for an odd one (by counting inversions).
Sign parity(const std::vector<std::size_t>& perm) {
    int inversions = 0;
    for (std::size_t i = 0; i < perm.size(); ++i) {
        for (std::size_t j = i + 1; j < perm.size(); ++j) {
            if (perm[i] > perm[j]) ++inversions;
        }
    }
    return inversions % 2 == 0 ? Sign::Positive : Sign::Negative;
}

std::string describe(const Tuple& t, int dims, const Indices& idx = {}) {
    std::string s;
    char buffer[160];
    for (std::size_t i = 0; i < t.size(); ++i) {
        if (dims == 2) {
            std::snprintf(buffer, sizeof buffer, "(%a, %a)", t[i][0], t[i][1]);
        } else {
            std::snprintf(buffer, sizeof buffer, "(%a, %a, %a)", t[i][0], t[i][1], t[i][2]);
        }
        s += buffer;
        if (!idx.empty()) s += "#" + std::to_string(idx[i]);
        s += i + 1 < t.size() ? " " : "";
    }
    return s;
}

/// Collects failures with the first few messages, reported once at the end of a test.
struct Failures {
    long count = 0;
    std::string text;
    void add(const std::string& message) {
        if (count++ < 10) text += message + "\n";
    }
    void expect_none(const char* what) const {
        EXPECT_EQ(count, 0) << what << ": " << count << " failures; the first ones:\n" << text;
    }
};

using exactmesh::testing::uniform;
using exactmesh::testing::uniform_int;

// ---------------------------------------------------------------------------------------------
// Inputs: random, integer grids (exact zeros, repeated points), exactly degenerate sets scaled
// to extreme magnitudes, and ulp perturbations of them.

Point random_point(Rng& rng, int dims, double lo, double hi) {
    return {uniform(rng, lo, hi), uniform(rng, lo, hi), dims == 3 ? uniform(rng, lo, hi) : 0.0};
}

Point grid_point(Rng& rng, int dims, int lo, int hi) {
    return {double(uniform_int(rng, lo, hi)), double(uniform_int(rng, lo, hi)),
            dims == 3 ? double(uniform_int(rng, lo, hi)) : 0.0};
}

/// Lattice points on the circle x^2 + y^2 = r^2 (z = 0), or on the sphere of radius r.
std::vector<Point> lattice_sphere(int r, int dims) {
    std::vector<Point> s;
    for (int x = -r; x <= r; ++x) {
        for (int y = -r; y <= r; ++y) {
            if (dims == 2) {
                if (x * x + y * y == r * r) s.push_back({double(x), double(y), 0.0});
                continue;
            }
            for (int z = -r; z <= r; ++z) {
                if (x * x + y * y + z * z == r * r) s.push_back({double(x), double(y), double(z)});
            }
        }
    }
    return s;
}

/// Integer points on a line (2D) or a plane (3D).
std::vector<Point> lattice_flat(int dims) {
    std::vector<Point> s;
    if (dims == 2) {
        for (int t = -3; t <= 3; ++t) s.push_back({double(1 + 3 * t), double(-2 + 7 * t), 0.0});
    } else {
        for (int a = -2; a <= 2; ++a) {
            for (int b = -2; b <= 2; ++b) {
                s.push_back({double(a - 2 * b), double(2 * a), double(3 * a + b)});
            }
        }
    }
    return s;
}

Tuple pick(Rng& rng, const std::vector<Point>& set, int n) {
    Tuple t;
    for (int i = 0; i < n; ++i)
        t.push_back(set[std::uniform_int_distribution<std::size_t>(0, set.size() - 1)(rng)]);
    return t;
}

Tuple scaled(Tuple t, int k) {
    for (Point& p : t) {
        for (double& x : p) x = std::ldexp(x, k);
    }
    return t;
}

/// Powers of two that move small integers to the subnormal range or near overflow.
constexpr std::array<int, 4> kExtremeScales = {-1074, -1000, 600, 1000};

/// A mixed bag of argument tuples for a predicate of `n` points in `dims` dimensions.
std::vector<Tuple> mixed_inputs(Rng& rng, int n, int dims, long random_count,
                                long degenerate_count) {
    std::vector<Tuple> cases;
    for (long c = 0; c < random_count; ++c) {
        Tuple t;
        for (int i = 0; i < n; ++i) t.push_back(random_point(rng, dims, -1.0, 1.0));
        cases.push_back(t);
    }
    const std::vector<Point> round = lattice_sphere(dims == 2 ? 5 : 3, dims);
    const std::vector<Point> flat = lattice_flat(dims);
    for (long c = 0; c < degenerate_count; ++c) {
        Tuple t;
        switch (c % 6) {
            case 0:  // integer grid: many zeros and repeated points
                for (int i = 0; i < n; ++i) t.push_back(grid_point(rng, dims, -2, 2));
                break;
            case 1:
                t = pick(rng, round, n);
                break;
            case 2:
                t = pick(rng, flat, n);
                break;
            case 3:  // exact degeneracies at extreme scales (GMP stage, subnormals)
                t = scaled(pick(rng, c % 12 == 3 ? round : flat, n),
                           kExtremeScales[static_cast<std::size_t>(uniform_int(rng, 0, 3))]);
                break;
            case 4: {  // one coordinate of a degenerate tuple moved by a few ulps
                t = pick(rng, c % 12 == 4 ? round : flat, n);
                double& x = t[static_cast<std::size_t>(uniform_int(rng, 0, n - 1))]
                             [static_cast<std::size_t>(uniform_int(rng, 0, dims - 1))];
                const int steps = uniform_int(rng, 1, 4);
                for (int s = 0; s < steps; ++s) {
                    x = std::nextafter(x, (c / 6) % 2 == 0 ? 1e300 : -1e300);
                }
                break;
            }
            default:  // huge and tiny magnitudes mixed
                for (int i = 0; i < n; ++i) {
                    Point p = random_point(rng, dims, -1.0, 1.0);
                    for (double& x : p)
                        x = std::ldexp(x, uniform_int(rng, 0, 1) == 0 ? 900 : -1000);
                    t.push_back(p);
                }
                break;
        }
        cases.push_back(t);
    }
    return cases;
}

// ---------------------------------------------------------------------------------------------
// Antisymmetry.

/// pred(permuted arguments) == parity * pred(arguments), for every permutation.
void check_all_permutations(const PointPredicate& pred, const Tuple& t, int dims,
                            Failures& failures) {
    const std::vector<const double*> p = pointers(t);
    const Sign base = pred(p);
    std::vector<std::size_t> perm(p.size());
    std::iota(perm.begin(), perm.end(), std::size_t{0});
    while (std::next_permutation(perm.begin(), perm.end())) {
        std::vector<const double*> q;
        for (const std::size_t i : perm) q.push_back(p[i]);
        const Sign s = pred(q);
        if (s != parity(perm) * base) {
            std::string order;
            for (const std::size_t i : perm) order += std::to_string(i);
            failures.add("permutation " + order + " gave " + std::to_string(pr::to_int(s)) +
                         ", identity " + std::to_string(pr::to_int(base)) + " for " +
                         describe(t, dims));
        }
    }
}

void check_antisymmetry(const PointPredicate& adaptive, const PointPredicate& exact, int n,
                        int dims, std::uint64_t seed, long random_count, long degenerate_count) {
    Rng rng(seed);
    Failures failures;
    long zeros = 0;
    const std::vector<Tuple> cases = mixed_inputs(rng, n, dims, random_count, degenerate_count);
    for (std::size_t c = 0; c < cases.size(); ++c) {
        if (adaptive(pointers(cases[c])) == Sign::Zero) ++zeros;
        check_all_permutations(adaptive, cases[c], dims, failures);
        if (c % 8 == 0) check_all_permutations(exact, cases[c], dims, failures);
    }
    EXPECT_GT(zeros, static_cast<long>(cases.size()) / 20) << "the inputs should hold exact zeros";
    failures.expect_none("antisymmetry");
}

// ---------------------------------------------------------------------------------------------
// Symbolic perturbation.

/// `n` distinct indices, drawn to include the extremes of uint32 and neighbours of each other.
Indices distinct_indices(Rng& rng, int n) {
    static const std::array<std::uint32_t, 6> special = {
        0u,
        1u,
        2u,
        std::numeric_limits<std::uint32_t>::max(),
        std::numeric_limits<std::uint32_t>::max() - 1u,
        0x80000000u};
    Indices idx;
    while (static_cast<int>(idx.size()) < n) {
        std::uint32_t v = 0;
        switch (uniform_int(rng, 0, 2)) {
            case 0:
                v = special[static_cast<std::size_t>(uniform_int(rng, 0, 5))];
                break;
            case 1:
                v = static_cast<std::uint32_t>(uniform_int(rng, 0, 9));
                break;
            default:
                v = static_cast<std::uint32_t>(rng());
                break;
        }
        if (std::find(idx.begin(), idx.end(), v) == idx.end()) idx.push_back(v);
    }
    return idx;
}

bool all_distinct(const Tuple& t) {
    for (std::size_t i = 0; i < t.size(); ++i) {
        for (std::size_t j = i + 1; j < t.size(); ++j) {
            if (t[i] == t[j]) return false;
        }
    }
    return true;
}

Sign orient2d_sos(const std::vector<const double*>& p, const Indices& i) {
    return pr::orient2d_sos(p[0], p[1], p[2], i[0], i[1], i[2]);
}
Sign incircle_sos(const std::vector<const double*>& p, const Indices& i) {
    return pr::incircle_sos(p[0], p[1], p[2], p[3], i[0], i[1], i[2], i[3]);
}
Sign insphere_sos(const std::vector<const double*>& p, const Indices& i) {
    return pr::insphere_sos(p[0], p[1], p[2], p[3], p[4], i[0], i[1], i[2], i[3], i[4]);
}
Sign orient2d_sos_reference(const std::vector<const double*>& p, const Indices& i) {
    return pr::reference::orient2d_sos(p[0], p[1], p[2], i[0], i[1], i[2]);
}
Sign incircle_sos_reference(const std::vector<const double*>& p, const Indices& i) {
    return pr::reference::incircle_sos(p[0], p[1], p[2], p[3], i[0], i[1], i[2], i[3]);
}
Sign insphere_sos_reference(const std::vector<const double*>& p, const Indices& i) {
    return pr::reference::insphere_sos(p[0], p[1], p[2], p[3], p[4], i[0], i[1], i[2], i[3], i[4]);
}
Sign orient2d_plain(const std::vector<const double*>& p) {
    return pr::orient2d(p[0], p[1], p[2]);
}
Sign incircle_plain(const std::vector<const double*>& p) {
    return pr::incircle(p[0], p[1], p[2], p[3]);
}
Sign insphere_plain(const std::vector<const double*>& p) {
    return pr::insphere(p[0], p[1], p[2], p[3], p[4]);
}

/// Small-integer tuples full of degeneracies: grids, lattice circles/spheres, lines/planes,
/// and mixtures of them (repeated points included unless `distinct`).
std::vector<Tuple> degenerate_integer_inputs(Rng& rng, int n, int dims, long count, bool distinct) {
    const std::vector<Point> round = lattice_sphere(dims == 2 ? 5 : 3, dims);
    const std::vector<Point> big_round = lattice_sphere(dims == 2 ? 25 : 9, dims);
    const std::vector<Point> flat = lattice_flat(dims);
    std::vector<Tuple> cases;
    while (static_cast<long>(cases.size()) < count) {
        Tuple t;
        switch (cases.size() % 5) {
            case 0:
                for (int i = 0; i < n; ++i) t.push_back(grid_point(rng, dims, -1, 2));
                break;
            case 1:
                t = pick(rng, round, n);
                break;
            case 2:
                t = pick(rng, big_round, n);
                break;
            case 3:
                t = pick(rng, flat, n);
                break;
            default:  // mostly degenerate with one intruder
                t = pick(rng, uniform_int(rng, 0, 1) == 0 ? round : flat, n - 1);
                t.insert(t.begin() + uniform_int(rng, 0, n - 1), grid_point(rng, dims, -3, 3));
                break;
        }
        if (!distinct || all_distinct(t)) cases.push_back(t);
    }
    return cases;
}

/// sos against its reference perturbation on every tuple of `cases` (in `dims` dimensions), each
/// with fresh distinct indices (and, when `reference_never_zero`, the reference must not be
/// Zero); more than a fifth of the `degenerate_count` integer inputs among the cases must be
/// degenerate before the perturbation.
void expect_sos_matches_reference(Rng& rng, const std::vector<Tuple>& cases, long degenerate_count,
                                  int dims, const std::string& name, const IndexedPredicate& sos,
                                  const IndexedPredicate& reference, const PointPredicate& plain,
                                  bool reference_never_zero) {
    Failures failures;
    long unperturbed_zeros = 0;
    for (const Tuple& t : cases) {
        const std::vector<const double*> p = pointers(t);
        const Indices idx = distinct_indices(rng, static_cast<int>(p.size()));
        if (plain(p) == Sign::Zero) ++unperturbed_zeros;
        const Sign got = sos(p, idx), expected = reference(p, idx);
        if (got != expected) {
            failures.add(name + " " + std::to_string(pr::to_int(got)) + ", reference " +
                         std::to_string(pr::to_int(expected)) + " for " + describe(t, dims, idx));
        }
        if (reference_never_zero && expected == Sign::Zero) {
            failures.add("reference Zero for " + describe(t, dims, idx));
        }
    }
    EXPECT_GT(unperturbed_zeros, degenerate_count / 5) << "the inputs should be mostly degenerate";
    failures.expect_none((name + " vs reference").c_str());
}

struct SosCase {
    Tuple points;
    Indices indices;
};

}  // namespace

// --- Antisymmetry of the unperturbed predicates -------------------------------------------------

TEST(Predicates_Orient2d, IsAntisymmetricUnderArgumentPermutations) {
    check_antisymmetry(
        orient2d_plain, [](const auto& p) { return pr::orient2d_exact(p[0], p[1], p[2]); }, 3, 2,
        21, 2000, 4000);
}

TEST(Predicates_Incircle, IsAntisymmetricUnderArgumentPermutations) {
    check_antisymmetry(
        incircle_plain, [](const auto& p) { return pr::incircle_exact(p[0], p[1], p[2], p[3]); }, 4,
        2, 22, 2000, 4000);
}

TEST(Predicates_Orient3d, IsAntisymmetricUnderArgumentPermutations) {
    check_antisymmetry([](const auto& p) { return pr::orient3d(p[0], p[1], p[2], p[3]); },
                       [](const auto& p) { return pr::orient3d_exact(p[0], p[1], p[2], p[3]); }, 4,
                       3, 23, 2000, 4000);
}

TEST(Predicates_Insphere, IsAntisymmetricUnderArgumentPermutations) {
    check_antisymmetry(
        insphere_plain,
        [](const auto& p) { return pr::insphere_exact(p[0], p[1], p[2], p[3], p[4]); }, 5, 3, 24,
        500, 1000);
}

// --- Symbolic perturbation ----------------------------------------------------------------------

TEST(Predicates_Sos, Orient2dNeverZeroForDistinctPoints) {
    Rng rng(31);
    Failures failures;
    long degenerate = 0;
    // Every ordered triple of distinct points of a 4x4 grid (many collinear), then lines far
    // from the origin and at extreme scales.
    std::vector<Point> grid;
    for (int x = 0; x < 4; ++x) {
        for (int y = 0; y < 4; ++y) grid.push_back({double(x), double(y), 0.0});
    }
    std::vector<Tuple> cases;
    for (const Point& a : grid) {
        for (const Point& b : grid) {
            for (const Point& c : grid) {
                if (a != b && b != c && a != c) cases.push_back({a, b, c});
            }
        }
    }
    for (const Tuple& t : degenerate_integer_inputs(rng, 3, 2, 3000, true)) {
        cases.push_back(t);
        cases.push_back(scaled(t, -1074));
        cases.push_back(scaled(t, 1000));
    }
    for (const Tuple& t : cases) {
        const std::vector<const double*> p = pointers(t);
        if (orient2d_plain(p) == Sign::Zero) ++degenerate;
        for (int trial = 0; trial < 3; ++trial) {
            const Indices idx = distinct_indices(rng, 3);
            if (orient2d_sos(p, idx) == Sign::Zero) failures.add("Zero for " + describe(t, 2, idx));
        }
    }
    EXPECT_GT(degenerate, 1000);
    failures.expect_none("orient2d_sos");
}

TEST(Predicates_Sos, IncircleNeverZeroUnlessAllFourCollinear) {
    Rng rng(32);
    Failures failures;
    long degenerate = 0, abc_collinear = 0;
    std::vector<Tuple> cases = degenerate_integer_inputs(rng, 4, 2, 30000, true);
    for (const Tuple& t : degenerate_integer_inputs(rng, 4, 2, 3000, true)) {
        cases.push_back(scaled(t, -1074));
        cases.push_back(scaled(t, 1000));
    }
    for (const Tuple& t : cases) {
        const std::vector<const double*> p = pointers(t);
        const bool abc_flat = pr::orient2d(p[0], p[1], p[2]) == Sign::Zero;
        const bool all_collinear = abc_flat && pr::orient2d(p[0], p[1], p[3]) == Sign::Zero &&
                                   pr::orient2d(p[0], p[2], p[3]) == Sign::Zero &&
                                   pr::orient2d(p[1], p[2], p[3]) == Sign::Zero;
        if (incircle_plain(p) == Sign::Zero) ++degenerate;
        if (abc_flat && !all_collinear) ++abc_collinear;
        const Indices idx = distinct_indices(rng, 4);
        const Sign s = incircle_sos(p, idx);
        // The brief's guarantee (a, b, c not collinear), and sos.hpp's wider one.
        if (!all_collinear && s == Sign::Zero) {
            failures.add(std::string(abc_flat ? "[a,b,c collinear] " : "") + "Zero for " +
                         describe(t, 2, idx));
        }
        if (all_collinear && s != Sign::Zero) {
            failures.add("nonzero for four collinear points " + describe(t, 2, idx));
        }
    }
    EXPECT_GT(degenerate, 5000);
    EXPECT_GT(abc_collinear, 100);
    failures.expect_none("incircle_sos");
}

TEST(Predicates_Sos, InsphereNeverZeroUnlessAllFiveCoplanar) {
    Rng rng(33);
    Failures failures;
    long degenerate = 0, abcd_flat_count = 0;
    std::vector<Tuple> cases = degenerate_integer_inputs(rng, 5, 3, 20000, true);
    for (const Tuple& t : degenerate_integer_inputs(rng, 5, 3, 1000, true)) {
        cases.push_back(scaled(t, -1074));
        cases.push_back(scaled(t, 1000));
    }
    for (const Tuple& t : cases) {
        const std::vector<const double*> p = pointers(t);
        const bool abcd_flat = pr::orient3d(p[0], p[1], p[2], p[3]) == Sign::Zero;
        bool all_coplanar = abcd_flat;
        for (int skip = 0; skip < 4 && all_coplanar; ++skip) {
            std::vector<const double*> q;
            for (int i = 0; i < 5; ++i) {
                if (i != skip) q.push_back(p[static_cast<std::size_t>(i)]);
            }
            all_coplanar = pr::orient3d(q[0], q[1], q[2], q[3]) == Sign::Zero;
        }
        if (insphere_plain(p) == Sign::Zero) ++degenerate;
        if (abcd_flat && !all_coplanar) ++abcd_flat_count;
        const Sign s = insphere_sos(p, distinct_indices(rng, 5));
        if (!all_coplanar && s == Sign::Zero) {
            failures.add(std::string(abcd_flat ? "[a,b,c,d coplanar] " : "") + "Zero for " +
                         describe(t, 3));
        }
        if (all_coplanar && s != Sign::Zero) failures.add("nonzero for coplanar " + describe(t, 3));
    }
    EXPECT_GT(degenerate, 3000);
    EXPECT_GT(abcd_flat_count, 100);
    failures.expect_none("insphere_sos");
}

TEST(Predicates_Sos, AgreesWithUnperturbedSignWhenNonzero) {
    Rng rng(34);
    Failures failures;
    long nonzero = 0;
    auto check = [&](const IndexedPredicate& sos, const PointPredicate& plain, int n, int dims) {
        std::vector<Tuple> cases = mixed_inputs(rng, n, dims, 3000, 6000);
        for (const Tuple& t : cases) {
            const std::vector<const double*> p = pointers(t);
            const Sign unperturbed = plain(p);
            if (unperturbed == Sign::Zero) continue;
            ++nonzero;
            const Indices idx = distinct_indices(rng, n);
            const Sign s = sos(p, idx);
            if (s != unperturbed) {
                failures.add("sos " + std::to_string(pr::to_int(s)) + " vs unperturbed " +
                             std::to_string(pr::to_int(unperturbed)) + " for " +
                             describe(t, dims, idx));
            }
        }
    };
    check(orient2d_sos, orient2d_plain, 3, 2);
    check(incircle_sos, incircle_plain, 4, 2);
    check(insphere_sos, insphere_plain, 5, 3);
    EXPECT_GT(nonzero, 15000);
    failures.expect_none("sos vs unperturbed");
}

TEST(Predicates_Sos, AntisymmetricWhenIndicesPermuteWithPoints) {
    Rng rng(35);
    Failures failures;
    auto check = [&](const IndexedPredicate& sos, int n, int dims, long count) {
        for (const Tuple& t : degenerate_integer_inputs(rng, n, dims, count, false)) {
            const std::vector<const double*> p = pointers(t);
            const Indices idx = distinct_indices(rng, n);
            const Sign base = sos(p, idx);
            std::vector<std::size_t> perm(p.size());
            std::iota(perm.begin(), perm.end(), std::size_t{0});
            while (std::next_permutation(perm.begin(), perm.end())) {
                std::vector<const double*> q;
                Indices qi;
                for (const std::size_t i : perm) {
                    q.push_back(p[i]);
                    qi.push_back(idx[i]);
                }
                const Sign s = sos(q, qi);
                if (s != parity(perm) * base) {
                    failures.add("permuted sos " + std::to_string(pr::to_int(s)) + " vs " +
                                 std::to_string(pr::to_int(base)) + " for " +
                                 describe(t, dims, idx));
                }
            }
        }
    };
    check(orient2d_sos, 3, 2, 4000);
    check(incircle_sos, 4, 2, 2000);
    check(insphere_sos, 5, 3, 300);
    failures.expect_none("sos antisymmetry");
}

TEST(Predicates_Sos, Orient2dAgreesWithReferencePerturbation) {
    Rng rng(36);
    // Repeated points included: the perturbation is defined for them too and never vanishes.
    // The reference takes any doubles here, so the degenerate sets also go to extreme scales.
    std::vector<Tuple> cases = degenerate_integer_inputs(rng, 3, 2, 6000, false);
    for (std::size_t c = 0; c < 6000; c += 3) {
        cases.push_back(scaled(cases[c], -1074));
        cases.push_back(scaled(cases[c + 1], 1000));
    }
    expect_sos_matches_reference(rng, cases, 6000, 2, "orient2d_sos", orient2d_sos,
                                 orient2d_sos_reference, orient2d_plain, true);
}

TEST(Predicates_Sos, IncircleAgreesWithReferencePerturbation) {
    Rng rng(37);
    expect_sos_matches_reference(rng, degenerate_integer_inputs(rng, 4, 2, 20000, false), 20000, 2,
                                 "incircle_sos", incircle_sos, incircle_sos_reference,
                                 incircle_plain, false);
}

TEST(Predicates_Sos, InsphereAgreesWithReferencePerturbation) {
    Rng rng(38);
    expect_sos_matches_reference(rng, degenerate_integer_inputs(rng, 5, 3, 10000, false), 10000, 3,
                                 "insphere_sos", insphere_sos, insphere_sos_reference,
                                 insphere_plain, false);
}

// The reference perturbations themselves: a hand-checked case for each. Three collinear points
// (0,0)#0, (1,1)#1, (2,2)#2: the largest index (2,2) has y perturbed most, by +eps, so it moves
// up off the line y = x: orient2d((0,0), (1,1), (2+eps^2, 2+eps)) = eps - eps^2 > 0.
TEST(Predicates_Sos, ReferencePerturbationsMatchHandComputedCases) {
    const double a[2] = {0, 0}, b[2] = {1, 1}, c[2] = {2, 2};
    EXPECT_EQ(pr::reference::orient2d_sos(a, b, c, 0, 1, 2), Sign::Positive);
    EXPECT_EQ(pr::reference::orient2d_sos(a, b, c, 0, 2, 1), Sign::Negative);  // (1,1) moves up
    // Four cocircular points on the unit circle, counter-clockwise a, b, c: raising w_d (the
    // largest index) by eps puts d outside the lifted plane's circle: the cofactor of w_d is
    // -orient2d(a,b,c) < 0, so the perturbed incircle is Negative (d just outside).
    const double p[2] = {1, 0}, q[2] = {0, 1}, r[2] = {-1, 0}, s[2] = {0, -1};
    EXPECT_EQ(pr::reference::incircle_sos(p, q, r, s, 0, 1, 2, 3), Sign::Negative);
    // With a the most perturbed instead, the cofactor is +orient2d(b, c, d) > 0.
    EXPECT_EQ(pr::reference::incircle_sos(p, q, r, s, 3, 1, 2, 0), Sign::Positive);
    EXPECT_THROW(pr::reference::incircle_sos(p, q, r, s, 1, 1, 2, 3), std::invalid_argument);
    const double half[2] = {0.5, 0};
    EXPECT_THROW(pr::reference::incircle_sos(half, q, r, s, 0, 1, 2, 3), std::invalid_argument);
}
