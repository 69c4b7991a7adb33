"""Steps a scenario to its end RUNS times from Python: the comparison with bench/step_loop.cpp.

    PYTHONPATH=build/release/python /usr/bin/python3 bench/step_loop.py SCENARIO RUNS [SEED]

One untimed warm-up run comes first; callgrind slopes (runs N2 − N1) cancel it and the imports.
"""
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


if __name__ == "__main__":
    main()
