#!/usr/bin/env bash
# A/B of the dynamic GVD benchmark (bench/topology_dynamic_bench.cpp) between two builds, runs
# interleaved so that both see the same machine load (the machine is shared: absolute times drift
# by +-30 % from run to run, the A/B ratio is the figure to compare). Prints, per map, the median
# and the minimum over the rounds of the CPU time per change (update/*) or per build (full/*) of
# each side (the minimum is the least disturbed round: the better figure for an A/B of code).
# Usage: bench/topology_dynamic_ab.sh BASE_BIN_DIR NEW_BIN_DIR [filter] [rounds] [min-time]
#   *_BIN_DIR: a build's bin/ folder holding topology_dynamic_bench (each binary finds its own
#   libraries through its RUNPATH, or beside it when copied there); filter: a --benchmark_filter regex (default update/).
# Example (base = main): git worktree add /tmp/base main && cmake -S /tmp/base -B /tmp/base/b
#   -DCMAKE_BUILD_TYPE=Release && cmake --build /tmp/base/b --target topology_dynamic_bench
#   && bench/topology_dynamic_ab.sh /tmp/base/b/bin build/default/bin
set -euo pipefail
base=${1:?base bin dir}
new=${2:?new bin dir}
filter=${3:-update/}
rounds=${4:-3}
min_time=${5:-0.3}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for r in $(seq "$rounds"); do
  for side in base new; do
    dir=$base
    [ "$side" = new ] && dir=$new
    # A copied binary with its libraries beside it: load those (LD_LIBRARY_PATH precedes RUNPATH).
    lib=
    [ -e "$dir/libvoronav_voronoi.so" ] && lib=$dir
    LD_LIBRARY_PATH=$lib "$dir/topology_dynamic_bench" --benchmark_min_time="$min_time" --benchmark_filter="$filter" \
      --benchmark_format=json >"$tmp/$side.$r.json" 2>/dev/null
  done
done
/usr/bin/python3 - "$tmp" "$rounds" <<'PY'
import glob, json, statistics, sys
tmp, rounds = sys.argv[1], int(sys.argv[2])
times = {}
for side in ("base", "new"):
    for f in glob.glob(f"{tmp}/{side}.*.json"):
        for b in json.load(open(f))["benchmarks"]:
            per = b["cpu_time"] / (20.0 if b["name"].startswith("update/") else 1.0)
            times.setdefault(b["name"], {}).setdefault(side, []).append(per)
print(f"| benchmark | base ms | new ms | new / base | base min | new min | new / base (min) |  (median and minimum of {rounds} interleaved rounds)")
print("|---|---|---|---|---|---|---|")
for name, t in times.items():
    if "base" not in t or "new" not in t:
        continue
    b, n = statistics.median(t["base"]), statistics.median(t["new"])
    bm, nm = min(t["base"]), min(t["new"])
    print(f"| {name} | {b:.3f} | {n:.3f} | {n / b:.2f} | {bm:.3f} | {nm:.3f} | {nm / bm:.2f} |")
PY
