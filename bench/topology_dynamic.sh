#!/usr/bin/env bash
# Dynamic GVD speed (seed 003, DynamicGvd): full build and per-change update on willow,
# warehouse, depot, lab_intel and turtlebot3_world (bench/topology_dynamic_bench.cpp), and the
# ratio full rebuild / per change. Writes the "Dynamic GVD" section of bench/results/topology.md
# (between the markers; the rest of the file is bench/topology_eval.sh's).
# Usage: bench/topology_dynamic.sh [build-dir] [min-time-seconds]   (defaults build/default, 1)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build/default}
min_time=${2:-1}
cmake --build "$build" --target topology_dynamic_bench >/dev/null
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$build/bin/topology_dynamic_bench" --benchmark_min_time="$min_time" --benchmark_repetitions=3 \
  --benchmark_report_aggregates_only=true --benchmark_format=json >"$tmp/dyn.json"
/usr/bin/python3 - "$tmp/dyn.json" "$root/bench/results/topology.md" "$min_time" <<'PY'
import datetime, json, os, re, sys
src, out, min_time = sys.argv[1], sys.argv[2], sys.argv[3]
j = json.load(open(src))
med = {b["run_name"]: b for b in j["benchmarks"] if b.get("aggregate_name") == "median"}
ctx = j["context"]
lines = ["<!-- dynamic-gvd:begin -->", "## Dynamic GVD: full build and per-change update", "",
         f"Measured {datetime.date.today()} with `bench/topology_dynamic.sh` (median of 3 "
         f"repetitions, min time {min_time} s each; {ctx.get('num_cpus')} CPUs, load average "
         f"{', '.join(f'{x:.1f}' for x in ctx.get('load_avg', []))} during the run: the machine is "
         "shared, so absolute times are inflated and the ratios are the figures to compare). CPU "
         "time. One update iteration = 10 accumulated 3x3 obstacle insertions at random free places, "
         "then their removal (20 `DynamicGvd::update` calls); per change = iteration / 20. Counters "
         "per change say where the work went: rows of the EDT that were rescanned and the cells it "
         "recomputed (in rows where only removals changed a column: the cells whose nearest "
         "obstacle was in a changed column), cells the local re-thinning/re-pruning examined, label merges/splits.", "",
         "| map | cells | free cells | full build ms | per change ms | full / per change | EDT rows | EDT row cells | skeleton cells | repartitions |",
         "|---|---|---|---|---|---|---|---|---|---|"]
for name in ["willow", "warehouse", "depot", "lab_intel", "turtlebot3_world"]:
    f, u = med.get(f"full/{name}"), med.get(f"update/{name}")
    if not f or not u:
        continue
    per = u["cpu_time"] / 20.0
    lines.append(f"| {name} | {int(f['cells'])} | {int(f['free_cells'])} | {f['cpu_time']:.1f} | "
                 f"{per:.3f} | {f['cpu_time'] / per:.0f}x | {u['rows_per_change']:.0f} | "
                 f"{u['row_cells_per_change']:.0f} | {u['skeleton_cells_per_change']:.0f} | "
                 f"{u['repartitions_per_change']:.2f} |")
lines += ["", "Reference figures of the issue (Lau, Sprunk & Burgard 2013 dynamic brushfire, same kind of "
          "run): per change willow 0.155 ms, warehouse 1.46, depot 0.745, lab_intel 0.730, "
          "turtlebot3_world 0.080; full build willow 174.5 ms.", "<!-- dynamic-gvd:end -->"]
block = "\n".join(lines) + "\n"
text = open(out).read() if os.path.exists(out) else ""
if "<!-- dynamic-gvd:begin -->" in text:
    text = re.sub(r"<!-- dynamic-gvd:begin -->.*?<!-- dynamic-gvd:end -->\n?", lambda m: block, text,
                  flags=re.S)
else:
    text = text + ("\n" if text and not text.endswith("\n") else "") + "\n" + block
open(out, "w").write(text)
print(block)
PY
