# The install label: cmake --install into a fresh prefix, then a program outside this tree
# (tests/install/consumer) finds the package, builds against the installed headers and libraries only, and
# renders a sphere through the API on the default OpenCL device. Checks what a user would: the installed
# command runs, the package names no path of the source or build tree, the image exists and is a picture.
# -D: BUILD_DIR, SOURCE_DIR, WORK_DIR, GENERATOR, CXX_COMPILER, [CXX_LAUNCHER], OIIOTOOL.
cmake_minimum_required(VERSION 3.20)
set(prefix ${WORK_DIR}/prefix)
set(consumer_build ${WORK_DIR}/consumer-build)
set(image ${WORK_DIR}/sphere.png)
file(REMOVE_RECURSE ${WORK_DIR})

function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE failed OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(failed)
    message(FATAL_ERROR "${what} failed (${failed}):\n${out}\n${err}")
  endif()
  set(run_output "${out}" PARENT_SCOPE)
endfunction()

run("cmake --install" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})

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

# README's "Using parashade from another program" shows this consumer as it is (a code block: indented).
file(READ ${SOURCE_DIR}/README.md readme)
file(READ ${SOURCE_DIR}/tests/install/consumer/consumer.cpp consumer)
string(REGEX REPLACE "\n([^\n])" "\n    \\1" consumer "${consumer}")
string(FIND "${readme}" "    ${consumer}" at)
if(at EQUAL -1)
  message(FATAL_ERROR "README.md does not show tests/install/consumer/consumer.cpp as it is")
endif()
