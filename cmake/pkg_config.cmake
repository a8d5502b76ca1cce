# parashade.pc, for builds without CMake: `pkg-config --cflags --libs parashade` compiles and links a program
# against the installed libraries (tests/install/install_test.cmake does). Relocatable: its prefix is found
# from the file's own place (${pcfiledir}), so an install moved elsewhere still works.
# Static libraries (the default) need their dependencies on the link line, so they are `Requires` and
# their flags `Libs`; shared ones carry them, so they are `Requires.private` and `Libs.private`.
set(pc_up "")
string(REPLACE "/" ";" libdir_parts "${CMAKE_INSTALL_LIBDIR}/pkgconfig")
foreach(part ${libdir_parts})
  string(APPEND pc_up "/..")
endforeach()
set(PARASHADE_PC_PREFIX "\${pcfiledir}${pc_up}")
# The compile definitions the libraries' INTERFACE carries (CMakeLists.txt).
set(PARASHADE_PC_CFLAGS "")
foreach(definition ${PARASHADE_GLM_DEFINITIONS} ${PARASHADE_CL_DEFINITIONS})
  string(APPEND PARASHADE_PC_CFLAGS " -D${definition}")
endforeach()
set(PARASHADE_PC_DEPENDENCIES "glm nlohmann_json openmesh OpenImageIO OpenCL")
if(BUILD_SHARED_LIBS)
  set(PARASHADE_PC_REQUIRES "glm nlohmann_json OpenCL")
  set(PARASHADE_PC_REQUIRES_PRIVATE "openmesh OpenImageIO")
  set(PARASHADE_PC_LIBS_PRIVATE "-pthread")
  set(PARASHADE_PC_LIBS_THREADS "")
else()
  set(PARASHADE_PC_REQUIRES "${PARASHADE_PC_DEPENDENCIES}")
  set(PARASHADE_PC_REQUIRES_PRIVATE "")
  set(PARASHADE_PC_LIBS_PRIVATE "")
  set(PARASHADE_PC_LIBS_THREADS " -pthread")
endif()
configure_file(cmake/parashade.pc.in ${CMAKE_BINARY_DIR}/generated/parashade.pc @ONLY)
install(FILES ${CMAKE_BINARY_DIR}/generated/parashade.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig COMPONENT package)
