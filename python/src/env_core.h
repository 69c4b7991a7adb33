#pragma once
// The per-step work of canopy.TrackingEnv and canopy.VectorEnv in C++ (issue 30): an agent's
// observation vector and reward from a StepRecord; VectorEnv steps many simulations at once on
// core/task_pool.h. Nothing here touches a Python object, so it all runs without the GIL.
#include <vector>

#include "core/task_pool.h"
#include "sim/step_record.h"
#include "spec/scenario_spec.h"

namespace canopy::python {

/// The observation layout of python/canopy/env.py (its docstring is the reference), with finite
/// bounds: every entry is clipped into [low, high] so that it lies inside its space.
struct EnvLayout {
  static constexpr int kTrack = 7;  // px, py, vx, vy, P_xx, P_yy, valid
  static constexpr int kTree = 4;   // dx, dy, r, valid

  int max_tracks = 8;
  int max_trees = 8;
  double map_radius = 30.0;  // m
  bool full_trace = false;   // reward: tr(P) over the whole 4 × 4 block, else the position block
  float position = 0.0F;     // m, |x| and |y| of positions are clipped to this
  float speed = 0.0F;        // m/s, |vx| and |vy| of velocities are clipped to this
  std::vector<float> low, high;

  int size() const { return 3 + kTrack * max_tracks + kTree * max_trees; }
};

/// The layout and its bounds for `spec`: positions within the AOI and every UAV start grown by
/// the distance the fastest UAV flies in the episode; yaw in [−π, π]; track velocities within
/// max(50, 5 · the fastest v_max) m/s; variances in [0, 10⁴] m²; tree offsets and radii within
/// map_radius. Throws std::invalid_argument for negative sizes or a non-positive map_radius.
EnvLayout makeLayout(const spec::ScenarioSpec& spec, int max_tracks, int max_trees,
                     double map_radius, bool full_trace);

/// Agent `agent`'s observation at `record` into out[0 .. layout.size()).
void observe(const sim::StepRecord& record, int agent, const EnvLayout& layout, float* out);

/// Minus the NBO stage cost of the agent's fused belief: −Σ_j tr(P_j) (position block, or all).
double stageReward(const sim::StepRecord& record, int agent, bool full_trace);

}  // namespace canopy::python
