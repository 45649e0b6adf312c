# ncurve gen as a user runs it: the program it writes runs under ncurve run, the JSON carries the
# documented keys, and bad input gives the documented exit codes.
include(${CMAKE_CURRENT_LIST_DIR}/cli_helpers.cmake)

set(prog "${OUT}/gen_spiral.nc")
run_expect(0 "gen spiral arcs" ${NCURVE} gen spiral --tol 0.005 --form arcs -o ${prog} --json)
foreach(key curve form tolerance words bytes blocks points path_length max_deviation worst_t within_tolerance)
  expect_text("${out}" "\"${key}\"" "gen --json")
endforeach()
run_expect(0 "run the generated program" ${NCURVE} run ${prog})

run_expect(0 "gen lathe hyperbola macro" ${NCURVE} gen hyperbola --from -20 --to 20
           --machine ${SRC}/profiles/fanuc-lathe.toml --form macro -o ${OUT}/gen_hyperbola.nc)
run_expect(0 "run the generated lathe program" ${NCURVE} run ${OUT}/gen_hyperbola.nc
           --machine ${SRC}/profiles/fanuc-lathe.toml)

run_expect(0 "gen --list" ${NCURVE} gen --list)
foreach(name spiral hyperbola ellipse parabola involute sine cycloid trochoid helix rotor expr)
  expect_text("${out}" "${name}" "gen --list")
endforeach()

run_expect(2 "unknown curve" ${NCURVE} gen nosuchcurve)
run_expect(2 "unknown parameter" ${NCURVE} gen spiral --radius 3)
run_expect(1 "curve through a pole" ${NCURVE} gen hyperbola --from -80 --to 100)
expect_text("${err}" "90" "the pole error says where")

# adaptive macro: runs on its own
run_expect(0 "gen adaptive-macro" ${NCURVE} gen spiral --form adaptive-macro -o ${OUT}/gen_adaptive.nc)
run_expect(0 "run the adaptive macro" ${NCURVE} run ${OUT}/gen_adaptive.nc)

# the G102 cycle: the parameter it needs is printed, and with it the program runs
run_expect(0 "gen cycle" ${NCURVE} gen spiral --form cycle -o ${OUT}/gen_cycle.nc --json)
expect_text("${out}" "\"6050\": 102" "gen cycle --json parameters")
run_expect(0 "gen cycle text" ${NCURVE} gen spiral --form cycle -o ${OUT}/gen_cycle.nc)
expect_text("${out}" "No.6050 = 102" "gen cycle names its parameter")
run_expect(0 "run the cycle with its parameter" ${NCURVE} run ${OUT}/gen_cycle.nc --param 6050=102)
run_expect(1 "run the cycle without its parameter" ${NCURVE} run ${OUT}/gen_cycle.nc)
run_expect(2 "an unknown parameter" ${NCURVE} run ${OUT}/gen_cycle.nc --param 9999=1)
expect_text("${err}" "9999" "the unknown parameter is named")

# a curve cycle: G103 (No.6051) in O9011 for the ellipse; the macro alone for the control's memory
# is the shipped one, and a hand-written call runs against the shipped library
run_expect(0 "gen ellipse cycle" ${NCURVE} gen ellipse --form cycle -o ${OUT}/gen_ellipse_cycle.nc --json)
expect_text("${out}" "\"6051\": 103" "gen ellipse cycle --json parameters")
expect_text("${out}" "\"macro\": \"%\\nO9011" "gen ellipse cycle --json macro")
run_expect(0 "run the ellipse cycle" ${NCURVE} run ${OUT}/gen_ellipse_cycle.nc --param 6051=103)
run_expect(0 "gen ellipse cycle macro only" ${NCURVE} gen ellipse --form cycle --macro-only -o ${OUT}/O9011.nc)
file(READ ${OUT}/O9011.nc written)
file(READ ${SRC}/macros/O9011.nc shipped)
if(NOT written STREQUAL shipped)
  message(FATAL_ERROR "gen --macro-only: O9011 differs from macros/O9011.nc")
endif()
file(WRITE ${OUT}/gen_call_g103.nc "G90 G17 G00 X20. Y0.\nG01 F300.\nG103 A20. B10. S0. E90. T0.01\nM30\n")
run_expect(0 "a hand-written G103 call" ${NCURVE} run ${OUT}/gen_call_g103.nc --param 6051=103 --lib ${SRC}/macros)
run_expect(0 "an expr curve's cycle in another slot" ${NCURVE} gen expr --x "4*COS[t]" --y "3*SIN[t]" --t 0:90
           --form cycle --cycle-program 9015 --json)
expect_text("${out}" "\"6055\": 107" "gen --cycle-program names its parameter")
run_expect(2 "macro-only without the cycle form" ${NCURVE} gen ellipse --macro-only)
run_expect(2 "a cycle program out of O9010..O9019" ${NCURVE} gen ellipse --form cycle --cycle-program 9020)

# tool radius: the cutter centre, and the gouge named
run_expect(0 "gen with a tool radius" ${NCURVE} gen ellipse --tool-radius 5 --side right --json)
expect_text("${out}" "\"tool_radius\": 5.0" "gen --json tool_radius")
run_expect(1 "gen with a gouging tool radius" ${NCURVE} gen ellipse --tool-radius 12 --side left)
expect_text("${err}" "gouge" "the gouge is reported")

# the plot: curve, path and deviation
run_expect(0 "gen --plot" ${NCURVE} gen sine --form arcs --plot ${OUT}/gen_plot.svg -o ${OUT}/gen_plot.nc)
file(READ ${OUT}/gen_plot.svg svg)
expect_text("${svg}" "<svg" "plot")
expect_text("${svg}" "stroke:#d22" "plot path")
expect_text("${svg}" "deviation per move" "plot deviation")

# depth passes: a plane contour cut in passes of --step-down, each measured; not for a helix
run_expect(0 "gen depth passes" ${NCURVE} gen ellipse --tol 0.01 --form arcs --depth 2 --step-down 0.8
           -o ${OUT}/gen_passes.nc --json)
expect_text("${out}" "\"passes\": 3" "three passes of 0.8 mm to 2 mm")
file(READ ${OUT}/gen_passes.nc passes_prog)
expect_text("${passes_prog}" "WHILE [#199 GT -2.] DO3" "the pass loop")
expect_text("${passes_prog}" "G01 Z#199" "the plunge to the pass depth")
run_expect(0 "run the depth-pass program" ${NCURVE} run ${OUT}/gen_passes.nc)
expect_text("${out}" "-2.0000 .. 5.0000" "Z down to the depth")
run_expect(1 "depth passes on a helix" ${NCURVE} gen helix --tol 0.01 --step-down 1)
expect_text("${err}" "depth passes need a plane curve" "helix rises in Z")

# a curve at rest at an end of its range (zero speed at t = 0 and 180: the parabola y = 10 (1 - x^2/900)
# traced by x = 30 cos t) is cut; a stop inside the range (a cusp) is refused with where
run_expect(0 "gen a curve at rest at both ends" ${NCURVE} gen expr --x "a*COS(t)" --y "b*SIN(t)*SIN(t)" --t 0:180
           --a 30 --b 10 -o ${OUT}/gen_rest.nc)
run_expect(0 "run the curve at rest" ${NCURVE} run ${OUT}/gen_rest.nc --format csv)
expect_text("${out}" "line,30.000000,0.000000,-1.000000," "the contour starts at x = 30")
expect_text("${out}" "line,-30.000000,0.000000,-1.000000," "the contour ends at x = -30")
run_expect(0 "gen a cycle for a curve at rest at its end" ${NCURVE} gen expr --x "a*COS(t)" --y "b*SIN(t)*SIN(t)"
           --t 90:180 --a 30 --b 10 --form cycle -o ${OUT}/gen_rest_cycle.nc)
run_expect(0 "run that cycle" ${NCURVE} run ${OUT}/gen_rest_cycle.nc --param 6059=111)
run_expect(1 "a cusp inside the range" ${NCURVE} gen expr --x "a*COS(t)" --y "b*SIN(t)*SIN(t)" --t 90:270
           --a 30 --b 10)
expect_text("${err}" "the curve stops at t = 180 (zero speed" "the cusp is named")
