"""Planning from Python equals the C++ library / CLI on the same inputs; statuses are returned."""

from __future__ import annotations

import math

import numpy as np
import pytest

import voronav as vn


def test_planner_names_from_factory():
    names = vn.planner_names()
    assert {"astar", "dijkstra", "ras", "topo"} <= set(names)
    for n in names:
        assert vn.Planner(n).name == n


def test_movingai_scenario_matches_optimal_and_cli(data, cli):
    grid = vn.io.load_movingai_map(str(data / "movingai/arena.map"))
    queries = vn.io.load_movingai_scen(str(data / "movingai/arena.map.scen"))
    assert len(queries) > 100
    blocked = vn.binarize(grid)
    planner = vn.Planner("astar")
    lengths = []
    for q in queries:
        r = planner.plan(blocked, q.start_cell, q.goal_cell)
        assert r.ok, q
        assert abs(r.length_cells - q.optimal_length) <= q.optimal_rounding + 1e-6, q
        assert vn.planning.is_valid_path(blocked, [tuple(c) for c in r.path])
        lengths.append(r.length_cells)
    out = cli("scen", "--map", str(data / "movingai/arena.map"), "--scen", str(data / "movingai/arena.map.scen"))
    assert out["queries"] == len(lengths) and out["mismatches"] == 0 and out["unsolved"] == 0
    # Per query: the CLI's `plan` (Moving AI file coordinates, y down) gives the same path.
    for q, length in list(zip(queries, lengths))[:: len(queries) // 4]:
        one = cli("plan", "--map", str(data / "movingai/arena.map"), "--start", f"{q.start_x},{q.start_y}",
                  "--goal", f"{q.goal_x},{q.goal_y}")
        assert one["cells"] == pytest.approx(length, abs=1e-9)
        r = planner.plan(blocked, q.start_cell, q.goal_cell)
        assert one["expanded"] == r.expanded


def test_plan_result_cells_metres_and_status(data):
    yaml = data / "ros_maps/turtlebot3_world/map.yaml"
    grid = vn.io.load_ros_map(str(yaml))
    r = vn.plan(grid, vn.Vec2(-1.9, -0.5), vn.Vec2(1.9, 0.5), robot_radius=0.1)
    assert r.ok and r.status == "ok"
    assert r.path.dtype == np.int32 and r.path.shape[1] == 2
    assert r.path_m.dtype == np.float64 and r.path_m.shape == r.path.shape
    assert r.length_m == pytest.approx(r.length_cells * grid.resolution)
    start = grid.cell_center(tuple(r.path[0]))
    assert math.hypot(start.x + 1.9, start.y + 0.5) <= grid.resolution
    assert r.expanded > 0
    assert "PlanResult(astar, ok" in repr(r)


def test_statuses_are_returned_not_raised():
    b = np.zeros((10, 10), dtype=np.uint8)
    b[:, 5] = 1
    g = vn.BinaryGrid(b)
    assert vn.Planner().plan(g, (0, 0), (9, 9)).status == "unreachable"
    assert vn.Planner().plan(g, (5, 0), (9, 9)).status == "start_occupied"
    assert vn.Planner().plan(g, (0, 0), (5, 3)).status == "goal_occupied"
    r = vn.Planner().plan(g, (0, 0), (20, 3))
    assert r.status == "out_of_map" and not r and len(r.path) == 0


def test_dijkstra_equals_astar_length():
    rng = np.random.default_rng(3)
    b = (rng.random((60, 80)) < 0.2).astype(np.uint8)
    b[0, 0] = b[59, 79] = 0
    g = vn.BinaryGrid(b)
    a = vn.Planner("astar").plan(g, (0, 0), (79, 59))
    d = vn.Planner("dijkstra").plan(g, (0, 0), (79, 59))
    assert a.status == d.status
    if a.ok:
        assert a.length_cells == pytest.approx(d.length_cells)
        assert d.expanded >= a.expanded


def test_unknown_planner_error_message():
    with pytest.raises(vn.Error, match="unknown planner 'jps2'; expected one of"):
        vn.Planner("jps2")
    with pytest.raises(vn.Error, match="connectivity: expected 4 or 8, got 6"):
        vn.Planner("astar", connectivity=6)


def test_ras_regions():
    b = np.zeros((32, 32), dtype=np.uint8)
    b[8:24, 16] = 1
    g = vn.BinaryGrid(b)
    opts = vn.planning.RasOptions(region_size=2, density=0, direction="optimal")
    r = vn.planning.plan_ras(g, (2, 16), (30, 16), opts)
    assert r.ok
    ids = r.ids.array
    assert ids.shape == (16, 16) and ids.dtype == np.int32
    assert int((ids >= 0).sum()) == r.regions
    assert r.path_ids[0] == 0 and len(r.path_ids) == len(r.path_regions)
    assert r.waypoints.shape[1] == 2
    # The GridPlanner face of RAS gives the same dense path.
    p = vn.Planner("ras", ras=opts).plan(g, (2, 16), (30, 16))
    assert np.array_equal(p.path, r.path)
    with pytest.raises(vn.Error, match="density"):
        vn.planning.RasOptions(density=9)
    with pytest.raises(vn.Error, match="unknown option 'densty'"):
        vn.planning.RasOptions(densty=2)


def test_topological_planner_by_name(data):
    grid = vn.io.load_floorplan(str(data / "floorplans/office_a.png"), free_from=250, occupied_below=250)
    blocked = vn.binarize(grid)
    free = np.argwhere(blocked.array == 0)
    s, g = tuple(int(v) for v in free[0][::-1]), tuple(int(v) for v in free[-1][::-1])
    r = vn.Planner("topo").plan(blocked, s, g)
    a = vn.Planner("astar").plan(blocked, s, g)
    assert r.status == a.status
    if r.ok:
        assert r.length_cells >= a.length_cells - 1e-9
