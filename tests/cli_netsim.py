#!/usr/bin/env python3
"""End-to-end checks of `voronav netsim` (seed 000): JSON shape, both methods, errors."""
import json
import subprocess
import sys
import tempfile
import os

exe, root, case = sys.argv[1], sys.argv[2], sys.argv[3]


def run(*args):
    return subprocess.run([exe, "netsim", *args], capture_output=True, text=True, timeout=240)


def check(cond, msg):
    if not cond:
        print("FAIL:", msg)
        sys.exit(1)


KEYS = ["traffic_bytes", "messages", "computation", "max_robot_computation", "route_time_s",
        "travel_m", "success_rate", "runs"]

if case == "both_json":
    r = run("--scenario", "1", "--runs", "2", "--json")
    check(r.returncode == 0, r.stderr)
    j = json.loads(r.stdout)
    check(j["methods"] == ["centralized", "decentralized"], j.keys())
    for m in (j[k] for k in j["methods"]):
        for k in KEYS:
            check(k in m, k)
        check(m["runs"] == 2, m)
        check(m["traffic_bytes"] > 0, m)
        check(sum(m["route_found_by"].values()) == 2 and len(m["per_run"]) == 2, m)
        for r in m["per_run"]:
            for k in ("route_found_by", "route_robots", "paths_lost", "repairs_executed",
                      "changes_on_route", "route_length_m", "source_travel_m", "relay_travel_m"):
                check(k in r, k)
    # Both methods reach the destination; the decentralized routes are built by the relays.
    check(j["centralized"]["success_rate"] == 1.0, j["centralized"])
    check(j["decentralized"]["success_rate"] == 1.0, j["decentralized"])
    check(j["decentralized"]["route_found_by"]["relays"] == 2, j["decentralized"])
    check(j["centralized"]["beta_bytes"] > j["centralized"]["alpha_bytes"], j)
elif case == "one_method_plots":
    with tempfile.TemporaryDirectory() as d:
        r = run("--scenario", "3", "--runs", "1", "--method", "decentralized", "--json",
                "--out", d, "--plots", d)
        check(r.returncode == 0, r.stderr)
        j = json.loads(r.stdout)
        check(j["methods"] == ["decentralized"] and "centralized" not in j, j.keys())
        check(os.path.exists(os.path.join(d, "netsim_scenario3.json")), os.listdir(d))
        check(os.path.getsize(os.path.join(d, "scenario3_traffic.png")) > 1000, os.listdir(d))
elif case == "errors":
    for args in (["--scenario", "7"], ["--scenario", "x"], ["--method", "teleport"],
                 ["--runs", "0"], ["--loss", "1.5", "--runs", "1"]):
        r = run(*args)
        check(r.returncode == 2, f"{args}: exit {r.returncode}")
        check("error" in r.stderr.lower(), r.stderr)
elif case == "scenario_file":
    r = run("--scenario", os.path.join(root, "data/netsim/turtlebot3_world.yaml"), "--json")
    check(r.returncode == 0, r.stderr)
    j = json.loads(r.stdout)
    check(j["methods"] == ["centralized", "decentralized"], j.keys())
    for m in (j[k] for k in j["methods"]):
        for k in KEYS:
            check(k in m, k)
        check(m["runs"] == 1, m)
        check(m["success_rate"] == 1.0, m)
    missing = os.path.join(tempfile.gettempdir(), "voronav_nonexistent.yaml")
    r = run("--scenario", missing)
    check(r.returncode == 2, f"missing file: exit {r.returncode}")
    check(missing in r.stderr and "not found" in r.stderr, r.stderr)
elif case == "write_scenario":
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "s1r2.yaml")
        r = run("--scenario", "1", "--run", "2", "--method", "centralized", "--write-scenario",
                path)
        check(r.returncode == 0, r.stderr)
        check(os.path.exists(os.path.join(d, "s1r2_world.pgm")), os.listdir(d))
        # The written file runs the method it names; --method overrides it.
        r = run("--scenario", path, "--json")
        check(r.returncode == 0, r.stderr)
        from_file = json.loads(r.stdout)
        check(from_file["methods"] == ["centralized"] and "decentralized" not in from_file,
              r.stdout)
        # ... and gives the same run as the paper run itself (CPU times aside).
        r = run("--scenario", "1", "--runs", "2", "--method", "centralized", "--out", d)
        check(r.returncode == 0, r.stderr)
        paper = json.load(open(os.path.join(d, "netsim_scenario1.json")))["runs"][1]
        for k in ("traffic_bytes", "messages", "computation", "route_time_s", "travel_m"):
            check(paper[k] == from_file["centralized"][k], f"{k}: {paper} vs {from_file}")
        r = run("--scenario", path, "--method", "decentralized", "--json")
        check(r.returncode == 0, r.stderr)
        j = json.loads(r.stdout)
        check(j["methods"] == ["decentralized"] and "centralized" not in j, r.stdout)
        check(j["decentralized"]["success_rate"] == 1.0, r.stdout)
else:
    print("unknown case", case)
    sys.exit(2)
print("ok")
