# The API reference (docs/api/Doxyfile): `cmake --build build --target docs` writes build/docs/api/html when
# Doxygen is installed (scripts/install-deps.sh --test installs it). tests/docs/api_reference_test.cmake runs
# the same with every warning an error.
find_program(PARASHADE_DOXYGEN doxygen DOC "Doxygen (package doxygen): the API reference, target docs")
set(PARASHADE_DOXYGEN_ENV PARASHADE_SOURCE_DIR=${CMAKE_SOURCE_DIR} PARASHADE_GENERATED_INCLUDE=${PARASHADE_GENERATED_INCLUDE})
if(PARASHADE_DOXYGEN)
  add_custom_target(docs
    COMMAND ${CMAKE_COMMAND} -E make_directory ${CMAKE_BINARY_DIR}/docs/api
    COMMAND ${CMAKE_COMMAND} -E env ${PARASHADE_DOXYGEN_ENV} PARASHADE_DOCS_OUT=${CMAKE_BINARY_DIR}/docs/api
            PARASHADE_DOXYGEN_WARN_AS_ERROR=NO ${PARASHADE_DOXYGEN} ${CMAKE_SOURCE_DIR}/docs/api/Doxyfile
    COMMENT "API reference: ${CMAKE_BINARY_DIR}/docs/api/html/index.html" VERBATIM)
else()
  add_custom_target(docs COMMAND ${CMAKE_COMMAND} -E echo "doxygen not found: scripts/install-deps.sh --test installs it"
                    VERBATIM)
endif()
