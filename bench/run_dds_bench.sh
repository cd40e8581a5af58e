#!/usr/bin/env bash
# Measures the DDS transport with robots as separate processes on loopback and writes
# bench/results/dds.md: one-way latency (paced traffic) and throughput (saturating senders) between
# 2 and 12 processes, the 50-process selftest wall time, and the in-process round trip
# (bench/dds_bench.cpp) as the baseline measured in the same run.
# Usage: bench/run_dds_bench.sh [build-dir]   (default build/default)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build/default}
cmake --build "$build" --target dds_bench voronav_cli >/dev/null
bin="$build/bin/voronav"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
load_before=$(cut -d' ' -f1-3 /proc/loadavg)
"$build/bin/dds_bench" --benchmark_min_time=0.3 --benchmark_format=json >"$tmp/inproc.json"
run() {  # name, selftest args...
  local name=$1; shift
  echo "running $name: voronav dds-selftest $*" >&2
  "$bin" dds-selftest --json "$@" >"$tmp/$name.json" || true
}
# Paced: 200 rounds, 5 ms apart, 64-byte payloads, everyone in range.
run lat2 --processes 2 --range inf --rounds 200 --interval 0.005 --payload-bytes 64
run lat12 --processes 12 --range inf --rounds 200 --interval 0.005 --payload-bytes 64
# Saturating: senders write as fast as dds_write returns; 256-byte payloads.
run thr2 --processes 2 --range inf --rounds 2000 --interval 0 --payload-bytes 256
run thr12 --processes 12 --range inf --rounds 300 --interval 0 --payload-bytes 256
# The selftest with 50 processes (line of robots, range 25 m), generous discovery limits.
run self50 --processes 50 --startup-timeout 60 --quiet 5 --timeout 150
load_after=$(cut -d' ' -f1-3 /proc/loadavg)
python3 - "$tmp" "$root/bench/results/dds.md" "$load_before" "$load_after" <<'PY'
import json, sys, datetime, os
tmp, out_path, load_before, load_after = sys.argv[1:5]
inproc = json.load(open(os.path.join(tmp, "inproc.json")))
base = {int(b["name"].split("/")[1]): b["real_time"] for b in inproc["benchmarks"]}
R = {n: json.load(open(os.path.join(tmp, n + ".json")))
     for n in ["lat2", "lat12", "thr2", "thr12", "self50"]}
rt64 = base[64]  # us, in-process round trip with 64-byte payloads
o = ["# Cyclone DDS transport: robots as processes on loopback", "",
     f"Measured {datetime.date.today()} on {os.cpu_count()} CPUs with `bench/run_dds_bench.sh` "
     f"(load average before {load_before}, after {load_after}: the machine is shared, so absolute "
     "times vary a lot; compare ratios within one run). Config: `voronav dds-config` (loopback, "
     "unicast discovery, multicast off); QoS reliable, keep-last 256 per sender.", "",
     "## Baseline: two participants in one process (bench/dds_bench.cpp)", "",
     "| payload [B] | round trip [us] |", "|---|---|"]
for k in sorted(base):
    o.append(f"| {k} | {base[k]:.1f} |")
o += ["", "## One-way latency, paced traffic (200 rounds, 5 ms apart, 64 B)", "",
      "Latency = receive time - send time (CLOCK_MONOTONIC, shared by the processes); "
      "p50 is the median of the receivers' medians, p99 the worst receiver's 99th percentile.", "",
      "| processes | delivered / expected | p50 [ms] | p99 [ms] | p50 / in-process round trip | wall [s] |",
      "|---|---|---|---|---|---|"]
for n, k in [(2, "lat2"), (12, "lat12")]:
    r = R[k]
    o.append(f"| {n} | {r['delivered']} / {r['expected']} | {r['latency_p50_ms']:.2f} | "
             f"{r['latency_p99_ms']:.1f} | {r['latency_p50_ms']*1000/rt64:.0f}x | {r['wall_s']:.1f} |")
o += ["", "## Throughput, saturating senders (256 B, no pause)", "",
      "Each process broadcasts and sends one directed message per round as fast as it can, and "
      "takes what arrived between rounds. Throughput = payloads delivered per second, summed "
      "over receivers. Below 100 % delivery, the keep-last history (256 per sender) overflowed "
      "at slow receivers: the bounded-history trade-off (counted as gaps), not a transport error.",
      "", "| processes | delivered / expected | delivery | throughput [msg/s] | vs 2 processes | wall [s] |",
      "|---|---|---|---|---|---|"]
t2 = R["thr2"]["throughput_msgs_s"] or 1.0
for n, k in [(2, "thr2"), (12, "thr12")]:
    r = R[k]
    o.append(f"| {n} | {r['delivered']} / {r['expected']} | {r['delivery_ratio']*100:.1f} % | "
             f"{r['throughput_msgs_s']:.0f} | {r['throughput_msgs_s']/t2:.2f}x | {r['wall_s']:.1f} |")
s = R["self50"]
starts = [c.get("startup_s", 0) for c in s["children"]]
o += ["", "## 50-process selftest", "",
      "`voronav dds-selftest --processes 50 --startup-timeout 60 --quiet 5 --timeout 150` "
      "(robots on a line 10 m apart, range 25 m, 5 rounds).", "",
      f"- passed: **{s['passed']}**, wall time **{s['wall_s']:.1f} s**, "
      f"delivered {s['delivered']} of {s['expected']} in-range messages, "
      f"out-of-range deliveries {s['out_of_range_delivered']}, duplicates {s['duplicates']}",
      f"- discovery (start to all 49 peers matched): slowest process {max(starts):.1f} s, "
      f"median {sorted(starts)[len(starts)//2]:.1f} s",
      f"- latency p50 {s['latency_p50_ms']:.1f} ms, p99 {s['latency_p99_ms']:.0f} ms"]
if s["violations"]:
    o.append(f"- violations ({len(s['violations'])}): " + "; ".join(s["violations"][:5]))
open(out_path, "w").write("\n".join(o) + "\n")
print("\n".join(o))
PY
