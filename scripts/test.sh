#!/usr/bin/env bash
# The README's second command: installs what is missing, builds everything (release preset) and
# runs every test with CTest. Usage: scripts/test.sh [preset]   (default | debug | asan)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
preset=${1:-default}
bash scripts/install-deps.sh --tests
cmake --preset "$preset" >/dev/null
cmake --build --preset "$preset"
ctest --preset "$preset" -j2
