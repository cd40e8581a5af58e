#!/usr/bin/env python3
"""End-to-end checks of `voronav coordinate` and `voronav validate-schedule` (seed 002).
Usage: cli_coordination.py VORONAV_BINARY REPO_ROOT CASE."""
import json
import math
import os
import sys
import tempfile

from cli_util import check, runner

BIN, ROOT, CASE = sys.argv[1], sys.argv[2], sys.argv[3]
DATA = os.path.join(ROOT, "data")
MAPF_MAP = os.path.join(DATA, "mapf", "random-32-32-20.map")
MAPF_SCEN = os.path.join(DATA, "mapf", "random-32-32-20-random-1.scen")
CROSSING = os.path.join(DATA, "coordination", "crossing.yaml")
ARENA = os.path.join(DATA, "coordination", "arena_four.yaml")


run = runner(BIN, timeout=120)


def check_summary(out, n):
    check(len(out["agents"]) == n, str(out))
    arrivals = [a["arrival"] for a in out["agents"]]
    for a in out["agents"]:
        check(abs(a["arrival"] - (a["delay"] + a["travel"])) < 1e-6, "arrival = delay + travel")
        check(a["delay"] >= 0, "delay >= 0")
    check(abs(out["makespan"] - max(arrivals)) < 1e-6, "makespan = max arrival")
    check(abs(out["sum_of_arrivals"] - sum(arrivals)) < 1e-6, "sum of arrivals")
    check(out["makespan"] >= max(a["travel"] for a in out["agents"]) - 1e-9, "makespan >= travel")


def case_crossing_delay():
    out = json.loads(run("coordinate", "--scenario", CROSSING, "--search", "none", "--json").stdout)
    check(out["valid"] and out["status"] == "ok", str(out))
    check_summary(out, 2)
    d = {a["id"]: a["delay"] for a in out["agents"]}
    check(d[1] == 0 and abs(d[2] - 2.25) < 1e-9, "hand-computed delay 2.25 s: " + str(d))
    # The scenario has a map (two crossing corridors): a replay page and a trajectory picture.
    with tempfile.TemporaryDirectory() as o:
        run("coordinate", "--scenario", CROSSING, "--search", "none", "--out", o)
        for f in ("index.html", "trajectories.png", "collision_map.png"):
            check(os.path.getsize(os.path.join(o, f)) > 1000, f"{f}: {os.listdir(o)}")


def case_mapf_searches():
    common = ["--map", MAPF_MAP, "--scen", MAPF_SCEN, "--agents", "8", "--at-start", "appear",
              "--at-goal", "leave", "--no-reduction", "--json"]
    res = {}
    for s in ["none", "edf", "exhaustive", "ga"]:
        out = json.loads(run("coordinate", "--search", s, *common).stdout)
        check(out["valid"], s + ": " + str(out))
        check_summary(out, 8)
        check(sorted(out["order"]) == list(range(1, 9)), "order is a permutation")
        res[s] = out["makespan"]
    for s in ["none", "edf", "ga"]:
        check(res["exhaustive"] <= res[s] + 1e-9, f"exhaustive optimum {res} ")
    check(res["ga"] <= res["edf"] + 1e-9, f"GA not worse than its EDF seed {res}")


def case_out_and_validate():
    with tempfile.TemporaryDirectory() as d:
        out = json.loads(run("coordinate", "--scenario", ARENA, "--search", "exhaustive", "--json",
                             "--out", d).stdout)
        check(out["valid"], str(out))
        for f in ["schedule.json", "schedule.yaml", "trajectories.png", "network.png"]:
            check(os.path.getsize(os.path.join(d, f)) > 100, f + " written")
        for f in ["schedule.json", "schedule.yaml"]:
            v = json.loads(run("validate-schedule", os.path.join(d, f), "--json").stdout)
            check(v["valid"] and v["agents"] == 4, f + ": " + str(v))
            check(abs(v["makespan"] - out["makespan"]) < 1e-6, "same makespan after round trip")
        run("coordinate", "--scenario", CROSSING, "--search", "none", "--out", d)
        sched = json.load(open(os.path.join(d, "schedule.json")))
        check(sched["agents"][1]["delay"] == 2.25, str(sched))
        sched["agents"][1]["delay"] = 0.0  # both robots reach the origin at t = 10
        bad = os.path.join(d, "bad.json")
        json.dump(sched, open(bad, "w"))
        v = json.loads(run("validate-schedule", bad, "--json", expect=1).stdout)
        check(not v["valid"] and len(v["conflicts"]) == 1, str(v))
        c = v["conflicts"][0]
        check(9.0 < c["time"] <= 10.0 + 1e-9 and c["distance"] < 1.0, str(c))
        sched["agents"][1]["delay"] = math.sqrt(2) + 1e-3  # just above the exact minimum
        json.dump(sched, open(bad, "w"))
        check(json.loads(run("validate-schedule", bad, "--json").stdout)["valid"], "sqrt 2 ok")


def case_no_delay_schedule():
    with tempfile.TemporaryDirectory() as d:
        sc = os.path.join(d, "parked.yaml")
        with open(sc, "w") as f:
            f.write("robots:\n"
                    "  - {id: 1, path: [[0, -5], [0, 0]]}\n"   # ends on robot 2's path, stays
                    "  - {id: 2, path: [[-5, 0], [5, 0]]}\n")
        out = json.loads(run("coordinate", "--scenario", sc, "--search", "none", "--json",
                             expect=1).stdout)
        check(out["status"] == "no_delay_schedule" and not out["valid"], str(out))
        check(out["makespan"] is None, "no makespan for an invalid order")
        out = json.loads(run("coordinate", "--scenario", sc, "--search", "exhaustive",
                             "--json").stdout)
        check(out["valid"] and out["order"] == [2, 1], str(out))


def case_sipp_mapf():
    """Prioritized SIPP on the MAPF benchmark: valid under both conventions, never below the
    8-connected bounds; the schedule (timed waypoints + map) passes validate-schedule, and a
    waypoint moved into a wall is caught by the map check."""
    common = ["--method", "sipp", "--map", MAPF_MAP, "--scen", MAPF_SCEN, "--agents", "30",
              "--json"]
    for conv in (["wait", "stay"], ["appear", "leave"]):
        out = json.loads(run("coordinate", *common, "--at-start", conv[0], "--at-goal",
                             conv[1]).stdout)
        check(out["valid"] and out["status"] == "ok", str(out)[:400])
        arr = [a["arrival"] for a in out["agents"]]
        check(abs(out["makespan"] - max(arr)) < 1e-9 and abs(out["sum_of_arrivals"] - sum(arr)) < 1e-6,
              "summary")
        for a in out["agents"]:
            check(a["arrival"] >= a["shortest"] - 1e-9, "arrival >= shortest travel " + str(a))
        check(out["makespan"] >= out["bound_makespan"] - 1e-9, "makespan >= bound")
    # PBS and the GA over SIPP orders say that they produced the result; deps is an order rule.
    ws = ["--at-start", "wait", "--at-goal", "stay"]
    out = json.loads(run("coordinate", *common, *ws, "--order", "pbs").stdout)
    check(out["valid"] and out["order_source"] == "pbs" and out["pbs_used"]
          and out["pbs_priority_pairs"] > 0 and out["pbs_replans"] >= 30, str(out)[:400])
    check(sorted(out["order"]) == sorted(a["id"] for a in out["agents"]), "pbs order")
    out = json.loads(run("coordinate", *common, *ws, "--order", "deps").stdout)
    check(out["valid"] and out["order_source"] == "deps" and not out["pbs_used"], str(out)[:400])
    ga = ["--method", "sipp", "--map", MAPF_MAP, "--scen", MAPF_SCEN, "--agents", "10", "--json"]
    out = json.loads(run("coordinate", *ga, "--order", "ga", "--sipp-ga-time-limit", "0.3").stdout)
    check(out["valid"] and out["order_source"] == "ga" and out["ga_evaluations"] >= 5,
          str(out)[:400])
    # The default order is the GA over orders, seeded with EDF and the other rules.
    out = json.loads(run("coordinate", *common, *ws).stdout)
    check(out["valid"] and out["order_source"] == "ga" and out["ga_evaluations"] >= 1,
          str(out)[:400])
    p = run("coordinate", *common, "--order", "magic", expect=2)
    check("pbs" in p.stderr and "ga" in p.stderr, p.stderr)
    with tempfile.TemporaryDirectory() as d:
        run("coordinate", *common, "--at-start", "wait", "--at-goal", "stay", "--out", d)
        sched = json.load(open(os.path.join(d, "schedule.json")))
        check("map" in sched and all("waypoints" in a for a in sched["agents"]), str(sched)[:300])
        for f in ["schedule.json", "schedule.yaml", "index.html", "trajectories.png"]:
            check(os.path.getsize(os.path.join(d, f)) > 100, f + " written")
        v = json.loads(run("validate-schedule", os.path.join(d, "schedule.json"), "--json").stdout)
        check(v["valid"] and v["map"] is not None and v["wall_hits"] == [], str(v)[:300])
        # Robot 1's second waypoint moved onto the map's first blocked cell: a wall hit.
        rows = open(MAPF_MAP).read().split("map\n", 1)[1].split("\n")
        y, x = next((y, r.index("@")) for y, r in enumerate(rows) if "@" in r)
        wx, wy = x + 0.5, len(rows[:32]) - y - 0.5  # Moving AI rows go down, the world y up
        sched["agents"][0]["waypoints"][1][1:] = [wx, wy]
        bad = os.path.join(d, "wall.json")
        json.dump(sched, open(bad, "w"))
        v = json.loads(run("validate-schedule", bad, "--json", expect=1).stdout)
        check(not v["valid"] and v["wall_hits"] and v["wall_hits"][0]["robot"] == sched["agents"][0]["id"],
              str(v)[:300])


def case_errors():
    with tempfile.TemporaryDirectory() as d:
        sc = os.path.join(d, "bad.yaml")
        with open(sc, "w") as f:
            f.write("robots:\n  - {id: 1, path: [[0, 0], [1, 0]], v_max: fast}\n")
        p = run("coordinate", "--scenario", sc, expect=2)
        check("bad.yaml" in p.stderr and "v_max" in p.stderr, p.stderr)
        p = run("coordinate", "--scenario", CROSSING, "--method", "magic", expect=2)
        check("delays|sipp" in p.stderr, p.stderr)
        # crossing.yaml has a map now; the same paths without one cannot be planned by SIPP.
        nomap = os.path.join(d, "nomap.yaml")
        with open(nomap, "w") as f:
            f.write("robots:\n  - {id: 1, path: [[-10, 0], [10, 0]], radius: 0.5}\n"
                    "  - {id: 2, path: [[0, -10], [0, 10]], radius: 0.5}\n")
        p = run("coordinate", "--scenario", nomap, "--method", "sipp", expect=2)
        check("needs a map" in p.stderr, p.stderr)
        p = run("coordinate", "--scenario", CROSSING, "--search", "tabu", expect=2)
        check("none|exhaustive|edf|ga" in p.stderr, p.stderr)
        p = run("coordinate", "--map", MAPF_MAP, "--scen", MAPF_SCEN, "--agents", "100000",
                expect=2)
        check("fewer than" in p.stderr, p.stderr)
        bad = os.path.join(d, "bad.json")
        with open(bad, "w") as f:
            f.write('{"agents": [{"id": 1, "radius": 0.5, "v_max": 1, "delay": -1, '
                    '"path": [[0, 0]]}]}')
        p = run("validate-schedule", bad, expect=2)
        check("delay" in p.stderr, p.stderr)


CASES = {k[5:]: v for k, v in globals().items() if k.startswith("case_")}
if CASE not in CASES:
    sys.exit(f"unknown case {CASE}; known: {', '.join(CASES)}")
CASES[CASE]()
print("ok", CASE)
