#!/usr/bin/env bash
# Scale runs of the networked-robot protocols (seed 000, issue item 9): one run per line of the
# table, office worlds at scenario 3's density (12 robots / 40 x 40 m) plus a sparse stress case at
# scenario 4's (12 robots / 80 x 80 m); NetSimOptions::scale_options(). Prints a markdown table.
# Usage: bench/run_netsim_scale.sh [build-dir]   (default build/default)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build/default}
bench=$build/bin/netsim_bench
# robots side_m method limit_s density-label
cases=(
  "6 28.3 centralized 600 s3" "6 28.3 decentralized 600 s3"
  "12 40.0 centralized 600 s3" "12 40.0 decentralized 600 s3"
  "100 115.5 centralized 600 s3" "100 115.5 decentralized 600 s3"
  "1000 365.1 decentralized 1500 s3" "1000 365.1 centralized 20 s3"
  "100 230.9 decentralized 1200 s4"
)
echo "| robots | world [m] | density | method | limit [s] | success | route after [s] | arrival [s] | simulated [s] | wall [s] | sim s / wall s | traffic / robot [B] | messages / robot | attempts |"
echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
fmt='
import json, sys
j = json.loads(sys.stdin.read())
d, lim = sys.argv[1], sys.argv[2]
ok = "yes" if j["success"] else "no"
print(f"| {j['"'"'robots'"'"']} | {j['"'"'world_m'"'"']:.1f} | {d} | {j['"'"'method'"'"']} | {lim} | {ok} | "
      f"{j['"'"'route_time_s'"'"']:.1f} | {j['"'"'arrival_time_s'"'"']:.1f} | {j['"'"'simulated_s'"'"']:.0f} | "
      f"{j['"'"'wall_s'"'"']:.1f} | {j['"'"'sim_s_per_wall_s'"'"']:.1f} | {j['"'"'traffic_bytes_per_robot'"'"']:.0f} | "
      f"{j['"'"'messages_per_robot'"'"']:.2f} | {j['"'"'search_attempts'"'"']} |")
'
for c in "${cases[@]}"; do
  read -r n side method limit dens <<<"$c"
  "$bench" --case "$n" "$side" "$method" "$limit" 1 | python3 -c "$fmt" "$dens" "$limit"
done
