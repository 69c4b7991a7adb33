#include "sim/simulation.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "agents/planning/altitude_choice.h"
#include "sim/finite_check.h"

namespace canopy::sim {

agents::TeamConfig teamConfig(const spec::ScenarioSpec& spec) {
  agents::TeamConfig config;
  config.tracking = spec.tracking;
  config.tracking.area = spec.aoi;  // bounds a lost known person (agents/tracking/known_people.h)
  config.fusion = spec.fusion;
  config.planner = spec.planner;
  for (const spec::UavSpec& uav : spec.uavs) {
    agents::planning::UavState state;
    state.position = uav.body.start;
    state.yaw = uav.body.yaw;
    state.yaw_mode = uav.body.yaw_mode;
    state.v_max = uav.body.v_max;
    state.kind = uav.body.kind;
    state.turn_rate = uav.body.turn_rate;
    state.radius = uav.body.radius;
    state.footprint = sensing::footprintAt(uav.sensor, uav.body.z);  // at its start altitude
    state.z = uav.body.z;
    state.z_min = uav.body.z_min;
    state.z_max = uav.body.z_max;
    state.climb_rate = uav.body.climb_rate;
    state.camera = uav.sensor.camera;
    state.reference_alpha = uav.sensor.quality.alpha;
    if (uav.sensor.camera) state = agents::planning::atAltitude(state, uav.body.z);
    state.quality = uav.sensor.quality;
    state.occlusion = sensing::occlusionModel(uav.sensor, spec.sensing);
    config.uavs.push_back(state);
  }
  if (spec.planner.occlusion_map == agents::OcclusionMapMode::a_priori)
    config.true_trees = spec.trees;
  config.seed = spec.seed;
  config.dt = spec.dt;
  return config;
}

Simulation::Simulation(spec::ScenarioSpec spec, int threads)
    : spec_(std::move(spec)),
      world_(spec_.worldDef()),
      team_(teamConfig(spec_)),
      target_labels_(spec_.targetLabels()) {
  if (threads < 1 || threads > kMaxThreads) {
    throw std::invalid_argument("Simulation: threads = " + std::to_string(threads) +
                                ", expected 1.." + std::to_string(kMaxThreads));
  }
  if (threads > 1) {
    pool_ = std::make_unique<TaskPool>(threads);
    team_.setPool(pool_.get());
  }
  const std::size_t n = spec_.uavs.size();
  for (std::size_t i = 0; i < n; ++i) sensing_rng_.emplace_back(spec_.seed, "sensing", i);
  for (const spec::UavSpec& uav : spec_.uavs) uav_names_.push_back(uav.name);
  scratch_.resize(n);
  commands_.assign(n, Vec2::Zero());
  climb_commands_.assign(n, 0.0);
  record_.uavs.resize(n);
  record_.targets.resize(spec_.targets.size());
  steps_per_plan_ = agents::stepsPerReplan(spec_.planner, spec_.dt);
  if (spec_.tracking.preseed) {
    // Paper: every OOI starts with a track of the same P₀ at every agent, centred on the truth.
    for (std::size_t t = 0; t < spec_.targets.size(); ++t) {
      const world::Path& path = spec_.targets[t].path;
      Vec4 state;
      state << path.positionAt(0.0), path.velocityAt(0.0);
      team_.preseed(static_cast<int>(t), spec_.targets[t].label, state);
    }
  }
}

void Simulation::readTruth() {
  record_.step = truth_.step;
  record_.time = truth_.time;
  for (std::size_t i = 0; i < record_.uavs.size(); ++i) {
    UavRecord& uav = record_.uavs[i];
    uav.position = truth_.uavs[i].position;
    uav.yaw = truth_.uavs[i].yaw;
    uav.velocity = truth_.uavs[i].velocity;
    uav.contacts = truth_.uavs[i].contacts;
    uav.contacts_begun = truth_.uavs[i].contacts_begun;
    uav.z = truth_.uavs[i].z;
    uav.climb = truth_.uavs[i].climb;
    uav.altitude = spec_.uavs[i].sensor.camera.has_value();
  }
  // Whether a target is under a crown is a const query of the forest: the targets side by side,
  // each writing its own record (a point query among 10⁵ crowns takes a few µs).
  forEachTask(pool_.get(), record_.targets.size(), [&](std::size_t t) {
    TargetRecord& target = record_.targets[t];
    target.position = truth_.targets[t].position;
    target.velocity = truth_.targets[t].velocity;
    target.occluded = world_.insideOccluder(target.position);
  });
}

void Simulation::senseAndTrack(double dt) {
  // UAV i's scan reads the world (const queries) and writes its own stream, scratch and record;
  // agent i's tracker reads that scan only: the UAVs run side by side.
  forEachTask(pool_.get(), record_.uavs.size(), [&](std::size_t i) {
    const int uav = static_cast<int>(i);
    const sensing::SensorDef& sensor = spec_.uavs[i].sensor;
    UavRecord& record = record_.uavs[i];
    record.footprint = sensing::footprintOf(truth_, uav, sensor);
    sensing::sense(world_, truth_, uav, sensor, spec_.sensing, target_labels_, sensing_rng_[i],
                   scratch_[i], record.scan);
    team_.trackLocally(uav, dt, record.position, record.yaw, record.scan, record.footprint);
    if (record.altitude) team_.setAltitude(uav, record.z);
  });
}

void Simulation::commandScriptedUavs() {
  // Scripted sweeps: aim at the path's position one step ahead (clamped to v_max by the world),
  // and at its altitude one step ahead, ż = (z(t + dt) − z) / dt (clamped to the climb rate and
  // [z_min, z_max] by the world).
  const double t_next = world_.time() + spec_.dt;
  for (std::size_t i = 0; i < spec_.uavs.size(); ++i) {
    const auto& path = spec_.uavs[i].path;
    commands_[i] = path ? Vec2((path->positionAt(t_next) - record_.uavs[i].position) / spec_.dt)
                        : Vec2::Zero();
    if (const auto& profile = spec_.uavs[i].altitude_profile)
      climb_commands_[i] = (profile->altitudeAt(t_next) - record_.uavs[i].z) / spec_.dt;
  }
}

void Simulation::commandFromPlan() {
  // Receding horizon: plan every replan_period from t = 0, apply the first action, hold it.
  if (record_.step % steps_per_plan_ != 0) return;
  record_.plan = team_.plan(record_.step / steps_per_plan_);
  for (std::size_t i = 0; i < record_.plan->plans.size(); ++i) {
    commands_[i] = record_.plan->plans[i].command();
    climb_commands_[i] = team_.climbCommand(static_cast<int>(i));
  }
}

void Simulation::commandUavs() {
  // Every UAV is commanded every step, so an external command (commandNext) lasts one step.
  for (std::size_t i = 0; i < commands_.size(); ++i) {
    world_.commandUav(static_cast<int>(i), commands_[i]);
    record_.uavs[i].command = world_.commandedVelocity(static_cast<int>(i));
    world_.commandClimb(static_cast<int>(i), climb_commands_[i]);
    record_.uavs[i].climb_command = world_.commandedClimb(static_cast<int>(i));
  }
}

void Simulation::readTeam() {
  team_.writeBeliefs(record_.beliefs);
  const std::vector<agents::Agent>& agents = team_.agents();
  record_.counts.resize(agents.size());
  for (std::size_t i = 0; i < agents.size(); ++i) {
    record_.counts[i] = {agents[i].tracker().targets().size(), agents[i].map().trees().size(),
                         agents[i].tracker().diagnostics()};
  }
  record_.fusion = team_.fusion().diagnostics();
  record_.intentions = team_.planner().intentionCounts();
}

void Simulation::commandNext(int uav, const Vec2& velocity) {
  if (next_step_ == 0 || done())
    throw std::logic_error("Simulation::commandNext: only between ticks, after the first");
  if (uav < 0 || uav >= static_cast<int>(spec_.uavs.size()))
    throw std::out_of_range("Simulation::commandNext: no UAV " + std::to_string(uav));
  if (!velocity.allFinite())
    throw std::invalid_argument("Simulation::commandNext: velocity not finite");
  world_.commandUav(uav, velocity);
}

void Simulation::commandClimbNext(int uav, double climb) {
  if (next_step_ == 0 || done())
    throw std::logic_error("Simulation::commandClimbNext: only between ticks, after the first");
  if (uav < 0 || uav >= static_cast<int>(spec_.uavs.size()))
    throw std::out_of_range("Simulation::commandClimbNext: no UAV " + std::to_string(uav));
  if (!std::isfinite(climb))
    throw std::invalid_argument("Simulation::commandClimbNext: climb not finite");
  world_.commandClimb(uav, climb);
}

const StepRecord& Simulation::tick() {
  const double dt = next_step_ > 0 ? spec_.dt : 0.0;
  if (next_step_ > 0) world_.step(spec_.dt);  // applies the commands set at the previous step
  truth_ = world_.snapshot();
  readTruth();
  senseAndTrack(dt);
  team_.fuse();
  record_.plan.reset();
  if (team_.plans()) {
    commandFromPlan();
  } else {
    commandScriptedUavs();
  }
  commandUavs();
  readTeam();
  checkFinite(record_, uav_names_);  // no NaN reaches an observer (sim/finite_check.h)
  ++next_step_;
  return record_;
}

}  // namespace canopy::sim
