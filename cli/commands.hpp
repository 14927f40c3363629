// SPDX-License-Identifier: MIT
// The subcommands of the `exactmesh` command, one file per family. Each adds itself to the
// application; its callback runs the work and throws exactmesh::Error on failure.
#pragma once

namespace CLI {
class App;
}  // namespace CLI

namespace exactmesh::cli {

/// Exit statuses of `exactmesh` (also listed in its --help footer).
inline constexpr int kExitSuccess = 0;
inline constexpr int kExitCheckFailed = 1;    ///< `check` or `fuzz` found a problem
inline constexpr int kExitBadInput = 2;       ///< bad input file, option or usage
inline constexpr int kExitInternalError = 3;  ///< a bug in exactmesh or out of memory

/// `exactmesh triangulate IN.node -o OUT[.ele|.msh|.vtu|.svg] [--algorithm A] [--order O]
/// [--seed S] [--stats]`.
void add_triangulate_command(CLI::App& app);

/// `exactmesh tetrahedralize IN.node -o OUT[.ele|.msh|.vtu] [--algorithm A] [--order O]
/// [--seed S] [--stats]`.
void add_tetrahedralize_command(CLI::App& app);

/// `exactmesh cdt IN.poly -o OUT [--recovery swap|cavity|conforming] [--convex-hull] [--order O]
/// [--seed S] [--stats]`.
void add_cdt_command(CLI::App& app);

/// `exactmesh mesh IN.poly|--domain NAME -o OUT [--generator G] [--min-angle DEG]
/// [--size NUM|FILE] [--max-steiner N] [--quality] [--stats]`.
void add_mesh_command(CLI::App& app);

/// `exactmesh check IN.node IN.ele`: sets `exit_status` to kExitCheckFailed when the mesh
/// fails the exact Delaunay check (2D, or 3D when IN.node declares dimension 3).
void add_check_command(CLI::App& app, int& exit_status);

/// `exactmesh fuzz --minutes M [--seed S] [--out DIR]`: sets `exit_status` to kExitCheckFailed
/// when any case fails (each failing input is minimized and saved in DIR).
void add_fuzz_command(CLI::App& app, int& exit_status);

/// `exactmesh swap IN.node IN.ele -o OUT.ele [--criterion C] [--data-cost abn|jnd] [--stats]`.
void add_swap_command(CLI::App& app);

/// `exactmesh min-max IN.node -o OUT.ele [--stats]`.
void add_min_max_command(CLI::App& app);

/// `exactmesh swap3d IN.node IN.ele -o OUT.ele [--criterion C] [--quality] [--stats]` (TetGen
/// files).
void add_swap3d_command(CLI::App& app);

/// `exactmesh adapt IN.poly|--domain NAME --field EXPR -o OUT [--method M] [--indicator I]
/// [--cycles K] [--max-vertices N] [--threshold T] [--smooth N] [--quality] [--stats]`.
void add_adapt_command(CLI::App& app);

/// `exactmesh tetmesh IN.poly|IN.smesh|IN.off|IN.stl|--domain NAME -o OUT[.ele|.msh|.vtu]
/// [--radius-edge B] [--max-volume V] [--max-steiner N] [--quality] [--stats]`.
void add_tetmesh_command(CLI::App& app);
}  // namespace exactmesh::cli
