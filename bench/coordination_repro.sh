#!/bin/sh
# Builds the coordination benchmark and the CLI, then writes bench/results/coordination.md.
# Usage: bench/coordination_repro.sh [--runs R] [--quick]
set -e
cd "$(dirname "$0")/.."
cmake --preset default >/dev/null
cmake --build --preset default --target coordination_bench voronav_cli -- -j2
python3 bench/coordination_repro.py build/default "$@"
