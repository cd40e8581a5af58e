"""Grid types: dtype, shape, strides, zero-copy views, geometry (resolution, origin), points."""

from __future__ import annotations

import gc
import math

import numpy as np
import pytest

import voronav as vn


@pytest.mark.parametrize(
    "cls, dtype",
    [(vn.OccupancyGrid, np.int8), (vn.BinaryGrid, np.uint8), (vn.FloatGrid, np.float32), (vn.LabelGrid, np.int32)],
)
def test_dtype_shape_strides(cls, dtype):
    g = cls(5, 3, resolution=0.1)
    a = g.array
    assert a.dtype == dtype
    assert a.shape == (3, 5) == g.shape
    assert a.strides == (5 * a.itemsize, a.itemsize)
    assert a.flags["C_CONTIGUOUS"]
    b = np.asarray(g)  # buffer protocol
    assert b.dtype == dtype and b.shape == (3, 5)
    assert np.shares_memory(a, b)


def test_array_roundtrip_and_cell_order():
    arr = np.zeros((4, 6), dtype=np.int8)
    arr[1, 2] = 100  # row y=1, column x=2
    g = vn.OccupancyGrid(arr, resolution=0.05, origin=(1.0, -2.0, 0.0))
    assert g[(2, 1)] == 100 and g[(1, 2)] == 0
    assert g.width == 6 and g.height == 4
    assert g.resolution == pytest.approx(0.05)
    assert tuple(g.origin) == (1.0, -2.0, 0.0)
    # The input is copied once; the grid's own view is zero-copy.
    assert not np.shares_memory(arr, g.array)
    view = g.array
    view[3, 5] = -1
    assert g[(5, 3)] == -1
    assert np.shares_memory(view, g.array)


def test_world_and_cells_rep103():
    g = vn.OccupancyGrid(10, 10, resolution=0.5, origin=vn.Pose2(-1.0, 2.0, 0.0))
    c = g.cell_center((0, 0))
    assert (c.x, c.y) == pytest.approx((-0.75, 2.25))
    assert g.world_to_cell(vn.Vec2(0.2, 3.1)) == (2, 2)
    assert g[vn.Vec2(0.2, 3.1)] == g[(2, 2)]
    # A rotated origin (yaw = 90 deg): cell x runs along world +y.
    r = vn.OccupancyGrid(4, 4, resolution=1.0, origin=(0.0, 0.0, math.pi / 2))
    p = r.cell_center((1, 0))
    assert (p.x, p.y) == pytest.approx((-0.5, 1.5))


def test_result_views_are_zero_copy_and_keep_owner_alive():
    b = np.zeros((20, 30), dtype=np.uint8)
    b[10, 15] = 1
    df = vn.field.distance_transform(vn.BinaryGrid(b))
    sq = df.squared_distance
    v1, v2 = sq.array, df.squared_distance.array
    assert v1.dtype == np.float32 and v1.shape == (20, 30)
    assert np.shares_memory(v1, v2)  # both views look into the C++ result
    assert v1[10, 15] == 0.0 and v1[10, 18] == pytest.approx(9.0)
    del df, sq
    gc.collect()
    assert v1[10, 18] == pytest.approx(9.0)  # the view keeps the result alive
    near = vn.field.distance_transform(vn.BinaryGrid(b)).nearest.array
    assert near.dtype == np.int32 and near[0, 0] == 10 * 30 + 15


def test_repr_shows_what_it_is():
    g = vn.OccupancyGrid(7, 3, resolution=0.05)
    assert repr(g) == "OccupancyGrid(7x3 cells, 0.05 m/cell, origin (0, 0, 0))"
    assert "Vec2(1.5, 2)" == repr(vn.Vec2(1.5, 2.0))


def test_bad_input_raises_with_message():
    with pytest.raises(vn.Error, match="expected a 2-D array"):
        vn.OccupancyGrid(np.zeros(5, dtype=np.int8))
    with pytest.raises(vn.Error, match="resolution must be a positive"):
        vn.OccupancyGrid(np.zeros((2, 2), dtype=np.int8), resolution=0.0)
    g = vn.BinaryGrid(3, 3)
    with pytest.raises(vn.Error, match=r"cell \(5, 1\) is outside the 3x3 grid"):
        g[(5, 1)]
    with pytest.raises(vn.Error, match="use voronav.Vec2"):
        g[(1.5, 1.0)]
    assert issubclass(vn.Error, ValueError)


def test_binarize():
    g = vn.OccupancyGrid(np.array([[0, 100, -1, 60]], dtype=np.int8))
    assert list(vn.binarize(g).array[0]) == [0, 1, 1, 1]
    assert list(vn.binarize(g, occupied_threshold=70, unknown_is_blocked=False).array[0]) == [0, 1, 0, 0]
