# PARASHADE_GIT_HASH: the source tree's commit (short hash, "-dirty" when tracked files differ from it), or
# "unknown" when the tree is not a git checkout or git is missing. Read at configure time; a commit or
# checkout re-runs the configure step (the HEAD reflog is a configure dependency), so --version follows it.
set(PARASHADE_GIT_HASH "unknown")
find_package(Git QUIET)
if(GIT_FOUND)
  execute_process(COMMAND ${GIT_EXECUTABLE} rev-parse --short=12 HEAD WORKING_DIRECTORY ${CMAKE_SOURCE_DIR}
                  OUTPUT_VARIABLE hash OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE failed ERROR_QUIET)
  if(NOT failed AND hash)
    set(PARASHADE_GIT_HASH ${hash})
    execute_process(COMMAND ${GIT_EXECUTABLE} diff --quiet HEAD -- WORKING_DIRECTORY ${CMAKE_SOURCE_DIR}
                    RESULT_VARIABLE dirty ERROR_QUIET)
    if(dirty)
      string(APPEND PARASHADE_GIT_HASH "-dirty")
    endif()
    execute_process(COMMAND ${GIT_EXECUTABLE} rev-parse --path-format=absolute --git-path logs/HEAD
                    WORKING_DIRECTORY ${CMAKE_SOURCE_DIR} OUTPUT_VARIABLE head_log
                    OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
    if(head_log AND EXISTS "${head_log}")
      set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${head_log}")
    endif()
  endif()
endif()
