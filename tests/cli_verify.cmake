# ncurve run --setup / --verify / --part: the summary's verify section, a finding in the text and
# the JSON, the part's STL, and the refusals (a lathe's part, a bad setup, the part over an input).
include(${CMAKE_CURRENT_LIST_DIR}/cli_helpers.cmake)

# the shipped spiral with its setup: 40 x 40 x 20 block, T1 3 mm, nothing goes wrong
run_expect(0 "run --setup" ${NCURVE} run ${SRC}/examples/spiral.nc --setup ${SRC}/examples/spiral.setup.toml
           --part ${OUT}/spiral-part.stl)
expect_text("${out}" "stock          box X-20..20 Y-20..20 Z-20..0" "the setup's stock")
expect_text("${out}" "Z-map          1000 x 1000 cells of 0.0400 mm" "1000 cells on the shorter side")
expect_text("${out}" "findings       0" "no finding")
expect_text("${out}" "part           ${OUT}/spiral-part.stl" "the part named")
file(SIZE ${OUT}/spiral-part.stl size)
# 999 x 999 quads on top (2 each), 4 x 999 boundary edges (a wall's 2 and the bottom's 1 each)
math(EXPR want "84 + 50 * (2 * 999 * 999 + 3 * 4 * 999)")
if(NOT size EQUAL want)
  message(SEND_ERROR "spiral-part.stl: ${size} bytes, expected ${want}")
endif()

# a rapid into the block: the finding in the text and in --json with where and how deep
file(WRITE ${OUT}/verify-rapid.nc "T1 M06\nM03 S1000\nG90 G00 X0 Y0 Z5.\nG00 Z-0.3\nG01 X5. F300.\nG00 Z5.\nM30\n")
run_expect(0 "a rapid into the stock" ${NCURVE} run ${OUT}/verify-rapid.nc --setup ${SRC}/examples/spiral.setup.toml)
expect_text("${out}" "verify-rapid.nc:4:1: warning: NC2080 a rapid removes material: 0.300 mm deep" "NC2080 in the text")
expect_text("${out}" "G00 Z-0.3" "the block quoted")
expect_text("${out}" "findings       1" "one finding")
run_expect(0 "the finding in --json" ${NCURVE} run ${OUT}/verify-rapid.nc --setup ${SRC}/examples/spiral.setup.toml --json)
expect_text("${out}" "\"verify\": {" "verify object")
expect_text("${out}" "\"code\": \"NC2080\"" "the finding's code")
if(NOT out MATCHES "\"amount\": 0\\.(3|29999999)")
  message(SEND_ERROR "how deep: no amount of 0.3 in:\n${out}")
endif()
expect_text("${out}" "\"volume_removed_mm3\"" "the volume")

# without a setup: the defaults stated, the stock the box around the cutting moves
run_expect(0 "run --verify without a setup" ${NCURVE} run ${OUT}/verify-rapid.nc --verify --set "#100=0")
expect_text("${out}" "setup          none (the defaults below)" "no setup")
expect_text("${out}" "default        stock: the box around the cutting moves" "the default stock stated")
expect_text("${out}" "T1: not in the library and no D offset in force when it cut: not cut" "a tool of no size")

# refusals
# a lathe: the bar's half-section cut by each tool, the part revolved as an STL whose size is its count's
run_expect(0 "a lathe's part" ${NCURVE} run ${SRC}/examples/lathe-mrc.nc --machine fanuc-lathe
           --setup ${SRC}/examples/lathe-mrc.setup.toml --part ${OUT}/lathe.stl)
expect_text("${out}" "stock          cylinder D50, 100 long from Z0" "the lathe's stock")
expect_text("${out}" "section        the bar's half-section" "the half-section")
expect_text("${out}" "part           ${OUT}/lathe.stl" "the lathe's part named")
# the chuck jaw's box (X25..45, Y-10..10) as the ring it sweeps, out to its corner sqrt(45^2 + 10^2)
expect_text("${out}" "fixture        chuck jaw: checked, the ring Z-100..-75 at radius 25..46.0977" "the lathe's jaw checked")
expect_text("${out}" "findings       0 (a lathe's" "the shipped lathe example clean")
file(READ ${OUT}/lathe.stl header LIMIT 4 OFFSET 80 HEX)
string(SUBSTRING "${header}" 6 2 b3)
string(SUBSTRING "${header}" 4 2 b2)
string(SUBSTRING "${header}" 2 2 b1)
string(SUBSTRING "${header}" 0 2 b0)
math(EXPR triangles "0x${b3}${b2}${b1}${b0}")
file(SIZE ${OUT}/lathe.stl size)
math(EXPR want "84 + 50 * ${triangles}")
if(NOT size EQUAL want OR triangles LESS 1000)
  message(SEND_ERROR "lathe.stl: ${size} bytes for ${triangles} triangles")
endif()
# without a setup, a lathe's default stock: the bar round the cutting moves
run_expect(0 "a lathe without a setup" ${NCURVE} run ${SRC}/examples/lathe-thread.nc --machine fanuc-lathe --verify)
expect_text("${out}" "(the bar round the cutting moves)" "the default bar said")
expect_text("${out}" "default        stock: the bar about the spindle axis" "the default bar's rule stated")
file(WRITE ${OUT}/bad.setup.toml "[stock]\nshape = \"box\"\nmin = [0, 0, 0]\nmax = [10, -5, 1]\n")
run_expect(2 "a bad setup" ${NCURVE} run ${SRC}/examples/spiral.nc --setup ${OUT}/bad.setup.toml)
expect_text("${err}" "bad.setup.toml:4:7: error:" "the setup's error at its place")
run_expect(2 "--part over the program" ${NCURVE} run ${OUT}/verify-rapid.nc --verify --setup ${SRC}/examples/spiral.setup.toml
           --part ${OUT}/verify-rapid.nc)
run_expect(2 "--part over the setup" ${NCURVE} run ${OUT}/verify-rapid.nc --setup ${OUT}/bad.setup.toml --part ${OUT}/bad.setup.toml)
run_expect(2 "--part to standard output" ${NCURVE} run ${SRC}/examples/spiral.nc --part -)
expect_text("${err}" "--part needs a file of its own" "--part -")

# every shipped mill example with its setup: verified, nothing found (a finding there is a fault of
# the example or a false alarm); the 4-axis one refused, saying why
foreach(example "custom-cycle;--lib;${SRC}/macros;--param;6050=102" "inch" "alarm;--set;#100=2" "spiral")
  list(POP_FRONT example name)
  run_expect(0 "${name} with its setup" ${NCURVE} run ${SRC}/examples/${name}.nc --setup ${SRC}/examples/${name}.setup.toml
             ${example})
  expect_text("${out}" "findings       0" "${name}: no finding")
endforeach()
run_expect(0 "4-axis with its setup" ${NCURVE} run ${SRC}/examples/4-axis.nc --setup ${SRC}/examples/4-axis.setup.toml
           --machine ${SRC}/profiles/fanuc-4axis-helicoid.toml)
expect_text("${out}" "verified       no: the program turns the A axis" "4-axis: refused, saying why")
