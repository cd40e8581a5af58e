#!/bin/bash
# GA 3-opt neighbourhood (issue #16): the delay GA of seed 002 (`coordinate --search ga`) with the
# paper's uniform random 3-opt (`--ga-three-opt-order paper`, N(N-1) moves per child) against the
# critical-first neighbourhood (`--ga-three-opt-order critical-first`, EXTRA options appended), on
# the MAPF map random-32-32-20 with the first K robots of random-1 (appear/leave). The two run
# alternately per (K, seed). Prints one Markdown row per (K, seed): CPU (user + system) and wall
# time [s], makespan and sum of arrivals of each, and the makespan change.
#
# Usage: bench/ga_order.sh VORONAV [KS] [SEEDS] [EXTRA]   (defaults: "30 50 100", "1 2 3 4 5 6 7 8")
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/.." && pwd)
BIN=$1
KS=${2:-"30 50 100"}
SEEDS=${3:-"1 2 3 4 5 6 7 8"}
EXTRA=${4:-}
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
echo "| K | seed | paper CPU [s] | paper wall [s] | paper makespan [s] | paper sum [s] | critical CPU [s] | critical wall [s] | critical makespan [s] | critical sum [s] | makespan change |"
echo "|---|---|---|---|---|---|---|---|---|---|---|"
for k in $KS; do
  for seed in $SEEDS; do
    for order in paper critical-first; do
      args=(--ga-three-opt-order "$order")
      # shellcheck disable=SC2206
      [ "$order" = critical-first ] && args+=($EXTRA)
      /usr/bin/time -f "%U %S %e" -o "$TMP/t_$order" "$BIN" coordinate \
        --map "$ROOT/data/mapf/random-32-32-20.map" \
        --scen "$ROOT/data/mapf/random-32-32-20-random-1.scen" --agents "$k" --seed "$seed" \
        --at-start appear --at-goal leave --search ga --quiet --json "${args[@]}" \
        >"$TMP/$order.json"
    done
    /usr/bin/python3 - "$TMP" "$k" "$seed" <<'PYEOF'
import json, sys
tmp, k, seed = sys.argv[1:4]
row = [k, seed]
res = {}
for order in ("paper", "critical-first"):
    a = json.load(open(f"{tmp}/{order}.json"))
    u, s, e = open(f"{tmp}/t_{order}").read().split()[-3:]
    res[order] = a["makespan"]
    row += [f"{float(u) + float(s):.2f}", f"{float(e):.2f}", f"{a['makespan']:.3f}",
            f"{a['sum_of_arrivals']:.1f}"]
row.append(f"{100.0 * (res['critical-first'] / res['paper'] - 1.0):+.2f} %")
print("| " + " | ".join(row) + " |")
PYEOF
  done
done
