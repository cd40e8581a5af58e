#!/usr/bin/python3
"""Where is the unknown left at the end of a run of the paper's tree method, and where were the robots?

Issue 14, stop 27 (depot, 4 robots, seeds 3, 10, 13 end below 99 %). Runs one exploration of
`--method tree` through the Python bindings and prints:
- the coverage at 400, 500, ..., 900 s;
- the largest clusters (8-connected) of the cells that coverage counts and the final team map does
  not know: size, centroid, extent [m];
- each robot's dealt leaves (figure 9's lists) [m];
- for each robot, from 400 s on (one frame in ten): its distance to the largest cluster (minimum,
  median) and the share of frames within 3 m of it (the laser's range).

Needs Debian's python3 with python3-numpy and python3-scipy.
Usage: PYTHONPATH=build/default/python /usr/bin/python3 bench/exploration_tree_trace.py
       WORLD SEED ROBOTS ['{"option": value, ...}']    (WORLD: a map file or 'paper')
"""
import json
import os
import sys

import numpy as np
from scipy import ndimage

import voronav as vn

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from exploration_reachable_unknown import ground_truth_blocked  # noqa: E402


def main():
    world, seed, robots = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
    options = json.loads(sys.argv[4]) if len(sys.argv) > 4 else {}
    if world == "paper":
        m = vn.explore.paper_world(0.05)
        options.setdefault("start", vn.Vec2(2.0, 2.0))
    else:
        m = vn.io.load_map(world)
    blocked, res = ground_truth_blocked(m)
    r = vn.explore.run(m, method="tree", robots=robots, seed=seed, time_limit=900.0,
                       stop_at_coverage=0.995, include_recording=True, **options)
    unknown = np.asarray(r["team_map"].array) < 0
    frames = r["recording"]["frames"]
    x0, y0 = frames[0]["poses"][0][:2]
    sx, sy = int((x0 - m.origin.x) / res), int((y0 - m.origin.y) / res)
    lab4, _ = ndimage.label(~blocked, structure=[[0, 1, 0], [1, 1, 1], [0, 1, 0]])
    left = (lab4 == lab4[sy, sx]) & unknown
    lab, n = ndimage.label(left, structure=np.ones((3, 3)))
    print(f"seed {seed}: coverage {r['coverage']:.4f}, t90 {r['t90_s']}, leaves {r['leaves']} "
          f"(reached {r['leaves_reached']}), unknown cells {int(left.sum())}")
    print("coverage % at", [(t, round(frames[t - 1]["coverage"] * 100, 1))
                             for t in range(400, 901, 100) if t <= len(frames)])
    sizes = ndimage.sum(left, lab, range(1, n + 1)) if n else np.array([])
    largest = None
    for k in np.argsort(-sizes)[:5]:
        ys, xs = np.nonzero(lab == k + 1)
        x, y = m.origin.x + (xs + 0.5) * res, m.origin.y + (ys + 0.5) * res
        largest = largest if largest is not None else np.stack([x, y], 1)
        print(f"  cluster {sizes[k] * res * res:.1f} m2: centroid ({x.mean():.1f}, {y.mean():.1f}), "
              f"x {x.min():.1f}-{x.max():.1f}, y {y.min():.1f}-{y.max():.1f}")
    for d in r["recording"]["dispatches"]:
        print(f"  robot {d['robot']} (t {d['t']:.0f} s) leaves: "
              + " ".join(f"({p[0]:.1f}, {p[1]:.1f})" for p in d["leaves"]))
    if largest is None:
        return
    for i in range(robots):
        dist = np.array([np.min(np.hypot(*(largest - np.array(f["poses"][i][:2])).T))
                         for f in frames[399::10]])
        if dist.size:
            print(f"  robot {i}, 400 s on: distance to the largest cluster min {dist.min():.1f} m, "
                  f"median {np.median(dist):.1f} m, within 3 m in {np.mean(dist < 3) * 100:.0f} % "
                  "of the frames")


if __name__ == "__main__":
    main()
