#!/usr/bin/env python3
"""Loads a ROS map, plans with a robot radius, builds the topological map, plots both.

    PYTHONPATH=build/default/python /usr/bin/python3 examples/python/ros_map_topology.py \
        [--map data/ros_maps/turtlebot3_world/map.yaml] [--out plan_topology.png]

Coordinates are world metres (REP-103) given as voronav.Vec2; arrays index [y, x] with row 0 at
the bottom, hence origin="lower" and the map's extent in metres for imshow.
"""

from __future__ import annotations

import argparse
import pathlib

import matplotlib

matplotlib.use("Agg")  # files only; remove for an interactive window
import matplotlib.pyplot as plt
import numpy as np

import voronav as vn

ROOT = pathlib.Path(__file__).resolve().parents[2]


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--map", default=str(ROOT / "data/ros_maps/turtlebot3_world/map.yaml"))
    ap.add_argument("--start", type=float, nargs=2, default=(-1.9, -0.5), help="world [m]")
    ap.add_argument("--goal", type=float, nargs=2, default=(1.9, 0.5), help="world [m]")
    ap.add_argument("--radius", type=float, default=0.1, help="robot radius [m]")
    ap.add_argument("--out", default="plan_topology.png")
    a = ap.parse_args()

    grid = vn.io.load_ros_map(a.map)
    result = vn.plan(grid, vn.Vec2(*a.start), vn.Vec2(*a.goal), planner="astar", robot_radius=a.radius)
    print(result)
    topo = vn.topology.build_topological_map(vn.binarize(grid))
    print(topo)

    # imshow extent in metres (origin yaw 0, as map_server maps have).
    ox, oy, _ = grid.origin
    extent = (ox, ox + grid.width * grid.resolution, oy, oy + grid.height * grid.resolution)
    occ = np.where(grid.array < 0, 0.8, 1.0 - grid.array / 100.0)
    fig, axes = plt.subplots(1, 2, figsize=(11, 5))
    ax = axes[0]
    ax.imshow(occ, cmap="gray", vmin=0, vmax=1, origin="lower", extent=extent)
    if result.ok:
        ax.plot(result.path_m[:, 0], result.path_m[:, 1], "r-", lw=2,
                label=f"A*, radius {a.radius} m: {result.length_m:.2f} m")
    ax.plot(*a.start, "go")
    ax.plot(*a.goal, "bs")
    ax.set_title(f"plan: {result.status}")
    ax.legend(loc="lower left")
    ax = axes[1]
    regions = np.ma.masked_less(topo.region.array, 0)
    ax.imshow(occ, cmap="gray", vmin=0, vmax=1, origin="lower", extent=extent)
    ax.imshow(regions, cmap="tab20", alpha=0.6, origin="lower", extent=extent, interpolation="nearest")
    for cp in topo.critical_points:
        p, q = grid.cell_center(cp.line[0]), grid.cell_center(cp.line[-1])
        ax.plot([p.x, q.x], [p.y, q.y], "k-", lw=1)
    centres = {r.id: r.centre_world for r in topo.regions}
    for u, v, _ in topo.edge_list():  # networkx.Graph().add_edges_from(topo.edge_list()) works too
        ax.plot([centres[u].x, centres[v].x], [centres[u].y, centres[v].y], "b-", lw=1)
    ax.set_title(f"{len(topo.regions)} regions, {len(topo.critical_points)} critical points")
    known = np.argwhere(grid.array >= 0)  # crop to the known part of the map
    (y0, x0), (y1, x1) = known.min(axis=0), known.max(axis=0) + 1
    for ax in axes:
        ax.set_xlim(ox + x0 * grid.resolution, ox + x1 * grid.resolution)
        ax.set_ylim(oy + y0 * grid.resolution, oy + y1 * grid.resolution)
        ax.set_xlabel("x [m]")
        ax.set_ylabel("y [m]")
    fig.tight_layout()
    fig.savefig(a.out, dpi=110)
    print(f"wrote {a.out}")


if __name__ == "__main__":
    main()
