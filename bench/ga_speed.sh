#!/bin/bash
# GA speed (issue #16): the delay GA of seed 002 (`coordinate --search ga`, the paper's parameters
# unless GA_ARGS says otherwise) on the MAPF map random-32-32-20 with the first K robots of
# random-1 (appear/leave, so that every K has a delay schedule), run by two voronav binaries
# alternately (ROUNDS rounds, the best CPU time of each kept). Prints one Markdown row per
# (K, seed): CPU time [s] of each binary (user + system of the process, so that a loaded machine
# inflates it less than wall time), their ratio, and whether makespan, sum of arrivals,
# evaluations and the order are identical.
#
# Usage: bench/ga_speed.sh OLD_VORONAV NEW_VORONAV [K:SEED ...]   (default 50:1 100:1)
#        env ROUNDS (default 2), GA_ARGS (extra coordinate options, e.g. "--ga-three-opt 400")
# shellcheck source=bench/ga_common.sh disable=SC1091
source "$(dirname "$0")/ga_common.sh"
OLD=$1
NEW=$2
shift 2
CASES=("$@")
[ ${#CASES[@]} -eq 0 ] && CASES=(50:1 100:1)
ROUNDS=${ROUNDS:-2}
echo "| K | seed | old CPU [s] | new CPU [s] | old / new | makespan [s] | evaluations | identical |"
echo "|---|---|---|---|---|---|---|---|"
for c in "${CASES[@]}"; do
  k=${c%%:*}
  seed=${c##*:}
  for r in $(seq "$ROUNDS"); do
    for which in old new; do
      bin=$OLD
      [ "$which" = new ] && bin=$NEW
      # shellcheck disable=SC2086
      ga_run "$bin" "$k" "$seed" "$TMP/$which.json" "$TMP/t_${which}_$r" ${GA_ARGS:-}
    done
  done
  $PY - "$TMP" "$ROUNDS" "$k" "$seed" <<'PYEOF'
import json, sys
tmp, rounds, k, seed = sys.argv[1], int(sys.argv[2]), sys.argv[3], sys.argv[4]
def cpu(which):
    best = None
    for r in range(1, rounds + 1):
        u, s = open(f"{tmp}/t_{which}_{r}").read().split()[-3:-1]
        t = float(u) + float(s)
        best = t if best is None else min(best, t)
    return best
a = json.load(open(f"{tmp}/old.json"))
b = json.load(open(f"{tmp}/new.json"))
same = all(a[key] == b[key] for key in ("makespan", "sum_of_arrivals", "evaluations", "order", "agents"))
co, cn = cpu("old"), cpu("new")
print(f"| {k} | {seed} | {co:.2f} | {cn:.2f} | {co / cn:.2f} | {b['makespan']:.3f} | {b['evaluations']} | {'yes' if same else 'NO: old makespan %.3f' % a['makespan']} |")
PYEOF
done
