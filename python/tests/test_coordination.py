"""coordination: a scenario from Python lists gives the CLI's schedule; validation returns status."""

from __future__ import annotations

import json

import pytest

import voronav as vn

co = vn.coordination


def crossing_agents():
    return [
        co.Agent(1, [(-10, 0), (10, 0)], radius=0.5, v_max=1.0),
        co.Agent(2, [(0, -10), (0, 10)], radius=0.5, v_max=1.0),
    ]


def test_crossing_schedule_from_lists_equals_file_and_cli(data, cli):
    r = co.coordinate(crossing_agents(), search="exhaustive", node_spacing=0.25)
    assert r.ok and r.valid and r.verified
    # Hand-computed in data/coordination/crossing.yaml: robot 2 waits 2.25 s.
    assert sorted(r.delays) == pytest.approx([0.0, 2.25])
    sc = co.load_scenario(str(data / "coordination/crossing.yaml"))
    from_file = co.coordinate(sc.plan_agents(), search="exhaustive", node_spacing=sc.node_spacing)
    assert from_file.delays == pytest.approx(r.delays)
    out = cli("coordinate", "--scenario", str(data / "coordination/crossing.yaml"), "--search", "exhaustive")
    assert [a["delay"] for a in out["agents"]] == pytest.approx(r.delays)
    assert out["makespan"] == pytest.approx(r.makespan)
    assert out["order"] == r.order_ids
    sched = json.loads(r.to_json())
    assert [a["delay"] for a in sched["agents"]] == pytest.approx(r.delays)


def test_mapf_scenario_equals_cli(data, cli):
    m, s = str(data / "mapf/random-32-32-20.map"), str(data / "mapf/random-32-32-20-random-1.scen")
    sc = co.load_mapf(m, s, 8)
    agents = sc.plan_agents()
    r = co.coordinate(agents, search="ga", seed=1)
    out = cli("coordinate", "--map", m, "--scen", s, "--agents", "8", "--search", "ga", "--seed", "1")
    assert out["status"] == r.status
    assert [a["delay"] for a in out["agents"]] == pytest.approx(r.delays)
    assert out["makespan"] == pytest.approx(r.makespan)
    assert out["valid"] == r.valid


def test_ga_preset_fast_equals_cli(data, cli):
    m, s = str(data / "mapf/random-32-32-20.map"), str(data / "mapf/random-32-32-20-random-1.scen")
    sc = co.load_mapf(m, s, 30)
    agents = sc.plan_agents()
    r = co.coordinate(agents, search="ga", seed=2, ga_preset="fast", at_start="appear",
                      at_goal="leave")
    out = cli("coordinate", "--map", m, "--scen", s, "--agents", "30", "--search", "ga", "--seed",
              "2", "--ga-preset", "fast", "--at-start", "appear", "--at-goal", "leave")
    assert out["three_opt_order"] == "critical-delayed"
    assert out["ga_ils_steps"] >= 15  # patience 15: the ILS ran
    assert out["makespan"] == pytest.approx(r.makespan)
    assert [a["delay"] for a in out["agents"]] == pytest.approx(r.delays)
    with pytest.raises(vn.Error, match="paper|fast"):
        co.coordinate(agents, search="ga", ga_preset="quick")


def test_scenario_from_lists_with_map():
    import numpy as np

    grid = vn.OccupancyGrid(np.zeros((20, 20), dtype=np.int8), resolution=0.5)
    sc = co.Scenario([{"id": 1, "start": (1.0, 1.0), "goal": (9.0, 9.0), "radius": 0.3},
                      {"id": 2, "start": (9.0, 1.0), "goal": (1.0, 9.0), "radius": 0.3}], map=grid)
    agents = sc.plan_agents()
    assert [a.id for a in agents] == [1, 2] and all(a.length > 10 for a in agents)
    r = co.coordinate(agents, search="none")
    assert r.valid
    with pytest.raises(vn.Error, match="unknown key 'speed'"):
        co.Scenario([{"id": 1, "path": [(0, 0), (1, 0)], "speed": 2}])


def test_invalid_schedule_is_returned_not_raised():
    agents = crossing_agents()
    v = co.verify_schedule(agents, [0.0, 0.0])
    assert v["valid"] is False and len(v["conflicts"]) == 1
    assert v["conflicts"][0]["distance"] < 1.0
    ok = co.verify_schedule(agents, [0.0, 2.25])
    assert ok["valid"] is True and ok["conflicts"] == []
    with pytest.raises(vn.Error, match="one delay per agent"):
        co.verify_schedule(agents, [0.0])
    with pytest.raises(vn.Error, match="search"):
        co.coordinate(agents, search="random")
