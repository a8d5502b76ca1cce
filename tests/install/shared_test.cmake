# install.shared: BUILD_SHARED_LIBS=ON configures, builds, installs and links. To stay cheap (CI's budget),
# it builds one library, parashade_scene, as a shared library in a build of its own (no tests, benchmarks or
# MPI), installs that component with the headers and the package files, and builds and runs the scene-only
# consumer against it, which must load libparashade_scene.so from the install. The other libraries are the
# same CMake code; a whole shared build is README's recipe.
# -D: SOURCE_DIR, WORK_DIR, GENERATOR, CXX_COMPILER, [CXX_LAUNCHER], READELF.
cmake_minimum_required(VERSION 3.20)
set(build ${WORK_DIR}/build)
set(prefix ${WORK_DIR}/prefix)
set(consumer_build ${WORK_DIR}/consumer-build)
file(REMOVE_RECURSE ${WORK_DIR})

include(${CMAKE_CURRENT_LIST_DIR}/run_step.cmake)

set(launcher "")
if(CXX_LAUNCHER)
  set(launcher -DCMAKE_CXX_COMPILER_LAUNCHER=${CXX_LAUNCHER})
endif()
string(TIMESTAMP start "%s")
run("configuring a shared build" ${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${build} -G ${GENERATOR}
    -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=${CXX_COMPILER} ${launcher} -DBUILD_SHARED_LIBS=ON
    -DPARASHADE_BUILD_TESTS=OFF -DPARASHADE_BUILD_BENCH=OFF -DPARASHADE_MPI=OFF)
run("building parashade_scene shared" ${CMAKE_COMMAND} --build ${build} --target parashade_scene)
foreach(component headers scene package)
  run("installing ${component}" ${CMAKE_COMMAND} --install ${build} --prefix ${prefix} --component ${component})
endforeach()
file(GLOB_RECURSE shared_library ${prefix}/lib*/libparashade_scene.so*)
file(GLOB_RECURSE static_library ${prefix}/lib*/libparashade_scene.a)
if(NOT shared_library OR static_library)
  message(FATAL_ERROR "BUILD_SHARED_LIBS=ON installed no libparashade_scene.so (or a static one) under ${prefix}")
endif()

run("configuring the consumer" ${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/install/scene_consumer -B ${consumer_build}
    -G ${GENERATOR} -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=${CXX_COMPILER} ${launcher}
    -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_FIND_PACKAGE_NO_PACKAGE_REGISTRY=ON -DPARASHADE_COMPONENTS=scene)
run("building the consumer" ${CMAKE_COMMAND} --build ${consumer_build})
run("reading the consumer's dynamic section" ${READELF} -d ${consumer_build}/scene_consumer)
if(NOT run_output MATCHES "NEEDED[^\n]*libparashade_scene\\.so")
  message(FATAL_ERROR "the consumer does not load libparashade_scene.so:\n${run_output}")
endif()
run("running the consumer" ${consumer_build}/scene_consumer)
string(TIMESTAMP end "%s")
math(EXPR seconds "${end} - ${start}")
message(STATUS "shared: ${run_output}(${seconds} s)")
