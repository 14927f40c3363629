# `cmake --install`: the four libraries and base/ as the CMake package `exactmesh`
# (find_package(exactmesh) gives exactmesh::predicates, ::triangulation, ::io, ::generators and
# ::base, GMP and MPFR found again on the consumer's side through pkg-config), their headers under
# include/exactmesh/, a pkg-config file, and the `exactmesh` command. README "C++ package" says
# which headers are the public API; the others are installed because public ones include them.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(EXACTMESH_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/exactmesh)

# The exported names drop the `exactmesh_` prefix: exactmesh::predicates, as inside the build.
foreach(layer base predicates triangulation io generators)
  set_target_properties(exactmesh_${layer} PROPERTIES EXPORT_NAME ${layer})
endforeach()
install(TARGETS exactmesh_base exactmesh_predicates exactmesh_triangulation exactmesh_io
                exactmesh_generators
        EXPORT exactmeshTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(TARGETS exactmesh RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})

foreach(layer base predicates triangulation io generators)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${layer}/
          DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/exactmesh/${layer}
          FILES_MATCHING PATTERN "*.hpp")
endforeach()
install(FILES ${PROJECT_BINARY_DIR}/generated/base/version.hpp
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/exactmesh/base)

install(EXPORT exactmeshTargets NAMESPACE exactmesh:: DESTINATION ${EXACTMESH_CMAKE_DIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/exactmeshConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/exactmeshConfig.cmake
                              INSTALL_DESTINATION ${EXACTMESH_CMAKE_DIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/exactmeshConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/exactmeshConfig.cmake
              ${PROJECT_BINARY_DIR}/exactmeshConfigVersion.cmake
        DESTINATION ${EXACTMESH_CMAKE_DIR})

# pkg-config: one module, every library in link order (generators before triangulation before
# predicates), the compile flags the inline filters need (-ffp-contract=off).
configure_file(${PROJECT_SOURCE_DIR}/cmake/exactmesh.pc.in ${PROJECT_BINARY_DIR}/exactmesh.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/exactmesh.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
