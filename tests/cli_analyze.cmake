# ncurve analyze as a user runs it: the circular test's JSON keys and values against the closed
# form, a program's cycle time, block table and plots, and errors for bad input.
include(${CMAKE_CURRENT_LIST_DIR}/cli_helpers.cmake)

# R 50, F 5000, Kv 30: V^2 / (2 R Kv^2) = 0.0772 mm (simulated 0.0770)
run_expect(0 "circle json" ${NCURVE} analyze circle --radius 50 --feed 5000 --json)
foreach(key radius_reduction roundness max_deviation_angle max_contour_error closed_form fanuc_radius_reduction)
  expect_text("${out}" "\"${key}\"" "analyze circle --json")
endforeach()
if(NOT out MATCHES "\"radius_reduction\": 0\\.07(69|70)")
  message(SEND_ERROR "radius reduction is not V^2/(2 R Kv^2): ${out}")
endif()
# Kv X 25 < Y 30: the ellipse's smallest radius near 135 degrees, roundness V (1/25 - 1/30) = 0.556 mm
run_expect(0 "circle mismatched gains" ${NCURVE} analyze circle --radius 50 --feed 5000 --kv 25,30 --json
           --plot ${OUT}/circle.svg)
if(NOT out MATCHES "\"max_deviation_angle\": (13[2-9]|14[0-9]|31[2-9]|32[0-9])\\.")
  message(SEND_ERROR "the ellipse is not at 135 (315) degrees: ${out}")
endif()
if(NOT out MATCHES "\"roundness\": 0\\.55")
  message(SEND_ERROR "roundness is not V (1/Kx - 1/Ky): ${out}")
endif()
file(READ ${OUT}/circle.svg svg)
expect_text("${svg}" "Circular test: R 50 mm, F 5000 mm/min" "polar plot title")
expect_text("${svg}" "µm" "polar plot rings")

run_expect(0 "analyze program" ${NCURVE} analyze ${SRC}/examples/spiral.nc --machine ${SRC}/profiles/fanuc-mill.toml
           --json --servo --blocks ${OUT}/blocks.csv --plot ${OUT}/feed.svg)
foreach(key cycle_time_s motion_s wait_s settle_s programmed_time_s starved_blocks mean_feed_mm_min macro_statements
        contour_error max_mm)
  expect_text("${out}" "\"${key}\"" "analyze --json")
endforeach()
file(READ ${OUT}/blocks.csv csv)
expect_text("${csv}" "file,line,kind,length_mm,programmed_mm_min,cap_mm_min,limit,v_in_mm_min,v_peak_mm_min" "block table")
expect_text("${csv}" "spiral.nc,23,line," "the loop's G01 block")
file(READ ${OUT}/feed.svg svg)
expect_text("${svg}" "feed, mm/min" "feed plot axis")
run_expect(0 "analyze text" ${NCURVE} analyze ${SRC}/examples/spiral.nc)
expect_text("${out}" "cycle time" "analyze text")
expect_text("${out}" "macro statements 604" "statements of the spiral loop: 6 per turn x 100 + 4")

run_expect(2 "no program" ${NCURVE} analyze)
run_expect(2 "bad gain" ${NCURVE} analyze circle --radius 50 --feed 100 --kv fast)
expect_text("${err}" "--kv" "bad gain message")
run_expect(2 "feed-forward above 1" ${NCURVE} analyze ${SRC}/examples/spiral.nc --servo --feed-forward 1.5)
run_expect(2 "circle feed-forward above 1" ${NCURVE} analyze circle --radius 50 --feed 100 --feed-forward 1.5)
run_expect(2 "negative radius" ${NCURVE} analyze circle --radius -5 --feed 100)
file(WRITE ${OUT}/bad_motion.toml "[motion]\nlook_ahead = -1\n")
run_expect(2 "bad profile" ${NCURVE} analyze ${SRC}/examples/spiral.nc --machine ${OUT}/bad_motion.toml)
expect_text("${err}" "bad_motion.toml:2:" "profile error position")
file(WRITE ${OUT}/alarm.nc "G01 X10.\nM30\n")
run_expect(1 "program alarm" ${NCURVE} analyze ${OUT}/alarm.nc)
expect_text("${err}" "PS0011" "feed zero alarm")

# shape error against the nominal spiral r = 1 + 2 theta: 100 equal 3.6 degree chords leave
# r (1 - cos 1.8 deg) = 6.69 um at the outer end (r = 13.57), plus IS-B rounding (< 0.71 um)
run_expect(0 "shape error" ${NCURVE} analyze ${SRC}/examples/spiral.nc --json --curve spiral --r0 1
           --pitch 12.566370614359172 --from 0 --to 360)
expect_text("${out}" "\"shape_error\"" "shape error json")
if(NOT out MATCHES "\"max_mm\": 0\\.00(669|6[7-9]|7[0-3])")
  message(SEND_ERROR "shape error is not the chord height of 3.6 degrees at r = 13.57: ${out}")
endif()
expect_text("${out}" "\"line\": 23" "worst block is the loop's G01")
run_expect(2 "unknown curve" ${NCURVE} analyze ${SRC}/examples/spiral.nc --curve trefoil)
expect_text("${err}" "no curve named 'trefoil'" "unknown curve message")
run_expect(2 "stray argument" ${NCURVE} analyze ${SRC}/examples/spiral.nc --r0 1)

# seed 000's models on the same spiral: Khan's arc is pi/(2 sqrt 2) = 1.1107 chords, so its total is
# 1.1107 x the contour (48.07 mm) = 53.39 mm; the true arc is the spiral's 48.08 mm
run_expect(0 "shape models" ${NCURVE} analyze ${SRC}/examples/spiral.nc --json --curve spiral --r0 1
           --pitch 12.566370614359172 --from 0 --to 360 --tol 0.005 --shape-csv ${OUT}/shape.csv
           --shape-plot ${OUT}/shape.svg)
foreach(key shape_models yang_chord_height joshi_radial narayan_arc khan_arc arc_length_mm blocks_beyond_tolerance)
  expect_text("${out}" "\"${key}\"" "analyze --curve --json")
endforeach()
if(NOT out MATCHES "\"khan_length_mm\": 53\\.39" OR NOT out MATCHES "\"arc_length_mm\": 48\\.08")
  message(SEND_ERROR "arc lengths are not the spiral's and 1.1107 x the chords: ${out}")
endif()
file(STRINGS ${OUT}/shape.csv rows)
list(LENGTH rows n)
if(NOT n EQUAL 101)
  message(SEND_ERROR "shape CSV has ${n} rows, not a header and 100 blocks")
endif()
list(GET rows 0 header)
expect_text("${header}" "line,kind,t0,t1,deviation_mm,chord_mm,arc_mm,radius_mm,yang_mm,joshi_mm,narayan_arc_mm,khan_arc_mm"
            "shape CSV header")
file(READ ${OUT}/shape.svg svg)
expect_text("${svg}" "tolerance 5 µm" "shape plot tolerance")
expect_text("${svg}" "X, mm" "shape plot axis")
run_expect(2 "shape plot without a curve" ${NCURVE} analyze ${SRC}/examples/spiral.nc --shape-plot ${OUT}/x.svg)
expect_text("${err}" "need a nominal curve" "shape options need --curve")

# checks that a file is well-formed XML, by Python's parser
function(expect_xml file what)
  if(NOT PYTHON3)
    message(SEND_ERROR "${what}: python3 was not found, so ${file} cannot be checked as XML (install python3)")
    return()
  endif()
  execute_process(COMMAND ${PYTHON3} -c "import sys, xml.dom.minidom; xml.dom.minidom.parse(sys.argv[1])" ${file}
                  RESULT_VARIABLE rc ERROR_VARIABLE e)
  if(NOT rc EQUAL 0)
    message(SEND_ERROR "${what}: ${file} is not well-formed XML: ${e}")
  endif()
endfunction()

# the contour error of cutting moves and of rapids apart. A move at 45 degrees with Kv X 30, Y 20
# runs beside its line by V/2 (1/20 - 1/30) once at speed: 0.138889 mm for the G01 at F1000,
# 2.946278 mm for the G00 back (each axis at 15000 mm/min: V = 15000 sqrt 2)
file(WRITE ${OUT}/diagonal.nc "G92 X0 Y0 Z0\nG90 G01 X50. Y50. F1000.\nG00 X-450. Y-450.\nM30\n")
run_expect(0 "contour errors" ${NCURVE} analyze ${OUT}/diagonal.nc --servo --kv 30,20 --json)
string(JSON cut_max GET "${out}" contour_error max_mm)
string(JSON cut_line GET "${out}" contour_error line)
string(JSON rapid_max GET "${out}" rapid_contour_error max_mm)
string(JSON rapid_line GET "${out}" rapid_contour_error line)
if(NOT cut_max MATCHES "^0\\.13888[89]" OR NOT cut_line EQUAL 2)
  message(SEND_ERROR "cutting contour error is not V/2 (1/Ky - 1/Kx) at F1000 on line 2: ${cut_max} at ${cut_line}")
endif()
if(NOT rapid_max MATCHES "^2\\.94627[89]" OR NOT rapid_line EQUAL 3)
  message(SEND_ERROR "rapid contour error is not V/2 (1/Ky - 1/Kx) at 15000 sqrt 2 on line 3: ${rapid_max} at ${rapid_line}")
endif()
run_expect(0 "contour errors text" ${NCURVE} analyze ${OUT}/diagonal.nc --servo --kv 30,20)
expect_text("${out}" "contour error, cutting max 0.138889 mm" "cutting contour error labelled")
expect_text("${out}" "contour error, rapids  max 2.946278 mm" "rapid contour error labelled")
expect_text("${out}" "Kv X 30 Y 20 /s" "gains")
# seed 000's spiral: the retract G00 Z5. (line 25) is a rapid, its corner no longer the contour's
run_expect(0 "spiral contour errors" ${NCURVE} analyze ${SRC}/examples/spiral.nc --servo --json)
string(JSON cut_line GET "${out}" contour_error line)
string(JSON rapid_line GET "${out}" rapid_contour_error line)
if(cut_line EQUAL 25 OR NOT rapid_line EQUAL 25)
  message(SEND_ERROR "spiral: the cutting moves' error is on line ${cut_line}, the rapids' on ${rapid_line} (G00 Z5. is 25)")
endif()

# a lathe names X (as a diameter) and Z: seed 003's hyperbola from ncurve gen, whose X words are
# diameters from 199.992 to 222.836 (radii would be under 112), and one approach move before it
run_expect(0 "lathe program" ${NCURVE} gen hyperbola --machine ${SRC}/profiles/fanuc-lathe.toml --tol 0.005
           -o ${OUT}/hyperbola.nc)
run_expect(0 "lathe analyze" ${NCURVE} analyze ${OUT}/hyperbola.nc --machine ${SRC}/profiles/fanuc-lathe.toml --servo
           --curve hyperbola --json --shape-plot ${OUT}/hyperbola.svg)
string(JSON axes GET "${out}" axes)
string(JSON x_at GET "${out}" contour_error at 0)
string(JSON shape_max GET "${out}" shape_error max_mm)
string(JSON approach GET "${out}" shape_error moves_set_aside 0)
if(NOT axes MATCHES "\"X\",[ ]*\"Z\"")
  message(SEND_ERROR "lathe axes are not X and Z: ${axes}")
endif()
if(x_at LESS 199 OR x_at GREATER 223)
  message(SEND_ERROR "lathe contour error position X ${x_at} is not a diameter of the program's")
endif()
if(NOT shape_max MATCHES "^0\\.00[0-4][0-9]*" AND NOT shape_max MATCHES "^0\\.005$" OR NOT approach EQUAL 1)
  message(SEND_ERROR "hyperbola: shape error ${shape_max} beyond gen's 0.005 mm, or ${approach} approach moves, not 1")
endif()
run_expect(0 "lathe analyze text" ${NCURVE} analyze ${OUT}/hyperbola.nc --machine ${SRC}/profiles/fanuc-lathe.toml
           --servo --curve hyperbola)
expect_text("${out}" "Kv X 30 Z 30 /s" "lathe gains named X and Z")
expect_text("${out}" "X(dia) 2" "lathe positions with X as a diameter")
if(out MATCHES " Y [-0-9]")
  message(SEND_ERROR "lathe text names a Y axis: ${out}")
endif()
file(READ ${OUT}/hyperbola.svg svg)
expect_text("${svg}" ">Z, mm" "lathe shape plot across")
expect_text("${svg}" ">X (radius), mm" "lathe shape plot up")
run_expect(0 "lathe circle" ${NCURVE} analyze circle --machine ${SRC}/profiles/fanuc-lathe.toml --radius 50 --feed 5000
           --kv 30,25 --json)
# Z (the plane's first axis) lags more: the smallest radius at 135 (315) degrees from +Z towards +X,
# roundness V (1/25 - 1/30) = 0.556 mm
expect_text("${out}" "\"plane\": \"ZX\"" "lathe circle plane")
if(NOT out MATCHES "\"max_deviation_angle\": (13[2-9]|31[2-9])\\." OR NOT out MATCHES "\"roundness\": 0\\.55")
  message(SEND_ERROR "lathe circle: not the ellipse of Z lagging: ${out}")
endif()

# the circle's angle means nothing when the two axes respond alike
run_expect(0 "circle equal gains" ${NCURVE} analyze circle --radius 50 --feed 5000 --json --plot ${OUT}/circle_equal.svg)
expect_text("${out}" "\"angle_meaningful\": false" "equal gains")
file(READ ${OUT}/circle_equal.svg svg)
expect_text("${svg}" "X and Y respond alike: the circle only shrinks" "equal gains diagram")
if(svg MATCHES "smallest radius at")
  message(SEND_ERROR "the equal-gains diagram marks an angle")
endif()
run_expect(0 "circle equal gains text" ${NCURVE} analyze circle --radius 50 --feed 5000)
expect_text("${out}" "smallest radius at  no particular angle: X and Y respond alike" "equal gains text")
if(out MATCHES "held to")
  message(SEND_ERROR "F5000 is within the profile's limits, yet the text says the feed is held: ${out}")
endif()
run_expect(0 "circle unequal gains" ${NCURVE} analyze circle --radius 50 --feed 5000 --kv 25,30 --json
           --plot ${OUT}/circle_unequal.svg)
expect_text("${out}" "\"angle_meaningful\": true" "unequal gains")
file(READ ${OUT}/circle_unequal.svg svg)
if(NOT svg MATCHES "smallest radius at (13[2-9]|31[2-9])\\.")
  message(SEND_ERROR "unequal gains: the diagram does not mark the ellipse's angle: ${svg}")
endif()
# above the profile's cutting feed (10000 mm/min) the circle runs at 10000: the first-order loop's
# steady state R (1 - 1/sqrt(1 + (V/(R Kv))^2)) = 0.3058 mm (20000 would give 1.18 mm)
run_expect(0 "circle above the cutting feed" ${NCURVE} analyze circle --radius 50 --feed 20000 --json)
if(NOT out MATCHES "\"feed_reached\": 10000" OR NOT out MATCHES "\"radius_reduction\": 0\\.305[89]")
  message(SEND_ERROR "circle above the cutting feed: not run at 10000 mm/min: ${out}")
endif()
run_expect(2 "circle too long to simulate" ${NCURVE} analyze circle --radius 1000000 --feed 1)
expect_text("${err}" "simulated at most: raise the feed or lower the radius" "circle too long")

# a program compared with the wrong curve, or the right curve with other parameters
run_expect(1 "wrong curve" ${NCURVE} analyze ${SRC}/examples/spiral.nc --curve ellipse)
expect_text("${err}" "the path does not follow the curve ellipse: it is " "wrong curve")
expect_text("${err}" "check --curve and its parameters" "wrong curve advice")
# the spiral starts at r = 1 (X1. Y0.): a curve starting at r0 = 5 is 4 mm from it
run_expect(1 "wrong parameters" ${NCURVE} analyze ${SRC}/examples/spiral.nc --curve spiral --r0 5)
expect_text("${err}" "the path does not follow the curve spiral: it is 4 mm away at line 23 of" "wrong parameters")
if(out MATCHES "um")
  message(SEND_ERROR "wrong parameters: model values printed: ${out}")
endif()

# numeric options: NaN, infinities and bad ranges refused in the option's unit
foreach(case "--radius;nan;--radius: must be a length above 0 mm, got nan"
             "--feed;inf;--feed: must be a feed above 0 mm/min, got inf"
             "--feed-forward;nan;--feed-forward: must be a number from 0 to 1, got nan"
             "--kv;30,nan;--kv: must be a gain above 0 /s, got nan")
  list(GET case 0 option)
  list(GET case 1 value)
  list(GET case 2 message)
  set(args --radius 50 --feed 100)
  list(FIND args ${option} at)
  if(at GREATER -1)
    math(EXPR next "${at} + 1")
    list(REMOVE_AT args ${next})
    list(INSERT args ${next} ${value})
  else()
    list(APPEND args ${option} ${value})
  endif()
  run_expect(2 "circle ${option} ${value}" ${NCURVE} analyze circle ${args})
  expect_text("${err}" "${message}" "circle ${option} ${value}")
endforeach()
run_expect(2 "analyze feed-forward nan" ${NCURVE} analyze ${SRC}/examples/spiral.nc --servo --feed-forward nan)
expect_text("${err}" "--feed-forward: must be a number from 0 to 1, got nan" "program feed-forward")
run_expect(2 "analyze tol inf" ${NCURVE} analyze ${SRC}/examples/spiral.nc --curve spiral --tol inf)
expect_text("${err}" "--tol: must be a length above 0 mm, got inf" "tolerance")
if(err MATCHES "[0-9]{20}")
  message(SEND_ERROR "a range bound printed in full: ${err}")
endif()

# plots escape their text: a program named with & < > " ' and a Latin-1 byte (not UTF-8), and a
# machine named with markup, still give well-formed SVG showing the name escaped
string(ASCII 233 latin1)
string(ASCII 239 191 189 replacement)  # U+FFFD in UTF-8
set(weird "${OUT}/w&<b>\"q'${latin1}")
set(escaped "w&amp;&lt;b&gt;&quot;q&apos;${replacement}")
file(COPY_FILE ${SRC}/examples/spiral.nc "${weird}.nc")
run_expect(0 "plots of an oddly named program" ${NCURVE} analyze "${weird}.nc" --plot "${weird}-feed.svg" --curve spiral
           --r0 1 --pitch 12.566370614359172 --shape-plot "${weird}-shape.svg")
foreach(plot feed shape)
  expect_xml("${weird}-${plot}.svg" "${plot} plot")
  file(READ "${weird}-${plot}.svg" svg)
  expect_text("${svg}" "${escaped}.nc" "${plot} plot title")
endforeach()
run_expect(0 "json of an oddly named program" ${NCURVE} analyze "${weird}.nc" --json)
expect_text("${out}" "q'${replacement}.nc" "program name in JSON")
file(WRITE ${OUT}/odd_machine.toml "[machine]\nname = \"mill <5 & 'fast'> \\\"A\\\"\"\n")
run_expect(0 "circle plot of an oddly named machine" ${NCURVE} analyze circle --radius 50 --feed 5000 --kv 25,30
           --machine ${OUT}/odd_machine.toml --plot "${weird}-circle.svg")
expect_xml("${weird}-circle.svg" "circle plot")
file(READ "${weird}-circle.svg" svg)
expect_text("${svg}" "mill &lt;5 &amp; &apos;fast&apos;&gt; &quot;A&quot;" "circle plot machine name")

# the radial model measures along rays from the curve's origin; the parabola y = x^2/40 passes
# through it, where a ray runs along the blocks: the model is said not to apply, not printed in km
run_expect(0 "parabola program" ${NCURVE} gen parabola --tol 0.01 -o ${OUT}/parabola.nc)
run_expect(0 "parabola models" ${NCURVE} analyze ${OUT}/parabola.nc --curve parabola --json)
string(JSON joshi GET "${out}" shape_models joshi_radial applies)
string(JSON yang GET "${out}" shape_models yang_chord_height applies)
if(joshi OR NOT yang)
  message(SEND_ERROR "parabola: the radial model applies (${joshi}) or the chord height does not (${yang})")
endif()
run_expect(0 "parabola models text" ${NCURVE} analyze ${OUT}/parabola.nc --curve parabola)
expect_text("${out}" "radial shape error, Joshi eqs 8-11      does not apply here: off by" "radial model")
# a curve undefined on part of its range (the square root of a negative number below t = 100)
run_expect(1 "undefined curve" ${NCURVE} analyze ${SRC}/examples/spiral.nc --curve expr --x "SQRT[t-100]" --y 0
           --t 0:360)
expect_text("${err}" "the curve expr is undefined at t = 0; check --curve and its parameters" "undefined curve")

# a program under cutter compensation (G41 D1 R5) cutting two 45-degree chords of a quarter circle
# R20: the tool's path, 5 mm inside with its G40 lead-out, does not follow the circle, and the
# message offers --programmed; the chords as programmed deviate 20 - 20 x 14.142 / sqrt(5.858^2 +
# 14.142^2) = 1.522498 mm (the distance of each chord's line from the centre), lead-in and
# lead-out set aside
set(chords ${SRC}/tests/programs/compensation/cc_quarter_chords.nc)
set(circle --curve expr --x "20*COS[t]" --y "20*SIN[t]" --t 0:90)
run_expect(1 "compensated tool path" ${NCURVE} analyze ${chords} ${circle})
expect_text("${err}" "the path measured is the tool's, radius compensation applied (G41/G42): --programmed measures the contour as programmed"
            "the tool path is named and the programmed contour offered")
run_expect(0 "programmed contour" ${NCURVE} analyze ${chords} ${circle} --programmed --json)
string(JSON chord_max GET "${out}" shape_error max_mm)
string(JSON chord_path GET "${out}" shape_error path)
string(JSON chord_blocks GET "${out}" shape_error blocks)
string(JSON aside_before GET "${out}" shape_error moves_set_aside 0)
string(JSON aside_after GET "${out}" shape_error moves_set_aside 1)
if(NOT chord_max MATCHES "^1\\.52249[7-8]" OR NOT chord_path STREQUAL "programmed" OR NOT chord_blocks EQUAL 2
   OR NOT aside_before EQUAL 1 OR NOT aside_after EQUAL 1)
  message(SEND_ERROR "programmed chords: max ${chord_max} (1.522498 by hand), path ${chord_path}, ${chord_blocks} "
                     "blocks, set aside ${aside_before} and ${aside_after}")
endif()
run_expect(0 "programmed contour text" ${NCURVE} analyze ${chords} ${circle} --programmed)
expect_text("${out}" "  path measured     the contour as programmed" "the text says which path")
# a program without compensation: its path is the program's
run_expect(0 "plain path json" ${NCURVE} analyze ${SRC}/examples/spiral.nc --curve spiral --json)
string(JSON plain_path GET "${out}" shape_error path)
if(NOT plain_path STREQUAL "programmed")
  message(SEND_ERROR "spiral.nc: shape_error.path is ${plain_path}")
endif()
# a full circle R20 about X0 Y0 cut under G41 D1 R5 from the centre and back (its only contour
# move the arc): as programmed, the circle itself, 0 mm from it
run_expect(0 "programmed full circle" ${NCURVE} analyze ${SRC}/tests/programs/compensation/cc_circle_pocket.nc --curve expr
           --x "20*COS[t]" --y "20*SIN[t]" --t 0:360 --programmed --json)
string(JSON circle_max GET "${out}" shape_error max_mm)
string(JSON circle_blocks GET "${out}" shape_error blocks)
if(circle_max GREATER 1e-9 OR NOT circle_blocks EQUAL 1)
  message(SEND_ERROR "the programmed full circle: max ${circle_max} mm over ${circle_blocks} blocks (0 over 1 by hand)")
endif()
# a lathe under G42 with tip 3 (nose R0.8): the convex arc R5 from X10 Z0 to X20 Z-5 (diameters)
# about X10 Z-5, as programmed, is the curve Z = -5 + 5 cos t, X/2 = 5 + 5 sin t itself: 0 mm
run_expect(0 "programmed lathe arc" ${NCURVE} analyze ${SRC}/tests/programs/nose/nt_arc_t3.nc
           --machine ${SRC}/tests/programs/nose/nt_arc_t3.toml --curve expr --x "-5+5*COS[t]" --y "5+5*SIN[t]" --t 0:90
           --programmed --json)
string(JSON arc_max GET "${out}" shape_error max_mm)
string(JSON arc_blocks GET "${out}" shape_error blocks)
if(arc_max GREATER 1e-9 OR NOT arc_blocks EQUAL 1)
  message(SEND_ERROR "the programmed lathe arc: max ${arc_max} mm over ${arc_blocks} blocks (0 over 1 by hand)")
endif()
