// SPDX-License-Identifier: MIT
// The 4 x 1000 sign fixtures of robust-predicates (originally Nanevski et al. 2001), stored in
// ../shared/corpus/predicates/ (format and provenance: ../shared/corpus/README.md). Shewchuk's
// conventions throughout, so the expected sign is compared directly for all four predicates.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "predicates/exact_reference.hpp"
#include "predicates/incircle.hpp"
#include "predicates/insphere.hpp"
#include "predicates/orient2d.hpp"
#include "predicates/orient3d.hpp"
#include "tests/support/predicate_calls.hpp"

namespace pr = exactmesh::predicates;
using pr::Sign;

namespace {

struct Fixture {
    int line = 0;
    std::vector<double> coordinates;
    Sign expected = Sign::Zero;
};

std::filesystem::path corpus_directory() {
#if defined(EXACTMESH_CORPUS_DIR)
    return std::filesystem::path(EXACTMESH_CORPUS_DIR) / "predicates";
#else
    return {};
#endif
}

/// Reads `<name>.txt`: lines `index coords... expected_sign`, `coordinates` numbers each.
/// Reports a fatal failure (and returns nothing) when the corpus is missing or malformed.
std::vector<Fixture> load(const std::string& name, std::size_t coordinates) {
    const std::filesystem::path dir = corpus_directory();
    const std::filesystem::path file = dir / (name + ".txt");
    if (dir.empty() || !std::filesystem::is_regular_file(file)) {
        ADD_FAILURE() << "predicate corpus not found: " << file
                      << " (EXACTMESH_CORPUS_DIR must name ../shared/corpus; see its README.md)";
        return {};
    }
    std::ifstream in(file);
    std::vector<Fixture> fixtures;
    std::string text;
    int line = 0;
    while (std::getline(in, text)) {
        ++line;
        if (text.empty()) continue;
        std::istringstream fields(text);
        std::vector<std::string> tokens;
        for (std::string token; fields >> token;) tokens.push_back(token);
        if (tokens.size() != coordinates + 2) {
            ADD_FAILURE() << file << ":" << line << ": expected " << coordinates + 2
                          << " fields, got " << tokens.size();
            return {};
        }
        Fixture f;
        f.line = line;
        for (std::size_t i = 1; i <= coordinates; ++i) {
            // strtod rounds correctly, and the files hold 17 significant digits: exact doubles.
            f.coordinates.push_back(std::strtod(tokens[i].c_str(), nullptr));
        }
        const int sign = std::atoi(tokens.back().c_str());
        f.expected = sign > 0 ? Sign::Positive : (sign < 0 ? Sign::Negative : Sign::Zero);
        fixtures.push_back(f);
    }
    return fixtures;
}

struct Outcome {
    int cases = 0;
    int adaptive_wrong = 0, exact_wrong = 0, filter_wrong = 0, reference_wrong = 0;
    int fast_wrong = 0;
    std::string first_failures;
};

/// Runs every fixture through the adaptive predicate, _exact, the filter, the GMP reference and
/// the plain double baseline. `call` maps the coordinates to the five results.
template <class Call>
Outcome run(const std::vector<Fixture>& fixtures, Call call) {
    Outcome out;
    for (const Fixture& f : fixtures) {
        ++out.cases;
        const auto r = call(f.coordinates.data());
        auto note = [&](int& counter, const char* what, Sign got) {
            ++counter;
            if (out.first_failures.size() < 2000) {
                out.first_failures += "line " + std::to_string(f.line) + ": " + what + " gave " +
                                      std::to_string(pr::to_int(got)) + ", expected " +
                                      std::to_string(pr::to_int(f.expected)) + "\n";
            }
        };
        if (r.adaptive != f.expected) note(out.adaptive_wrong, "adaptive", r.adaptive);
        if (r.exact != f.expected) note(out.exact_wrong, "exact", r.exact);
        if (r.filter && *r.filter != f.expected) note(out.filter_wrong, "filter", *r.filter);
        if (r.reference != f.expected) note(out.reference_wrong, "reference", r.reference);
        if (pr::sign_of(r.fast) != f.expected) ++out.fast_wrong;
    }
    return out;
}

struct Results {
    Sign adaptive, exact;
    std::optional<Sign> filter;
    Sign reference;
    double fast;
};

void expect_all_pass(const char* name, const Outcome& out) {
    EXPECT_EQ(out.cases, 1000) << name << ": the corpus has 1000 lines per predicate";
    EXPECT_EQ(out.adaptive_wrong, 0) << name << "\n" << out.first_failures;
    EXPECT_EQ(out.exact_wrong, 0) << name << "\n" << out.first_failures;
    EXPECT_EQ(out.filter_wrong, 0) << name << "\n" << out.first_failures;
    EXPECT_EQ(out.reference_wrong, 0) << name << "\n" << out.first_failures;
}

/// The corpus of the predicate `name` of N points in D dimensions through every stage (as
/// EM_TEST_STAGES lists them).
template <std::size_t N, std::size_t D, auto Adaptive, auto Exact, auto Filter, auto Reference,
          auto /*ReferenceDifferences*/, auto Fast>
Outcome run_predicate(const std::string& name) {
    return run(load(name, N * D), [](const double* x) {
        using exactmesh::testing::call_on_flat;
        return Results{call_on_flat<N, D>(Adaptive, x), call_on_flat<N, D>(Exact, x),
                       call_on_flat<N, D>(Filter, x), call_on_flat<N, D>(Reference, x),
                       call_on_flat<N, D>(Fast, x)};
    });
}

Outcome run_orient2d() {
    return run_predicate<3, 2, EM_TEST_STAGES(orient2d)>("orient2d");
}

Outcome run_incircle() {
    return run_predicate<4, 2, EM_TEST_STAGES(incircle)>("incircle");
}

Outcome run_orient3d() {
    return run_predicate<4, 3, EM_TEST_STAGES(orient3d)>("orient3d");
}

Outcome run_insphere() {
    return run_predicate<5, 3, EM_TEST_STAGES(insphere)>("insphere");
}

}  // namespace

TEST(Predicates_Corpus, CorpusDirectoryIsPresent) {
    const std::filesystem::path dir = corpus_directory();
    ASSERT_FALSE(dir.empty()) << "EXACTMESH_CORPUS_DIR is not defined for this test";
    ASSERT_TRUE(std::filesystem::is_directory(dir))
        << "predicate corpus directory missing: " << dir
        << " (expected ../shared/corpus/predicates beside the repository)";
    for (const char* name : {"orient2d", "incircle", "orient3d", "insphere"}) {
        EXPECT_TRUE(std::filesystem::is_regular_file(dir / (std::string(name) + ".txt")))
            << "missing " << dir / (std::string(name) + ".txt");
    }
}

TEST(Predicates_Corpus, Orient2dMatchesAllFixtures) {
    expect_all_pass("orient2d", run_orient2d());
}

TEST(Predicates_Corpus, IncircleMatchesAllFixtures) {
    expect_all_pass("incircle", run_incircle());
}

TEST(Predicates_Corpus, Orient3dMatchesAllFixtures) {
    expect_all_pass("orient3d", run_orient3d());
}

TEST(Predicates_Corpus, InsphereMatchesAllFixtures) {
    expect_all_pass("insphere", run_insphere());
}

// The corpus README says a plain double evaluation gets 2 / 38 / 4 / 31 of the signs wrong: the
// fixtures are hard enough to catch a non-robust predicate. The _fast functions are that baseline.
TEST(Predicates_Corpus, PlainDoubleBaselineGetsTheDocumentedCasesWrong) {
    EXPECT_EQ(run_orient2d().fast_wrong, 2);
    EXPECT_EQ(run_incircle().fast_wrong, 38);
    EXPECT_EQ(run_orient3d().fast_wrong, 4);
    EXPECT_EQ(run_insphere().fast_wrong, 31);
}
