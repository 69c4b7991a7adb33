"""A Python policy flying the UAVs, against the built-in planner (issue 30). It trains nothing:
it shows the loop an RL policy sits in, and how to score it as `canopy run` scores a run.

    pip install .          # once, from the repository (README, "Python")
    python3 examples/python_policy.py [--scenario trajectory_handover] [--seed 1] [--out out/policy]

1. The built-in planner: canopy.run() writes its run folder (record, summary.json, PNG frames).
2. The policy: canopy.TrackingEnv (planner off) with a hand-written rule in Python — each UAV
   chases the nearest of the fused tracks that are nearer to it than to any teammate —
   stepped to the end, its frames rendered with env.render() into OUT/policy/frames/.
3. Both are scored the way summary.json scores targets (sim/summary.cpp): per target, the
   fraction of steps some UAV sees it ("visible") and the mean number of footprints on it
   ("coverage"). The Python tally is checked against the planner's summary.json first.
"""
import argparse
import json
import os
import struct
import sys
import zlib

import numpy as np

import canopy


def write_png(path, rgb):
    """An (h, w, 3) uint8 image as an 8-bit RGB PNG (filter Sub on every row), with zlib alone."""
    h, w, _ = rgb.shape
    row = rgb.reshape(h, w * 3).astype(np.int16)
    sub = np.concatenate([row[:, :3], row[:, 3:] - row[:, :-3]], axis=1) % 256
    raw = np.concatenate([np.ones((h, 1), np.uint8), sub.astype(np.uint8)], axis=1).tobytes()

    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))

    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
                + chunk(b"IDAT", zlib.compress(raw, 6)) + chunk(b"IEND", b""))


class Tally:
    """summary.json's per-target visibility and coverage, from a Simulation's scans."""

    def __init__(self, n_targets):
        self.steps, self.visible, self.coverage = 0, np.zeros(n_targets), np.zeros(n_targets)

    def add(self, sim):
        seen, footprints = np.zeros_like(self.visible), np.zeros_like(self.coverage)
        for i in range(sim.n_uavs):
            scan = sim.scan(i)
            seen[scan["visible"]] = 1
            np.add.at(footprints, scan["in_footprint"], 1)
        self.steps += 1
        self.visible += seen
        self.coverage += footprints

    def result(self):
        return {"visible_fraction": self.visible / self.steps, "mean_coverage": self.coverage / self.steps}


def policy(env):
    """Each UAV chases the nearest of its fused tracks that are nearer to it than to a teammate
    (of all its tracks when none is; it holds still without tracks), at most at v_max."""
    positions = env.sim.uav_states[:, :2]
    actions = {}
    for agent in env.agents:
        i = env.possible_agents.index(agent)
        tracks = env.sim.tracks(i)["means"][:, :2]
        if len(tracks):
            nearest = np.argmin(np.linalg.norm(tracks[:, None, :] - positions[None], axis=2), axis=1)
            mine = tracks[nearest == i] if np.any(nearest == i) else tracks
            goal = mine[np.argmin(np.linalg.norm(mine - positions[i], axis=1))]
        else:
            goal = positions[i]
        v = (goal - positions[i]) / env.dt
        v_max = env.action_space(agent).high[0]
        speed = np.linalg.norm(v)
        actions[agent] = v * (v_max / speed) if speed > v_max else v
    return actions


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--scenario", default="trajectory_handover")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--out", default="out/policy")
    parser.add_argument("--duration", type=float, help="shorten the scenario (s)")
    parser.add_argument("--frame-every", type=int, default=5)
    args = parser.parse_args(argv)
    scenario = canopy.load(args.scenario)
    if args.duration:
        scenario["clock.duration"] = args.duration
    os.makedirs(args.out, exist_ok=True)

    # 1. The built-in planner, as `canopy run --frames` runs it; the same run stepped here.
    planner_dir = os.path.join(args.out, "planner")
    summary = canopy.run(scenario, planner_dir, seed=args.seed, frames=True,
                         frame_every=args.frame_every, size=(480, 360))
    sim = canopy.Simulation(scenario, seed=args.seed)
    planner = Tally(sim.n_targets)
    planner.add(sim)
    while not sim.done:
        sim.step()
        planner.add(sim)
    for t, target in enumerate(summary["targets"]):  # the Python tally is summary.json's
        assert planner.result()["visible_fraction"][t] == target["visible_fraction"], target["name"]
        assert planner.result()["mean_coverage"][t] == target["mean_coverage"], target["name"]

    # 2. The Python policy in the loop.
    env = canopy.TrackingEnv(scenario, render_mode="rgb_array", render_size=(480, 360))
    env.reset(seed=args.seed)
    frames = os.path.join(args.out, "policy", "frames")
    os.makedirs(frames, exist_ok=True)
    mine = Tally(env.sim.n_targets)
    mine.add(env.sim)
    while env.agents:
        if env.sim.step_index % args.frame_every == 0:
            write_png(os.path.join(frames, f"frame_{env.sim.step_index:06d}.png"), env.render())
        env.step(policy(env))
        mine.add(env.sim)
    write_png(os.path.join(frames, f"frame_{env.sim.step_index:06d}.png"), env.render())

    # 3. The comparison.
    names = [t["name"] for t in summary["targets"]]
    result = {"scenario": scenario.name, "seed": args.seed, "targets": names,
              "planner": {k: v.tolist() for k, v in planner.result().items()},
              "policy": {k: v.tolist() for k, v in mine.result().items()}}
    with open(os.path.join(args.out, "comparison.json"), "w", encoding="utf-8") as f:
        json.dump(result, f, indent=2)
    print(f"{scenario.name}, seed {args.seed}: visible fraction (mean coverage) per target")
    print(f"{'target':>8}  {'planner':>15}  {'Python policy':>15}")
    for t, name in enumerate(names):
        p, q = planner.result(), mine.result()
        print(f"{name:>8}  {p['visible_fraction'][t]:6.3f} ({p['mean_coverage'][t]:5.3f})  "
              f"{q['visible_fraction'][t]:6.3f} ({q['mean_coverage'][t]:5.3f})")
    print(f"frames: {planner_dir}/frames/ and {frames}/")
    return result


if __name__ == "__main__":
    main(sys.argv[1:])
