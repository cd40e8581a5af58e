#!/usr/bin/env bash
# End-to-end browser test of the replay page (issue 9).
# Usage: tests/browser/run.sh VORONAV_BINARY BUILD_DIR
# Installs Debian's chromium when missing (apt-get; as root or via sudo), installs playwright-core
# from the pinned package-lock.json with `npm ci` into BUILD_DIR/browser-test when node_modules is
# missing there (never downloads browsers), generates a page with `voronav replay --example`, and
# runs replay.test.mjs against it. The screenshot lands in BUILD_DIR/browser-test/replay.png.
set -euo pipefail
bin=${1:?usage: run.sh VORONAV_BINARY BUILD_DIR}
build=${2:?usage: run.sh VORONAV_BINARY BUILD_DIR}
here=$(cd "$(dirname "$0")" && pwd)
work="$build/browser-test"
mkdir -p "$work"

if [ ! -x /usr/bin/chromium ] && [ -z "${CHROMIUM:-}" ]; then
  echo "run.sh: installing Debian's chromium"
  SUDO=""
  if [ "$(id -u)" -ne 0 ]; then
    command -v sudo >/dev/null || { echo "run.sh: chromium missing; run as root or install it" >&2; exit 1; }
    SUDO=sudo
  fi
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get install -y -qq --no-install-recommends chromium ||
    { $SUDO apt-get update -qq && $SUDO apt-get install -y -qq --no-install-recommends chromium; }
fi
command -v node >/dev/null || { echo "run.sh: node (Debian: nodejs npm) is required" >&2; exit 1; }

cp "$here/package.json" "$here/package-lock.json" "$here/replay.test.mjs" "$work/"
if [ ! -d "$work/node_modules/playwright-core" ]; then
  (cd "$work" && PLAYWRIGHT_SKIP_BROWSER_DOWNLOAD=1 npm ci --no-audit --no-fund --loglevel=error)
fi

rm -rf "$work/page"
"$bin" replay --example --out "$work/page" >/dev/null
# A map-only recording: 40 x 30 cells, a wall across the middle.
python3 - "$work/minimal.json" <<'PY'
import json, sys
occ = [0, 40 * 14, 100, 40 * 2, 0, 40 * 14]
json.dump({"format": "voronav-recording", "version": 1, "title": "map only",
           "map": {"width": 40, "height": 30, "resolution": 0.25, "occupancy": occ}},
          open(sys.argv[1], "w"))
PY
rm -rf "$work/minimal"
"$bin" replay --recording "$work/minimal.json" --out "$work/minimal" >/dev/null
node "$work/replay.test.mjs" "$work/page/index.html" "$work/replay.png" \
  "$here/../../voronav/report/viewer.html" "$work/minimal/index.html"
