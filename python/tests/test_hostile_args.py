"""Every public Python function × {NaN, inf, negative, wrong type, wrong shape}: refused with
canopy.ScenarioError (a ValueError) naming the function and the argument, as the command line
names the option — before any work, and never a bare exit or another exception type. The cases
are generated from one table of (function, argument, valid value) rows."""
import math
import os
import pathlib

import numpy as np
import pytest

import canopy

NAN, INF = math.nan, math.inf


@pytest.fixture(scope="module")
def demo():
    scenario = canopy.load("demo")
    scenario["clock.duration"] = 1
    return scenario


@pytest.fixture(scope="module")
def finished_sweep(tmp_path_factory):
    folder = tmp_path_factory.mktemp("sweep")
    (folder / "s.json").write_text('{"name": "s", "scenario": "demo", "trials": 1, '
                                   '"set": {"clock.duration": 1}}')
    canopy.sweep(folder / "s.json", folder / "out")
    return folder


# (label, call with one argument replaced, that argument's name, its valid value, kind):
# kind "number" (a scalar), "pair" / "quad" (a sequence of numbers), "path", "flag", "count".
def calls(demo, tmp, sweep_folder):
    return [
        ("run.seed", lambda v: canopy.run(demo, tmp / "r", seed=v), "seed", 1, "count"),
        ("run.frame_every", lambda v: canopy.run(demo, tmp / "r", frames=True, frame_every=v),
         "frame_every", 1, "count"),
        ("run.size", lambda v: canopy.run(demo, tmp / "r", frames=True, size=v), "size",
         (64, 48), "pair"),
        ("run.out", lambda v: canopy.run(demo, v), "out", tmp / "r", "path"),
        ("run.frames", lambda v: canopy.run(demo, tmp / "r", frames=v), "frames", False, "flag"),
        ("sweep.jobs", lambda v: canopy.sweep(sweep_folder / "s.json", sweep_folder / "o2", jobs=v),
         "jobs", 1, "count"),
        ("sweep.file", lambda v: canopy.sweep(v, sweep_folder / "o3"), "file",
         sweep_folder / "s.json", "path"),
        ("analyze.dir", lambda v: canopy.analyze(v), "dir", sweep_folder / "out", "path"),
        ("analyze.figures", lambda v: canopy.analyze(sweep_folder / "out", figures=v), "figures",
         False, "flag"),
        ("read_run.dir", lambda v: canopy.read_run(v), "dir", None, "path"),
        ("load.name", lambda v: canopy.load(v), "name_or_path", "demo", "path"),
        ("load.overrides", lambda v: canopy.load("demo", overrides={"planner.horizon": v}),
         "planner.horizon", 1, "count"),
        ("poisson.aoi", lambda v: canopy.forest.poisson(v, 0.001, 1.0), "aoi", (0, 0, 100, 100),
         "quad"),
        ("poisson.lam", lambda v: canopy.forest.poisson((0, 0, 100, 100), v, 1.0), "lam", 0.001,
         "number"),
        ("poisson.radius", lambda v: canopy.forest.poisson((0, 0, 100, 100), 0.001, v), "radius",
         1.0, "number"),
        ("poisson.min_gap", lambda v: canopy.forest.poisson((0, 0, 100, 100), 0.001, 1, min_gap=v),
         "min_gap", 0.5, "number"),
        ("poisson.seed", lambda v: canopy.forest.poisson((0, 0, 100, 100), 0.001, 1, seed=v),
         "seed", 3, "count"),
        ("grid.origin", lambda v: canopy.forest.grid(v, (5, 5), 2, 2, 1.0), "origin", (0, 0),
         "pair"),
        ("grid.spacing", lambda v: canopy.forest.grid((0, 0), v, 2, 2, 1.0), "spacing", (5, 5),
         "pair"),
        ("grid.rows", lambda v: canopy.forest.grid((0, 0), (5, 5), v, 2, 1.0), "rows", 2, "count"),
        ("grid.cols", lambda v: canopy.forest.grid((0, 0), (5, 5), 2, v, 1.0), "cols", 2, "count"),
        ("grid.angle", lambda v: canopy.forest.grid((0, 0), (5, 5), 2, 2, 1.0, angle=v), "angle",
         0.1, "number"),
        ("grid.jitter", lambda v: canopy.forest.grid((0, 0), (5, 5), 2, 2, 1.0, jitter=v),
         "jitter", 0.1, "number"),
        ("cluster.spread", lambda v: canopy.forest.cluster((0, 0, 100, 100), 0.0005, 3, v, 1.0),
         "spread", 2.0, "number"),
        ("cluster.mean_trees",
         lambda v: canopy.forest.cluster((0, 0, 100, 100), 0.0005, v, 2.0, 1.0), "mean_trees", 3,
         "number"),
        ("disc.centre", lambda v: canopy.forest.disc(v, 1.0), "centre", (1, 2), "pair"),
        ("disc.radius", lambda v: canopy.forest.disc((1, 2), v), "radius", 1.0, "number"),
        ("Simulation.seed", lambda v: canopy.Simulation(demo, seed=v), "seed", 2, "count"),
        ("Simulation.scenario", lambda v: canopy.Simulation(v), "scenario", demo, "object"),
        ("Simulation.step", lambda v: canopy.Simulation(demo).step(v), "commands",
         np.zeros((2, 2)), "array"),
        ("Simulation.render", lambda v: canopy.Simulation(demo).render(v, 48), "width", 64,
         "count"),
        ("Scenario.setitem", lambda v: demo.copy().__setitem__("uavs.0.v_max", v),
         "uavs[0].v_max", 3.0, "number"),
        ("Scenario.config", lambda v: canopy.Scenario(v), "config",
         dict(demo.config) if demo else None, "object"),
        ("Scenario.save", lambda v: demo.save(v), "path", tmp / "saved.json", "path"),
        ("TrackingEnv.map_radius", lambda v: canopy.TrackingEnv(demo, map_radius=v),
         "map_radius", 30.0, "number"),
        ("TrackingEnv.max_tracks", lambda v: canopy.TrackingEnv(demo, max_tracks=v),
         "max_tracks", 4, "count"),
        ("TrackingEnv.render_size", lambda v: canopy.TrackingEnv(demo, render_size=v),
         "render_size", (64, 48), "pair"),
        ("TrackingEnv.reset", lambda v: canopy.TrackingEnv(demo).reset(seed=v), "seed", 5,
         "count"),
        ("VectorEnv.n", lambda v: canopy.VectorEnv(v, demo), "n", 1, "count"),
        ("VectorEnv.threads", lambda v: canopy.VectorEnv(1, demo, threads=v), "threads", 1,
         "count"),
        ("VectorEnv.reset", lambda v: canopy.VectorEnv(2, demo).reset(seed=v), "seed", 5,
         "count"),
    ]


# The hostile values for each kind of argument: (name, value).
HOSTILE = {
    "number": [("nan", NAN), ("inf", INF), ("-inf", -INF), ("string", "1"), ("list", [1.0]),
               ("none", None), ("bool", True), ("complex", 1j)],
    "count": [("nan", NAN), ("inf", INF), ("negative", -1), ("fraction", 1.5), ("string", "1"),
              ("list", [1]), ("huge", 2**70), ("bool", True)],
    "pair": [("nan", (NAN, 1)), ("inf", (1, INF)), ("negative", (-1, -1)), ("short", (1,)),
             ("long", (1, 2, 3)), ("string", "12"), ("scalar", 5), ("nested", ((1, 2), (3, 4))),
             ("none", None)],
    "quad": [("nan", (0, 0, NAN, 1)), ("inf", (0, 0, INF, 100)), ("inverted", (10, 10, 0, 0)),
             ("short", (0, 0, 1)), ("string", "0,0,1,1"), ("scalar", 4), ("none", None)],
    "path": [("int", 3), ("none_or_float", 1.5), ("list", ["a"]), ("empty", ""),
             ("nul", "a\0b"), ("bytes", b"x")],
    "flag": [("string", "yes"), ("two", 2), ("nan", NAN), ("list", [True])],
    "object": [("int", 3), ("none", None), ("list", [1])],
    "array": [("nan", np.full((2, 2), NAN)), ("inf", np.full((2, 2), INF)),
              ("wrong_shape", np.zeros((3, 2))), ("flat", np.zeros(4)), ("string", "go"),
              ("ragged", [[1, 2], [3]])],
}


# Values of a hostile kind that are valid for one argument: None is the documented default of
# run(size=) and poisson(min_gap=), and coordinates may be negative. These are accepted.
VALID_HERE = {("run.size", "none"), ("poisson.min_gap", "none"), ("grid.origin", "negative"),
              ("disc.centre", "negative")}


def cases():
    out = []
    for label, kind in [(row[0], row[4]) for row in calls(None, pathlib.Path("/tmp"), pathlib.Path("/tmp"))]:
        for name, _ in HOSTILE[kind]:
            out.append((label, name))
    return out


@pytest.mark.parametrize("label,hostile", cases())
def test_every_public_function_refuses_every_hostile_value_with_a_named_scenario_error(
        label, hostile, demo, tmp_path, finished_sweep):
    rows = {row[0]: row for row in calls(demo, tmp_path, finished_sweep)}
    _, call, field, _valid, kind = rows[label]
    value = dict(HOSTILE[kind])[hostile]
    if label == "Scenario.setitem" and hostile == "string":
        pytest.skip("a string is a valid JSON value; the loader refuses it (tested below)")
    if (label, hostile) in VALID_HERE:
        call(value)  # accepted
        return
    with pytest.raises(canopy.ScenarioError) as caught:
        call(value)
    assert isinstance(caught.value, ValueError)
    message = str(caught.value)
    # The argument is named (its field path for a scenario field), and the message is bounded.
    assert field in message or field.split(".")[-1] in message, message
    assert len(message) < 2000


def test_the_valid_values_of_the_table_are_accepted(demo, tmp_path, finished_sweep):
    for label, call, _field, valid, _kind in calls(demo, tmp_path, finished_sweep):
        if label in ("read_run.dir",):
            continue
        call(valid)  # no exception


def test_the_issue_examples(demo, tmp_path, finished_sweep):
    with pytest.raises(canopy.ScenarioError, match="jobs"):
        canopy.sweep(finished_sweep / "s.json", tmp_path / "o", jobs=0)
    with pytest.raises(canopy.ScenarioError, match="size"):
        canopy.run(demo, tmp_path / "r", frames=True, size=(-1, 480))
    assert not (tmp_path / "o").exists() and not (tmp_path / "r").exists()


def test_vector_env_checks_seeds_and_n_as_tracking_env_does(demo):
    # Issue 47: 1.7 was taken as 1, and -5, NaN, text, 2-D arrays and 2**70 got messages that did
    # not name seed; VectorEnv(10**7) ran into gigabytes before a MemoryError.
    vec = canopy.VectorEnv(2, demo)
    for seed in (1.7, -5, NAN, "7", np.zeros((2, 2)), 2**70, [1, 2, 3], [1, -1], 2**64 - 1):
        with pytest.raises(canopy.ScenarioError, match="VectorEnv.reset: seed"):
            vec.reset(seed=seed)
    _, infos = vec.reset(seed=2**64 - 2)  # the largest first seed for two environments
    assert list(infos["seed"]) == [2**64 - 2, 2**64 - 1]
    _, infos = vec.reset(seed=np.array([4, 9]))
    assert list(infos["seed"]) == [4, 9]
    with pytest.raises(canopy.ScenarioError, match=r"VectorEnv: n: expected an integer in \[1, 4096\]"):
        canopy.VectorEnv(10**7, demo)


def test_an_output_that_is_not_ours_is_refused_and_left_as_it_was(demo, tmp_path):
    # Issue 47: canopy.run(out=<a file>) raised RuntimeError where the CLI exits 2; Scenario.save
    # renamed its file over whatever the path was.
    a_file = tmp_path / "a_file"
    a_file.write_text("mine")
    with pytest.raises(canopy.ScenarioError, match="canopy.run: out: expected a directory"):
        canopy.run(demo, a_file)
    assert a_file.read_text() == "mine"
    fifo = tmp_path / "fifo"
    os.mkfifo(fifo)
    with pytest.raises(canopy.ScenarioError, match="Scenario.save: path: .* exists and is a FIFO"):
        demo.save(fifo)
    out = tmp_path / "run"
    out.mkdir()
    os.mkfifo(out / "record.jsonl")
    with pytest.raises(ValueError, match="record.jsonl': exists and is a FIFO"):
        canopy.run(demo, out)
    assert (out / "record.jsonl").is_fifo() and fifo.is_fifo()
    assert sorted(p.name for p in out.iterdir()) == ["record.jsonl"]


def test_an_over_deep_value_is_blamed_on_the_field_it_was_set_to(demo):
    # Issue 47: the loader's depth error named the base file, not the edit.
    scenario = demo.copy()
    deep = 0
    for _ in range(100):
        deep = [deep]
    with pytest.raises(canopy.ScenarioError) as caught:
        scenario["uavs.0.v_max"] = deep
    assert caught.value.field == "uavs[0].v_max", str(caught.value)
    assert "nested at most 62 levels deep here" in str(caught.value)
    assert scenario["uavs.0.v_max"] == demo["uavs.0.v_max"]  # the edit was not made
    # At the limit the loader reads it (and refuses it for what it is, not for its depth).
    shallow = 0
    for _ in range(62):
        shallow = [shallow]
    with pytest.raises(canopy.ScenarioError) as caught:
        scenario["uavs.0.v_max"] = shallow
    assert "nested" not in str(caught.value) and "uavs[0].v_max" in str(caught.value)


def test_edits_name_the_field_path_the_cli_would_name(demo):
    scenario = demo.copy()
    with pytest.raises(canopy.ScenarioError) as caught:
        scenario["uavs.0.v_max"] = "fast"
    assert caught.value.field == "uavs[0].v_max", str(caught.value)
    with pytest.raises(canopy.ScenarioError) as caught:
        scenario["occluders"] = [{"type": "polygon",
                                  "vertices": [[10, 10], [20, 10], [15, 10.000000001]]}]
    assert "occluders[0].vertices" in str(caught.value)
    # A NaN put into the dict by hand is named when the scenario is next checked.
    scenario.config["uavs"][0]["v_max"] = NAN
    with pytest.raises(canopy.ScenarioError, match=r"uavs\.0\.v_max|uavs\[0\]\.v_max"):
        scenario.validate()


def test_a_polygon_box2d_cannot_build_is_refused_not_an_abort(demo, tmp_path):
    """The issue's class 0 through Python: run and Simulation get the loader's error."""
    scenario = demo.copy()
    scenario.config.setdefault("occluders", []).append(
        {"type": "polygon", "vertices": [[30, 30], [40, 30], [35, 30.000000001]]})
    index = len(scenario.config["occluders"]) - 1
    for attempt in (lambda: canopy.run(scenario, tmp_path / "r"),
                    lambda: canopy.Simulation(scenario)):
        with pytest.raises(canopy.ScenarioError, match=rf"occluders\[{index}\]\.vertices"):
            attempt()


def test_read_run_of_a_hostile_folder_raises_scenario_error(tmp_path):
    (tmp_path / "run").mkdir()
    os.mkfifo(tmp_path / "run" / "manifest.json")
    with pytest.raises(canopy.ScenarioError, match="manifest.json"):
        canopy.read_run(tmp_path / "run")
