# Sourced by the scripts: ensure_packages PKG... installs the Debian packages not yet installed.
tool_packages=(cmake ninja-build g++ pkg-config libfmt-dev libcli11-dev libtomlplusplus-dev nlohmann-json3-dev
               libeigen3-dev)
test_packages=(libgtest-dev libgmock-dev libbenchmark-dev python3)
fuzz_packages=(clang libclang-rt-14-dev)
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
