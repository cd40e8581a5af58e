#!/bin/bash
# Shared prologue of the GA benchmarks (bench/ga_budget.sh, ga_order.sh, ga_speed.sh; issue #16):
# strict mode, ROOT, a temporary folder TMP removed on exit, PY (Debian's python3), and ga_run,
# one run of the delay GA of seed 002 (`coordinate --search ga`) on the MAPF map random-32-32-20
# with the first K robots of random-1 (appear/leave, so that every K has a delay schedule).
# Source it: `source "$(dirname "$0")/ga_common.sh"`.
set -euo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
# shellcheck disable=SC2034  # used by the scripts that source this one
PY=/usr/bin/python3

# ga_run BIN K SEED OUT_JSON TIME_FILE [coordinate options...]: the run's JSON goes to OUT_JSON,
# "user system wall" seconds of the process (/usr/bin/time) to TIME_FILE.
ga_run() {
  local bin=$1 k=$2 seed=$3 out=$4 tfile=$5
  shift 5
  /usr/bin/time -f "%U %S %e" -o "$tfile" "$bin" coordinate \
    --map "$ROOT/data/mapf/random-32-32-20.map" \
    --scen "$ROOT/data/mapf/random-32-32-20-random-1.scen" --agents "$k" --seed "$seed" \
    --at-start appear --at-goal leave --search ga --quiet --json "$@" >"$out"
}

# ga_variant_name "OPTIONS": a short column name for a setting ("--ga-three-opt-order
# critical-delayed --ga-stall 6" -> "critical-delayed stall 6").
ga_variant_name() {
  echo "$1" | sed -e 's/--ga-three-opt-order //' -e 's/--ga-//g' -e 's/ *$//'
}
