#!/usr/bin/env bash
# Installs the test packages, builds ncurve with its tests and benchmarks in build/ (beside the tool
# that setup.sh built there), and runs every test.
# With --sanitize: the same tests under AddressSanitizer and UndefinedBehaviorSanitizer (clang,
# build-sanitize/, shared with fuzz.sh: see configure_sanitize in packages.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/packages.sh
if [ "${1:-}" = "--sanitize" ]; then
  ensure_packages "${tool_packages[@]}" "${test_packages[@]}" "${fuzz_packages[@]}"
  ensure_node
  configure_sanitize
  cmake --build build-sanitize
  # undefined behaviour stops the program (-fno-sanitize-recover); leaks are reported
  UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 ctest --test-dir build-sanitize --output-on-failure -j2
  exit
fi
ensure_packages "${tool_packages[@]}" "${test_packages[@]}"
ensure_node
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DNCURVE_TESTS=ON -DNCURVE_BENCH=ON >/dev/null
cmake --build build
ctest --test-dir build --output-on-failure -j2
