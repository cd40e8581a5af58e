#!/usr/bin/env bash
# Draws the RAS pictures of docs/reproductions/ras.md into docs/img/ras/ with the voronav CLI:
# the paper's figure 2 example, the Table 3 stand-in at region sizes 16 and 8 (figure 12), the
# Table 4 stand-in at region size 8 with density 0 and 8 (figures 14 and 15), and RAS vs A* with a
# robot radius on a floor plan. Usage: bench/ras_pictures.sh [build-dir]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build/default}
cmake --build "$build" --target ras_bench voronav_cli >/dev/null
out="$root/docs/img/ras"
mkdir -p "$out"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$build/bin/ras_bench" --write-maps "$tmp" >/dev/null
v="$build/bin/voronav"
# Figure 2: 8x8 regions, obstacles at (2,2), (6,5), (3,6), start (4,4) (image frame, y down).
printf 'type octile\nheight 8\nwidth 8\nmap\n........\n........\n..@.....\n........\n........\n......@.\n...@....\n........\n' >"$tmp/figure2.map"
"$v" plan --map "$tmp/figure2.map" --planner ras --start 4,4 --goal 0,0 --png "$out/figure2.png" >/dev/null
for r in 16 8; do
  "$v" plan --map "$tmp/ras_table3.map" --planner ras --no-corner-cutting --region-size $r \
    --start 40,472 --goal 472,40 --png "$out/table3_r$r.png" >/dev/null
done
for d in 0 8; do
  "$v" plan --map "$tmp/ras_table4.map" --planner ras --no-corner-cutting --region-size 8 \
    --density $d --start 100,250 --goal 700,250 --png "$out/table4_r8_d$d.png" >/dev/null
done
"$v" plan --map "$tmp/ras_table4.map" --planner ras --no-corner-cutting --region-size 2 \
  --density 8 --start 100,250 --goal 700,250 --png "$out/table4_r2_d8.png" >/dev/null
# RAS (robot 0.4 m: region 5 cells, density 8) vs A* with a 0.2 m radius on a floor plan [m].
fp="$root/data/floorplans/lab_ipa.png"
"$v" plan --map "$fp" --planner ras --region-size 5 --density 8 --no-corner-cutting \
  --start 16,32 --goal 24,12 --png "$out/lab_ipa_ras.png" >/dev/null || true
"$v" plan --map "$fp" --planner astar --radius 0.2 \
  --start 16,32 --goal 24,12 --png "$out/lab_ipa_astar.png" >/dev/null || true
ls -la "$out"
