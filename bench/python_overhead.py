#!/usr/bin/env python3
"""Cost of voronav from Python against C++ (issue 18), written to bench/results/python.md.

1. One Moving AI query on den520d: mean time per query of A* over an even sample of the .scen
   queries, from Python (voronav.Planner.plan on a prebuilt BinaryGrid) and from C++
   (bench/python_overhead_bench.cpp, the same sample, planner and grid), in alternating rounds of
   the same run; the best round of each side is compared (target: Python < 5 % more).
   The split inside each Python call is reported too: wall time minus the planner's own time_ms.
2. Passing a 2000 x 2000 grid into C++ (voronav.BinaryGrid(array): one copy into the C++ grid)
   and getting it out (grid.array / np.asarray(grid): zero-copy views); target: < 1 ms.

Usage: PYTHONPATH=build/default/python /usr/bin/python3 bench/python_overhead.py \
           [--build build/default] [--rounds 5] [--sample 200] [--map den520d]
"""

from __future__ import annotations

import argparse
import datetime
import json
import os
import pathlib
import platform
import statistics
import subprocess
import sys
import time

import numpy as np

ROOT = pathlib.Path(__file__).resolve().parents[1]


def data_dir() -> pathlib.Path:
    if "VORONAV_MOVINGAI_DIR" in os.environ:
        return pathlib.Path(os.environ["VORONAV_MOVINGAI_DIR"])
    for p in (ROOT / "../shared/data/movingai", ROOT / "../../shared/data/movingai",
              pathlib.Path("/work/shared/data/movingai")):
        if p.exists():
            return p.resolve()
    return ROOT / "data/movingai"


def cpp_round(binary: pathlib.Path, env: dict) -> float:
    """us per query from one run of the C++ benchmark."""
    out = subprocess.run([str(binary), "--benchmark_format=json", "--benchmark_min_time=1"],
                         capture_output=True, text=True, check=True, env=env)
    b = json.loads(out.stdout)["benchmarks"][0]
    assert b["time_unit"] == "ms"
    return b["real_time"] * 1000.0 / b["queries"]


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--build", default=str(ROOT / "build/default"))
    ap.add_argument("--rounds", type=int, default=5)
    ap.add_argument("--sample", type=int, default=200)
    ap.add_argument("--map", default="den520d")
    ap.add_argument("--out", default=str(ROOT / "bench/results/python.md"))
    a = ap.parse_args()
    sys.path.insert(0, str(pathlib.Path(a.build) / "python"))
    import voronav as vn

    d = data_dir()
    grid = vn.io.load_movingai_map(str(d / f"{a.map}.map"))
    allq = vn.io.load_movingai_scen(str(d / f"{a.map}.map.scen"))
    step = max(1, len(allq) // max(1, a.sample))
    queries = allq[::step][: a.sample]
    pairs = [(q.start_cell, q.goal_cell) for q in queries]
    blocked = vn.binarize(grid)
    planner = vn.Planner("astar")
    binary = pathlib.Path(a.build) / "bin/python_overhead_bench"
    env = dict(os.environ, VORONAV_MOVINGAI_DIR=str(d), VORONAV_BENCH_MAP=a.map,
               VORONAV_BENCH_SAMPLE=str(a.sample))

    py_rounds, cpp_rounds, inside = [], [], []
    for _ in range(a.rounds):
        cpp_rounds.append(cpp_round(binary, env))
        reps, t_in, t0 = 0, 0.0, time.perf_counter()
        while True:
            for s, g in pairs:
                r = planner.plan(blocked, s, g)
                t_in += r.time_ms
            reps += 1
            if time.perf_counter() - t0 >= 1.0:
                break
        wall = time.perf_counter() - t0
        py_rounds.append(wall * 1e6 / (reps * len(pairs)))
        inside.append((wall * 1e3 - t_in) * 1e3 / (reps * len(pairs)))  # us per call outside C++ plan()
    py, cpp = min(py_rounds), min(cpp_rounds)
    ratio = py / cpp

    # Passing a 2000 x 2000 grid.
    rng = np.random.default_rng(1)
    arr = (rng.random((2000, 2000)) < 0.2).astype(np.uint8)
    occ = np.where(arr == 1, 100, 0).astype(np.int8)

    def best_ms(fn, n=30) -> tuple[float, float]:
        ts = []
        for _ in range(n):
            t = time.perf_counter()
            fn()
            ts.append((time.perf_counter() - t) * 1e3)
        return min(ts), statistics.median(ts)

    g2000 = vn.BinaryGrid(arr)
    rows_pass = [
        ("BinaryGrid(uint8 array) (copy into C++)", best_ms(lambda: vn.BinaryGrid(arr, 0.05))),
        ("OccupancyGrid(int8 array) (copy into C++)", best_ms(lambda: vn.OccupancyGrid(occ, 0.05))),
        ("grid.array (zero-copy view out)", best_ms(lambda: g2000.array)),
        ("np.asarray(grid) (buffer protocol, zero copy)", best_ms(lambda: np.asarray(g2000))),
        ("field.distance_transform(grid).squared_distance.array (for scale)",
         best_ms(lambda: vn.field.distance_transform(g2000).squared_distance.array, n=5)),
    ]
    assert np.shares_memory(g2000.array, np.asarray(g2000))

    cpus = os.cpu_count()
    load = os.getloadavg()[0]
    lines = [
        "# Python bindings: overhead against C++",
        "",
        f"Measured {datetime.date.today()} on {cpus} CPUs (load average {load:.1f} at the end, a shared "
        f"machine), {platform.python_implementation()} {platform.python_version()}; "
        f"`PYTHONPATH=build/default/python /usr/bin/python3 bench/python_overhead.py --rounds {a.rounds} "
        f"--sample {a.sample}` (C++ side: `bench/python_overhead_bench.cpp`).",
        "",
        f"## One Moving AI query ({a.map}, A*, {len(pairs)} queries evenly over the .scen, {a.rounds} "
        "alternating rounds, best round of each side)",
        "",
        "| side | us/query (best round) | all rounds |",
        "|---|---|---|",
        f"| C++ `AStarPlanner::plan` | {cpp:.1f} | {', '.join(f'{x:.1f}' for x in cpp_rounds)} |",
        f"| Python `voronav.Planner.plan` | {py:.1f} | {', '.join(f'{x:.1f}' for x in py_rounds)} |",
        "",
        f"Python / C++ = **{ratio:.3f}** ({(ratio - 1) * 100:+.1f} %; target < +5 %). "
        f"Inside each Python call, the time outside the C++ planner (argument conversion, GIL release, "
        f"result object) is {min(inside):.2f} us per query (best round; the planner's own time_ms subtracted).",
        "",
        "## Passing a 2000 x 2000 grid (target < 1 ms)",
        "",
        "| operation | best ms | median ms |",
        "|---|---|---|",
    ]
    for name, (best, med) in rows_pass:
        lines.append(f"| {name} | {best:.3f} | {med:.3f} |")
    lines += [
        "",
        "Into C++ a grid is copied once (the C++ API takes `GridMap` by reference, which owns its "
        "vector); out of C++ every grid is a zero-copy numpy view (`np.shares_memory` is checked by "
        "the tests).",
        "",
    ]
    pathlib.Path(a.out).write_text("\n".join(lines))
    print("\n".join(lines))
    return 0


if __name__ == "__main__":
    sys.exit(main())
