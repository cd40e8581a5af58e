#!/usr/bin/env bash
# Replay page at scale (issue 20): frames per second while playing near the end of synthetic
# recordings of 100, 300 and 1,000 netsim robots and of a 64-robot, 1,800 s exploration, in
# headless Chromium (the browser test's machinery: Debian chromium + playwright-core from npm).
# Usage: bench/run_replay_bench.sh [BUILD_DIR]   (default build/default; run the browser test once
# before, or this installs playwright-core from tests/browser/package-lock.json).
# Writes bench/results/replay.md. Software drawing on a shared 2-core machine: the figures are
# what a laptop without a GPU would see at worst; requestAnimationFrame caps them at 60.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build/default}
bin="$build/bin/voronav"
work="$build/replay-bench"
mkdir -p "$work"
node_dir="$build/tests/browser-test"
if [ ! -d "$node_dir/node_modules/playwright-core" ]; then
  mkdir -p "$node_dir"
  cp "$root/tests/browser/package.json" "$root/tests/browser/package-lock.json" "$node_dir/"
  (cd "$node_dir" && PLAYWRIGHT_SKIP_BROWSER_DOWNLOAD=1 npm ci --no-audit --no-fund --loglevel=error)
fi
cp "$root/bench/replay_fps.mjs" "$node_dir/"
out="$root/bench/results/replay.md"
{
  echo "# Replay page at scale"
  echo
  echo "\`bash bench/run_replay_bench.sh\` on $(date -u +%Y-%m-%d), $(nproc) cores, headless Chromium"
  echo "$(/usr/bin/chromium --version 2>/dev/null | head -1), software drawing (--disable-gpu), viewport 1400 x 1000."
  echo "Frames per second while playing the last seconds of the recording (every trail at its"
  echo "longest); page load until the first frame is drawn. requestAnimationFrame caps at 60 fps."
  echo
  echo "| recording | robots | duration | page size | load | speed | fps |"
  echo "|---|---|---|---|---|---|---|"
} > "$out"
run() {  # kind robots seconds speed
  local name="$1_$2_$3"
  python3 "$root/bench/replay_recordings.py" "$1" "$2" "$3" "$work/$name.json"
  rm -rf "$work/$name"
  "$bin" replay --recording "$work/$name.json" --out "$work/$name" >/dev/null
  local size
  size=$(du -k "$work/$name/index.html" | cut -f1)
  local json
  json=$(cd "$node_dir" && node replay_fps.mjs "$work/$name/index.html" "$4" 4)
  local fps load
  fps=$(python3 -c "import json,sys; print('%.1f' % json.loads(sys.argv[1])['fps'])" "$json")
  load=$(python3 -c "import json,sys; print('%.2f s' % (json.loads(sys.argv[1])['load_ms'] / 1000))" "$json")
  echo "| $1 | $2 | $3 s | ${size} KiB | $load | $4x | $fps |" | tee -a "$out"
}
run netsim 100 300 1
run netsim 300 300 1
run netsim 1000 300 1
run netsim 1000 300 8
run explore 64 1800 8
run explore 64 1800 64
echo "wrote $out"
