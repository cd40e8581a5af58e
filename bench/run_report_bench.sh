#!/usr/bin/env bash
# Runs bench/report_bench.cpp and writes bench/results/report.md: time and size of writing a
# recording as JSON, reading it back and rendering the replay page, for the example recording and
# the NLB floor plan, as ratios against a naive JSON dump of the map measured in the same run.
# Usage: bench/run_report_bench.sh [build-dir]   (default build/default)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build/default}
cmake --build "$build" --target report_bench >/dev/null
mkdir -p "$root/bench/results"
json=$(mktemp)
"$build/bin/report_bench" --benchmark_min_time=0.3 --benchmark_format=json >"$json"
python3 - "$json" "$root/bench/results/report.md" <<'PY'
import json, sys, datetime
data = json.load(open(sys.argv[1]))
rows = {}
for b in data["benchmarks"]:
    name, arg = b["name"].split("/")[:2]
    rows.setdefault(arg, {})[name] = b
labels = {"0": "example (320 x 200)", "1": "NLB.png floor plan (999 x 850)"}
out = ["# Replay page pipeline", "",
       f"Measured {datetime.date.today()} on {data['context'].get('num_cpus')} CPUs; "
       "`bench/run_report_bench.sh`. Baseline (same run): nlohmann::json dumping the occupancy "
       "as a plain array, without run-length encoding. Ratios are ours / baseline.", "",
       "| recording | cells | naive map JSON ms | naive bytes | to_json ms | bytes | from_json ms | page ms | page bytes | to_json / naive time | bytes / naive bytes |",
       "|---|---|---|---|---|---|---|---|---|---|---|"]
for arg in sorted(rows):
    r = rows[arg]
    n, t, f, p = r["BM_NaiveJsonMap"], r["BM_ToJson"], r["BM_FromJson"], r["BM_RenderPage"]
    out.append(f"| {labels.get(arg, arg)} | {int(t['cells'])} | {n['real_time']:.2f} | {int(n['bytes'])} | "
               f"{t['real_time']:.2f} | {int(t['bytes'])} | {f['real_time']:.2f} | {p['real_time']:.2f} | "
               f"{int(p['bytes'])} | {t['real_time']/n['real_time']:.2f} | {t['bytes']/n['bytes']:.3f} |")
open(sys.argv[2], "w").write("\n".join(out) + "\n")
print("\n".join(out))
PY
rm -f "$json"
