#!/usr/bin/env python3
"""Delays (seed 002) vs prioritized SIPP on MAPF benchmark maps (issue #21).

For each map, K and presence convention, runs `voronav coordinate --method delays|sipp --json`
(one process per run, wall-clock timeout) and reports makespan / bound, sum of arrivals / bound
(bounds: each robot's 8-connected shortest travel time on the map inflated by its radius, as
printed by --method sipp), the time the command reports, validity and what produced the result
(restarts, fallback tiers, order rule). Writes a Markdown table.

The SIPP priority orders compared are --sipp-orders (default: `default`, i.e. no --order: the GA
over orders with its auto CPU budget; edf, longest-first, deps and pbs: priority-based search). Besides the time the command reports, the CPU time of the process is
recorded (the machine is shared: wall time is inflated when it is loaded).

Usage: coordination_sipp.py VORONAV OUT.md [--ks 10,30,60,100,200] [--timeout 60]
       [--delays-search edf] [--maps a,b,c] [--sipp-orders default,edf,longest-first,deps,pbs]
"""
import argparse
import json
import os
import resource
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


def cpu_children():
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def run(binary, args, timeout):
    t0 = time.monotonic()
    c0 = cpu_children()
    try:
        p = subprocess.run([binary, "coordinate", *args, "--json"], capture_output=True,
                           text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return None, time.monotonic() - t0
    wall = time.monotonic() - t0
    try:
        out = json.loads(p.stdout)
    except json.JSONDecodeError:
        out = {"status": "error", "message": p.stderr.strip()[:120]}
    out["cpu_s"] = cpu_children() - c0
    return out, wall


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("binary")
    ap.add_argument("out")
    ap.add_argument("--ks", default="10,30,60,100,200")
    ap.add_argument("--timeout", type=float, default=60.0)
    ap.add_argument("--delays-search", default="edf")
    ap.add_argument("--maps", default=",".join(MAPS))
    ap.add_argument("--sipp-orders", default="default,edf,longest-first,deps,pbs")
    a = ap.parse_args()
    rows = []
    for name in a.maps.split(","):
        m, s = MAPS[name]
        base = ["--map", os.path.join(ROOT, "data", "mapf", m), "--scen",
                os.path.join(ROOT, "data", "mapf", s)]
        for k in map(int, a.ks.split(",")):
            for st, gl in CONVENTIONS:
                conv = ["--agents", str(k), "--at-start", st, "--at-goal", gl]
                runs = []
                for order in a.sipp_orders.split(","):
                    extra = ["--pbs-time-limit", str(0.8 * a.timeout)] if order == "pbs" else []
                    chosen = [] if order == "default" else ["--order", order]
                    r, wall = run(a.binary, [*base, *conv, "--method", "sipp", *chosen, *extra],
                                  a.timeout)
                    runs.append(("sipp/" + order, r, wall))
                dl, dl_wall = run(a.binary, [*base, *conv, "--method", "delays", "--search",
                                             a.delays_search], a.timeout)
                runs.insert(0, ("delays/" + a.delays_search, dl, dl_wall))
                bm = bs = None
                for _, r, _ in runs[1:]:
                    if r and r.get("bound_makespan"):
                        bm, bs = r["bound_makespan"], r["bound_sum"]
                for method, r, wall in runs:
                    row = {"map": name, "k": k, "conv": f"{st}/{gl}", "method": method,
                           "wall_s": wall}
                    if r is None:
                        row["status"] = f"timeout {a.timeout:.0f} s"
                    else:
                        row["status"] = r.get("status")
                        row["valid"] = r.get("valid")
                        row["time_s"] = r.get("time_ms", 0) / 1000.0
                        row["cpu_s"] = r.get("cpu_s")
                        if r.get("makespan") is not None and bm:
                            row["ms"] = r["makespan"] / bm
                            row["sum"] = r["sum_of_arrivals"] / bs
                        if r.get("pbs_used"):
                            row["note"] = (f"PBS: {r.get('pbs_nodes')} nodes, "
                                           f"{r.get('pbs_priority_pairs')} pairs, "
                                           f"{r.get('pbs_replans')} SIPP calls; restarts before "
                                           f"{r.get('restarts')}")
                            if r.get("status") != "ok":
                                row["note"] += "; " + str(r.get("message"))
                        elif r.get("order_source") == "ga":
                            row["note"] = (f"GA: {r.get('ga_generations')} generations, "
                                           f"{r.get('ga_evaluations')} orders planned, "
                                           + ("better than every seed"
                                              if r.get("ga_improved_over_seeds")
                                              else "a seed order is the best"))
                        elif "restarts" in r:
                            row["note"] = ((f"GA: no order without restarts in "
                                            f"{r.get('ga_evaluations')} planned; then "
                                            f"{r.get('order_source')} with ")
                                           if r.get("ga_evaluations") else "")
                            row["note"] += (f"restarts {r.get('restarts')}, tier fallbacks "
                                           f"{r.get('soft_fallbacks')}")
                        else:
                            row["note"] = f"repairs {r.get('repairs')}"
                    rows.append(row)
                    print(json.dumps(row), flush=True)
    with open(a.out, "w") as f:
        f.write("| map | K | at-start/at-goal | method | status | valid | makespan / bound | "
                "sum / bound | time [s] | CPU [s] | what produced it |\n"
                "|---|---|---|---|---|---|---|---|---|---|---|\n")
        for r in rows:
            f.write("| {map} | {k} | {conv} | {method} | {st} | {v} | {ms} | {sm} | {t} | {c} | {n} "
                    "|\n".format(
                c=f"{r['cpu_s']:.2f}" if r.get("cpu_s") is not None else "–",
                map=r["map"], k=r["k"], conv=r["conv"], method=r["method"], st=r["status"],
                v="yes" if r.get("valid") else "no", ms=f"{r['ms']:.3f}" if "ms" in r else "–",
                sm=f"{r['sum']:.3f}" if "sum" in r else "–",
                t=f"{r['time_s']:.2f}" if "time_s" in r else f"> {a.timeout:.0f}",
                n=r.get("note", "")))


if __name__ == "__main__":
    sys.exit(main())
