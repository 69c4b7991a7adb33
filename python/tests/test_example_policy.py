"""examples/python_policy.py: a Python policy in the loop against the built-in planner."""
import importlib.util
import json
import pathlib

import numpy as np

from png_reader import read_png

EXAMPLE = pathlib.Path(__file__).resolve().parents[2] / "examples" / "python_policy.py"


def _example():
    spec = importlib.util.spec_from_file_location("python_policy", EXAMPLE)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_png_writer_round_trips(tmp_path):
    example = _example()
    rgb = np.random.default_rng(3).integers(0, 256, (7, 5, 3), dtype=np.uint8)
    example.write_png(tmp_path / "x.png", rgb)
    np.testing.assert_array_equal(read_png(tmp_path / "x.png"), rgb)


def test_policy_against_planner(tmp_path, capsys):
    # 4 s of trajectory_handover (K = 20): the example itself asserts that its Python tally of
    # visibility and coverage equals the planner run's summary.json, target by target.
    result = _example().main(["--out", str(tmp_path), "--duration", "4", "--frame-every", "5"])
    assert result["targets"] == ["I", "II", "III", "IV"]
    saved = json.loads((tmp_path / "comparison.json").read_text())
    assert saved == result
    for who in ("planner", "policy"):
        for key in ("visible_fraction", "mean_coverage"):
            values = np.array(result[who][key])
            assert values.shape == (4,) and np.all(values >= 0)
        assert np.all(np.array(result[who]["visible_fraction"]) <= 1)
    frames = sorted((tmp_path / "policy" / "frames").glob("frame_*.png"))
    assert [f.name for f in frames] == [f"frame_{k:06d}.png" for k in (0, 5, 10, 15, 20)]
    assert read_png(frames[-1]).shape == (360, 480, 3)
    assert len(list((tmp_path / "planner" / "frames").glob("*.png"))) == 5
    assert "Python policy" in capsys.readouterr().out
