#!/usr/bin/env python3
"""Issue #13, stop 21: which mechanism executed the decentralized Repairs of the change runs.

Usage: netsim_repair_mechanism.py FOLDER [ON_FOLDER]
FOLDER holds s1.json..s4.json from `voronav netsim --scenario N --method both --runs 16 --json
--quiet`; prints per scenario arrivals, route_found_by relays, change runs with a Repair executed
and by which mechanism (per-run counters repairs_own, repair_answers_fixed(_walk); an answer taken
as sent is the rest of repairs_executed), source travel d / c and traffic with changes d / c.
With ON_FOLDER (the same runs with --repair-fix-answer true, decentralized only), prints the
off / on comparison run by run instead.
"""
import json
import statistics as st
import sys


def runs(folder, s, method="decentralized"):
    return json.load(open(f"{folder}/s{s}.json"))[method]["per_run"]


def changed(rs):
    return [r for r in rs if r["changes_applied"] > 0]


def executed(rs):
    return [r for r in changed(rs) if r["repairs_executed"] > 0]


def ok(rs):
    return [r for r in rs if r["success"]]


def travel(rs):
    return st.mean(r["source_travel_m"] for r in rs) if rs else float("nan")


def mechanisms(rs):
    e = executed(rs)
    own = sum(r["repairs_own"] > 0 for r in e)
    walk = sum(r["repair_answers_fixed_walk"] > 0 for r in e)
    pts = sum(r["repair_answers_fixed"] > 0 for r in e)
    sent = sum(r["repairs_executed"] - r["repairs_own"] - r["repair_answers_fixed"]
               - r["repair_answers_fixed_walk"] > 0 for r in e)
    return own, sent, walk, pts


def missing(rs):
    return ", ".join(f"r{r['run']}" for r in changed(rs) if r["repairs_executed"] == 0) or "–"


def main():
    d = sys.argv[1]
    if len(sys.argv) == 2:
        print("| scenario | arrived d / c | route by relays | change runs with a Repair executed | "
              "by mechanism: own detour / answer taken as sent / refused answer repaired by A* "
              "(by own points) | change runs without | source drove d / c [m] | "
              "traffic with changes d / c [B] |")
        print("|---|---|---|---|---|---|---|---|")
        for s in (1, 2, 3, 4):
            dd, cc = runs(d, s), runs(d, s, "centralized")
            relays = json.load(open(f"{d}/s{s}.json"))["decentralized"]["route_found_by"]["relays"]
            own, sent, walk, pts = mechanisms(dd)
            tr = lambda rs: st.mean(r["traffic_bytes"] for r in changed(rs))
            print(f"| {s} | {len(ok(dd))}/16 / {len(ok(cc))}/16 | {relays} | "
                  f"{len(executed(dd))} of {len(changed(dd))} | {own} / {sent} / {walk} ({pts}) | "
                  f"{missing(dd)} | {travel(ok(dd)):.1f} / {travel(ok(cc)):.1f} | "
                  f"{tr(dd):.0f} / {tr(cc):.0f} |")
        return
    on = sys.argv[2]
    print("| scenario | arrived off / on | change runs with a Repair executed off / on | on, by "
          "mechanism: own detour / answer taken as sent / refused answer repaired by A* (by own "
          "points); runs where A* alone did it | change runs without (on) | source drove off / on "
          "[m] | runs both arrived: off / on [m] | traffic with changes off / on [B] |")
    print("|---|---|---|---|---|---|---|---|")
    for s in (1, 2, 3, 4):
        a, b = runs(d, s), runs(on, s)
        own, sent, walk, pts = mechanisms(b)
        alone = ", ".join(f"r{r['run']}" for r in executed(b) if r["repairs_executed"] ==
                          r["repair_answers_fixed_walk"] + r["repair_answers_fixed"]) or "–"
        both = [(x, y) for x, y in zip(a, b) if x["success"] and y["success"]]
        tr = lambda rs: st.mean(r["traffic_bytes"] for r in changed(rs))
        print(f"| {s} | {len(ok(a))}/16 / {len(ok(b))}/16 | {len(executed(a))} / "
              f"{len(executed(b))} of 12 | {own} / {sent} / {walk} ({pts}); {alone} | "
              f"{missing(b)} | {travel(ok(a)):.1f} / {travel(ok(b)):.1f} | "
              f"{travel([x for x, _ in both]):.1f} / {travel([y for _, y in both]):.1f} "
              f"(n={len(both)}) | {tr(a):.0f} / {tr(b):.0f} |")


main()
