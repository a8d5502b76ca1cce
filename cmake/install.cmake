# cmake --install: the parashade command, the libraries, the public headers (with the generated
# parashade/version.hpp and the kernel headers they include, as parashade/kernels/) and a CMake package, so
# another project writes find_package(parashade) and links parashade::parashade. The kernels' sources are
# embedded in parashade_cl (cmake/embed_kernels.cmake): nothing else is needed at run time.
# MPI (parashade_distributed) stays with the command; the package is the single-process library.
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
install(TARGETS parashade_scene parashade_core parashade_cl parashade_library EXPORT parashadeTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(DIRECTORY include/parashade DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} PATTERN distributed.hpp EXCLUDE)
install(FILES ${PARASHADE_GENERATED_INCLUDE}/parashade/version.hpp ${PARASHADE_GENERATED_INCLUDE}/parashade/unit_kinds.hpp DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/parashade)
install(DIRECTORY kernels/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/parashade/kernels FILES_MATCHING PATTERN "*.h")
install(FILES LICENSE README.md CHANGELOG.md DESTINATION ${CMAKE_INSTALL_DOCDIR})

install(EXPORT parashadeTargets NAMESPACE parashade:: DESTINATION ${PARASHADE_CMAKE_DIR})
configure_package_config_file(cmake/parashadeConfig.cmake.in ${CMAKE_BINARY_DIR}/generated/parashadeConfig.cmake
                              INSTALL_DESTINATION ${PARASHADE_CMAKE_DIR})
# 0.x: a minor version may change the interface.
write_basic_package_version_file(${CMAKE_BINARY_DIR}/generated/parashadeConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/generated/parashadeConfig.cmake
              ${CMAKE_BINARY_DIR}/generated/parashadeConfigVersion.cmake DESTINATION ${PARASHADE_CMAKE_DIR})
