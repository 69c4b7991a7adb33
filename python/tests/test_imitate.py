"""canopy.imitate (issue 54): the command line without torch, the C++ network against PyTorch's,
a policy trained on a hand-written rule reproducing it, and `train` end to end. The torch tests
skip when python3-torch is missing."""
import json
import os
import random
import subprocess
import sys

import pytest

from canopy import imitate

SELF, TRACK, MATE = imitate.FEATURES["self"], imitate.FEATURES["track"], imitate.FEATURES["mate"]
NO_TORCH = ("import sys, runpy; sys.modules['torch'] = None; sys.argv = ['canopy.imitate'] + "
            "sys.argv[1:]; runpy.run_module('canopy.imitate', run_name='__main__')")


def run_without_torch(*args):
    return subprocess.run([sys.executable, "-c", NO_TORCH, *args], capture_output=True, text=True)


def test_help_works_without_torch():
    done = run_without_torch("--help")
    assert done.returncode == 0, done.stderr
    assert "collect" in done.stdout and "train" in done.stdout
    assert "python3-torch" in done.stdout


def test_train_without_torch_names_the_package(tmp_path):
    done = run_without_torch("train", "--out", str(tmp_path / "p"))
    assert done.returncode == 2
    assert "apt-get install python3-torch" in done.stderr


def test_collect_writes_the_documented_format(cli, tmp_path):
    out = tmp_path / "d.jsonl"
    n = imitate.collect("trajectory_handover", out, trials=2, seed=7)
    header, decisions = imitate.read_demonstrations(out)
    assert header["format"] == "canopy-demonstrations" and header["expert"] == "sma"
    # 2 trials × 13 epochs (12 s, every 1 s, t = 0 included) × 2 agents.
    assert n == len(decisions) == 52
    d = decisions[0]
    assert len(d["self"]) == SELF and len(d["tracks"]) == 4 and len(d["mates"]) == 1
    assert all(len(row) == TRACK for row in d["tracks"]) and len(d["mates"][0]) == MATE
    assert d["expert"] == d["flown"]  # SMA-NBO flies its own decisions
    assert [x["seed"] for x in decisions[::26]] == [7, 8]


def test_collect_from_dec_pomdp(cli, tmp_path):
    out = tmp_path / "d.jsonl"
    assert imitate.collect("trajectory_handover", out, overrides=["planner.algorithm=dec_pomdp",
                                                                  "planner.horizon=2"]) == 26
    header, decisions = imitate.read_demonstrations(out)
    assert header["flown"] == header["expert"] == "dec_pomdp"
    # Epoch 0: nothing flown yet, the teammate's intention is hovering; later its flown plan.
    assert decisions[0]["mates"][0][2:6] == [0, 0, 0, 0]
    assert any(d["mates"][0][2:4] != [0, 0] for d in decisions[2:])


def random_observations(rng, n):
    out = []
    for k in range(n):
        t, m = k % 5, k % 3  # empty sets included
        out.append({"self": [rng.uniform(-1, 1) for _ in range(SELF)],
                    "tracks": [[rng.uniform(-1, 1) for _ in range(TRACK)] for _ in range(t)],
                    "mates": [[rng.uniform(-1, 1) for _ in range(MATE)] for _ in range(m)]})
    return out


def write_lines(path, rows):
    with open(path, "w", encoding="utf-8") as f:
        for row in rows:
            f.write(json.dumps(row) + "\n")


def torch_outputs(torch_module, model, observations, dtype):
    from canopy import _imitate_torch as it
    with torch_module.no_grad():
        outs = []
        for o in observations:  # one at a time: each its own set sizes
            outs.append(model(*it.batch([o], dtype=dtype))[0].tolist())
        return outs


def test_cpp_network_equals_pytorch(cli, tmp_path):
    torch = pytest.importorskip("torch")
    from canopy import _imitate_torch as it
    torch.manual_seed(3)
    model = it.DeepSetsPolicy(hidden=16)
    for p in model.parameters():  # weights large enough that every unit matters
        torch.nn.init.normal_(p, std=0.5)
    it.write_policy(model, tmp_path / "policy.json")
    observations = random_observations(random.Random(5), 60)
    write_lines(tmp_path / "obs.jsonl", observations)
    cpp = imitate.evaluate(tmp_path / "policy.json", tmp_path / "obs.jsonl")
    assert len(cpp) == 60
    ref64 = torch_outputs(torch, model.double(), observations, torch.float64)
    ref32 = torch_outputs(torch, model.float(), observations, torch.float32)
    worst64 = max(abs(a - b) for c, r in zip(cpp, ref64) for a, b in zip(c, r))
    worst32 = max(abs(a - b) for c, r in zip(cpp, ref32) for a, b in zip(c, r))
    assert worst64 < 1e-12
    assert worst32 < 1e-5
    spread = max(abs(x) for c in cpp for x in c)
    assert spread > 0.5  # not a network that says 0 to everything


def rule(observation):
    """Fly toward the mean of the tracks at v = mean offset / 1 s: u = 20 m · mean(dx, dy) / 5 m/s
    (features in units of 20 m, commands of v_max = 5 m/s); hover without tracks."""
    tracks = observation["tracks"]
    if not tracks:
        return [0.0, 0.0]
    return [4.0 * sum(t[0] for t in tracks) / len(tracks), 4.0 * sum(t[1] for t in tracks) / len(tracks)]


def test_a_policy_trained_on_a_rule_reproduces_it(cli, tmp_path):
    torch = pytest.importorskip("torch")
    from canopy import _imitate_torch as it
    torch.manual_seed(1)
    torch.set_num_threads(1)
    rng = random.Random(11)

    def sample(n):
        out = []
        for k in range(n):
            o = random_observations(rng, 1)[0]
            o["tracks"] = [[rng.uniform(-0.2, 0.2) if i < 2 else rng.uniform(-1, 1)
                            for i in range(TRACK)] for _ in range(1 + k % 4)]
            o["v_max"] = 5.0
            o["expert"] = [5.0 * u for u in rule(o)]
            out.append(o)
        return out

    train, held_out = sample(1200), sample(200)
    model = it.DeepSetsPolicy(hidden=16)
    losses = it.fit(model, train, epochs=60, seed=1, lr=3e-3)
    assert losses[-1] < losses[0] / 10
    it.write_policy(model, tmp_path / "rule.json")
    write_lines(tmp_path / "held_out.jsonl", held_out)
    cpp = imitate.evaluate(tmp_path / "rule.json", tmp_path / "held_out.jsonl")
    error = sum(abs(c - r) for o, out in zip(held_out, cpp) for c, r in zip(out, rule(o)))
    error /= 2 * len(held_out)
    hover = sum(abs(r) for o in held_out for r in rule(o)) / (2 * len(held_out))
    assert hover > 0.15  # the rule moves: saying 0 would be far off
    assert error < 0.03, (error, hover)


def test_train_end_to_end_is_seeded(cli, tmp_path):
    pytest.importorskip("torch")
    env = dict(os.environ)

    def train(out):
        args = [sys.executable, "-m", "canopy.imitate", "train", "--scenario", "trajectory_handover",
                "--trials", "2", "--dagger", "1", "--epochs", "3", "--hidden", "8", "--out", str(out)]
        done = subprocess.run(args, capture_output=True, text=True, env=env)
        assert done.returncode == 0, done.stderr
        return done

    done = train(tmp_path / "a")
    assert "round 1/1" in done.stderr  # the progress bar
    for name in ("policy.json", "checkpoint.pt", "learning_curve.png", "training.jsonl",
                 "demonstrations_0.jsonl", "demonstrations_1.jsonl"):
        assert (tmp_path / "a" / name).is_file(), name
    rounds = [json.loads(x) for x in open(tmp_path / "a" / "training.jsonl")]
    assert [r["round"] for r in rounds] == [0, 1] and rounds[1]["on_policy"] is not None
    header, dagger = imitate.read_demonstrations(tmp_path / "a" / "demonstrations_1.jsonl")
    assert header["flown"] == "learned" and header["expert"] == "sma"
    assert any(d["flown"] != d["expert"] for d in dagger)
    # The policy flies in canopy.
    cli("validate", "trajectory_handover", "--set", "planner.algorithm=learned", "--set",
        f"planner.policy={tmp_path / 'a' / 'policy.json'}", "--allow-path", str(tmp_path))
    train(tmp_path / "b")
    a = json.load(open(tmp_path / "a" / "policy.json"))
    b = json.load(open(tmp_path / "b" / "policy.json"))
    assert a["layers"] == b["layers"]  # the same seed, the same weights
