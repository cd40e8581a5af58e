#!/bin/bash
# GA 3-opt budget vs makespan (issue #16): the delay GA (bench/ga_common.sh) for each seed and
# each `--ga-three-opt` budget (0 = N(N-1), the paper's). Prints one Markdown row per run:
# seed, budget, CPU time [s] (user + system of the process), makespan, sum of arrivals,
# evaluations.
#
# Usage: bench/ga_budget.sh VORONAV [K] [SEEDS] [BUDGETS]   (defaults: 100, "1 2 3", "0 2000 1000 400")
# shellcheck source=bench/ga_common.sh disable=SC1091
source "$(dirname "$0")/ga_common.sh"
BIN=$1
K=${2:-100}
SEEDS=${3:-"1 2 3"}
BUDGETS=${4:-"0 2000 1000 400"}
echo "| K | seed | 3-opt moves per child | CPU [s] | makespan [s] | sum of arrivals [s] | evaluations |"
echo "|---|---|---|---|---|---|---|"
for seed in $SEEDS; do
  for b in $BUDGETS; do
    ga_run "$BIN" "$K" "$seed" "$TMP/out.json" "$TMP/t" --ga-three-opt "$b"
    $PY - "$TMP" "$K" "$seed" "$b" <<'PYEOF'
import json, sys
tmp, k, seed, b = sys.argv[1:5]
a = json.load(open(f"{tmp}/out.json"))
u, s = open(f"{tmp}/t").read().split()[-3:-1]
label = "N(N-1)" if b == "0" else b
print(f"| {k} | {seed} | {label} | {float(u) + float(s):.2f} | {a['makespan']:.3f} | "
      f"{a['sum_of_arrivals']:.1f} | {a['evaluations']} |")
PYEOF
  done
done
