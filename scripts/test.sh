#!/usr/bin/env bash
# Installs the test packages, builds ncurve with its tests and benchmarks, and runs every test.
# With --sanitize: the same tests under AddressSanitizer and UndefinedBehaviorSanitizer.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/packages.sh
ensure_packages "${tool_packages[@]}" "${test_packages[@]}"
dir=build
flags=(-DCMAKE_BUILD_TYPE=Release -DNCURVE_TESTS=ON -DNCURVE_BENCH=ON)
if [ "${1:-}" = "--sanitize" ]; then
  dir=build-asan
  flags=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DNCURVE_SANITIZE=ON -DNCURVE_TESTS=ON -DNCURVE_BENCH=OFF)
fi
cmake -S . -B "$dir" -G Ninja "${flags[@]}" >/dev/null
cmake --build "$dir"
ctest --test-dir "$dir" --output-on-failure -j2
