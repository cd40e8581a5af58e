#!/usr/bin/env bash
# The README's first command: installs what is missing, builds voronav (release preset) and runs
# the demo, which writes pictures and summary.json into an output folder and prints its path.
# Usage: scripts/demo.sh [--out DIR]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
bash scripts/install-deps.sh
cmake --preset default >/dev/null
cmake --build --preset default --target voronav_cli
exec build/default/bin/voronav demo "$@"
