# ncurve run --plot / --view, and the plots of gen, analyze and helicoid on the shared layer: each
# SVG parses, has nothing off its page and no two texts overlapping (tests/plot_check.py), with
# the axes expected.
include(${CMAKE_CURRENT_LIST_DIR}/cli_helpers.cmake)
set(CHECK ${CMAKE_CURRENT_LIST_DIR}/plot_check.py)
if(NOT PYTHON3)
  message(FATAL_ERROR "python3 was not found, so the plots cannot be checked (install python3)")
endif()

# checks FILE with plot_check.py; its report (class counts and classed texts) in `report`
function(check_plot file what)
  execute_process(COMMAND ${PYTHON3} ${CHECK} ${file} OUTPUT_VARIABLE o ERROR_VARIABLE e RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(SEND_ERROR "${what}: ${file}: ${e}")
  endif()
  set(report "${o}" PARENT_SCOPE)
endfunction()

# four views of a mill program in inches: axes in inches
run_expect(0 "run --plot" ${NCURVE} run ${SRC}/examples/inch.nc --plot ${OUT}/plot_inch.svg)
expect_text("${out}" "moves" "run --plot keeps the summary")
check_plot(${OUT}/plot_inch.svg "run --plot")
expect_text("${report}" "view=4" "four views")
expect_text("${report}" "text label-u: X, in" "inch axes")
expect_text("${report}" "text label-v: Y, in" "inch axes")

# the caption counts the moves as the run's summary does, not the elements drawn: counted by hand,
# 2 rapids (the first a dog-leg of several pieces on the factory mill, non-linear positioning),
# 3 lines (X20. and X30. along one line, drawn as one element) and 1 arc
file(WRITE ${OUT}/plot_count.nc "G90 G17 G21 G54\nG00 X10. Y20. Z5.\nG01 Z-1. F100.\nG01 X20.\nG01 X30.\n"
     "G03 X40. Y30. I0 J10.\nG00 Z5.\nM30\n")
run_expect(0 "run --plot of a counted program" ${NCURVE} run ${OUT}/plot_count.nc --plot ${OUT}/plot_count.svg)
expect_text("${out}" "2 rapid, 3 line, 1 arc" "the run's summary")
file(READ ${OUT}/plot_count.svg svg)
expect_text("${svg}" ">6 motions: 2 rapid, 3 line and 1 arc moves<" "the plot's caption")
check_plot(${OUT}/plot_count.svg "run --plot of a counted program")

# one view; the drawing on standard output, the summary then on the terminal
run_expect(0 "run --plot - --view xz" ${NCURVE} run ${SRC}/examples/spiral.nc --plot - --view xz)
expect_text("${out}" "<svg" "plot on standard output")
expect_text("${err}" "moves" "summary on the terminal")
file(WRITE ${OUT}/plot_stdout.svg "${out}")
check_plot(${OUT}/plot_stdout.svg "run --plot -")
expect_text("${report}" "view=1" "one view")
expect_text("${report}" "text label-v: Z, mm" "XZ view")
run_expect(2 "two outputs on standard output" ${NCURVE} run ${SRC}/examples/spiral.nc --plot - --format csv)
expect_text("${err}" "both write to standard output" "two outputs on standard output")
run_expect(2 "bad view" ${NCURVE} run ${SRC}/examples/spiral.nc --plot ${OUT}/x.svg --view top)

# the alarm marked: exit 1 as without --plot, the drawing written
run_expect(1 "run --plot of an alarm" ${NCURVE} run ${SRC}/examples/alarm.nc --plot ${OUT}/plot_alarm.svg)
check_plot(${OUT}/plot_alarm.svg "alarm plot")
expect_text("${report}" "text alarm: MC3001 line 9" "alarm marker")
expect_text("${report}" "DEPTH #100 NOT SET" "alarm message")

# a lathe: Z across, X up as a diameter
run_expect(0 "lathe plot" ${NCURVE} run ${SRC}/examples/lathe-hyperbola.nc --machine fanuc-lathe --plot ${OUT}/plot_lathe.svg)
check_plot(${OUT}/plot_lathe.svg "lathe plot")
expect_text("${report}" "text label-u: Z, mm" "lathe Z across")
expect_text("${report}" "text label-v: X (diameter), mm" "lathe X up")

# a lathe has one plane: zx (or xz) draws it, a view of Y is refused before the run, naming the
# option and the lathe's view; a lathe with a Y axis has them all
run_expect(0 "lathe --view zx" ${NCURVE} run ${SRC}/examples/lathe-hyperbola.nc --machine fanuc-lathe --plot ${OUT}/plot_lathe_zx.svg
           --view zx)
check_plot(${OUT}/plot_lathe_zx.svg "lathe --view zx")
expect_text("${report}" "text label-u: Z, mm" "lathe --view zx")
foreach(view xy yz iso)
  file(REMOVE ${OUT}/plot_lathe_${view}.svg)
  run_expect(2 "lathe --view ${view}" ${NCURVE} run ${SRC}/examples/lathe-hyperbola.nc --machine fanuc-lathe
             --plot ${OUT}/plot_lathe_${view}.svg --view ${view})
  expect_text("${err}" "--view ${view}: a lathe without a Y axis" "lathe --view ${view}")
  expect_text("${err}" "--view zx" "lathe --view ${view} names the lathe's view")
  if(EXISTS ${OUT}/plot_lathe_${view}.svg)
    message(SEND_ERROR "lathe --view ${view}: a drawing was written")
  endif()
endforeach()
file(WRITE ${OUT}/plot_lathe_y.toml "[machine]\nname = \"lathe with a Y axis\"\ntype = \"lathe\"\naxes = [\"X\", \"Y\", \"Z\"]\n")
run_expect(0 "lathe with Y --view xy" ${NCURVE} run ${SRC}/examples/lathe-hyperbola.nc --machine ${OUT}/plot_lathe_y.toml
           --plot ${OUT}/plot_lathe_y.svg --view xy)
check_plot(${OUT}/plot_lathe_y.svg "lathe with Y --view xy")
expect_text("${report}" "text label-v: Y, mm" "lathe with Y --view xy")

# a rotary A axis is not drawn, and the drawing says so with its range
run_expect(0 "run --plot, 4 axes" ${NCURVE} run ${SRC}/examples/4-axis.nc --machine ${SRC}/profiles/fanuc-4axis-helicoid.toml
           --plot ${OUT}/plot_4axis.svg)
check_plot(${OUT}/plot_4axis.svg "run --plot, 4 axes")
expect_text("${report}" "text not-drawn: A axis not drawn: 0 to 360 deg" "the A axis named")

# written whole or not at all
file(REMOVE ${OUT}/no-such-dir/p.svg)
run_expect(2 "plot to a missing folder" ${NCURVE} run ${SRC}/examples/spiral.nc --plot ${OUT}/no-such-dir/p.svg)

# the other commands' plots, now with axes
run_expect(0 "gen --plot" ${NCURVE} gen sine --form arcs --plot ${OUT}/plot_gen.svg -o ${OUT}/plot_gen.nc)
check_plot(${OUT}/plot_gen.svg "gen --plot")
expect_text("${report}" "text label-u: X, mm" "gen plot axes")
expect_text("${report}" "text label-u: curve parameter t" "gen deviation axis")
expect_text("${report}" "text tick-u: 80" "gen plot ticks")
run_expect(0 "analyze --plot" ${NCURVE} analyze ${SRC}/examples/spiral.nc --plot ${OUT}/plot_feed.svg --curve spiral
           --r0 1 --pitch 12.566370614359172 --shape-plot ${OUT}/plot_shape.svg --tol 0.005)
check_plot(${OUT}/plot_feed.svg "analyze --plot")
expect_text("${report}" "text label-v: feed, mm/min" "feed plot axes")
check_plot(${OUT}/plot_shape.svg "analyze --shape-plot")
expect_text("${report}" "text label-v: Y, mm" "shape plot axes")
# a file name of more than 100 characters: the titles wrap within the page (plot_check.py)
set(long ${OUT}/plot_a_program_whose_name_is_far_longer_than_any_title_line_can_hold_roughing_pass_twelve_revision_c.nc)
configure_file(${SRC}/examples/spiral.nc ${long} COPYONLY)
run_expect(0 "analyze --plot of a long name" ${NCURVE} analyze ${long} --plot ${OUT}/plot_long_feed.svg --curve spiral
           --r0 1 --pitch 12.566370614359172 --shape-plot ${OUT}/plot_long_shape.svg)
check_plot(${OUT}/plot_long_feed.svg "analyze --plot, long name")
check_plot(${OUT}/plot_long_shape.svg "analyze --shape-plot, long name")
run_expect(0 "run --plot of a long name" ${NCURVE} run ${long} --plot ${OUT}/plot_long_run.svg)
check_plot(${OUT}/plot_long_run.svg "run --plot, long name")
file(READ ${OUT}/plot_long_feed.svg svg)
expect_text("${svg}" "revision_c.nc" "the whole name in the title")

# the deviation's colour scale when the tolerance is its top: the tolerance's label and the
# scale's title apart (plot_check.py: no two texts overlap)
run_expect(0 "gen ellipse" ${NCURVE} gen ellipse --a 20 --b 10 --tol 0.005 -o ${OUT}/plot_ellipse.nc)
run_expect(0 "analyze --shape-plot, tolerance at the top" ${NCURVE} analyze ${OUT}/plot_ellipse.nc --curve ellipse
           --a 20 --b 10 --tol 0.005 --shape-plot ${OUT}/plot_ellipse.svg)
check_plot(${OUT}/plot_ellipse.svg "analyze --shape-plot of the ellipse")
expect_text("${report}" "text label-u: X, mm" "shape plot axes")
file(READ ${OUT}/plot_ellipse.svg svg)
expect_text("${svg}" ">tolerance 5 µm<" "the tolerance marked on the colour scale")
foreach(kv "25,30" "25,25" "2,40")
  run_expect(0 "circle plot ${kv}" ${NCURVE} analyze circle --radius 50 --feed 5000 --kv ${kv} --plot ${OUT}/plot_circle.svg)
  check_plot(${OUT}/plot_circle.svg "circle plot ${kv}")
  expect_text("${report}" "text ring: 0 µm" "circle plot rings")
endforeach()
run_expect(0 "helicoid --plot" ${NCURVE} helicoid --example seed004 --csv -o ${OUT}/plot_rotor.csv --plot ${OUT}/plot_rotor.svg)
check_plot(${OUT}/plot_rotor.svg "helicoid --plot")
expect_text("${report}" "text label-u: psi, degrees" "helicoid plot axes")
expect_text("${report}" "text label-v: error, µm" "helicoid plot axes")

# run --setup --plot: the cut part under the path, a picture from above and outlines from the
# front and side (class "part"), none in the isometric view
run_expect(0 "run --setup --plot" ${NCURVE} run ${SRC}/examples/spiral.nc --setup ${SRC}/examples/spiral.setup.toml
           --plot ${OUT}/plot_part.svg)
check_plot(${OUT}/plot_part.svg "run --setup --plot")
expect_text("${report}" "part=3" "the part in three views")
file(READ ${OUT}/plot_part.svg svg)
expect_text("${svg}" "href=\"data:image/png;base64,iVBORw0KGgo" "a PNG picture from above")
# a lathe's part: the bar's half-section as cut, one filled outline in the ZX plane
run_expect(0 "lathe run --setup --plot" ${NCURVE} run ${SRC}/examples/lathe-mrc.nc --machine fanuc-lathe
           --setup ${SRC}/examples/lathe-mrc.setup.toml --plot ${OUT}/plot_lathe_part.svg)
check_plot(${OUT}/plot_lathe_part.svg "lathe run --setup --plot")
expect_text("${report}" "part=1" "the lathe's part")
file(READ ${OUT}/plot_lathe_part.svg svg)
expect_text("${svg}" "fill-rule=\"evenodd\"" "a hole cut out of the section")
