"""field / voronoi / topology: equal to the CLI on a floor plan; DynamicGvd equals a rebuild."""

from __future__ import annotations

import numpy as np
import pytest

import voronav as vn


def office(data):
    # The CLI's `topo` reads images with free_from = occupied_below = 250.
    return vn.io.load_floorplan(str(data / "floorplans/office_a.png"), resolution=0.05, free_from=250,
                                occupied_below=250)


def test_floorplan_regions_equal_cli(data, cli):
    blocked = vn.binarize(office(data))
    topo = vn.topology.build_topological_map(blocked)
    out = cli("topo", "--map", str(data / "floorplans/office_a.png"))
    assert len(topo.regions) == out["regions"] > 1
    assert len(topo.critical_points) == len(out["critical_points"])
    assert int((topo.diagram.array != 0).sum()) == out["voronoi_cells"]
    labels = topo.region.array
    assert labels.dtype == np.int32 and labels.shape == blocked.shape
    assert set(np.unique(labels[labels >= 0])) == set(range(len(topo.regions)))
    assert (labels[blocked.array == 1] == -1).all()
    edges = topo.edge_list()
    assert [(a, b) for a, b, _ in edges] == [(e["a"], e["b"]) for e in out["graph"]["edges"]]
    for a, b, attrs in edges:  # networkx: Graph().add_edges_from(edges)
        assert isinstance(a, int) and isinstance(b, int) and attrs["weight"] == attrs["length_m"] > 0
    cp = topo.critical_points[0]
    assert len(cp.line) > 0 and cp.clearance_m > 0


def test_critical_line_options_equal_cli(data, cli):
    # The passage and room-test options of seed 003's critical lines (docs/reproductions/topology.md)
    # give the same regions from Python as from the CLI, and change the regions of this plan.
    blocked = vn.binarize(office(data))
    opts = vn.topology.TopologyOptions(passage_length=1.5, passage_rise_ratio=0.5, validate_sides=True,
                                       room_test_elongation=2.0)
    assert opts.passage_length == 1.5 and opts.passage_rise_ratio == 0.5 and opts.validate_sides
    assert opts.room_test_elongation == 2.0
    topo = vn.topology.build_topological_map(blocked, opts)
    out = cli("topo", "--map", str(data / "floorplans/office_a.png"), "--passage-length", "1.5",
              "--passage-rise-ratio", "0.5", "--validate-sides", "true", "--room-test-elongation", "2")
    assert len(topo.regions) == out["regions"]
    assert len(topo.critical_points) == len(out["critical_points"])
    classic = vn.topology.build_topological_map(
        blocked, vn.topology.TopologyOptions(passage_length=0.0, validate_sides=False))
    assert len(classic.critical_points) != len(topo.critical_points)
    assert vn.topology.TopologyOptions().passage_bulges  # on by default, settable
    assert not vn.topology.TopologyOptions(passage_bulges=False).passage_bulges
    assert not vn.topology.TopologyOptions().basis_across  # off by default, settable
    assert vn.topology.TopologyOptions(basis_across=True).basis_across


def test_rise_options_equal_cli(data, cli):
    # The classic rule's rise (`--rise-ratio`, `--min-rise`, stop 27): the same regions and critical
    # points from Python as from the CLI, and the old ratio 0.25 cuts the furnished plan's corridor
    # between its benches again (docs/reproductions/topology.md, "The rise ratio").
    plan = str(data / "floorplans/lab_ipa_furnitures.png")
    blocked = vn.binarize(vn.io.load_floorplan(plan, resolution=0.05, free_from=250, occupied_below=250))
    assert vn.topology.TopologyOptions().rise_ratio == pytest.approx(0.3)
    default = cli("topo", "--map", plan)
    for args, kwargs in ((("--rise-ratio", "0.25"), {"rise_ratio": 0.25}),
                         (("--min-rise", "0.6"), {"min_rise": 0.6})):
        topo = vn.topology.build_topological_map(blocked, vn.topology.TopologyOptions(**kwargs))
        out = cli("topo", "--map", plan, *args)
        assert len(topo.regions) == out["regions"], args
        assert len(topo.critical_points) == len(out["critical_points"]), args
        assert len(out["critical_points"]) != len(default["critical_points"]), args


def test_wall_openings_equal_cli(data, cli):
    # Openings in wall lines (on by default): NLB's open room fronts and wall stubs give wall-gap
    # critical lines; the same from Python as from the CLI; none when turned off.
    blocked = vn.binarize(vn.io.load_floorplan(str(data / "floorplans/NLB.png"), resolution=0.05,
                                               free_from=250, occupied_below=250))
    topo = vn.topology.build_topological_map(blocked)
    out = cli("topo", "--map", str(data / "floorplans/NLB.png"))
    assert len(topo.regions) == out["regions"]
    walls = sum(cp.wall_gap for cp in topo.critical_points)
    assert walls == sum(cp["source"] == "wall_gap" for cp in out["critical_points"]) and walls > 0
    off = vn.topology.TopologyOptions(wall_openings=vn.topology.WallOpeningOptions(max_width=0.0))
    assert off.wall_openings.max_width == 0.0
    assert not any(cp.wall_gap for cp in vn.topology.build_topological_map(blocked, off).critical_points)


def test_topo_plan_status_returned(data):
    blocked = vn.binarize(office(data))
    topo = vn.topology.build_topological_map(blocked)
    wall = tuple(int(v) for v in np.argwhere(blocked.array == 1)[0][::-1])
    free = tuple(int(v) for v in np.argwhere(blocked.array == 0)[0][::-1])
    assert topo.plan(wall, free).status == "start_blocked"
    c0 = topo.regions[0].centre
    c1 = topo.regions[-1].centre
    p = topo.plan(c0, c1)
    assert p.ok and p.regions[0] == 0 and p.regions[-1] == len(topo.regions) - 1


def test_distance_transform_values():
    b = np.zeros((9, 9), dtype=np.uint8)
    b[4, 4] = 1
    g = vn.BinaryGrid(b, resolution=0.5)
    df = vn.field.distance_transform(g)
    assert df.squared_distance.array[4, 7] == pytest.approx(9.0)
    assert df.squared_distance.array[0, 0] == pytest.approx(32.0)
    assert df.distance_m.array[4, 7] == pytest.approx(1.5)
    assert vn.field.inflate(g, 0.51).array.sum() == 5  # the cell and its 4 neighbours at 0.5 m
    # < 1.01 m = 2.02 cells: distances 0, 1 (x4), sqrt 2 (x4), 2 (x4).
    assert vn.field.inflate(g, 1.01).array.sum() == 13


def gvd_fixture():
    b = np.zeros((40, 60), dtype=np.uint8)
    b[10:30, 20:24] = 1
    b[5:8, 40:50] = 1
    return vn.BinaryGrid(b)


def test_gvd_and_dynamic_update_equal_rebuild():
    g = gvd_fixture()
    gvd = vn.voronoi.build_gvd(g)
    assert gvd.diagram.array.dtype == np.uint8 and gvd.diagram.array.sum() > 0
    assert gvd.clearance.array.dtype == np.float32
    dyn = vn.voronoi.DynamicGvd(g)
    assert np.array_equal(dyn.snapshot().diagram.array, gvd.diagram.array)
    changes = [((x, 30), True) for x in range(30, 36)] + [((21, 20), False)]
    stats = dyn.update(changes)
    assert stats["changed_cells"] == 7
    arr = g.array.copy()
    for (x, y), blk in changes:
        arr[y, x] = 1 if blk else 0
    rebuilt = vn.voronoi.build_gvd(vn.BinaryGrid(arr))
    assert np.array_equal(dyn.snapshot().diagram.array, rebuilt.diagram.array)
    with pytest.raises(vn.Error):
        dyn.update([((100, 100), True)])


def test_labeled_voronoi_and_graph():
    g = gvd_fixture()
    lv = vn.voronoi.build_labeled_voronoi(g, vn.voronoi.CaVoronoiOptions(labels="obstacle_component"))
    assert lv.diagram.array.sum() > 0 and lv.steps > 0
    assert lv.label.array.dtype == np.int32
    graph = vn.voronoi.build_voronoi_graph(vn.voronoi.build_gvd(g))
    assert len(graph.nodes) >= 2
    for a, b, attrs in graph.edge_list():
        assert 0 <= a < len(graph.nodes) and 0 <= b < len(graph.nodes) and attrs["length_m"] > 0
