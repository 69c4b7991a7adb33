#!/usr/bin/env python3
"""Writes a scale-point scenario as a new user would write it: U UAVs, M people, about N trees, and
canopy's defaults for everything the user does not name (issue 46).

What the user names: 20 x 20 m footprints; a Poisson forest of 0.005 trees per m^2 with crowns of
radius 2.5 m (its side is sqrt(N / 0.005)); the UAVs on a square grid, one per cell; the people in
groups of about M/U around each UAV's start (within --spread m), each walking at a constant velocity
of up to 1.4 m/s in a uniform direction; SMA-NBO with H = 5 on the a-priori map. Tracking, fusion
(full communication, no interest range), the cost's scope and every other field stay at canopy's
defaults. Everything is a function of --seed (Python's random.Random).

    bench/scale_point.py 16 64 10000 --seed 3 > s.json
"""
import argparse
import json
import math
import random
import sys


def scale_point(uavs, people, trees, seed, duration=20.0, spread=15.0, speed=1.4, density=0.005):
    rng = random.Random(seed)
    side = math.sqrt(trees / density) if trees else 200.0
    grid = math.ceil(math.sqrt(uavs))
    cell = side / grid
    starts = [((c + 0.5) * cell, (r + 0.5) * cell) for r in range(grid) for c in range(grid)][:uavs]
    targets = []
    for k in range(people):
        cx, cy = starts[k % uavs]
        r = spread * math.sqrt(rng.random())
        a = rng.uniform(0.0, 2.0 * math.pi)
        x = min(max(cx + r * math.cos(a), 0.0), side)
        y = min(max(cy + r * math.sin(a), 0.0), side)
        v = speed * rng.random()
        h = rng.uniform(0.0, 2.0 * math.pi)
        targets.append({"name": f"p{k + 1}",
                        "path": {"start": [round(x, 3), round(y, 3)],
                                 "velocity": [round(v * math.cos(h), 4), round(v * math.sin(h), 4)]}})
    scenario = {
        "name": f"scale_{uavs}_{people}_{trees}_s{seed}",
        "aoi": [0, 0, round(side, 3), round(side, 3)],
        "clock": {"duration": duration},
        "seed": seed,
        "uavs": [{"name": f"uav{i + 1}", "start": [round(p[0], 3), round(p[1], 3)],
                  "fov": {"size": [20, 20]}} for i, p in enumerate(starts)],
        "targets": targets,
        "planner": {"algorithm": "sma", "horizon": 5, "occlusion_map": "a_priori"},
    }
    if trees:
        scenario["occluders"] = [{"type": "poisson", "lambda": density, "radius": 2.5, "seed": seed}]
    return scenario


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("uavs", type=int)
    p.add_argument("people", type=int)
    p.add_argument("trees", type=int)
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--duration", type=float, default=20.0, help="simulated seconds")
    p.add_argument("--spread", type=float, default=15.0, help="people start this close to a UAV (m)")
    args = p.parse_args()
    if args.uavs < 1 or args.people < 0 or args.trees < 0 or args.seed < 0:
        p.error("uavs >= 1, people >= 0, trees >= 0 and seed >= 0")
    json.dump(scale_point(args.uavs, args.people, args.trees, args.seed, args.duration, args.spread),
              sys.stdout, indent=1)
    sys.stdout.write("\n")


if __name__ == "__main__":
    main()
