#!/usr/bin/env bash
# Scale runs with the DEFAULT NetSimOptions (issue #13, "Scale": "rerun 100 and 1000 robots with
# default options and report route_found_by there too"): the office worlds of
# bench/run_netsim_scale.sh at scenario 3's density (100 robots: 115.5 m, 1000 robots: 365.1 m),
# seed 1, both methods. Prints one markdown row per run with simulated s, wall s, process CPU s
# (user + sys of the child), simulated s per CPU s, success, route_found_by and traffic.
# A run stops at its simulated time limit (LIMIT_100, LIMIT_1000); a run that cannot finish in
# reasonable wall time is cut at WALL_MAX seconds (timeout) and reported as such.
# Usage: bench/run_netsim_scale_defaults.sh [build-dir]
#   env: LIMIT_100 (600), LIMIT_1000 (1500), WALL_MAX (600), CASES (override, "n side method limit")
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build/default}
bench=$build/bin/netsim_bench
wall_max=${WALL_MAX:-600}
l100=${LIMIT_100:-600}
l1000=${LIMIT_1000:-1500}
if [ -n "${CASES:-}" ]; then
  IFS=';' read -r -a cases <<<"$CASES"
else
  cases=("100 115.5 centralized $l100" "100 115.5 decentralized $l100"
         "1000 365.1 centralized $l1000" "1000 365.1 decentralized $l1000")
fi
echo "| robots | world [m] | method | limit [s] | success | route_found_by | route robots | paths lost | route after [s] | arrival [s] | simulated [s] | wall [s] | CPU [s] | sim s / CPU s | traffic / robot [B] | attempts |"
echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
for c in "${cases[@]}"; do
  read -r n side method limit <<<"$c"
  /usr/bin/python3 - "$bench" "$n" "$side" "$method" "$limit" "$wall_max" <<'PY'
import json, resource, subprocess, sys
bench, n, side, method, limit, wall_max = sys.argv[1:7]
try:
    out = subprocess.run([bench, "--case", n, side, method, limit, "1", "defaults"], check=True,
                         capture_output=True, text=True, timeout=float(wall_max)).stdout
except subprocess.TimeoutExpired:
    ru = resource.getrusage(resource.RUSAGE_CHILDREN)
    print(f"| {n} | {float(side):.1f} | {method} | {limit} | cut after {wall_max} s wall "
          f"(CPU {ru.ru_utime + ru.ru_stime:.0f} s) | | | | | | | | | | | |")
    sys.exit(0)
ru = resource.getrusage(resource.RUSAGE_CHILDREN)
cpu = ru.ru_utime + ru.ru_stime
j = json.loads(out)
print(f"| {j['robots']} | {j['world_m']:.1f} | {j['method']} | {limit} | "
      f"{'yes' if j['success'] else 'no'} | {j['route_found_by']} | {j['route_robots']} | "
      f"{j['paths_lost']} | {j['route_time_s']:.1f} | {j['arrival_time_s']:.1f} | "
      f"{j['simulated_s']:.0f} | {j['wall_s']:.1f} | {cpu:.1f} | {j['simulated_s'] / cpu:.1f} | "
      f"{j['traffic_bytes_per_robot']:.0f} | {j['search_attempts']} |")
PY
done
