# voronav.voronoi: generalized Voronoi diagram (seed 003), incremental updates, labeled Voronoi.
from enum import Enum
from typing import Any, Dict, Iterable, List, Tuple

from . import BinaryGrid, FloatGrid, GridGeometry, LabelGrid, Point

class GvdOptions:
    border_is_blocked: bool
    site_separation: float  # [cells]
    site_separation_ratio: float
    thin: bool
    spur_min_length: float  # [m]
    spur_clearance_ratio: float
    prune_rounds: int
    def __init__(self, **kwargs: object) -> None: ...

class GeneralizedVoronoi:
    geometry: GridGeometry
    blocked: BinaryGrid
    clearance: FloatGrid  # [cells]
    obstacle_label: LabelGrid
    raw: BinaryGrid
    diagram: BinaryGrid
    def cells(self) -> List[Tuple[int, int]]: ...

def build_gvd(blocked: BinaryGrid, options: GvdOptions = ...) -> GeneralizedVoronoi: ...

class DynamicGvd:
    geometry: GridGeometry
    def __init__(self, blocked: BinaryGrid, options: GvdOptions = ...) -> None: ...
    def update(self, changes: Iterable[Tuple[Point, bool]]) -> Dict[str, Any]: ...
    def is_voronoi(self, cell: Point) -> bool: ...
    def is_blocked(self, cell: Point) -> bool: ...
    def squared_clearance(self, cell: Point) -> int: ...  # [cells^2], -1 none
    def snapshot(self) -> GeneralizedVoronoi: ...

class CaLabels(Enum):
    obstacle_component = ...
    edge_code = ...

class CaVoronoiOptions:
    border_is_blocked: bool
    labels: CaLabels
    noise_cells_are_sources: bool
    site_separation: float  # [cells]
    site_separation_ratio: float
    thin: bool
    def __init__(self, **kwargs: object) -> None: ...

class LabeledVoronoi:
    edge_code: BinaryGrid  # uint8 codes 1..12
    label: LabelGrid
    time: LabelGrid
    vor: BinaryGrid
    diagram: BinaryGrid
    steps: int

def build_labeled_voronoi(blocked: BinaryGrid, options: CaVoronoiOptions = ...) -> LabeledVoronoi: ...

class VoronoiGraph:
    nodes: List[Dict[str, Any]]  # cell, kind, clearance_m, degree
    node_of: LabelGrid
    def edge_list(self) -> List[Tuple[int, int, Dict[str, Any]]]: ...

def build_voronoi_graph(gvd: GeneralizedVoronoi) -> VoronoiGraph: ...
