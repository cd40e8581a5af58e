# voronav.planning: grid planners by name, RAS (seed 001) with its regions.
from enum import Enum
from typing import Dict, List, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

from . import BinaryGrid, LabelGrid, OccupancyGrid, Point
from .topology import TopologyOptions

class PlanResult:
    status: str  # 'ok', 'start_occupied', 'goal_occupied', 'out_of_map', 'unreachable', 'cancelled'
    ok: bool
    planner: str
    path: npt.NDArray[np.int32]  # (N, 2) cells
    path_m: npt.NDArray[np.float64]  # (N, 2) cell centres [m]
    length_cells: float  # octile [cells]
    length_m: float  # [m]
    expanded: int
    time_ms: float  # [ms]
    expanded_cells: npt.NDArray[np.int32]
    def __bool__(self) -> bool: ...

class RegionRule(Enum):
    any_blocked = ...
    majority_blocked = ...

class RasDirection(Enum):
    default = ...
    optimal = ...
    optimal_per_region = ...

class RasExtent(Enum):
    until_goal = ...
    whole_map = ...

class RasStartDensity(Enum):
    exempt = ...
    enforced = ...

class RasCornerRule(Enum):
    no_corner_cutting = ...
    allow_corner_cutting = ...

class RasOptions:
    region_size: int  # [cells]
    region_rule: RegionRule
    density: int  # 0..8
    direction: RasDirection
    connectivity: int  # 4 or 8
    extent: RasExtent
    start_density: RasStartDensity
    corner_rule: RasCornerRule
    def __init__(self, **kwargs: object) -> None: ...

class RasResult:
    status: str
    ok: bool
    regions: int
    steps: int
    region_size: int  # [cells]
    path_ids: List[int]
    path_regions: npt.NDArray[np.int32]
    waypoints: npt.NDArray[np.float64]  # [m]
    path: npt.NDArray[np.int32]
    path_m: npt.NDArray[np.float64]
    length_cells: float
    ids: LabelGrid  # id >= 0, -1 obstacle, -2 below density, -3 not numbered
    region_blocked: BinaryGrid
    time_ms: float

class Planner:
    name: str
    def __init__(self, name: str = ..., connectivity: int = ..., robot_radius: float = ..., record_expanded: bool = ...,
                 ras: Optional[RasOptions] = ..., topology: Optional[TopologyOptions] = ...) -> None: ...
    def plan(self, grid: BinaryGrid, start: Point, goal: Point) -> PlanResult: ...

def planner_names() -> List[str]: ...
def make_planning_grid(blocked: BinaryGrid, robot_radius: float) -> BinaryGrid: ...
def plan(map: Union[OccupancyGrid, BinaryGrid], start: Point, goal: Point, planner: str = ..., robot_radius: float = ...,
         connectivity: int = ..., ras: Optional[RasOptions] = ...) -> PlanResult: ...
def octile_distance(a: Point, b: Point) -> float: ...
def is_valid_path(grid: BinaryGrid, path: Sequence[Tuple[int, int]], connectivity: int = ...) -> bool: ...
def plan_ras(grid: BinaryGrid, start: Point, goal: Point, ras: RasOptions = ...) -> RasResult: ...
def ras_parameters_for_robot(robot_size: float, resolution: float, density: int = ...) -> Dict[str, int]: ...
