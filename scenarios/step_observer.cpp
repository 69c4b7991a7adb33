#include "scenarios/step_observer.h"

namespace canopy::scenarios {

void runToEnd(Simulation& sim, std::span<StepObserver* const> observers) {
  while (!sim.done()) {
    sim.tick();
    for (StepObserver* observer : observers) observer->onStep(sim);
  }
}

}  // namespace canopy::scenarios
