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
