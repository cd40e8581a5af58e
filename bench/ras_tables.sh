#!/usr/bin/env bash
# Reproduces seed 001's Tables 3 and 4 (stand-in maps and real Moving AI maps) and compares RAS
# with density against A* with a robot radius on the real ROS maps and floor plans; writes
# bench/results/ras.md. Usage: bench/ras_tables.sh [build-dir]   (default build/default)
# Real maps: $VORONAV_DATA_DIR, else ../shared/data (or ../../shared/data from a worktree), else data/.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build/default}
cmake --build "$build" --target ras_bench >/dev/null
mkdir -p "$root/bench/results"
{
  "$build/bin/ras_bench" --tables
  echo "Machine: $(nproc) CPUs, $(uname -m), measured $(date -u +%Y-%m-%d)."
} >"$root/bench/results/ras.md.tmp"
mv "$root/bench/results/ras.md.tmp" "$root/bench/results/ras.md"
echo "wrote $root/bench/results/ras.md"
