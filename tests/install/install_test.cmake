# The install label: cmake --install into a fresh prefix, then a program outside this tree
# (tests/install/consumer) finds the package, builds against the installed headers and libraries only, and
# renders a sphere through the API on the default OpenCL device. Checks what a user would: the installed
# command runs, the package names no path of the source or build tree, the image exists and is a picture;
# the package's components load alone and an unknown one is refused with its reason; the kernels are
# installed as data, not headers; parashade.pc builds the same consumer without CMake.
# -D: BUILD_DIR, SOURCE_DIR, WORK_DIR, GENERATOR, CXX_COMPILER, [CXX_LAUNCHER], OIIOTOOL, [PKG_CONFIG].
cmake_minimum_required(VERSION 3.20)
set(prefix ${WORK_DIR}/prefix)
set(consumer_build ${WORK_DIR}/consumer-build)
set(image ${WORK_DIR}/sphere.png)
set(components_build ${WORK_DIR}/components-build)
file(REMOVE_RECURSE ${WORK_DIR})

include(${CMAKE_CURRENT_LIST_DIR}/run_step.cmake)

run("cmake --install" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})

# The kernels' sources are data (share/parashade/kernels); only the headers the host shares with them are
# headers (cmake/install.cmake).
if(NOT EXISTS ${prefix}/share/parashade/kernels/render_tiles.cl OR NOT EXISTS ${prefix}/share/parashade/kernels/units/all.h)
  message(FATAL_ERROR "the kernels' sources are not installed under ${prefix}/share/parashade/kernels")
endif()
file(GLOB_RECURSE kernel_sources_as_headers ${prefix}/include/*.cl ${prefix}/include/parashade/kernels/tile_walk.h)
if(kernel_sources_as_headers)
  message(FATAL_ERROR "kernel sources installed as headers: ${kernel_sources_as_headers}")
endif()

run("installed parashade --version" ${prefix}/bin/parashade --version)
if(NOT run_output MATCHES "^parashade [0-9]+\\.[0-9]+\\.[0-9]+ \\(git [^)]+\\)")
  message(FATAL_ERROR "installed parashade --version printed '${run_output}'")
endif()

# An installed package must stand alone: no include directory or file of this checkout or its build.
file(GLOB_RECURSE package_files ${prefix}/lib*/cmake/parashade/*.cmake)
if(NOT package_files)
  message(FATAL_ERROR "no CMake package installed under ${prefix}/lib*/cmake/parashade")
endif()
foreach(f IN LISTS package_files)
  file(READ ${f} text)
  foreach(tree ${SOURCE_DIR} ${BUILD_DIR})
    string(FIND "${text}" "${tree}" at)
    if(NOT at EQUAL -1)
      message(FATAL_ERROR "${f} names ${tree}: the installed package depends on the tree it was built in")
    endif()
  endforeach()
endforeach()

set(launcher "")
if(CXX_LAUNCHER)
  set(launcher -DCMAKE_CXX_COMPILER_LAUNCHER=${CXX_LAUNCHER})
endif()
run("configuring the consumer" ${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/install/consumer -B ${consumer_build}
    -G ${GENERATOR} -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=${CXX_COMPILER} ${launcher}
    -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_FIND_PACKAGE_NO_PACKAGE_REGISTRY=ON)
run("building the consumer" ${CMAKE_COMMAND} --build ${consumer_build})
run("running the consumer" ${consumer_build}/consumer ${image})
message(STATUS "consumer: ${run_output}")

if(NOT EXISTS ${image})
  message(FATAL_ERROR "the consumer wrote no ${image}")
endif()
# A picture, not a blank frame: 160x120, and its pixels differ (a constant image has no shading).
run("oiiotool --stats" ${OIIOTOOL} ${image} --printstats)
string(REGEX MATCH "160 x +120" size "${run_output}")
if(NOT size)
  message(FATAL_ERROR "${image} is not 160x120:\n${run_output}")
endif()
string(REGEX MATCH "Constant: No" varies "${run_output}")
string(REGEX MATCH "Stats StdDev: ([0-9.]+)" stddev "${run_output}")
if(NOT varies OR NOT CMAKE_MATCH_1 GREATER 5)  # levels of 255
  message(FATAL_ERROR "${image} is (nearly) one colour:\n${run_output}")
endif()
message(STATUS "install test: ${image} ok (${stddev})")

# The render step (render_step.hpp) links and runs from the package alone.
run("running the render step" ${consumer_build}/render_step ${SOURCE_DIR}/scenes/sphere.json)
string(FIND "${run_output}" "render step ok" ok)
if(ok EQUAL -1)
  message(FATAL_ERROR "the render step consumer did not finish:\n${run_output}")
endif()
message(STATUS "${run_output}")

# Components: scene alone links and runs (its CMakeLists refuses more targets than it asked for); cl
# brings the layers it needs; an unknown one fails and says why.
run("configuring the scene-only consumer" ${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/install/scene_consumer
    -B ${components_build} -G ${GENERATOR} -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=${CXX_COMPILER} ${launcher}
    -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_FIND_PACKAGE_NO_PACKAGE_REGISTRY=ON -DPARASHADE_COMPONENTS=scene)
run("building the scene-only consumer" ${CMAKE_COMMAND} --build ${components_build})
run("running the scene-only consumer" ${components_build}/scene_consumer)
message(STATUS "${run_output}")
run("find_package(parashade COMPONENTS cl)" ${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/install/scene_consumer
    -B ${components_build} -DPARASHADE_COMPONENTS=cl)
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/install/scene_consumer -B ${components_build}
                        -DPARASHADE_COMPONENTS=nonesuch
                RESULT_VARIABLE failed OUTPUT_VARIABLE out ERROR_VARIABLE err)
string(REGEX REPLACE "[ \n]+" " " err_words "${err}")  # CMake wraps the reason's lines
if(NOT failed OR NOT err_words MATCHES "parashade has no component 'nonesuch': its components are scene, core and cl")
  message(FATAL_ERROR "find_package(parashade COMPONENTS nonesuch) did not fail with the reason (${failed}):\n${err}")
endif()
message(STATUS "components: scene alone, cl with its layers, nonesuch refused")

# parashade.pc: the same consumer built with `pkg-config --cflags --libs parashade` alone, and run.
if(PKG_CONFIG)
  file(GLOB pc_file ${prefix}/lib*/pkgconfig/parashade.pc ${prefix}/lib/*/pkgconfig/parashade.pc)
  if(NOT pc_file)
    message(FATAL_ERROR "no parashade.pc installed under ${prefix}")
  endif()
  get_filename_component(pc_dir "${pc_file}" DIRECTORY)
  run("pkg-config --cflags --libs parashade" ${CMAKE_COMMAND} -E env PKG_CONFIG_PATH=${pc_dir}
      ${PKG_CONFIG} --cflags --libs parashade)
  separate_arguments(pc_flags UNIX_COMMAND "${run_output}")
  run("building the consumer with pkg-config" ${CXX_LAUNCHER} ${CXX_COMPILER} -std=c++17 -O1
      ${SOURCE_DIR}/tests/install/consumer/consumer.cpp -o ${WORK_DIR}/pc-consumer ${pc_flags})
  run("running the pkg-config consumer" ${WORK_DIR}/pc-consumer ${WORK_DIR}/pc-sphere.png)
  if(NOT EXISTS ${WORK_DIR}/pc-sphere.png)
    message(FATAL_ERROR "the pkg-config consumer wrote no ${WORK_DIR}/pc-sphere.png")
  endif()
  message(STATUS "pkg-config consumer: ${run_output}")
else()
  message(STATUS "pkg-config not found (scripts/install-deps.sh installs it): parashade.pc is not tried")
endif()

# README's "Using parashade from another program" shows this consumer as it is (a code block: indented).
file(READ ${SOURCE_DIR}/README.md readme)
file(READ ${SOURCE_DIR}/tests/install/consumer/consumer.cpp consumer)
string(REGEX REPLACE "\n([^\n])" "\n    \\1" consumer "${consumer}")
string(FIND "${readme}" "    ${consumer}" at)
if(at EQUAL -1)
  message(FATAL_ERROR "README.md does not show tests/install/consumer/consumer.cpp as it is")
endif()
