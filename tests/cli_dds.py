#!/usr/bin/env python3
"""End-to-end checks of the DDS subcommands (robots as separate processes over Cyclone DDS).
Usage: cli_dds.py VORONAV_BINARY REPO_ROOT CASE.

Each case runs the real binary: dds-selftest launches one `voronav dds-echo` process per robot on
loopback and checks delivery; the assertions here re-check its JSON report."""
import json
import os
import sys
import tempfile
import time

from cli_util import check, runner

BIN, ROOT, CASE = sys.argv[1], sys.argv[2], sys.argv[3]


run = runner(BIN, timeout=120)


def selftest(*args, expect=0):
    p = run("dds-selftest", "--json", "--quiet", "1.0", *args, expect=expect)
    return json.loads(p.stdout)


def case_selftest_6():
    r = selftest("--processes", "6")
    check(r["passed"], f"selftest failed: {r['violations']}")
    # 6 robots 10 m apart, range 25 m: 18 ordered in-range pairs x 5 broadcasts + 5 in-range
    # directed pairs (5 -> 0 is 50 m apart) x 5 rounds.
    check(r["expected"] == 115, f"expected 115 messages, got {r['expected']}")
    check(r["delivered"] == 115, f"delivered {r['delivered']} of 115")
    check(r["out_of_range_delivered"] == 0 and r["duplicates"] == 0, "range or duplicates")
    check(len(r["children"]) == 6 and all(c["status"] == "exited" for c in r["children"]),
          "every robot process exits by itself")
    check(r["wall_s"] < 60, "wall time is reported and bounded")


def case_selftest_kill():
    t0 = time.monotonic()
    r = selftest("--processes", "6", "--kill", "2", "--rounds", "20")
    check(r["passed"], f"selftest with a killed robot failed: {r['violations']}")
    check(r["killed"] == 2, "the report names the killed robot")
    st = {c["id"]: c["status"] for c in r["children"]}
    check(st[2] == "killed", f"robot 2 should be killed, is {st[2]}")
    check(all(s == "exited" for i, s in st.items() if i != 2), f"the others exit: {st}")
    check(r["delivered"] == r["expected"], "all messages of the survivors arrive")
    check(time.monotonic() - t0 < 60, "nobody hangs")


def case_selftest_loss():
    r = selftest("--processes", "4", "--range", "inf", "--rounds", "50", "--interval", "0.002",
                 "--loss", "0.3", "--seed", "7")
    check(r["passed"], f"lossy selftest failed: {r['violations']}")
    check(r["expected"] == 800, f"expected 800, got {r['expected']}")
    ratio = r["delivery_ratio"]
    check(abs(ratio - 0.7) < 0.08, f"delivery ratio {ratio} should be about 0.7")
    check(r["duplicates"] == 0, "no duplicates under loss")


def case_selftest_text():
    p = run("dds-selftest", "--processes", "3", "--quiet", "0.5")
    check("PASSED" in p.stdout and "3 of" not in p.stdout, p.stdout)


def case_echo_bad_args():
    p = run("dds-echo", "--id", "5", "--peers", "3", expect=2)
    check("--id" in p.stderr, f"the error names --id: {p.stderr}")
    p = run("dds-echo", "--id", "0", "--peers", "2", "--payload-bytes", "3", expect=2)
    check("--payload-bytes" in p.stderr, p.stderr)
    p = run("dds-selftest", "--processes", "3", "--kill", "3", expect=2)
    check("--kill" in p.stderr, p.stderr)
    p = run("dds-selftest", "--processes", "1", expect=2)


def case_echo_alone_times_out():
    # A lone robot waits for its peer only up to --startup-timeout, then reports and exits 0.
    t0 = time.monotonic()
    p = run("dds-echo", "--id", "0", "--peers", "2", "--startup-timeout", "0.5", "--quiet",
            "0.3", "--rounds", "2", "--interval", "0", "--domain", str(1 + os.getpid() % 200),
            "--partition", f"alone-{os.getpid()}")
    r = json.loads(p.stdout)
    check(not r["ready"] and r["received_total"] == 0, f"nobody to hear: {r}")
    check(r["sent_rounds"] == 2, "it still sends")
    check(time.monotonic() - t0 < 20, "and does not hang")


def case_config():
    p = run("dds-config")
    check("<Peer address=\"127.0.0.1\"/>" in p.stdout and "<AllowMulticast>false" in p.stdout,
          p.stdout)
    with tempfile.TemporaryDirectory() as d:
        out = os.path.join(d, "cyclone.xml")
        run("dds-config", "--interface", "eth0", "--peer", "10.0.0.2", "--peer", "10.0.0.3",
            "--out", out)
        xml = open(out).read()
        check("name=\"eth0\"" in xml and "10.0.0.3" in xml, xml)
    p = run("dds-config", "--max-index", "200", expect=2)
    check("max_auto_participant_index" in p.stderr, p.stderr)


CASES = {k[5:]: v for k, v in globals().items() if k.startswith("case_")}
if CASE not in CASES:
    sys.exit(f"unknown case {CASE}; known: {', '.join(sorted(CASES))}")
CASES[CASE]()
print("ok")
