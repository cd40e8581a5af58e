#!/usr/bin/env bash
# Scale runs with the DEFAULT NetSimOptions (issue #13, "Scale": "rerun 100 and 1000 robots with
# default options and report route_found_by there too"): the office worlds of
# bench/run_netsim_scale.sh at scenario 3's density (100 robots: 115.5 m, 1000 robots: 365.1 m),
# seed 1, both methods. Prints one markdown row per run with simulated s, wall s, process CPU s
# (user + sys of the child), simulated s per CPU s, success, route_found_by and traffic.
# A run stops at its simulated time limit (LIMIT_100, LIMIT_1000); a run that cannot finish in
# reasonable wall time is cut at WALL_MAX seconds (timeout) and reported as such.
# Also per run: the eq. 2 length of the route the source got, the source's own driving and the
# Repairs it executed. JSON_DIR, if set, keeps each run's netsim_bench JSON there.
# Usage: bench/run_netsim_scale_defaults.sh [build-dir]
#   env: LIMIT_100 (600), LIMIT_1000 (1500), WALL_MAX (600), CASES (override, "n side method limit";
#        cases separated by ';'), JSON_DIR (unset)
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
echo "| robots | world [m] | method | limit [s] | success | route_found_by | route robots | paths lost | route after [s] | arrival [s] | simulated [s] | wall [s] | CPU [s] | sim s / CPU s | traffic / robot [B] | attempts | route, eq. 2 [m] | source drove [m] | Repairs executed |"
echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
for c in "${cases[@]}"; do
  read -r n side method limit <<<"$c"
  /usr/bin/python3 - "$bench" "$n" "$side" "$method" "$limit" "$wall_max" "${JSON_DIR:-}" <<'PY'
import json, os, resource, subprocess, sys
bench, n, side, method, limit, wall_max, json_dir = sys.argv[1:8]
try:
    out = subprocess.run([bench, "--case", n, side, method, limit, "1", "defaults"], check=True,
                         capture_output=True, text=True, timeout=float(wall_max)).stdout
except subprocess.TimeoutExpired:
    ru = resource.getrusage(resource.RUSAGE_CHILDREN)
    print(f"| {n} | {float(side):.1f} | {method} | {limit} | cut after {wall_max} s wall "
          f"(CPU {ru.ru_utime + ru.ru_stime:.0f} s) | | | | | | | | | | | | | | |")
    sys.exit(0)
ru = resource.getrusage(resource.RUSAGE_CHILDREN)
cpu = ru.ru_utime + ru.ru_stime
j = json.loads(out)
if json_dir:
    os.makedirs(json_dir, exist_ok=True)
    with open(os.path.join(json_dir, f"scale_{n}_{method}_{limit}.json"), "w") as f:
        f.write(out)
print(f"| {j['robots']} | {j['world_m']:.1f} | {j['method']} | {limit} | "
      f"{'yes' if j['success'] else 'no'} | {j['route_found_by']} | {j['route_robots']} | "
      f"{j['paths_lost']} | {j['route_time_s']:.1f} | {j['arrival_time_s']:.1f} | "
      f"{j['simulated_s']:.0f} | {j['wall_s']:.1f} | {cpu:.1f} | {j['simulated_s'] / cpu:.1f} | "
      f"{j['traffic_bytes_per_robot']:.0f} | {j['search_attempts']} | {j['route_length_m']:.1f} | "
      f"{j['source_travel_m']:.1f} | {j['repairs_executed']} |")
PY
done
