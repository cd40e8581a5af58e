# voronav.topology: topological map (seed 003): critical points, regions, graph, planning.
from enum import Enum
from typing import Any, Dict, List, Tuple

from . import BinaryGrid, FloatGrid, GridGeometry, LabelGrid, Point, Vec2
from .voronoi import CaVoronoiOptions, GvdOptions

class DiagramMethod(Enum):
    edt = ...
    ca = ...

class WallOpeningOptions:
    min_width: float  # [m]
    max_width: float  # [m], 0 = off
    min_wall_length: float  # [m]
    max_offset: float  # [m]
    max_angle_deg: float  # [deg]
    fit_tolerance: float  # [m]
    max_wall_thickness: float  # [m]
    wall_ends: bool
    def __init__(self, **kwargs: object) -> None: ...

class TopologyOptions:
    method: DiagramMethod
    gvd: GvdOptions
    ca: CaVoronoiOptions
    min_rise: float  # [m]
    rise_ratio: float
    max_door_width: float  # [m]
    max_rise_walk: float  # [m]
    passage_length: float  # [m]
    passage_rise_ratio: float
    passage_bulges: bool
    min_wall_area: float  # [m^2]
    validate_sides: bool
    room_test_elongation: float
    min_region_area: float  # [m^2]
    regions_absorb_obstacles: float  # [m^2], 0 = off
    wall_openings: WallOpeningOptions
    wall_openings_first: bool
    basis_across: bool  # second basis point across the point (off)
    passage_junctions: bool  # a passage into a junction of narrower branches is cut there (on)
    furniture_line_area: float  # [m^2], 0 = off; a line to a smaller piece hides no opening
    def __init__(self, **kwargs: object) -> None: ...

class CriticalPoint:
    cell: Tuple[int, int]
    basis: Tuple[Tuple[int, int], Tuple[int, int]]
    clearance_m: float
    line: List[Tuple[int, int]]
    midpoint: Tuple[int, int]
    separates: bool
    wall_gap: bool

class Region:
    id: int
    cells: int
    absorbed_cells: int
    area_m2: float
    centre: Tuple[int, int]
    centre_world: Vec2

class TopoPlan:
    status: str  # 'ok', 'start_blocked', 'goal_blocked', 'unreachable'
    ok: bool
    regions: List[int]
    edges: List[int]
    waypoints: List[Tuple[int, int]]
    graph_cost_m: float
    waypoint_length_m: float
    expanded: int

class TopologicalMap:
    geometry: GridGeometry
    blocked: BinaryGrid
    diagram: BinaryGrid
    clearance: FloatGrid  # [cells]
    critical_points: List[CriticalPoint]
    region: LabelGrid
    regions: List[Region]
    def edge_list(self) -> List[Tuple[int, int, Dict[str, Any]]]: ...
    def region_of(self, cell: Point) -> int: ...
    def plan(self, start: Point, goal: Point) -> TopoPlan: ...

def build_topological_map(blocked: BinaryGrid, options: TopologyOptions = ...) -> TopologicalMap: ...
def build_topological_map_from_diagram(blocked: BinaryGrid, diagram: BinaryGrid, options: TopologyOptions = ...) -> TopologicalMap: ...
def segmentation_scores(regions: LabelGrid, rooms: LabelGrid, min_room_cells: int = ...) -> Dict[str, float]: ...
def free_components(blocked: BinaryGrid, eight: bool = ...) -> LabelGrid: ...
