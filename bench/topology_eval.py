#!/usr/bin/env python3
"""Formats the outputs of bench/topology_eval.sh into bench/results/topology.md."""
import datetime
import glob
import json
import os
import re
import sys

tmp, out = sys.argv[1], sys.argv[2]
lines = ["# Topological maps (seed 003): segmentation and speed", "",
         f"Measured {datetime.date.today()} with `bench/topology_eval.sh`. Floor plans from "
         "`data/floorplans` (ipa_room_segmentation, 0.05 m/pixel; a pixel is free when its grey is "
         ">= 250, the grey outside the building counts as an obstacle). Recall: per ground-truth "
         "room, best overlap with one region / room area; precision: per region, best overlap with "
         "one room / region area; both averaged over rooms / regions. **ipa** (the default, the "
         "ipa_room_segmentation evaluation): rooms are the 8-connected white areas over 100 px, "
         "regions of 100 px or less are dropped, full room and region areas. **intersection** "
         "(voronav's earlier score): 4-connected rooms of at least 1 m^2, all regions, areas cut "
         "to the cells inside both a room and a region (door lines and furniture never count). "
         "Time: CPU time of `build_topological_map` (diagram + critical points + regions + graph), "
         "single thread; the wall clock on the shared, loaded machine is larger.", "",
         "Published reference for Voronoi segmentation on these maps (Bormann et al. 2016): "
         "recall 95.0 %, precision 94.8 % unfurnished, 86.6 / 94.5 furnished, 13 s per map.", "",
         "| map | size | method | rooms (ipa) | regions | critical points | ipa recall % | ipa precision % | intersection recall % | intersection precision % | CPU ms |",
         "|---|---|---|---|---|---|---|---|---|---|---|"]
runs = {}
for path in sorted(glob.glob(os.path.join(tmp, "*.json"))):
    base = os.path.basename(path)
    if base == "bench.json":
        continue
    name, method, metric, _ = base.rsplit(".", 3)
    runs.setdefault((name, method), {})[metric] = json.load(open(path))
sums = {}
for (name, method), m in sorted(runs.items()):
    j, i = m["ipa"], m["intersection"]
    s, t = j["segmentation"], i["segmentation"]
    lines.append(f"| {name} | {j['width']}x{j['height']} | {method} | {s['rooms']} | {j['regions']} | "
                 f"{len(j['critical_points'])} | {100 * s['recall']:.1f} | {100 * s['precision']:.1f} | "
                 f"{100 * t['recall']:.1f} | {100 * t['precision']:.1f} | {j['cpu_ms']:.0f} |")
    acc = sums.setdefault(method, [0, 0.0, 0.0, 0.0, 0.0, 0.0])
    acc[0] += 1
    acc[1] += s["recall"]
    acc[2] += s["precision"]
    acc[3] += t["recall"]
    acc[4] += t["precision"]
    acc[5] += j["cpu_ms"]
for method, (n, r, p, r2, p2, t) in sorted(sums.items()):
    lines.append(f"| **mean** | | {method} | | | | **{100 * r / n:.1f}** | **{100 * p / n:.1f}** | "
                 f"{100 * r2 / n:.1f} | {100 * p2 / n:.1f} | {t / n:.0f} |")

bench = json.load(open(os.path.join(tmp, "bench.json")))
rows = {b["name"]: b for b in bench["benchmarks"]}
edt = rows["edt"]["cpu_time"]
cells = rows["edt"]["cells"]
lines += ["", f"## Speed on the benchmark map ({int(cells)} cells)", "",
          "CPU time per call (Google Benchmark, `bin/topology_bench`), ns per map cell, and the ratio "
          "to the exact EDT (`field::distance_transform`) measured in the same run.", "",
          "| stage | ms | ns/cell | / EDT |", "|---|---|---|---|"]
for name, label in [("edt", "EDT (baseline)"), ("gvd_nothin", "GVD without thinning"),
                    ("gvd_full", "GVD full build"), ("ca", "labeled Voronoi by CA"),
                    ("topology", "topological map"), ("incr_3x3", "incremental 3x3 update")]:
    b = rows[name]
    lines.append(f"| {label} | {b['cpu_time']:.1f} | {b['ns_per_cell']:.1f} | {b['cpu_time'] / edt:.2f} |")
full = rows["gvd_full"]["cpu_time"]
lines += ["", f"Incremental 3x3 update vs full GVD rebuild: {full / rows['incr_3x3']['cpu_time']:.1f}x faster "
          "(one 3x3 block added, then removed, at a time; the dynamic-GVD table accumulates 10 blocks "
          "before removing them, the reference's measure, so its ratio differs)."]
# Keep the dynamic GVD section written by bench/topology_dynamic.sh.
old = open(out).read() if os.path.exists(out) else ""
m = re.search(r"<!-- dynamic-gvd:begin -->.*?<!-- dynamic-gvd:end -->\n?", old, flags=re.S)
open(out, "w").write("\n".join(lines) + "\n" + ("\n" + m.group(0) if m else ""))
