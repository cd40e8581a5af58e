#!/bin/bash
# GA wall and CPU time per setting (issue #16): the delay GA (bench/ga_common.sh) with one or more
# settings, run alternately per (round, seed), without the paper runs (their makespans are fixed
# for a seed; bench/ga_order.sh measures them). Prints one Markdown row per (K, seed): for each
# setting the smallest CPU (user + system) and the smallest and median wall time [s] over ROUNDS
# rounds, and the makespan. The load average before, during (per round) and after goes to stderr.
#
# Usage: bench/ga_wall.sh VORONAV [KS] [SEEDS]   (defaults: "100", "1 2 3 4 5 6 7 8")
#        env VARIANTS (settings separated by '|'), ROUNDS (default 3)
# shellcheck source=bench/ga_common.sh disable=SC1091
source "$(dirname "$0")/ga_common.sh"
BIN=$1
KS=${2:-"100"}
SEEDS=${3:-"1 2 3 4 5 6 7 8"}
ROUNDS=${ROUNDS:-3}
IFS='|' read -r -a VARS <<<"${VARIANTS:---ga-three-opt-order critical-delayed --ga-delayed-gate 10 --ga-stall 6|--ga-three-opt-order critical-delayed --ga-delayed-gate 10 --ga-stall 6 --ga-threads 2}"
echo "load before: $(cut -d' ' -f1-3 /proc/loadavg)" >&2
head="| K | seed"
sep="|---|---"
for v in "${VARS[@]}"; do
  name=$(ga_variant_name "$v")
  head+=" | $name CPU [s] | wall min [s] | wall median [s] | makespan [s]"
  sep+="|---|---|---|---"
done
for r in $(seq "$ROUNDS"); do
  for k in $KS; do
    for seed in $SEEDS; do
      for i in "${!VARS[@]}"; do
        # shellcheck disable=SC2086
        ga_run "$BIN" "$k" "$seed" "$TMP/v${i}_${k}_$seed.json" "$TMP/t_${i}_${k}_${seed}_$r" ${VARS[$i]}
      done
    done
  done
  echo "load after round $r: $(cut -d' ' -f1-3 /proc/loadavg)" >&2
done
echo "$head |"
echo "$sep|"
for k in $KS; do
  for seed in $SEEDS; do
    $PY - "$TMP" "$k" "$seed" "$ROUNDS" "${#VARS[@]}" <<'PYEOF'
import json, statistics, sys
tmp, k, seed, rounds, nv = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4]), int(sys.argv[5])
row = [k, seed]
for v in range(nv):
    a = json.load(open(f"{tmp}/v{v}_{k}_{seed}.json"))
    cpu, wall = [], []
    for r in range(1, rounds + 1):
        u, s, e = open(f"{tmp}/t_{v}_{k}_{seed}_{r}").read().split()[-3:]
        cpu.append(float(u) + float(s))
        wall.append(float(e))
    row += [f"{min(cpu):.2f}", f"{min(wall):.2f}", f"{statistics.median(wall):.2f}",
            f"{a['makespan']:.3f}"]
print("| " + " | ".join(row) + " |")
PYEOF
  done
done
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)" >&2
