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
# Z from -2 (the depth) to 400, where the shipped mill powers on (reference position 1, G54 Z-400)
expect_text("${out}" "-2.0000 .. 400.0000" "Z down to the depth")
run_expect(1 "depth passes on a helix" ${NCURVE} gen helix --tol 0.01 --step-down 1)
expect_text("${err}" "depth passes need a plane curve" "helix rises in Z")
run_expect(1 "arcs of a lathe curve on the mill" ${NCURVE} gen hyperbola --form arcs -o ${OUT}/gen_hyperbola_arcs.nc)
expect_text("${err}" "arcs on a mill are made in the XY plane (G17), and this curve moves in Z" "why: the plane")
expect_text("${err}" "--machine fanuc-lathe" "what to do for a lathe curve")
run_expect(0 "the same arcs on the lathe" ${NCURVE} gen hyperbola --form arcs --machine fanuc-lathe -o ${OUT}/gen_hyperbola_arcs.nc)

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

# every number typed is checked, with the option and what it takes; NaN and infinities are refused
run_expect(2 "a range of t that is not a number" ${NCURVE} gen expr --x "a*COS(t)" --y "SIN(t)" --t 0:abc --a 1)
expect_text("${err}" "--t: 'abc' is not a number (expected FROM:TO" "--t names the bad number")
run_expect(2 "a range of t without a colon" ${NCURVE} gen expr --x "COS(t)" --y "SIN(t)" --t 0-90)
expect_text("${err}" "--t: '0-90' has no ':'" "--t needs FROM:TO")
run_expect(2 "an empty range of t" ${NCURVE} gen expr --x "COS(t)" --y "SIN(t)" --t 90:0)
expect_text("${err}" "--t: the range 90:0 is empty" "--t FROM below TO")
run_expect(2 "an empty --from/--to range" ${NCURVE} gen spiral --from 30 --to 20)
expect_text("${err}" "--from must be below --to" "--from below --to")
run_expect(2 "a tolerance of 0" ${NCURVE} gen spiral --tol 0)
expect_text("${err}" "--tol: must be a length above 0 mm, got 0" "--tol 0 in mm")
foreach(bad nan inf -inf)
  run_expect(2 "--tol ${bad}" ${NCURVE} gen spiral --tol ${bad})
  expect_text("${err}" "--tol: must be a length above 0 mm, got ${bad}" "--tol ${bad} refused")
  run_expect(2 "--tool-radius ${bad}" ${NCURVE} gen spiral --tool-radius ${bad})
  expect_text("${err}" "--tool-radius: must be a length of at least 0 mm, got ${bad}" "--tool-radius ${bad} refused")
  run_expect(2 "--from ${bad}" ${NCURVE} gen spiral --from ${bad})
  expect_text("${err}" "--from: must be a finite value of the curve parameter t, got ${bad}" "--from ${bad} refused")
  run_expect(2 "curve parameter ${bad}" ${NCURVE} gen spiral --r0 ${bad})
  expect_text("${err}" "--r0: must be a finite value of the parameter r0, got ${bad}" "--r0 ${bad} refused")
  run_expect(2 "--t with ${bad}" ${NCURVE} gen expr --x "COS(t)" --y "SIN(t)" --t 0:${bad})
  expect_text("${err}" "--t: TO must be a finite number, got ${bad}" "--t 0:${bad} refused")
endforeach()
foreach(case "--feed;0;--feed: must be a feed above 0 mm/min (mill) or mm/rev (lathe), got 0"
              "--depth;-1;--depth: must be a length of at least 0 mm, got -1"
              "--step-down;abc;--step-down: 'abc' is not a number (expected a length of at least 0 mm)"
              "--clearance;0;--clearance: must be a length above 0 mm, got 0"
              "--program-number;1.5;--program-number: must be a whole number from 1 to 9999, got 1.5"
              "--tip;nan;--tip: must be a whole number from 0 to 9, got nan"
              "--cycle-program;9020;--cycle-program: must be a whole number from 9010 to 9019, got 9020"
              "--form;arc;--form: 'arc' is not a form (expanded, arcs, macro, adaptive-macro, cycle); did you mean arcs?"
              "--r0;abc;--r0: 'abc' is not a number (expected a finite value of the parameter r0)")
  list(GET case 0 option)
  list(GET case 1 value)
  list(GET case 2 message)
  run_expect(2 "${option} ${value}" ${NCURVE} gen spiral ${option} ${value})
  expect_text("${err}" "${message}" "${option} ${value}")
endforeach()

# names: a name in an expression needs a value, a function must be one, an unknown --NAME is an error
run_expect(2 "a parameter without a value" ${NCURVE} gen expr --x "c*COS(t)" --y "SIN(t)" --t 0:90)
expect_text("${err}" "expr x(t): 'c' at column 1 is a parameter without a value: give --c VALUE" "missing --c")
run_expect(2 "a misspelt function" ${NCURVE} gen expr --x "a*COZ(t)" --y "SIN(t)" --t 0:90 --a 1)
expect_text("${err}" "'COZ' at column 3 is not a function of the macro language; did you mean COS?" "COZ for COS")
run_expect(2 "a parameter named like an option" ${NCURVE} gen expr --x "depth*COS(t)" --y "SIN(t)" --t 0:90)
expect_text("${err}" "named like the option --depth" "a parameter cannot be --depth")
run_expect(2 "an unknown option" ${NCURVE} gen spiral --tolerance 0.01)
expect_text("${err}" "--tolerance is not an option of ncurve gen nor a parameter of spiral (r0, pitch, cx, cy); did you mean --tol?"
            "--tolerance for --tol")
run_expect(2 "a misspelt parameter" ${NCURVE} gen spiral --pich 3)
expect_text("${err}" "did you mean --pitch?" "--pich for --pitch")
run_expect(2 "an expr parameter its expressions do not use" ${NCURVE} gen expr --x "a*COS(t)" --y "SIN(t)" --t 0:90
           --a 1 --b 2)
expect_text("${err}" "--b is not an option of ncurve gen nor a name in the expressions (they use a)" "--b unused")
run_expect(2 "an expr option given to a catalogue curve" ${NCURVE} gen spiral --t 0:90)
expect_text("${err}" "--t is for expr" "--t is for expr")
run_expect(2 "a parameter given twice" ${NCURVE} gen spiral --r0 1 --r0 2)
expect_text("${err}" "--r0 is given twice" "--r0 twice")
run_expect(2 "a misspelt curve" ${NCURVE} gen elipse)
expect_text("${err}" "did you mean ellipse?" "elipse for ellipse")
run_expect(2 "one dash" ${NCURVE} gen spiral -tol 0.01)
expect_text("${err}" "did you mean --tol?" "-tol for --tol")
run_expect(0 "a parameter in another case" ${NCURVE} gen spiral --R0 2 --json)

# a lathe curve without a lathe profile: a mill program, and a warning saying how to get the lathe one
run_expect(0 "gen hyperbola on the mill" ${NCURVE} gen hyperbola -o ${OUT}/gen_hyperbola_mill.nc)
expect_text("${err}" "warning: hyperbola is a lathe curve; without a lathe profile this is a mill program" "lathe warning")
expect_text("${err}" "--machine profiles/fanuc-lathe.toml" "the warning says how")
run_expect(0 "gen hyperbola on the lathe" ${NCURVE} gen hyperbola --machine ${SRC}/profiles/fanuc-lathe.toml
           -o ${OUT}/gen_hyperbola_lathe.nc)
string(FIND "${err}" "warning" at)
expect_rc("${at}" -1 "no warning with a lathe profile")
run_expect(0 "gen ellipse on the mill" ${NCURVE} gen ellipse -o ${OUT}/gen_ellipse_mill.nc)
string(FIND "${err}" "warning" at)
expect_rc("${at}" -1 "no warning for a mill curve")
run_expect(0 "gen --list marks the lathe curves" ${NCURVE} gen --list)
expect_text("${out}" "a lathe curve: --machine profiles/fanuc-lathe.toml" "--list marks the hyperbola")

# the set-up: tool, spindle, coolant once before the contour, and their end; the program runs
run_expect(0 "gen with a tool, spindle and coolant" ${NCURVE} gen ellipse --tool 3 --spindle 2400 --coolant
           -o ${OUT}/gen_setup.nc)
file(READ ${OUT}/gen_setup.nc setup_prog)
expect_text("${setup_prog}" "G21 G17 G90 G94 G54\nT3 M06\nS2400 M03\nG00 G43 Z5. H3\nM08\n" "the mill set-up")
expect_text("${setup_prog}" "\nM09\nM05\nM30\n" "the end")
run_expect(0 "run the set-up program" ${NCURVE} run ${OUT}/gen_setup.nc --format jsonl)
expect_text("${out}" "\"kind\":\"tool_change\"" "the tool change runs")
expect_text("${out}" "\"kind\":\"coolant\"" "the coolant runs")
run_expect(0 "gen a lathe set-up" ${NCURVE} gen hyperbola --machine ${SRC}/profiles/fanuc-lathe.toml --tool 2 --css 180
           --max-rpm 3000 --spindle-ccw -o ${OUT}/gen_lathe_setup.nc)
file(READ ${OUT}/gen_lathe_setup.nc setup_prog)
expect_text("${setup_prog}" "G21 G18 G99\nT0202\nG50 S3000\nG96 S180 M04\n" "the lathe set-up")
run_expect(0 "run the lathe set-up" ${NCURVE} run ${OUT}/gen_lathe_setup.nc --machine ${SRC}/profiles/fanuc-lathe.toml)
run_expect(0 "css without a clamp" ${NCURVE} gen hyperbola --machine ${SRC}/profiles/fanuc-lathe.toml --css 180
           -o ${OUT}/gen_lathe_css.nc)
expect_text("${err}" "warning: --css without --max-rpm" "an unclamped surface speed is warned of")
run_expect(2 "css on a mill" ${NCURVE} gen ellipse --css 180)
expect_text("${err}" "a constant surface speed (G96) is for the lathe" "css is for the lathe")
run_expect(2 "a clamp without css" ${NCURVE} gen ellipse --max-rpm 3000)
expect_text("${err}" "the spindle clamp is for a constant surface speed" "max-rpm needs css")
run_expect(2 "a tool 0" ${NCURVE} gen ellipse --tool 0)
expect_text("${err}" "--tool: must be a whole number from 1 to 9999, got 0" "tool range")

# inch: G20, coordinates and feeds in inches; the control reads them back in mm
run_expect(0 "gen in inches" ${NCURVE} gen ellipse --inch -o ${OUT}/gen_inch.nc)
file(READ ${OUT}/gen_inch.nc inch_prog)
expect_text("${inch_prog}" "G20 G17 G90 G94 G54\nG00 Z0.1969\nX1.5748 Y0.\nG01 Z-0.0394 F7.874\n" "inch words")
run_expect(0 "run the inch program" ${NCURVE} run ${OUT}/gen_inch.nc --format csv)
expect_text("${out}" "line,39.999920,0.000000,-1.000760," "1.5748 in and -0.0394 in in mm")
run_expect(2 "a cycle in inches" ${NCURVE} gen ellipse --inch --form cycle)
expect_text("${err}" "the cycles' macros (O9010..O9019) are written in mm" "no inch cycles")

# the form's cycle time on the chosen machine is the one `ncurve analyze` gives its program; a
# macro form much slower than its G01 lines is warned of, with both times
set(cycle_prog "${OUT}/gen_cycle_seed000.nc")
run_expect(0 "gen a cycle on seed 000" ${NCURVE} gen ellipse --a 40 --b 20 --form cycle --feed 2000
           --machine ${SRC}/profiles/seed000.toml -o ${cycle_prog} --json)
string(JSON gen_time GET "${out}" cycle_time_s)
string(JSON lines_time GET "${out}" expanded_cycle_time_s)
expect_text("${err}" "warning: the cycle form takes " "a slow cycle is warned of")
expect_text("${err}" "times the " "the warning compares with the expanded form")
run_expect(0 "analyze the cycle" ${NCURVE} analyze ${cycle_prog} --machine ${SRC}/profiles/seed000.toml
           --param 6051=103 --json)
string(JSON analyze_time GET "${out}" cycle_time_s)
if(NOT gen_time STREQUAL analyze_time)
  message(SEND_ERROR "gen says the cycle takes ${gen_time} s, analyze ${analyze_time} s")
endif()
# the expanded form's time is analyze's of the expanded program; the cycle, at 120 ms a macro statement
# (seed 000), takes longer
run_expect(0 "gen the lines on seed 000" ${NCURVE} gen ellipse --a 40 --b 20 --feed 2000
           --machine ${SRC}/profiles/seed000.toml -o ${OUT}/gen_lines_seed000.nc)
run_expect(0 "analyze the lines" ${NCURVE} analyze ${OUT}/gen_lines_seed000.nc --machine ${SRC}/profiles/seed000.toml
           --json)
string(JSON analyze_lines GET "${out}" cycle_time_s)
if(NOT lines_time STREQUAL analyze_lines)
  message(SEND_ERROR "gen says the expanded form takes ${lines_time} s, analyze ${analyze_lines} s")
endif()
if(gen_time LESS lines_time)
  message(SEND_ERROR "the cycle (${gen_time} s) is not slower than the lines (${lines_time} s)")
endif()
run_expect(0 "gen expanded" ${NCURVE} gen ellipse --a 40 --b 20 --feed 2000 -o ${OUT}/gen_lines.nc)
expect_text("${out}" "  cycle time " "the expanded form's time")
string(FIND "${err}" "warning: the" slow_warned)
if(NOT slow_warned EQUAL -1)
  message(SEND_ERROR "the expanded form is warned of as slow:\n${err}")
endif()

# the common variables the macro form sets, read from its text: every #100..#199 / #500..#999
# assigned outside a comment
run_expect(0 "gen macro" ${NCURVE} gen ellipse --form macro -o ${OUT}/gen_macro_commons.nc)
expect_text("${out}" "  common variables it sets: #100..#102, #110..#114 (what they held before the program is lost)"
            "the macro's common variables")
file(READ ${OUT}/gen_macro_commons.nc macro_text)
string(REGEX REPLACE "\\([^)]*\\)" "" macro_code "${macro_text}")
string(REGEX MATCHALL "#[0-9]+=" assigned "${macro_code}")
list(REMOVE_DUPLICATES assigned)
list(SORT assigned)
if(NOT assigned STREQUAL "#100=;#101=;#102=;#110=;#111=;#112=;#113=;#114=")
  message(SEND_ERROR "the macro form assigns ${assigned}")
endif()
run_expect(0 "gen macro json" ${NCURVE} gen ellipse --form macro --json)
string(JSON commons GET "${out}" common_variables)
string(REGEX REPLACE "[ \n]" "" commons "${commons}")
if(NOT commons STREQUAL "[100,101,102,110,111,112,113,114]")
  message(SEND_ERROR "gen --json common_variables: ${commons}")
endif()

# a lathe program's comment names the path written: the imaginary tip, or the nose centre
run_expect(0 "gen lathe tip 3" ${NCURVE} gen hyperbola --machine ${SRC}/profiles/fanuc-lathe.toml --tool-radius 0.8
           --tip 3 --form arcs)
expect_text("${out}" "(IMAGINARY TOOL TIP 3 PATH: NOSE RADIUS 0.8 MM, THE NOSE CENTRE LEFT OF THE CURVE)"
            "the tip's path is named")
string(FIND "${out}" "CUTTER CENTRE" cutter)
if(NOT cutter EQUAL -1)
  message(SEND_ERROR "a lathe program says cutter centre:\n${out}")
endif()
run_expect(0 "gen lathe nose centre" ${NCURVE} gen hyperbola --machine ${SRC}/profiles/fanuc-lathe.toml
           --tool-radius 0.8 --side right --form arcs)
expect_text("${out}" "(NOSE CENTRE PATH: NOSE RADIUS 0.8 MM, RIGHT OF THE CURVE)" "the nose centre's path is named")
