// SPDX-License-Identifier: MIT
// Issue 11, cavity recovery: on PSLGs whose coordinates span 1e-225..1e212 a segment can cross
// the whole star of a vertex but one edge; when that edge was a piece of an earlier segment it
// lay inside the cavity and lost its constraint flag (a piece missing from the output, exit 0).
// Swap recovery was right. Both must now return the same triangles and pass the exact check.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <set>
#include <string>
#include <vector>

#include "tests/support/canonical_triangles_2d.hpp"
#include "triangulation/checks/check_constrained_2d.hpp"
#include "triangulation/constrained/constrained_2d.hpp"

namespace tri = exactmesh::triangulation;

TEST(Issue11, issue_11_cavity_dangling_piece) {
    // Segments i: vertices 2i, 2i+1 (random magnitudes 10^-225..10^212; the second input has
    // crossings, the first none).
    const std::vector<std::vector<double>> inputs = {
        {-3.0982232154626844e+150, 5.7724041369071462e-178, 4.0886637829128318e-57,
         3.4243242918686446e+85, 4.0680024128211141e+92, -5.6341475775048683e+210,
         -6.2769996205471947e-13, 5.0317422034633928e+180, 1.1294705583054272e+71,
         4.7835736715319949e+136, 4.8637681531430973e+79, 3.1810499953566162e-223},
        {-7.6460006422655469e+204, -730729.63543811196,      -8.5920943455504034e-186,
         -6.8290665987715308e+89,  -6.6512404302752191e-94,  5.9694071428777419e+75,
         -2.2455786558979847e-07,  4.9669868189935904e-138,  0.0061890868099943397,
         640.72936513779496,       5.6841357650775322e-159,  2.6251850286147423e+76,
         1.8824067087078492e-19,   4.7874499648306695e-131,  56315600516164.672,
         8.3085302170380525e+87,   -8.1481280303016883e-195, 2.7785441627286128e-200,
         -7.9168201424783681e-26,  7.589108909426223e+160},
        {2.697110805581287e-120,   8.0000674783890063e-181,  7.7819393636788271e-225,
         2.0927356179730959e+18,   -5.6748368245405664e-70,  -7.3441370885867827e+18,
         2.6465965761821416e-195,  -5.532117945988401e-88,   4.5508331776969655e+139,
         -8.8448082133798585e+182, -3.9640145629954348e-208, 9.7032186103010063e-25,
         9.468069764399152e+178,   7.9570661098110248e-153,  4.8323145083708633e-127,
         -6.5024353992616643e-22,  9.6592994030033137e-162,  3.269298207486596e+203,
         8.9912453983850219e-148,  -4.6138068934419203e+199},
    };
    for (std::size_t i = 0; i < inputs.size(); ++i) {
        const std::vector<double>& xy = inputs[i];
        std::vector<tri::VertIdx> segments;
        for (tri::VertIdx v = 0; v < xy.size() / 2; ++v) segments.push_back(v);
        for (const bool hull : {false, true}) {
            std::vector<std::set<std::array<tri::VertIdx, 3>>> meshes;
            for (const tri::SegmentRecovery recovery :
                 {tri::SegmentRecovery::Swap, tri::SegmentRecovery::Cavity}) {
                const std::string label = "input " + std::to_string(i) + (hull ? " hull " : " ") +
                                          tri::segment_recovery_name(recovery);
                tri::Cdt2Options options;
                options.recovery = recovery;
                options.remove_exterior = !hull;
                const tri::Cdt2Result r =
                    tri::constrained_delaunay_2d({xy, segments, {}, {}}, options);
                const auto check = tri::check_constrained_delaunay_2d(
                    r.mesh, r.input_vertex_count, segments,
                    hull ? std::span<const tri::VertIdx>{} : std::span(r.pieces));
                EXPECT_TRUE(check.ok) << label << ": " << check.problem;
                meshes.push_back(exactmesh::testing::canonical_triangles(r.mesh.triangles));
            }
            EXPECT_TRUE(meshes[0] == meshes[1]) << "input " << i << ": swap and cavity differ";
        }
    }
}
