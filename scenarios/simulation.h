#pragma once
// The one place where a tick is wired (architecture.md, "One tick"): commands → world step →
// truth snapshot → sensing per UAV → local tracking → fusion → occlusion maps → on planning
// epochs, the team's plan → commands for the next step.
#include <optional>
#include <vector>

#include "agents/belief.h"
#include "agents/planning/team_planner.h"
#include "agents/team.h"
#include "core/random.h"
#include "scenarios/spec.h"
#include "sensing/sensor.h"
#include "world/world.h"

namespace canopy::scenarios {

/// The team's configuration a scenario gives: tracking, fusion and planner sections, each UAV's
/// limits and camera at its start, the true trees when the planner uses the a-priori map.
agents::TeamConfig teamConfig(const ScenarioSpec& spec);

class Simulation {
 public:
  explicit Simulation(const ScenarioSpec& spec);

  /// Runs step k = nextStep(): for k = 0 senses the initial state, otherwise applies the
  /// commands set at step k − 1 and advances the world by dt first.
  void tick();
  /// True once steps 0..K have all run.
  bool done() const { return next_step_ > spec_.steps(); }
  /// The step the next tick() runs.
  int nextStep() const { return next_step_; }

  const ScenarioSpec& spec() const { return spec_; }
  const world::World& world() const { return world_; }
  const world::WorldSnapshot& truth() const { return truth_; }
  const std::vector<sensing::Scan>& scans() const { return scans_; }
  /// Each UAV agent's fused tracks, occlusion map and planned path, after this step's fusion.
  const std::vector<agents::AgentBelief>& beliefs() const { return beliefs_; }
  const agents::Team& team() const { return team_; }
  /// The plan made at this step, when it was a planning epoch.
  const std::optional<agents::planning::TeamPlan>& plan() const { return plan_; }
  /// Steps between planning epochs (plan_period / dt).
  int stepsPerPlan() const { return steps_per_plan_; }

 private:
  void commandScriptedUavs();
  void commandFromPlan();

  const ScenarioSpec& spec_;
  world::World world_;
  agents::Team team_;
  std::vector<sensing::LabelId> target_labels_;
  std::vector<RandomStream> sensing_rng_;  // one "sensing" stream per UAV
  sensing::SenseScratch scratch_;
  world::WorldSnapshot truth_;
  std::vector<sensing::Scan> scans_;
  std::vector<sensing::Footprint> footprints_;
  std::vector<Vec2> positions_;
  std::vector<double> yaws_;
  std::vector<agents::AgentBelief> beliefs_;
  std::optional<agents::planning::TeamPlan> plan_;
  int steps_per_plan_ = 1;
  int next_step_ = 0;
};

}  // namespace canopy::scenarios
