#!/usr/bin/env python3
"""End-to-end checks of `voronav explore`. Usage: cli_exploration.py VORONAV_BINARY REPO_ROOT CASE."""
import json
import os
import sys
import tempfile

from cli_util import check, runner

BIN, ROOT, CASE = sys.argv[1], sys.argv[2], sys.argv[3]
TB3 = os.path.join(ROOT, "data", "ros_maps", "turtlebot3_world", "map.yaml")


run = runner(BIN, timeout=240)


KEYS = ["coverage", "t90_s", "t99_s", "distance_m", "collisions", "feature_points", "leaves",
        "stalled_robots", "dispatches", "leaves_reached", "tree_time_s"]


def case_paper_json():
    out = json.loads(run("explore", "--world", "paper", "--robots", "4", "--time", "150",
                         "--tree-start", "80", "--json").stdout)
    for k in KEYS:
        check(k in out, f"missing {k}: {out}")
    check(out["method"] == "tree" and out["robots"] == 4, str(out))
    check(out["collisions"] == 0, "collisions in the paper world: " + str(out))
    check(0.0 < out["coverage"] <= 1.0, str(out))
    check(out["t99_s"] is None or out["t99_s"] >= (out["t90_s"] or 0), str(out))
    check(out["feature_points"] > 0 and out["leaves"] > 0, str(out))
    # One dispatch (the paper): one per robot, at the tree start.
    check(out["dispatches"] == 4 and out["tree_time_s"] == 80 and out["trees"] == 1, str(out))


def case_ros_map_coordinated():
    out = json.loads(run("explore", "--world", TB3, "--robots", "2", "--method", "coordinated",
                         "--time", "60", "--seed", "3", "--json").stdout)
    check(out["coverage"] > 0.9 and out["t90_s"] is not None, str(out))
    check(out["collisions"] == 0, str(out))
    # Same seed, same result.
    again = json.loads(run("explore", "--world", TB3, "--robots", "2", "--method", "coordinated",
                           "--time", "60", "--seed", "3", "--json").stdout)
    check(again == out, f"not deterministic: {out} vs {again}")


def case_out_folder():
    with tempfile.TemporaryDirectory() as d:
        run("explore", "--world", "paper", "--robots", "3", "--time", "100", "--tree-start", "60",
            "--out", d)
        for f in ["exploration.json", "explore.png", "tree.png"]:
            check(os.path.getsize(os.path.join(d, f)) > 100, f"{f} missing or empty")
        rec = json.load(open(os.path.join(d, "exploration.json")))["recording"]
        check(len(rec["frames"]) == 100 and len(rec["frames"][0]["poses"]) == 3, "frames")
        check(rec["tree"]["root"] >= 0 and len(rec["routes"]) == 3, "tree/routes")


def case_errors():
    p = run("explore", "--world", "paper", "--method", "random", expect=2)
    check("tree, frontier, coordinated" in p.stderr, p.stderr)
    p = run("explore", "--world", "paper", "--tree-replan", "always", expect=2)
    check("--tree-replan" in p.stderr and "none, robots" in p.stderr, p.stderr)
    p = run("explore", "--world", "paper", "--start", "0.05,0.05", expect=2)
    check("--start" in p.stderr and "not free" in p.stderr, p.stderr)
    p = run("explore", "--world", "paper", "--start", "abc", expect=2)
    check("--start" in p.stderr, p.stderr)
    p = run("explore", "--world", os.path.join(ROOT, "no_such_map.yaml"), expect=2)
    check("no_such_map.yaml" in p.stderr, p.stderr)


globals()["case_" + CASE]()
print("ok", CASE)
