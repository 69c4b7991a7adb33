#include "agents/planning/team_planner.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <numeric>

#include "agents/planning/interaction.h"
#include "agents/planning/policy_network.h"

namespace canopy::agents::planning {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

[[noreturn]] void fail(const char* what) {
  std::fprintf(stderr, "TeamPlanner: %s\n", what);
  std::abort();
}

}  // namespace

TeamPlanner::TeamPlanner(const PlannerConfig& config, double sigma_a, std::uint64_t seed,
                         const LinkConfig& links)
    : config_(config),
      settings_(CostSettings::from(config, sigma_a)),
      seed_(seed),
      link_config_(links) {}

double TeamPlanner::actionsSince(int earlier_epoch, int epoch) const {
  // Epochs are replan_period apart, actions plan_period long.
  return (epoch - earlier_epoch) * (config_.replan_period / config_.plan_period);
}

Plan TeamPlanner::heldAt(const Plan& plan, int made, int epoch) const {
  const int H = settings_.horizon;
  return made < 0 ? hoverPlan(H) : shiftedPlan(plan, actionsSince(made, epoch), H);
}

TeamPlan TeamPlanner::plan(int epoch, std::span<const UavState> uavs,
                           std::span<const AgentView> views) {
  const int n = static_cast<int>(uavs.size());
  if (static_cast<int>(views.size()) != n) fail("one view per UAV expected");
  if (rng_.empty()) {
    for (int i = 0; i < n; ++i) rng_.emplace_back(seed_, "pso", static_cast<std::uint64_t>(i));
    own_.assign(n, IntentionMessage{});
    links_ = IntentionLinks(link_config_, n, seed_);
    last_joint_.assign(n, {});
    last_joint_epoch_.assign(n, -1);
    optimizers_.resize(n);
    order_ = config_.order;
    if (order_.empty()) {
      order_.resize(n);
      std::iota(order_.begin(), order_.end(), 0);
    }
    std::vector<char> seen(n, 0);
    if (static_cast<int>(order_.size()) != n) fail("the order must list every UAV once");
    for (const int i : order_) {
      if (i < 0 || i >= n || seen[i]++) fail("the order must list every UAV once");
    }
  }
  if (static_cast<int>(rng_.size()) != n) fail("the team size changed between epochs");
  links_.beginEpoch(epoch, uavs);

  TeamPlan out;
  out.epoch = epoch;
  out.plans.assign(n, hoverPlan(settings_.horizon));
  out.reports.resize(n);
  for (int i = 0; i < n; ++i) {
    out.reports[i].agent = i;
    out.reports[i].plan = out.plans[i];
  }
  if (decision_observer_) own_previous_ = own_;
  switch (config_.algorithm) {
    case PlannerAlgorithm::none:
      break;
    case PlannerAlgorithm::sma:
      planSequential(out, uavs, views);
      break;
    case PlannerAlgorithm::dec_pomdp:
      // Each agent searches on its own belief, optimiser and the epoch's shared stream (a copy
      // of its own): the agents are independent, so they run side by side; a tool observing the
      // joint problems sees them one after the other, in order.
      // (the pool runs the agents: their swarms evaluate on their own threads)
      for (PlanOptimizer& optimizer : optimizers_) optimizer.share(nullptr);
      forEachTask(joint_observer_ ? nullptr : pool_, order_.size(),
                  [&](std::size_t k) { planJoint(out, order_[k], uavs, views[order_[k]]); });
      break;
    case PlannerAlgorithm::centralized:
      optimizers_[order_.front()].share(&shared_);  // the one search: its particles side by side
      planJoint(out, order_.front(), uavs, views[order_.front()]);
      break;
    case PlannerAlgorithm::learned:
      planLearned(out, uavs, views);
      break;
  }
  if (decision_observer_ && (config_.algorithm == PlannerAlgorithm::sma ||
                             config_.algorithm == PlannerAlgorithm::dec_pomdp))
    reportDecisions(out, uavs, views);
  if (decision_observer_) {
    flown_ = out.plans;
    flown_epoch_ = epoch;
  }
  return out;
}

long long TeamPlanner::sharedBatches() const {
  long long total = 0;
  for (const PlanOptimizer& optimizer : optimizers_) total += optimizer.sharedBatches();
  total += alone_.sharedBatches();
  return total;
}

void TeamPlanner::reportDecisions(const TeamPlan& out, std::span<const UavState> uavs,
                                  std::span<const AgentView> views) {
  const int n = static_cast<int>(uavs.size());
  const int H = settings_.horizon;
  std::vector<Plan> intentions(n);
  for (const int i : order_) {
    if (config_.algorithm == PlannerAlgorithm::sma) {
      // The intentions its search held; its own entry: its previous plan, shifted.
      intentions = out.reports[i].joint;
      const IntentionMessage& own = own_previous_[i];
      intentions[i] = heldAt(own.plan, own.epoch, out.epoch);
    } else {
      for (int j = 0; j < n; ++j) {
        intentions[j] = heldAt(flown_[j], flown_epoch_, out.epoch);
      }
    }
    Decision d;
    d.epoch = out.epoch;
    d.agent = i;
    d.observation = observe(i, uavs, views[i].tracks, views[i].map, intentions, H,
                            settings_.period);
    d.v_max = uavs[i].v_max;
    d.expert = d.flown = out.plans[i].command();
    decision_observer_(d);
  }
}

void TeamPlanner::planLearned(TeamPlan& out, std::span<const UavState> uavs,
                              std::span<const AgentView> views) {
  if (!config_.policy) fail("the learned planner has no policy");
  const int n = static_cast<int>(uavs.size());
  const int H = settings_.horizon;
  std::vector<IntentionLinks::Route> routes;
  std::vector<Plan> intentions(n);
  std::vector<int> epochs(n);
  for (const int i : order_) {
    links_.route(i, -1, routes);
    for (int j = 0; j < n; ++j) {
      const IntentionMessage& m = j == i ? own_[i] : links_.latest(i, j);
      intentions[j] = heldAt(m.plan, m.epoch, out.epoch);
      epochs[j] = m.epoch;
    }
    const PlanningProblem problem{views[i].tracks, uavs, views[i].map, settings_};
    const Clock::time_point start = Clock::now();
    Decision d;
    d.observation = observe(i, uavs, views[i].tracks, views[i].map, intentions, H,
                            settings_.period);
    const Vec2 command = config_.policy->command(d.observation, uavs[i].v_max);
    const double seconds = secondsSince(start);
    Plan plan{std::vector<Vec2>(static_cast<std::size_t>(H), command), 0.0};
    if (label_expert_ && decision_observer_) {
      // DAgger's label: SMA-NBO's search for agent i against the same intentions, warm-started
      // from its own previous plan.
      const int self[] = {i};
      const std::span<const Plan> warm = own_[i].epoch < 0
                                             ? std::span<const Plan>()
                                             : std::span<const Plan>(&intentions[i], 1);
      const PlanSearch search =
          optimizers_[i].optimise(problem, config_.pso, self, intentions, warm, rng_[i]);
      d.epoch = out.epoch;
      d.agent = i;
      d.v_max = uavs[i].v_max;
      d.expert = search.plans.front().command();
      d.flown = command;
      decision_observer_(d);
    }
    intentions[i] = plan;
    epochs[i] = out.epoch;
    out.plans[i] = plan;
    out.reports[i] = AgentPlanReport{i, plan, intentions, epochs, 0.0, seconds, 0, 0};
    out.messages.push_back(IntentionMessage{i, i, out.epoch, plan});
    own_[i] = out.messages.back();
    links_.post(routes, out.messages.back());
  }
}

void TeamPlanner::planSequential(TeamPlan& out, std::span<const UavState> uavs,
                                 std::span<const AgentView> views) {
  // The paper's loop, agent i in `order` at rank r_i, gives agent i for every other UAV j the
  // latest plan of j that has reached it: j's new plan when r_j < r_i and the links delivered it at
  // once ("fresh"), else what it held when the epoch began. Where a message goes does not depend
  // on its plan, so every route is drawn first, in the order the loop sends (the same draws).
  // Agent i's search then waits only for the fresh plans its cost reads
  // (NominalCost::readsPlanOf): level(i) = 1 + max level(j) over those, 0 without any. The agents
  // of one level run side by side, each on its own optimiser and stream, on exactly the inputs
  // the loop gives them; messages, reports and deliveries follow in `order`.
  const int n = static_cast<int>(uavs.size());
  const int H = settings_.horizon;
  routes_.resize(n);
  for (const int i : order_) links_.route(i, -1, routes_[i]);
  rank_.resize(n);
  for (int r = 0; r < n; ++r) rank_[order_[r]] = r;
  fresh_.assign(static_cast<std::size_t>(n) * n, 0);  // [i·n + j]
  for (int j = 0; j < n; ++j) {
    for (const IntentionLinks::Route& route : routes_[j]) {
      if (route.arrival_epoch == out.epoch && rank_[j] < rank_[route.receiver])
        fresh_[static_cast<std::size_t>(route.receiver) * n + j] = 1;
    }
  }
  auto fresh = [&](int i, int j) { return fresh_[static_cast<std::size_t>(i) * n + j] != 0; };
  auto freshPlan = [&](int j) {
    return shiftedPlan(searches_[j].plans.front(), actionsSince(out.epoch, out.epoch), H);
  };

  joints_.resize(n);
  joint_epochs_.resize(n);
  level_.assign(n, 0);
  int levels = 0;
  for (const int i : order_) {
    std::vector<Plan>& joint = joints_[i];
    joint.resize(n);
    joint_epochs_[i].assign(n, -1);
    const int self[] = {i};
    const PlanningProblem problem{views[i].tracks, uavs, views[i].map, settings_};
    for (int j = 0; j < n; ++j) {
      if (fresh(i, j)) {
        joint[j] = Plan{};  // filled once j has planned
        joint_epochs_[i][j] = out.epoch;
        if (NominalCost::readsPlanOf(problem, self, j)) level_[i] = std::max(level_[i], level_[j] + 1);
        continue;
      }
      const IntentionMessage& m = j == i ? own_[i] : links_.latest(i, j);
      joint[j] = heldAt(m.plan, m.epoch, out.epoch);
      joint_epochs_[i][j] = m.epoch;
    }
    levels = std::max(levels, level_[i] + 1);
  }

  levels_ = levels;
  searches_.resize(n);
  seconds_.resize(n);
  for (int level = 0; level < levels; ++level) {
    batch_.clear();
    for (const int i : order_) {
      if (level_[i] != level) continue;
      batch_.push_back(i);
      for (int j = 0; j < n; ++j) {
        if (fresh(i, j) && level_[j] < level) joints_[i][j] = freshPlan(j);
      }
    }
    // A level of one agent (every level in team scope) leaves the pool idle: that agent's swarm
    // evaluates its particles on it instead (PlanOptimizer::share), in the team's one optimiser
    // for such levels (alone_).
    for (const int i : batch_) optimizers_[i].share(nullptr);
    alone_.share(&shared_);
    forEachTask(pool_, batch_.size(), [&](std::size_t k) {
      const int i = batch_[k];
      const PlanningProblem problem{views[i].tracks, uavs, views[i].map, settings_};
      const std::span<const Plan> warm = own_[i].epoch < 0
                                             ? std::span<const Plan>()
                                             : std::span<const Plan>(&joints_[i][i], 1);
      const int self[] = {i};
      const Clock::time_point start = Clock::now();
      PlanOptimizer& optimizer = batch_.size() == 1 ? alone_ : optimizers_[i];
      searches_[i] = optimizer.optimise(problem, config_.pso, self, joints_[i], warm, rng_[i]);
      seconds_[i] = secondsSince(start);
    });
  }

  for (const int i : order_) {
    std::vector<Plan>& joint = joints_[i];
    for (int j = 0; j < n; ++j) {
      if (fresh(i, j)) joint[j] = freshPlan(j);  // as the loop's picture held it
    }
    const PlanSearch& search = searches_[i];
    joint[i] = search.plans.front();
    joint_epochs_[i][i] = out.epoch;
    out.plans[i] = joint[i];
    out.reports[i] = AgentPlanReport{i,
                                     joint[i],
                                     joint,
                                     joint_epochs_[i],
                                     search.cost,
                                     seconds_[i],
                                     search.iterations,
                                     search.evaluations};
    out.messages.push_back(IntentionMessage{i, i, out.epoch, joint[i]});
    own_[i] = out.messages.back();
    links_.post(routes_[i], out.messages.back());
  }
}

std::vector<Plan> jointWarmStarts(std::span<const Plan> previous, int n, int horizon) {
  // Start-major, n plans per start: the previous joint plan shifted; every UAV hovering; then for
  // each UAV, the previous plan with that UAV hovering (the others as before). Without a previous
  // plan only the hover start.
  std::vector<Plan> starts;
  const bool has_previous = previous.size() == static_cast<std::size_t>(n);
  if (has_previous) starts.insert(starts.end(), previous.begin(), previous.end());
  starts.insert(starts.end(), n, hoverPlan(horizon));
  if (has_previous && n > 1) {
    for (int f = 0; f < n; ++f) {
      for (int i = 0; i < n; ++i) starts.push_back(i == f ? hoverPlan(horizon) : previous[i]);
    }
  }
  return starts;
}

namespace {

PlanSearch searchByBlocks(PlanOptimizer& optimizer, const PlanningProblem& problem,
                          const PlannerConfig& config, std::span<const int> order,
                          std::span<const Plan> warm, RandomStream& rng) {
  // Block coordinate descent on J(b_i, a): each UAV's 2·H variables in turn, the others held at
  // their current plans. The block's current plan is one of its swarm's particles, so J never
  // increases from one block to the next; the last block's cost is J of the joint plan returned.
  const int n = static_cast<int>(problem.uavs.size());
  PlanSearch joint;
  joint.plans = warm.size() == static_cast<std::size_t>(n)
                    ? std::vector<Plan>(warm.begin(), warm.end())
                    : std::vector<Plan>(n, hoverPlan(problem.settings.horizon));
  PsoConfig pso = config.pso;
  pso.warm_start = true;
  for (int round = 0; round < config.joint_rounds; ++round) {
    for (const int i : order) {
      const int self[] = {i};
      const PlanSearch block =
          optimizer.optimise(problem, pso, self, joint.plans, {&joint.plans[i], 1}, rng);
      joint.plans[i] = block.plans.front();
      joint.cost = block.cost;
      joint.iterations += block.iterations;
      joint.evaluations += block.evaluations;
    }
  }
  for (Plan& plan : joint.plans) plan.cost = joint.cost;
  return joint;
}

}  // namespace

PlanSearch searchJointPlan(PlanOptimizer& optimizer, const PlanningProblem& problem,
                           const PlannerConfig& config, std::span<const int> order,
                           std::span<const Plan> warm, RandomStream& rng, const SwarmShape& local) {
  const int n = static_cast<int>(problem.uavs.size());
  std::vector<int> everyone(n);
  std::iota(everyone.begin(), everyone.end(), 0);
  const std::vector<Plan> unused(n);  // every UAV is free: no plan is held fixed
  switch (config.joint_search) {
    case JointSearch::global_best:
      return optimizer.optimise(problem, config.pso, everyone, unused, warm, rng);
    case JointSearch::local_best:
      return optimizer.optimise(problem, config.pso, everyone, unused,
                                jointWarmStarts(warm, n, problem.settings.horizon), rng, local);
    case JointSearch::block_coordinate:
      break;
  }
  return searchByBlocks(optimizer, problem, config, order, warm, rng);
}

void TeamPlanner::planJoint(TeamPlan& out, int planner, std::span<const UavState> uavs,
                            const AgentView& view) {
  const int n = static_cast<int>(uavs.size());
  const int H = settings_.horizon;
  std::vector<Plan> warm;
  if (last_joint_epoch_[planner] >= 0) {
    for (const Plan& previous : last_joint_[planner]) {
      warm.push_back(shiftedPlan(previous, actionsSince(last_joint_epoch_[planner], out.epoch), H));
    }
  }
  const PlanningProblem problem{view.tracks, uavs, view.map, settings_};
  // Dec-POMDP (paper eq. 6): agent i applies its part of argmax_a J(b_i, a), a function of its
  // belief alone. The swarm only approximates the argmax, so every agent draws from the same
  // stream for this epoch: agents with equal beliefs reach the same joint plan, as the argmax
  // would, and the team does not miscoordinate through optimiser noise. Centralised planning
  // keeps the leader's own stream.
  RandomStream joint_stream(seed_, "pso.joint", static_cast<std::uint64_t>(out.epoch));
  RandomStream& rng =
      config_.algorithm == PlannerAlgorithm::dec_pomdp ? joint_stream : rng_[planner];
  if (joint_observer_) joint_observer_(out.epoch, planner, problem, warm);
  const Clock::time_point start = Clock::now();
  // Dec-POMDP: the blocks of the UAVs whose plans can interact with this agent's own; the others
  // keep their previous plans (planner.joint_blocks, agents/planning/interaction.h).
  const std::vector<int> blocks =
      config_.algorithm == PlannerAlgorithm::dec_pomdp &&
              config_.joint_blocks == JointBlocks::interacting
          ? interactingBlocks(problem, planner, order_)
          : order_;
  PlanSearch search = searchJointPlan(optimizers_[planner], problem, config_, blocks, warm, rng);
  const double seconds = secondsSince(start);
  last_joint_[planner] = search.plans;
  last_joint_epoch_[planner] = out.epoch;

  const std::vector<int> joint_epoch(n, out.epoch);
  const bool centralised = config_.algorithm == PlannerAlgorithm::centralized;
  for (int i = 0; i < n; ++i) {
    if (!centralised && i != planner) continue;
    const bool own = i == planner;
    Plan flown = search.plans[i];
    if (centralised) {
      out.messages.push_back(IntentionMessage{planner, i, out.epoch, search.plans[i]});
      if (!own) {
        // UAV i flies the latest order that has reached it (this one, when the link delivered
        // it at once), shifted by the time elapsed; it hovers until one does.
        links_.send(out.messages.back(), i);
        const IntentionMessage& order = links_.latest(i, i);
        flown = heldAt(order.plan, order.epoch, out.epoch);
      }
    }
    out.plans[i] = flown;
    out.reports[i] = AgentPlanReport{i,
                                     flown,
                                     search.plans,
                                     joint_epoch,
                                     search.cost,
                                     own ? seconds : 0.0,
                                     own ? search.iterations : 0,
                                     own ? search.evaluations : 0};
  }
}

}  // namespace canopy::agents::planning
