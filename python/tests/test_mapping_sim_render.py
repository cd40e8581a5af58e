"""mapping (log-odds, laser/sonar insert), netsim and explore (metrics dicts), render (to_rgb)."""

from __future__ import annotations

import math

import numpy as np
import pytest

import voronav as vn


def box_world():
    b = np.zeros((40, 40), dtype=np.uint8)
    b[0, :] = b[-1, :] = b[:, 0] = b[:, -1] = 1
    return vn.BinaryGrid(b, resolution=0.1)


def test_laser_insert_marks_walls_and_clears_free_space():
    world = box_world()
    pose = vn.Pose2(2.0, 2.0, 0.0)
    bearings, ranges = vn.mapping.simulate_laser_scan(world, pose, beams=180)
    assert bearings.shape == ranges.shape == (180,)
    assert ranges.min() == pytest.approx(1.9, abs=0.11)
    m = vn.mapping.OccupancyMap(world.geometry)
    lo = m.log_odds.array
    assert lo.dtype == np.float32 and np.shares_memory(lo, m.log_odds.array)
    m.insert_laser_scan(pose, bearings, ranges)
    assert m.probability((20, 20)) < 0.5  # at the sensor: cleared
    assert m.probability((39, 20)) > 0.5  # the east wall
    assert lo[20, 39] > 0  # the view sees the update (zero copy)
    occ = m.to_occupancy_grid()
    assert occ.array[20, 39] > 50
    with pytest.raises(vn.Error, match="differ in length"):
        m.insert_laser_scan(pose, [0.0, 1.0], [1.0])


def test_sonar_insert():
    m = vn.mapping.OccupancyMap(vn.GridGeometry(40, 40, 0.1))
    m.insert_sonar(vn.Pose2(0.5, 2.0, 0.0), 2.0, vn.mapping.SonarModelOptions(half_angle=math.radians(10)))
    assert m.probability(m.log_odds.world_to_cell(vn.Vec2(2.5, 2.0))) > 0.5
    assert m.probability(m.log_odds.world_to_cell(vn.Vec2(1.2, 2.0))) < 0.5


def test_netsim_run_metrics_dict():
    world = np.full((60, 100), 0, dtype=np.int8)
    world[0, :] = world[-1, :] = world[:, 0] = world[:, -1] = 100
    grid = vn.OccupancyGrid(world, resolution=0.1)
    sc = vn.netsim.Scenario(grid, [(1.0, 3.0), (4.0, 3.0), (7.0, 3.0)], destination=(9.0, 3.0))
    res = vn.netsim.run(sc, method="decentralized", time_limit_s=60.0)
    assert res["success"] is True
    assert len(res["robots"]) == 3 and {"work", "travel_m", "sent_bytes"} <= set(res["robots"][0])
    assert res["traffic_bytes"] == sum(r["sent_bytes"] for r in res["robots"])
    # Which mechanism produced the route: the robot at 4 m relays the Search (3 m sensing).
    assert res["route_found_by"] == "relays" and res["route_robots"] == 1
    assert res["repairs_executed"] == 0 and res["changes_applied"] == 0
    assert res["repair_rings_expanded"] == 0 and "repair_answers_fixed_seen" in res
    assert res["repair_walk_targets_kept"] == 0
    cen = vn.netsim.run(sc, vn.netsim.Options(method="centralized"), time_limit_s=60.0, record=True)
    assert cen["success"] is True and cen["route_found_by"] == "source_alone"
    route = cen["route"]
    assert len(route) >= 2 and route[-1] == pytest.approx((9.0, 3.0), abs=0.2)
    assert len(cen["steps"]) > 1 and len(cen["steps"][0]["positions"]) == 3
    with pytest.raises(vn.Error, match="unknown option 'sped'"):
        vn.netsim.run(sc, sped=2.0)


def test_explore_run_dict():
    world = vn.explore.paper_world(0.1)
    res = vn.explore.run(world, method="frontier", robots=2, time_limit=20.0, seed=1)
    assert 0.0 < res["coverage"] <= 1.0
    assert isinstance(res["team_map"], vn.OccupancyGrid)
    assert res["robots"] == 2


def test_figure_to_rgb_and_save(tmp_path):
    g = vn.OccupancyGrid(np.zeros((10, 20), dtype=np.int8))
    with pytest.raises(vn.Error, match="title"):  # every picture says what it shows
        vn.render.Figure(g.geometry, pixels_per_cell=4).save(str(tmp_path / "untitled.png"))
    fig = vn.render.Figure(g.geometry, pixels_per_cell=4, title="a path")
    fig.occupancy(g).path([(0, 0), (19, 9)], color="red")
    rgba = fig.to_rgba()
    assert rgba.shape == (28 + 40, 80, 4) and rgba.dtype == np.uint8  # title band + map
    assert tuple(rgba[28 + 2, 40, :3]) == (255, 255, 255)  # free cells are white
    red = (rgba[..., 0] > 200) & (rgba[..., 1] < 80)
    assert red.sum() > 0
    rgb = fig.to_rgb()
    assert rgb.shape == (28 + 40, 80, 3) and np.array_equal(rgb[red], rgba[red][:, :3])
    out = tmp_path / "fig.png"
    fig.save(str(out))
    assert out.stat().st_size > 100
    with pytest.raises(vn.Error, match="expected .png or .svg"):
        fig.save(str(tmp_path / "fig.jpg"))
    with pytest.raises(vn.Error, match="color"):
        fig.point((1.0, 1.0), color="mauve")


def test_explore_options_match_the_cli(cli):
    """Every controller and re-planning option the CLI has is an explore.Options field, and the
    same settings give the same run (issue 14). Every switch is set away from its default, and the
    options each front end hands the library are compared through the library's own echo
    (`input`): a field bound to the wrong member, or a flag parsed into the wrong one, shows there
    even when the run's counters cannot see it."""
    o = vn.explore.Options(method="tree", robots=2, time_limit=60.0, seed=3, tree_start_time=20.0,
                           start=vn.Vec2(2.0, 2.0))
    assert o.controller.random_turn_rate == 0.0 and o.controller.avoid_escape == vn.explore.AvoidEscape.corridor
    assert o.frontier_controller.random_turn_rate == pytest.approx(0.4)
    assert o.frontier_controller.avoid_escape == vn.explore.AvoidEscape.spin
    defaults = o.to_dict()
    o.tree_replan = "robots"
    o.tree_leg_replan = "none"
    o.unstick = False
    o.frontier_unstick = True
    o.idle_unstick = False
    o.yield_to_held = False
    o.retry_banned = False
    o.share_bans = True
    o.crowd_limit = 3
    o.drop_goalless_routes = True
    o.guard = "cone"
    o.skip_known_leaves = True
    o.gain_through_free = False
    o.margin_escape = False
    o.disperse_neighbours = True
    o.clear_way_out = True
    o.unstick_retry = False  # no-ops with unstick and margin_escape off: bound and echoed
    o.unstick_right_of_way = False
    o.unknown_leaves_first = True  # a no-op beside nearest_leaf_next (one dealt leaf each): bound
    o.nearest_leaf_next = True
    o.frontiers_after_leaves = True
    o.min_leaf_gain = 0.25
    o.stall_reach_radius = 0.12
    o.stop_at_coverage = 0.97
    o.controller.random_turn_rate = 0.3  # in place: the field is the options' own member
    o.controller.avoid_escape = "spin"
    assert o.controller.random_turn_rate == pytest.approx(0.3)
    res = vn.explore.run(vn.explore.paper_world(), o)
    got = cli("explore", "--world", "paper", "--robots", "2", "--time", "60", "--seed", "3",
              "--tree-start", "20", "--tree-replan", "robots", "--tree-leg-replan", "none",
              "--unstick", "off", "--frontier-unstick", "on", "--idle-unstick", "off",
              "--yield-to-held", "off", "--retry-banned", "off", "--share-bans", "on",
              "--crowd-limit", "3", "--drop-goalless-routes", "on",
              "--random-turn-rate", "0.3", "--avoid-escape", "spin",
              "--guard", "cone", "--skip-known-leaves", "on",
              "--gain-through-free", "off", "--margin-escape", "off",
              "--disperse-neighbours", "on", "--clear-way-out", "on", "--nearest-leaf-next", "on",
              "--unknown-leaves-first", "on", "--frontiers-after-leaves", "on",
              "--min-leaf-gain", "0.25", "--stall-reach-radius", "0.12", "--stop-at", "0.97",
              "--unstick-retry", "off", "--unstick-right-of-way", "off")
    # The same options reached the library from both sides, and every one the CLI has was moved
    # off its default (so a swapped pair of switches cannot hide behind equal values).
    cli_input = {k: v for k, v in got["input"].items() if k != "map"}
    assert res["input"] == cli_input
    assert o.to_dict() == res["input"]
    moved = {k for k in defaults if defaults[k] != res["input"][k]}
    cli_flags = {"tree_replan", "tree_leg_replan", "unstick", "frontier_unstick", "idle_unstick",
                 "yield_to_held", "retry_banned", "share_bans", "crowd_limit",
                 "drop_goalless_routes", "guard", "skip_known_leaves", "gain_through_free",
                 "margin_escape", "disperse_neighbours", "clear_way_out", "unknown_leaves_first",
                 "nearest_leaf_next", "frontiers_after_leaves", "min_leaf_gain",
                 "stall_reach_radius", "stop_at_coverage", "random_turn_rate", "avoid_escape",
                 "unstick_retry", "unstick_right_of_way"}
    assert cli_flags <= moved, cli_flags - moved
    for key in ("coverage", "distance_m", "feature_points", "leaves", "dispatches", "escapes",
                "unsticks", "collisions", "guard_wall_stops", "guard_robot_stops", "leaves_skipped",
                "dispersals", "way_clearances", "leaves_promoted", "leaves_pooled", "frontier_goals",
                "stalled_robots", "idle_when_explored", "unstick_retries", "unstick_yields"):
        assert res[key] == pytest.approx(got[key], rel=1e-5), key
    default = vn.explore.run(vn.explore.paper_world(), method="tree", robots=2, time_limit=60.0,
                             seed=3, tree_start_time=20.0, start=vn.Vec2(2.0, 2.0))
    assert default["distance_m"] != pytest.approx(res["distance_m"], rel=1e-6)
    with pytest.raises(vn.Error, match="unknown option"):
        vn.explore.ControllerOptions(random_turn=1.0)
    assert vn.explore.Method("tree_frontier") == vn.explore.Method.tree_frontier
