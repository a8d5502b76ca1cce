# cmake --install: the parashade command, the libraries, the public headers (with the generated
# parashade/version.hpp and parashade/unit_kinds.hpp, and the kernel headers they include, as
# parashade/kernels/), a CMake package with components, a pkg-config file, and the kernels' sources as data.
# The command and the libraries need no kernel file at run time: the sources are embedded in parashade_cl
# (cmake/embed_kernels.cmake); share/parashade/kernels is for reading them or building them elsewhere.
# MPI (parashade_distributed) stays with the command; the package is the single-process library.
#
# Install components, so a partial install is possible (tests/install/shared_test.cmake installs one
# library): `headers`, `package` (CMake package files, parashade.pc), one per library (`scene`, `core`,
# `cl`, each with its CMake targets file), and the unnamed rest (command, kernels, documents).
include(CMakePackageConfigHelpers)

# parashade::parashade, every library at once (parashade::scene, ::core, ::cl alone for less).
add_library(parashade_library INTERFACE)
target_link_libraries(parashade_library INTERFACE parashade_cl)
set_target_properties(parashade_library PROPERTIES EXPORT_NAME parashade)
set_target_properties(parashade_scene PROPERTIES EXPORT_NAME scene)
set_target_properties(parashade_core PROPERTIES EXPORT_NAME core)
set_target_properties(parashade_cl PROPERTIES EXPORT_NAME cl)
add_library(parashade::parashade ALIAS parashade_library)

set(PARASHADE_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/parashade)
install(TARGETS parashade RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# One export set per component: find_package(parashade COMPONENTS scene) loads parashade-scene-targets.cmake
# alone (cmake/parashadeConfig.cmake.in).
foreach(component scene core cl)
  set(targets parashade_${component})
  if(component STREQUAL "cl")
    list(APPEND targets parashade_library)
  endif()
  install(TARGETS ${targets} EXPORT parashade-${component}-targets COMPONENT ${component}
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
  install(EXPORT parashade-${component}-targets NAMESPACE parashade:: DESTINATION ${PARASHADE_CMAKE_DIR}
          COMPONENT ${component})
endforeach()

install(DIRECTORY include/parashade DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} COMPONENT headers
        PATTERN distributed.hpp EXCLUDE)
install(FILES ${PARASHADE_GENERATED_INCLUDE}/parashade/version.hpp ${PARASHADE_GENERATED_INCLUDE}/parashade/unit_kinds.hpp
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/parashade COMPONENT headers)
# The kernel headers the host shares with the kernels (records, fixed point, the units' clocks), included by
# the public headers: the only kernel files installed as headers. tests/install/headers_alone.py compiles
# every installed header alone against the install, so a missing one here fails there.
set(PARASHADE_SHARED_KERNEL_HEADERS constants.h fixed_point.h sierpinski_leaf.h span_division.h span_registers.h
    triangle_record.h unit_cost.h)
foreach(header ${PARASHADE_SHARED_KERNEL_HEADERS})
  install(FILES kernels/${header} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/parashade/kernels COMPONENT headers)
endforeach()
install(DIRECTORY kernels/units/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/parashade/kernels/units COMPONENT headers
        FILES_MATCHING PATTERN "*.h")
# Every kernel source, with the generated units/all.h, as data: the tree the program builds from.
install(DIRECTORY kernels/ DESTINATION ${CMAKE_INSTALL_DATADIR}/parashade/kernels FILES_MATCHING PATTERN "*.h"
        PATTERN "*.cl")
install(FILES ${PARASHADE_GENERATED_KERNELS}/units/all.h DESTINATION ${CMAKE_INSTALL_DATADIR}/parashade/kernels/units)
install(FILES LICENSE README.md CHANGELOG.md DESTINATION ${CMAKE_INSTALL_DOCDIR})

configure_package_config_file(cmake/parashadeConfig.cmake.in ${CMAKE_BINARY_DIR}/generated/parashadeConfig.cmake
                              INSTALL_DESTINATION ${PARASHADE_CMAKE_DIR})
# 0.x: a minor version may change the interface.
write_basic_package_version_file(${CMAKE_BINARY_DIR}/generated/parashadeConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/generated/parashadeConfig.cmake
              ${CMAKE_BINARY_DIR}/generated/parashadeConfigVersion.cmake DESTINATION ${PARASHADE_CMAKE_DIR}
        COMPONENT package)

include(cmake/pkg_config.cmake)
