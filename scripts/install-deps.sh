#!/usr/bin/env bash
# Installs the Debian 12 packages voronav needs, only those that are missing (apt-get, as root;
# uses sudo when not root). Usage: scripts/install-deps.sh [--tests] [--fuzz]  (--tests adds the
# browser test's; --fuzz adds clang and its libFuzzer runtime for scripts/fuzz.sh)
set -euo pipefail
pkgs=(cmake ninja-build g++ pkg-config python3 libyaml-cpp-dev nlohmann-json3-dev libcli11-dev
      libfmt-dev libspdlog-dev libboost-dev libcairo2-dev libpng-dev libtbb-dev
      libgtest-dev libgmock-dev libbenchmark-dev cyclonedds-dev cyclonedds-tools libzstd-dev
      liblz4-dev
      # The Python package (python/, docs/python.md) and its tests and examples.
      pybind11-dev python3-pybind11 python3-dev python3-numpy python3-pytest python3-matplotlib)
for arg in "$@"; do
  case "$arg" in
    # The browser test of the replay page (Debian's Chromium, driven by Playwright from npm) and
    # the MCAP test (node + npm packages pinned in tests/mcap/package-lock.json).
    --tests) pkgs+=(chromium)
             command -v npm >/dev/null || pkgs+=(nodejs npm) ;;
    # libFuzzer for Debian's clang 14 is in libclang-rt-14-dev (libclang_rt.fuzzer-x86_64.a).
    --fuzz) pkgs+=(clang libclang-rt-14-dev) ;;
    *) echo "install-deps.sh: unknown option '$arg'" >&2; exit 2 ;;
  esac
done
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "voronav: installing missing Debian packages: ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "install-deps.sh: run as root to install: ${missing[*]}" >&2; exit 1; }
  SUDO=sudo
fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
