#!/usr/bin/env bash
# Seed 000, Tables 6-7 (issue #13): runs `voronav netsim --scenario N --method both --runs R --json`
# for N = 1..4 and prints markdown tables that say which mechanism produced each result: who found
# the route (route_found_by), Paths lost, Repairs executed, whether the obstacle changes hit the
# route in use, the eq. 2 route length, the source's driving and the relays' driving, traffic with
# and without changes; the paper's claims side by side (travel, traffic, computation); the bytes
# of each message kind (means over change-free and change runs); then, per change run, the
# messages of each kind both methods sent (the trace behind the traffic comparison).
# Usage: bench/run_netsim_mechanism.sh [build-dir] [runs (default 16)] [folder to keep the JSON]
# With a folder that already holds sN.json, those are read instead of running scenario N again.
# SCENARIOS="1 3" restricts the scenarios (default: 1 2 3 4).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build/default}
runs=${2:-16}
keep=${3:-}
cli=$build/bin/voronav
if [ -n "$keep" ]; then
  mkdir -p "$keep"
  tmp=$keep
else
  tmp=$(mktemp -d)
  trap 'rm -rf "$tmp"' EXIT
fi
scenarios=${SCENARIOS:-1 2 3 4}
for s in $scenarios; do
  [ -s "$tmp/s$s.json" ] && continue
  "$cli" netsim --scenario "$s" --runs "$runs" --method both --json --quiet > "$tmp/s$s.json"
done
/usr/bin/python3 - "$tmp" $scenarios <<'PY'
import json, os, statistics, sys
d = sys.argv[1]
print("| scenario | method | success | route by relays / source alone / none | Paths lost | "
      "Paths unacknowledged | Repairs executed | change runs with a change on the route | "
      "change runs with a Repair asked / answered / executed | route eq. 2 [m] | "
      "source drove [m] | relays drove [m] | traffic no change [B] | traffic with changes [B] |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
data = {}
for s in map(int, sys.argv[2:]):
    j = data[s] = json.load(open(os.path.join(d, f"s{s}.json")))
    for m in ("centralized", "decentralized"):
        v = j[m]
        runs = v["per_run"]
        ok = [r for r in runs if r["success"]]
        mean = lambda k, rs: statistics.mean(r[k] for r in rs) if rs else float("nan")
        nochange = [r for r in runs if r["changes_applied"] == 0]
        change = [r for r in runs if r["changes_applied"] > 0]
        by = v["route_found_by"]
        rq = "–" if m == "centralized" else (f"{v.get('change_runs_repair_asked', '?')} / "
              f"{v.get('change_runs_repair_answered', '?')} / {v.get('change_runs_repaired', '?')} of {v['change_runs']}")
        print(f"| {s} | {m} | {len(ok)}/{len(runs)} | {by['relays']} / {by['source_alone']} / {by['none']} | "
              f"{v['paths_lost']} | {v.get('paths_unacknowledged', '?')} | {v['repairs_executed']} | "
              f"{v['change_runs_on_route']}/{v['change_runs']} | {rq} | "
              f"{mean('route_length_m', ok):.1f} | {mean('source_travel_m', ok):.1f} | "
              f"{mean('relay_travel_m', ok):.1f} | {mean('traffic_bytes', nochange):.0f} | "
              f"{mean('traffic_bytes', change):.0f} |")
print()
print("The paper's claims side by side (means over successful runs for travel; over all runs "
      "otherwise): centralized source travel vs decentralized eq. 2 route and source travel "
      "(figures 30-33), traffic without / with changes (figures 22-25), computation total and of "
      "the busiest robot (work units, eq. 8-9; figures 26-29, 34-37).")
print()
print("| scenario | travel c [m] | route eq. 2 d [m] | source drove d [m] | traffic no change c / d [B] | "
      "traffic with changes c / d [B] | computation c / d | busiest robot c / d |")
print("|---|---|---|---|---|---|---|---|")
for s, j in data.items():
    c, dd = j["centralized"]["per_run"], j["decentralized"]["per_run"]
    def m(rs, k, only_ok=False, cond=lambda r: True):
        v = [r[k] for r in rs if cond(r) and (r["success"] or not only_ok)]
        return statistics.mean(v) if v else float("nan")
    nc = lambda r: r["changes_applied"] == 0
    wc = lambda r: r["changes_applied"] > 0
    print(f"| {s} | {m(c, 'source_travel_m', True):.1f} | {m(dd, 'route_length_m', True):.1f} | "
          f"{m(dd, 'source_travel_m', True):.1f} | {m(c, 'traffic_bytes', cond=nc):.0f} / "
          f"{m(dd, 'traffic_bytes', cond=nc):.0f} | {m(c, 'traffic_bytes', cond=wc):.0f} / "
          f"{m(dd, 'traffic_bytes', cond=wc):.0f} | {m(c, 'computation'):.3g} / {m(dd, 'computation'):.3g} | "
          f"{m(c, 'max_robot_computation'):.3g} / {m(dd, 'max_robot_computation'):.3g} |")
print()
print("Traffic by message kind: mean bytes per run (change-free runs / change runs).")
print()
print("| scenario | method | " + " | ".join(["request", "ack", "notify", "search", "path", "repair", "link_ack"]) + " |")
print("|---|---|" + "---|" * 7)
for s, j in data.items():
    for meth in ("centralized", "decentralized"):
        rs = j[meth]["per_run"]
        cells = []
        for k in ["request", "ack", "notify", "search", "path", "repair", "link_ack"]:
            def mb(cond):
                v = [r.get("sent_by_type", {}).get(k, {}).get("bytes", 0) for r in rs if cond(r)]
                return statistics.mean(v) if v else float("nan")
            cells.append(f"{mb(lambda r: r['changes_applied'] == 0):.0f} / {mb(lambda r: r['changes_applied'] > 0):.0f}")
        print(f"| {s} | {meth} | " + " | ".join(cells) + " |")
print()
print("Repair per change run (decentralized; absent in JSON from before stop 17: `?`): Repairs "
      "started by the source / by all robots, detours sent back by answerers, repaired routes that "
      "reached the source / that it refused as blocked in its own map, Repairs the source sent again "
      "with cells it learned / the most cells one of its Repairs carried (repair_share_met_blocks), "
      "Repairs executed, success.")
print()
print("| scenario | run | source asked / all asked | answers sent | reached source / refused | "
      "re-asks / most cells carried | executed | arrived | searches |")
print("|---|---|---|---|---|---|---|---|---|")
g = lambda r, k: r.get(k, "?")
for s, j in data.items():
    for r in j["decentralized"]["per_run"]:
        if r["changes_applied"] == 0:
            continue
        print(f"| {s} | {r['run']} | {g(r, 'source_repair_requests')} / {g(r, 'repair_requests')} | "
              f"{g(r, 'repair_answers')} | {g(r, 'repair_answers_received')} / "
              f"{g(r, 'repair_answers_refused')} | {g(r, 'repair_reasks')} / {g(r, 'repair_cells_max')} | "
              f"{r['repairs_executed']} | "
              f"{'yes' if r['success'] else 'no'} | {r['search_attempts']} |")
print()
print("Change runs: changes placed / on the route (centralized, decentralized), Repairs executed "
      "(decentralized), traffic [B] and messages sent by kind (`kind count`, all robots).")
print()
print("| scenario | run | changes | on route c / d | Repairs executed | traffic c / d [B] | "
      "centralized messages | decentralized messages |")
print("|---|---|---|---|---|---|---|---|")
kinds = lambda r: ", ".join(f"{k} {v['messages']}" for k, v in sorted(r.get("sent_by_type", {}).items())) or "?"
for s, j in data.items():
    cent = {r["run"]: r for r in j["centralized"]["per_run"]}
    for r in j["decentralized"]["per_run"]:
        if r["changes"] == 0:
            continue
        c = cent[r["run"]]
        print(f"| {s} | {r['run']} | {r['changes']} | {c['changes_on_route']} / {r['changes_on_route']} | "
              f"{r['repairs_executed']} | {c['traffic_bytes']} / {r['traffic_bytes']} | {kinds(c)} | {kinds(r)} |")
PY
