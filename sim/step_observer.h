#pragma once
// The one place where a run's steps meet their observers (record, summary, trial collector,
// frames): every observer sees every step's record, in the order the observers were given,
// right after the tick that made it. Observers read the record and keep values; they hold no
// pointer or reference into it or into the simulation between steps, and get the static facts
// they need (names, dt) when they are made.
#include <span>

#include "sim/step_record.h"

namespace canopy::sim {

class Simulation;

class StepObserver {
 public:
  virtual ~StepObserver() = default;
  /// Step record.step has just run. The record is valid during the call only.
  virtual void onStep(const StepRecord& record) = 0;
};

/// Ticks `sim` until done(), handing each step's record to every observer in turn. An exception
/// from an observer stops the run and propagates.
void runToEnd(Simulation& sim, std::span<StepObserver* const> observers);

}  // namespace canopy::sim
