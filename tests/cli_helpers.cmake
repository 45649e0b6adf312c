# Helpers for the command-line tests: run a command, check its exit code and its output.
function(expect_rc rc want what)
  if(NOT rc STREQUAL want)
    message(SEND_ERROR "${what}: exit ${rc}, expected ${want}")
  endif()
endfunction()

# runs a command, checks its exit code, and leaves its output in `out` and `err`
function(run_expect want what)
  execute_process(COMMAND ${ARGN} OUTPUT_VARIABLE o ERROR_VARIABLE e RESULT_VARIABLE rc)
  expect_rc("${rc}" ${want} "${what}")
  set(out "${o}" PARENT_SCOPE)
  set(err "${e}" PARENT_SCOPE)
endfunction()

function(expect_text text needle what)
  string(FIND "${text}" "${needle}" at)
  if(at EQUAL -1)
    message(SEND_ERROR "${what}: no '${needle}' in:\n${text}")
  endif()
endfunction()

