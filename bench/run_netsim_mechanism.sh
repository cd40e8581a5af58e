#!/usr/bin/env bash
# Seed 000, Tables 6-7 (issue #13): runs `voronav netsim --scenario N --method both --runs R --json`
# for N = 1..4 and prints markdown tables that say which mechanism produced each result: who found
# the route (route_found_by), Paths lost, Repairs executed, whether the obstacle changes hit the
# route in use, the eq. 2 route length, the source's driving and the relays' driving, traffic with
# and without changes. Usage: bench/run_netsim_mechanism.sh [build-dir] [runs (default 16)]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build/default}
runs=${2:-16}
cli=$build/bin/voronav
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for s in 1 2 3 4; do
  "$cli" netsim --scenario "$s" --runs "$runs" --method both --json > "$tmp/s$s.json"
done
/usr/bin/python3 - "$tmp" <<'PY'
import json, os, statistics, sys
d = sys.argv[1]
print("| scenario | method | success | route by relays / source alone / none | Paths lost | "
      "Repairs executed | change runs with a change on the route | route eq. 2 [m] | "
      "source drove [m] | relays drove [m] | traffic no change [B] | traffic with changes [B] |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|")
for s in (1, 2, 3, 4):
    j = json.load(open(os.path.join(d, f"s{s}.json")))
    for m in ("centralized", "decentralized"):
        v = j[m]
        runs = v["per_run"]
        ok = [r for r in runs if r["success"]]
        mean = lambda k, rs: statistics.mean(r[k] for r in rs) if rs else float("nan")
        nochange = [r for r in runs if r["changes_applied"] == 0]
        change = [r for r in runs if r["changes_applied"] > 0]
        by = v["route_found_by"]
        print(f"| {s} | {m} | {len(ok)}/{len(runs)} | {by['relays']} / {by['source_alone']} / {by['none']} | "
              f"{v['paths_lost']} | {v['repairs_executed']} | {v['change_runs_on_route']}/{v['change_runs']} | "
              f"{mean('route_length_m', ok):.1f} | {mean('source_travel_m', ok):.1f} | "
              f"{mean('relay_travel_m', ok):.1f} | {mean('traffic_bytes', nochange):.0f} | "
              f"{mean('traffic_bytes', change):.0f} |")
PY
