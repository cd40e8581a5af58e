#!/usr/bin/env python3
"""Formats the outputs of bench/topology_eval.sh into bench/results/topology.md."""
import datetime
import glob
import json
import os
import sys

tmp, out = sys.argv[1], sys.argv[2]
lines = ["# Topological maps (seed 003): segmentation and speed", "",
         f"Measured {datetime.date.today()} with `bench/topology_eval.sh`. Floor plans from "
         "`data/floorplans` (ipa_room_segmentation, 0.05 m/pixel; a pixel is free when its grey is "
         ">= 250, the grey outside the building counts as an obstacle). Recall: per ground-truth "
         "room, best overlap with one region / room area; precision: per region, best overlap with "
         "one room / region area; both averaged over rooms / regions. Ground-truth rooms under 1 m^2 (specks of white "
         "pixels inside drawn walls) are ignored. Time: CPU time of `build_topological_map` "
         "(diagram + critical points + regions + graph), single thread; the wall clock on the "
         "shared, loaded machine is larger.", "",
         "Published reference for Voronoi segmentation on these maps (Bormann et al. 2016): "
         "recall 95.0 %, precision 94.8 %, 13 s per map.", "",
         "| map | size | method | rooms | regions | critical points | recall % | precision % | CPU ms |",
         "|---|---|---|---|---|---|---|---|---|"]
sums = {}
for path in sorted(glob.glob(os.path.join(tmp, "*.json"))):
    base = os.path.basename(path)
    if base == "bench.json":
        continue
    name, method, _ = base.rsplit(".", 2)
    j = json.load(open(path))
    s = j["segmentation"]
    lines.append(f"| {name} | {j['width']}x{j['height']} | {method} | {s['rooms']} | {j['regions']} | "
                 f"{len(j['critical_points'])} | {100 * s['recall']:.1f} | {100 * s['precision']:.1f} | "
                 f"{j['cpu_ms']:.0f} |")
    acc = sums.setdefault(method, [0, 0.0, 0.0, 0.0])
    acc[0] += 1
    acc[1] += s["recall"]
    acc[2] += s["precision"]
    acc[3] += j["cpu_ms"]
for method, (n, r, p, t) in sorted(sums.items()):
    lines.append(f"| **mean** | | {method} | | | | **{100 * r / n:.1f}** | **{100 * p / n:.1f}** | {t / n:.0f} |")

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
lines += ["", f"Incremental 3x3 update vs full GVD rebuild: {full / rows['incr_3x3']['cpu_time']:.1f}x faster."]
open(out, "w").write("\n".join(lines) + "\n")
