# ncurve run / analyze --curve: the cut part's walls against the design's curve. Expected values:
# the seeds' chord error of the first paper's spiral (100 equal-angle chords: 6.9 um), and a G41
# ellipse pocket whose D offset is 0.02 under the cutter's radius (the wall 0.02 out, less a chord's
# sagitta of at most c^2 / 8 rho = 0.003 mm at 2-degree steps).
include(${CMAKE_CURRENT_LIST_DIR}/cli_helpers.cmake)

# the spiral groove: within 0.01 clean, at 0.005 both walls found off by about the chord error
run_expect(0 "spiral's walls" ${NCURVE} run ${SRC}/examples/spiral.nc --setup ${SRC}/examples/spiral.setup.toml
           --curve spiral)
expect_text("${out}" "curve          spiral (groove: the tool's axis on the curve)" "a groove measured")
expect_text("${out}" "0 points beyond the tolerance" "within 0.01")
run_expect(0 "spiral's walls at 5 um" ${NCURVE} run ${SRC}/examples/spiral.nc --setup ${SRC}/examples/spiral.setup.toml
           --curve spiral --tol 0.005 --json)
foreach(code NC2087 NC2088)
  if(NOT out MATCHES "\"amount\": 0\\.00(6[5-9]|7[0-9])[0-9]*,[^}]*\"code\": \"${code}\"")
    message(SEND_ERROR "${code}: no finding of 6.5..8 um in:\n${out}")
  endif()
endforeach()
expect_text("${out}" "\"largest_gouge_mm\"" "the JSON's walls")

# a G41 ellipse pocket, the D offset set by #9
file(WRITE ${OUT}/ellipse-pocket.nc "%\nO2000\nG21 G17 G90 G54\n#2001=#9\nS3000 M03\nG00 X0 Y0 Z5.\nG01 Z-2. F100.\n"
     "G41 G01 X20. Y0 D1 F300.\n#1=0\nWHILE [#1 LT 360] DO1\n#1=#1+2.\nG01 X[20*COS[#1]] Y[12*SIN[#1]]\nEND1\n"
     "G40 G01 X0 Y0\nG00 Z5.\nM30\n%\n")
file(WRITE ${OUT}/ellipse-pocket.setup.toml "tool_in_spindle = 1\n[stock]\nshape = \"box\"\nmin = [-30, -20, -10]\n"
     "max = [30, 20, 0]\n[tools.1]\nkind = \"flat\"\ndiameter = 6\nflute_length = 15\n")
set(pocket ${NCURVE} run ${OUT}/ellipse-pocket.nc --setup ${OUT}/ellipse-pocket.setup.toml --curve ellipse --a 20 --b 12)
run_expect(0 "D equal to the radius" ${pocket} --set "#9=3")
expect_text("${out}" "(edge: the part's wall on the curve)" "G41: the curve is the edge")
expect_text("${out}" "; findings 0" "within 0.01")
run_expect(0 "D 0.02 under the radius" ${pocket} --set "#9=2.98")
if(NOT out MATCHES "warning: NC2087 the cut goes 0\\.02[0-3][0-9] mm beyond the design's wall")
  message(SEND_ERROR "D 2.98: no gouge of 0.020..0.024 in:\n${out}")
endif()
run_expect(0 "D 0.05 over the radius" ${pocket} --set "#9=3.05")
if(NOT out MATCHES "warning: NC2088 the cut stops 0\\.05[0-3][0-9] mm short of the design's wall")
  message(SEND_ERROR "D 3.05: no stock left of 0.050..0.054 in:\n${out}")
endif()
run_expect(0 "--wall groove on the same" ${pocket} --set "#9=3" --wall groove)
expect_text("${out}" "(groove: the tool's axis on the curve)" "--wall chooses")

# analyze --curve: the path's shape error and the cut part's
run_expect(0 "analyze's cut part" ${NCURVE} analyze ${SRC}/examples/spiral.nc --curve spiral
           --setup ${SRC}/examples/spiral.setup.toml)
expect_text("${out}" "cut part          75.6 mm^3 (T1 75.6) removed from the stock of" "the volume by tool")
expect_text("${out}" "beyond design     0.00" "the gouge")

# refusals
# a lathe: the G71/G70 example's diameter 30 (Z-20..-35) against the design 0.02 above it, a gouge
run_expect(0 "a lathe's surface" ${NCURVE} run ${SRC}/examples/lathe-mrc.nc --machine fanuc-lathe
           --setup ${SRC}/examples/lathe-mrc.setup.toml --curve expr --x 15.02 --z t --t -34:-21)
expect_text("${out}" "(edge: the part's wall on the curve)" "a lathe's surface is an edge")
if(NOT out MATCHES "warning: NC2087 the cut goes 0\\.020[0-1] mm beyond the design's wall at t = [-0-9.e]+ of the curve \\(Z-[0-9.]+, radius 15\\.0200\\)")
  message(SEND_ERROR "a lathe: no gouge of 0.020 in:\n${out}")
endif()
run_expect(2 "a parameter not of the curve" ${NCURVE} run ${SRC}/examples/spiral.nc --curve spiral --pich 3)
expect_text("${err}" "did you mean --pitch?" "the parameter suggested")
run_expect(2 "an argument without --curve" ${NCURVE} run ${SRC}/examples/spiral.nc --verfy)
expect_text("${err}" "unexpected argument '--verfy' (did you mean --verify?)" "the option suggested")
