#include "agents/team.h"

#include "agents/planning/altitude_choice.h"

#include <cmath>
#include <utility>
#include <vector>

namespace canopy::agents {

Team::Team(const TeamConfig& config)
    : config_(config),
      fusion_(config.fusion, static_cast<int>(config.uavs.size()), config.seed, config.dt,
              config.tracking.sigma_a),
      planner_(config.planner, config.tracking.sigma_a, config.seed,
               planning::LinkConfig{config.fusion.comm_range, config.fusion.comm_drop,
                                    config.fusion.comm_latency,
                                    stepsPerReplan(config.planner, config.dt)}),
      a_priori_(config.true_trees),
      uav_states_(config.uavs),
      planned_paths_(config.uavs.size()),
      climbs_(config.uavs.size(), 0.0) {
  for (int i = 0; i < static_cast<int>(config.uavs.size()); ++i) {
    const planning::UavState& uav = config.uavs[i];
    agents_.emplace_back(
        i, config.tracking,
        tracking::CameraOcclusion{uav.occlusion, uav.kind == world::AgentKind::ground});
  }
}

void Team::preseed(int target, sensing::LabelId label, const Vec4& state) {
  for (Agent& agent : agents_) agent.preseed(target, label, state);
}

void Team::trackLocally(int agent, double dt, const Vec2& position, double yaw,
                        const sensing::Scan& scan, const sensing::Footprint& footprint) {
  uav_states_[agent].position = position;
  uav_states_[agent].yaw = yaw;
  agents_[agent].trackLocally(dt, scan, footprint);
}

void Team::fuse() {
  fusion_inputs_.clear();
  for (std::size_t i = 0; i < agents_.size(); ++i) {
    const tracking::Tracker& tracker = agents_[i].tracker();
    fusion_inputs_.push_back({tracker.targets(), tracker.trees(), uav_states_[i].position});
  }
  fusion_.fuse(fusion_inputs_, fused_);
  const double range = config_.fusion.interest_range;
  forEachTask(pool_, agents_.size(), [&](std::size_t i) {
    if (std::isfinite(range)) {  // forget what lies beyond the agent's interest
      const Vec2 p = uav_states_[i].position;
      std::erase_if(fused_.targets[i], [&](const tracking::TargetTrack& t) {
        return (t.posterior.x.head<2>() - p).norm() > range;
      });
      std::erase_if(fused_.trees[i], [&](const tracking::TreeTrack& t) {
        return (t.posterior.x.head<2>() - p).norm() > range;
      });
    }
    agents_[i].adoptFused(std::move(fused_.targets[i]), std::move(fused_.trees[i]));
  });
}

std::optional<planning::TeamPlan> Team::plan(int epoch) {
  if (!plans()) return std::nullopt;
  planning_views_.clear();
  for (std::size_t i = 0; i < agents_.size(); ++i) {
    const OcclusionMap* map = nullptr;  // "none": nothing occludes
    if (config_.planner.occlusion_map == OcclusionMapMode::a_priori) map = &a_priori_;
    if (config_.planner.occlusion_map == OcclusionMapMode::dynamic) map = &agents_[i].map();
    planning_views_.push_back({agents_[i].planningTracks(), map});
  }
  planning::TeamPlan plan = planner_.plan(epoch, uav_states_, planning_views_);
  // Height: a UAV whose altitude is free flies its plan's first climb rate (the swarm chose it
  // with the speeds and headings, plan_optimizer.h).
  for (std::size_t i = 0; i < agents_.size(); ++i)
    climbs_[i] = planning::altitudeFree(uav_states_[i]) ? plan.plans[i].climb(0) : 0.0;
  for (std::size_t i = 0; i < agents_.size(); ++i) {
    planned_paths_[i] =
        planning::plannedPath(uav_states_[i], plan.plans[i], config_.planner.plan_period);
  }
  return plan;
}

void Team::setAltitude(int agent, double z) {
  planning::UavState& u = uav_states_[static_cast<std::size_t>(agent)];
  if (u.z != z) u = planning::atAltitude(u, z);
}

void Team::writeBeliefs(std::vector<AgentBelief>& out) const {
  out.resize(agents_.size());
  forEachTask(pool_, agents_.size(), [&](std::size_t i) {
    agents_[i].writeBelief(out[i]);
    out[i].planned_path = planned_paths_[i];
  });
}

}  // namespace canopy::agents
