"""examples/ppo_vector.py: PPO in PyTorch on canopy.VectorEnv, and its learning curve. Skipped
where PyTorch (Debian python3-torch, about 1 GB) is not installed: CI does not install it."""
import csv
import pathlib
import subprocess
import sys

import pytest

pytest.importorskip("torch")

EXAMPLE = pathlib.Path(__file__).resolve().parents[2] / "examples" / "ppo_vector.py"


def test_ppo_trains_and_plots_its_learning_curve(tmp_path):
    done = subprocess.run([sys.executable, str(EXAMPLE), "--out", str(tmp_path), "--envs", "2",
                           "--iterations", "3", "--steps", "16", "--duration", "2"],
                          capture_output=True, text=True, cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    rows = list(csv.DictReader(open(tmp_path / "learning_curve.csv")))
    assert [int(r["iteration"]) for r in rows] == [1, 2, 3]
    assert [int(r["env_steps"]) for r in rows] == [32, 64, 96]
    assert all(int(r["episodes"]) >= 2 and float(r["mean_return"]) < 0 for r in rows)  # K = 10
    assert (tmp_path / "learning_curve.pdf").read_bytes().startswith(b"%PDF-")
    assert (tmp_path / "learning_curve.png").read_bytes().startswith(b"\x89PNG")
