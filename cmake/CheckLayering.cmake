# Fails when an #include crosses the layers the wrong way (run as a CTest test with -P).
# Allowed (every layer may also use base/: errors, number text, counter tables): predicates ->
# predicates; triangulation -> predicates, triangulation; generators -> predicates,
# triangulation, generators; io -> triangulation/mesh*.hpp, io;
# cli -> the four layers and cli (never tests/ or bench/: the command ships);
# bench -> the four layers and bench; tests -> the four layers, tests and the peer wrappers
# bench/cgal_*.hpp (the differential tests compare with the same peer the benchmarks run).
# CGAL may appear only in tests/ and bench/.
set(allowed_base "base")
set(allowed_predicates "base|predicates")
set(allowed_triangulation "base|predicates|triangulation")
set(allowed_generators "base|predicates|triangulation|generators")
set(allowed_io "base|io|triangulation/mesh[23]\\.hpp")
set(allowed_cli "base|predicates|triangulation|generators|io|cli")
set(allowed_bench "base|predicates|triangulation|generators|io|bench")
set(allowed_tests "base|predicates|triangulation|generators|io|tests|bench/cgal_[a-z0-9_]+\\.hpp")
set(failures "")
foreach(layer base predicates triangulation generators io cli bench tests)
  file(GLOB_RECURSE files "${SOURCE_DIR}/${layer}/*.hpp" "${SOURCE_DIR}/${layer}/*.cpp"
       "${SOURCE_DIR}/${layer}/*.ipp")
  foreach(f ${files})
    file(STRINGS "${f}" lines REGEX "^[ \t]*#[ \t]*include[ \t]*[\"<]")
    foreach(line ${lines})
      if(line MATCHES "#[ \t]*include[ \t]*\"([a-z_]+)/([^\"]+)\"")
        set(target "${CMAKE_MATCH_1}/${CMAKE_MATCH_2}")
        if(NOT target MATCHES "^(${allowed_${layer}})")
          list(APPEND failures "${f}: ${line}")
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
