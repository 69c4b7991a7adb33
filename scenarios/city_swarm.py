#!/usr/bin/env python3
"""Generates a city-swarm scenario: a team of UAVs over a square city of street trees and walking
people, scaled by the command line (issue 33). The built-in scenarios/library/city_swarm.json is

    scenarios/city_swarm.py --uavs 64 --people 256 --trees 100000 > scenarios/library/city_swarm.json

The UAVs start on a square grid, one per cell of the city; the people start in groups of
people/uavs around the UAVs' start points (within `--spread` m) and walk piecewise-straight
paths (a new heading every 6-14 s, 0.8-1.6 m/s, reflected at the city's edge). The trees are a
Poisson layout generator ({"type": "poisson"}) over the city, so the file stays small: the loader
draws them. Everything is a function of --seed (Python's random.Random, documented and stable).
"""
import argparse
import json
import math
import random
import sys


def positive_int(text):
    value = int(text)
    if value < 1:
        raise argparse.ArgumentTypeError(f"expected an integer >= 1, got {text}")
    return value


def non_negative_int(text):
    value = int(text)
    if value < 0:
        raise argparse.ArgumentTypeError(f"expected an integer >= 0, got {text}")
    return value


def positive_float(text):
    value = float(text)
    if not (value > 0.0 and math.isfinite(value)):
        raise argparse.ArgumentTypeError(f"expected a finite number > 0, got {text}")
    return value


def walk(rng, start, side, duration):
    """Waypoints of a person's walk: straight legs, reflected at the city's edge [0, side]²."""
    x, y = start
    t = 0.0
    points = [{"t": 0.0, "p": [round(x, 3), round(y, 3)]}]
    while t < duration:
        leg = min(rng.uniform(6.0, 14.0), duration - t)
        speed = rng.uniform(0.8, 1.6)
        heading = rng.uniform(0.0, 2.0 * math.pi)
        x += speed * leg * math.cos(heading)
        y += speed * leg * math.sin(heading)
        # Reflect into the city (a leg is at most 22.4 m, far shorter than the city).
        x = -x if x < 0.0 else (2.0 * side - x if x > side else x)
        y = -y if y < 0.0 else (2.0 * side - y if y > side else y)
        t += leg
        points.append({"t": round(t, 3), "p": [round(x, 3), round(y, 3)]})
    return points


def scenario(args):
    rng = random.Random(args.seed)
    side = args.side if args.side else math.sqrt(args.trees / args.tree_density) if args.trees else 500.0
    grid = math.ceil(math.sqrt(args.uavs))
    cell = side / grid
    starts = [((c + 0.5) * cell, (r + 0.5) * cell) for r in range(grid) for c in range(grid)]
    starts = starts[: args.uavs]
    uavs = [
        {"name": f"uav{i + 1}", "start": [round(p[0], 3), round(p[1], 3)], "fov": {"size": [20, 20]}}
        for i, p in enumerate(starts)
    ]
    targets = []
    for k in range(args.people):
        cx, cy = starts[k % len(starts)]
        r = args.spread * math.sqrt(rng.random())
        a = rng.uniform(0.0, 2.0 * math.pi)
        start = (min(max(cx + r * math.cos(a), 0.0), side), min(max(cy + r * math.sin(a), 0.0), side))
        targets.append({"name": f"p{k + 1}", "label": "human",
                        "path": {"waypoints": walk(rng, start, side, args.duration)}})
    occluders = []
    if args.trees:
        occluders.append({"type": "poisson", "region": [0, 0, round(side, 3), round(side, 3)],
                          "lambda": args.trees / (side * side), "radius": [1.0, 2.5],
                          "seed": args.seed})
    return {
        "name": args.name,
        "description": f"city swarm: {args.uavs} UAVs, {args.people} people, about {args.trees} "
                       f"trees over {side:.0f} x {side:.0f} m (scenarios/city_swarm.py)",
        "aoi": [0, 0, round(side, 3), round(side, 3)],
        "clock": {"dt": 0.2, "duration": args.duration},
        "seed": args.seed,
        "uavs": uavs,
        "targets": targets,
        "occluders": occluders,
        "tracking": {"preseed": True, "preseed_variance": [1, 1, 1, 1]},
        "fusion": {"method": "ci", "rounds": 5, "comm_range": args.comm_range,
                   "interest_range": args.interest_range},
        "planner": {"algorithm": args.planner, "horizon": 5, "occlusion_map": "dynamic",
                    "cost_scope": args.cost_scope},
    }


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--uavs", type=positive_int, default=64)
    p.add_argument("--people", type=non_negative_int, default=256)
    p.add_argument("--trees", type=non_negative_int, default=100000, help="expected tree count")
    p.add_argument("--tree-density", type=positive_float, default=0.025,
                   help="trees per m² when --side is not given (side = sqrt(trees / density))")
    p.add_argument("--side", type=positive_float, default=None, help="the city's side (m)")
    p.add_argument("--spread", type=positive_float, default=30.0,
                   help="people start within this distance of a UAV's start (m)")
    p.add_argument("--duration", type=positive_float, default=60.0, help="simulated seconds")
    p.add_argument("--comm-range", type=positive_float, default=250.0, help="fusion.comm_range (m)")
    p.add_argument("--interest-range", type=positive_float, default=150.0,
                   help="fusion.interest_range (m)")
    p.add_argument("--planner", choices=["sma", "dec_pomdp", "centralized", "none"], default="sma")
    p.add_argument("--cost-scope", choices=["team", "reach"], default="reach",
                   help="planner.cost_scope")
    p.add_argument("--seed", type=non_negative_int, default=1)
    p.add_argument("--name", default="city_swarm")
    args = p.parse_args()
    text = json.dumps(scenario(args), indent=1)
    sys.stdout.write(f"// Generated by scenarios/city_swarm.py {' '.join(sys.argv[1:])}\n{text}\n")


if __name__ == "__main__":
    main()
