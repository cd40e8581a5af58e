#!/usr/bin/env python3
"""End-to-end checks of the voronav CLI. Usage: cli_check.py VORONAV_BINARY REPO_ROOT CASE.

Each case runs the real binary on the bundled data and asserts outcomes (exit codes, JSON values,
files written, error messages that name what was wrong)."""
import json
import math
import os
import sys
import tempfile

from cli_util import check, runner

BIN, ROOT, CASE = sys.argv[1], sys.argv[2], sys.argv[3]
DATA = os.path.join(ROOT, "data")
ARENA = os.path.join(DATA, "movingai", "arena.map")
TB3 = os.path.join(DATA, "ros_maps", "turtlebot3_world", "map.yaml")


run = runner(BIN, timeout=240)


def scen_rows(path):
    rows = []
    with open(path) as f:
        next(f)
        for line in f:
            c = line.split()
            if len(c) >= 9:
                rows.append((int(c[4]), int(c[5]), int(c[6]), int(c[7]), float(c[8])))
    return rows


def case_scen_arena():
    out = json.loads(run("scen", "--map", ARENA, "--scen", ARENA + ".scen", "--json").stdout)
    check(out["queries"] == len(scen_rows(ARENA + ".scen")) and out["queries"] > 0, str(out))
    check(out["mismatches"] == 0 and out["unsolved"] == 0, str(out))
    out = json.loads(run("scen", "--map", ARENA, "--scen", ARENA + ".scen", "--planner",
                         "dijkstra", "--json").stdout)
    check(out["mismatches"] == 0 and out["unsolved"] == 0, "dijkstra: " + str(out))


def case_scen_jps_and_wild_formats():
    """Issue #16: jps and jps+ on a shipped map, query subsets and per-query CSV, and the Moving AI
    files as they are in the wild (space-separated v1.0, %g lengths, water, scaled maps)."""
    astar = json.loads(run("scen", "--map", ARENA, "--scen", ARENA + ".scen", "--json").stdout)
    for planner in ("jps", "jps+"):
        out = json.loads(run("scen", "--map", ARENA, "--scen", ARENA + ".scen", "--planner",
                             planner, "--json").stdout)
        check(out["planner"] == planner and out["mismatches"] == 0 and out["unsolved"] == 0,
              str(out))
        check(out["expanded_total"] < astar["expanded_total"], f"{planner}: {out} vs {astar}")
    out = json.loads(run("scen", "--map", ARENA, "--scen", ARENA + ".scen", "--first", "7",
                         "--json").stdout)
    check(out["queries"] == 7 and out["first_id"] == 0, str(out))
    with tempfile.TemporaryDirectory() as d:
        csv = os.path.join(d, "q.csv")
        out = json.loads(run("scen", "--map", ARENA, "--scen", ARENA + ".scen", "--range", "5:15",
                             "--per-query", csv, "--json").stdout)
        lines = open(csv).read().splitlines()
        check(out["queries"] == 10 and lines[0] == "id,length,expected,expanded,us", str(lines[:2]))
        ids = [int(l.split(",")[0]) for l in lines[1:]]
        check(ids == list(range(5, 15)), str(ids))
        check(sum(int(l.split(",")[3]) for l in lines[1:]) == out["expanded_total"], str(out))
        p = run("scen", "--map", ARENA, "--scen", ARENA + ".scen", "--range", "9:3", expect=2)
        check("--range" in p.stderr and "9:3" in p.stderr, p.stderr)
        # The reproduction: empty 970x170, corner to corner, "1039" printed by %g.
        m = os.path.join(d, "empty.map")
        with open(m, "w") as f:
            f.write("type octile\nheight 170\nwidth 970\nmap\n" + ("." * 970 + "\n") * 170)
        with open(m + ".scen", "w") as f:
            f.write("version 1.0\n0 empty.map 970 170 0 0 969 169 1039\n")
        for planner in ("astar", "jps", "jps+"):
            out = json.loads(run("scen", "--map", m, "--scen", m + ".scen", "--planner", planner,
                                 "--json").stdout)
            check(out["mismatches"] == 0 and out["expanded_total"] < 2000, f"{planner}: {out}")
        with open(m + ".bad.scen", "w") as f:
            f.write("version 1.0\n0 empty.map 970 170 0 0 969 169 1038.9\n")
        run("scen", "--map", m, "--scen", m + ".bad.scen", "--json", expect=1)
        # Water to water (W is traversable from water only); land queries avoid the pool; the
        # scenario's size columns ask for the map scaled 2x.
        w = os.path.join(d, "pool.map")
        with open(w, "w") as f:
            f.write("type octile\nheight 3\nwidth 4\nmap\n.WW.\n.WW.\n....\n")
        with open(w + ".scen", "w") as f:
            f.write("version 1\n0\tpool.map\t4\t3\t1\t0\t2\t1\t1.41421356\n"
                    "0\tpool.map\t4\t3\t0\t0\t3\t0\t7\n"
                    "0\tpool.map\t8\t6\t2\t0\t5\t3\t4.24264069\n")
        out = json.loads(run("scen", "--map", w, "--scen", w + ".scen", "--json").stdout)
        check(out["mismatches"] == 0 and out["unsolved"] == 0, str(out))
        check(out["water_queries"] == 2 and out["scaled_queries"] == 1, str(out))


def case_scen_mapf_map():
    m = os.path.join(DATA, "mapf", "random-32-32-20.map")
    s = os.path.join(DATA, "mapf", "random-32-32-20-random-1.scen")
    out = json.loads(run("scen", "--map", m, "--scen", s, "--json").stdout)
    check(out["queries"] > 0 and out["mismatches"] == 0 and out["unsolved"] == 0, str(out))


def case_plan_movingai_matches_scen():
    rows = scen_rows(ARENA + ".scen")
    for sx, sy, gx, gy, opt in [rows[0], rows[len(rows) // 2], rows[-1]]:
        out = json.loads(run("plan", "--map", ARENA, "--start", f"{sx},{sy}", "--goal",
                             f"{gx},{gy}", "--json").stdout)
        check(out["status"] == "ok", str(out))
        check(abs(out["cells"] - opt) < 1e-4, f"length {out['cells']} != optimal {opt}")
        check(out["path"][0] == [sx, sy] and out["path"][-1] == [gx, gy],
              "path endpoints must be in the .scen frame")
        # consecutive cells are neighbours and the octile sum equals the reported length
        total = 0.0
        for (x0, y0), (x1, y1) in zip(out["path"], out["path"][1:]):
            check(max(abs(x1 - x0), abs(y1 - y0)) == 1, "path steps must be neighbours")
            total += math.sqrt(2) if x0 != x1 and y0 != y1 else 1.0
        check(abs(total - out["cells"]) < 1e-6, "octile sum of path differs from length")


def case_plan_ros_world_frame():
    out = json.loads(run("plan", "--map", TB3, "--start", "-1.9,-0.5", "--goal", "1.9,0.5",
                         "--radius", "0.1", "--json").stdout)
    check(out["status"] == "ok", str(out)[:300])
    check(out["length_unit"] == "m" and out["length"] > 3.8, f"length {out['length']}")
    check(abs(out["length"] - out["cells"] * 0.05) < 1e-9, "length must be cells * resolution")
    x, y = out["path_world"][0]
    check(abs(x + 1.9) <= 0.05 and abs(y + 0.5) <= 0.05, f"start {x},{y}")


def case_plan_pictures():
    with tempfile.TemporaryDirectory() as d:
        png, svg = os.path.join(d, "p.png"), os.path.join(d, "p.svg")
        run("plan", "--map", ARENA, "--start", "4,4", "--goal", "40,40", "--expanded", "--png",
            png, "--svg", svg)
        with open(png, "rb") as f:
            check(f.read(8) == b"\x89PNG\r\n\x1a\n", "PNG signature")
        with open(svg) as f:
            check("<svg" in f.read(), "SVG content")


def case_plan_unreachable_and_occupied():
    # arena: (0,0) is a wall ('@' on the first line)
    with open(ARENA) as f:
        lines = f.read().split("\n")[4:]
    blocked = next((x, y) for y, row in enumerate(lines) for x, ch in enumerate(row) if ch in "@OTW")
    free = next((x, y) for y, row in enumerate(lines) for x, ch in enumerate(row) if ch == ".")
    out = json.loads(run("plan", "--map", ARENA, "--start", f"{free[0]},{free[1]}", "--goal",
                         f"{blocked[0]},{blocked[1]}", "--json", expect=1).stdout)
    check(out["status"] == "goal_occupied", str(out))
    out = json.loads(run("plan", "--map", ARENA, "--start", f"{blocked[0]},{blocked[1]}",
                         "--goal", f"{free[0]},{free[1]}", "--json", expect=1).stdout)
    check(out["status"] == "start_occupied", str(out))
    with tempfile.TemporaryDirectory() as d:
        m = os.path.join(d, "split.map")
        with open(m, "w") as f:
            f.write("type octile\nheight 3\nwidth 5\nmap\n..@..\n..@..\n..@..\n")
        out = json.loads(run("plan", "--map", m, "--start", "0,0", "--goal", "4,2", "--json",
                             expect=1).stdout)
        check(out["status"] == "unreachable", str(out))


def case_error_missing_map():
    p = run("plan", "--map", "/nonexistent/x.yaml", "--start", "0,0", "--goal", "1,1", expect=2)
    check("/nonexistent/x.yaml" in p.stderr, "error must name the file: " + p.stderr)


def case_error_bad_point():
    p = run("plan", "--map", ARENA, "--start", "1,abc", "--goal", "1,1", expect=2)
    check("--start" in p.stderr and "1,abc" in p.stderr, p.stderr)
    p = run("plan", "--map", ARENA, "--start", "nan,1", "--goal", "1,1", expect=2)
    check("--start" in p.stderr, p.stderr)


def case_error_point_outside():
    p = run("plan", "--map", ARENA, "--start", "1,1", "--goal", "100000,3", expect=2)
    check("--goal" in p.stderr and "outside" in p.stderr, p.stderr)


def case_error_malformed_map():
    with tempfile.TemporaryDirectory() as d:
        m = os.path.join(d, "bad.map")
        with open(m, "w") as f:
            f.write("type octile\nheight 2\nwidth 3\nmap\n...\n.X.\n")
        p = run("plan", "--map", m, "--start", "0,0", "--goal", "2,0", expect=2)
        check("bad.map:6" in p.stderr, "error must name file and line: " + p.stderr)
        y = os.path.join(d, "bad.yaml")
        with open(y, "w") as f:
            f.write("image: missing.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n"
                    "occupied_thresh: 0.65\nfree_thresh: 0.196\nnegate: 0\n")
        p = run("plan", "--map", y, "--start", "0,0", "--goal", "1,1", expect=2)
        check("missing.pgm" in p.stderr, "error must name the missing image: " + p.stderr)


def case_demo():
    with tempfile.TemporaryDirectory() as d:
        out = os.path.join(d, "demo")
        p = run("demo", "--out", out, "--mcap")
        check(os.path.abspath(out) in p.stdout, "demo must print its output folder")
        # --mcap: each stage as a ROS 2 bag (read back fully by tests/mcap, docs/ros.md)
        for bag in ("plan", "topology", "coordination", "netsim", "explore"):
            with open(os.path.join(out, bag + ".mcap"), "rb") as f:
                data = f.read()
            check(data[:8] == b"\x89MCAP0\r\n" and data[-8:] == data[:8] and len(data) > 1000,
                  bag + ".mcap must be a complete MCAP file")
        summary = json.load(open(os.path.join(out, "summary.json")))
        plan = summary["plan"]
        check(plan["astar"]["status"] == "ok", str(plan))
        check(abs(plan["astar"]["length_m"] - plan["dijkstra"]["length_m"]) < 1e-9,
              "A* and Dijkstra must find equally long paths")
        # The topological and RAS paths are not shorter than the optimal grid path.
        for name in ("topo", "ras"):
            check(plan[name]["status"] == "ok", name + ": " + str(plan[name]))
            check(plan[name]["length_m"] >= plan["astar"]["length_m"] - 1e-9, name)
        check(summary["map"]["agreement_pct"] > 95, str(summary["map"]))
        check(summary["topology"]["regions"] > 1 and summary["topology"]["critical_points"] > 0,
              str(summary["topology"]))
        co = summary["coordination"]
        check(co["valid"] is True and co["status"] == "ok", str(co))
        check(co["makespan_s"] >= max(a["arrival_s"] for a in co["agents"]) - 1e-9, str(co))
        # Priorities matter in the demo's team: some robots wait, and the searched order is no
        # worse than the id order.
        check(co["nonzero_delays"] >= 1 and any(a["delay_s"] > 0 for a in co["agents"]), str(co))
        # (the id order may have no delay schedule at all: then the search is what found one)
        check(co["default_order_status"] != "ok" or
              co["makespan_s"] <= co["default_order_makespan_s"] + 1e-9, str(co))
        check(summary["exploration"]["coverage"] >= 0.9, "the paper's tree explores >= 90 %: " +
              str(summary["exploration"]))
        check(summary["networked"]["success"] is True, str(summary["networked"]))
        # The obstacle change lies on the route while the source drives it, and a local Repair
        # (Tables 4-5) handles it.
        check(summary["networked"]["changes_on_route"] >= 1 and
              summary["networked"]["repairs_executed"] >= 1, str(summary["networked"]))
        dds = summary["networked_dds"]
        check(dds["ok"] and dds["same_as_in_process"], f"the DDS run equals the in-process one: {dds}")
        check(summary["exploration"]["collisions"] == 0, str(summary["exploration"]))
        check(summary["exploration"]["coverage_pct"] > 20, str(summary["exploration"]))
        check(abs(summary["exploration"]["coverage"] * 100 - summary["exploration"]["coverage_pct"])
              < 1e-9, "coverage is the fraction of coverage_pct")
        check(summary["movingai"]["mismatches"] == 0 and summary["movingai"]["unsolved"] == 0,
              str(summary["movingai"]))
        for name in ("1_occupancy_map.png", "3_plan_astar.png", "3_plan_ras.png",
                     "4_coordination.png", "2_topology/f_graph.png"):
            check(os.path.getsize(os.path.join(out, name)) > 1000, name)
        for page in ("index.html", "netsim.html", "explore.html"):
            html = open(os.path.join(out, page)).read()
            check("voronav-recording" in html and "http://" not in html.replace(
                "http://www.w3.org", ""), page + " must be a self-contained replay page")
        # What the pages tell (issue 20): the events come from the runs themselves and the robot
        # ids are the ids of summary.json.
        def recording(page):
            html = open(os.path.join(out, page)).read()
            start = html.index('<script id="recording" type="application/json">')
            start = html.index(">", start) + 1
            return json.loads(html[start:html.index("</script>", start)])
        net = recording("netsim.html")
        repairs = [e for e in net["events"] if e["kind"] == "repair"]
        check(len(repairs) == summary["networked"]["repairs_executed"],
              f"one repair event per Repair executed: {len(repairs)} events, {summary['networked']}")
        check(all("robot" in e and e["t"] >= summary["networked"]["route_time_s"] for e in repairs),
              "repair events name their robot and come after the route: " + str(repairs[:3]))
        check(sorted(r["id"] for r in net["robots"]) == list(range(summary["networked"]["robots"])),
              "netsim page ids 0..N-1 as the scenario and --kill-robot")
        ex = recording("explore.html")
        kinds = {e["kind"] for e in ex["events"]}
        check("tree" in kinds and "leaf" in kinds, f"exploration events: {sorted(kinds)}")
        first_tree = min(e["t"] for e in ex["events"] if e["kind"] == "tree")
        trees = [g for g in ex["graphs"] if g["name"] == "Voronoi tree"]
        check(len(trees) == 1 and trees[0].get("shown_from") == first_tree,
              "the tree is drawn from its first build, not from t = 0: " +
              str([(g["name"], g.get("shown_from")) for g in ex["graphs"]]))
        check(sorted(r["id"] for r in recording("index.html")["robots"]) ==
              sorted(a["id"] for a in co["agents"]), "coordination page ids are the summary's ids")
        check(sorted(a["id"] for a in co["agents"]) == list(range(len(co["agents"]))),
              "the demo numbers every team from 0: " + str(co["agents"]))


globals()["case_" + CASE]()
print(f"cli {CASE}: passed")
