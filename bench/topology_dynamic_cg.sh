#!/usr/bin/env bash
# Load-independent A/B of DynamicGvd::update: Callgrind counts (instructions, simulated D1 misses)
# per change of the bench's update sequence (bench/topology_dynamic_drive.cpp: one warm-up
# iteration, then ITERATIONS x 20 counted updates), for two trees. The driver is compiled against
# each tree's headers and linked with its built libraries. Slow (valgrind: ~2 min per map and side).
# Usage: bench/topology_dynamic_cg.sh BASE_SRC BASE_LIBDIR NEW_SRC NEW_LIBDIR [iterations] [maps...]
#   *_SRC: a source tree (for the headers; `git archive main voronav/ | tar -x -C DIR` gives main's);
#   *_LIBDIR: a folder holding that tree's libvoronav_{core,field,io,voronoi}.so, or its build
#   folder (build/default: the libraries under voronav/<module>/).
#   maps: names among willow warehouse depot lab_intel turtlebot3_world (default all five).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
base_src=${1:?base source tree}
base_lib=${2:?base library dir}
new_src=${3:?new source tree}
new_lib=${4:?new library dir}
iters=${5:-4}
shift $(($# < 5 ? $# : 5))
maps=("$@")
[ ${#maps[@]} -eq 0 ] && maps=(willow warehouse depot lab_intel turtlebot3_world)
shared=$root/../../shared/data
[ -d "$shared" ] || shared=/work/shared/data
declare -A path=([willow]=$shared/ros_maps/willow/willow-full-0.05.yaml
  [warehouse]=$shared/ros_maps/warehouse/warehouse.yaml [depot]=$root/data/ros_maps/depot/depot.yaml
  [lab_intel]=$root/data/floorplans/lab_intel.png
  [turtlebot3_world]=$root/data/ros_maps/turtlebot3_world/map.yaml)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for side in base new; do
  src=$base_src lib=$base_lib
  [ "$side" = new ] && src=$new_src lib=$new_lib
  dirs=("$lib")
  [ -e "$lib/voronav/voronoi/libvoronav_voronoi.so" ] &&
    dirs=("$lib/voronav/core" "$lib/voronav/field" "$lib/voronav/io" "$lib/voronav/voronoi")
  flags=()
  for d in "${dirs[@]}"; do flags+=("-L$d" "-Wl,-rpath,$d"); done
  g++ -O2 -std=c++20 -I"$src" "$root/bench/topology_dynamic_drive.cpp" -o "$tmp/drive_$side" \
    "${flags[@]}" -lvoronav_voronoi -lvoronav_io -lvoronav_field -lvoronav_core
done
echo "| map | base Ir / change | new Ir / change | new / base | base D1 misses / change | new D1 misses / change | new / base |"
echo "|---|---|---|---|---|---|---|"
for m in "${maps[@]}"; do
  p=${path[$m]:-}
  if [ -z "$p" ] || [ ! -e "$p" ]; then
    echo "skipping $m: map not found" >&2
    continue
  fi
  declare -A ir=() d1=()
  for side in base new; do
    valgrind --tool=callgrind --cache-sim=yes --toggle-collect='measured_update*' \
      --callgrind-out-file="$tmp/cg.$side.out" "$tmp/drive_$side" "$p" "$iters" >"$tmp/$side.log" 2>&1
    ir[$side]=$(grep -E 'I +refs' "$tmp/$side.log" | awk '{gsub(",", "", $4); print $4}')
    d1[$side]=$(grep -E 'D1 +misses' "$tmp/$side.log" | awk '{gsub(",", "", $4); print $4}')
  done
  n=$((iters * 20))
  /usr/bin/python3 -c "
b, nn, bd, nd, n = ${ir[base]}, ${ir[new]}, ${d1[base]}, ${d1[new]}, $n
print(f'| $m | {b / n / 1e3:.0f} k | {nn / n / 1e3:.0f} k | {nn / b:.2f} | {bd / n / 1e3:.1f} k | {nd / n / 1e3:.1f} k | {nd / bd:.2f} |')"
done
