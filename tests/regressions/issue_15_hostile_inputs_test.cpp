// SPDX-License-Identifier: MIT
// Issue 15, hostile inputs of 3D meshing (library level; tests/cli/cli_test.sh's
// tetmesh_bad_input checks the command's messages): a facet's line in the PLC checks' messages,
// and the built-in domains' surface sampling refused at once when it is NaN, infinite or asks
// for more than 10^6 surface vertices (1e-300 made static_cast<int> of 1.6e300: undefined, in
// practice an octahedron; 0.001 sampled 10^7 vertices for minutes).
#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "base/errors.hpp"
#include "generators/boundary_3d/sample_domains_3d.hpp"
#include "io/plc_format.hpp"
#include "tests/support/error_message.hpp"
#include "triangulation/recovery_3d/plc_3d.hpp"

namespace {

namespace gen = exactmesh::generators;
namespace io = exactmesh::io;
namespace tri = exactmesh::triangulation;
using exactmesh::InputError;
using exactmesh::testing::error_message;

// The unit cube; the facet on line 15 has its third corner lifted off its plane when `bent`.
std::string cube_off(bool bent) {
    return std::string("OFF\n8 6 0\n0 0 0\n1 0 0\n1 1 ") + (bent ? "0.125" : "0") +
           "\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
           "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n";
}

TEST(Issue15, PlcCheckMessagesNameTheFacetsLine) {
    const tri::Plc3 flat = io::plc_from_file(io::parse_off(cube_off(false), "cube.off"));
    ASSERT_EQ(flat.facet_origin.size(), 6u);
    EXPECT_EQ(flat.facet_origin[0], 11u);
    EXPECT_NO_THROW(tri::validate_plc_3d(flat));

    const tri::Plc3 bent = io::plc_from_file(io::parse_off(cube_off(true), "cube.off"));
    const std::string message =
        error_message<InputError>([&] { (void)tri::validate_plc_3d(bent); });
    // Vertex 2 (0-based, as the OFF file numbers it) is in facets 0 (line 11) and 3 (line 14).
    EXPECT_NE(message.find("facet 0 (line 11) is not planar"), std::string::npos) << message;

    // A PLC built in code has no lines: the message names the facet only.
    tri::Plc3 code = bent;
    code.facet_origin.clear();
    const std::string plain = error_message<InputError>([&] { (void)tri::validate_plc_3d(code); });
    EXPECT_NE(plain.find("facet 0 is not planar"), std::string::npos) << plain;
}

TEST(Issue15, BinaryStlFacetsAreNamedByTriangle) {
    // Two triangles of a binary STL: their origins are triangle numbers, not lines.
    std::string bytes(84 + 50 * 2, '\0');
    bytes[80] = 2;
    const tri::Plc3 plc = io::plc_from_file(io::parse_stl(bytes, "two.stl"));
    EXPECT_STREQ(plc.facet_origin_kind, "triangle");
    ASSERT_EQ(plc.facet_origin.size(), 2u);
    EXPECT_EQ(plc.facet_origin[1], 2u);
}

TEST(Issue15, SampleDomainSurfaceSizesAreCheckedBeforeSampling) {
    for (const double size :
         {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
        EXPECT_NE(error_message<InputError>([&] {
                      (void)gen::sample_domain_3d(gen::SampleDomain3::Ellipsoid, size);
                  }).find("must be a finite number"),
                  std::string::npos);
    }
    const std::string tiny = error_message<InputError>(
        [] { (void)gen::sample_domain_3d(gen::SampleDomain3::Ellipsoid, 1e-300); });
    EXPECT_NE(tiny.find("far more than 1e300"), std::string::npos) << tiny;
    const std::string fine = error_message<InputError>(
        [] { (void)gen::sample_domain_3d(gen::SampleDomain3::Ellipsoid, 0.001); });
    EXPECT_NE(fine.find("about 9.87e+06 surface vertices"), std::string::npos) << fine;
    const std::string wing = error_message<InputError>(
        [] { (void)gen::sample_domain_3d(gen::SampleDomain3::Wing, 1e-7); });
    EXPECT_NE(wing.find("about 4.08e+07 surface vertices"), std::string::npos) << wing;
    // Just past the bound: n = 501 subdivisions, 1,004,006 vertices; the default is sampled.
    EXPECT_NE(error_message<InputError>([] {
                  (void)gen::sample_domain_3d(gen::SampleDomain3::Ellipsoid, 0.00314);
              }).find("about 1e+06 surface vertices"),
              std::string::npos);
    EXPECT_EQ(gen::sample_domain_3d(gen::SampleDomain3::Ellipsoid, 0).vertex_count(),
              4u * 16 * 16 + 2);
}

}  // namespace
