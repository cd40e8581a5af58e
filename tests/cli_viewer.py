#!/usr/bin/env python3
"""End-to-end checks of `voronav replay`. Usage: cli_viewer.py VORONAV_BINARY REPO_ROOT CASE."""
import json
import os
import re
import subprocess
import sys
import tempfile

from cli_util import check, runner

BIN, ROOT, CASE = sys.argv[1], sys.argv[2], sys.argv[3]


run = runner(BIN, timeout=120)


def embedded(page_path):
    with open(page_path, encoding="utf-8") as f:
        page = f.read()
    m = re.search(r'<script id="recording" type="application/json">(.*?)</script>', page, re.S)
    check(m is not None, "no embedded recording in " + page_path)
    return page, json.loads(m.group(1))


def case_example_and_roundtrip():
    with tempfile.TemporaryDirectory() as d:
        a, b = os.path.join(d, "a"), os.path.join(d, "b")
        out = json.loads(run("replay", "--example", "--out", a, "--json").stdout)
        check(os.path.isfile(out["index_html"]) and out["index_html"].endswith("index.html"), str(out))
        check(out["robots"] == 3 and out["plots"] == 2 and out["layers"] == 3, str(out))
        check(out["messages"] > 50 and out["end_s"] > 30, str(out))
        page, rec = embedded(out["index_html"])
        check("http://" not in page and "https://" not in page, "page references the network")
        check(rec["format"] == "voronav-recording" and rec["version"] == 1, str(rec.keys()))
        check(len(rec["robots"]) == 3 and rec["map"]["width"] == 320, "recording content")
        with open(out["recording"], encoding="utf-8") as f:
            check(json.load(f) == rec, "recording.json differs from the embedded data")
        # The recording file gives the same page back.
        out2 = json.loads(run("replay", "--recording", out["recording"], "--out", b, "--json").stdout)
        with open(out2["index_html"], encoding="utf-8") as f:
            check(f.read() == page, "the page from recording.json differs from the example page")
        text = run("replay", "--recording", out["recording"], "--out", b).stdout
        check("replay page:" in text and "3 robots" in text, text)


def case_hand_written_recording():
    rec = {"format": "voronav-recording", "version": 1, "title": "two cells",
           "map": {"width": 2, "height": 1, "resolution": 1.0, "occupancy": [0, 1, 100, 1]},
           "robots": [{"id": 4, "poses": [[0, 0.5, 0.5, 0], [2, 0.5, 0.5, 1.5]]}]}
    with tempfile.TemporaryDirectory() as d:
        p = os.path.join(d, "rec.json")
        with open(p, "w") as f:
            json.dump(rec, f)
        out = json.loads(run("replay", "--recording", p, "--out", os.path.join(d, "o"), "--json").stdout)
        check(out["robots"] == 1 and out["start_s"] == 0 and out["end_s"] == 2, str(out))
        _, back = embedded(out["index_html"])
        check(back["map"]["occupancy"] == [0, 1, 100, 1] and back["robots"][0]["id"] == 4, str(back))


def case_map_only():
    ros = os.path.join(ROOT, "data", "ros_maps", "turtlebot3_world", "map.yaml")
    with tempfile.TemporaryDirectory() as d:
        out = json.loads(run("replay", "--map", ros, "--out", d, "--json").stdout)
        check(out["robots"] == 0 and out["end_s"] == 0, str(out))
        _, rec = embedded(out["index_html"])
        m = rec["map"]
        check(m["resolution"] == 0.05 and sum(m["occupancy"][1::2]) == m["width"] * m["height"], str(m.keys()))
        check(any(v == 100 for v in m["occupancy"][0::2]) and any(v == 0 for v in m["occupancy"][0::2]),
              "the map has free and occupied cells")
        run("replay", "--map", ros, "--example", "--out", d, expect=2)


def case_errors():
    with tempfile.TemporaryDirectory() as d:
        missing = os.path.join(d, "nope.json")
        e = run("replay", "--recording", missing, "--out", d, expect=2).stderr
        check("nope.json" in e, e)
        run("replay", "--example", "--recording", missing, "--out", d, expect=2)
        e = run("replay", "--out", d, expect=2).stderr
        check("--recording" in e and "--example" in e and "--map" in e, e)
        run("replay", "--example", expect=2)  # --out is required
        bad = os.path.join(d, "bad.json")
        with open(bad, "w") as f:
            f.write('{\n  "format": "voronav-recording",\n  "version": 1,\n  "map": [,\n}\n')
        e = run("replay", "--recording", bad, "--out", d, expect=2).stderr
        check("bad.json:4" in e, e)
        with open(bad, "w") as f:
            json.dump({"format": "voronav-recording", "version": 1,
                       "map": {"width": 2, "height": 1, "resolution": 1, "occupancy": [0, 2]},
                       "robots": [{"id": 1, "poses": [[1, 0, 0, 0], [0, 0, 0, 0]]}]}, f)
        e = run("replay", "--recording", bad, "--out", d, expect=2).stderr
        check("robots[0].poses[1].t" in e and "non-decreasing" in e, e)
        afile = os.path.join(d, "file.txt")
        open(afile, "w").close()
        e = run("replay", "--example", "--out", afile, expect=2).stderr
        check("directory" in e, e)


def case_js_syntax():
    """The page's script parses (node --check); exit 77 (skipped) when node is missing."""
    import shutil
    node = shutil.which("node")
    if not node:
        print("SKIP: node not found")
        sys.exit(77)
    with open(os.path.join(ROOT, "voronav", "report", "viewer.html"), encoding="ascii") as f:
        html = f.read()  # ascii: the template must stay ASCII-only (embedded by CMake in chunks)
    scripts = re.findall(r"<script>(.*?)</script>", html, re.S)
    check(len(scripts) == 1, f"expected one code script in viewer.html, found {len(scripts)}")
    with tempfile.TemporaryDirectory() as d:
        js = os.path.join(d, "viewer.js")
        with open(js, "w") as f:
            f.write(scripts[0])
        p = subprocess.run([node, "--check", js], capture_output=True, text=True)
        check(p.returncode == 0, "viewer.html script has a syntax error:\n" + p.stderr)


CASES = {"example_and_roundtrip": case_example_and_roundtrip, "js_syntax": case_js_syntax,
         "hand_written_recording": case_hand_written_recording, "map_only": case_map_only,
         "errors": case_errors}
if CASE not in CASES:
    sys.exit(f"unknown case {CASE}; cases: {', '.join(CASES)}")
CASES[CASE]()
print("ok", CASE)
