# Sourced by the scripts: ensure_packages PKG... installs the Debian packages not yet installed.
# libjs-three: three.js, compiled into the page of `run --html`; libpolyclipping-dev: Clipper, the lathe's
# half-section (src/sim/lathe_section.cpp)
# pybind11-dev, python3-dev, python3-numpy: the Python module (src/python/), built for Debian's /usr/bin/python3
tool_packages=(cmake ninja-build g++ pkg-config libfmt-dev libcli11-dev libtomlplusplus-dev nlohmann-json3-dev
               libeigen3-dev libjs-three libcpp-httplib-dev libpolyclipping-dev zlib1g-dev
               pybind11-dev python3-dev python3-numpy)
# linuxcnc-uspace: its rs274 interpreter is the second implementation the compensation is compared with
# chromium: the browser the pages are tested in (tests/browser, with playwright-core from npm)
# python3-pytest: the Python module's tests (tests/python)
test_packages=(libgtest-dev libgmock-dev libbenchmark-dev python3 python3-pytest linuxcnc-uspace chromium)
fuzz_packages=(clang libclang-rt-14-dev)
# `pip install .` of the Python module offline (pyproject.toml, setup.py; docs/python.md): Debian's pip,
# venv, setuptools and wheel, with --no-build-isolation
pip_packages=(python3-pip python3-venv python3-setuptools python3-wheel)
ensure_packages() {
  local missing=() p
  for p in "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  if [ ${#missing[@]} -gt 0 ]; then
    local sudo=""
    [ "$(id -u)" -ne 0 ] && sudo="sudo"
    $sudo apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
  fi
}
# node and npm for the browser tests: Debian's, unless a node is installed already
ensure_node() {
  command -v node >/dev/null && command -v npm >/dev/null || ensure_packages nodejs npm
}
# The sanitizer build (build-sanitize/), one for test.sh --sanitize and fuzz.sh: clang with
# AddressSanitizer and UndefinedBehaviorSanitizer (float-cast-overflow included, no recovery, libstdc++
# assertions) and libFuzzer's coverage, line tables for the stack traces. Both scripts configure it
# alike, so the second builds only what the first has not. No Python module: a library built with
# AddressSanitizer cannot be loaded into an uninstrumented python.
configure_sanitize() {
  CC=clang CXX=clang++ cmake -S . -B build-sanitize -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only -DNDEBUG" \
    -DNCURVE_SANITIZE=ON -DNCURVE_FUZZ=ON -DNCURVE_TESTS=ON -DNCURVE_BENCH=OFF -DNCURVE_PYTHON=OFF >/dev/null
}
