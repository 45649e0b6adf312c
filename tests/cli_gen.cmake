# ncurve gen as a user runs it: the program it writes runs under ncurve run, the JSON carries the
# documented keys, and bad input gives the documented exit codes.
function(expect_rc rc want what)
  if(NOT rc STREQUAL want)
    message(SEND_ERROR "${what}: exit ${rc}, expected ${want}")
  endif()
endfunction()

set(prog "${OUT}/gen_spiral.nc")
execute_process(COMMAND ${NCURVE} gen spiral --tol 0.005 --form arcs -o ${prog} --json
                OUTPUT_VARIABLE out RESULT_VARIABLE rc)
expect_rc("${rc}" 0 "gen spiral arcs")
foreach(key curve form tolerance words bytes blocks points path_length max_deviation worst_t within_tolerance)
  string(FIND "${out}" "\"${key}\"" at)
  if(at EQUAL -1)
    message(SEND_ERROR "gen --json lacks '${key}':\n${out}")
  endif()
endforeach()
execute_process(COMMAND ${NCURVE} run ${prog} OUTPUT_VARIABLE out RESULT_VARIABLE rc)
expect_rc("${rc}" 0 "run the generated program")

execute_process(COMMAND ${NCURVE} gen hyperbola --from -20 --to 20 --machine ${SRC}/profiles/fanuc-lathe.toml
                        --form macro -o ${OUT}/gen_hyperbola.nc OUTPUT_VARIABLE out RESULT_VARIABLE rc)
expect_rc("${rc}" 0 "gen lathe hyperbola macro")
execute_process(COMMAND ${NCURVE} run ${OUT}/gen_hyperbola.nc --machine ${SRC}/profiles/fanuc-lathe.toml
                RESULT_VARIABLE rc OUTPUT_QUIET)
expect_rc("${rc}" 0 "run the generated lathe program")

execute_process(COMMAND ${NCURVE} gen --list OUTPUT_VARIABLE out RESULT_VARIABLE rc)
expect_rc("${rc}" 0 "gen --list")
foreach(name spiral hyperbola ellipse parabola involute sine cycloid trochoid helix rotor expr)
  string(FIND "${out}" "${name}" at)
  if(at EQUAL -1)
    message(SEND_ERROR "gen --list lacks ${name}")
  endif()
endforeach()

execute_process(COMMAND ${NCURVE} gen nosuchcurve RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_QUIET)
expect_rc("${rc}" 2 "unknown curve")
execute_process(COMMAND ${NCURVE} gen spiral --radius 3 RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_QUIET)
expect_rc("${rc}" 2 "unknown parameter")
execute_process(COMMAND ${NCURVE} gen hyperbola --from -80 --to 100 RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_QUIET)
expect_rc("${rc}" 1 "curve through a pole")
string(FIND "${err}" "90" at)
if(at EQUAL -1)
  message(SEND_ERROR "the pole error does not say where: ${err}")
endif()
