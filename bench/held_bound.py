#!/usr/bin/env python3
"""An optimistic bound on "people held" (issue 46): what a UAV team could hold if every UAV knew
where every person is at every instant and saw perfectly.

    bench/held_bound.py SCENARIO.json [--policy nearest|largest_error|tracks_only] [--duration S]

Each person belongs to the UAV whose start is nearest to the person's start. Each UAV flies at
its v_max (default 5 m/s) straight toward its goal, re-chosen every step of the scenario's dt:
  - the centre of its people's bounding box when that box fits in the footprint less a 1 m margin;
  - otherwise, with `nearest` (the default), the nearest of its people not in view whose track
    error exceeds half the hold distance (else the nearest one not in view); with
    `largest_error`, the one not in view whose track error is largest.
With `tracks_only` the UAV knows no truth, only its tracks: the box and the goal are the tracks'
predicted positions, and the goal is the nearest prediction of a person not seen for over 1 s
that the UAV has not reached (and found empty) in the last 3 s; with none, the box's centre.
That is no bound but a simple policy in the same ideal sensing, a yardstick for planners.
Every person inside a footprint (axis-aligned `fov.size`, or a `fov.radius` disc) is seen, with no
occlusion and no noise, and its track becomes its true position and velocity; unseen, the track
moves at that velocity (constant-velocity prediction). A person is held at a step when its track
lies within 5 m of it, the distance of `canopy run`'s team measure (which also asks the person to
lie in the track's 99 % ellipse: a bound on it too).

The UAVs know the truth, never miss a person, never mistake one person for another and share
nothing they need not: `canopy` can do no better by this measure than a planner that knows the
future, and greedy policies are not that planner, so this is an estimate of what is reachable,
optimistic in sensing and pessimistic in planning. It reads waypoint and constant-velocity paths.
"""
import argparse
import json
import math
import sys

HOLD_DISTANCE = 5.0  # m, sim/team_metrics.h's hold distance


def fail(message):
    sys.stderr.write(f"held_bound: {message}\n")
    sys.exit(2)


def load(path):
    try:
        with open(path) as f:
            text = "".join(line for line in f if not line.lstrip().startswith("//"))
        return json.loads(text)
    except (OSError, ValueError) as error:
        fail(f"{path}: {error}")


class Path:
    """A target's scripted path: position and velocity at time t."""

    def __init__(self, source, field):
        path = source.get("path")
        if not isinstance(path, dict):
            fail(f"{field}.path: expected an object")
        if "waypoints" in path:
            self.points = [(float(w["t"]), float(w["p"][0]), float(w["p"][1]))
                           for w in path["waypoints"]]
            self.extrapolate = False
        elif "start" in path and "velocity" in path:
            x, y = map(float, path["start"])
            vx, vy = map(float, path["velocity"])
            self.points = [(0.0, x, y), (1.0, x + vx, y + vy)]
            self.extrapolate = True
        else:
            fail(f"{field}.path: this bound reads waypoint and constant-velocity paths only")

    def at(self, t):
        pts = self.points
        if len(pts) == 1:
            return (pts[0][1], pts[0][2]), (0.0, 0.0)
        for a, b in zip(pts, pts[1:]):
            if t <= b[0] or (self.extrapolate and b is pts[-1]):
                span = b[0] - a[0]
                v = ((b[1] - a[1]) / span, (b[2] - a[2]) / span) if span > 0 else (0.0, 0.0)
                f = (t - a[0]) / span if span > 0 else 0.0
                return (a[1] + f * (b[1] - a[1]), a[2] + f * (b[2] - a[2])), v
        return (pts[-1][1], pts[-1][2]), (0.0, 0.0)  # standing at its last waypoint


def in_footprint(fov, uav, p):
    dx, dy = p[0] - uav[0], p[1] - uav[1]
    if "radius" in fov:
        return math.hypot(dx, dy) <= float(fov["radius"])
    w, h = map(float, fov.get("size", [20.0, 20.0]))
    return abs(dx) <= w / 2 and abs(dy) <= h / 2


def half_extent(fov):
    if "radius" in fov:
        r = float(fov["radius"]) / math.sqrt(2.0)  # the square inscribed in the disc
        return r, r
    w, h = map(float, fov.get("size", [20.0, 20.0]))
    return w / 2, h / 2


def bound(spec, policy="nearest", duration=None):
    """Fraction of (step, person) pairs held, and the fraction held at the last step."""
    dt = float(spec.get("clock", {}).get("dt", 0.2))
    duration = float(duration if duration is not None else spec.get("clock", {}).get("duration", 30.0))
    steps = int(round(duration / dt)) + 1
    people = [Path(t, f"targets[{j}]") for j, t in enumerate(spec.get("targets", []))]
    uavs = spec.get("uavs", [])
    if not uavs or not people:
        fail("the scenario needs uavs and targets")
    starts = [tuple(map(float, u["start"])) for u in uavs]
    owner = [min(range(len(uavs)), key=lambda i: math.dist(starts[i], p.at(0.0)[0])) for p in people]
    held_pairs, held_last = 0, 0
    track = [p.at(0.0) + (0.0,) for p in people]  # (position, velocity, time seen)
    positions = list(starts)
    looked = {}  # tracks_only: person -> when the UAV last reached its prediction
    for k in range(steps):
        t = k * dt
        truth = [p.at(t) for p in people]
        held_now = 0
        estimate = []
        for j, (p, v) in enumerate(truth):
            i = owner[j]
            fov = uavs[i].get("fov", {})
            if in_footprint(fov, positions[i], p):
                track[j] = (p, v, t)
            (tp, tv, ts) = track[j]
            e = (tp[0] + tv[0] * (t - ts), tp[1] + tv[1] * (t - ts))  # constant velocity
            estimate.append(e)
            if math.dist(e, p) <= HOLD_DISTANCE:
                held_now += 1
        held_pairs += held_now
        held_last = held_now
        for i, u in enumerate(uavs):
            mine = [j for j in range(len(people)) if owner[j] == i]
            if not mine:
                continue
            fov = u.get("fov", {})
            hx, hy = half_extent(fov)
            # Where the UAV believes its people are: the truth, or (tracks_only) its tracks.
            where = {j: estimate[j] if policy == "tracks_only" else truth[j][0] for j in mine}
            xs = [where[j][0] for j in mine]
            ys = [where[j][1] for j in mine]
            if max(xs) - min(xs) <= 2 * hx - 2 and max(ys) - min(ys) <= 2 * hy - 2:
                goal = ((max(xs) + min(xs)) / 2, (max(ys) + min(ys)) / 2)
            else:
                here = positions[i]
                unseen = [j for j in mine if not in_footprint(fov, here, truth[j][0])] or mine
                error = {j: math.dist(estimate[j], truth[j][0]) for j in unseen}
                if policy == "tracks_only":
                    stale = [j for j in unseen
                             if t - track[j][2] > 1.0 and t - looked.get(j, -math.inf) > 3.0]
                    if stale:
                        target = min(stale, key=lambda j: (math.dist(here, where[j]), j))
                        if math.dist(here, where[target]) <= 1.0:
                            looked[target] = t  # reached its prediction: not there
                        goal = where[target]
                    else:
                        goal = ((max(xs) + min(xs)) / 2, (max(ys) + min(ys)) / 2)
                else:
                    if policy == "largest_error":
                        target = max(unseen, key=lambda j: (error[j], -j))
                    else:
                        drifting = [j for j in unseen if error[j] > HOLD_DISTANCE / 2] or unseen
                        target = min(drifting, key=lambda j: (math.dist(here, truth[j][0]), j))
                    goal = truth[target][0]
            step = float(u.get("v_max", 5.0)) * dt
            d = math.dist(goal, positions[i])
            if d <= step:
                positions[i] = goal
            else:
                positions[i] = (positions[i][0] + (goal[0] - positions[i][0]) * step / d,
                                positions[i][1] + (goal[1] - positions[i][1]) * step / d)
    return held_pairs / (steps * len(people)), held_last / len(people)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("scenario")
    parser.add_argument("--policy", choices=["nearest", "largest_error", "tracks_only"], default="nearest")
    parser.add_argument("--duration", type=float, default=None, help="simulated seconds")
    args = parser.parse_args()
    if args.duration is not None and not (args.duration >= 0 and math.isfinite(args.duration)):
        fail(f"--duration: expected a finite number >= 0, got {args.duration}")
    held, last = bound(load(args.scenario), args.policy, args.duration)
    what = "a tracks-only policy holds" if args.policy == "tracks_only" else "bound on people held"
    print(f"{args.scenario}: {what} {100 * held:.1f} % of (step, person) pairs, "
          f"{100 * last:.1f} % at the end ({args.policy})")


if __name__ == "__main__":
    main()
