# The install test (a CTest test, run with -P): installs this build into a fresh temporary
# prefix, configures examples/ against it alone (find_package(exactmesh) with CMAKE_PREFIX_PATH
# = that prefix), builds both examples and runs them; any step failing fails the test, so a
# broken install, header or package file fails CI.
# Variables: BUILD_DIR (the build tree), SOURCE_DIR, WORK_DIR (emptied first), GENERATOR, PYTHON.
file(REMOVE_RECURSE "${WORK_DIR}")
set(prefix "${WORK_DIR}/prefix")
function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what} failed (${rc}):\n${out}\n${err}")
  endif()
  message(STATUS "${what}: ok\n${out}")
endfunction()
run("install" ${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${prefix}")
foreach(f include/exactmesh/predicates/orient2d.hpp include/exactmesh/base/version.hpp
          lib/cmake/exactmesh/exactmeshConfig.cmake lib/pkgconfig/exactmesh.pc bin/exactmesh)
  if(NOT EXISTS "${prefix}/${f}")
    message(FATAL_ERROR "install: ${prefix}/${f} missing")
  endif()
endforeach()
set(launcher "")
find_program(ccache ccache)
if(ccache)
  set(launcher "-DCMAKE_CXX_COMPILER_LAUNCHER=${ccache}")
endif()
run("configure examples" ${CMAKE_COMMAND} -S "${SOURCE_DIR}/examples" -B "${WORK_DIR}/examples"
    -G "${GENERATOR}" -DCMAKE_BUILD_TYPE=Release "-DCMAKE_PREFIX_PATH=${prefix}" ${launcher})
run("build examples" ${CMAKE_COMMAND} --build "${WORK_DIR}/examples")
run("run triangulate_points" "${WORK_DIR}/examples/triangulate_points")
run("run mesh_domain_quality" "${WORK_DIR}/examples/mesh_domain_quality" key)
run("installed exactmesh --version" "${prefix}/bin/exactmesh" --version)
# The installed Python module imports and meshes from the prefix alone (PYTHON: the build's
# interpreter, empty when the module is not built).
if(PYTHON)
  file(GLOB site "${prefix}/lib/python*/dist-packages")
  set(ENV{PYTHONPATH} "${site}")
  run("installed Python module" ${PYTHON} -c
      "import exactmesh; m = exactmesh.mesh(domain='key'); assert exactmesh.check_mesh(m).ok; print(exactmesh.__file__, exactmesh.__version__, len(m.triangles))")
endif()
# pkg-config sees the installed module (found relative to the .pc file).
find_program(pkg_config pkg-config)
if(pkg_config)
  set(ENV{PKG_CONFIG_PATH} "${prefix}/lib/pkgconfig")
  run("pkg-config" ${pkg_config} --cflags --libs exactmesh)
endif()
