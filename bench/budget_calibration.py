#!/usr/bin/env python3
"""The work budget's estimate against measured instructions (issue 48): for a grid of scenarios,
runs `canopy run` under callgrind, splits the instructions by stage (inclusive cost of each stage's
entry function) and prints them beside `canopy validate`'s estimate per stage, with the ratio.

    bench/budget_calibration.py build/release/app/canopy --out /tmp/calibration  # the whole grid
    bench/budget_calibration.py build/release/app/canopy --only th,ra          # some rows

The coefficients in spec/budget.cpp (kInstructionsPer…) are instructions per unit of each stage's
term; after speed work, multiply each by the geometric mean of its stage's measured / estimate
column (printed last) and run this again. Needs valgrind; a whole grid takes about an hour on two
shared cores (callgrind runs about 50 times slower than the program).
"""
import argparse
import math
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from scale_point import scale_point  # noqa: E402

# Each stage's measured instructions: the inclusive cost of its entry function (callgrind names).
STAGES = [
    ("planning_search", [r"canopy::agents::Team::plan\(int\)"]),  # less the two below
    ("planning_penalty", [r"canopy::agents::planning::NominalCost::addTerminalPenalty\(int, double\)"]),
    ("planning_prepare", [r"canopy::agents::planning::NominalCost::prepare\("]),
    ("fusion", [r"canopy::agents::Team::fuse\(\)"]),
    ("tracking", [r"canopy::agents::Team::trackLocally\("]),
    ("sensing", [r"canopy::sensing::sense\(", r"canopy::sensing::footprintOf\("]),
    ("world", [r"canopy::world::World::step\(double\)", r"canopy::sim::Simulation::readTruth\(\)"]),
    ("metrics", [r"canopy::sim::SummaryBuilder::onStep\("]),
    ("setup", [r"canopy::spec::loadScenario\(", r"canopy::sim::Simulation::Simulation\("]),
]

# (row name, how to make it): a scale point (U, M, trees, duration, algorithm) or a library name
# with --set overrides.
GRID = [
    ("4x16x1e3", ("scale", 4, 16, 1000, 4.0, "sma")),
    ("16x64x1e4", ("scale", 16, 64, 10000, 4.0, "sma")),
    ("16x256x1e4", ("scale", 16, 256, 10000, 4.0, "sma")),
    ("16x64x1e5", ("scale", 16, 64, 100000, 4.0, "sma")),
    ("64x256x1e5", ("scale", 64, 256, 100000, 2.0, "sma")),
    ("256x1024x1e6 1s", ("scale", 256, 1024, 1000000, 1.0, "sma")),
    ("4x16x1e3 dec", ("scale", 4, 16, 1000, 4.0, "dec_pomdp")),
    ("16x64x1e4 dec", ("scale", 16, 64, 10000, 2.0, "dec_pomdp")),
    ("th", ("library", "trajectory_handover", [])),
    ("ra", ("library", "resource_allocation", [])),
    ("je", ("library", "joint_effect", [])),
    ("os", ("library", "occlusion_sharing", [])),
    ("city_swarm 4s", ("library", "city_swarm", ["clock.duration=4"])),
]


def scenario_args(row, out):
    kind = row[1][0]
    if kind == "library":
        _, name, sets = row[1]
        return [name] + [a for s in sets for a in ("--set", s)]
    _, u, m, n, duration, algorithm = row[1]
    import json
    spec = scale_point(u, m, n, seed=21, duration=duration)
    spec["planner"]["algorithm"] = algorithm
    path = os.path.join(out, re.sub(r"\W+", "_", row[0]) + ".json")
    with open(path, "w") as f:
        json.dump(spec, f)
    return [path]


def estimate(canopy, args):
    text = subprocess.run([canopy, "validate", *args, "--budget", "1e6"], capture_output=True,
                          text=True, check=True).stdout
    m = re.search(r"work by stage \(instructions\): (.*)", text)
    stages = dict((k, float(v)) for k, v in re.findall(r"(\w+) ([\d.e+-]+)", m.group(1)))
    total = float(re.search(r"work: about ([\d.e+-]+) instructions", text).group(1))
    return total, stages


def measure(canopy, args, out, name):
    base = os.path.join(out, re.sub(r"\W+", "_", name))
    cg = base + ".callgrind"
    if not os.path.exists(cg):
        subprocess.run(["valgrind", "--tool=callgrind", f"--callgrind-out-file={cg}", canopy,
                        "run", *args, "--threads", "1", "--budget", "1e6", "--out", base + "_run"],
                       check=True, capture_output=True)
    text = subprocess.run(["callgrind_annotate", "--inclusive=yes", "--threshold=100", cg],
                          capture_output=True, text=True, check=True).stdout
    total = float(re.search(r"([\d,]+) \(100.0%\)\s+PROGRAM TOTALS", text).group(1).replace(",", ""))
    measured = {}
    for stage, patterns in STAGES:
        measured[stage] = 0.0
        for pattern in patterns:
            for line in text.splitlines():
                m = re.match(r"\s*([\d,]+) \([^)]*\)\s+[^: ]*:(.*)$", line)
                if m and re.match(pattern, m.group(2)):
                    measured[stage] += float(m.group(1).replace(",", ""))
                    break
    measured["planning_search"] -= measured["planning_penalty"] + measured["planning_prepare"]
    measured["record"] = total - sum(measured.values())  # observers, metrics, the rest
    return total, measured


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("canopy", help="the canopy program (Release)")
    p.add_argument("--out", default="/tmp/budget_calibration")
    p.add_argument("--only", default="", help="comma-separated row names (default: all)")
    p.add_argument("--measure-only", action="store_true", help="callgrind only, no estimate")
    args = p.parse_args()
    os.makedirs(args.out, exist_ok=True)
    rows = [r for r in GRID if not args.only or r[0] in args.only.split(",")]
    ratios = {}
    print("| file | measured Ir | estimate | estimate / measured | by stage, estimate / measured |")
    print("|---|---:|---:|---:|---|")
    for row in rows:
        run_args = scenario_args(row, args.out)
        total, measured = measure(args.canopy, run_args, args.out, row[0])
        if args.measure_only:
            print(row[0], f"{total:.3e}", " ".join(f"{k} {v:.3e}" for k, v in measured.items()),
                  flush=True)
            continue
        est_total, est = estimate(args.canopy, run_args)
        parts = []
        for stage, value in measured.items():
            if stage in est and value > 0:
                parts.append(f"{stage} {est[stage]:.2g}/{value:.2g}")
                if value > 0.01 * total:  # a stage that matters in this row
                    ratios.setdefault(stage, []).append(est[stage] / value)
        ratios.setdefault("total", []).append(est_total / total)
        print(f"| {row[0]} | {total:.3g} | {est_total:.3g} | {est_total / total:.2f} | "
              f"{', '.join(parts)} |", flush=True)
    if args.measure_only:
        return
    print()
    for stage, values in ratios.items():
        g = math.exp(sum(math.log(v) for v in values) / len(values))
        worst = max(values, key=lambda v: max(v, 1 / v))
        print(f"{stage}: geometric mean estimate/measured {g:.2f}, worst {worst:.2f} "
              f"over {len(values)} rows (those where it is at least 1 % of the run)"
              + ("" if stage == "total" else f"; its coefficient times {1 / g:.3g} fits them"))


if __name__ == "__main__":
    main()
