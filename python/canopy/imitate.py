"""Learned planners that imitate SMA-NBO (issue 54; docs/imitation.md).

    python3 -m canopy.imitate collect trajectory_handover --trials 20 --out demos.jsonl
    python3 -m canopy.imitate train --scenario trajectory_handover --trials 20 --out out/policy
    python3 -m canopy.imitate --help

``collect`` runs ``canopy imitate collect``: every agent's decision at every planning epoch as
(observation, expert action), the observation built by the same C++ code the learned planner flies
on. ``train`` needs PyTorch (Debian: ``apt-get install python3-torch``; only this part does):
behaviour cloning on SMA-NBO's demonstrations, then DAgger rounds in which the learned policy flies
and SMA-NBO labels the states it visits; it writes the policy file the C++ planner reads
(``planner.policy``), a checkpoint, the learning curve (PNG) and its log.
"""
import argparse
import json
import os
import shutil
import subprocess
import sys

FEATURES = {"self": 31, "track": 11, "mate": 7}  # agents/planning/observation.h
TORCH_HINT = ("canopy.imitate train needs PyTorch: install Debian's python3-torch "
              "(sudo apt-get install python3-torch) and run it with /usr/bin/python3")


def program():
    """The canopy program: $CANOPY_CLI, the installed package's, the build folder's, or PATH's."""
    candidates = [os.environ.get("CANOPY_CLI")]
    try:
        from . import _cli
        candidates.append(_cli.program())
    except ImportError:  # pragma: no cover - the package is always beside it
        pass
    here = os.path.dirname(os.path.abspath(__file__))
    candidates.append(os.path.join(here, "..", "..", "app", "canopy"))  # build/release/python/canopy
    candidates.append(shutil.which("canopy"))
    for path in candidates:
        if path and os.path.isfile(path) and os.access(path, os.X_OK):
            return os.path.abspath(path)
    raise RuntimeError("canopy.imitate: the canopy program was not found (set CANOPY_CLI)")


def collect(scenario, out, trials=1, seed=None, overrides=(), jobs=1, allow=()):
    """Writes ``trials`` trials' decisions of ``scenario`` to the demonstration file ``out`` (as
    ``canopy imitate collect``) and returns the number of decisions. ``overrides``: "PATH=VALUE"
    texts, as --set; with ``planner.algorithm=learned`` the policy flies and SMA-NBO labels.
    ``allow``: folders a policy file may also be read from (--allow-path)."""
    args = [program(), "imitate", "collect", str(scenario), "--out", str(out),
            "--trials", str(int(trials)), "--jobs", str(int(jobs))]
    if seed is not None:
        args += ["--seed", str(int(seed))]
    for text in overrides:
        args += ["--set", str(text)]
    for folder in allow:
        args += ["--allow-path", str(folder)]
    done = subprocess.run(args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if done.returncode != 0:
        raise RuntimeError(f"canopy imitate collect failed ({done.returncode}): {done.stderr.strip()}")
    return len(read_demonstrations(out)[1])


def read_demonstrations(path):
    """(header, decisions) of a demonstration file: the header dict and one dict per decision."""
    with open(path, encoding="utf-8") as f:
        lines = [json.loads(line) for line in f if line.strip()]
    if not lines or lines[0].get("format") != "canopy-demonstrations":
        raise ValueError(f"{path}: not a demonstration file (its first line is no header)")
    header = lines[0]
    if header.get("features") != FEATURES:
        raise ValueError(f"{path}: features {header.get('features')}, expected {FEATURES}")
    return header, lines[1:]


def evaluate(policy, observations_file):
    """The C++ network's outputs u for each observation line (``canopy imitate eval``)."""
    done = subprocess.run([program(), "imitate", "eval", str(policy), str(observations_file)],
                          stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if done.returncode != 0:
        raise RuntimeError(f"canopy imitate eval failed ({done.returncode}): {done.stderr.strip()}")
    return [json.loads(line) for line in done.stdout.splitlines() if line.strip()]


def _parser():
    p = argparse.ArgumentParser(
        prog="python3 -m canopy.imitate",
        description="Learned planners imitating SMA-NBO (docs/imitation.md). 'collect' needs only "
                    "the canopy program; 'train' also needs PyTorch (apt-get install python3-torch).")
    sub = p.add_subparsers(dest="action", required=True)
    c = sub.add_parser("collect", help="demonstrations of SCENARIO's planner (canopy imitate collect)")
    c.add_argument("scenario")
    c.add_argument("--out", required=True, help="the demonstration file (JSON lines)")
    c.add_argument("--trials", type=int, default=1)
    c.add_argument("--seed", type=int, default=None, help="the first trial's seed")
    c.add_argument("--jobs", type=int, default=1)
    c.add_argument("--set", action="append", default=[], metavar="PATH=VALUE")
    t = sub.add_parser("train", help="behaviour cloning, then DAgger with SMA-NBO as the expert")
    t.add_argument("--scenario", default="trajectory_handover")
    t.add_argument("--out", required=True, help="folder: policy.json, checkpoint.pt, "
                                                "learning_curve.png, training.jsonl, demonstrations")
    t.add_argument("--trials", type=int, default=20, help="trials per collection (default 20)")
    t.add_argument("--seed", type=int, default=1, help="the first trial's seed and torch's (default 1)")
    t.add_argument("--dagger", type=int, default=4, help="DAgger rounds after cloning (default 4)")
    t.add_argument("--epochs", type=int, default=150, help="epochs per round (default 150)")
    t.add_argument("--hidden", type=int, default=32, help="width of every hidden layer (default 32)")
    t.add_argument("--jobs", type=int, default=2, help="trials collected at once (default 2)")
    t.add_argument("--set", action="append", default=[], metavar="PATH=VALUE",
                   help="scenario overrides for every collection")
    return p


def main(argv=None):
    args = _parser().parse_args(argv)
    if args.action == "collect":
        n = collect(args.scenario, args.out, args.trials, args.seed, args.set, args.jobs)
        print(f"{args.out}: {n} decisions")
        return 0
    try:
        from . import _imitate_torch
    except ImportError as error:
        if "torch" not in str(error):
            raise
        sys.stderr.write(TORCH_HINT + "\n")
        return 2
    return _imitate_torch.train_command(args)


if __name__ == "__main__":
    sys.exit(main())
