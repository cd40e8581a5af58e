#!/usr/bin/env python3
"""Delays (seed 002) vs prioritized SIPP on MAPF benchmark maps (issue #21).

For each map, K and presence convention, runs `voronav coordinate --method delays|sipp --json`
(one process per run, wall-clock timeout) and reports makespan / bound, sum of arrivals / bound
(bounds: each robot's 8-connected shortest travel time on the map inflated by its radius, as
printed by --method sipp), the time the command reports, validity and what produced the result
(restarts, fallback tiers, order rule). Writes a Markdown table.

Usage: coordination_sipp.py VORONAV OUT.md [--ks 10,30,60,100,200] [--timeout 60]
       [--delays-search edf] [--maps a,b,c]
"""
import argparse
import json
import os
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
MAPS = {
    "random-32-32-20": ("random-32-32-20.map", "random-32-32-20-random-1.scen"),
    "random-32-32-10": ("random-32-32-10.map", "random-32-32-10-random-1.scen"),
    "warehouse-20-40-10-2-2": ("warehouse-20-40-10-2-2.map",
                               "warehouse-20-40-10-2-2-first300.scen"),
}
CONVENTIONS = [("wait", "stay"), ("appear", "leave")]


def run(binary, args, timeout):
    t0 = time.monotonic()
    try:
        p = subprocess.run([binary, "coordinate", *args, "--json"], capture_output=True,
                           text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return None, time.monotonic() - t0
    wall = time.monotonic() - t0
    try:
        return json.loads(p.stdout), wall
    except json.JSONDecodeError:
        return {"status": "error", "message": p.stderr.strip()[:120]}, wall


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("binary")
    ap.add_argument("out")
    ap.add_argument("--ks", default="10,30,60,100,200")
    ap.add_argument("--timeout", type=float, default=60.0)
    ap.add_argument("--delays-search", default="edf")
    ap.add_argument("--maps", default=",".join(MAPS))
    a = ap.parse_args()
    rows = []
    for name in a.maps.split(","):
        m, s = MAPS[name]
        base = ["--map", os.path.join(ROOT, "data", "mapf", m), "--scen",
                os.path.join(ROOT, "data", "mapf", s)]
        for k in map(int, a.ks.split(",")):
            for st, gl in CONVENTIONS:
                conv = ["--agents", str(k), "--at-start", st, "--at-goal", gl]
                sipp, sipp_wall = run(a.binary, [*base, *conv, "--method", "sipp"], a.timeout)
                dl, dl_wall = run(a.binary, [*base, *conv, "--method", "delays", "--search",
                                             a.delays_search], a.timeout)
                bm = sipp.get("bound_makespan") if sipp else None
                bs = sipp.get("bound_sum") if sipp else None
                for method, r, wall in (("delays/" + a.delays_search, dl, dl_wall),
                                        ("sipp/edf", sipp, sipp_wall)):
                    row = {"map": name, "k": k, "conv": f"{st}/{gl}", "method": method,
                           "wall_s": wall}
                    if r is None:
                        row["status"] = f"timeout {a.timeout:.0f} s"
                    else:
                        row["status"] = r.get("status")
                        row["valid"] = r.get("valid")
                        row["time_s"] = r.get("time_ms", 0) / 1000.0
                        if r.get("makespan") is not None and bm:
                            row["ms"] = r["makespan"] / bm
                            row["sum"] = r["sum_of_arrivals"] / bs
                        row["note"] = (f"restarts {r.get('restarts')}, tier fallbacks "
                                       f"{r.get('soft_fallbacks')}" if "restarts" in r else
                                       f"repairs {r.get('repairs')}")
                    rows.append(row)
                    print(json.dumps(row), flush=True)
    with open(a.out, "w") as f:
        f.write("| map | K | at-start/at-goal | method | status | valid | makespan / bound | "
                "sum / bound | time [s] | what produced it |\n|---|---|---|---|---|---|---|---|---|---|\n")
        for r in rows:
            f.write("| {map} | {k} | {conv} | {method} | {st} | {v} | {ms} | {sm} | {t} | {n} |\n".format(
                map=r["map"], k=r["k"], conv=r["conv"], method=r["method"], st=r["status"],
                v="yes" if r.get("valid") else "no", ms=f"{r['ms']:.3f}" if "ms" in r else "–",
                sm=f"{r['sum']:.3f}" if "sum" in r else "–",
                t=f"{r['time_s']:.2f}" if "time_s" in r else f"> {a.timeout:.0f}",
                n=r.get("note", "")))


if __name__ == "__main__":
    sys.exit(main())
