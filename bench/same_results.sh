#!/usr/bin/env bash
# Same results before and after a refactoring of the simulators (issue 14, the one stepping loop):
# runs `voronav netsim --scenario N --runs 4 --method both --json` (N = 1..4) and
# `voronav explore --json --out` (paper world and depot; tree, frontier, coordinated,
# tree-frontier; seeds 1 and 2) with two binaries and compares the outputs: netsim JSON without
# wall/CPU times; explore JSON and exploration.json byte for byte; the replay page number by
# number (a last-bit difference, relative <= 1e-12, is reported, not failed).
# Usage: bench/same_results.sh OLD_BIN NEW_BIN [OUT_DIR]
# Give each binary its own build (the build's shared libraries are found through its RUNPATH, so a
# copied binary still runs the libraries of the tree it was built in). About 10 min on 2 cores.
set -euo pipefail
old=${1:?usage: same_results.sh OLD_BIN NEW_BIN [OUT_DIR]}
new=${2:?usage: same_results.sh OLD_BIN NEW_BIN [OUT_DIR]}
out=${3:-$(mktemp -d)}
root=$(cd "$(dirname "$0")/.." && pwd)
depot=$root/data/ros_maps/depot/depot.yaml
py=/usr/bin/python3
strip_times='
import json, sys
def s(o):
    if isinstance(o, dict):
        return {k: s(v) for k, v in o.items() if "wall" not in k and "cpu" not in k}
    if isinstance(o, list):
        return [s(v) for v in o]
    return o
print(json.dumps(s(json.load(sys.stdin)), indent=1, sort_keys=True))'
numdiff='
import re, sys
num = re.compile(r"-?\d+\.?\d*(?:[eE][-+]?\d+)?")
a, b = open(sys.argv[1]).read(), open(sys.argv[2]).read()
if num.split(a) != num.split(b):
    print("DIFFERENT text"); sys.exit(1)
worst, n = 0.0, 0
for x, y in zip(num.findall(a), num.findall(b)):
    if x != y:
        n += 1
        worst = max(worst, abs(float(x) - float(y)) / max(1.0, abs(float(x))))
print(f"{n} numbers differ in the last bits (worst relative {worst:.2g})" if n else "same")
sys.exit(0 if worst <= 1e-12 else 1)'
fail=0
for side in old new; do mkdir -p "$out/$side"; done
for n in 1 2 3 4; do
  for side in old new; do
    "${!side}" netsim --scenario $n --runs 4 --method both --json --quiet | $py -c "$strip_times" \
      > "$out/$side/netsim_$n.json"
  done
  if cmp -s "$out/old/netsim_$n.json" "$out/new/netsim_$n.json"; then echo "netsim $n: same"
  else echo "netsim $n: DIFFERENT"; fail=1; fi
done
for map in paper "$depot"; do
  mb=$(basename "$map" .yaml)
  for m in tree frontier coordinated tree-frontier; do
    for s in 1 2; do
      run=${mb}_${m}_$s
      for side in old new; do
        "${!side}" explore --map "$map" --method $m --seed $s --json --quiet \
          --out "$out/$side/$run" > "$out/$side/$run.json"
      done
      j=same; cmp -s "$out/old/$run.json" "$out/new/$run.json" || { j=DIFFERENT; fail=1; }
      r=same
      cmp -s "$out/old/$run/exploration.json" "$out/new/$run/exploration.json" || { r=DIFFERENT; fail=1; }
      h=$($py -c "$numdiff" "$out/old/$run/index.html" "$out/new/$run/index.html") || fail=1
      echo "explore $run: json $j; exploration.json $r; replay page $h"
    done
  done
done
echo "outputs in $out"
exit $fail
