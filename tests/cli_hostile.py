#!/usr/bin/env python3
"""Hostile input against the real CLI (issue 17): every case must end with the expected exit code
within a CPU-time limit, with a message naming the file (and line/key) or the option, and (release
builds) under a memory limit. Usage: cli_hostile.py BIN ROOT [CASE_REGEX].

Each case: the files it needs (made here, small), the command, the exit code, fragments that
stderr (or stdout) must contain, fragments it must not. Peak RSS is measured per run (wait4) and
must stay under 200 MB; an address-space limit of 1 GiB is set too. Both are skipped under
AddressSanitizer (its shadow memory needs terabytes of address space), where the time limit is
also 5x longer.

The limit is on the CPU time the run used (wait4's user + system time; RLIMIT_CPU kills a run
that spins past it), not on wall time: on a shared 2-core machine under `ctest -j2` a case that
needs 0.1 s of CPU can wait seconds for a core, and a wall-clock limit then fails a correct build.
A run that blocks without using CPU (a read that never returns) is caught by a wall-clock
backstop of WALL_LIMIT seconds."""
import os
import re
import resource
import shutil
import signal
import struct
import subprocess
import sys
import tempfile
import threading
import time
import zlib

BIN, ROOT = sys.argv[1], sys.argv[2]
ONLY = re.compile(sys.argv[3]) if len(sys.argv) > 3 else None
ASAN = b"libasan" in subprocess.run(["ldd", BIN], capture_output=True).stdout or \
    "ASAN_OPTIONS" in os.environ
TIME_LIMIT = 2.0 * (5 if ASAN else 1)  # CPU seconds per case
WALL_LIMIT = 60.0 * (5 if ASAN else 1)  # hang backstop
RSS_LIMIT_MB = 200
AS_LIMIT = 1 << 30


def limits(cpu_seconds):
    def apply():
        if not ASAN:
            resource.setrlimit(resource.RLIMIT_AS, (AS_LIMIT, AS_LIMIT))
        soft = int(cpu_seconds) + 2  # whole seconds; SIGXCPU ends a spinning run soon after
        resource.setrlimit(resource.RLIMIT_CPU, (soft, soft + 1))
    return apply


def run(args, cwd, cpu_limit=TIME_LIMIT, env=None):
    """(exit code, stdout, stderr, CPU seconds, peak RSS MB); exit code None when the run was
    killed at the wall-clock backstop or by RLIMIT_CPU."""
    out_f, err_f = tempfile.TemporaryFile(), tempfile.TemporaryFile()
    p = subprocess.Popen([BIN, *args], cwd=cwd, stdout=out_f, stderr=err_f,
                         stdin=subprocess.DEVNULL, preexec_fn=limits(cpu_limit), env=env)
    timed_out = []
    timer = threading.Timer(WALL_LIMIT, lambda: (timed_out.append(1), p.kill()))
    timer.start()
    _, status, usage = os.wait4(p.pid, 0)
    timer.cancel()
    p.returncode = 0
    secs = usage.ru_utime + usage.ru_stime
    out_f.seek(0)
    err_f.seek(0)
    killed_by_cpu = os.WIFSIGNALED(status) and os.WTERMSIG(status) in (signal.SIGXCPU,
                                                                       signal.SIGKILL)
    code = None if timed_out or killed_by_cpu else os.waitstatus_to_exitcode(status)
    return (code, out_f.read().decode(errors="replace"), err_f.read().decode(errors="replace"),
            secs, usage.ru_maxrss / 1024.0)


# --- small inputs -------------------------------------------------------------------------------
def png(w, h, rows=b""):
    def chunk(t, d):
        return struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d) & 0xffffffff)
    ihdr = struct.pack(">IIBBBBB", w, h, 8, 0, 0, 0, 0)
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + chunk(b"IDAT", zlib.compress(rows)) + \
        chunk(b"IEND", b"")


MAP4 = "type octile\nheight 4\nwidth 4\nmap\n....\n.@..\n....\n....\n"
MAP3 = "type octile\nheight 3\nwidth 3\nmap\n...\n...\n...\n"
MAP2 = "type octile\nheight 2\nwidth 2\nmap\n..\n..\n"
ROS_YAML = "image: {img}\nresolution: {res}\norigin: [0, 0, 0]\nnegate: 0\n" \
           "occupied_thresh: 0.65\nfree_thresh: 0.196\n"
PGM_1x2 = b"P5\n1 2\n255\n\xfe\xfe"
PGM_10 = b"P5\n10 10\n255\n" + b"\xfe" * 100
SCHED_OK = '{"agents": [{"id": 1, "path": [[0, 0], [1, 0]], "v_max": 1, "radius": 0.2, ' \
           '"delay": 0}]}\n'


def crowd_schedule(n):
    agents = ",\n".join('{"id": %d, "path": [[0, 0], [5, 0]], "v_max": 1, "radius": 0.5, '
                        '"delay": 0}' % (i + 1) for i in range(n))
    return '{"agents": [\n' + agents + "\n]}\n"


CROSS = ("  - {id: 1, start: [0, 0], goal: [2, 2], radius: 0.3}\n"
         "  - {id: 2, start: [2, 0], goal: [0, 2], radius: 0.3}\n")


def scenario(extra="", robots="  - {id: 1, start: [0, 0], goal: [2, 2], radius: 0.3}\n"):
    return "map: m3.map\n" + extra + "robots:\n" + robots


# --- the cases ----------------------------------------------------------------------------------
# (name, files {name: text|bytes}, args, exit code, must contain [...], must not contain [...])
# "{d}" in args is the case's folder. Fragments are matched against stderr + stdout.
CASES = [
    # crash
    ("ras_region_size_huge", {"m.map": MAP4},
     ["plan", "--map", "m.map", "--planner", "ras", "--region-size", "2147483647",
      "--start", "0,0", "--goal", "3,3"], 2, ["--region-size", "1 to 65536"], []),
    ("ras_region_size_2x2", {"m.map": MAP2},
     ["plan", "--map", "m.map", "--planner", "ras", "--region-size", "2147483647",
      "--start", "0,0", "--goal", "1,1"], 2, ["--region-size"], []),
    ("ras_region_size_max_ok", {"m.map": MAP4},
     ["plan", "--map", "m.map", "--planner", "ras", "--region-size", "65536",
      "--start", "0,0", "--goal", "3,3"], 1, ["region grid 1x1"], []),
    # hangs
    ("coord_node_spacing_1e9_file", {"m3.map": MAP3, "s.yaml": scenario("node_spacing: 1e9\n")},
     ["coordinate", "--scenario", "s.yaml", "--json"], 0, ['"valid"'], []),
    ("coord_node_spacing_1e9_option", {"m3.map": MAP3, "s.yaml": scenario()},
     ["coordinate", "--scenario", "s.yaml", "--node-spacing", "1e9", "--json"], 0, ['"valid"'], []),
    ("coord_radius_huge", {"m3.map": MAP3, "s.yaml": scenario(robots=(
        "  - {id: 1, start: [0, 0], goal: [2, 2], radius: 100000}\n"
        "  - {id: 2, start: [2, 0], goal: [0, 2], radius: 0.3}\n"))},
     ["coordinate", "--scenario", "s.yaml"], 1, ["no delay-only schedule"], []),
    ("map_tiny_resolution", {"w.pgm": PGM_1x2, "w.yaml": ROS_YAML.format(img="w.pgm", res="1e-6")},
     ["map", "--map", "w.yaml", "--poses", "5", "--clearance", "0"], 0, [], []),
    ("dev_zero_schedule", {}, ["validate-schedule", "/dev/zero"], 2,
     ["/dev/zero", "over the limit of 64 MiB"], []),
    ("dev_zero_scen", {"m3.map": MAP3}, ["scen", "--map", "m3.map", "--scen", "/dev/zero"], 2,
     ["/dev/zero", "over the limit"], []),
    ("dev_zero_recording", {}, ["replay", "--recording", "/dev/zero", "--out", "{d}/r"], 2,
     ["/dev/zero", "over the limit"], []),
    ("dev_zero_coord_scenario", {}, ["coordinate", "--scenario", "/dev/zero"], 2,
     ["/dev/zero", "over the limit"], []),
    ("dev_zero_netsim_scenario", {}, ["netsim", "--scenario", "/dev/zero"], 2,
     ["/dev/zero", "--scenario"], []),
    # runaway memory
    ("pgm_header_65536", {"big.pgm": b"P5\n65536 65536\n255\n"},
     ["plan", "--map", "big.pgm", "--start", "0,0", "--goal", "1,1"], 2, ["big.pgm", "pixels"], []),
    ("pgm_header_30000", {"big.pgm": b"P5\n30000 30000\n255\n"},
     ["plan", "--map", "big.pgm", "--start", "0,0", "--goal", "1,1"], 2,
     ["big.pgm", "over the limit of 268435456 pixels"], []),
    ("pgm_header_10000", {"big.pgm": b"P5\n10000 10000\n255\n"},
     ["plan", "--map", "big.pgm", "--start", "0,0", "--goal", "1,1"], 2,
     ["big.pgm", "truncated raster"], []),
    ("pgm_ascii_header_16000", {"big.pgm": b"P2\n16000 16000\n255\n0 0 0\n"},
     ["plan", "--map", "big.pgm", "--start", "0,0", "--goal", "1,1"], 2,
     ["big.pgm", "truncated raster"], []),
    ("png_header_16000", {"big.png": png(16000, 16000, b"\0" * 100)},
     ["plan", "--map", "big.png", "--start", "0,0", "--goal", "1,1"], 2,
     ["big.png", "cannot be stored"], []),
    ("movingai_header_65536", {"big.map": "type octile\nheight 65536\nwidth 65536\nmap\n"},
     ["plan", "--map", "big.map", "--start", "0,0", "--goal", "1,1"], 2,
     ["big.map:4", "truncated file"], []),
    ("coord_node_spacing_tiny", {"m3.map": MAP3, "s.yaml": scenario("node_spacing: 1e-9\n", CROSS)},
     ["coordinate", "--scenario", "s.yaml"], 2, ["node_spacing", "1000000 nodes"], []),
    ("ros_resolution_1e6", {"w.pgm": PGM_10, "w.yaml": ROS_YAML.format(img="w.pgm", res="1e6"),
                            "s.yaml": "map: w.yaml\nrobots:\n"
                            "  - {id: 1, start: [1e6, 1e6], goal: [8e6, 8e6], radius: 0.3}\n"
                            "  - {id: 2, start: [8e6, 1e6], goal: [1e6, 8e6], radius: 0.3}\n"},
     ["coordinate", "--scenario", "s.yaml"], 2, ["node_spacing"], []),
    ("schedule_1000_identical", {"c.json": crowd_schedule(1000)},
     ["validate-schedule", "c.json"], 1, ["INVALID", "more overlapping pairs"], []),
    # unhelpful messages
    ("schedule_missing_key", {"s.json": SCHED_OK.replace('"v_max": 1, ', "")},
     ["validate-schedule", "s.json"], 2, ["s.json:1", "v_max", "missing key"], ["invalid node"]),
    ("schedule_missing_key_yaml", {"s.yaml": "agents:\n  - id: 1\n    path: [[0, 0], [1, 0]]\n"
                                             "    radius: 0.2\n    delay: 0\n"},
     ["validate-schedule", "s.yaml"], 2, ["s.yaml:2", "v_max", "missing key"], ["invalid node"]),
    ("schedule_at_start_not_string", {"s.yaml": "at_start: [1]\n" + "agents: []\n"},
     ["validate-schedule", "s.yaml"], 2, ["s.yaml:1", "at_start", "expected a string"],
     ["bad conversion"]),
    ("scenario_map_not_string", {"s.yaml": "map: [1, 2]\nrobots:\n  - {path: [[0, 0], [1, 0]]}\n"},
     ["coordinate", "--scenario", "s.yaml"], 2, ["s.yaml:1", "map: expected a string"],
     ["bad conversion"]),
    ("scenario_coordinates_not_string",
     {"m3.map": MAP3, "s.yaml": scenario("coordinates: {a: 1}\n")},
     ["coordinate", "--scenario", "s.yaml"], 2, ["s.yaml:2", "coordinates"], ["bad conversion"]),
    ("recording_number_overflow", {"r.json": '{"format": "voronav-recording", "version": 1, '
                                             '"resolution": 1e309}'},
     ["replay", "--recording", "r.json", "--out", "{d}/out"], 2, ["r.json", "invalid JSON"],
     ["json.exception"]),
    ("scenario_node_spacing_negative", {"m3.map": MAP3, "s.yaml": scenario("node_spacing: -1\n")},
     ["coordinate", "--scenario", "s.yaml"], 2, ["s.yaml:2", "node_spacing"], []),
    ("explore_no_room", {"m3.map": MAP3},
     ["explore", "--world", "m3.map", "--robots", "64", "--time", "1"], 2, ["--robots"],
     ["run_exploration"]),
    ("map_sweep_clearance", {"m3.map": MAP3},
     ["map", "--map", "m3.map", "--clearance", "100"], 2, ["--clearance"], []),
    ("range_readable", {"m3.map": MAP3},
     ["plan", "--map", "m3.map", "--start", "0,0", "--goal", "2,2", "--radius", "-1"], 2,
     ["--radius", "expected a finite number >= 0, got '-1'"], ["17976931348623157"]),
    ("topo_out_root", {"m3.map": MAP3}, ["topo", "--map", "m3.map", "--out", "/"], 2,
     ["--out", "filesystem root"], []),
    ("coordinate_out_is_file", {"m3.map": MAP3, "s.yaml": scenario(), "f": "x"},
     ["coordinate", "--scenario", "s.yaml", "--out", "f"], 2, ["--out", "is a file"], []),
    ("netsim_out_is_file", {"f": "x"}, ["netsim", "--scenario", "1", "--out", "f"], 2,
     ["--out", "is a file"], []),
    # silent wrong results and side effects
    ("explore_time_huge", {"m3.map": MAP3}, ["explore", "--world", "m3.map", "--time", "1e18"], 2,
     ["--time", "1e+06"], []),
    ("scen_tolerance_nan", {"m3.map": MAP3, "q.scen": "version 1\n"},
     ["scen", "--map", "m3.map", "--scen", "q.scen", "--tolerance", "nan"], 2, ["--tolerance"],
     []),
    ("coord_node_spacing_negative_option", {"m3.map": MAP3, "s.yaml": scenario()},
     ["coordinate", "--scenario", "s.yaml", "--node-spacing", "-1"], 2, ["--node-spacing"], []),
    ("coord_node_spacing_nan_option", {"m3.map": MAP3, "s.yaml": scenario()},
     ["coordinate", "--scenario", "s.yaml", "--node-spacing", "nan"], 2, ["--node-spacing"], []),
    ("explore_stop_at_negative", {"m3.map": MAP3},
     ["explore", "--world", "m3.map", "--stop-at", "-1"], 2, ["--stop-at", "0..1"], []),
    ("explore_stop_at_2", {"m3.map": MAP3},
     ["explore", "--world", "m3.map", "--stop-at", "2"], 2, ["--stop-at", "0..1"], []),
    ("netsim_kill_robot_negative", {}, ["netsim", "--kill-robot", "-1"], 2, ["--kill-robot"], []),
    ("seed_negative", {"m3.map": MAP3}, ["map", "--map", "m3.map", "--seed", "-1"], 2, ["--seed"],
     []),
    ("netsim_seed_negative", {}, ["netsim", "--seed", "-1"], 2, ["--seed"], []),
    ("scenario_id_huge", {"m3.map": MAP3, "s.yaml": scenario(robots=(
        "  - {id: 1e300, start: [0, 0], goal: [2, 2], radius: 0.3}\n"))},
     ["coordinate", "--scenario", "s.yaml"], 2, ["s.yaml:3", "id"], []),
    ("netsim_write_scenario_dir", {"existing/keep": "x"},
     ["netsim", "--scenario", "1", "--write-scenario", "existing"], 2,
     ["--write-scenario", "is a folder"], []),
    ("netsim_write_scenario_tmp", {}, ["netsim", "--scenario", "1", "--write-scenario", "/tmp"], 2,
     ["--write-scenario", "is a folder"], []),
    ("netsim_write_scenario_root_file", {},
     ["netsim", "--scenario", "1", "--write-scenario", "/voronav_hostile_test.yaml"], 2,
     ["--write-scenario", "filesystem root"], []),
    ("demo_out_in_proc", {}, ["demo", "--out", "/proc/voronav_hostile_test"], 2,
     ["--out", "cannot create the output folder '/proc/voronav_hostile_test'"], ["filesystem error"]),
    ("replay_example_out_root", {}, ["replay", "--example", "--out", "/"], 2,
     ["--out", "filesystem root"], []),
]


# Cases that take ~1.5 s in release on a loaded 2-core machine get more headroom (no hang is
# anywhere near it: before issue 17 they ran out of memory or for minutes).
SLOW = {"schedule_1000_identical": 3}


def main():
    failures = []
    with tempfile.TemporaryDirectory() as top:
        for name, files, args, expect, must, must_not in CASES:
            if ONLY and not ONLY.search(name):
                continue
            d = os.path.join(top, name)
            os.makedirs(d)
            for fname, content in files.items():
                path = os.path.join(d, fname)
                os.makedirs(os.path.dirname(path), exist_ok=True)
                with open(path, "wb") as f:
                    f.write(content.encode() if isinstance(content, str) else content)
            before = set(os.listdir(d))
            argv = [a.replace("{d}", d) for a in args]
            limit = TIME_LIMIT * SLOW.get(name, 1)
            code, out, err, secs, rss = run(argv, d, cpu_limit=limit)
            text = err + out
            problems = []
            if code is None:
                problems.append(f"killed: no exit within {WALL_LIMIT:g} s wall or CPU limit")
            elif secs > limit:
                problems.append(f"used {secs:.2f} s CPU, limit {limit:g} s")
            elif code != expect:
                problems.append(f"exit {code}, expected {expect}")
            problems += [f"missing '{m}'" for m in must if m not in text]
            problems += [f"unwanted '{m}'" for m in must_not if m in text]
            if not ASAN and rss > RSS_LIMIT_MB:
                problems.append(f"peak RSS {rss:.0f} MB > {RSS_LIMIT_MB} MB")
            if expect == 2:
                extra = set(os.listdir(d)) - before
                if extra:
                    problems.append(f"wrote {sorted(extra)} although the input was refused")
            status = "ok" if not problems else "FAIL"
            print(f"{status} {name}: exit {code}, {secs:.2f} s CPU, {rss:.0f} MB")
            if problems:
                failures.append(f"{name}: voronav {' '.join(argv)}\n  " + "; ".join(problems) +
                                f"\n  output: {text[:600]}")
    for root_file in ("/voronav_hostile_test.yaml", "/voronav_hostile_test_world.yaml"):
        if os.path.exists(root_file):
            failures.append(f"{root_file} was written")
    if failures:
        sys.exit("FAIL:\n" + "\n".join(failures))
    print("all hostile-input cases passed")


def interrupt_check():
    """A long-but-legal run (map with 1e6 poses) prints its heartbeat and stops on SIGINT."""
    with tempfile.TemporaryDirectory() as d:
        with open(os.path.join(d, "m.pgm"), "wb") as f:
            f.write(PGM_10)
        env = dict(os.environ, VORONAV_PROGRESS="1")
        p = subprocess.Popen([BIN, "map", "--map", "m.pgm", "--poses", "1000000", "--clearance", "0"], cwd=d,
                             stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, env=env, text=True)
        time.sleep(6.5)
        p.send_signal(signal.SIGINT)
        try:
            _, err = p.communicate(timeout=5)
        except subprocess.TimeoutExpired:
            p.kill()
            sys.exit("FAIL: map --poses 1000000 did not stop within 5 s of SIGINT")
        if p.returncode != 130 or "still running after 5 s" not in err or "interrupted" not in err:
            sys.exit(f"FAIL: SIGINT: exit {p.returncode}, stderr {err!r}")
        print("ok interrupt: heartbeat after 5 s, exit 130 on SIGINT")


if __name__ == "__main__":
    if ONLY and ONLY.pattern == "interrupt":
        interrupt_check()
    else:
        main()
