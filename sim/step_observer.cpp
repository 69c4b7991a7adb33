#include "sim/step_observer.h"

#include "core/progress.h"
#include "sim/simulation.h"

namespace canopy::sim {

void runToEnd(Simulation& sim, std::span<StepObserver* const> observers) {
  // Steps k = 0 … steps(): one report each (a step is far more work than the report).
  ProgressCounter progress("running steps", sim.spec().steps() + 1.0, 1);
  while (!sim.done()) {
    progress.add();
    const StepRecord& record = sim.tick();
    for (StepObserver* observer : observers) observer->onStep(record);
  }
}

}  // namespace canopy::sim
