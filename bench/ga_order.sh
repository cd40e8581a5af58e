#!/bin/bash
# GA 3-opt neighbourhoods (issue #16): the delay GA (bench/ga_common.sh) with the paper's uniform
# random 3-opt (`--ga-three-opt-order paper`, N(N-1) moves per child) against one or more other
# settings, run alternately per (K, seed, round). A setting is a list of coordinate options; the
# settings are separated by '|' in VARIANTS (default "--ga-three-opt-order critical-first").
# Prints one Markdown row per (K, seed): for the paper and for each setting the CPU (user +
# system, the smallest of ROUNDS rounds) and wall time [s] (smallest), the makespan, and for each
# setting the makespan change against the paper. The load average before and after goes to stderr.
#
# Usage: bench/ga_order.sh VORONAV [KS] [SEEDS] [EXTRA]   (defaults: "30 50 100", "1 2 3 4 5 6 7 8")
#        EXTRA is appended to the first setting (compatibility); env VARIANTS, ROUNDS (default 1)
# shellcheck source=bench/ga_common.sh disable=SC1091
source "$(dirname "$0")/ga_common.sh"
BIN=$1
KS=${2:-"30 50 100"}
SEEDS=${3:-"1 2 3 4 5 6 7 8"}
EXTRA=${4:-}
ROUNDS=${ROUNDS:-1}
IFS='|' read -r -a VARS <<<"${VARIANTS:---ga-three-opt-order critical-first}"
VARS[0]="${VARS[0]} $EXTRA"
echo "load before: $(cut -d' ' -f1-3 /proc/loadavg)" >&2
head="| K | seed | paper CPU [s] | paper wall [s] | paper makespan [s]"
sep="|---|---|---|---|---"
for v in "${VARS[@]}"; do
  name=$(ga_variant_name "$v")
  head+=" | $name CPU [s] | $name wall [s] | $name makespan [s] | change"
  sep+="|---|---|---|---"
done
echo "$head |"
echo "$sep|"
for k in $KS; do
  for seed in $SEEDS; do
    for r in $(seq "$ROUNDS"); do
      ga_run "$BIN" "$k" "$seed" "$TMP/v0.json" "$TMP/t_v0_$r" --ga-three-opt-order paper
      for i in "${!VARS[@]}"; do
        # shellcheck disable=SC2086
        ga_run "$BIN" "$k" "$seed" "$TMP/v$((i + 1)).json" "$TMP/t_v$((i + 1))_$r" ${VARS[$i]}
      done
    done
    $PY - "$TMP" "$k" "$seed" "$ROUNDS" "${#VARS[@]}" <<'PYEOF'
import json, sys
tmp, k, seed, rounds, nv = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4]), int(sys.argv[5])
row = [k, seed]
paper = None
for v in range(nv + 1):
    a = json.load(open(f"{tmp}/v{v}.json"))
    cpu, wall = [], []
    for r in range(1, rounds + 1):
        u, s, e = open(f"{tmp}/t_v{v}_{r}").read().split()[-3:]
        cpu.append(float(u) + float(s))
        wall.append(float(e))
    row += [f"{min(cpu):.2f}", f"{min(wall):.2f}", f"{a['makespan']:.3f}"]
    if v == 0:
        paper = a["makespan"]
    else:
        row.append(f"{100.0 * (a['makespan'] / paper - 1.0):+.2f} %")
print("| " + " | ".join(row) + " |")
PYEOF
  done
done
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)" >&2
