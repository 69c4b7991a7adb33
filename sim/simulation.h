#pragma once
// The one place where a tick is wired (architecture.md, "One tick"): commands → world step →
// truth snapshot → per UAV (in parallel with threads > 1): footprint, scan, pose and local
// tracking → fusion,
// adopted by every agent → occlusion maps → on planning epochs, the team's plan → commands for
// the next step → the step's record. Each tick fills one StepRecord (sim/step_record.h),
// the only thing observers see.
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "agents/team.h"
#include "core/random.h"
#include "core/task_pool.h"
#include "sensing/sensor.h"
#include "sim/step_record.h"
#include "spec/scenario_spec.h"
#include "world/world.h"

namespace canopy::sim {

/// The team's configuration a scenario gives: tracking, fusion and planner sections, each UAV's
/// limits and camera at its start, the true trees when the planner uses the a-priori map.
agents::TeamConfig teamConfig(const spec::ScenarioSpec& spec);

class Simulation {
 public:
  /// Keeps its own copy of the spec: a simulation built from a temporary is safe. threads
  /// (1..kMaxThreads, the calling thread included): how many threads sense, track and plan the
  /// agents of a tick side by side; every record is the same bits at any count (each agent's
  /// streams, scratch and optimiser are its own; docs/design-notes.md, "Threads inside one run").
  /// Throws std::invalid_argument outside that range.
  explicit Simulation(spec::ScenarioSpec spec, int threads = 1);
  static constexpr int kMaxThreads = 256;

  /// Runs step k = nextStep(): for k = 0 senses the initial state, otherwise applies the
  /// commands set at step k − 1 and advances the world by dt first. Returns the step's record,
  /// valid until the next tick (its storage is reused: copy it to keep it).
  /// Throws NonFiniteState (sim/finite_check.h) when a state of the step is not finite.
  const StepRecord& tick();
  /// External command (a custom controller, a Python binding): UAV `uav` flies `velocity` (m/s)
  /// during the next step, the one the next tick() runs, instead of its planner's or scripted
  /// command; like those it is clamped to the UAV's v_max (World::commandUav). It holds for that
  /// one step: the tick after it commands the UAV from its planner (the command held since the
  /// last planning epoch) or its path again, so a controller calls it before every tick it wants
  /// to steer. Planning epochs are untouched: the planner still plans on its schedule from the
  /// true positions, and its plan and intentions are recorded and published as if flown. What was
  /// flown is the next step's record (uavs[i].velocity); world().commandedVelocity(uav) reports
  /// the clamped command until then. Call between ticks, after the first and before done();
  /// throws std::logic_error otherwise, std::out_of_range for an unknown UAV and
  /// std::invalid_argument for a non-finite velocity.
  void commandNext(int uav, const Vec2& velocity);
  /// commandNext's altitude part (issue 53): UAV `uav` climbs at `climb` (m/s, down negative)
  /// during the next step, clamped to its climb rate and kept within [z_min, z_max] (a UAV
  /// without altitude limits stays where it is). Same rules and errors as commandNext.
  void commandClimbNext(int uav, double climb);
  /// True once steps 0..K have all run.
  bool done() const { return next_step_ > spec_.steps(); }
  /// The step the next tick() runs.
  int nextStep() const { return next_step_; }

  /// The record of the step the last tick() ran (the one tick() returned).
  const StepRecord& lastStep() const { return record_; }

  const spec::ScenarioSpec& spec() const { return spec_; }
  const world::World& world() const { return world_; }
  const agents::Team& team() const { return team_; }
  /// TeamPlanner::observeJointProblems: every joint search's planning state, for tools
  /// (bench/joint_search_gaps.cpp); it never changes the run.
  void observeJointProblems(agents::planning::TeamPlanner::JointProblemObserver observer) {
    team_.observeJointProblems(std::move(observer));
  }
  /// TeamPlanner::observeDecisions: every agent's decision as a demonstration, labelled by
  /// SMA-NBO when the team flies a learned policy and label_expert is set; never changes the
  /// run's flight (the labels draw only from streams the learned planner does not use).
  void observeDecisions(agents::planning::TeamPlanner::DecisionObserver observer,
                        bool label_expert) {
    team_.observeDecisions(std::move(observer), label_expert);
  }
  /// Steps between planning epochs (plan_period / dt).
  int stepsPerPlan() const { return steps_per_plan_; }

 private:
  void readTruth();
  void senseAndTrack(double dt);
  void commandScriptedUavs();
  void commandFromPlan();
  void commandUavs();
  void readTeam();

  const spec::ScenarioSpec spec_;
  world::World world_;
  agents::Team team_;
  std::vector<sensing::LabelId> target_labels_;
  std::vector<RandomStream> sensing_rng_;  // one "sensing" stream per UAV
  std::vector<sensing::SenseScratch> scratch_;  // per UAV, so that UAVs sense on any thread
  std::unique_ptr<TaskPool> pool_;              // threads > 1 only
  world::WorldSnapshot truth_;  // this step's, as sensing reads it
  std::vector<std::string> uav_names_;  // for the messages of checkFinite
  std::vector<Vec2> commands_;  // m/s, per UAV: its planner's or path's command, before clamping
  std::vector<double> climb_commands_;  // m/s, per UAV: its planner's climb, before clamping
  StepRecord record_;           // this step's, refilled in place by every tick
  int steps_per_plan_ = 1;
  int next_step_ = 0;
};

}  // namespace canopy::sim
