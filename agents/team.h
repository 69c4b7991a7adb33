#pragma once
// The UAV team's stack for one step (architecture.md, "One tick"): local JPDAF per agent → L
// consensus rounds over the network (targets and trees) → occlusion maps → on planning epochs,
// SMA-NBO / Dec-POMDP / centralised planning → velocity commands.
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "agents/agent.h"
#include "agents/config.h"
#include "agents/fusion/team_fusion.h"
#include "agents/planning/team_planner.h"
#include "core/task_pool.h"
#include "world/tree.h"

namespace canopy::agents {

struct TeamConfig {
  TrackingConfig tracking;
  FusionConfig fusion;
  PlannerConfig planner;
  std::vector<planning::UavState>
      uavs;  // each UAV's limits and camera (positions filled per epoch)
  std::vector<world::TreeDef> true_trees;  // the a-priori map (occlusion_map "a_priori" only)
  std::uint64_t seed = 1;                  // the trial's seed
  double dt = 0.2;                         // s, the simulation step (message latencies in steps)
};

class Team {
 public:
  explicit Team(const TeamConfig& config);

  /// Every agent starts with a confirmed track {−1, t} on target t (mean `state`: m, m/s).
  void preseed(int target, sensing::LabelId label, const Vec4& state);

  /// Agent `agent`'s part of a step, for every agent before fuse(): it takes its UAV's pose now
  /// (its own navigation, taken as exact: position m, yaw rad) and runs its local JPDAF on its
  /// scan (dt: s since the last step, 0 at the start). Touches agent `agent`'s state only:
  /// different agents may be tracked at once, on different threads.
  void trackLocally(int agent, double dt, const Vec2& position, double yaw,
                    const sensing::Scan& scan, const sensing::Footprint& footprint);
  /// The team's fusion at the positions given to trackLocally; each agent then adopts its fused
  /// lists, deletes stale tracks and rebuilds its map.
  void fuse();

  /// Whether the team plans at all (planner.algorithm ≠ none): the one place this is decided;
  /// without a planner the UAVs follow their scripted paths.
  bool plans() const { return config_.planner.algorithm != PlannerAlgorithm::none; }

  /// One planning epoch from the poses given to trackLocally (the rest of each UAV from the
  /// config). Returns the team plan (plans[i].command() is UAV i's command), or nothing without a
  /// planner.
  std::optional<planning::TeamPlan> plan(int epoch);
  /// Height (issue 53): agent `agent`'s UAV is at altitude z (m) now; with a camera its planning
  /// footprint and noise follow (planning/altitude_choice.h). Call before plan().
  void setAltitude(int agent, double z);
  /// The climb rate (m/s) the latest plan() chose for agent `agent` (0: hold; always 0 when its
  /// altitude is not free).
  double climbCommand(int agent) const { return climbs_[static_cast<std::size_t>(agent)]; }

  /// Each agent's belief (its planned path from its latest plan), into `out` (resized to the
  /// team; its storage reused).
  void writeBeliefs(std::vector<AgentBelief>& out) const;

  /// Runs the per-agent parts (the fused lists' adoption, the beliefs, the planner's independent
  /// agents) on `pool` (nullptr: one after the other); the result is the same bits either way.
  /// The pool must outlive the team's use of it.
  void setPool(TaskPool* pool) {
    pool_ = pool;
    planner_.setPool(pool);
    fusion_.setPool(pool);
  }

  const std::vector<Agent>& agents() const { return agents_; }
  const fusion::TeamFusion& fusion() const { return fusion_; }
  const planning::TeamPlanner& planner() const { return planner_; }
  /// TeamPlanner::observeJointProblems: a hook for tools that save planning states.
  void observeJointProblems(planning::TeamPlanner::JointProblemObserver observer) {
    planner_.observeJointProblems(std::move(observer));
  }
  /// TeamPlanner::observeDecisions and labelExpert: demonstrations (canopy imitate collect).
  void observeDecisions(planning::TeamPlanner::DecisionObserver observer, bool label_expert) {
    planner_.observeDecisions(std::move(observer));
    planner_.labelExpert(label_expert);
  }

 private:
  TeamConfig config_;
  std::vector<Agent> agents_;
  fusion::TeamFusion fusion_;
  planning::TeamPlanner planner_;
  OcclusionMap a_priori_;
  std::vector<fusion::AgentTracks> fusion_inputs_;  // rebuilt every step, read-only views
  fusion::FusedTracks fused_;  // each step's fusion result, adopted by the agents (buffers reused)
  std::vector<planning::UavState> uav_states_;  // poses from trackLocally, the rest from config
  std::vector<planning::AgentView> planning_views_;
  std::vector<std::vector<Vec2>> planned_paths_;  // per agent, from its latest plan
  std::vector<double> climbs_;                     // m/s, per agent, from its latest plan
  TaskPool* pool_ = nullptr;
};

}  // namespace canopy::agents
