#pragma once
// The one place where a tick is wired (architecture.md, "One tick"): commands → world step →
// truth snapshot → sensing per UAV → (agents) → commands for the next step.
#include <memory>
#include <vector>

#include "agents/belief.h"
#include "core/random.h"
#include "scenarios/spec.h"
#include "sensing/sensor.h"
#include "world/world.h"

namespace canopy::scenarios {

class Simulation {
 public:
  explicit Simulation(const ScenarioSpec& spec);

  /// Runs step k = stepIndex(): for k = 0 senses the initial state, otherwise applies the
  /// commands of step k − 1 and advances the world by dt first.
  void tick();
  /// True once steps 0..K have all run.
  bool done() const { return next_step_ > spec_.steps(); }
  /// The step the next tick() runs.
  int nextStep() const { return next_step_; }

  const ScenarioSpec& spec() const { return spec_; }
  const world::World& world() const { return world_; }
  const world::WorldSnapshot& truth() const { return truth_; }
  const std::vector<sensing::Scan>& scans() const { return scans_; }
  /// Each UAV agent's fused tracks, occlusion map and plan (empty until agents are wired in).
  const std::vector<agents::AgentBelief>& beliefs() const { return beliefs_; }

 private:
  void commandScriptedUavs();

  const ScenarioSpec& spec_;
  world::World world_;
  std::vector<sensing::LabelId> target_labels_;
  std::vector<RandomStream> sensing_rng_;   // one "sensing" stream per UAV
  sensing::SenseScratch scratch_;
  world::WorldSnapshot truth_;
  std::vector<sensing::Scan> scans_;
  std::vector<agents::AgentBelief> beliefs_;
  int next_step_ = 0;
};

}  // namespace canopy::scenarios
