# voronav.netsim: networked robots finding a route (seed 000).
from enum import Enum
from typing import Any, Dict, List, Optional, Sequence, Tuple

from . import OccupancyGrid, Vec2

class Method(Enum):
    centralized = ...
    decentralized = ...

class Scenario:
    world: OccupancyGrid
    robots: List[Vec2]
    source: int
    destination: Vec2
    changes: int
    def __init__(self, world: OccupancyGrid, robots: Sequence[Tuple[float, float]], destination: Tuple[float, float], source: int = ...) -> None: ...

class Options:
    method: Method
    sensing_range_m: float
    speed_mps: float
    robot_radius_m: float
    dt_s: float
    time_limit_s: float
    radio_range_m: float
    radio_loss: float
    path_wait_s: float
    bridge_wait_s: float
    search_timeout_s: float
    max_search_attempts: int
    hop_limit: int
    repair_hops: int
    repair_expand_hops: int
    repair_fix_seen_only: bool
    repair_walk_keep_ratio: float
    repair_sense_walk: bool  # a relay walks to sense the break of a Repair (on since stop 28)
    repair_sense_wait_s: float
    collect_s: float
    repair_timeout_s: float
    seed: int
    record: bool
    def __init__(self, **kwargs: object) -> None: ...
    def scale_options(self) -> Options: ...

def paper_run(scenario: int, run: int, seed: int = ...) -> Scenario: ...
def load_scenario(path: str) -> Tuple[Scenario, Options]: ...
def run(scenario: Scenario, options: Optional[Options] = ..., **kwargs: object) -> Dict[str, Any]: ...
