#!/usr/bin/env bash
# The real-map rows of the networked-robot comparison (seed 000): the scenario files
# data/netsim/{turtlebot3_world,depot,corridor}.yaml on the ROS maps and the test corridor, both
# methods, one run each, default options. Prints one markdown table (the "Real maps" section of
# bench/results/networked.md; bench/run_netsim_bench.sh calls this). Travel is every robot's
# driving; "route, eq. 2" is the length of the open-point path the source got, "source drove" the
# source's own driving (issue #13: the three are reported separately); "route robots" are the
# robots whose open points are on the source's first route.
# Usage: bench/run_netsim_realmaps.sh [build-dir]   (default build/default)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build/default}
cli=$build/bin/voronav
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "| scenario file | robots | method | success | route_found_by | route robots | traffic [B] | messages | computation | max per robot | route after [s] | arrival [s] | route, eq. 2 [m] | source drove [m] | travel [m] | changes on route | Repairs executed |"
echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
for f in turtlebot3_world depot corridor; do
  "$cli" netsim --scenario "$root/data/netsim/$f.yaml" --method both --out "$tmp/$f" > /dev/null
  /usr/bin/python3 - "$tmp/$f/netsim_$f.json" "$f" <<'PY'
import json, sys
for r in json.load(open(sys.argv[1]))["runs"]:
    arrival = f"{r['simulated_s']:.1f}" if r["success"] else "-"
    print(f"| {sys.argv[2]} | {len(r['robots'])} | {r['method']} | {'yes' if r['success'] else 'no'} | "
          f"{r['route_found_by']} | {r['route_robots']} | {r['traffic_bytes']} | {r['messages']} | {r['computation']:.3g} | "
          f"{r['max_robot_computation']:.3g} | {r['route_time_s']:.1f} | {arrival} | "
          f"{r['route_length_m']:.1f} | {r['source_travel_m']:.1f} | {r['travel_m']:.1f} | "
          f"{r['changes_on_route']} | {r['repairs_executed']} |")
PY
done
