#!/usr/bin/env python3
"""End-to-end checks of `voronav topo`, `voronav map` and `voronav plan --planner topo`.
Usage: cli_topology.py VORONAV_BINARY REPO_ROOT CASE."""
import json
import os
import sys
import tempfile

from cli_util import check, runner

BIN, ROOT, CASE = sys.argv[1], sys.argv[2], sys.argv[3]
PLANS = os.path.join(ROOT, "data", "floorplans")
TB3 = os.path.join(ROOT, "data", "ros_maps", "turtlebot3_world", "map.yaml")


run = runner(BIN, timeout=240)


def topo(name, method):
    with tempfile.TemporaryDirectory() as out:
        j = json.loads(run("topo", "--map", os.path.join(PLANS, name + ".png"), "--method", method,
                           "--ground-truth", os.path.join(PLANS, name + "_gt_segmentation.png"),
                           "--out", out, "--json").stdout)
        for stage in ["a_binary", "b_edges", "c_voronoi", "d_critical", "e_regions", "f_graph"]:
            path = os.path.join(out, stage + ".png")
            check(os.path.getsize(path) > 1000, path + " missing or empty")
        with open(os.path.join(out, "topology.json")) as f:
            check(json.load(f)["regions"] == j["regions"], "topology.json differs from --json")
    check(isinstance(j["critical_points"], list) and len(j["critical_points"]) > 0, str(j)[:300])
    cp = j["critical_points"][0]
    check(len(cp["basis"]) == 2 and cp["clearance_m"] > 0, str(cp))
    check(j["regions"] == len(j["graph"]["nodes"]) and len(j["graph"]["edges"]) > 0, "graph")
    for e in j["graph"]["edges"]:
        check(0 <= e["a"] < e["b"] < j["regions"] and e["length_m"] > 0, str(e))
    return j


def case_topo_edt():
    j = topo("office_b", "edt")
    s = j["segmentation"]
    check(s["recall"] > 0.95 and s["precision"] > 0.95, str(s))
    check(s["rooms"] >= 20, str(s))


def read_pgm16(path):
    with open(path, "rb") as f:
        data = f.read()
    parts = data.split(b"\n", 3)
    check(parts[0] == b"P5" and parts[2] == b"65535", "16-bit P5 header")
    w, h = (int(v) for v in parts[1].split())
    px = parts[3]
    check(len(px) == 2 * w * h, "pixel data size")
    return w, h, [(px[2 * i] << 8) | px[2 * i + 1] for i in range(w * h)]


def ring_area(ring):
    return 0.5 * sum(ring[i][0] * ring[(i + 1) % len(ring)][1] -
                     ring[(i + 1) % len(ring)][0] * ring[i][1] for i in range(len(ring)))


def case_topo_labels():
    with tempfile.TemporaryDirectory() as out:
        labels = os.path.join(out, "labels.pgm")
        run("topo", "--map", os.path.join(PLANS, "office_a.png"), "--labels", labels, "--out", out)
        with open(os.path.join(out, "topology.json")) as f:
            j = json.load(f)
        w, h, px = read_pgm16(labels)
        check((w, h) == (j["width"], j["height"]), f"{w}x{h} vs map {j['width']}x{j['height']}")
        counts = {}
        for v in px:
            counts[v] = counts.get(v, 0) + 1
        res2 = j["resolution"] ** 2
        nodes = j["graph"]["nodes"]
        check(len(nodes) == j["regions"] and len(nodes) > 5, "regions")
        check(set(counts) - {0} == {n["label"] for n in nodes}, "label values = region ids + 1")
        for n in nodes:
            check(counts[n["label"]] == n["cells"], f"region {n['id']}: {counts[n['label']]} px "
                  f"in the image, {n['cells']} in topology.json")
            check(abs(counts[n["label"]] * res2 - n["area_m2"]) < 1e-6, "area")
            poly = sum(ring_area(r) for r in n["polygon"])
            check(abs(poly - n["area_m2"]) < 1e-6, f"polygon area {poly} vs {n['area_m2']}")
            check(n["area_m2"] >= 1.0, f"region {n['id']} under --min-region-area: {n['area_m2']}")


def case_topo_ca():
    j = topo("office_b", "ca")
    s = j["segmentation"]
    check(s["recall"] > 0.9 and s["precision"] > 0.9, str(s))


def case_plan_topo():
    m = os.path.join(PLANS, "office_a.png")
    a = json.loads(run("plan", "--map", m, "--start", "5,5", "--goal", "50,30", "--json").stdout)
    t = json.loads(run("plan", "--map", m, "--start", "5,5", "--goal", "50,30", "--planner",
                       "topo", "--json").stdout)
    check(t["status"] == "ok" and t["planner"] == "topo", str(t)[:200])
    check(t["path"][0] == a["path"][0] and t["path"][-1] == a["path"][-1], "endpoints")
    check(a["length"] - 1e-9 <= t["length"] < 1.5 * a["length"], f"{t['length']} vs {a['length']}")


def case_map_sweep():
    laser = json.loads(run("map", "--map", TB3, "--poses", "40", "--json").stdout)
    check(laser["agreement"] > 0.97 and laser["observed"] > 0.03, str(laser))
    sonar = json.loads(run("map", "--map", TB3, "--sensor", "sonar", "--poses", "60",
                           "--json").stdout)
    check(0.5 < sonar["agreement"] < laser["agreement"], str(sonar))
    again = json.loads(run("map", "--map", TB3, "--poses", "40", "--json").stdout)
    check(again == laser, "same seed, same result")


def case_errors():
    p = run("topo", "--map", os.path.join(PLANS, "office_a.png"), "--method", "voronoi", expect=2)
    check("--method" in p.stderr and "voronoi" in p.stderr, p.stderr)
    p = run("topo", "--map", os.path.join(PLANS, "missing.png"), expect=2)
    check("missing.png" in p.stderr, p.stderr)
    p = run("map", "--map", TB3, "--sensor", "radar", expect=2)
    check("--sensor" in p.stderr, p.stderr)
    p = run("topo", "--map", os.path.join(PLANS, "office_a.png"), "--metric", "iou", expect=2)
    check("--metric" in p.stderr and "iou" in p.stderr, p.stderr)
    p = run("topo", "--map", os.path.join(PLANS, "office_a.png"), "--labels", "/tmp/x.jpg",
            expect=2)
    check("x.jpg" in p.stderr and ".png" in p.stderr, p.stderr)
    # A ground truth of another size is scaled to the map with a notice.
    p = run("topo", "--map", os.path.join(PLANS, "office_a.png"), "--ground-truth",
            os.path.join(PLANS, "lab_ipa_gt_segmentation.png"), "--json")
    check("scaled" in p.stderr, p.stderr)
    check(json.loads(p.stdout)["ground_truth_scaled_from"] == [864, 768], p.stdout[:200])


globals()["case_" + CASE]()
