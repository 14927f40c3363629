// SPDX-License-Identifier: MIT
// The comparisons moved into predicates/ (angle_comparisons_2d/3d, within_rounding_of_segment,
// triangle_area) against the GMP references of predicates/exact_reference.*: random inputs,
// near-degenerate ones (exact ties moved by a few ulps) and the same inputs scaled by 2^+-600;
// each filter stage (the *_filter functions) must agree with the reference whenever it answers,
// and answer most random calls.
#include <gtest/gtest.h>

#include <array>
#include <cfloat>
#include <cmath>
#include <optional>
#include <random>
#include <vector>

#include "predicates/angle_comparisons_2d.hpp"
#include "predicates/angle_comparisons_3d.hpp"
#include "predicates/exact_reference.hpp"
#include "predicates/orient2d.hpp"
#include "predicates/orient3d.hpp"
#include "predicates/triangle_area.hpp"
#include "predicates/within_rounding_of_segment.hpp"

namespace pr = exactmesh::predicates;
using pr::Sign;

namespace {

using Rng = std::mt19937_64;
using P2 = std::array<double, 2>;
using P3 = std::array<double, 3>;

double uniform(Rng& rng, double lo = -1.0, double hi = 1.0) {
    return std::uniform_real_distribution<double>(lo, hi)(rng);
}

/// x moved by k ulps (k may be negative).
double ulps(double x, int k) {
    for (; k > 0; --k) x = std::nextafter(x, HUGE_VAL);
    for (; k < 0; ++k) x = std::nextafter(x, -HUGE_VAL);
    return x;
}

P2 scaled(const P2& p, int k) {
    return {std::ldexp(p[0], k), std::ldexp(p[1], k)};
}
P3 scaled(const P3& p, int k) {
    return {std::ldexp(p[0], k), std::ldexp(p[1], k), std::ldexp(p[2], k)};
}

constexpr int kScales[] = {0, 600, -600};

/// Two corners (o, p, q), counter-clockwise.
struct AngleCase {
    P2 o1, p1, q1, o2, p2, q2;
};

AngleCase scaled(const AngleCase& c, int k) {
    return {scaled(c.o1, k), scaled(c.p1, k), scaled(c.q1, k),
            scaled(c.o2, k), scaled(c.p2, k), scaled(c.q2, k)};
}

/// Reorders (o, p, q) counter-clockwise; false when collinear.
bool make_ccw(const P2& o, P2& p, P2& q) {
    const Sign s = pr::orient2d(o.data(), p.data(), q.data());
    if (s == Sign::Zero) return false;
    if (s == Sign::Negative) std::swap(p, q);
    return true;
}

/// Counts of one predicate's filter: answers and cases.
struct FilterCount {
    long answered = 0, cases = 0;
};

void check_angles(const AngleCase& c, FilterCount& count, const char* what) {
    const Sign ref = pr::reference::compare_angles(c.o1.data(), c.p1.data(), c.q1.data(),
                                                   c.o2.data(), c.p2.data(), c.q2.data());
    const pr::Corner a{c.o1.data(), c.p1.data(), c.q1.data()};
    const pr::Corner b{c.o2.data(), c.p2.data(), c.q2.data()};
    ASSERT_EQ(pr::compare_angles(a, b), ref) << what;
    ASSERT_EQ(pr::compare_angles(b, a), -ref) << what;
    ++count.cases;
    if (const auto f = pr::compare_angles_filter(a, b)) {
        ++count.answered;
        ASSERT_EQ(*f, ref) << what;
    }
}

void check_lengths(const P2& p1, const P2& q1, const P2& p2, const P2& q2, FilterCount& count,
                   const char* what) {
    const Sign ref = pr::reference::compare_lengths(p1.data(), q1.data(), p2.data(), q2.data());
    ASSERT_EQ(pr::compare_lengths(p1.data(), q1.data(), p2.data(), q2.data()), ref) << what;
    ASSERT_EQ(pr::compare_lengths(q2.data(), p2.data(), p1.data(), q1.data()), -ref) << what;
    ++count.cases;
    if (const auto f = pr::compare_lengths_filter(p1.data(), q1.data(), p2.data(), q2.data())) {
        ++count.answered;
        ASSERT_EQ(*f, ref) << what;
    }
}

void check_dots(const P2& o, const P2& p, const P2& q, const P2& r, FilterCount& corner,
                FilterCount& direction, const char* what) {
    // corner_dot_sign(o, p, q) = (p - o) . (q - o); direction_dot_sign(o, p, q, r) = (p - o) . (r -
    // q).
    const Sign ref_corner = pr::reference::dot_sign(o.data(), p.data(), o.data(), q.data());
    ASSERT_EQ(pr::corner_dot_sign(o.data(), p.data(), q.data()), ref_corner) << what;
    ++corner.cases;
    if (const auto f = pr::corner_dot_sign_filter(o.data(), p.data(), q.data())) {
        ++corner.answered;
        ASSERT_EQ(*f, ref_corner) << what;
    }
    const Sign ref_direction = pr::reference::dot_sign(o.data(), p.data(), q.data(), r.data());
    ASSERT_EQ(pr::direction_dot_sign(o.data(), p.data(), q.data(), r.data()), ref_direction)
        << what;
    ++direction.cases;
    if (const auto f = pr::direction_dot_sign_filter(o.data(), p.data(), q.data(), r.data())) {
        ++direction.answered;
        ASSERT_EQ(*f, ref_direction) << what;
    }
}

void check_within(const P2& w, const P2& s0, const P2& s1, FilterCount& count, const char* what) {
    const bool ref = pr::reference::within_rounding_of_segment(w.data(), s0.data(), s1.data());
    ASSERT_EQ(pr::within_rounding_of_segment(w.data(), s0.data(), s1.data()), ref) << what;
    ASSERT_EQ(pr::within_rounding_of_segment(w.data(), s1.data(), s0.data()), ref) << what;
    ASSERT_EQ(pr::within_rounding_of_segment_exact(w.data(), s0.data(), s1.data()), ref) << what;
    ++count.cases;
    if (const auto f = pr::within_rounding_of_segment_filter(w.data(), s0.data(), s1.data())) {
        ++count.answered;
        ASSERT_EQ(*f, ref) << what;
    }
}

}  // namespace

TEST(Predicates_AngleComparisons2d, AgreeWithGmpOnRandomAndScaledInputs) {
    Rng rng(2026);
    // counts[scale][predicate]: angles, lengths, corner dot, direction dot.
    FilterCount counts[3][4];
    for (int n = 0; n < 4000; ++n) {
        AngleCase c;
        for (P2* p : {&c.o1, &c.p1, &c.q1, &c.o2, &c.p2, &c.q2}) *p = {uniform(rng), uniform(rng)};
        if (!make_ccw(c.o1, c.p1, c.q1) || !make_ccw(c.o2, c.p2, c.q2)) continue;
        const Sign unscaled = pr::compare_angles({c.o1.data(), c.p1.data(), c.q1.data()},
                                                 {c.o2.data(), c.p2.data(), c.q2.data()});
        for (int i = 0; i < 3; ++i) {
            const AngleCase s = scaled(c, kScales[i]);
            FilterCount* f = counts[i];
            check_angles(s, f[0], "random angles");
            check_lengths(s.o1, s.p1, s.o2, s.p2, f[1], "random lengths");
            check_dots(s.o1, s.p1, s.q1, s.o2, f[2], f[3], "random dots");
            ASSERT_EQ(pr::compare_angles({s.o1.data(), s.p1.data(), s.q1.data()},
                                         {s.o2.data(), s.p2.data(), s.q2.data()}),
                      unscaled)
                << "scale 2^" << kScales[i];
        }
    }
    // The filters decide nearly every random call at scale 2^0; at 2^+-600 the differences
    // leave their window and the filters abstain (the exact stages decide, as checked above).
    for (const FilterCount& f : counts[0]) {
        EXPECT_GT(f.cases, 3000);
        EXPECT_GT(f.answered, f.cases * 99 / 100);
    }
}

TEST(Predicates_AngleComparisons2d, AgreeWithGmpOnNearDegenerateInputs) {
    Rng rng(12);
    FilterCount sink[4];
    long ties = 0;
    for (int n = 0; n < 1500; ++n) {
        // A corner and its copy turned by 90 degrees (exact): equal angles, equal lengths and
        // equal dot products; then one coordinate moved by -2..2 ulps.
        AngleCase c;
        c.o1 = {uniform(rng), uniform(rng)};
        c.p1 = {uniform(rng), uniform(rng)};
        c.q1 = {uniform(rng), uniform(rng)};
        if (!make_ccw(c.o1, c.p1, c.q1)) continue;
        auto turn = [](const P2& p) { return P2{-p[1], p[0]}; };
        c.o2 = turn(c.o1);
        c.p2 = turn(c.p1);
        c.q2 = turn(c.q1);
        const int moved = static_cast<int>(rng() % 6), by = static_cast<int>(rng() % 5) - 2;
        P2* targets[6] = {&c.o2, &c.p2, &c.q2, &c.o2, &c.p2, &c.q2};
        (*targets[moved])[moved / 3] = ulps((*targets[moved])[moved / 3], by);
        if (pr::orient2d(c.o2.data(), c.p2.data(), c.q2.data()) != Sign::Positive) continue;
        if (by == 0) ++ties;
        for (const int k : kScales) {
            const AngleCase s = scaled(c, k);
            check_angles(s, sink[0], "turned angles");
            check_lengths(s.o1, s.p1, s.o2, s.p2, sink[1], "turned lengths");
            check_dots(s.o1, s.p1, s.q1, s.o2, sink[2], sink[3], "turned dots");
        }
        if (by == 0) {
            EXPECT_EQ(pr::compare_angles({c.o1.data(), c.p1.data(), c.q1.data()},
                                         {c.o2.data(), c.p2.data(), c.q2.data()}),
                      Sign::Zero);
        }
    }
    EXPECT_GT(ties, 100);
    // A right angle at o = (1, 1) over p = (0, 0), q = (2, 0) (o on the circle with diameter pq),
    // o moved along x by a lattice step of 2^-43 i / 128: the encroachment test's boundary.
    for (int i = -64; i <= 64; ++i) {
        const P2 p{0.0, 0.0}, q{2.0, 0.0}, o{1.0 + std::ldexp(i, -50), 1.0};
        check_dots(o, p, q, p, sink[2], sink[3], "diametral circle");
        if (i == 0) {
            EXPECT_EQ(pr::corner_dot_sign(o.data(), p.data(), q.data()), Sign::Zero);
        }
    }
    // Dot products whose differences span 1e-225..1e212: direction_dot_sign's long double stage.
    for (int n = 0; n < 500; ++n) {
        const P2 o{uniform(rng) * 1e-225, uniform(rng) * 1e-225};
        const P2 p{uniform(rng) * 1e-225, uniform(rng) * 1e212};
        const P2 q{uniform(rng) * 1e212, uniform(rng)};
        const P2 r{ulps(q[0], 1), q[1] + uniform(rng) * 1e-200};
        check_dots(o, p, q, r, sink[2], sink[3], "wide span");
    }
}

TEST(Predicates_WithinRounding, AgreesWithGmpNearTheSquaresBoundary) {
    Rng rng(99);
    FilterCount at_scale[3];
    for (int n = 0; n < 3000; ++n) {
        const P2 s0{uniform(rng), uniform(rng)}, s1{uniform(rng), uniform(rng)};
        // A point of the segment, moved perpendicular by about the half-width (2^-40 |w|) or
        // by a random amount, and sometimes beyond an end.
        const double r = uniform(rng, -0.01, 1.01);
        P2 w{s0[0] + r * (s1[0] - s0[0]), s0[1] + r * (s1[1] - s0[1])};
        const double h = std::ldexp(std::max(std::fabs(w[0]), std::fabs(w[1])), -40);
        const double off = (n % 3 == 0) ? uniform(rng) * 1e-3 : h * uniform(rng, 0.5, 2.0);
        const double dx = s1[0] - s0[0], dy = s1[1] - s0[1], len = std::hypot(dx, dy);
        w = {w[0] - off * dy / len, w[1] + off * dx / len};
        for (int i = 0; i < 3; ++i) {
            check_within(scaled(w, kScales[i]), scaled(s0, kScales[i]), scaled(s1, kScales[i]),
                         at_scale[i], "near the square");
            ASSERT_EQ(pr::within_rounding_of_segment(scaled(w, kScales[i]).data(),
                                                     scaled(s0, kScales[i]).data(),
                                                     scaled(s1, kScales[i]).data()),
                      pr::within_rounding_of_segment(w.data(), s0.data(), s1.data()));
        }
    }
    // The long double filter decides all but the closest calls, at every scale.
    for (const FilterCount& f : at_scale) EXPECT_GT(f.answered, f.cases * 95 / 100);
}

TEST(Predicates_WithinRounding, ExactStageAgreesWithGmpWhereTheFilterCannotDecide) {
    // A vertex w far smaller than the segment's ends, a few ulps off the segment through it
    // (a crossing or split point near the origin): the half-width 2^-40 |w| is far below the
    // rounding of the cross product's terms, so the filter gives up and the exact stage
    // decides; coordinates from 1e-300 to 1e300, subnormal half-widths included.
    Rng rng(7);
    FilterCount count;
    int inside = 0, outside = 0;  // decided by the exact stage
    for (int n = 0; n < 4000; ++n) {
        const double big = std::ldexp(1.0, static_cast<int>(uniform(rng, -990, 990)));
        const double small = big * std::ldexp(1.0, -static_cast<int>(uniform(rng, 20, 900)));
        // s1 a power-of-two multiple of -s0: the segment's line passes through the origin.
        const P2 s0{-big * uniform(rng, 0.5, 1), -big * uniform(rng, 0.5, 1)};
        const double k = std::ldexp(1.0, static_cast<int>(uniform(rng, -3, 3)));
        const P2 s1{-k * s0[0], -k * s0[1]};
        // The point s0 r (r about small / big, either sign) rounded, then nudged a few ulps.
        const double r = uniform(rng, -1, 1) * small / big;
        P2 w{s0[0] * r, s0[1] * r};
        const int ulps = static_cast<int>(uniform(rng, -3, 4));
        for (int i = 0; i < std::abs(ulps); ++i)
            w[1] = std::nextafter(w[1], ulps > 0 ? HUGE_VAL : -HUGE_VAL);
        if (ulps == 0) w[1] = w[1] + std::fabs(w[1]) * std::ldexp(1.0, -39);
        check_within(w, s0, s1, count, "near the origin on a long segment");
        const bool within = pr::within_rounding_of_segment(w.data(), s0.data(), s1.data());
        (within ? inside : outside) +=
            pr::within_rounding_of_segment_filter(w.data(), s0.data(), s1.data()) ? 0 : 1;
    }
    // The exact stage decided both ways.
    EXPECT_GT(inside, 100) << count.answered << " of " << count.cases << " by the filter";
    EXPECT_GT(outside, 100) << count.answered << " of " << count.cases << " by the filter";
}

namespace {

using Tet = std::array<P3, 4>;

std::array<const double*, 4> corners(const Tet& t) {
    return {t[0].data(), t[1].data(), t[2].data(), t[3].data()};
}

Tet scaled(const Tet& t, int k) {
    return {scaled(t[0], k), scaled(t[1], k), scaled(t[2], k), scaled(t[3], k)};
}

/// A random positively oriented tetrahedron (orient3d > 0, the convention of TetMesh3).
Tet random_tet(Rng& rng) {
    for (;;) {
        Tet t;
        for (P3& p : t) p = {uniform(rng), uniform(rng), uniform(rng)};
        const Sign s = pr::orient3d(t[0].data(), t[1].data(), t[2].data(), t[3].data());
        if (s == Sign::Zero) continue;
        if (s == Sign::Negative) std::swap(t[0], t[1]);
        return t;
    }
}

/// Pulls corner 0 toward the opposite face by 2^-(n % 40) (angles near 0 and 180 degrees);
/// false when that made the tetrahedron flat.
bool flatten(Tet& t, int n) {
    const double f = std::ldexp(1.0, -(n % 40));
    for (int k = 0; k < 3; ++k)
        t[0][k] = t[1][k] + f * (t[0][k] - t[1][k]) + (1 - f) * ((t[2][k] + t[3][k]) / 2 - t[1][k]);
    return pr::orient3d(t[0].data(), t[1].data(), t[2].data(), t[3].data()) != Sign::Zero;
}

}  // namespace

TEST(Predicates_AngleComparisons3d, AgreeWithGmpOnRandomTurnedAndScaledTetrahedra) {
    Rng rng(3);
    FilterCount dihedral[3], quality[3];
    for (int n = 0; n < 300; ++n) {
        const Tet a = random_tet(rng);
        Tet b = random_tet(rng);
        if (n % 2 == 1) {
            // b: a turned by 90 degrees about z (exact), one coordinate moved by an ulp or not.
            for (int v = 0; v < 4; ++v) b[v] = {-a[v][1], a[v][0], a[v][2]};
            b[n % 4][n % 3] = ulps(b[n % 4][n % 3], static_cast<int>(n % 3) - 1);
            if (pr::orient3d(b[0].data(), b[1].data(), b[2].data(), b[3].data()) != Sign::Positive)
                continue;
        }
        const unsigned i = static_cast<unsigned>(n % 4),
                       j = static_cast<unsigned>((n / 4 + 1 + n % 4) % 4);
        if (i == j) continue;
        for (int s = 0; s < 3; ++s) {
            const Tet as = scaled(a, kScales[s]), bs = scaled(b, kScales[s]);
            const auto ca = corners(as), cb = corners(bs);
            const Sign ref = pr::reference::compare_dihedral(ca.data(), i, j, cb.data(), i, j);
            const pr::Dihedral x{ca, i, j}, y{cb, i, j};
            ASSERT_EQ(pr::compare_dihedral(x, y), ref) << n << " scale " << kScales[s];
            ++dihedral[s].cases;
            if (const auto f = pr::compare_dihedral_filter(x, y)) {
                ++dihedral[s].answered;
                ASSERT_EQ(*f, ref);
            }
            const Sign qref = pr::reference::compare_volume_edge(ca.data(), cb.data());
            ASSERT_EQ(pr::compare_volume_edge(ca, cb), qref) << n << " scale " << kScales[s];
            ++quality[s].cases;
            if (const auto f = pr::compare_volume_edge_filter(ca, cb)) {
                ++quality[s].answered;
                ASSERT_EQ(*f, qref);
            }
        }
    }
    // The long double filter decides the random (odd: nearly tied) calls at 2^0 and abstains
    // outside its window (2^600).
    EXPECT_GT(dihedral[0].answered, dihedral[0].cases / 2);
    EXPECT_GT(quality[0].answered, quality[0].cases / 2);
    EXPECT_EQ(dihedral[1].answered, 0);
}

TEST(Predicates_AngleComparisons3d, DihedralsOfLatticeTetrahedraAgreeWithGmp) {
    // Tetrahedra on a small integer lattice (their dihedral angles tie: 90, 60, 45 degrees),
    // translated (exact), one coordinate sometimes moved by an ulp, at 2^0, 2^600 and 2^-600:
    // the small-integer stage and, beyond its range, GMP, against the rational reference.
    Rng rng(11);
    std::uniform_int_distribution<int> small(-3, 3), wide(-40, 40);
    int ties = 0, cases = 0;
    auto lattice_tet = [&](bool widely) {
        for (;;) {
            Tet t;
            for (P3& p : t) {
                for (double& x : p) x = double(widely ? wide(rng) : small(rng)) + 512;
            }
            const Sign s = pr::orient3d(t[0].data(), t[1].data(), t[2].data(), t[3].data());
            if (s == Sign::Zero) continue;
            if (s == Sign::Negative) std::swap(t[0], t[1]);
            return t;
        }
    };
    for (int n = 0; n < 400; ++n) {
        const Tet a = lattice_tet(n % 5 == 4);
        Tet b = n % 3 == 0 ? a : lattice_tet(false);
        if (n % 7 == 6) {
            b[n % 4][n % 3] = ulps(b[n % 4][n % 3], 1);
            if (pr::orient3d(b[0].data(), b[1].data(), b[2].data(), b[3].data()) != Sign::Positive)
                continue;
        }
        for (unsigned e = 0; e < 6; ++e) {
            const unsigned i = e < 3 ? 0 : (e < 5 ? 1 : 2), j = e < 3 ? e + 1 : (e < 5 ? e - 1 : 3);
            const unsigned f = (e + static_cast<unsigned>(n)) % 6;
            const unsigned k = f < 3 ? 0 : (f < 5 ? 1 : 2), l = f < 3 ? f + 1 : (f < 5 ? f - 1 : 3);
            for (const int scale : {0, 600, -600}) {
                const Tet as = scaled(a, scale), bs = scaled(b, scale);
                const auto ca = corners(as), cb = corners(bs);
                const Sign ref = pr::reference::compare_dihedral(ca.data(), i, j, cb.data(), k, l);
                ASSERT_EQ(pr::compare_dihedral({ca, i, j}, {cb, k, l}), ref)
                    << n << " edge " << e << " scale " << scale;
                ties += ref == Sign::Zero;
                ++cases;
            }
        }
    }
    EXPECT_GT(ties, cases / 20);
}

TEST(Predicates_TriangleArea, AgreesWithGmpOnRandomTiedAndScaledInputs) {
    Rng rng(5);
    for (int n = 0; n < 3000; ++n) {
        const P2 a{uniform(rng), uniform(rng)}, b{uniform(rng), uniform(rng)},
            c{uniform(rng), uniform(rng)};
        // Random areas, and the area rounded from the determinant (a near tie), moved by ulps.
        double area = uniform(rng);
        if (n % 2 == 1) {
            area = ulps(0.5 * pr::orient2d_fast(a.data(), b.data(), c.data()),
                        static_cast<int>(rng() % 5) - 2);
        }
        const Sign ref = pr::reference::triangle_area_sign(a.data(), b.data(), c.data(), area);
        // The area scales by 2^(2k): coordinates by 2^+-300 keep it finite and normal.
        for (const int k : {0, 300, -300}) {
            const P2 as = scaled(a, k), bs = scaled(b, k), cs = scaled(c, k);
            ASSERT_EQ(
                pr::triangle_area_sign(as.data(), bs.data(), cs.data(), std::ldexp(area, 2 * k)),
                ref)
                << n << " scale " << k;
        }
        // Coordinates by 2^+-600 against areas at the ends of the double range.
        for (const int k : {600, -600}) {
            const P2 as = scaled(a, k), bs = scaled(b, k), cs = scaled(c, k);
            for (const double bound : {0.0, 0x1p-1074, -0x1p-1074, DBL_MAX, -DBL_MAX}) {
                ASSERT_EQ(pr::triangle_area_sign(as.data(), bs.data(), cs.data(), bound),
                          pr::reference::triangle_area_sign(as.data(), bs.data(), cs.data(), bound))
                    << n << " scale " << k << " area " << bound;
            }
        }
    }
    // Integer triangles: exact ties.
    const P2 a{0, 0}, b{4, 0}, c{0, 3};
    EXPECT_EQ(pr::triangle_area_sign(a.data(), b.data(), c.data(), 6.0), Sign::Zero);
    EXPECT_EQ(pr::triangle_area_sign(a.data(), b.data(), c.data(), ulps(6.0, 1)), Sign::Negative);
    EXPECT_EQ(pr::triangle_area_sign(a.data(), b.data(), c.data(), ulps(6.0, -1)), Sign::Positive);
}

TEST(Predicates_AngleComparisons3d, SmallestAndEveryDihedralAgreeWithGmp) {
    // smallest_dihedral and every_dihedral_compares (the six angles' filter terms from the face
    // area vectors, the bound's cached) against the rational reference, on lattice tetrahedra
    // (ties), random ones and slivers, at 2^0, 2^600 and 2^-600.
    Rng rng(13);
    std::uniform_int_distribution<int> small(-3, 3);
    auto tet = [&](int n) {
        if (n % 4 == 2) {
            // A sliver: corner 3 moved to within a few ulps of the plane of the other three
            // (the filters abstain on its small and large angles).
            Tet t = random_tet(rng);
            const double w = 0.25 + 0.5 * std::ldexp(double(rng() % 1024), -10);
            for (std::size_t i = 0; i < 3; ++i)
                t[3][i] = w * t[0][i] + (0.75 - w) * t[1][i] + 0.25 * t[2][i] +
                          std::ldexp(double(small(rng)), -50);
            const Sign s = pr::orient3d(t[0].data(), t[1].data(), t[2].data(), t[3].data());
            if (s == Sign::Negative) std::swap(t[0], t[1]);
            if (s != Sign::Zero) return t;
        }
        if (n % 2 == 0) return random_tet(rng);
        for (;;) {
            Tet t;
            for (P3& p : t) {
                for (double& x : p) x = double(small(rng)) + 64;
            }
            const Sign s = pr::orient3d(t[0].data(), t[1].data(), t[2].data(), t[3].data());
            if (s == Sign::Zero) continue;
            if (s == Sign::Negative) std::swap(t[0], t[1]);
            return t;
        }
    };
    constexpr unsigned kEdges[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
    int all_true = 0, all_false = 0;
    for (int n = 0; n < 300; ++n) {
        const Tet a = tet(n), b = tet(n / 2);
        const unsigned be = static_cast<unsigned>(n) % 6;
        for (const int scale : {0, 600, -600}) {
            const Tet as = scaled(a, scale), bs = scaled(b, scale);
            const auto ca = corners(as), cb = corners(bs);
            // The smallest: no angle below it, and none tied with it before it.
            const pr::Dihedral smallest = pr::smallest_dihedral(ca);
            unsigned at = 6;
            for (unsigned e = 0; e < 6; ++e) {
                if (kEdges[e][0] == smallest.i && kEdges[e][1] == smallest.j) at = e;
            }
            ASSERT_LT(at, 6u);
            for (unsigned e = 0; e < 6; ++e) {
                const Sign s = pr::reference::compare_dihedral(
                    ca.data(), kEdges[e][0], kEdges[e][1], ca.data(), smallest.i, smallest.j);
                ASSERT_NE(s, Sign::Negative) << n << " scale " << scale;
                if (e < at) {
                    ASSERT_EQ(s, Sign::Positive) << n << " scale " << scale;
                }
            }
            // Every angle of a against an angle of b.
            const pr::Dihedral bound{cb, kEdges[be][0], kEdges[be][1]};
            for (const Sign wanted : {Sign::Positive, Sign::Negative}) {
                bool expected = true;
                for (unsigned e = 0; e < 6; ++e) {
                    expected = expected && pr::reference::compare_dihedral(
                                               ca.data(), kEdges[e][0], kEdges[e][1], cb.data(),
                                               bound.i, bound.j) == wanted;
                }
                ASSERT_EQ(pr::every_dihedral_compares(ca, bound, wanted), expected)
                    << n << " scale " << scale;
                (expected ? all_true : all_false) += 1;
            }
        }
    }
    EXPECT_GT(all_true, 0);
    EXPECT_GT(all_false, 0);
}

TEST(Predicates_AngleComparisons3d, SmallestDihedralRoundedIsWithinRoundingOfTheSmallest) {
    // smallest_dihedral_rounded picks an angle of the tetrahedron that is the exact smallest
    // (smallest_dihedral) or within rounding of it, the same edge at every scale, on random and
    // flattened tetrahedra (angles near 0 and 180 degrees); its cosine is the picked angle's.
    Rng rng(23);
    int exact_picks = 0, cases = 0;
    for (int n = 0; n < 2000; ++n) {
        Tet t = random_tet(rng);
        if (n % 2 == 1 && !flatten(t, n)) continue;
        const auto c = corners(t);
        double cosine = 0;
        const pr::Dihedral pick = pr::smallest_dihedral_rounded(c, &cosine);
        const pr::Dihedral smallest = pr::smallest_dihedral(c);
        ++cases;
        ASSERT_NE(pick.i, pick.j);
        const long double picked = pr::dihedral_radians(pick);
        const long double least = pr::dihedral_radians(smallest);
        ASSERT_LE(std::fabs(picked - least), 1e-6L * (1 + least)) << n;
        ASSERT_NEAR(std::acos(std::clamp(cosine, -1.0, 1.0)), static_cast<double>(picked),
                    1e-6 * (1 + static_cast<double>(picked)))
            << n;
        if (pr::compare_dihedral(pick, smallest) == Sign::Zero) ++exact_picks;
        for (const int s : kScales) {
            const pr::Dihedral scaled_pick = pr::smallest_dihedral_rounded(corners(scaled(t, s)));
            ASSERT_EQ(scaled_pick.i, pick.i) << n << " scale " << s;
            ASSERT_EQ(scaled_pick.j, pick.j) << n << " scale " << s;
        }
    }
    EXPECT_GT(exact_picks, cases * 9 / 10);
}

TEST(Predicates_AngleComparisons3d, DihedralBelowRoundedAgreesWithTheAngleAndScales) {
    // (and any_dihedral_below_rounded with the smallest of the six)
    // dihedral_below_rounded(a, cos^2 T) against dihedral_radians(a) < T, away from T (both
    // round), on random tetrahedra and flattened ones (a corner pulled toward the opposite
    // face: angles near 0 and 180 degrees); the same answer at every scale.
    Rng rng(17);
    int below = 0, cases = 0, any_below = 0, any_cases = 0;
    for (const double degrees : {5.0, 15.0, 40.0, 80.0}) {
        const long double threshold =
            static_cast<long double>(degrees) * 3.14159265358979323846L / 180;
        const long double cos_squared = std::cos(threshold) * std::cos(threshold);
        for (int n = 0; n < 400; ++n) {
            Tet t = random_tet(rng);
            if (n % 2 == 1 && !flatten(t, n)) continue;
            // any_dihedral_below_rounded against the smallest angle, away from T.
            long double smallest = 10;
            for (unsigned i = 0; i < 4; ++i)
                for (unsigned j = i + 1; j < 4; ++j)
                    smallest = std::min(smallest, pr::dihedral_radians({corners(t), i, j}));
            const bool any = pr::any_dihedral_below_rounded(corners(t), cos_squared);
            if (std::fabs(smallest - threshold) > 1e-9L) {
                ASSERT_EQ(any, smallest < threshold) << n << " " << degrees;
                ++any_cases;
                any_below += any ? 1 : 0;
            }
            for (const int s : kScales)
                ASSERT_EQ(pr::any_dihedral_below_rounded(corners(scaled(t, s)), cos_squared), any)
                    << n << " scale " << s;
            for (unsigned i = 0; i < 4; ++i) {
                for (unsigned j = i + 1; j < 4; ++j) {
                    const auto c = corners(t);
                    const long double angle = pr::dihedral_radians({c, i, j});
                    const bool answer = pr::dihedral_below_rounded({c, i, j}, cos_squared);
                    if (std::fabs(angle - threshold) > 1e-12L) {
                        ASSERT_EQ(answer, angle < threshold) << n << " " << degrees;
                        ++cases;
                        below += answer ? 1 : 0;
                    }
                    for (const int s : kScales) {
                        const Tet ts = scaled(t, s);
                        ASSERT_EQ(pr::dihedral_below_rounded({corners(ts), i, j}, cos_squared),
                                  answer)
                            << n << " scale " << s;
                    }
                }
            }
        }
    }
    EXPECT_GT(below, cases / 20);
    EXPECT_LT(below, cases - cases / 20);
    EXPECT_GT(any_below, any_cases / 20);
    EXPECT_LT(any_below, any_cases - any_cases / 20);
}
