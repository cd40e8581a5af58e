#!/usr/bin/env python3
"""Issue #13, stop 24: decentralized variants against a reference, run by run (stop 22's table).

Usage: netsim_variants.py REF_FOLDER LABEL=FOLDER [LABEL=FOLDER ...]
Every folder holds s1.json..s4.json from `voronav netsim --scenario N --runs 16 --json --quiet`
(REF_FOLDER: the reference, e.g. the defaults with --method both; the others with
--method decentralized and the variant's flags). Prints per scenario and variant: arrivals (the
runs that fail), change runs with a Repair executed (those without), the source's travel on the
runs where both the variant and the reference arrived (variant vs reference, n), the mean
traffic of the change runs, replans and kept walk targets (repair_walk_targets_kept), summed.
"""
import json
import statistics as st
import sys


def runs(folder, s):
    return json.load(open(f"{folder}/s{s}.json"))["decentralized"]["per_run"]


def row(label, s, rs, ref):
    fails = ", ".join(f"r{r['run']}" for r in rs if not r["success"]) or "–"
    ch = [r for r in rs if r["changes_applied"] > 0]
    ex = [r for r in ch if r["repairs_executed"] > 0]
    without = ", ".join(f"r{r['run']}" for r in ch if r["repairs_executed"] == 0) or "–"
    both = [(x, y) for x, y in zip(rs, ref) if x["success"] and y["success"]]
    drove = st.mean(x["source_travel_m"] for x, _ in both) if both else float("nan")
    drove_ref = st.mean(y["source_travel_m"] for _, y in both) if both else float("nan")
    traffic = st.mean(r["traffic_bytes"] for r in ch) if ch else 0.0
    ok = sum(r["success"] for r in rs)
    replans = sum(r["replans"] for r in rs)
    kept = sum(r.get("repair_walk_targets_kept", 0) for r in rs)
    print(f"| {s} | {label} | {ok}/16 ({fails}) | {len(ex)} of {len(ch)} ({without}) | "
          f"{drove:.1f} vs {drove_ref:.1f} ({len(both)}) | {traffic:.0f} | {replans} / {kept} |")


def main():
    ref = sys.argv[1]
    variants = [a.split("=", 1) for a in sys.argv[2:]]
    print("| scen. | variant | arrived (fails) | change runs with a Repair executed (without) | "
          "drove [m], variant vs reference (n) | traffic, change runs [B] | replans / kept |")
    print("|---|---|---|---|---|---|---|")
    for s in (1, 2, 3, 4):
        r0 = runs(ref, s)
        row("reference", s, r0, r0)
        for label, folder in variants:
            row(label, s, runs(folder, s), r0)


main()
