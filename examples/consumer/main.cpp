// Uses canopy as an installed library: loads a scenario (a file, or a built-in name), runs it
// step by step and prints where the first target is and how many tracks the first agent holds.
#include <cstdio>
#include <string>

#include "scenarios/error.h"
#include "scenarios/loader.h"
#include "scenarios/simulation.h"

int main(int argc, char** argv) {
  const std::string scenario = argc > 1 ? argv[1] : "demo";
  try {
    canopy::scenarios::LoadOptions load;
    load.overrides = {"clock.duration=2"};
    canopy::scenarios::Simulation sim(canopy::scenarios::loadScenario(scenario, load));
    int steps = 0;
    std::size_t tracks = 0;
    while (!sim.done()) {
      const canopy::scenarios::StepRecord& step = sim.tick();
      ++steps;
      tracks = step.beliefs.empty() ? 0 : step.beliefs[0].tracks.size();
    }
    std::printf("%s: %d steps, agent 0 holds %zu tracks\n", scenario.c_str(), steps, tracks);
  } catch (const canopy::scenarios::ScenarioError& e) {
    std::fprintf(stderr, "consumer: %s\n", e.what());
    return 2;
  }
  return 0;
}
