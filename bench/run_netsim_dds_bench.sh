#!/usr/bin/env bash
# The networked-robot comparison of seed 000 with every robot its own process over Cyclone DDS
# (voronav netsim --transport dds) against the in-process simulated radio, measured in the same
# run, and writes bench/results/netsim_dds.md: for Table 6 scenarios 1..4 x 16 runs x both methods,
# how many per-run records are identical (every figure but CPU and wall time), and the wall time
# of the multi-process run as a ratio to the in-process run; then a 50-process run (49 robots
# placed on the 80 x 80 m world of scenario 4) both ways.
# Usage: bench/run_netsim_dds_bench.sh [build-dir] [runs]   (default build/default, 16)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build/default}
runs=${2:-16}
cmake --build "$build" --target voronav_cli >/dev/null
bin="$build/bin/voronav"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
load_before=$(cut -d' ' -f1-3 /proc/loadavg)
for s in 1 2 3 4; do
  for t in sim dds; do
    echo "scenario $s, $t" >&2
    "$bin" netsim --scenario $s --runs "$runs" --method both --transport $t --out "$tmp/s$s-$t" \
      >/dev/null 2>"$tmp/s$s-$t.err"
  done
done
"$bin" netsim --scenario 4 --run 1 --method decentralized --write-scenario "$tmp/s4.yaml" >/dev/null
cat >"$tmp/p49.yaml" <<YAML
world: s4_world.yaml
placement: {robots: 49, seed: 1}
source: 0
YAML
for t in sim dds; do
  echo "49 robots, $t" >&2
  "$bin" netsim --scenario "$tmp/p49.yaml" --method both --transport $t --out "$tmp/p49-$t" \
    --dds-timeout 1800 >/dev/null 2>"$tmp/p49-$t.err"
done
load_after=$(cut -d' ' -f1-3 /proc/loadavg)
python3 - "$tmp" "$root/bench/results/netsim_dds.md" "$load_before" "$load_after" "$runs" <<'PY'
import json, sys, os, datetime
tmp, out, lb, la, runs = sys.argv[1:6]
MACHINE = {"cpu_s", "max_robot_cpu_s", "wall_s", "processes", "dead_robots", "world_restarts"}
def load(d):
    f = [x for x in os.listdir(d) if x.startswith("netsim_") and x.endswith(".json")][0]
    return json.load(open(os.path.join(d, f)))["runs"]
def compare(a, b):
    same, diffs = 0, []
    for x, y in zip(a, b):
        bad = [k for k in x if k not in MACHINE and x[k] != y.get(k)]
        if bad: diffs.append(f"{x['method']} run {x['run']}: {', '.join(bad)}")
        else: same += 1
    return same, diffs
o = ["# Networked robots as processes over Cyclone DDS vs. the simulated radio", "",
     f"Measured {datetime.date.today()} on {os.cpu_count()} CPUs with `bench/run_netsim_dds_bench.sh` "
     f"(load average before {lb}, after {la}; the machine is shared, so wall times are ratios to the "
     "in-process run measured in the same script).", "",
     "A record is identical when every figure of the run but CPU and wall time is equal: success, "
     "traffic (bytes, messages), computation (total, busiest robot), route time and length, travel, "
     "search attempts, repairs, simulated time and, per robot, travel, work and messages sent by type.",
     "", "| scenario | robot processes | runs x methods | identical records | wall in-process [s] | "
     "wall over DDS [s] | DDS / in-process |", "|---|---|---|---|---|---|---|"]
notes = []
for s in ["1", "2", "3", "4"]:
    a, b = load(f"{tmp}/s{s}-sim"), load(f"{tmp}/s{s}-dds")
    same, diffs = compare(a, b)
    notes += [f"scenario {s}, {d}" for d in diffs]
    wa, wb = sum(r["wall_s"] for r in a), sum(r["wall_s"] for r in b)
    o.append(f"| {s} | {len(a[0]['robots'])} | {len(a)} | {same} / {len(a)} | {wa:.1f} | {wb:.1f} | {wb / wa:.1f} |")
a, b = load(f"{tmp}/p49-sim"), load(f"{tmp}/p49-dds")
same, diffs = compare(a, b)
notes += [f"49 robots, {d}" for d in diffs]
wa, wb = sum(r["wall_s"] for r in a), sum(r["wall_s"] for r in b)
o.append(f"| 49 robots on scenario 4's world (50 processes) | 49 | {len(a)} | {same} / {len(a)} | "
         f"{wa:.1f} | {wb:.1f} | {wb / wa:.1f} |")
o += ["", "The 50-process run, per method:", "", "| method | success | messages | traffic [B] | "
      "route after [s] | simulated [s] | wall in-process [s] | wall over DDS [s] |", "|---|---|---|---|---|---|---|---|"]
for x, y in zip(a, b):
    o.append(f"| {x['method']} | {y['success']} | {y['messages']} | {y['traffic_bytes']} | "
             f"{y['route_time_s']:.1f} | {y['simulated_s']:.1f} | {x['wall_s']:.2f} | {y['wall_s']:.1f} |")
if notes:
    o += ["", "Records that differ:", ""] + [f"- {n}" for n in notes]
o += ["", f"Reproduce: `bash bench/run_netsim_dds_bench.sh build/default {runs}`.", ""]
open(out, "w").write("\n".join(o))
print("\n".join(o))
PY
