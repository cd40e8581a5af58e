#!/bin/bash
# GA 3-opt budget vs makespan (issue #16): the delay GA of seed 002 (`coordinate --search ga`) on
# the MAPF map random-32-32-20 with the first K robots of random-1 (appear/leave), for each seed
# and each `--ga-three-opt` budget (0 = N(N-1), the paper's). Prints one Markdown row per run:
# seed, budget, CPU time [s] (user + system of the process), makespan, sum of arrivals,
# evaluations.
#
# Usage: bench/ga_budget.sh VORONAV [K] [SEEDS] [BUDGETS]   (defaults: 100, "1 2 3", "0 2000 1000 400")
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
BIN=$1
K=${2:-100}
SEEDS=${3:-"1 2 3"}
BUDGETS=${4:-"0 2000 1000 400"}
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
echo "| K | seed | 3-opt moves per child | CPU [s] | makespan [s] | sum of arrivals [s] | evaluations |"
echo "|---|---|---|---|---|---|---|"
for seed in $SEEDS; do
  for b in $BUDGETS; do
    /usr/bin/time -f "%U %S" -o "$TMP/t" "$BIN" coordinate \
      --map "$ROOT/data/mapf/random-32-32-20.map" \
      --scen "$ROOT/data/mapf/random-32-32-20-random-1.scen" --agents "$K" --seed "$seed" \
      --at-start appear --at-goal leave --search ga --quiet --json --ga-three-opt "$b" \
      >"$TMP/out.json"
    /usr/bin/python3 - "$TMP" "$K" "$seed" "$b" <<'PYEOF'
import json, sys
tmp, k, seed, b = sys.argv[1:5]
a = json.load(open(f"{tmp}/out.json"))
u, s = open(f"{tmp}/t").read().split()[-2:]
label = "N(N-1)" if b == "0" else b
print(f"| {k} | {seed} | {label} | {float(u) + float(s):.2f} | {a['makespan']:.3f} | "
      f"{a['sum_of_arrivals']:.1f} | {a['evaluations']} |")
PYEOF
  done
done
