#!/usr/bin/env bash
# Builds the libFuzzer targets (clang, in build-sanitize/ with the sanitizer tests: see
# configure_sanitize in packages.sh) and fuzzes for about SECONDS (default 60), two targets at a
# time: the parser and interpreter with the CSV, JSON Lines and G-code writers for three quarters of
# SECONDS, then the cutter-profile and point-list files for a quarter; beside them the streamed
# reader against the whole reading, the curve expressions, the server's request bodies and the
# command line for a quarter or an eighth each,
# the machine profiles, setups and STL files for an eighth. A crash,
# undefined behaviour, a leak, a time-out (10 s an input) or 2 GB of memory fails.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
source scripts/packages.sh
ensure_packages "${tool_packages[@]}" "${test_packages[@]}" "${fuzz_packages[@]}"
configure_sanitize
cmake --build build-sanitize --target fuzz_run fuzz_stream fuzz_curve fuzz_rows fuzz_profile fuzz_setup fuzz_stl fuzz_cli fuzz_serve
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
dir=build-sanitize/fuzz
# fuzz TARGET CORPUS SECONDS MAX_LEN: runs one target, prints its totals, or the failing input's log
fuzz() {
  local log="$dir/$1.log"
  if (cd "$dir" && ./"$1" "corpus-$2" -max_total_time="$3" -max_len="$4" -timeout=10 -rss_limit_mb=2048 \
        -print_final_stats=1 >"$1.log" 2>&1); then
    echo "$1: $(grep -E "^Done" "$log")"
  else
    tail -n 60 "$log"
    echo "$1: failure; the input that caused it is named above (crash-*, timeout-*, leak-* in $dir)"
    return 1
  fi
}

mkdir -p "$dir"/corpus-{programs,stream,curves,rows,profiles,setups,stls,cli,serve}
# the test programs of every folder of tests/programs (their names are unique across folders)
find tests/programs -name '*.nc' -exec cp -t "$dir/corpus-programs/" {} +
cp examples/*.nc macros/*.nc "$dir/corpus-programs/"
# the streamed reader against the whole reading: a byte for the piece size, then the program
for f in "$dir"/corpus-programs/*.nc; do { printf '\x07'; cat "$f"; } >"$dir/corpus-stream/$(basename "$f")"; done
printf 'CX+[R0+A*t/360]*COS[t]\nCY+[R0+A*t/360]*SIN[t]\n0' >"$dir/corpus-curves/spiral"
printf 'A/COS[t]\n0\nA*TAN[t]' >"$dir/corpus-curves/hyperbola"
printf '63*SIN[t]-7.5*SIN[6*t]+20*SIN[ATAN[SIN[5*t]]/[1.4-COS[5*t]]-t]\nSQRT[ABS[t]]*EXP[t/90]\nLN[t+1]' \
  >"$dir/corpus-curves/rotor"
cp examples/*.csv "$dir/corpus-rows/"
printf '100,-5,-20\n100,5\n' >"$dir/corpus-rows/dish"
cp profiles/*.toml "$dir/corpus-profiles/"
find tests/programs -name '*.toml' -exec cp -t "$dir/corpus-profiles/" {} +
cp examples/*.setup.toml "$dir/corpus-setups/"
# STL files: an ASCII tetrahedron, and a binary one (80-byte header, count 1, a triangle)
printf 'solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 10 0 0\nvertex 0 10 5\nendloop\nendfacet\nendsolid t\n' \
  >"$dir/corpus-stls/ascii"
{ head -c 80 /dev/zero; printf '\x01\x00\x00\x00'; head -c 12 /dev/zero
  printf '\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00\x20\x41\x00\x00\x00\x00\x00\x00\x00\x00'
  printf '\x00\x00\x00\x00\x00\x00\x20\x41\x00\x00\xa0\x40\x00\x00'; } >"$dir/corpus-stls/binary"
# nesting past the bound (a dotted key of 40 parts, arrays 40 deep), refused before toml++ reads it
printf '[machine]\nname = "deep"\n[%sb]\nx = 1\n' "$(printf 'a.%.0s' {1..40})" >"$dir/corpus-profiles/deep-key"
printf '[machine]\nx = %s1%s\n' "$(printf '[%.0s' {1..40})" "$(printf ']%.0s' {1..40})" >"$dir/corpus-profiles/deep-array"
# a cycle of endless pecks: its moves count as steps
printf 'G00 X0 Y0 Z10.\nG91 G83 X1. Z-1000000. R-5. Q0.001 K1000 F100.\nM30\n' >"$dir/corpus-programs/endless-pecks.nc"
# command lines: arguments separated by NUL bytes
printf 'gen\x00ellipse\x00--tol\x000.01\x00--form\x00cycle' >"$dir/corpus-cli/gen"
printf 'analyze\x00circle\x00--radius\x0050\x00--feed\x001000\x00--kv\x0030,25' >"$dir/corpus-cli/circle"
printf 'analyze\x00x.nc\x00--servo\x00--curve\x00expr\x00--x\x00t\x00--t\x000:1' >"$dir/corpus-cli/analyze"
printf 'helicoid\x00--example\x00seed004\x00--step\x001\x00--centre-distance\x00200:300:10' >"$dir/corpus-cli/helicoid"
printf 'run\x00x.nc\x00--format\x00csv\x00--arc-tol\x000.01\x00--param\x006050=102' >"$dir/corpus-cli/run"

# request bodies: the first byte picks /api/run (0), /api/analyze (1) or /api/gen (2)
printf '\x00{"program": "G01 X10. F100.\\nG02 X0 R5.\\nM30\\n", "machine": "fanuc-lathe", "trace": true, "set": {"#100": 1}}' \
  >"$dir/corpus-serve/run"
printf '\x01{"program": "G01 X100. F600.\\nM30\\n", "machine": "fanuc-mill", "servo": true, "moves": true}' \
  >"$dir/corpus-serve/analyze"
printf '\x02{"curve": "ellipse", "params": {"a": 20, "b": 10}, "tol": 0.05, "form": "arcs"}' >"$dir/corpus-serve/gen"
printf '\x02{"curve": "expr", "x": "t", "y": "SIN[t]", "t": "0:90", "tol": 0.1}' >"$dir/corpus-serve/expr"

quarter=$(( (seconds + 3) / 4 ))
eighth=$(( (seconds + 7) / 8 ))
# two streams on the two cores: the interpreter and the point lists; the curves, requests, profiles,
# setups and command line
{ fuzz fuzz_run programs "$(( seconds - quarter ))" 8192 && fuzz fuzz_rows rows "$quarter" 4096; } &
first=$!
status=0
{ fuzz fuzz_stream stream "$quarter" 4096 && fuzz fuzz_curve curves "$quarter" 512 && fuzz fuzz_serve serve "$quarter" 4096 &&
  fuzz fuzz_profile profiles "$eighth" 4096 && fuzz fuzz_setup setups "$eighth" 4096 &&
  fuzz fuzz_stl stls "$eighth" 4096 && fuzz fuzz_cli cli "$eighth" 512; } || status=1
wait "$first" || status=1
exit "$status"
