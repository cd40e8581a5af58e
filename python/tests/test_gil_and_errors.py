"""The GIL is released in long C++ calls; C++ errors arrive as voronav.Error with their message."""

from __future__ import annotations

import threading

import numpy as np
import pytest

import voronav as vn


def test_second_thread_progresses_during_a_long_call(data):
    grid = vn.binarize(vn.io.load_movingai_map(str(data / "movingai/den312d.map")))
    big = vn.BinaryGrid(np.kron(grid.array, np.ones((8, 8), dtype=np.uint8)))  # 520 x 520 cells
    free = np.argwhere(big.array == 0)
    start, goal = tuple(int(v) for v in free[0][::-1]), tuple(int(v) for v in free[-1][::-1])
    planner = vn.Planner("dijkstra")
    ticks = 0
    stop = threading.Event()
    started = threading.Event()

    def spin():
        nonlocal ticks
        started.set()
        while not stop.is_set():
            ticks += 1

    t = threading.Thread(target=spin)
    t.start()
    started.wait()
    during = []
    for _ in range(3):
        before = ticks  # this thread holds the GIL here, so `ticks` is not moving
        r = planner.plan(big, start, goal)
        during.append(ticks - before)
    stop.set()
    t.join()
    assert r.status in ("ok", "unreachable") and r.expanded > 10000
    # With the GIL held for the whole call the other thread could not count at all.
    assert max(during) > 1000, during


def test_one_planner_shared_by_threads_gives_sequential_results(data):
    grid = vn.binarize(vn.io.load_movingai_map(str(data / "movingai/den312d.map")))
    queries = vn.io.load_movingai_scen(str(data / "movingai/den312d.map.scen"))[::40]
    planner = vn.Planner("astar")
    expected = [planner.plan(grid, q.start_cell, q.goal_cell).length_cells for q in queries]
    got: dict[int, list[float]] = {0: [], 1: []}

    def work(k: int) -> None:
        for q in queries:
            got[k].append(planner.plan(grid, q.start_cell, q.goal_cell).length_cells)

    threads = [threading.Thread(target=work, args=(k,)) for k in (0, 1)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert got[0] == expected and got[1] == expected


def test_error_messages_name_file_and_line(tmp_path):
    missing = tmp_path / "nope.yaml"
    with pytest.raises(vn.Error, match=f"{missing}: map file not found"):
        vn.io.load_map(str(missing))
    bad = tmp_path / "bad.yaml"
    bad.write_text("image: x.pgm\nresolution: abc\norigin: [0, 0, 0]\n")
    with pytest.raises(vn.Error, match=r"bad\.yaml:2: .*resolution"):
        vn.io.read_ros_map(str(bad))
    txt = tmp_path / "map.txt"
    txt.write_text("not a map\n")
    with pytest.raises(vn.Error, match=r"map\.txt: .*\.yaml"):  # names the accepted extensions
        vn.io.load_map(str(txt))


def test_ros_map_roundtrip(tmp_path, data):
    grid, meta = vn.io.read_ros_map(str(data / "ros_maps/turtlebot3_world/map.yaml"))
    assert meta.resolution == grid.resolution
    out = tmp_path / "copy.yaml"
    image = vn.io.save_ros_map(grid, str(out))
    assert image.endswith(".pgm")
    back = vn.io.load_ros_map(str(out))
    assert back == grid
    assert np.array_equal(back.array, grid.array) and back.origin == grid.origin


def test_movingai_roundtrip(tmp_path, data):
    g = vn.io.load_movingai_map(str(data / "movingai/arena.map"))
    vn.io.save_movingai_map(g, str(tmp_path / "a.map"))
    assert vn.io.load_movingai_map(str(tmp_path / "a.map")) == g
    q = vn.io.load_movingai_scen(str(data / "movingai/arena.map.scen"))
    vn.io.save_movingai_scen(q[:5], str(tmp_path / "a.map.scen"))
    back = vn.io.load_movingai_scen(str(tmp_path / "a.map.scen"))
    assert [(b.start_x, b.goal_y, b.optimal_length) for b in back] == [(a.start_x, a.goal_y, a.optimal_length) for a in q[:5]]
    assert vn.io.map_format(str(data / "movingai/arena.map")) == "movingai"
