#!/usr/bin/env bash
# Speed of the networked-robot simulator on a real ROS map (issue #13, "Scale"): ROBOTS robots
# placed on willow (`placement: {robots: N, seed: 1}`, docs/formats.md), one method, SIM_S
# simulated seconds (time_limit_s). Prints one markdown row per method: simulated s, wall s,
# process CPU s (user + sys of the child), real-time factor (simulated s / wall s and / CPU s),
# success and route_found_by of the run (a short limit usually ends before the source arrives).
# Usage: bench/run_netsim_willow.sh [build-dir]   env: WILLOW (map yaml), ROBOTS (100),
#        SIM_S (10), METHODS ("decentralized centralized"), SEED (1)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build/default}
willow=${WILLOW:-$root/../shared/data/ros_maps/willow/willow-full-0.05.yaml}
[ -f "$willow" ] || willow=/work/shared/data/ros_maps/willow/willow-full-0.05.yaml
robots=${ROBOTS:-100}
sim_s=${SIM_S:-10}
seed=${SEED:-1}
methods=${METHODS:-"decentralized centralized"}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "| map | robots | method | simulated [s] | wall [s] | CPU [s] | sim s / wall s | sim s / CPU s | success | route_found_by | messages |"
echo "|---|---|---|---|---|---|---|---|---|---|---|"
for m in $methods; do
  cat > "$tmp/s.yaml" <<YAML
world: $(realpath "$willow")
placement: {robots: $robots, seed: $seed}
options:
  method: $m
  time_limit_s: $sim_s
YAML
  /usr/bin/python3 - "$build/bin/voronav" "$tmp/s.yaml" "$m" "$robots" <<'PY'
import json, resource, subprocess, sys, time
cli, scen, m, n = sys.argv[1:5]
t0 = time.monotonic()
out = subprocess.run([cli, "netsim", "--scenario", scen, "--json", "--quiet"], check=True,
                     capture_output=True, text=True).stdout
wall = time.monotonic() - t0
ru = resource.getrusage(resource.RUSAGE_CHILDREN)
cpu = ru.ru_utime + ru.ru_stime
v = json.loads(out)[m]
run = v["per_run"][0]
sim = run.get("simulated_s", run.get("end_time_s", 0.0))
by = [k for k, c in v["route_found_by"].items() if c][0]
print(f"| willow | {n} | {m} | {sim:.1f} | {wall:.1f} | {cpu:.1f} | {sim / wall:.2f} | "
      f"{sim / cpu:.2f} | {'yes' if v['success_rate'] > 0 else 'no'} | {by} | {v['messages']:.0f} |")
PY
done
