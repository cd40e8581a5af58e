# voronav.explore: swarm exploration (seed 004).
from enum import Enum
from typing import Any, Dict, Optional

from . import OccupancyGrid, Vec2

class Method(Enum):
    tree = ...
    frontier = ...
    coordinated = ...

class Options:
    method: Method
    robots: int
    time_limit: float  # [s]
    dt: float  # [s]
    seed: int
    start: Optional[Vec2]
    start_spacing: float  # [m]
    stop_at_coverage: float
    map_period: float  # [s]
    record_period: float  # [s]
    tree_start_time: float  # [s]
    replan_period: float  # [s]
    goal_tolerance: float  # [m]
    clearance: float  # [m]
    min_cell_size: float  # [m]
    def __init__(self, **kwargs: object) -> None: ...

def run(world: OccupancyGrid, options: Optional[Options] = ..., include_recording: bool = ..., **kwargs: object) -> Dict[str, Any]: ...
def paper_world(resolution: float = ...) -> OccupancyGrid: ...
