#!/usr/bin/env bash
# Runs bench/planning_bench.cpp on every Moving AI map and writes bench/results/planning.md:
# mean us per query for A*, Dijkstra and a BFS flood of the whole map (same run), and A*/BFS.
# Usage: bench/run_planning_bench.sh [build-dir]   (default build/default)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build/default}
cmake --build "$build" --target planning_bench >/dev/null
mkdir -p "$root/bench/results"
json=$(mktemp)
"$build/bin/planning_bench" --benchmark_min_time=0.2 --benchmark_format=json >"$json"
python3 - "$json" "$root/bench/results/planning.md" <<'PY'
import json, sys, platform, datetime
data = json.load(open(sys.argv[1]))
rows = {}
for b in data["benchmarks"]:
    algo, name = b["name"].split("/")[:2]
    rows.setdefault(name, {})[algo] = b
out = ["# Grid planners on the Moving AI maps", "",
       f"Measured {datetime.date.today()} on {data['context'].get('num_cpus')} CPUs "
       f"({data['context'].get('host_name','')}); `bench/run_planning_bench.sh`. "
       "Queries: an even sample of each map's .scen file (all buckets). BFS floods the whole map "
       "from the query's start (8-connected, same corner rule) and is the memory-bound floor of "
       "any search that touches the whole map.", "",
       "| map | queries | A* us/query | A* expanded | Dijkstra us/query | Dijkstra expanded | BFS us/flood | BFS cells | A*/BFS | Dijkstra/BFS |",
       "|---|---|---|---|---|---|---|---|---|---|"]
for name in sorted(rows):
    r = rows[name]
    a, d, f = r["astar"], r["dijkstra"], r["bfs"]
    us = lambda b: b["us_per_query"] * 1e6
    out.append(f"| {name} | {int(a['queries'])} | {us(a):.1f} | {a['expanded_per_query']:.0f} | "
               f"{us(d):.1f} | {d['expanded_per_query']:.0f} | {us(f):.1f} | {f['expanded_per_query']:.0f} | "
               f"{us(a)/us(f):.2f} | {us(d)/us(f):.2f} |")
open(sys.argv[2], "w").write("\n".join(out) + "\n")
print("\n".join(out))
PY
rm -f "$json"
