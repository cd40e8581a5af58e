# Type stubs of the voronav package (the C++ extension voronav._voronav). Units in comments.
from typing import Iterator, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

from . import coordination as coordination
from . import explore as explore
from . import field as field
from . import io as io
from . import mapping as mapping
from . import netsim as netsim
from . import planning as planning
from . import render as render
from . import topology as topology
from . import voronoi as voronoi
from .planning import Planner as Planner
from .planning import plan as plan
from .planning import planner_names as planner_names

__version__: str

class Error(ValueError):
    """A C++ voronav::Error: 'file:line: what was expected'."""

class Vec2:
    """A world point or vector [m], x forward / y left (REP-103)."""
    x: float
    y: float
    def __init__(self, x: float = ..., y: float = ...) -> None: ...
    def __iter__(self) -> Iterator[float]: ...

class Pose2:
    """Position [m] and heading yaw [rad, counter-clockwise from +x]."""
    x: float
    y: float
    yaw: float
    def __init__(self, x: float = ..., y: float = ..., yaw: float = ...) -> None: ...
    def __iter__(self) -> Iterator[float]: ...

PoseLike = Union[Pose2, Tuple[float, float], Tuple[float, float, float]]
Cell = Tuple[int, int]
Point = Union[Cell, Sequence[int], Vec2]
"""A cell (x, y) of ints, or a voronav.Vec2 world point [m]."""

class GridGeometry:
    width: int
    height: int
    resolution: float  # [m/cell]
    origin: Pose2  # world pose of cell (0, 0)'s lower-left corner
    def __init__(self, width: int, height: int, resolution: float = ..., origin: PoseLike = ...) -> None: ...
    def cell_center(self, cell: Point) -> Vec2: ...

class _Grid:
    width: int  # [cells]
    height: int  # [cells]
    shape: Tuple[int, int]  # (height, width)
    resolution: float  # [m/cell]
    origin: Pose2
    geometry: GridGeometry
    def contains(self, point: Point) -> bool: ...
    def cell_center(self, cell: Point) -> Vec2: ...
    def world_to_cell(self, point: Vec2) -> Cell: ...
    def __eq__(self, other: object) -> bool: ...

class OccupancyGrid(_Grid):
    """0 free, 100 occupied, 1..99 probability [%], -1 unknown (int8)."""
    def __init__(self, array: npt.ArrayLike | int, resolution: float | int = ..., origin: PoseLike | int = ..., *args: object) -> None: ...
    @property
    def array(self) -> npt.NDArray[np.int8]: """Zero-copy view (height, width); arr[y, x] is cell (x, y)."""
    def __getitem__(self, p: Point) -> int: ...
    def __setitem__(self, p: Point, v: int) -> None: ...
    def copy(self) -> OccupancyGrid: ...

class BinaryGrid(_Grid):
    """1 blocked, 0 free (uint8)."""
    def __init__(self, array: npt.ArrayLike | int, resolution: float | int = ..., origin: PoseLike | int = ..., *args: object) -> None: ...
    @property
    def array(self) -> npt.NDArray[np.uint8]: ...
    def __getitem__(self, p: Point) -> int: ...
    def __setitem__(self, p: Point, v: int) -> None: ...
    def copy(self) -> BinaryGrid: ...

class FloatGrid(_Grid):
    """float32 field per cell (distances: see the producing function for the unit)."""
    def __init__(self, array: npt.ArrayLike | int, resolution: float | int = ..., origin: PoseLike | float = ..., *args: object) -> None: ...
    @property
    def array(self) -> npt.NDArray[np.float32]: ...
    def __getitem__(self, p: Point) -> float: ...
    def __setitem__(self, p: Point, v: float) -> None: ...
    def copy(self) -> FloatGrid: ...

class LabelGrid(_Grid):
    """int32 label per cell, -1 = none."""
    def __init__(self, array: npt.ArrayLike | int, resolution: float | int = ..., origin: PoseLike | int = ..., *args: object) -> None: ...
    @property
    def array(self) -> npt.NDArray[np.int32]: ...
    def __getitem__(self, p: Point) -> int: ...
    def __setitem__(self, p: Point, v: int) -> None: ...
    def copy(self) -> LabelGrid: ...

def binarize(grid: OccupancyGrid, occupied_threshold: int = ..., unknown_is_blocked: bool = ...) -> BinaryGrid: ...
