#!/usr/bin/env bash
# End-to-end browser test of the replay page (issue 9).
# Usage: tests/browser/run.sh VORONAV_BINARY BUILD_DIR
# Sets up BUILD_DIR/browser-test with prepare.sh (Debian's chromium when missing, playwright-core
# from the pinned package-lock.json, the shared launch module chromium.mjs), generates a page
# with `voronav replay --example`, and runs replay.test.mjs against it. The screenshot lands in BUILD_DIR/browser-test/replay.png.
set -euo pipefail
bin=${1:?usage: run.sh VORONAV_BINARY BUILD_DIR}
build=${2:?usage: run.sh VORONAV_BINARY BUILD_DIR}
here=$(cd "$(dirname "$0")" && pwd)
work="$build/browser-test"
bash "$here/prepare.sh" "$work" "$here/replay.test.mjs"

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
# A crowded exploration-style recording: 60 robots on a 120 x 80 map that is revealed over time
# (reveal times grow with the distance from the start), with a tree that appears at t = 5 s and
# 40 repeated requests 0.1 s apart (dense events).
python3 - "$work/many.json" <<'PY'
import json, math, sys
W, H, res, n = 120, 80, 0.25, 60
occ = []
for y in range(H):
    for x in range(W):
        occ.append(100 if x in (0, W - 1) or y in (0, H - 1) else 0)
def rle(v):
    out = []
    for a in v:
        if out and out[-2] == a: out[-1] += 1
        else: out += [a, 1]
    return out
reveal = [int(10 * 0.2 * math.hypot(x - 10, y - 10)) for y in range(H) for x in range(W)]
robots = []
for i in range(n):
    a = 2 * math.pi * i / n
    poses = [[0.1 * k, 2.5 + 0.005 * k * 20 * (1 + math.cos(a)), 2.5 + 0.005 * k * 12 * (1 + math.sin(a)), a] for k in range(0, 301, 10)]
    robots.append({"id": i + 1, "poses": poses})
json.dump({"format": "voronav-recording", "version": 1, "title": "many robots",
           "map": {"width": W, "height": H, "resolution": res, "occupancy": rle(occ)},
           "reveal": {"period_s": 0.1, "cells": rle(reveal)},
           "graphs": [{"name": "tree", "shown_from": 5.0, "nodes": [{"id": 0, "p": [3, 3]}, {"id": 1, "p": [20, 15]}], "edges": [[0, 1]]}],
           "robots": robots,
           "markers": [{"kind": "goal", "p": [25, 16], "robot": 1, "label": "goal of robot 1"}],
           "plots": [{"kind": "bar", "title": "distance per robot", "x_label": "robot", "y_label": "m",
                      "categories": ["robot %d" % (i + 1) for i in range(n)],
                      "series": [{"name": "distance", "y": [1.0 + i % 7 for i in range(n)]}]}],
           "events": [{"t": 5.0, "kind": "tree", "text": "the tree is built"}] +
                     [{"t": 10.0 + 0.1 * k, "kind": "blocked", "text": "robot 3 asks for a detour", "robot": 3} for k in range(40)]},
          open(sys.argv[1], "w"))
PY
rm -rf "$work/many"
"$bin" replay --recording "$work/many.json" --out "$work/many" >/dev/null
node "$work/replay.test.mjs" "$work/page/index.html" "$work/replay.png" \
  "$here/../../voronav/report/viewer.html" "$work/minimal/index.html" "$work/many/index.html"
