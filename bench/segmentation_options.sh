#!/usr/bin/env bash
# Room segmentation of every floor plan in data/floorplans with one set of `voronav topo` options
# (issue #15): one line per run, "plan:regions:ipa recall/precision %" for each plan, so that
# option settings can be compared on all plans at once (docs/reproductions/topology.md).
# Usage: bench/segmentation_options.sh [build-dir] -- [topo options...]
#   e.g. bench/segmentation_options.sh build/default -- --passage-length 1.5 --validate-sides true
# With VORONAV_SEG_OUT=DIR, each plan's label image and topology.json are kept in DIR/PLAN/ (for
# bench/segmentation_diagnosis.py).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build/default}
shift || true
[ "${1:-}" = "--" ] && shift
out=${VORONAV_SEG_OUT:-$(mktemp -d)}
line=""
for png in "$root"/data/floorplans/*.png; do
  name=$(basename "$png" .png)
  case "$name" in *_gt_segmentation) continue ;; esac
  gt="$root/data/floorplans/${name%_furnitures}_gt_segmentation.png"
  [ -f "$gt" ] || continue
  mkdir -p "$out/$name"
  "$build/bin/voronav" topo --map "$png" --ground-truth "$gt" --metric ipa \
    --labels "$out/$name/labels.png" --json "$@" >"$out/$name/topology.json"
  line="$line $(/usr/bin/python3 -c "
import json, sys
j = json.load(open(sys.argv[1])); s = j['segmentation']
print('%s:%d:%.1f/%.1f' % (sys.argv[2], j['regions'], 100 * s['recall'], 100 * s['precision']))
" "$out/$name/topology.json" "$name")"
done
echo "options [$*]:$line"
