#include "scenarios/simulation.h"

namespace canopy::scenarios {

Simulation::Simulation(const ScenarioSpec& spec)
    : spec_(spec), world_(spec.worldDef()), target_labels_(spec.targetLabels()) {
  const std::size_t n = spec.uavs.size();
  for (std::size_t i = 0; i < n; ++i) sensing_rng_.emplace_back(spec.seed, "sensing", i);
  scans_.resize(n);
  beliefs_.resize(n);
}

void Simulation::commandScriptedUavs() {
  // Scripted sweeps: aim at the path's position one step ahead (clamped to v_max by the world).
  const double t_next = world_.time() + spec_.dt;
  for (std::size_t i = 0; i < spec_.uavs.size(); ++i) {
    const auto& path = spec_.uavs[i].path;
    const Vec2 command = path ? Vec2((path->positionAt(t_next) - truth_.uavs[i].position) / spec_.dt)
                              : Vec2::Zero();
    world_.commandUav(static_cast<int>(i), command);
  }
}

void Simulation::tick() {
  if (next_step_ > 0) world_.step(spec_.dt);  // applies the commands set at the previous step
  truth_ = world_.snapshot();
  for (std::size_t i = 0; i < spec_.uavs.size(); ++i) {
    sensing::sense(world_, truth_, static_cast<int>(i), spec_.uavs[i].sensor, spec_.sensing,
                   target_labels_, sensing_rng_[i], scratch_, scans_[i]);
  }
  commandScriptedUavs();
  ++next_step_;
}

}  // namespace canopy::scenarios
