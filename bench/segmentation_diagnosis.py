#!/usr/bin/env python3
"""Per-room diagnosis of a room segmentation against its ground truth (issue #15).

Reads the map image, the ground-truth room image (white rooms) and the 16-bit label image that
`voronav topo --labels` writes (0 = no region), scores with the ipa_room_segmentation definition
(rooms: 8-connected white components over 100 px; regions over 100 px; full areas), prints which
ground-truth rooms are split (recall < threshold: the regions covering them) and which regions
are merged over several rooms (precision < threshold: the rooms they cover), and optionally draws
a picture: regions in colours, ground-truth room borders in black, split rooms hatched red,
merged regions hatched blue, critical lines (from topology.json) in green.

Usage: segmentation_diagnosis.py MAP.png GT.png LABELS.png [--topology topology.json]
                                  [--picture out.png] [--threshold 0.9]
"""
import argparse
import json

import numpy as np
from PIL import Image
from scipy import ndimage


def components8(mask, min_pixels):
    lab, n = ndimage.label(mask, structure=np.ones((3, 3), dtype=int))
    sizes = np.bincount(lab.ravel(), minlength=n + 1)
    keep = [i for i in range(1, n + 1) if sizes[i] > min_pixels]
    out = np.zeros_like(lab)
    for k, i in enumerate(keep, start=1):
        out[lab == i] = k
    return out, len(keep)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("map")
    ap.add_argument("gt")
    ap.add_argument("labels")
    ap.add_argument("--topology")
    ap.add_argument("--picture")
    ap.add_argument("--threshold", type=float, default=0.9)
    a = ap.parse_args()
    gt = np.array(Image.open(a.gt).convert("L"))
    lab = np.array(Image.open(a.labels)).astype(np.int64)
    if gt.shape != lab.shape:
        gt = np.array(Image.fromarray(gt).resize(lab.shape[::-1], Image.NEAREST))
    rooms, nrooms = components8(gt >= 250, 100)
    sizes = np.bincount(lab.ravel())
    regions = [r for r in range(1, len(sizes)) if sizes[r] > 100]
    # overlap[room, region]
    both = (rooms > 0) & (lab > 0)
    pairs = np.stack([rooms[both], lab[both]], axis=1)
    ov = {}
    for (r, g), c in zip(*np.unique(pairs, axis=0, return_counts=True)):
        ov[(int(r), int(g))] = int(c)
    room_area = np.bincount(rooms.ravel(), minlength=nrooms + 1)
    recall, precision = [], []
    split, merged = [], []
    for r in range(1, nrooms + 1):
        cover = sorted(((c, g) for (rr, g), c in ov.items() if rr == r), reverse=True)
        best = cover[0][0] if cover else 0
        recall.append(best / room_area[r])
        if recall[-1] < a.threshold:
            split.append((r, recall[-1], room_area[r], cover[:5]))
    for g in regions:
        cover = sorted(((c, r) for (r, gg), c in ov.items() if gg == g), reverse=True)
        best = cover[0][0] if cover else 0
        precision.append(best / sizes[g])
        if precision[-1] < a.threshold:
            merged.append((g, precision[-1], sizes[g], cover[:5]))
    print(f"rooms {nrooms} regions {len(regions)} recall {100 * np.mean(recall):.1f} "
          f"precision {100 * np.mean(precision):.1f}")
    for r, rec, area, cover in split:
        ys, xs = np.nonzero(rooms == r)
        print(f"  room {r} (centre x={xs.mean():.0f} y={ys.mean():.0f} image px, {area} px): "
              f"recall {100 * rec:.1f}, regions " +
              ", ".join(f"{g}:{c}" for c, g in cover))
    for g, prec, area, cover in merged:
        ys, xs = np.nonzero(lab == g)
        print(f"  region {g} (centre x={xs.mean():.0f} y={ys.mean():.0f}, {area} px): precision "
              f"{100 * prec:.1f}, rooms " + ", ".join(f"{r}:{c}" for c, r in cover))
    if not a.picture:
        return
    rng = np.random.default_rng(3)
    pal = rng.integers(90, 230, size=(int(lab.max()) + 1, 3)).astype(np.uint8)
    pal[0] = (255, 255, 255)
    img = pal[lab]
    img[np.array(Image.open(a.map).convert("L").resize(lab.shape[::-1])) < 250] = (40, 40, 40)
    border = (rooms > 0) & ~ndimage.binary_erosion(rooms > 0, iterations=1)
    edges = ndimage.grey_dilation(rooms, size=3) != ndimage.grey_erosion(rooms, size=3)
    img[(border | edges) & (gt >= 250)] = (0, 0, 0)
    yy, xx = np.mgrid[0:lab.shape[0], 0:lab.shape[1]]
    hatch = ((xx + yy) % 8) < 2
    for r, *_ in split:
        img[(rooms == r) & hatch] = (220, 0, 0)
    hatch2 = ((xx - yy) % 8) < 2
    for g, *_ in merged:
        img[(lab == g) & hatch2] = (0, 0, 220)
    if a.topology:
        t = json.load(open(a.topology))
        h = lab.shape[0]
        for cp in t["critical_points"]:
            (x0, y0), (x1, y1) = cp["basis"]
            n = int(max(abs(x1 - x0), abs(y1 - y0))) + 1
            for k in range(n + 1):
                x = round(x0 + (x1 - x0) * k / n)
                y = h - 1 - round(y0 + (y1 - y0) * k / n)
                if 0 <= x < lab.shape[1] and 0 <= y < h:
                    img[max(0, y - 1):y + 2, max(0, x - 1):x + 2] = (0, 170, 0)
    Image.fromarray(img).save(a.picture)


if __name__ == "__main__":
    main()
