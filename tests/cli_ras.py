#!/usr/bin/env python3
"""End-to-end checks of `voronav plan --planner ras` (seed 001). Usage: cli_ras.py BIN ROOT CASE.

Runs the real binary on the bundled Moving AI arena map and checks the RAS JSON fields against an
independent breadth-first search over the region grid written here in Python."""
import collections
import json
import os
import sys
import tempfile

from cli_util import check, runner

BIN, ROOT, CASE = sys.argv[1], sys.argv[2], sys.argv[3]
ARENA = os.path.join(ROOT, "data", "movingai", "arena.map")


run = runner(BIN, timeout=240, stdout_limit=2000)


def load_map(path):
    """Blocked flags indexed [y][x] with y = 0 the bottom row (voronav cells)."""
    with open(path) as f:
        lines = f.read().split("\n")
    h = int(lines[1].split()[1])
    w = int(lines[2].split()[1])
    rows = lines[4:4 + h]
    return [[rows[h - 1 - y][x] not in ".GS" for x in range(w)] for y in range(h)], w, h


def region_grid(blocked, w, h, r):
    """Any-blocked rule; partial border regions keep their in-map cells."""
    rw, rh = (w + r - 1) // r, (h + r - 1) // r
    g = [[False] * rw for _ in range(rh)]
    for y in range(h):
        for x in range(w):
            if blocked[y][x]:
                g[y // r][x // r] = True
    return g, rw, rh


def bfs_steps(g, rw, rh, s, t, density=0):
    def free(c):
        return 0 <= c[0] < rw and 0 <= c[1] < rh and not g[c[1]][c[0]]

    def dens(c):
        return sum(free((c[0] + dx, c[1] + dy)) for dx in (-1, 0, 1) for dy in (-1, 0, 1)
                   if dx or dy)

    dist = {s: 0}
    q = collections.deque([s])
    while q:
        c = q.popleft()
        if c == t:
            return dist[c]
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                n = (c[0] + dx, c[1] + dy)
                if (dx or dy) and free(n) and n not in dist and (density == 0 or dens(n) >= density):
                    dist[n] = dist[c] + 1
                    q.append(n)
    return -1


def plan(*extra, expect=0):
    return json.loads(run("plan", "--map", ARENA, "--planner", "ras", "--json", *extra,
                          expect=expect).stdout)


START, GOAL = "3,3", "40,40"  # Moving AI file frame (x right, y down)


def to_cell(p, h):
    x, y = map(int, p.split(","))
    return x, h - 1 - y


def case_json_matches_bfs():
    blocked, w, h = load_map(ARENA)
    for r, density in [(1, 0), (2, 0), (3, 0), (2, 8)]:
        out = plan("--start", START, "--goal", GOAL, "--region-size", str(r), "--density",
                   str(density))
        check(out["status"] == "ok" and out["ras_status"] == "ok", str(out)[:300])
        check(out["planner"] == "ras" and out["region_size"] == r, "echo of options")
        g, rw, rh = region_grid(blocked, w, h, r)
        check(out["region_grid"] == [rw, rh], f"region grid {out['region_grid']} != {[rw, rh]}")
        s, t = to_cell(START, h), to_cell(GOAL, h)
        sr, tr = (s[0] // r, s[1] // r), (t[0] // r, t[1] // r)
        pr = out["path_regions"]
        want = bfs_steps(g, rw, rh, sr, tr, density)
        check(len(pr) - 1 == want, f"r={r} d={density}: {len(pr) - 1} steps, BFS says {want}")
        check(pr[0]["k"] == 0 and tuple(pr[0]["region"]) == sr, "path starts at region 0")
        check(tuple(pr[-1]["region"]) == tr, "path ends at the goal region")
        for i, (a, b) in enumerate(zip(pr, pr[1:])):
            check(max(abs(a["region"][0] - b["region"][0]), abs(a["region"][1] - b["region"][1]))
                  == 1, "consecutive path regions are neighbours")
            check(b["step"] == i + 1, "the i-th path region lies in expansion step i")
            check(a["k"] < b["k"], "ids grow along the path")
            check(not g[b["region"][1]][b["region"][0]], "path regions are free")
        check(out["regions"] >= len(pr), "numbered regions include the path")
        check(len(out["waypoints"]) == len(pr) + 2, "waypoints: start, centres, goal")
        if density == 8:
            for reg in pr[1:]:
                check(reg["d"] == 8, f"density-8 path region with d = {reg['d']}")


def case_directions():
    a = plan("--start", START, "--goal", GOAL, "--region-size", "2", "--direction", "default")
    b = plan("--start", START, "--goal", GOAL, "--region-size", "2", "--direction", "optimal")
    check(a["direction"] == "default" and b["direction"] == "optimal", "direction echo")
    check(len(a["path_regions"]) == len(b["path_regions"]), "both directions: minimum regions")
    check(b["regions"] <= a["regions"], f"optimal numbers {b['regions']} > default {a['regions']}")


def case_statuses():
    blocked, w, h = load_map(ARENA)
    # A goal next to the outer wall cannot reach density 8.
    fx, fy = next((x, y) for y in range(h) for x in range(w)
                  if not blocked[y][x] and any(blocked[y + dy][x + dx] for dx in (-1, 0, 1)
                                               for dy in (-1, 0, 1) if 0 <= y + dy < h and 0 <= x + dx < w))
    goal = f"{fx},{h - 1 - fy}"
    out = plan("--start", START, "--goal", goal, "--density", "8", expect=1)
    check(out["status"] == "unreachable" and out["ras_status"] == "goal_below_density", str(out)[:300])
    with tempfile.TemporaryDirectory() as d:
        m = os.path.join(d, "split.map")
        with open(m, "w") as f:
            f.write("type octile\nheight 3\nwidth 5\nmap\n..@..\n..@..\n..@..\n")
        out = json.loads(run("plan", "--map", m, "--planner", "ras", "--start", "0,0", "--goal",
                             "4,2", "--json", expect=1).stdout)
        check(out["status"] == "unreachable" and out["path_regions"] == [], str(out))
        out = json.loads(run("plan", "--map", m, "--planner", "ras", "--start", "2,0", "--goal",
                             "4,2", "--json", expect=1).stdout)
        check(out["status"] == "start_occupied", str(out))
        # Region size 2: the start region holds the wall.
        out = json.loads(run("plan", "--map", m, "--planner", "ras", "--region-size", "2",
                             "--start", "3,1", "--goal", "4,2", "--json", expect=1).stdout)
        check(out["ras_status"] == "start_blocked", str(out))


def case_bad_options():
    for opt, val in [("--density", "9"), ("--density", "-1"), ("--region-size", "0"),
                     ("--direction", "sideways")]:
        p = run("plan", "--map", ARENA, "--planner", "ras", "--start", START, "--goal", GOAL,
                opt, val, expect=2)
        check(opt in p.stderr or val in p.stderr, f"error must name {opt}: {p.stderr}")


def case_pictures():
    with tempfile.TemporaryDirectory() as d:
        png, svg = os.path.join(d, "ras.png"), os.path.join(d, "ras.svg")
        run("plan", "--map", ARENA, "--planner", "ras", "--start", START, "--goal", GOAL,
            "--region-size", "2", "--density", "8", "--png", png, "--svg", svg)
        with open(png, "rb") as f:
            check(f.read(8) == b"\x89PNG\r\n\x1a\n", "PNG signature")
        with open(svg) as f:
            text = f.read()
        check("<svg" in text, "SVG written")
        check(os.path.getsize(png) > 5000, "PNG is not trivially small")


CASES = {n[5:]: f for n, f in globals().items() if n.startswith("case_")}
if CASE not in CASES:
    sys.exit(f"unknown case {CASE}; known: {', '.join(CASES)}")
CASES[CASE]()
print("ok")
