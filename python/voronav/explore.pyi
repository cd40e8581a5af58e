# voronav.explore: swarm exploration (seed 004).
from enum import Enum
from typing import Any, Dict, Optional

from . import OccupancyGrid, Vec2

class Method(Enum):
    tree = ...
    frontier = ...
    coordinated = ...
    tree_frontier = ...

class TreeReplan(Enum):
    none = ...
    robots = ...

class TreeLegReplan(Enum):
    none = ...
    robots = ...

class FrontGuard(Enum):
    cone = ...
    corridor = ...

class AvoidEscape(Enum):
    spin = ...
    corridor = ...

class Table1Variant(Enum):
    paper = ...
    corrected = ...

class ControllerOptions:
    table: Table1Variant
    drive_velocity: float  # [m/s]
    obs_approach: float  # [m/s]
    obs_avoid: float  # [rad/s]
    approach_dist: float  # [m]
    obs_dist: float  # [m]
    desired_wf_dist: float  # [m]
    wall_detect_dist: float  # [m]
    wall_lost_time: float  # [s]
    wall_follow_timeout: float  # [s] (0 = never)
    wf_gain: float  # [rad/s per m]
    random_turn_rate: float  # [rad/s]
    random_period: float  # [s]
    seed: int
    avoid_escape: AvoidEscape
    escape_after_turn: float  # [rad]
    escape_half_width: float  # [m]
    escape_min_length: float  # [m]
    escape_max_length: float  # [m]
    stuck_time: float  # [s] (0 = never)
    stuck_radius: float  # [m]
    def __init__(self, **kwargs: object) -> None: ...

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
    map_beam_stride: int
    tree_replan: TreeReplan
    tree_leg_replan: TreeLegReplan
    hybrid_tree_start_time: float  # [s]
    hybrid_tree_period: float  # [s]
    min_leaf_gain: float
    gain_radius: float  # [m]
    stall_time: float  # [s]
    stall_distance: float  # [m]
    stall_reach_radius: float  # [m] stall rule's reach; 0 = body radius + clearance
    unstick: bool
    frontier_unstick: bool
    idle_unstick: bool  # frontier methods, goalless robots
    disperse_neighbours: bool  # tree: robots without a route near a watchdog-stuck robot move away
    disperse_range: float  # [m]
    clear_way_out: bool  # tree: robots in a watchdog-stuck robot's way out to open space move first (off)
    unstick_retry: bool  # tree: a watchdog-stuck robot plans its unstick again while it has no route (on)
    unstick_retry_period: float  # [s]
    unstick_right_of_way: bool  # tree: a robot on an unstick route goes first at the right of way (on)
    yield_to_held: bool
    retry_banned: bool  # frontier methods
    share_bans: bool  # frontier methods: a reached goal no robot can observe is banned for all
    crowd_limit: int  # frontier: skip a frontier N other robots are at or heading to (0 = off)
    drop_goalless_routes: bool  # frontier methods
    margin_escape: bool  # every method: a watchdog-stuck robot in the planning margin drives out first (on)
    skip_known_leaves: bool  # tree: skip dispatched leaves the team map already knows (off)
    unknown_leaves_first: bool  # tree: drive first to the next dealt leaf that faces unknown space (off)
    nearest_leaf_next: bool  # tree: after figure 9's first round, the pooled leaf nearest along the tree (off)
    frontiers_after_leaves: bool  # tree: coordinated frontier goals once the leaves are done (off)
    gain_through_free: bool  # a target's gain counts only unknown cells it connects to (on)
    guard: FrontGuard  # front guard: cone | corridor (default)
    controller: ControllerOptions  # tree's reactive search
    frontier_controller: ControllerOptions  # frontier methods' reactive windows
    def __init__(self, **kwargs: object) -> None: ...

def run(world: OccupancyGrid, options: Optional[Options] = ..., include_recording: bool = ..., **kwargs: object) -> Dict[str, Any]: ...
def tree_search_controller() -> ControllerOptions: ...
def frontier_window_controller() -> ControllerOptions: ...
def paper_world(resolution: float = ...) -> OccupancyGrid: ...
