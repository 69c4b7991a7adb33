"""Whole jobs from Python write what the command line writes."""
import json

import numpy as np

import canopy


def _summary_without_wall_times(path):
    summary = json.loads(path.read_text())
    summary.pop("timing", None)  # wall times
    return summary


def test_run_writes_the_clis_record(tmp_path, cli):
    summary = canopy.run("demo", tmp_path / "py", seed=9)
    cli("run", "demo", "--seed", "9", "--out", tmp_path / "cli")
    for name in ("record.jsonl",):
        assert (tmp_path / "py" / name).read_bytes() == (tmp_path / "cli" / name).read_bytes()
    assert summary == json.loads((tmp_path / "py" / "summary.json").read_text())
    assert (_summary_without_wall_times(tmp_path / "py" / "summary.json") ==
            _summary_without_wall_times(tmp_path / "cli" / "summary.json"))
    manifest = json.loads((tmp_path / "py" / "manifest.json").read_text())
    assert manifest["seed"] == 9 and manifest["effective_config"]["seed"] == 9


def test_read_run_gives_the_records_truth(tmp_path):
    canopy.run("demo", tmp_path, seed=4)
    run = canopy.read_run(str(tmp_path))
    lines = [json.loads(line) for line in (tmp_path / "record.jsonl").read_text().splitlines()]
    assert list(run["k"]) == [line["k"] for line in lines]
    assert run["uav_positions"].shape == (len(lines), len(lines[0]["uavs"]), 2)
    for s, line in enumerate(lines):
        assert run["t"][s] == line["t"]
        for i, uav in enumerate(line["uavs"]):
            assert list(run["uav_positions"][s, i]) == uav["p"] and run["uav_yaw"][s, i] == uav["yaw"]
        for j, target in enumerate(line["targets"]):
            assert list(run["target_positions"][s, j]) == target["p"]


def test_read_record_and_read_run_read_the_compact_form_as_the_plain_one(tmp_path, cli):
    for form in ("jsonl", "compact"):
        cli("run", "demo", "--set", "clock.duration=4", "--record", form, "--out", tmp_path / form)
    assert (tmp_path / "compact" / "record.jsonl.zst").exists()
    plain = [json.loads(line) for line in (tmp_path / "jsonl" / "record.jsonl").read_bytes().splitlines()]
    assert len(plain) == 21
    assert canopy.read_record(tmp_path / "compact") == plain
    assert canopy.read_record(tmp_path / "jsonl") == plain
    assert canopy.read_record(tmp_path / "compact", steps=(5, 8)) == plain[5:8]
    whole, part = canopy.read_run(tmp_path / "compact"), canopy.read_run(tmp_path / "compact", steps=(5, 8))
    assert list(part["k"]) == [5, 6, 7]
    assert np.array_equal(part["uav_positions"], whole["uav_positions"][5:8])
    assert np.array_equal(whole["target_positions"], canopy.read_run(tmp_path / "jsonl")["target_positions"])
    for bad in ((3, 3), (-1, 2), [0, 2], (0.5, 2), "0:2"):
        with np.testing.assert_raises_regex(canopy.ScenarioError, "canopy.read_record: steps: expected"):
            canopy.read_record(tmp_path / "compact", steps=bad)


def test_read_run_names_the_file_it_cannot_read(tmp_path):
    with np.testing.assert_raises_regex(canopy.ScenarioError, "manifest.json: missing"):
        canopy.read_run(str(tmp_path))


def test_run_writes_frames(tmp_path):
    s = canopy.load("demo", overrides={"clock.duration": 1.0})  # K = 5
    canopy.run(s, tmp_path, frames=True, frame_every=2, size=(64, 48))
    frames = sorted(p.name for p in (tmp_path / "frames").iterdir())
    assert frames == ["frame_000000.png", "frame_000002.png", "frame_000004.png"]


def _sweep_file(tmp_path):
    path = tmp_path / "sweep.json"
    path.write_text(json.dumps({
        "name": "tiny", "scenario": "demo", "trials": 2, "seed": 4,
        "set": {"clock.duration": 2.0},
        "axes": [{"path": "uavs.0.v_max", "values": [2, 4]}]}))
    return path


def test_sweep_writes_the_clis_trials(tmp_path, cli):
    file = _sweep_file(tmp_path)
    assert canopy.sweep(file, tmp_path / "py", jobs=2) == 4  # 2 configurations × 2 trials
    assert canopy.sweep(file, tmp_path / "py") == 0          # resumed: nothing left to run
    cli("sweep", file, "--out", tmp_path / "cli", "--jobs", "1")
    py_trials = sorted(p.relative_to(tmp_path / "py") for p in (tmp_path / "py" / "trials").rglob("*") if p.is_file())
    cli_trials = sorted(p.relative_to(tmp_path / "cli") for p in (tmp_path / "cli" / "trials").rglob("*") if p.is_file())
    assert py_trials == cli_trials and len(py_trials) == 4
    for rel in py_trials:
        assert (tmp_path / "py" / rel).read_bytes() == (tmp_path / "cli" / rel).read_bytes()


def test_analyze_returns_tables_as_arrays(tmp_path):
    file = _sweep_file(tmp_path)
    canopy.sweep(file, tmp_path / "s", jobs=2)
    tables = canopy.analyze(tmp_path / "s")
    assert {"coverage", "tracking"} <= set(tables)
    coverage = tables["coverage"]
    # demo: 3 targets; duration 2 s at dt 0.2 → steps 0..10; 2 configurations.
    assert len(coverage["step"]) == 2 * 3 * 11
    assert coverage["mean_coverage"].dtype == np.float64
    assert set(coverage["config"]) == set(np.unique(coverage["config"])) and len(set(coverage["config"])) == 2
    tracking = tables["tracking"]
    np.testing.assert_allclose(np.unique(tracking["t_s"]), np.arange(11) * 0.2, atol=1e-9)
    assert (tmp_path / "s" / "analysis" / "coverage.csv").exists()
