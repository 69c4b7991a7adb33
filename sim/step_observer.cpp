#include "sim/step_observer.h"

#include "sim/simulation.h"

namespace canopy::sim {

void runToEnd(Simulation& sim, std::span<StepObserver* const> observers) {
  while (!sim.done()) {
    const StepRecord& record = sim.tick();
    for (StepObserver* observer : observers) observer->onStep(record);
  }
}

}  // namespace canopy::sim
