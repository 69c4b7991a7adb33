#pragma once
// The team's planning epoch (algorithms.md §6): SMA-NBO (sequential, intentions passed in
// `order`), Dec-POMDP NBO (every agent optimises the joint plan on its own belief) or centralised
// (the first agent in `order` plans for all). The entry point the simulation calls.
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "agents/config.h"
#include "agents/gaussian.h"
#include "agents/occlusion_map.h"
#include "agents/planning/intention_links.h"
#include "agents/planning/nominal_cost.h"
#include "agents/planning/observation.h"
#include "agents/planning/plan.h"
#include "agents/planning/plan_optimizer.h"
#include "agents/planning/uav_state.h"
#include "core/random.h"
#include "core/task_pool.h"

namespace canopy::agents::planning {

/// What one agent plans on: its own belief and its own map.
struct AgentView {
  std::span<const TargetGaussian> tracks;  // its fused OOI tracks ξ_j (m, m/s), P_j
  const OcclusionMap* map = nullptr;       // its planning map (a-priori, Ŵ_i, or nullptr: none)
};

/// What one agent did in one epoch: the record of who saw what.
struct AgentPlanReport {
  int agent = -1;
  Plan plan;                     // the plan it applies; plan.command() is its command now
  std::vector<Plan> joint;       // the joint plan (one per UAV) its choice was evaluated in
  std::vector<int> joint_epoch;  // per UAV: the epoch the plan used for it was made in (this
                                 // epoch: a new plan; earlier: a shifted intention, the latest
                                 // that reached this agent; −1: hover, none reached it)
  double cost = 0.0;             // J of `joint` on the agent's own belief (m²)
  double seconds = 0.0;          // s, wall time of its optimisation (steady_clock, reporting only)
  int iterations = 0;            // swarm iterations (0: it did not optimise)
  long long evaluations = 0;     // cost evaluations
};

struct TeamPlan {
  int epoch = -1;
  std::vector<Plan> plans;                 // per UAV: the plan it applies
  std::vector<IntentionMessage> messages;  // published this epoch, in publication order (sent;
                                           // whether each arrived is IntentionLinks' business)
  std::vector<AgentPlanReport> reports;    // per UAV, by index
};

/// Keeps what persists between epochs: the published intentions, each agent's previous joint plan
/// (warm starts of Dec-POMDP and centralised planning) and one "pso" RandomStream per agent (SMA
/// and the centralised leader), so a sequence of calls is bit-for-bit reproducible for a seed.
/// Dec-POMDP agents all draw from one stream per epoch ("pso.joint", epoch): the paper's argmax
/// is a function of the belief, so equal beliefs must give equal joint plans. Wall time is measured
/// for the report only and never feeds back into a decision.
/// The joint warm starts of the local-best search (k starts of n plans each, start-major): the
/// previous joint plan already shifted (when `previous` has n plans), every UAV hovering, and for
/// each UAV the previous plan with that UAV hovering.
std::vector<Plan> jointWarmStarts(std::span<const Plan> previous, int n, int horizon);

/// The local-best joint search's swarm (docs/design-notes.md, "Dec-POMDP's joint search").
/// A ring of ±1 neighbours, restarts after 25 iterations without progress, and at most 250
/// iterations: 250 · 20·H particles, about 1.5 times the evaluations the paper's swarm makes
/// before its stall rule stops it in Resource Allocation (bench/RESULTS.md).
inline constexpr SwarmShape kLocalBest{SwarmTopology::ring, 1, 25, 0, 250};

/// The joint plan of Dec-POMDP and centralised planning by config.joint_search, over every UAV of
/// the problem: global_best, one swarm with the previous plan (`warm`, already shifted; or empty)
/// as particle 0; local_best, one swarm of shape `local` with jointWarmStarts(warm); block
/// coordinate descent over `order` for config.joint_rounds rounds, starting from `warm` (or
/// hover). The entry point of TeamPlanner and of the tools that compare the searches.
PlanSearch searchJointPlan(PlanOptimizer& optimizer, const PlanningProblem& problem,
                           const PlannerConfig& config, std::span<const int> order,
                           std::span<const Plan> warm, RandomStream& rng,
                           const SwarmShape& local = kLocalBest);

/// One agent's decision as a demonstration (issue 54, docs/imitation.md): what it observed, what
/// the expert chose there and what it flew. SMA-NBO: the observation is built from the intentions
/// its search held, expert = flown. Dec-POMDP: from the teammates' plans flown since the previous
/// epoch (shifted), as if published, expert = flown. Learned with labelling on: the learned team
/// flies, and the expert is SMA-NBO's search for that agent against the same intentions
/// (DAgger's labels), drawn from the agent's own "pso" stream (never used by the network).
struct Decision {
  int epoch = -1;
  int agent = -1;
  Observation observation;
  double v_max = 0.0;  // m/s
  Vec2 expert = Vec2::Zero();  // m/s
  Vec2 flown = Vec2::Zero();   // m/s
};

class TeamPlanner {
 public:
  /// Called once per agent per epoch, in planning order, after the epoch's plans are made (SMA,
  /// Dec-POMDP; learned only with labelExpert(true)): the demonstrations of `canopy imitate
  /// collect`. Never feeds back into what is flown.
  using DecisionObserver = std::function<void(const Decision&)>;
  void observeDecisions(DecisionObserver observer) { decision_observer_ = std::move(observer); }
  /// Learned planning: also run SMA-NBO's search for every agent, to label its decision.
  void labelExpert(bool on) { label_expert_ = on; }

  /// Called before every joint search (Dec-POMDP and centralised) with the epoch, the planning
  /// agent, its problem and its warm start (the previous joint plan shifted, or empty): a hook
  /// for tools that save planning states (bench/joint_search_gaps.cpp). Never feeds back.
  using JointProblemObserver =
      std::function<void(int epoch, int agent, const PlanningProblem&, std::span<const Plan> warm)>;
  void observeJointProblems(JointProblemObserver observer) {
    joint_observer_ = std::move(observer);
  }

  /// sigma_a: the trackers' NCV σ_a (m/s²); seed: the trial seed (streams "pso", agent index);
  /// links: what intention messages travel through (default: every message arrives at once).
  TeamPlanner(const PlannerConfig& config, double sigma_a, std::uint64_t seed,
              const LinkConfig& links = {});

  /// One planning epoch (epochs increase by one per replan_period; actions last plan_period). uavs
  /// and views: one per UAV, by index, the same team size at every call. With algorithm `none`
  /// every UAV hovers. SMA-NBO: agents plan in `order`; agent i optimises its own H actions
  /// against, for every other UAV, the latest plan of it that has reached agent i through the links
  /// (with perfect links: the new plans of the agents before it and the intentions of those after
  /// it), shifted by the time elapsed, a missing step repeating the last action; hover when none
  /// has reached it. Then it publishes {i, i, epoch, plan} to the team. Dec-POMDP: each agent
  /// optimises all N·H actions on its own view and applies its own; no messages. Centralised: the
  /// first agent in `order` optimises the joint plan on its view and sends each UAV its part
  /// ({leader, i, epoch, plan_i}); a UAV whose order did not arrive flies the latest one that did,
  /// shifted.
  TeamPlan plan(int epoch, std::span<const UavState> uavs, std::span<const AgentView> views);

  /// Plans independent agents side by side on `pool` (nullptr: one after the other), with the
  /// same bits: SMA-NBO agents whose costs do not read each other's new plans (a level at a
  /// time, planSequential), Dec-POMDP agents all at once. The pool must outlive the planner's
  /// use of it.
  void setPool(TaskPool* pool) {
    pool_ = pool;
    shared_.pool = pool;
  }

  const PlannerConfig& config() const { return config_; }
  /// Intention messages since the start (SMA-NBO's plans, the centralised leader's orders).
  const MessageCounts& intentionCounts() const { return links_.counts(); }
  /// SMA-NBO: how many levels the latest epoch's agents were planned in (planSequential): 1 when
  /// no agent's cost read a plan made earlier in the same epoch (all side by side), N when each
  /// read its predecessor's (one after another); 0 before the first SMA epoch.
  int levels() const { return levels_; }
  /// Swarm iterations whose particles were evaluated side by side on the pool (an agent planned
  /// alone in its level, or the centralised leader; PlanOptimizer::share), since the start.
  long long sharedBatches() const;

 private:
  void planSequential(TeamPlan& out, std::span<const UavState> uavs,
                      std::span<const AgentView> views);
  void planJoint(TeamPlan& out, int planner, std::span<const UavState> uavs, const AgentView& view);
  /// Learned: agents in `order` each evaluate the policy on their observation (the latest
  /// intentions that reached them, with this epoch's of the agents before them), fly the command
  /// for all H actions and publish that plan as SMA-NBO agents do.
  void planLearned(TeamPlan& out, std::span<const UavState> uavs, std::span<const AgentView> views);
  /// The demonstrations of an SMA or Dec-POMDP epoch (decision_observer_ set).
  void reportDecisions(const TeamPlan& out, std::span<const UavState> uavs,
                       std::span<const AgentView> views);
  /// Actions (of plan_period) elapsed from one epoch to a later one.
  double actionsSince(int earlier_epoch, int epoch) const;
  /// A plan made at `made` (−1: none yet), as held at `epoch`: shifted by the actions elapsed,
  /// or hovering when there is none.
  Plan heldAt(const Plan& plan, int made, int epoch) const;
  PlannerConfig config_;
  CostSettings settings_;
  std::uint64_t seed_;
  std::vector<int> order_;         // planning order (UAV indices)
  std::vector<RandomStream> rng_;  // per agent, purpose "pso"
  LinkConfig link_config_;
  IntentionLinks links_;                       // intention messages in flight and received
  std::vector<IntentionMessage> own_;          // per agent: its own latest plan (epoch −1: none)
  std::vector<std::vector<Plan>> last_joint_;  // per agent: its previous joint plan (or empty)
  std::vector<int> last_joint_epoch_;          // per agent: the epoch of last_joint_
  std::vector<PlanOptimizer> optimizers_;     // per agent: its own buffers, whichever thread runs it
  JointProblemObserver joint_observer_;
  DecisionObserver decision_observer_;
  bool label_expert_ = false;
  std::vector<IntentionMessage> own_previous_;  // own_ as the epoch began (decision reports)
  std::vector<Plan> flown_;  // per UAV: the plan it applied at the previous epoch
  int flown_epoch_ = -1;
  TaskPool* pool_ = nullptr;
  // The pool and its blocks' costs for the one search at a time that shares its particles out:
  // two copies of a prepared cost for the team, not two per agent.
  PlanOptimizer::SharedEvaluation shared_;
  // The optimiser of every level of one agent (all of them in team scope): those searches run one
  // at a time, and a search's result does not depend on the searches before it (its swarm and
  // cost tables are refilled on every call), so one set of buffers serves the team. At 256 UAVs
  // over 1024 people a prepared cost's tables are about 4 MB; per agent they were about 1 GB.
  PlanOptimizer alone_;
  // planSequential's per-epoch scratch, by agent.
  std::vector<std::vector<IntentionLinks::Route>> routes_;  // where its message goes
  std::vector<int> rank_;                                   // its place in order_
  std::vector<char> fresh_;              // [i·n + j]: j's new plan reaches i before i plans
  std::vector<std::vector<Plan>> joints_;  // its picture of the team
  std::vector<std::vector<int>> joint_epochs_;
  std::vector<int> level_;               // 1 + the highest level of the fresh plans it reads
  std::vector<int> batch_;               // the agents of one level, in order_
  std::vector<PlanSearch> searches_;
  std::vector<double> seconds_;
  int levels_ = 0;
};

}  // namespace canopy::agents::planning
