// SPDX-License-Identifier: MIT
// libFuzzer target for the PLC readers (io/plc_format) and checks (triangulation/recovery_3d):
// the first byte picks the reader (.poly, .smesh, .off, .stl), the rest is the file. Every
// malformed input must end in an io::FormatError, every invalid PLC in an InputError; anything
// else (a crash, an InternalError, another exception) is a bug.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <string_view>

#include "base/errors.hpp"
#include "io/format_error.hpp"
#include "io/plc_format.hpp"
#include "triangulation/recovery_3d/plc_3d.hpp"

namespace {

namespace tri = exactmesh::triangulation;

[[noreturn]] void fail(const char* what) {
    std::fprintf(stderr, "fuzz_plc_3d: %s\n", what);
    std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    const std::string_view text(reinterpret_cast<const char*>(data) + 1, size - 1);
    exactmesh::io::PlcFile file;
    try {
        switch (data[0] % 4) {
            case 0:
                // A .poly of 0 points names a .node file that does not exist: a FormatError.
                file = exactmesh::io::parse_tetgen_poly_3d(text, "f.poly", "/nonexistent/f.node");
                break;
            case 1:
                file = exactmesh::io::parse_smesh(text, "f.smesh", "/nonexistent/f.node");
                break;
            case 2:
                file = exactmesh::io::parse_off(text, "f.off");
                break;
            default:
                file = exactmesh::io::parse_stl(text, "f.stl");
                break;
        }
    } catch (const exactmesh::io::FormatError&) {
        return 0;
    } catch (const std::exception& e) {
        fail((std::string("a reader threw something else than FormatError: ") + e.what()).c_str());
    }
    // Keep the checks' inputs small: the fuzzer looks for crashes, not for slow inputs.
    if (file.facets.size() > 256 || file.vertex_count() > 1024) return 0;
    try {
        tri::Plc3 plc = exactmesh::io::plc_from_file(std::move(file));
        // As prepare_plc_for_meshing_3d: vertices at one point merged, facets with no area
        // and repeated facets left out, then validated; the merged PLC names only its own vertices
        // (or the input's out-of-range ones, refused).
        const std::uint32_t input_vertices = plc.vertex_count();
        tri::merge_duplicate_vertices_3d(plc);
        if (!plc.input_vertex.empty()) {
            if (plc.merged_vertex.size() != input_vertices) fail("merge lost the input's count");
            for (tri::VertIdx v = 0; v < plc.vertex_count(); ++v) {
                if (plc.from_input_vertex(plc.to_input_vertex(v)) != v)
                    fail("merge's numberings are not inverse on the merged vertices");
            }
        }
        tri::drop_zero_area_facets_3d(plc);
        tri::drop_repeated_facets_3d(plc);
        tri::validate_plc_3d_input(plc);
        const std::uint32_t polygons_before = [&plc] {
            std::uint32_t count = 0;
            for (const auto& facet : plc.facets)
                count += static_cast<std::uint32_t>(facet.polygons.size());
            return count;
        }();
        const tri::FreeVertexEmbedding3 embedded = tri::embed_free_vertices_3d(plc);
        std::uint32_t polygons_after = 0;
        for (const auto& facet : plc.facets)
            polygons_after += static_cast<std::uint32_t>(facet.polygons.size());
        if (polygons_after < polygons_before + embedded.on_facets)
            fail("embedding free vertices lost a facet polygon");
        // Embedded, no free vertex is left on the surface: validate_plc_3d must not refuse one.
        tri::SurfaceTriangles3 surface;
        try {
            surface = tri::validate_plc_3d(plc);
        } catch (const exactmesh::InputError& e) {
            if (std::string(e.what()).find("in no facet polygon") != std::string::npos)
                fail((std::string("a free vertex was left on the surface: ") + e.what()).c_str());
            throw;
        }
        for (const tri::VertIdx v : surface.triangles) {
            if (v >= plc.vertex_count()) fail("a surface triangle names a vertex out of range");
        }
        try {
            tri::check_surface_closed_3d(plc, surface);
        } catch (const exactmesh::InputError&) {
        }
    } catch (const exactmesh::InternalError& e) {
        fail((std::string("internal error: ") + e.what()).c_str());
    } catch (const exactmesh::InputError&) {
        return 0;
    } catch (const std::exception& e) {
        fail((std::string("the checks threw something else than InputError: ") + e.what()).c_str());
    }
    return 0;
}
