#!/usr/bin/env bash
# Replay page at scale (issue 20): frames per second while playing near the end of synthetic
# recordings of 100, 300 and 1,000 netsim robots and of a 64-robot, 1,800 s exploration, in
# headless Chromium (the browser test's machinery: tests/browser/prepare.sh and chromium.mjs).
# Usage: bench/run_replay_bench.sh [BUILD_DIR]   (default build/default)
# Environment: REPLAY_BENCH_BEFORE=<git revision> also measures each page with the viewer
#   template of that revision (the same recording spliced into the old page), in the same run.
#   REPLAY_BENCH_QUICK=1 measures only the netsim 300 and 1,000 rows.
# Writes bench/results/replay.md. Each row also measures, in the same browser right after, a
# baseline page (one netsim robot on the same map) so that a loaded machine shows as a low
# baseline, and the renderer's main-thread CPU time per frame (thread time from a Chromium trace).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build/default}
bin="$build/bin/voronav"
work="$build/replay-bench"
py=/usr/bin/python3
mkdir -p "$work"
node_dir="$build/tests/browser-test"
bash "$root/tests/browser/prepare.sh" "$node_dir" "$root/bench/replay_fps.mjs" "$root/bench/replay_profile.mjs"
before=${REPLAY_BENCH_BEFORE:-}
if [ -n "$before" ]; then
  git -C "$root" show "$before:voronav/report/viewer.html" > "$work/viewer_before.html"
fi
page() {  # kind robots seconds -> prints the page path (generated once per run)
  local name="$1_$2_$3"
  "$py" "$root/bench/replay_recordings.py" "$1" "$2" "$3" "$work/$name.json"
  rm -rf "$work/$name"
  "$bin" replay --recording "$work/$name.json" --out "$work/$name" >/dev/null
  if [ -n "$before" ]; then  # the same recording in the old page template
    rm -rf "$work/$name.before" && mkdir -p "$work/$name.before"
    "$py" - "$work/viewer_before.html" "$work/$name/index.html" "$work/$name.before/index.html" <<'PY'
import sys
tpl, page, out = open(sys.argv[1]).read(), open(sys.argv[2]).read(), sys.argv[3]
head = '<script id="recording" type="application/json">'
a = page.index(head) + len(head)
open(out, "w").write(tpl.replace('"__VORONAV_RECORDING_JSON__"', page[a:page.index("</script>", a)], 1))
PY
  fi
  echo "$work/$name/index.html"
}
out="$root/bench/results/replay.md"
{
  echo "# Replay page at scale"
  echo
  echo "\`bash bench/run_replay_bench.sh\` on $(date -u '+%Y-%m-%d %H:%M') UTC, $(nproc) cores, load average $(cut -d' ' -f1-3 /proc/loadavg) at the start,"
  echo "headless $(/usr/bin/chromium --version 2>/dev/null | head -1), software drawing (--disable-gpu), viewport 1400 x 1000."
  echo "fps: frames drawn per second while playing the last seconds of the recording (every trail at its"
  echo "longest). baseline: the same measurement, in the same browser right after, of a page with one"
  echo "robot on the same map (a loaded machine shows as a baseline far below 60). CPU: the renderer's"
  echo "main-thread time per frame from a Chromium trace (thread time), with the script and the canvas"
  echo "drawing Chromium does at commit (LayerTreeHost::DoUpdateLayers) in brackets."
  [ -z "$before" ] || echo "before: the same recording in the page of revision \`$before\`, measured in the same run."
  echo
  if [ -n "$before" ]; then
    echo "| recording | robots | duration | page size | load | speed | fps | baseline fps | fps / baseline | CPU ms/frame (script, canvas) | before: fps | before: CPU ms/frame |"
    echo "|---|---|---|---|---|---|---|---|---|---|---|---|"
  else
    echo "| recording | robots | duration | page size | load | speed | fps | baseline fps | fps / baseline | CPU ms/frame (script, canvas) |"
    echo "|---|---|---|---|---|---|---|---|---|---|"
  fi
} > "$out"
base=$(page netsim 1 300)
fmt() {  # json -> "fps|baseline|ratio|cpu"
  "$py" -c "
import json, sys
d = json.loads(sys.argv[1]); c = d['cpu_ms_per_frame']
b = d.get('baseline_fps')
print('%.1f|%s|%s|%.1f (%.1f, %.1f)|%.2f s' % (d['fps'], '%.1f' % b if b else '-', '%.2f' % (d['fps'] / b) if b else '-',
      c['main'], c['script'], c['raster'], d['load_ms'] / 1000))" "$1"
}
run() {  # kind robots seconds speed
  local p json f size
  p=$(page "$1" "$2" "$3")
  size=$(du -k "$p" | cut -f1)
  json=$(cd "$node_dir" && node replay_fps.mjs "$p" "$4" 4 "$base")
  IFS='|' read -r fps bfps ratio cpu load <<< "$(fmt "$json")"
  local row="| $1 | $2 | $3 s | ${size} KiB | $load | $4x | $fps | $bfps | $ratio | $cpu |"
  if [ -n "$before" ]; then
    json=$(cd "$node_dir" && node replay_fps.mjs "${p%/index.html}.before/index.html" "$4" 4)
    IFS='|' read -r fps bfps ratio cpu load <<< "$(fmt "$json")"
    row="$row $fps | ${cpu%% *} |"
  fi
  echo "$row" | tee -a "$out"
}
if [ -n "${REPLAY_BENCH_QUICK:-}" ]; then
  run netsim 300 300 1
  run netsim 1000 300 1
else
  run netsim 100 300 1
  run netsim 300 300 1
  run netsim 1000 300 1
  run netsim 1000 300 8
  run explore 64 1800 8
  run explore 64 1800 64
fi
echo "load average $(cut -d' ' -f1-3 /proc/loadavg) at the end" | tee -a "$out"
echo "wrote $out"
