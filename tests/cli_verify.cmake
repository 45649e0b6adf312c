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

# --design: a 40 x 40 block 0.5 above a design whose top is Z0, a slot 0.5 below it; the slot's block
# gouges the design by 0.5 (no design cell is that low: the vertical amount), and the uncut top is
# 0.5 of stock left, said at M30; each cell 0.04 mm (the shorter side in 1000)
function(ascii_box out x0 x1 y0 y1 z0 z1)  # an ASCII STL of a box, two facets a side
  set(quads "${x0} ${y0} ${z0},${x0} ${y1} ${z0},${x1} ${y1} ${z0},${x1} ${y0} ${z0}"
            "${x0} ${y0} ${z1},${x1} ${y0} ${z1},${x1} ${y1} ${z1},${x0} ${y1} ${z1}"
            "${x0} ${y0} ${z0},${x1} ${y0} ${z0},${x1} ${y0} ${z1},${x0} ${y0} ${z1}"
            "${x1} ${y1} ${z0},${x0} ${y1} ${z0},${x0} ${y1} ${z1},${x1} ${y1} ${z1}"
            "${x0} ${y1} ${z0},${x0} ${y0} ${z0},${x0} ${y0} ${z1},${x0} ${y1} ${z1}"
            "${x1} ${y0} ${z0},${x1} ${y1} ${z0},${x1} ${y1} ${z1},${x1} ${y0} ${z1}")
  set(text "solid box\n")
  foreach(q IN LISTS quads)
    string(REPLACE "," ";" corners "${q}")
    list(GET corners 0 a)
    list(GET corners 1 b)
    list(GET corners 2 c)
    list(GET corners 3 d)
    foreach(t "${a}|${b}|${c}" "${a}|${c}|${d}")
      string(REPLACE "|" "\n      vertex " t "${t}")
      string(APPEND text "  facet normal 0 0 0\n    outer loop\n      vertex ${t}\n    endloop\n  endfacet\n")
    endforeach()
  endforeach()
  file(WRITE ${out} "${text}endsolid box\n")
endfunction()
ascii_box(${OUT}/design.stl -20 20 -20 20 -10 0)
file(WRITE ${OUT}/design.setup.toml "[stock]\nshape = \"box\"\nmin = [-20, -20, -10]\nmax = [20, 20, 0.5]\n[tools.1]\nkind = \"flat\"\ndiameter = 6\n")
file(WRITE ${OUT}/design.nc "T1 M06\nM03 S1000\nG90 G00 X-25. Y0 Z5.\nG43 H1 Z5.\nG01 Z-0.5 F300.\nX25.\nG00 Z5.\nM30\n")
run_expect(0 "run --design" ${NCURVE} run ${OUT}/design.nc --setup ${OUT}/design.setup.toml --design ${OUT}/design.stl)
expect_text("${out}" "design         ${OUT}/design.stl, tol 0.01 mm, exact to the cell (0.0400 mm); findings 2"
            "the design named, its findings counted")
# the slot 6 wide: 150 rows of cells beyond the tolerance, 1000 cells each; the rest of the top stock left
expect_text("${out}" "gouge          0.500 mm at X" "the gouge")
expect_text("${out}" "(150000 cells beyond the tolerance)" "the slot's cells")
expect_text("${out}" "stock left     0.500 mm at X" "the stock left")
expect_text("${out}" "(850000 cells beyond the tolerance)" "the rest of the top")
expect_text("${out}" "design.nc:6:1: warning: NC2087 the cut goes 0.500 mm into the design" "NC2087 at the slot's block")
expect_text("${out}" "design.nc:8:1: warning: NC2088 at the end 0.500 mm of stock is left" "NC2088 at M30")
expect_text("${out}" "findings       2" "the design's listed with the verifier's")
run_expect(0 "run --design --json" ${NCURVE} run ${OUT}/design.nc --setup ${OUT}/design.setup.toml --design ${OUT}/design.stl
           --tol 0.6 --json)
expect_text("${out}" "\"design\": {" "the design in --json")
expect_text("${out}" "\"tol_mm\": 0.6" "--tol")
if(out MATCHES "NC208[78]")
  message(SEND_ERROR "--tol 0.6: nothing beyond it, yet:\n${out}")
endif()
# --design alone turns on the verification; its errors name the file
# (here with no tool of known size: refused, saying why)
run_expect(2 "--design without --setup" ${NCURVE} run ${OUT}/design.nc --design ${OUT}/design.stl)
expect_text("${err}" "--design: no default stock" "--design turned the verification on")
file(WRITE ${OUT}/flat.stl "solid flat\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex 1 0 0\n   vertex 0 1 0\n  endloop\n endfacet\nendsolid flat\n")
run_expect(2 "a flat design" ${NCURVE} run ${OUT}/design.nc --design ${OUT}/flat.stl)
expect_text("${err}" "flat.stl: error: every vertex of the STL has Z = 0: a flat surface, not a solid" "the flat design refused")
file(WRITE ${OUT}/short.stl "solid bad\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertx 1 0 0\n")
run_expect(2 "a bad ASCII design" ${NCURVE} run ${OUT}/design.nc --design ${OUT}/short.stl)
expect_text("${err}" "short.stl:5:4: error: 'vertx' where 'vertex' was expected" "the word's line and column")
run_expect(2 "--design on a lathe" ${NCURVE} run ${SRC}/examples/lathe-mrc.nc --machine fanuc-lathe --design ${OUT}/design.stl)
expect_text("${err}" "--design: the check against a design is a mill's" "a lathe refused")
# an STL stock: the same block as an STL, the same cut
ascii_box(${OUT}/stock.stl -20 20 -20 20 -10 0.5)
file(WRITE ${OUT}/stl-stock.setup.toml "[stock]\nshape = \"stl\"\nfile = \"stock.stl\"\n[tools.1]\nkind = \"flat\"\ndiameter = 6\n")
run_expect(0 "an STL stock" ${NCURVE} run ${OUT}/design.nc --setup ${OUT}/stl-stock.setup.toml --design ${OUT}/design.stl)
expect_text("${out}" "stock          STL ${OUT}/stock.stl" "the STL stock named")
expect_text("${out}" "(850000 cells beyond the tolerance)" "the same stock left as the box's")
# the STL files read are inputs: no output is written over them
run_expect(2 "--part over the design" ${NCURVE} run ${OUT}/design.nc --setup ${OUT}/stl-stock.setup.toml
           --design ${OUT}/design.stl --part ${OUT}/design.stl)
run_expect(2 "-o over the STL stock" ${NCURVE} run ${OUT}/design.nc --setup ${OUT}/stl-stock.setup.toml
           --format csv -o ${OUT}/stock.stl)
file(READ ${OUT}/stock.stl head LIMIT 9)
expect_text("${head}" "solid box" "the stock's STL kept")
