# voronav.field: exact Euclidean distance transform, inflation, obstacle labels.
from typing import Tuple

from . import BinaryGrid, FloatGrid, LabelGrid

class DistanceField:
    squared_distance: FloatGrid  # [cells^2]
    nearest: LabelGrid  # row-major index of the nearest blocked cell, -1 none
    distance_m: FloatGrid  # [m] (a new grid)

def distance_transform(blocked: BinaryGrid, border_is_blocked: bool = ...) -> DistanceField: ...
def inflate(blocked: BinaryGrid, radius_m: float) -> BinaryGrid: ...
def label_obstacles(blocked: BinaryGrid) -> Tuple[LabelGrid, int]: ...
