"""Steps a scenario to its end RUNS times from Python: the comparison with bench/step_loop.cpp.

    PYTHONPATH=build/release/python /usr/bin/python3 bench/step_loop.py SCENARIO RUNS [SEED]

One untimed warm-up run comes first; callgrind slopes (runs N2 − N1) cancel it and the imports.

    PYTHONPATH=... /usr/bin/python3 bench/step_loop.py --vector N SCENARIO STEPS PAIRS [--keep-planner]

canopy.VectorEnv(N, SCENARIO) (planner off unless --keep-planner) stepped STEPS times with zero
actions (autoresets included) on one thread and on one thread per core, PAIRS alternating pairs
of timings: prints the env-steps per second of each (median and best of the pairs) and the
median of the pair ratios. Each round also times one thread pinned to each core in turn: the
threads' rate over the sum of those is the share of the machine they use, which holds when the
cores differ in speed (a virtual machine's may: one core 1.65× slower than the other, measured).

    PYTHONPATH=... /usr/bin/python3 bench/step_loop.py --vector-once N SCENARIO STEPS THREADS

canopy.VectorEnv(N, SCENARIO, threads=THREADS) reset and stepped once, then STEPS times (for
callgrind slopes over STEPS).

    PYTHONPATH=... /usr/bin/python3 bench/step_loop.py --env SCENARIO RUNS [SEED]

canopy.TrackingEnv(SCENARIO) reset and stepped to its end RUNS times with zero actions (after one
untimed episode): for callgrind, whose slope over RUNS against Simulation::tick()'s inclusive
count is the environment's overhead per step.
"""
import statistics
import sys
import time

import canopy


def main():
    name, runs = sys.argv[1], int(sys.argv[2])
    seed = int(sys.argv[3]) if len(sys.argv) > 3 else None
    scenario = canopy.load(name)
    checksum, building, stepping = 0.0, 0.0, 0.0
    # One run first, not timed: the first numpy view makes pybind11 import parts of numpy (~20 000
    # Python objects, tens of ms), once per process.
    for run in range(-1, runs):
        t0 = time.perf_counter()
        sim = canopy.Simulation(scenario, seed=seed)  # builds and runs step 0
        checksum += sim.uav_states[0, 0]
        t1 = time.perf_counter()
        while not sim.done:
            sim.step()
            checksum += sim.uav_states[0, 0]
        t2 = time.perf_counter()
        if run >= 0:
            building += t1 - t0
            stepping += t2 - t1
        del sim  # destroyed outside the timing, as the C++ loop's is
    n = max(runs, 1)
    print(f"{scenario.name}: {runs} runs; per run: build + step 0 {building / n * 1e6:.1f} us, "
          f"steps 1..K {stepping / n * 1e6:.1f} us (checksum {checksum:.6f})")


def env_loop(name, runs, seed):
    import numpy as np

    env = canopy.TrackingEnv(name)
    zero = {a: np.zeros(2) for a in env.possible_agents}
    steps, t = 0, 0.0
    for run in range(-1, runs):
        env.reset(seed=seed)
        t0 = time.perf_counter()
        while env.agents:
            env.step(zero)
            steps += run >= 0
        t += (time.perf_counter() - t0) if run >= 0 else 0.0
    print(f"TrackingEnv({name!r}): {runs} episodes, {steps} steps, {t / max(steps, 1) * 1e6:.1f} us a step")


def vector(n, name, steps, pairs, keep_planner=False):
    import os

    import numpy as np

    envs = {label: canopy.VectorEnv(n, name, threads=threads, keep_planner=keep_planner)
            for label, threads in (("1 thread", 1), ("threads", None))}
    zero = np.zeros(envs["threads"].action_space.shape)
    cores = sorted(os.sched_getaffinity(0))
    rates = {label: [] for label in envs}
    on_core = {c: [] for c in cores}  # one thread, pinned to core c

    def rate(env):
        env.reset(seed=0)
        env.step(zero)  # warm-up step: first-touch of the buffers
        t0 = time.perf_counter()
        for _ in range(steps):
            env.step(zero)
        return n * steps / (time.perf_counter() - t0)

    for _ in range(pairs):
        for label, env in envs.items():
            rates[label].append(rate(env))
        for c in cores:
            os.sched_setaffinity(0, {c})
            on_core[c].append(rate(envs["1 thread"]))
        os.sched_setaffinity(0, cores)
    ratios = [b / a for a, b in zip(rates["1 thread"], rates["threads"])]
    # Against the sum of what one thread does on each core: the share of the cores' capacity the
    # threads use, which does not depend on the cores being equally fast.
    efficiency = [t / sum(on_core[c][k] for c in cores) for k, t in enumerate(rates["threads"])]
    print(f"VectorEnv({n}, {name!r}): {steps} steps x {pairs} pairs; "
          f"threads = {envs['threads'].threads}")
    for label, r in rates.items():
        print(f"  {label:9}: env-steps/s median {statistics.median(r):9.0f}, best {max(r):9.0f}")
    for c, r in on_core.items():
        print(f"  on core {c} : env-steps/s median {statistics.median(r):9.0f}, best {max(r):9.0f}")
    print(f"  speed-up: median of pair ratios {statistics.median(ratios):.3f}, "
          f"best/best {max(rates['threads']) / max(rates['1 thread']):.3f}")
    print(f"  threads' rate / sum of one thread's rate on each core: median "
          f"{statistics.median(efficiency):.3f} (× {len(cores)} = the speed-up on equal cores)")


if __name__ == "__main__":
    if sys.argv[1] == "--env":
        env_loop(sys.argv[2], int(sys.argv[3]), int(sys.argv[4]) if len(sys.argv) > 4 else 1)
    elif sys.argv[1] == "--vector-once":
        import numpy as np

        v = canopy.VectorEnv(int(sys.argv[2]), sys.argv[3], threads=int(sys.argv[5]))
        v.reset(seed=0)
        zero = np.zeros(v.action_space.shape)
        for _ in range(1 + int(sys.argv[4])):
            v.step(zero)
    elif sys.argv[1] == "--vector":
        vector(int(sys.argv[2]), sys.argv[3], int(sys.argv[4]), int(sys.argv[5]),
               keep_planner=sys.argv[6:] == ["--keep-planner"])
    else:
        main()
