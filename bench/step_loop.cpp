// Steps a scenario to its end `runs` times, the C++ side of the Python stepping comparison
// (bench/step_loop.py is the same loop from Python; bench/RESULTS.md, "Stepping from Python").
//   step_loop SCENARIO RUNS [SEED]   → prints the wall time per run
// One untimed warm-up run comes first; callgrind slopes (runs N2 − N1) cancel it and the loading.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "sim/simulation.h"
#include "spec/loader.h"

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: step_loop SCENARIO RUNS [SEED]\n");
    return 2;
  }
  canopy::spec::LoadOptions options;
  if (argc > 3) options.seed = std::strtoull(argv[3], nullptr, 10);
  const canopy::spec::ScenarioSpec spec = canopy::spec::loadScenario(argv[1], options);
  const int runs = std::atoi(argv[2]);
  using Clock = std::chrono::steady_clock;
  auto since = [](Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
  };
  double checksum = 0.0, building = 0.0, stepping = 0.0;
  for (int r = -1; r < runs; ++r) {  // run −1 warms up and is not timed, as in step_loop.py
    const auto t0 = Clock::now();
    canopy::sim::Simulation sim(spec);
    checksum += sim.tick().uavs[0].position.x();  // step 0, as canopy.Simulation's constructor
    building += since(t0);
    const auto t1 = Clock::now();
    while (!sim.done()) checksum += sim.tick().uavs[0].position.x();
    if (r < 0)
      building = stepping = 0.0;
    else
      stepping += since(t1);
  }
  const double n = runs ? runs : 1;
  std::printf("%s: %d runs; per run: build + step 0 %.1f us, steps 1..K %.1f us (checksum %.6f)\n",
              spec.name.c_str(), runs, building / n * 1e6, stepping / n * 1e6, checksum);
  return 0;
}
