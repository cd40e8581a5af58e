#!/usr/bin/env bash
# Regenerates the screenshots of the three replay pages the demo writes (issue 20):
# docs/img/replay/{coordination,netsim,exploration}.png, 1280 x 860 CSS px, headless Chromium
# (Debian chromium + playwright-core pinned in tests/browser/package-lock.json, as the browser test).
# Usage: scripts/replay_screenshots.sh [BUILD_DIR] [DEMO_OUT]
#   BUILD_DIR  default build/default (its bin/voronav must be built)
#   DEMO_OUT   an existing `voronav demo --out` folder; default: run the demo into BUILD_DIR/replay-shots
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${1:-$root/build/default}" && pwd)
bin="$build/bin/voronav"
demo=${2:-}
[ -x "$bin" ] || { echo "replay_screenshots.sh: $bin not found; build voronav_cli first" >&2; exit 1; }
node_dir="$build/tests/browser-test"
bash "$root/tests/browser/prepare.sh" "$node_dir" "$root/scripts/replay_screenshots.mjs"
if [ -z "$demo" ]; then
  demo="$build/replay-shots/demo"
  rm -rf "$demo"
  mkdir -p "$demo"
  "$bin" demo --out "$demo" --quiet >/dev/null
fi
demo=$(cd "$demo" && pwd)
for f in index.html netsim.html explore.html; do
  [ -f "$demo/$f" ] || { echo "replay_screenshots.sh: $demo/$f missing (not a demo output folder?)" >&2; exit 1; }
done
out="$root/docs/img/replay"
mkdir -p "$out"
shot() {  # page png fraction
  (cd "$node_dir" && node replay_screenshots.mjs "$demo/$1" "$out/$2" "$3")
}
# Coordination: the team half-way, some robots still waiting at their start (non-zero delays).
shot index.html coordination.png 0.35
# Networked: after the obstacle change and the repair, the source on the repaired route.
shot netsim.html netsim.png 0.8
# Exploration: after the first tree (400 s of 600 s), the map revealed so far and the tree being followed.
shot explore.html exploration.png 0.8
ls -l "$out"
