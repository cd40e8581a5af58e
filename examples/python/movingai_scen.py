#!/usr/bin/env python3
"""Runs every query of a Moving AI scenario file and prints the mismatches with the optimal lengths.

    PYTHONPATH=build/default/python /usr/bin/python3 examples/python/movingai_scen.py \
        data/movingai/den312d.map data/movingai/den312d.map.scen [--planner dijkstra]

Exit code 1 when any query is unsolved or differs from the optimal length (as `voronav scen`).
"""

from __future__ import annotations

import argparse
import sys
import time

import voronav as vn


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("map")
    ap.add_argument("scen")
    ap.add_argument("--planner", default="astar", choices=vn.planner_names())
    a = ap.parse_args()

    grid = vn.io.load_movingai_map(a.map)
    queries = vn.io.load_movingai_scen(a.scen)
    vn.io.check_scen_fits(queries, grid, a.scen)
    blocked = vn.binarize(grid)
    planner = vn.Planner(a.planner)
    mismatches = 0
    t0 = time.perf_counter()
    for q in queries:
        r = planner.plan(blocked, q.start_cell, q.goal_cell)
        if not r.ok or abs(r.length_cells - q.optimal_length) > q.optimal_rounding + 1e-9:
            mismatches += 1
            print(f"  line {q.line}: ({q.start_x}, {q.start_y}) -> ({q.goal_x}, {q.goal_y}): "
                  f"{r.status}, found {r.length_cells:.6f}, optimal {q.optimal_length}")
    ms = (time.perf_counter() - t0) * 1000.0
    print(f"{a.map}: {len(queries)} queries, {mismatches} mismatches, {ms:.1f} ms ({a.planner})")
    return 1 if mismatches else 0


if __name__ == "__main__":
    sys.exit(main())
