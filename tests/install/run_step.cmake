# run(WHAT COMMAND...) for the install tests' scripts: runs the command, stops the script naming WHAT with
# the command's output when it fails, and leaves its standard output in run_output.
function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE failed OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(failed)
    message(FATAL_ERROR "${what} failed (${failed}):\n${out}\n${err}")
  endif()
  set(run_output "${out}" PARENT_SCOPE)
endfunction()
