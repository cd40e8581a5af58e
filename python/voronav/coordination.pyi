# voronav.coordination: start delays for robots on fixed paths (seed 002).
from enum import Enum
from typing import Any, Dict, List, Optional, Sequence, Tuple

import numpy as np
import numpy.typing as npt

from . import OccupancyGrid, Vec2

class AtStart(Enum):
    wait = ...
    appear = ...

class AtGoal(Enum):
    stay = ...
    leave = ...

class Agent:
    id: int
    radius: float  # [m]
    path: npt.NDArray[np.float64]  # (N, 2) [m]
    v_max: float  # [m/s]
    a_max: float  # [m/s^2]
    length: float  # [m]
    travel_time: float  # [s]
    def __init__(self, id: int, path: Sequence[Tuple[float, float]], radius: float = ..., v_max: float = ..., a_max: float = ...) -> None: ...
    def position(self, t: float) -> Vec2: ...

class Scenario:
    robots: int
    map: Optional[OccupancyGrid]
    node_spacing: float  # [m]
    at_start: AtStart
    at_goal: AtGoal
    def __init__(self, robots: List[Dict[str, Any]], map: Optional[OccupancyGrid] = ..., cell_coordinates: bool = ...,
                 node_spacing: float = ..., at_start: AtStart | str = ..., at_goal: AtGoal | str = ...) -> None: ...
    def plan_agents(self) -> List[Agent]: ...

class CoordinationResult:
    status: str
    ok: bool
    message: str
    order: List[int]
    order_ids: List[int]
    ids: List[int]
    delays: List[float]  # [s]
    arrivals: List[float]  # [s]
    makespan: float  # [s]
    sum_of_arrivals: float  # [s]
    valid: bool
    verified: bool
    repairs: int
    missed: List[Dict[str, Any]]
    remaining: List[Dict[str, Any]]
    boxes: int
    evaluations: int
    time_ms: float
    agents: List[Agent]
    def to_json(self) -> str: ...
    def save(self, path: str) -> None: ...

def load_scenario(path: str) -> Scenario: ...
def load_mapf(map: str, scen: str, agents: int, radius: float = ...) -> Scenario: ...
def coordinate(agents: List[Agent], search: str = ..., seed: int = ..., edf_reduction: bool = ..., node_spacing: float = ...,
               at_start: AtStart | str = ..., at_goal: AtGoal | str = ..., verify: bool = ...,
               ga_preset: str = ...) -> CoordinationResult: ...
def verify_schedule(agents: List[Agent], delays: Sequence[float], at_start: AtStart | str = ..., at_goal: AtGoal | str = ...,
                    tolerance: float = ...) -> Dict[str, Any]: ...
def read_schedule(path: str) -> Dict[str, Any]: ...
