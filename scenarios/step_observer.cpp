#include "scenarios/step_observer.h"

#include "scenarios/simulation.h"

namespace canopy::scenarios {

void runToEnd(Simulation& sim, std::span<StepObserver* const> observers) {
  while (!sim.done()) {
    const StepRecord& record = sim.tick();
    for (StepObserver* observer : observers) observer->onStep(record);
  }
}

}  // namespace canopy::scenarios
