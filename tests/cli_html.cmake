# ncurve run --html: the page written whole (to a file or the standard output), the summary kept,
# the exit status of the run, and refusals where two outputs would share the standard output.
# What the page draws is checked in a browser (tests/browser/backplot.test.cjs).
include(${CMAKE_CURRENT_LIST_DIR}/cli_helpers.cmake)

function(count_text text needle want what)
  string(REPLACE "${needle}" "" rest "${text}")
  string(LENGTH "${text}" a)
  string(LENGTH "${rest}" b)
  string(LENGTH "${needle}" n)
  math(EXPR found "(${a} - ${b}) / ${n}")
  if(NOT found EQUAL want)
    message(SEND_ERROR "${what}: ${found} times '${needle}', expected ${want}")
  endif()
endfunction()

file(REMOVE ${OUT}/html_spiral.html)
run_expect(0 "run --html" ${NCURVE} run ${SRC}/examples/spiral.nc --html ${OUT}/html_spiral.html)
expect_text("${out}" "3 rapid, 101 line" "run --html keeps the summary")
file(READ ${OUT}/html_spiral.html page)
expect_text("${page}" "<title>${SRC}/examples/spiral.nc · ncurve backplot</title>" "title")
expect_text("${page}" "REVISION=\"111\"" "three.js embedded")
expect_text("${page}" "\"motions\":104" "the motions encoded")
count_text("${page}" "<script" 15 "the page's scripts")  # the two data blocks and thirteen scripts

# the page on standard output, the summary on the terminal
run_expect(0 "run --html -" ${NCURVE} run ${SRC}/examples/spiral.nc --html - --json)
expect_text("${out}" "<!DOCTYPE html>" "page on standard output")
expect_text("${err}" "\"motions\": 104" "summary on the terminal")
run_expect(2 "--html - with --format csv" ${NCURVE} run ${SRC}/examples/spiral.nc --html - --format csv)
expect_text("${err}" "both write to standard output" "two outputs on standard output")
run_expect(2 "--html - with --plot -" ${NCURVE} run ${SRC}/examples/spiral.nc --html - --plot -)
# with -o the moves go to the file and the page to standard output
run_expect(0 "--html - with -o" ${NCURVE} run ${SRC}/examples/spiral.nc --html - --format csv -o ${OUT}/html_moves.csv)
expect_text("${out}" "<!DOCTYPE html>" "page on standard output beside -o")
expect_text("${err}" "3 rapid, 101 line" "summary on the terminal beside -o")
# --plot and --html together
run_expect(0 "--plot and --html" ${NCURVE} run ${SRC}/examples/spiral.nc --html ${OUT}/html_both.html --plot ${OUT}/html_both.svg)
foreach(f html_both.html html_both.svg)
  if(NOT EXISTS ${OUT}/${f})
    message(SEND_ERROR "--plot and --html: ${f} not written")
  endif()
endforeach()

# an alarm: exit 1 as without --html, the page written with the alarm in it
run_expect(1 "run --html of an alarm" ${NCURVE} run ${SRC}/examples/alarm.nc --html ${OUT}/html_alarm.html)
file(READ ${OUT}/html_alarm.html page)
expect_text("${page}" "\"code\":\"MC3001\"" "the alarm in the page")

# written whole or not at all, never over the program
file(REMOVE_RECURSE ${OUT}/no-such-dir)
run_expect(2 "page to a missing folder" ${NCURVE} run ${SRC}/examples/spiral.nc --html ${OUT}/no-such-dir/p.html)
file(COPY ${SRC}/examples/spiral.nc DESTINATION ${OUT}/html_input)
run_expect(2 "page over its program" ${NCURVE} run ${OUT}/html_input/spiral.nc --html ${OUT}/html_input/spiral.nc)
file(READ ${OUT}/html_input/spiral.nc kept)
expect_text("${kept}" "WHILE" "the program is kept")
