#pragma once
// No NaN reaches an output: every state a tick produces (the world's truth, the commands, the
// agents' fused tracks and maps) is checked finite before any observer sees it. The first value
// that is not stops the run, naming the step, the body and the quantity; `canopy run` then exits
// with code 1 and leaves none of its files (sim/run.h).
#include <stdexcept>
#include <string>

#include "sim/step_record.h"

namespace canopy::sim {

/// A state that is not finite (NaN or ±inf), at the step, body and quantity what() names, e.g.
/// "step 3: uav 0 (UAV1) position is not finite (nan, nan): the world's step produced it".
class NonFiniteState : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Throws NonFiniteState at the first non-finite value of `record`, in the order: UAVs (position,
/// yaw, velocity, command), targets (position, velocity), then each agent's tracks (mean,
/// covariance) and trees (centre and radius, covariance). `names`: the UAVs' names, by index.
void checkFinite(const StepRecord& record, const std::vector<std::string>& names);

}  // namespace canopy::sim
