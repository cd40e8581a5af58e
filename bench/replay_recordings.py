#!/usr/bin/env python3
"""Synthetic recordings for the replay-page benchmark (bench/run_replay_bench.sh).

usage: replay_recordings.py KIND ROBOTS SECONDS OUT.json
  KIND netsim:  ROBOTS robots wander a 200 x 200 m free map with walls for SECONDS s, sampled at
                5 Hz, each sending a message to a neighbour every 2 s (like `voronav netsim`);
  KIND explore: ROBOTS robots drive outwards from the centre of a 100 x 100 m map sampled at 2 Hz,
                and the map is revealed over time (like `voronav explore`).
The motion is deterministic (no random module state), so every run draws the same pages.
"""
import json
import math
import sys


def rle(values):
    out = []
    for v in values:
        if out and out[-2] == v:
            out[-1] += 1
        else:
            out += [v, 1]
    return out


def main():
    kind, n, seconds, out = sys.argv[1], int(sys.argv[2]), float(sys.argv[3]), sys.argv[4]
    res = 0.5 if kind == "netsim" else 0.25
    side_m = 200.0 if kind == "netsim" else 100.0
    W = H = int(side_m / res)
    occ = [0] * (W * H)
    for y in range(H):
        for x in range(W):
            border = x in (0, W - 1) or y in (0, H - 1)
            wall = (x % 80 == 40 and (y % 80) < 60) or (y % 80 == 40 and (x % 80) > 20)
            occ[y * W + x] = 100 if border or wall else 0
    rate = 5.0 if kind == "netsim" else 2.0
    steps = int(seconds * rate)
    robots = []
    for i in range(n):
        a = 2.0 * math.pi * i / n + 0.37 * i
        cx = side_m / 2 + (side_m / 3) * math.cos(a) * ((i % 7) / 7.0) if kind == "netsim" else side_m / 2
        cy = side_m / 2 + (side_m / 3) * math.sin(a) * ((i % 5) / 5.0) if kind == "netsim" else side_m / 2
        poses = []
        for k in range(steps + 1):
            t = k / rate
            if kind == "netsim":
                r = 4.0 + (i % 11)
                w = 0.05 + 0.01 * (i % 13)
                x, y, yaw = cx + r * math.cos(w * t + a), cy + r * math.sin(w * t + a), w * t + a + math.pi / 2
            else:
                d = min(side_m / 2 - 2.0, 0.3 * t) * (0.5 + 0.5 * ((i * 37) % 100) / 100.0)
                wig = 2.0 * math.sin(0.05 * t + i)
                x = cx + d * math.cos(a) - wig * math.sin(a)
                y = cy + d * math.sin(a) + wig * math.cos(a)
                yaw = a
            poses.append([round(t, 3), round(x, 3), round(y, 3), round(yaw, 3)])
        robots.append({"id": i, "poses": poses})
    rec = {"format": "voronav-recording", "version": 1,
           "title": f"replay benchmark: {kind}, {n} robots, {seconds:.0f} s",
           "map": {"width": W, "height": H, "resolution": res, "occupancy": rle(occ)},
           "robots": robots}
    if kind == "netsim":
        msgs = []
        for k in range(int(seconds / 2)):
            for i in range(0, n, 3):
                msgs.append({"t": 2.0 * k + 0.01 * (i % 100), "from": i, "to": (i + 1) % n,
                             "type": "Search" if i % 2 else "Path", "bytes": 64})
        msgs.sort(key=lambda m: m["t"])
        rec["messages"] = msgs
        rec["events"] = [{"t": seconds / 2, "kind": "change", "text": "a door closes"}]
    else:
        c = W // 2
        reveal = []
        for y in range(H):
            for x in range(W):
                dist_m = math.hypot(x - c, y - c) * res
                reveal.append(int(10 * dist_m / 0.3 * 0.75) if dist_m < side_m / 2 else -1)
        rec["reveal"] = {"period_s": 0.1, "cells": rle(reveal)}
    with open(out, "w") as f:
        json.dump(rec, f, separators=(",", ":"))


if __name__ == "__main__":
    main()
