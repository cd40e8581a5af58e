#!/usr/bin/env bash
# End-to-end test of the ROS 2 bags (MCAP) voronav writes (issue 19).
# Usage: tests/mcap/run.sh VORONAV_BINARY BUILD_DIR
# Installs @mcap/core, @foxglove/rosmsg(2-serialization) and fzstd from the pinned
# package-lock.json with `npm ci` into BUILD_DIR/mcap-test when node_modules is missing there
# (later runs work offline), then runs mcap.test.mjs: short runs of plan, topo, coordinate,
# netsim and explore with --mcap, each file read back with the reference reader and decoders.
set -euo pipefail
bin=${1:?usage: run.sh VORONAV_BINARY BUILD_DIR}
build=${2:?usage: run.sh VORONAV_BINARY BUILD_DIR}
here=$(cd "$(dirname "$0")" && pwd)
work="$build/mcap-test"
mkdir -p "$work"
command -v node >/dev/null || { echo "run.sh: node (Debian: nodejs npm) is required" >&2; exit 1; }

cp "$here/package.json" "$here/package-lock.json" "$here/mcap.test.mjs" "$work/"
if [ ! -d "$work/node_modules/@mcap/core" ] || [ ! -d "$work/node_modules/fzstd" ]; then
  (cd "$work" && npm ci --no-audit --no-fund --loglevel=error)
fi
rm -rf "$work/out"
node "$work/mcap.test.mjs" "$bin" "$here/../../data" "$work/out"
