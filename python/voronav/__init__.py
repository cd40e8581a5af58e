"""voronav: grid maps, Voronoi/topological maps, single- and multi-robot planning (C++ bindings).

Grids are numpy-compatible: ``grid.array`` (and ``np.asarray(grid)``) is a zero-copy view of shape
(height, width) where ``arr[y, x]`` is cell (x, y) and row 0 is the *bottom* row of the map (plot
with ``origin="lower"``). Points are cells ``(x, y)`` (ints) or world points ``voronav.Vec2(x, y)``
in metres (REP-103: x forward, y left; the grid origin is the world pose of cell (0, 0)'s
lower-left corner). Errors raise ``voronav.Error`` (a ``ValueError``) with the C++ message
(file:line: what was expected); expected outcomes (no path, invalid schedule) are returned as
status. See docs/python.md.
"""

from __future__ import annotations

from . import _voronav
from ._voronav import (
    BinaryGrid,
    Error,
    FloatGrid,
    GridGeometry,
    LabelGrid,
    OccupancyGrid,
    Pose2,
    Vec2,
    binarize,
    coordination,
    explore,
    field,
    io,
    mapping,
    netsim,
    planning,
    render,
    topology,
    voronoi,
)

import sys as _sys

# `import voronav.planning` and `from voronav.io import load_map` work like real subpackages.
for _name in ("io", "planning", "field", "voronoi", "topology", "mapping", "coordination",
              "netsim", "explore", "render"):
    _sys.modules[f"{__name__}.{_name}"] = getattr(_voronav, _name)

Planner = planning.Planner
plan = planning.plan
planner_names = planning.planner_names

__all__ = [
    "BinaryGrid",
    "Error",
    "FloatGrid",
    "GridGeometry",
    "LabelGrid",
    "OccupancyGrid",
    "Planner",
    "Pose2",
    "Vec2",
    "binarize",
    "coordination",
    "explore",
    "field",
    "io",
    "mapping",
    "netsim",
    "plan",
    "planner_names",
    "planning",
    "render",
    "topology",
    "voronoi",
]

__version__ = "0.1.0"
