#pragma once
// The one place where a run's steps meet their observers (record, summary, trial collector,
// frames): every observer sees every step, in the order the observers were given, right after
// the tick that made it. Observers read the step and keep values; they hold nothing of the
// simulation between steps.
#include <span>

#include "scenarios/simulation.h"

namespace canopy::scenarios {

class StepObserver {
 public:
  virtual ~StepObserver() = default;
  /// Step sim.truth().step has just run.
  virtual void onStep(const Simulation& sim) = 0;
};

/// Ticks `sim` until done(), handing each step to every observer in turn. An exception from an
/// observer stops the run and propagates.
void runToEnd(Simulation& sim, std::span<StepObserver* const> observers);

}  // namespace canopy::scenarios
