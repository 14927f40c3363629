// SPDX-License-Identifier: MIT
// Tests of base/enum_names.hpp: name <-> value through one table, and the name/parse functions
// built on it keep the names and the error messages they had as switch statements (issue 12).
#include "base/enum_names.hpp"

#include <gtest/gtest.h>

#include <array>
#include <string>
#include <string_view>
#include <utility>

#include "generators/boundary/sample_domains.hpp"
#include "generators/mesh_2d/mesh_generators_2d.hpp"
#include "tests/support/error_message.hpp"
#include "triangulation/constrained/constrained_2d.hpp"
#include "triangulation/modification/edge_face_swap_3d.hpp"
#include "triangulation/modification/edge_swap_2d.hpp"

namespace gen = exactmesh::generators;
namespace tri = exactmesh::triangulation;

namespace {

enum class Colour { Red, Green, Blue, Unnamed };

constexpr std::array<exactmesh::EnumName<Colour>, 3> kColours{{
    {"red", Colour::Red},
    {"green", Colour::Green},
    {"blue", Colour::Blue},
}};

/// Expects `parse` to throw an InputError saying exactly `message`.
template <class Parse>
void expect_input_error(Parse parse, std::string_view message) {
    EXPECT_EQ(exactmesh::testing::error_message<exactmesh::InputError>(parse), message);
}

}  // namespace

TEST(EnumNames, NameAndParseReadTheSameTable) {
    static_assert(exactmesh::name_of(kColours, Colour::Green) == "green");
    static_assert(exactmesh::name_of(kColours, Colour::Unnamed) == "?");
    static_assert(exactmesh::name_of(kColours, Colour::Unnamed, "unknown") == "unknown");
    static_assert(exactmesh::find_name(kColours, "blue") == Colour::Blue);
    static_assert(!exactmesh::find_name(kColours, "Blue").has_value());
    for (const auto& row : kColours) {
        EXPECT_EQ(exactmesh::parse_name(kColours, row.name, "colour"), row.value);
        EXPECT_EQ(exactmesh::name_of(kColours, row.value), row.name);
    }
}

TEST(EnumNames, ErrorListsTheKnownNamesInTableOrder) {
    EXPECT_EQ(exactmesh::known_names(kColours), "red, green, blue");
    EXPECT_EQ(exactmesh::known_names(kColours, " or "), "red, green or blue");
    expect_input_error([] { exactmesh::parse_name(kColours, "mauve", "colour"); },
                       "unknown colour 'mauve' (known: red, green, blue)");
    expect_input_error([] { exactmesh::parse_name(kColours, "", "colour"); },
                       "unknown colour '' (known: red, green, blue)");
}

// The messages below are the ones the hand-written parse functions threw.
TEST(EnumNames, SampleDomainsKeepTheirNamesAndMessage) {
    const std::array<std::string_view, 4> names{"square-with-holes", "naca0012", "key",
                                                "three-element"};
    for (std::size_t i = 0; i < names.size(); ++i) {
        EXPECT_EQ(gen::sample_domain_name(gen::kAllSampleDomains[i]), names[i]);
        EXPECT_EQ(gen::sample_domain_from_name(names[i]), gen::kAllSampleDomains[i]);
    }
    expect_input_error(
        [] { gen::sample_domain_from_name("moon"); },
        "unknown domain 'moon' (known: square-with-holes, naca0012, key, three-element)");
}

TEST(EnumNames, SegmentRecoveryKeepsItsNamesAndMessage) {
    EXPECT_STREQ(tri::segment_recovery_name(tri::SegmentRecovery::Swap), "swap");
    EXPECT_STREQ(tri::segment_recovery_name(tri::SegmentRecovery::Cavity), "cavity");
    EXPECT_STREQ(tri::segment_recovery_name(tri::SegmentRecovery::Conforming), "conforming");
    EXPECT_EQ(tri::segment_recovery_from_name("swap"), tri::SegmentRecovery::Swap);
    EXPECT_EQ(tri::segment_recovery_from_name("cavity"), tri::SegmentRecovery::Cavity);
    EXPECT_EQ(tri::segment_recovery_from_name("conforming"), tri::SegmentRecovery::Conforming);
    expect_input_error([] { tri::segment_recovery_from_name("flip"); },
                       "unknown segment recovery 'flip' (expected swap, cavity or conforming)");
}

TEST(EnumNames, SwapCriteriaKeepTheirNamesAndMessages) {
    const std::array<std::pair<std::string_view, tri::SwapCriterion3>, 4> criteria3{{
        {"delaunay", tri::SwapCriterion3::Delaunay},
        {"max-min-dihedral", tri::SwapCriterion3::MaxMinDihedral},
        {"min-max-dihedral", tri::SwapCriterion3::MinMaxDihedral},
        {"volume-edge", tri::SwapCriterion3::VolumeEdge},
    }};
    for (const auto& [name, criterion] : criteria3) {
        EXPECT_EQ(tri::swap_criterion_3d_name(criterion), name);
        EXPECT_EQ(tri::swap_criterion_3d_from_name(name), criterion);
    }
    expect_input_error([] { tri::swap_criterion_3d_from_name("x"); },
                       "unknown 3D swap criterion 'x' (known: delaunay, max-min-dihedral, "
                       "min-max-dihedral, volume-edge)");
    EXPECT_EQ(tri::swap_criterion_from_name("delaunay"), tri::SwapCriterion::Delaunay);
    EXPECT_EQ(tri::swap_criterion_from_name("max-min-angle"), tri::SwapCriterion::MaxMinAngle);
    EXPECT_EQ(tri::swap_criterion_from_name("min-max-angle"), tri::SwapCriterion::MinMaxAngle);
    EXPECT_EQ(tri::swap_criterion_from_name("min-length"), tri::SwapCriterion::MinTotalLength);
    EXPECT_EQ(tri::swap_criterion_from_name("data-dependent"), tri::SwapCriterion::DataDependent);
    expect_input_error([] { tri::swap_criterion_from_name("x"); },
                       "unknown swap criterion 'x' (known: delaunay, max-min-angle, min-max-angle, "
                       "min-length, data-dependent)");
}

TEST(EnumNames, MeshOptionsKeepTheirNames) {
    EXPECT_EQ(gen::mesh_option_name(gen::MeshOption::Size), "--size");
    EXPECT_EQ(gen::mesh_option_name(gen::MeshOption::MinAngle), "--min-angle");
    EXPECT_EQ(gen::mesh_option_name(gen::MeshOption::PolishAngle), "--polish-angle");
    EXPECT_EQ(gen::mesh_option_name(gen::MeshOption::MaxSteinerPoints), "--max-steiner");
    EXPECT_EQ(gen::mesh_option_name(gen::MeshOption::RegionAttributes), "regional attributes");
    EXPECT_EQ(gen::mesh_option_name(gen::MeshOption::RegionAreas), "region maximum areas");
}
