#!/usr/bin/env bash
# Installs what ncurve needs on Debian 12, builds the tool alone (no tests or benchmarks), and runs
# the shipped spiral example. `cmake --install build` then installs it (default prefix /usr/local).
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/packages.sh
ensure_packages "${tool_packages[@]}"
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DNCURVE_TESTS=OFF -DNCURVE_BENCH=OFF >/dev/null
cmake --build build
./build/ncurve run examples/spiral.nc
# the Python module, built beside the binary (docs/python.md)
PYTHONPATH=build/python /usr/bin/python3 -c 'import ncurve; print(ncurve.run("examples/spiral.nc"))'
