#!/usr/bin/env bash
# Builds the libFuzzer targets (CMake preset "fuzz": clang, ASan + UBSan) and runs each for a
# bounded time; exits 1 on any finding (crash, sanitizer report, leak, timeout, out-of-memory,
# or an error message that does not name its source). The .ci/run fuzz stage.
# Usage: scripts/fuzz.sh [SECONDS_PER_TARGET (default 20)] [TARGET ...]  (targets: fuzz/fuzz_*.cpp)
# Findings are saved as build/fuzz/runs/<target>/crash-*; replay one with
#   build/fuzz/fuzz/fuzz_<target> build/fuzz/runs/<target>/crash-<hash>
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
secs=${1:-20}
shift || true
all=(image ros_map movingai_map movingai_scen coordination_scenario schedule netsim_scenario
     recording messages dds_sample)
targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=("${all[@]}")
bash scripts/install-deps.sh --fuzz
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz -j2

# Seeds: fuzz/corpus/<target>/ (hand-made and the issue-17 reproductions) plus bundled data.
seeds_for() {
  case "$1" in
    image) echo data/floorplans/Freiburg52_scan.png data/floorplans/lab_ipa.png \
                data/floorplans/office_b.png data/netsim/corridor.pgm ;;
    ros_map) echo data/ros_maps/depot/depot.yaml data/ros_maps/turtlebot3_world/map.yaml \
                  data/netsim/corridor_map.yaml ;;
    movingai_map) echo data/movingai/arena.map data/mapf/random-32-32-20.map ;;
    movingai_scen) echo data/movingai/arena.map.scen ;;
    coordination_scenario) echo data/coordination/crossing.yaml data/coordination/arena_four.yaml ;;
    netsim_scenario) echo data/netsim/corridor.yaml data/netsim/depot.yaml ;;
  esac
}

runs=build/fuzz/runs
failed=()
summary=()
for t in "${targets[@]}"; do
  bin=build/fuzz/fuzz/fuzz_$t
  dir=$runs/$t
  rm -rf "$dir"
  mkdir -p "$dir/corpus"
  [ -d "fuzz/corpus/$t" ] && cp fuzz/corpus/"$t"/* "$dir/corpus/" 2>/dev/null || true
  for s in $(seeds_for "$t"); do cp "$s" "$dir/corpus/"; done
  echo "== fuzz_$t (${secs} s)"
  set +e
  VORONAV_FUZZ_SEEDS_OUT="$dir/corpus" ASAN_OPTIONS=detect_leaks=1 \
    "$bin" -max_total_time="$secs" -timeout=10 -rss_limit_mb=1024 -max_len=65536 \
    -print_final_stats=1 -artifact_prefix="$dir/" "$dir/corpus" >"$dir/log" 2>&1
  rc=$?
  set -e
  execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$dir/log" | grep -o '[0-9]*$' || echo 0)
  summary+=("fuzz_$t: ${execs:-0} executions, exit $rc")
  if [ $rc -ne 0 ]; then
    failed+=("$t")
    echo "fuzz_$t FOUND A PROBLEM (exit $rc); last lines of $dir/log:"
    tail -40 "$dir/log"
  fi
done
echo "== fuzz summary"
printf '%s\n' "${summary[@]}"
if [ ${#failed[@]} -ne 0 ]; then
  echo "fuzz: findings in: ${failed[*]}"
  exit 1
fi
echo "fuzz: all ${#targets[@]} targets ran without a finding"
