#!/usr/bin/env python3
"""Side-by-side pictures of room segmentations (issue #15): a crop of the ground-truth rooms and of
one or more 16-bit label images (`voronav topo --labels`), obstacles black, cells outside every
ground-truth room greyed, each room / region in its own colour (same random palette by id).

Usage: segmentation_panels.py MAP.png GT.png LABELS1.png[,LABELS2.png...] X0,Y0,X1,Y1 OUT.png
                              [--scale N] [--vertical]
"""
import argparse

import numpy as np
from PIL import Image
from scipy import ndimage


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("map")
    ap.add_argument("gt")
    ap.add_argument("labels", help="comma-separated label images")
    ap.add_argument("box", help="crop X0,Y0,X1,Y1 in image pixels")
    ap.add_argument("out")
    ap.add_argument("--scale", type=int, default=4)
    ap.add_argument("--vertical", action="store_true")
    a = ap.parse_args()
    x0, y0, x1, y1 = (int(v) for v in a.box.split(","))
    blocked = np.array(Image.open(a.map).convert("L")) < 128
    rooms = np.array(Image.open(a.gt).convert("L")) >= 128
    gt_ids, _ = ndimage.label(rooms, structure=np.ones((3, 3), dtype=int))
    palette = np.random.default_rng(3).integers(60, 255, size=(70000, 3)).astype(np.uint8)
    panels = []
    for ids in [gt_ids] + [np.array(Image.open(p)).astype(np.int64) for p in a.labels.split(",")]:
        img = palette[ids % 70000]
        img[ids == 0] = (255, 255, 255)
        img[blocked] = (0, 0, 0)
        outside = ~rooms & ~blocked
        img[outside] = np.minimum(img[outside], 150)
        crop = img[y0:y1, x0:x1]
        panels.append(Image.fromarray(crop).resize((crop.shape[1] * a.scale, crop.shape[0] * a.scale),
                                                   Image.NEAREST))
    gap = 10
    if a.vertical:
        out = Image.new("RGB", (panels[0].width, sum(p.height for p in panels) + gap * (len(panels) - 1)),
                        "white")
        pos = 0
        for p in panels:
            out.paste(p, (0, pos))
            pos += p.height + gap
    else:
        out = Image.new("RGB", (sum(p.width for p in panels) + gap * (len(panels) - 1), panels[0].height),
                        "white")
        pos = 0
        for p in panels:
            out.paste(p, (pos, 0))
            pos += p.width + gap
    out.save(a.out)


if __name__ == "__main__":
    main()
