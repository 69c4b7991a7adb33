#!/usr/bin/env python3
"""Planning time per call of the learned planner beside SMA-NBO (issue 54): runs SCENARIO with
each algorithm for TRIALS seeds from SEED through `canopy run` and averages every planning call's
wall time in the runs' timings.jsonl (one entry per agent per epoch).

    bench/learned_timing.py --canopy build/release/app/canopy            # Trajectory Handover, seeds 5401–5420
    bench/learned_timing.py --canopy … --scenario trajectory_handover --trials 20 --seed 5401
"""
import argparse
import json
import math
import os
import subprocess
import sys
import tempfile


def mean_call_seconds(canopy, scenario, algorithm, trials, seed, extra):
    calls = []
    with tempfile.TemporaryDirectory() as tmp:
        for k in range(trials):
            out = os.path.join(tmp, f"{algorithm}_{k}")
            subprocess.run([canopy, "run", scenario, "--seed", str(seed + k), "--out", out,
                            "--set", f"planner.algorithm={algorithm}", *extra],
                           check=True, stdout=subprocess.DEVNULL)
            with open(os.path.join(out, "timings.jsonl"), encoding="utf-8") as f:
                for line in f:
                    calls += json.loads(line)["plan_seconds"]
    mean = sum(calls) / len(calls)
    sd = math.sqrt(sum((c - mean) ** 2 for c in calls) / (len(calls) - 1))
    return mean, sd, len(calls)


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--canopy", required=True)
    p.add_argument("--scenario", default="trajectory_handover")
    p.add_argument("--trials", type=int, default=20)
    p.add_argument("--seed", type=int, default=5401)
    p.add_argument("--set", action="append", default=[], metavar="PATH=VALUE")
    a = p.parse_args()
    extra = [x for s in a.set for x in ("--set", s)]
    rows = {alg: mean_call_seconds(a.canopy, a.scenario, alg, a.trials, a.seed, extra)
            for alg in ("learned", "sma")}
    for alg, (mean, sd, n) in rows.items():
        print(f"{alg:8s} {n:5d} calls  mean {mean * 1e6:10.2f} µs  sd {sd * 1e6:10.2f} µs")
    ratio = rows["sma"][0] / rows["learned"][0]
    print(f"SMA-NBO / learned: {ratio:.0f}× (bar: ≥ 50×)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
