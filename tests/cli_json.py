#!/usr/bin/env python3
"""Frames and units in the JSON outputs (issue 19, docs/ros.md): every pose {x, y, yaw} in metres
and radians with frame_id "map", cells with their convention named (cell_frame), the inputs
echoed, lengths as *_m, coverage as a fraction, timed waypoints [t, x, y] in schedules, and
out-of-map errors in the unit the user gave.
Usage: cli_json.py VORONAV_BINARY REPO_ROOT CASE."""
import json
import math
import os
import sys
import tempfile

from cli_util import check, runner

BIN, ROOT, CASE = sys.argv[1], sys.argv[2], sys.argv[3]
DATA = os.path.join(ROOT, "data")
TB3 = os.path.join(DATA, "ros_maps", "turtlebot3_world", "map.yaml")
ARENA = os.path.join(DATA, "movingai", "arena.map")
run = runner(BIN, timeout=120)


def is_pose(p, frame=True):
    keys = {"x", "y", "yaw"} | ({"frame_id"} if frame else set())
    return (isinstance(p, dict) and set(p) == keys and all(math.isfinite(p[k]) for k in "xy")
            and -math.pi <= p["yaw"] <= math.pi and (not frame or p["frame_id"] == "map"))


def near(a, b, tol=1e-9):
    return abs(a - b) <= tol


def case_plan_ros():
    j = json.loads(run("plan", "--map", TB3, "--start", "-1.9,-0.5", "--goal", "1.9,0.5",
                       "--radius", "0.1", "--json").stdout)
    check(j["frame_id"] == "map" and j["cell_frame"] == "grid_y_up", str(j)[:300])
    check(j["input"] == {"map": TB3, "start": [-1.9, -0.5], "goal": [1.9, 0.5], "units": "m",
                         "cell_frame": "grid_y_up", "radius_m": 0.1, "connectivity": 8},
          str(j["input"]))
    check(is_pose(j["start"]) and is_pose(j["goal"]), f"{j['start']} {j['goal']}")
    # The start/goal poses are the centres of the cells holding the given points (0.05 m cells).
    check(near(j["start"]["x"], -1.9, 0.0251) and near(j["start"]["y"], -0.5, 0.0251), str(j["start"]))
    check(near(j["goal"]["x"], 1.9, 0.0251) and near(j["goal"]["y"], 0.5, 0.0251), str(j["goal"]))
    check(near(j["length_m"], j["length"]) and near(j["length_m"], j["length_cells"] * 0.05),
          "length_m must be length_cells * resolution")
    poses = j["poses"]
    check(len(poses) == len(j["path_world"]) and all(is_pose(p, False) for p in poses), "poses")
    for a, b in zip(poses, poses[1:]):  # yaw points along the path
        check(near(a["yaw"], math.atan2(b["y"] - a["y"], b["x"] - a["x"])), f"yaw {a} -> {b}")
    check([poses[0]["x"], poses[0]["y"]] == j["path_world"][0], "poses[0] != path_world[0]")


def case_plan_movingai():
    j = json.loads(run("plan", "--map", ARENA, "--start", "3,3", "--goal", "40,40",
                       "--json").stdout)
    check(j["cell_frame"] == "movingai_y_down" and j["input"]["units"] == "cells", str(j)[:300])
    check(j["path"][0] == [3, 3] and j["path"][-1] == [40, 40], "path in the user's cells")
    # Cell (3, 3), y down, on the 49-row arena is the world point (3.5, 45.5).
    check(near(j["start"]["x"], 3.5) and near(j["start"]["y"], 45.5), str(j["start"]))
    check(near(j["goal"]["x"], 40.5) and near(j["goal"]["y"], 8.5), str(j["goal"]))


def case_errors_in_user_units():
    p = run("plan", "--map", TB3, "--start", "30,0", "--goal", "1,1", expect=2)
    check("m" in p.stderr and "-10 .. 9.2 m" in p.stderr, p.stderr)
    p = run("plan", "--map", ARENA, "--start", "60,3", "--goal", "1,1", expect=2)
    check("49x49 cell map" in p.stderr, p.stderr)


def case_topo():
    j = json.loads(run("topo", "--map", TB3, "--json").stdout)
    check(j["frame_id"] == "map" and j["cell_frame"] == "grid_y_up", str(j)[:300])
    check(is_pose(j["origin"]) and near(j["origin"]["x"], -10) and near(j["origin"]["y"], -10),
          str(j["origin"]))
    check(j["resolution_unit"] == "m/cell" and near(j["resolution"], 0.05), "resolution")
    cp = j["critical_points"][0]
    x = -10 + (cp["cell"][0] + 0.5) * 0.05
    check(near(cp["world"][0], x), f"critical point world/cell frames disagree: {cp}")


def case_coordinate():
    with tempfile.TemporaryDirectory() as out:
        j = json.loads(run("coordinate", "--scenario",
                           os.path.join(DATA, "coordination", "arena_four.yaml"), "--search",
                           "exhaustive", "--json", "--out", out).stdout)
        check(j["frame_id"] == "map" and j["units"] == {"time": "s", "length": "m"}, str(j)[:200])
        for a in j["agents"]:
            check(is_pose(a["start"]) and is_pose(a["goal"]), str(a)[:200])
            w = a["waypoints"]
            check(near(w[0][0], a["delay"]) and near(w[-1][0], a["arrival"], 1e-6),
                  f"robot {a['id']}: waypoints must run from its delay to its arrival: {w}")
            check(all(p[0] <= q[0] for p, q in zip(w, w[1:])), "waypoint times decrease")
            check([w[0][1], w[0][2]] == [a["start"]["x"], a["start"]["y"]], "first waypoint")
        # Robot 1 starts at cell (3, 5) (y down) of the 49-row arena: (3.5, 43.5) m.
        r1 = next(a for a in j["agents"] if a["id"] == 1)
        check(near(r1["start"]["x"], 3.5) and near(r1["start"]["y"], 43.5), str(r1["start"]))
        with open(os.path.join(out, "schedule.json")) as f:
            s = json.load(f)
        check(s["frame_id"] == "map" and s["units"]["time"] == "s", str(s)[:200])
        for sa, ja in zip(s["agents"], j["agents"]):
            # Delay schedules carry the node times as "timed_path" ("waypoints" is SIPP's motion).
            check(sa["timed_path"] == ja["waypoints"], "schedule.json timed_path differs from --json")
        # The schedule with its new fields still validates.
        run("validate-schedule", os.path.join(out, "schedule.yaml"))


def case_explore():
    with tempfile.TemporaryDirectory() as out:
        # --map, as every command takes it (--world is the older name of the same option).
        j = json.loads(run("explore", "--map", "paper", "--robots", "2", "--time", "30",
                           "--start", "2,2", "--json", "--out", out).stdout)
        check(0.0 <= j["coverage"] <= 1.0, "coverage must be a fraction")
        check(j["frame_id"] == "map" and j["units"]["coverage"] == "fraction"
              and j["units"]["length"] == "m" and j["units"]["time"] == "s", str(j)[:300])
        check(j["input"]["map"] == "paper" and j["input"]["robots"] == 2
              and j["input"]["time_s"] == 30 and j["input"]["start"] == [2, 2], str(j["input"]))
        # Every on/off option is echoed (the tree's stop-26/27 options were missing until stop 27).
        for k in ("disperse_neighbours", "clear_way_out", "unknown_leaves_first", "nearest_leaf_next",
                  "frontiers_after_leaves", "skip_known_leaves", "margin_escape", "unstick_retry",
                  "unstick_right_of_way"):
            check(j["input"].get(k) in ("on", "off"), k)
        check(len(j["robot_poses"]) == 2, str(j["robot_poses"]))
        for p in j["robot_poses"]:
            check(is_pose(p["start"]) and is_pose(p["final"]), str(p))
            check(near(p["start"]["x"], 2, 1.0) and near(p["start"]["y"], 2, 1.0), str(p))
        with open(os.path.join(out, "exploration.json")) as f:
            e = json.load(f)
            check(0.0 <= e["coverage"] <= 1.0, "exploration.json coverage")
            check(e["frame_id"] == "map" and e["input"] == j["input"], "exploration.json frames")
        old = json.loads(run("explore", "--world", "paper", "--robots", "2", "--time", "30",
                             "--start", "2,2", "--json").stdout)
        check(old["coverage"] == j["coverage"], "--world and --map give the same run")


def case_netsim():
    corridor = os.path.join(DATA, "netsim", "corridor.yaml")
    j = json.loads(run("netsim", "--scenario", corridor, "--method", "decentralized",
                       "--json").stdout)
    check(j["frame_id"] == "map" and j["units"]["length"] == "m" and j["units"]["time"] == "s"
          and j["units"]["traffic"] == "bytes" and j["units"]["success_rate"] == "fraction",
          str(j)[:300])
    check(j["methods"] == ["decentralized"], str(j["methods"]))
    i = j["input"]
    check(i["scenario"] == corridor and i["runs"] == 1 and i["transport"] == "sim"
          and i["radio_range_m"] > 0 and i["dt_s"] > 0, str(i))
    m = j["decentralized"]
    check(0.0 <= m["success_rate"] <= 1.0, "success_rate must be a fraction")
    r = m["per_run"][0]
    check(is_pose(r["source_start"]) and is_pose(r["destination"]), str(r)[:300])
    # The corridor's source (robot 0) starts at (2.1, 1.7); the destination is (38.5, 1.7).
    check(near(r["source_start"]["x"], 2.1) and near(r["source_start"]["y"], 1.7), str(r))
    check(near(r["destination"]["x"], 38.5) and near(r["destination"]["y"], 1.7), str(r))
    check(r["source"] == 0 and r["robot_count"] == 10, str(r)[:300])


CASES = {name[5:]: f for name, f in globals().items() if name.startswith("case_")}
if CASE not in CASES:
    sys.exit(f"unknown case {CASE}; known: {', '.join(CASES)}")
CASES[CASE]()
print("ok", CASE)
