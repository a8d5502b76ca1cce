# docs.api_reference: Doxygen over the public headers (docs/api/Doxyfile) with WARN_AS_ERROR=YES, so a
# malformed comment fails; and every public header opens with a comment saying what it holds (the file's
# entry in the reference).
# -D: DOXYGEN, SOURCE_DIR, GENERATED_INCLUDE, WORK_DIR.
cmake_minimum_required(VERSION 3.20)
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})

file(GLOB headers ${SOURCE_DIR}/include/parashade/*.hpp ${GENERATED_INCLUDE}/parashade/*.hpp)
set(undescribed "")
foreach(header IN LISTS headers)
  file(STRINGS ${header} opening LIMIT_COUNT 3)
  if(NOT opening MATCHES "(^|;)// [^;]")
    list(APPEND undescribed ${header})
  endif()
endforeach()
if(undescribed)
  list(JOIN undescribed "\n  " undescribed)
  message(FATAL_ERROR "public headers without an opening comment (the reference's description of the file):\n  ${undescribed}")
endif()

execute_process(COMMAND ${CMAKE_COMMAND} -E env PARASHADE_SOURCE_DIR=${SOURCE_DIR}
                        PARASHADE_GENERATED_INCLUDE=${GENERATED_INCLUDE} PARASHADE_DOCS_OUT=${WORK_DIR}
                        PARASHADE_DOXYGEN_WARN_AS_ERROR=YES ${DOXYGEN} ${SOURCE_DIR}/docs/api/Doxyfile
                RESULT_VARIABLE failed OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(failed)
  message(FATAL_ERROR "doxygen docs/api/Doxyfile failed (${failed}), warnings are errors:\n${out}\n${err}")
endif()
if(NOT EXISTS ${WORK_DIR}/html/classparashade_1_1Renderer.html)
  message(FATAL_ERROR "doxygen wrote no page for parashade::Renderer under ${WORK_DIR}/html")
endif()
list(LENGTH headers count)
message(STATUS "API reference: ${count} headers, no warning (${WORK_DIR}/html/index.html)")
