#!/usr/bin/env bash
# Runs bench/render_bench.cpp and writes bench/results/render.md: a 1000x1000-cell map with a path
# rendered to PNG, against only filling the raster in memory (same run). CPU time is reported
# because wall time on a shared machine includes waiting for a core.
# Usage: bench/run_render_bench.sh [build-dir]   (default build/default)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build/default}
cmake --build "$build" --target render_bench >/dev/null
mkdir -p "$root/bench/results"
json=$(mktemp)
"$build/bin/render_bench" --benchmark_min_time=0.5 --benchmark_format=json >"$json"
python3 - "$json" "$root/bench/results/render.md" <<'PY'
import json, sys, datetime
d = json.load(open(sys.argv[1]))
b = {x["name"].split("/")[0]: x for x in d["benchmarks"]}
png, raster = b["BM_RenderPng"], b["BM_RasterOnly"]
out = ["# Rendering speed", "",
       f"Measured {datetime.date.today()}, `bench/run_render_bench.sh` (1000x1000 cells, 1 pixel per cell).", "",
       "| case | CPU ms | wall ms |", "|---|---|---|",
       f"| Figure: occupancy + path, saved as PNG | {png['cpu_time']:.1f} | {png['real_time']:.1f} |",
       f"| fill the raster only (floor) | {raster['cpu_time']:.2f} | {raster['real_time']:.2f} |",
       "", f"PNG picture / raster fill (CPU): {png['cpu_time']/raster['cpu_time']:.0f}x; most of it is PNG compression."]
open(sys.argv[2], "w").write("\n".join(out) + "\n")
print("\n".join(out))
PY
rm -f "$json"
