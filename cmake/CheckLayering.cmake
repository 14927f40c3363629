# Fails when an #include crosses the layers the wrong way (run as a CTest test with -P).
# Allowed (every layer may also use base/: errors, number text, counter tables): predicates ->
# predicates; triangulation -> predicates, triangulation; generators -> predicates,
# triangulation, generators; io -> triangulation/mesh/mesh[23].hpp and plc_3d.hpp, io;
# cli -> the four layers and cli (never tests/ or bench/: the command ships); python -> the
# four layers and python; examples -> nothing by repository path (only <exactmesh/...>);
# bench -> the four layers and bench; tests -> the four layers, tests and the peer wrappers
# bench/cgal_*.hpp (the differential tests compare with the same peer the benchmarks run).
# CGAL may appear only in tests/ and bench/.
# Inside triangulation/ and generators/ every source lies in a family sub-folder, and families
# include only themselves and the families listed before them (DESIGN.md: one way inside a
# layer too): checks rely on the mesh types alone, never on the algorithms they check.
# generators: topology (edges of a mesh) serves every family; the stretched generators come
# before mesh_2d, whose registry lists them (metric-delaunay, advancing-layers); fuzzing (the
# drivers that judge other programs on the inputs) comes last.
set(families_triangulation mesh checks delaunay constrained modification recovery_3d)
set(families_generators topology sizing boundary boundary_3d mesh_3d stretched mesh_2d inputs
    adaptation fuzzing)
set(allowed_base "base")
set(allowed_predicates "base|predicates")
set(allowed_triangulation "base|predicates|triangulation")
set(allowed_generators "base|predicates|triangulation|generators")
set(allowed_io "base|io|triangulation/mesh/(mesh[23]|plc_3d)\\.hpp")
set(allowed_cli "base|predicates|triangulation|generators|io|cli")
set(allowed_python "base|predicates|triangulation|generators|io|python")
# examples/ use only the installed package: <exactmesh/...>, never a repository path.
set(allowed_examples "<no repository header>")
set(allowed_bench "base|predicates|triangulation|generators|io|bench")
set(allowed_tests "base|predicates|triangulation|generators|io|tests|bench/cgal_[a-z0-9_]+\\.hpp")
set(failures "")
foreach(layer triangulation generators)
  file(GLOB loose "${SOURCE_DIR}/${layer}/*.hpp" "${SOURCE_DIR}/${layer}/*.cpp")
  foreach(f ${loose})
    list(APPEND failures "${f}: not in a family sub-folder (${families_${layer}})")
  endforeach()
endforeach()
foreach(layer base predicates triangulation generators io cli python examples bench tests)
  file(GLOB_RECURSE files "${SOURCE_DIR}/${layer}/*.hpp" "${SOURCE_DIR}/${layer}/*.cpp"
       "${SOURCE_DIR}/${layer}/*.ipp")
  foreach(f ${files})
    file(STRINGS "${f}" lines REGEX "^[ \t]*#[ \t]*include[ \t]*[\"<]")
    foreach(line ${lines})
      if(line MATCHES "#[ \t]*include[ \t]*\"([a-z_]+)/([^\"]+)\"")
        set(to_layer "${CMAKE_MATCH_1}")
        set(to_path "${CMAKE_MATCH_2}")
        set(target "${to_layer}/${to_path}")
        if(NOT target MATCHES "^(${allowed_${layer}})")
          list(APPEND failures "${f}: ${line}")
        endif()
        if(DEFINED families_${layer} AND to_layer STREQUAL layer)
          file(RELATIVE_PATH rel "${SOURCE_DIR}/${layer}" "${f}")
          string(REGEX MATCH "^[a-z0-9_]+" from_family "${rel}")
          string(REGEX MATCH "^[a-z0-9_]+" to_family "${to_path}")
          list(FIND families_${layer} "${from_family}" from_rank)
          list(FIND families_${layer} "${to_family}" to_rank)
          if(from_rank LESS 0 OR to_rank LESS 0 OR to_rank GREATER from_rank)
            list(APPEND failures "${f}: ${line} (family ${from_family} may not include ${to_family})")
          endif()
        endif()
      endif()
      if(line MATCHES "CGAL/" AND NOT layer MATCHES "^(tests|bench)$")
        list(APPEND failures "${f}: CGAL outside tests/bench: ${line}")
      endif()
    endforeach()
  endforeach()
endforeach()
if(failures)
  list(JOIN failures "\n" text)
  message(FATAL_ERROR "layering violations:\n${text}")
endif()
message(STATUS "layering: ok")
