#!/usr/bin/env bash
# Reproduces the seed-003 figures of docs/reproductions/topology.md and writes
# bench/results/topology.md:
#  1. room segmentation of every floor plan in data/floorplans against its *_gt_segmentation.png
#     (recall, precision with --metric ipa and --metric intersection, regions, time) with both
#     diagrams (edt, ca), via `voronav topo --json`;
#  2. bench/topology_bench.cpp: full build ns/cell on willow (or the bundled depot map) and the
#     incremental 3x3 update, as ratios against the EDT measured in the same run.
# Usage: bench/topology_eval.sh [build-dir]   (default build/default)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build/default}
cmake --build "$build" --target voronav_cli topology_bench >/dev/null
mkdir -p "$root/bench/results"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for png in "$root"/data/floorplans/*.png; do
  name=$(basename "$png" .png)
  case "$name" in *_gt_segmentation) continue ;; esac
  gt="$root/data/floorplans/${name%_furnitures}_gt_segmentation.png"
  [ -f "$gt" ] || continue
  for method in edt ca; do
    for metric in ipa intersection; do
      "$build/bin/voronav" topo --map "$png" --ground-truth "$gt" --method "$method" \
        --metric "$metric" --json >"$tmp/$name.$method.$metric.json"
    done
  done
done
"$build/bin/topology_bench" --benchmark_min_time=0.2 --benchmark_format=json >"$tmp/bench.json"
/usr/bin/python3 "$root/bench/topology_eval.py" "$tmp" "$root/bench/results/topology.md"
cat "$root/bench/results/topology.md"
