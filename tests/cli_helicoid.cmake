# ncurve helicoid as a user runs it: seed 004's table with its sanity values, the documented CSV
# and JSON columns, a program that runs under ncurve run, and errors for incomplete input.
include(${CMAKE_CURRENT_LIST_DIR}/cli_helpers.cmake)

run_expect(0 "helicoid seed004 csv" ${NCURVE} helicoid --example seed004 --csv)
expect_text("${out}" "psi_deg,A_mm,u_deg,r_mm,x_mm,y_mm,z_mm," "csv header")
expect_text("${out}" "evaluations,plane_A_mm,plane_error_mm,cusp_mm" "csv header")
expect_text("${out}" "\n0.000000,161.5000000," "A(0) = 35.5 + 126")
expect_text("${out}" "\n36.000000,176.5000000," "A(36) = 50.5 + 126")
expect_text("${out}" "\n72.000000,161.5000000," "A(72) = A(0)")

run_expect(0 "helicoid json" ${NCURVE} helicoid --example seed004 --step 6 --json --program ${OUT}/rotor.nc
           --plot ${OUT}/rotor.svg)
foreach(key psi_deg A_mm u_deg r_mm x_mm y_mm z_mm cutter_x_mm cutter_alpha_deg cutter_s_mm evaluations plane_A_mm
        plane_error_mm mean_evaluations)
  expect_text("${out}" "\"${key}\"" "helicoid --json")
endforeach()
file(READ ${OUT}/rotor.svg svg)
expect_text("${svg}" "<svg" "plot")
expect_text("${svg}" "plane method" "plot")
run_expect(0 "run the rotor program" ${NCURVE} run ${OUT}/rotor.nc --machine ${SRC}/profiles/fanuc-4axis-helicoid.toml
           --format csv)
expect_text("${out}" ",line,161.500000,0.000000,0.000000," "first pass at A(0)")
expect_text("${out}" ",line,176.500000,0.000000," "pass at A(36)")

# the program fitted to a cusp tolerance: fewer passes than steps, each a helical pass that runs
run_expect(0 "helicoid program within a cusp tolerance" ${NCURVE} helicoid --example seed004 --step 0.5 --to 36
           --program-tol 0.05 --program ${OUT}/rotor_tol.nc --json)
string(REGEX MATCH "\"passes\": ([0-9]+)" passes "${out}")
set(passes ${CMAKE_MATCH_1})
if(NOT passes OR passes GREATER_EQUAL 73 OR passes LESS 10)
  message(SEND_ERROR "--program-tol 0.05: expected fewer passes than the 73 steps: ${passes}")
endif()
expect_text("${out}" "\"cusp_mm\"" "json cusp column")
file(READ ${OUT}/rotor_tol.nc prog)
expect_text("${prog}" "(${passes} PASSES OF 73 STEPS, CUSPS WITHIN 0.05 MM)" "program header")
string(REGEX MATCHALL "G01 Z" cuts "${prog}")
list(LENGTH cuts cut_count)
if(NOT cut_count EQUAL passes)
  message(SEND_ERROR "program has ${cut_count} passes, the JSON says ${passes}")
endif()
run_expect(0 "run the fitted rotor program" ${NCURVE} run ${OUT}/rotor_tol.nc --machine
           ${SRC}/profiles/fanuc-4axis-helicoid.toml)
expect_text("${out}" "completed" "fitted program runs")
run_expect(1 "cusp tolerance below what the step allows" ${NCURVE} helicoid --example seed004 --step 3 --program-tol 0.01)
expect_text("${err}" "make the psi step smaller" "coarse step for the tolerance")

# final motion along Z at a fixed centre distance: the same contact for every psi, shifted along Z
run_expect(0 "helicoid final motion z" ${NCURVE} helicoid --example seed004 --final-motion z- --centre-distance 170
           --step 6 --to 12 --csv --program ${OUT}/rotor_z.nc)
expect_text("${out}" "cusp_mm,Z_mm" "csv Z column")
expect_text("${out}" "\n0.000000,170.0000000," "A is the fixed centre distance")
expect_text("${out}" ",-45.830" "Z where the cutter touches at psi 0")
expect_text("${out}" ",-60.163" "Z at psi 6: 6 deg / (360 / 860 mm) further")
run_expect(0 "run the z-motion program" ${NCURVE} run ${OUT}/rotor_z.nc --machine ${SRC}/profiles/fanuc-4axis-helicoid.toml
           --format csv)
expect_text("${out}" ",line,170.000000,0.000000,0.000000," "passes at the centre distance")
run_expect(0 "helicoid final motion z over centre distances" ${NCURVE} helicoid --example seed004 --final-motion z-
           --centre-distance 162:176:7 --csv)
expect_text("${out}" "\n0.000000,162.0000000," "first centre distance")
expect_text("${out}" "\n0.000000,169.0000000," "second centre distance")
expect_text("${out}" "\n0.000000,176.0000000," "last centre distance")
run_expect(2 "bad centre distance range" ${NCURVE} helicoid --example seed004 --final-motion z- --centre-distance 162:x)
expect_text("${err}" "--centre-distance '162:x': give A or FROM:TO:STEP" "bad range")
run_expect(2 "z motion without a centre distance" ${NCURVE} helicoid --example seed004 --final-motion z-)
expect_text("${err}" "need --centre-distance" "z motion needs a centre distance")
run_expect(1 "z motion start not clear" ${NCURVE} helicoid --example seed004 --final-motion z+ --centre-distance 170
           --start-z 0 --from 36 --to 36)
expect_text("${err}" "psi = 36 deg: the cutter at centre distance 170 mm and Z = 0 mm is not clear" "start not clear")

run_expect(0 "helicoid any profile" ${NCURVE} helicoid --profile-x "40*COS[u]" --profile-y "30*SIN[u]" --lead 500
           --lobes 2 --cutter-diameter 200 --corner-radius 1 --included-angle 40 --step 15)
expect_text("${out}" "   0.000   140.000000" "ellipse: A(0) = a + R")

run_expect(2 "profile without lead" ${NCURVE} helicoid --profile ellipse)
expect_text("${err}" "--lead is needed" "missing lead")
run_expect(2 "no profile" ${NCURVE} helicoid)
expect_text("${err}" "--example seed004" "no profile")

# the seed's rotor as 360 points (periodic spline) and its insert as a general cutter profile
run_expect(0 "helicoid point profile and general cutter" ${NCURVE} helicoid --profile-csv ${SRC}/examples/rotor-points.csv
           --lead 860 --lobes 5 --cutter-profile ${SRC}/examples/seed004-insert.csv --start-distance 177.7 --step 36 --csv)
# within a micrometre (the points carry 6 decimals)
if(NOT out MATCHES "\n0\\.000000,161\\.(4999|5000)" OR NOT out MATCHES "\n36\\.000000,176\\.(4999|5000)")
  message(SEND_ERROR "point profile: A(0) is not 35.5 + 126 or A(36) not 50.5 + 126: ${out}")
endif()
file(WRITE ${OUT}/bad_cutter.csv "rho,w\n120,-3,0.5\n120,3\n")
run_expect(2 "bad cutter profile" ${NCURVE} helicoid --example seed004 --cutter-profile ${OUT}/bad_cutter.csv)
expect_text("${err}" "bad_cutter.csv:2:1: arc radius 0.5 is less than half the chord" "cutter profile error")
run_expect(2 "cutter profile and insert" ${NCURVE} helicoid --example seed004 --cutter-profile
           ${SRC}/examples/seed004-insert.csv --corner-radius 2)
expect_text("${err}" "leave out --cutter-diameter" "two cutters")
file(WRITE ${OUT}/bad_points.csv "x,y\n40,0\n0,40\n-40,zero\n")
run_expect(2 "bad point profile" ${NCURVE} helicoid --profile-csv ${OUT}/bad_points.csv --lead 500)
expect_text("${err}" "bad_points.csv:4:5: 'zero' is not a number" "point profile error")

# numeric options: NaN, infinities and bad ranges refused in the option's unit
run_expect(2 "step nan" ${NCURVE} helicoid --example seed004 --step nan)
expect_text("${err}" "--step: must be an angle above 0 degrees, got nan" "step nan")
run_expect(2 "lead nan" ${NCURVE} helicoid --example seed004 --lead nan)
expect_text("${err}" "--lead: must be a length of 0 mm or more, got nan" "lead nan")
run_expect(2 "included angle 180" ${NCURVE} helicoid --example seed004 --included-angle 180)
expect_text("${err}" "--included-angle: must be an angle above 0 and below 180 degrees, got 180" "included angle")
run_expect(2 "lobes 2.5" ${NCURVE} helicoid --example seed004 --lobes 2.5)
expect_text("${err}" "--lobes: must be a whole number of 1 or more, got 2.5" "lobes")
run_expect(2 "feed overflow" ${NCURVE} helicoid --example seed004 --feed 1e999 --program ${OUT}/never.nc)
expect_text("${err}" "--feed: must be a feed from 0.001 to 99999 mm/min, got 1e999" "feed overflow")
run_expect(2 "u nan" ${NCURVE} helicoid --profile-x "40*COS[u]" --profile-y "30*SIN[u]" --u nan:360 --lead 500)
expect_text("${err}" "--u 'nan:360': give FROM:TO in degrees" "u range")
run_expect(2 "psi backwards" ${NCURVE} helicoid --example seed004 --from 10 --to 5)
expect_text("${err}" "--to (5 deg) is before --from (10 deg)" "psi backwards")
run_expect(2 "psi steps beyond count" ${NCURVE} helicoid --example seed004 --step 1e-300)
expect_text("${err}" "raise --step" "too many steps")

# the plot escapes its title: a profile file named with & < > " ' and a Latin-1 byte (not UTF-8)
# gives well-formed SVG showing the name escaped, and JSON with the byte replaced
string(ASCII 233 latin1)
string(ASCII 239 191 189 replacement)  # U+FFFD in UTF-8
set(weird "${OUT}/p&<b>\"q'${latin1}")
file(COPY_FILE ${SRC}/examples/rotor-points.csv "${weird}.csv")
run_expect(0 "plot of an oddly named profile" ${NCURVE} helicoid --profile-csv "${weird}.csv" --lead 860 --lobes 5
           --cutter-diameter 252 --corner-radius 1.2 --included-angle 35 --start-distance 177.7 --step 12 --json
           --plot "${weird}.svg")
expect_text("${out}" "q'${replacement}.csv" "profile name in JSON")
if(NOT PYTHON3)
  message(SEND_ERROR "python3 was not found, so the helicoid plot cannot be checked as XML (install python3)")
else()
  execute_process(COMMAND ${PYTHON3} -c "import sys, xml.dom.minidom; xml.dom.minidom.parse(sys.argv[1])" "${weird}.svg"
                  RESULT_VARIABLE rc ERROR_VARIABLE e)
  if(NOT rc EQUAL 0)
    message(SEND_ERROR "helicoid plot of an oddly named profile is not well-formed XML: ${e}")
  endif()
endif()
file(READ "${weird}.svg" svg)
expect_text("${svg}" "p&amp;&lt;b&gt;&quot;q&apos;${replacement}.csv" "helicoid plot title")
