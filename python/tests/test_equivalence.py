"""Python stepping is the command line's run: the same truth and beliefs at every step as
record.jsonl, for a library scenario and for a layout built in Python, saved and run by the CLI."""
import json

import numpy as np

import canopy


def _upper(P):
    """P's upper triangle row by row, as record.jsonl writes covariances."""
    n = P.shape[0]
    return [P[r, c] for r in range(n) for c in range(r, n)]


def _compare_step(sim, line):
    rec = json.loads(line)
    assert rec["k"] == sim.step_index and rec["t"] == sim.time
    # Truth. JSON holds each double as its shortest round trip, so equality is exact.
    targets = sim.target_states
    for t, target in enumerate(rec["targets"]):
        assert list(targets[t]) == target["p"] + target["v"]
    uavs = sim.uav_states
    for i, uav in enumerate(rec["uavs"]):
        assert list(uavs[i]) == uav["p"] + [uav["yaw"]]
        assert list(sim.uav_velocities[i]) == uav["v"]
        assert list(sim.uav_commands[i]) == uav["cmd"]
    # Beliefs: each agent's fused tracks and occlusion map.
    for i, agent in enumerate(rec["agents"]):
        tracks = sim.tracks(i)
        assert [list(k) for k in tracks["keys"]] == [t["key"] for t in agent["tracks"]]
        for j, t in enumerate(agent["tracks"]):
            assert list(tracks["means"][j]) == t["x"]
            assert _upper(tracks["covariances"][j]) == t["P"]
            assert tracks["existence"][j] == t["existence"]
        trees = sim.occlusion_map(i)
        assert [list(k) for k in trees["keys"]] == [t["key"] for t in agent["map"]]
        for j, t in enumerate(agent["map"]):
            assert list(trees["means"][j]) == t["x"]
            assert _upper(trees["covariances"][j]) == t["P"]
        assert [list(p) for p in sim.planned_path(i)] == agent["planned_path"]
    # Scans.
    for i, scan in enumerate(rec["scans"]):
        mine = sim.scan(i)
        assert list(mine["in_footprint"]) == scan["in_footprint"]
        assert list(mine["visible"]) == scan["visible"]
        assert [list(z) for z in mine["z"]] == [o["z"] for o in scan["obs"]]
        assert [[R[0, 0], R[0, 1], R[1, 1]] for R in mine["R"]] == [o["R"] for o in scan["obs"]]
    # And the whole line, byte for byte.
    assert sim.record_line() == line


def _step_and_compare(sim, record_path):
    lines = record_path.read_text().splitlines()
    assert len(lines) == sim.steps
    _compare_step(sim, lines[0])
    for line in lines[1:]:
        sim.step()
        _compare_step(sim, line)
    assert sim.done


def test_trajectory_handover_seed_3_equals_the_cli(tmp_path, cli):
    cli("run", "trajectory_handover", "--seed", "3", "--out", tmp_path)
    sim = canopy.Simulation(canopy.load("trajectory_handover"), seed=3)
    _step_and_compare(sim, tmp_path / "record.jsonl")


def test_layout_built_in_python_runs_the_same_in_the_cli(tmp_path, cli):
    s = canopy.load("occlusion_sharing")
    s.config["occluders"] = (
        canopy.forest.poisson((-30, -30, 30, 30), 0.004, (1.0, 2.0), seed=12, min_gap=1.0)
        + canopy.forest.grid((-20, 10), (6, 0), 1, 4, radius=1.5)
        + [canopy.forest.disc((-6.6, 1.6), 2.0)])
    s["uavs.1.start"] = [0.0, -20.0]
    s["targets.1.path.velocity"] = [1.5, 0.5]
    path = tmp_path / "built.json"
    s.save(path)
    cli("run", path, "--seed", "11", "--out", tmp_path / "run")
    saved = json.loads(path.read_text())
    assert len(saved["occluders"]) == len(s.occluders)
    sim = canopy.Simulation(canopy.load(path), seed=11)
    _step_and_compare(sim, tmp_path / "run" / "record.jsonl")
    # The scenario object as built (not reloaded from the file) steps the same.
    again = canopy.Simulation(s, seed=11)
    while not again.done:
        again.step()
    np.testing.assert_array_equal(again.uav_states, sim.uav_states)
    assert again.record_line() == sim.record_line()
