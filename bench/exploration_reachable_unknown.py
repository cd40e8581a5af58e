#!/usr/bin/python3
"""How much of the unknown that exploration coverage counts could a robot's body reach?

Runs one exploration through the Python bindings. In the final team map it counts the unknown
cells among:
- the ground-truth free cells 4-connected to the start (the denominator of `coverage`);
- the cells where a disc of radius 0.12 m (the body), 0.17 m or 0.22 m (body + clearance, the
  planning grid) can centre, 8-connected to the start;
- the cells those discs cover.

The ground truth is rebuilt as the runner builds it: resampled to 0.1 m cells, unknown counts as
blocked, and the map's border is closed. Issue 14, stop 25: on willow (coordinated, seed 6) it
shows that the last 1.5 % that coverage counts is out of the planners' reach.

Needs Debian's python3 with python3-numpy and python3-scipy.
Usage: PYTHONPATH=build/default/python /usr/bin/python3 bench/exploration_reachable_unknown.py
       WORLD METHOD SEED ROBOTS [TIME_S]
"""
import sys

import numpy as np
from scipy import ndimage

import voronav as vn


def ground_truth_blocked(m, cell=0.1):
    a = np.asarray(m.array)
    k = int(np.floor(cell / m.resolution + 1e-9))
    if k < 2:
        blocked, res = (a >= 50) | (a < 0), m.resolution
    else:
        h, w = (a.shape[0] + k - 1) // k, (a.shape[1] + k - 1) // k
        blocked = np.zeros((h, w), bool)
        ys, xs = np.nonzero((a >= 50) | (a < 0))
        blocked[ys // k, xs // k] = True
        res = m.resolution * k
    blocked[0, :] = blocked[-1, :] = blocked[:, 0] = blocked[:, -1] = True
    return blocked, res


def main():
    world, method, seed, robots = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4])
    time_s = float(sys.argv[5]) if len(sys.argv) > 5 else 900.0
    m = vn.io.load_map(world)
    blocked, res = ground_truth_blocked(m)
    r = vn.explore.run(m, method=method, robots=robots, seed=seed, time_limit=time_s,
                       stop_at_coverage=0.995, include_recording=True)
    unknown = np.asarray(r["team_map"].array) < 0
    if unknown.shape != blocked.shape:
        sys.exit(f"team map {unknown.shape} and ground truth {blocked.shape} differ")
    x0, y0 = r["recording"]["frames"][0]["poses"][0][:2]
    sx, sy = int((x0 - m.origin.x) / res), int((y0 - m.origin.y) / res)
    free = ~blocked
    lab4, _ = ndimage.label(free, structure=[[0, 1, 0], [1, 1, 1], [0, 1, 0]])
    reach4 = lab4 == lab4[sy, sx]
    print(f"coverage {r['coverage']:.6f}, stalled robots {r['stalled_robots']}; unknown among the "
          f"{int(reach4.sum())} cells coverage counts: {int((reach4 & unknown).sum())}")
    clearance = ndimage.distance_transform_edt(free) * res
    for radius in (0.12, 0.17, 0.22):
        fits = clearance > radius + res / 2
        lab8, _ = ndimage.label(fits, structure=np.ones((3, 3)))
        centres = (lab8 == lab8[sy, sx]) if fits[sy, sx] else np.zeros_like(fits)
        covered = ndimage.binary_dilation(centres, iterations=max(1, round(radius / res))) & free
        print(f"radius {radius} m: unknown centre cells {int((centres & unknown).sum())} of "
              f"{int(centres.sum())}, unknown covered cells {int((covered & unknown).sum())}")


if __name__ == "__main__":
    main()
