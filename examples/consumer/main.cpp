// Uses canopy as an installed library: loads a scenario (a file, or a built-in name), runs it
// step by step and prints where the first target is and how many tracks the first agent holds.
#include <cstdio>
#include <string>

#include "sim/simulation.h"
#include "spec/error.h"
#include "spec/loader.h"

int main(int argc, char** argv) {
  const std::string scenario = argc > 1 ? argv[1] : "demo";
  try {
    canopy::spec::LoadOptions load;
    load.overrides = {"clock.duration=2"};
    canopy::sim::Simulation sim(canopy::spec::loadScenario(scenario, load));
    int steps = 0;
    std::size_t tracks = 0;
    while (!sim.done()) {
      const canopy::sim::StepRecord& step = sim.tick();
      ++steps;
      tracks = step.beliefs.empty() ? 0 : step.beliefs[0].tracks.size();
    }
    std::printf("%s: %d steps, agent 0 holds %zu tracks\n", scenario.c_str(), steps, tracks);
  } catch (const canopy::spec::ScenarioError& e) {
    std::fprintf(stderr, "consumer: %s\n", e.what());
    return 2;
  }
  return 0;
}
