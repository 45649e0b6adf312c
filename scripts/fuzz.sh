#!/usr/bin/env bash
# Builds the libFuzzer targets with clang and fuzzes the parser and interpreter for SECONDS (default 60),
# then the curve expressions (compile, differentiate, print, check) for half as long, and the
# cutter-profile and point-list files for a quarter.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
source scripts/packages.sh
ensure_packages "${tool_packages[@]}" "${fuzz_packages[@]}"
CC=clang CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DNCURVE_FUZZ=ON \
  -DNCURVE_TESTS=OFF -DNCURVE_BENCH=OFF >/dev/null
cmake --build build-fuzz --target fuzz_run fuzz_curve fuzz_rows
# fuzz TARGET CORPUS SECONDS MAX_LEN: runs one target, prints its totals, or the failing input's log
fuzz() {
  local log="build-fuzz/$1.log"
  if ./build-fuzz/fuzz/"$1" "$2" -max_total_time="$3" -max_len="$4" -timeout=10 -rss_limit_mb=2048 \
      -print_final_stats=1 >"$log" 2>&1; then
    grep -E "^Done|^stat::(number_of_executed_units|peak_rss_mb)" "$log" || true
  else
    tail -n 60 "$log"
    echo "$1: failure; the input that caused it is named above (crash-*, timeout-* or leak-*)"
    exit 1
  fi
}

corpus=build-fuzz/corpus
mkdir -p "$corpus"
cp tests/programs/*.nc examples/*.nc macros/*.nc "$corpus"/
fuzz fuzz_run "$corpus" "$seconds" 8192

curves=build-fuzz/corpus-curves
mkdir -p "$curves"
printf 'CX+[R0+A*t/360]*COS[t]\nCY+[R0+A*t/360]*SIN[t]\n0' >"$curves/spiral"
printf 'A/COS[t]\n0\nA*TAN[t]' >"$curves/hyperbola"
printf '63*SIN[t]-7.5*SIN[6*t]+20*SIN[ATAN[SIN[5*t]]/[1.4-COS[5*t]]-t]\nSQRT[ABS[t]]*EXP[t/90]\nLN[t+1]' >"$curves/rotor"
fuzz fuzz_curve "$curves" "$(( (seconds + 1) / 2 ))" 512

rows=build-fuzz/corpus-rows
mkdir -p "$rows"
cp examples/*.csv "$rows"/
printf '100,-5,-20\n100,5\n' >"$rows/dish"
fuzz fuzz_rows "$rows" "$(( (seconds + 3) / 4 ))" 4096
