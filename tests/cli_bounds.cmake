# Every long computation has a bound on its work and memory (docs/analyze.md, gen.md,
# helicoid.md): beyond it the command refuses with exit 2 and a message naming the option to
# change, before or early in the work (no test here is timed: each refusal is quick by design).
include(${CMAKE_CURRENT_LIST_DIR}/cli_helpers.cmake)

function(refused what needle)
  run_expect(2 "${what}" ${ARGN})
  expect_text("${err}" "${needle}" "${what}")
endfunction()

set(W ${OUT}/bounds)
file(MAKE_DIRECTORY ${W})

# analyze --servo: servo periods simulated (--max-ticks, default 5e7: 50000 s at 1 ms)
file(WRITE ${W}/slow_feed.nc "G90 G01 X10000. F1.\nM30\n")          # 600000 s at F1
file(WRITE ${W}/long_dwell.nc "G01 X1. F100.\nG04 X99999.\nG04 X99999.\nG01 X2.\nM30\n")
refused("servo: a slow feed" "raise --max-ticks" ${NCURVE} analyze ${W}/slow_feed.nc --servo)
refused("servo: long dwells" "raise --max-ticks" ${NCURVE} analyze ${W}/long_dwell.nc --servo --json)
refused("servo: a low --max-ticks" "raise --max-ticks" ${NCURVE} analyze ${SRC}/examples/spiral.nc --servo
        --max-ticks 1000 --blocks ${W}/blocks.csv)
if(EXISTS ${W}/blocks.csv)
  message(SEND_ERROR "servo refused: the --blocks file was written all the same")
endif()
run_expect(0 "servo: no servo, no bound" ${NCURVE} analyze ${W}/slow_feed.nc)
run_expect(2 "servo: --max-ticks must be a whole number" ${NCURVE} analyze ${W}/slow_feed.nc --servo --max-ticks 1.5)

# analyze --curve keeps the contour's moves (--max-moves, default 500000)
file(WRITE ${W}/runaway.nc "#1=0\nWHILE[#1LT100000]DO1\nG01 X[#1/1000] Y0 F1000\n#1=#1+1\nEND1\nM30\n")
file(WRITE ${W}/arcs.nc "G01 X10. Y0 F500\n#1=0\nWHILE[#1LT5000]DO1\nG03 I-10. J0\n#1=#1+1\nEND1\nM30\n")
refused("curve moves: a line loop" "raise --max-moves" ${NCURVE} analyze ${W}/runaway.nc --curve expr --x t
        --y 0 --t 0:100 --max-moves 1000)
refused("curve moves: full circles" "raise --max-moves" ${NCURVE} analyze ${W}/arcs.nc --curve expr
        --x "10*COS[t]" --y "10*SIN[t]" --t 0:360 --max-moves 4000)
refused("curve moves: the spiral example" "more than 5, at" ${NCURVE} analyze ${SRC}/examples/spiral.nc
        --curve spiral --max-moves 5)

# analyze --plot keeps at most 3000 bins whatever the program's length: the runaway is drawn
run_expect(0 "plot of a long program" ${NCURVE} analyze ${W}/runaway.nc --plot ${W}/runaway.svg)
file(READ ${W}/runaway.svg svg)
expect_text("${svg}" "feed, mm/min" "plot of a long program")

# analyze circle: at most an hour and 1e7 servo periods
file(WRITE ${W}/fast_servo.toml "[machine]\nname = \"fast servo\"\n[servo]\nperiod = 0.00001\n")
refused("circle: slow feed" "simulated at most: raise the feed or lower the radius" ${NCURVE} analyze circle
        --radius 1000 --feed 1)
refused("circle: large radius" "simulated at most" ${NCURVE} analyze circle --radius 100000 --feed 5000)
refused("circle: a 10 us servo period" "servo periods of 0.01 ms" ${NCURVE} analyze circle --radius 50
        --feed 100 --machine ${W}/fast_servo.toml)

# gen: depth passes (at most 1000) and lines or arcs (--max-moves, default 200000)
refused("gen: 1e6 depth passes" "raise --step-down" ${NCURVE} gen ellipse --step-down 0.001 --depth 1000)
refused("gen: 2000 depth passes" "2e+03 passes, more than 1000" ${NCURVE} gen ellipse --step-down 0.0005 --depth 1)
refused("gen: a spiral of 10000 turns" "raise --max-moves" ${NCURVE} gen spiral --to 3600000)
refused("gen: a low --max-moves" "more than 1000 lines or arcs" ${NCURVE} gen spiral --to 36000 --max-moves 1000)
refused("gen: arcs" "raise --max-moves" ${NCURVE} gen spiral --to 3600 --form arcs --max-moves 10)
refused("gen: equal steps" "raise --max-moves" ${NCURVE} gen spiral --to 3600 --lines equal-step --max-moves 50)
refused("gen: equal chords" "raise --max-moves" ${NCURVE} gen spiral --to 3600 --lines equal-chord --max-moves 50)
refused("gen: the macro's loop" "raise --max-moves" ${NCURVE} gen spiral --to 3600 --form macro --max-moves 100)
refused("gen: the cycle's loop" "raise --max-moves" ${NCURVE} gen ellipse --form cycle --max-moves 20)
refused("gen: depth passes of lines" "(all depth passes)" ${NCURVE} gen ellipse --step-down 0.1 --depth 5
        --max-moves 500)

# gen expr: differentiating twice builds at most 500000 expression nodes
set(sines "SIN[t*1]")
set(linears "[t+1]")
foreach(k RANGE 2 60)
  math(EXPR m "${k} % 9 + 1")
  string(APPEND sines "*SIN[t*${m}]")
  string(APPEND linears "*[t+${m}]")
endforeach()
set(quotients "[t+1]")
foreach(k RANGE 2 150)
  math(EXPR m "${k} % 9 + 1")
  string(APPEND quotients "/[t+${m}]")
endforeach()
foreach(k RANGE 1 2)
  string(APPEND linears "*${linears}")
endforeach()
refused("expr: 60 sines" "expression nodes" ${NCURVE} gen expr --x "${sines}" --y t --t 0:1)
refused("expr: 244 linear factors" "expression nodes" ${NCURVE} gen expr --x t --y "${linears}" --t 0:1)
refused("expr: 150 quotients" "expression nodes" ${NCURVE} gen expr --x t --y t --z "${quotients}" --t 0:1)
refused("expr: analyze --curve" "expression nodes" ${NCURVE} analyze ${SRC}/examples/spiral.nc --curve expr
        --x "${sines}" --y t --t 0:1)

# helicoid: at most 20000 rows, 2e7 lattice points, 1e9 brute-force evaluations
set(seed ${NCURVE} helicoid --example seed004)
refused("helicoid: psi step 1e-7" "raise --step" ${seed} --step 1e-7)
refused("helicoid: psi step 0.001" "7.2e+04 steps, more than 20000" ${seed} --step 0.001)
refused("helicoid: alpha step" "raise --alpha-step or --s-step" ${seed} --alpha-step 1e-300)
refused("helicoid: s step" "raise --alpha-step or --s-step" ${seed} --s-step 1e-9)
refused("helicoid: alpha range" "raise --alpha-step or --s-step" ${seed} --alpha-range 89 --alpha-step 0.0001)
refused("helicoid: brute force" "use --method robust" ${seed} --method brute --step 0.01)
refused("helicoid: centre distances" "a larger STEP" ${seed} --final-motion z- --centre-distance 200:300:1e-9)

# Memory that runs out is said, with exit 2 (sanitizers reserve more address space than the limit)
if(NOT SANITIZE)
  execute_process(COMMAND truncate -s 300M ${W}/huge.nc)
  foreach(cmd "run ${W}/huge.nc" "analyze ${W}/huge.nc" "run ${W}/huge.nc --format csv -o ${W}/huge.csv")
    execute_process(COMMAND sh -c "ulimit -v 100000; exec ${NCURVE} ${cmd}" RESULT_VARIABLE status ERROR_VARIABLE err)
    if(NOT status EQUAL 2)
      message(SEND_ERROR "out of memory (${cmd}): exit ${status}, expected 2")
    endif()
    expect_text("${err}" "out of memory" "out of memory (${cmd})")
  endforeach()
  if(EXISTS ${W}/huge.csv)
    message(SEND_ERROR "out of memory: a CSV was left under the requested name")
  endif()
  file(REMOVE ${W}/huge.nc)
endif()

# a program's compiled form is bounded (--max-memory, default ten times its size, at least 256 MB):
# 10,000,000 one-word blocks of 30 MB would take about a gigabyte; refused before compiling, but by
# run, which reads it as a stream
string(REPEAT "X1\n" 10000000 one_word)
file(WRITE ${W}/one_word.nc "${one_word}")
set(one_word "")
run_expect(0 "run streams a program too large to read whole" ${NCURVE} run ${W}/one_word.nc)
expect_text("${out}" "executed       10000000 blocks" "run streams a program too large to read whole")
run_expect(2 "a program of one-word blocks" ${NCURVE} analyze ${W}/one_word.nc)
expect_text("${err}" "one_word.nc: 10000000 lines in 30.0 MB would take at least" "one-word blocks")
expect_text("${err}" "more than the bound of 300 MB (ten times the program's size" "one-word blocks")
expect_text("${err}" "--max-memory MB raises it" "one-word blocks")
file(REMOVE ${W}/one_word.nc)
string(REPEAT "G01 X1.\nX0\n" 50000 lines)
file(WRITE ${W}/lines.nc "F100.\n${lines}M30\n")
refused("a program over --max-memory" "more than the bound of 5 MB (--max-memory)" ${NCURVE} analyze ${W}/lines.nc
        --max-memory 5)
run_expect(0 "run streams a program over --max-memory" ${NCURVE} run ${W}/lines.nc --max-memory 5)
run_expect(0 "a program within --max-memory" ${NCURVE} run ${W}/lines.nc --max-memory 20)
