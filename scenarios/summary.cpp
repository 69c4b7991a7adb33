#include "scenarios/summary.h"

#include <algorithm>
#include <nlohmann/json.hpp>

namespace canopy::scenarios {

SummaryBuilder::SummaryBuilder(const ScenarioSpec& spec)
    : spec_(spec), targets_(spec.targets.size()), uavs_(spec.uavs.size()) {}

void SummaryBuilder::add(const Simulation& sim) {
  const world::WorldSnapshot& truth = sim.truth();
  if (!last_uav_position_.empty()) {
    for (std::size_t i = 0; i < uavs_.size(); ++i) {
      uavs_[i].distance += (truth.uavs[i].position - last_uav_position_[i]).norm();
    }
  }
  last_uav_position_.clear();
  for (const world::UavState& uav : truth.uavs) last_uav_position_.push_back(uav.position);

  visible_by_.assign(targets_.size(), 0);
  in_footprint_of_.assign(targets_.size(), 0);
  for (const sensing::Scan& scan : sim.scans()) {
    UavTally& tally = uavs_[scan.uav];
    tally.visible += static_cast<long>(scan.visible.size());
    tally.observations += static_cast<long>(scan.observations.size());
    for (const int t : scan.visible) ++visible_by_[t];
    for (const int t : scan.in_footprint) ++in_footprint_of_[t];
  }
  for (std::size_t t = 0; t < targets_.size(); ++t) {
    targets_[t].steps_visible += visible_by_[t] > 0;
    targets_[t].steps_in_footprint += in_footprint_of_[t] > 0;
    targets_[t].coverage += in_footprint_of_[t];
  }
  ++steps_;
}

std::string SummaryBuilder::json(double wall_seconds) const {
  using Json = nlohmann::json;
  const double steps = std::max(1, steps_);
  Json summary;
  summary["scenario"] = spec_.name;
  summary["seed"] = spec_.seed;
  summary["steps"] = steps_;
  summary["dt"] = spec_.dt;
  summary["trees"] = spec_.trees.size();
  Json targets = Json::array();
  double visible_sum = 0.0;
  for (std::size_t t = 0; t < targets_.size(); ++t) {
    const TargetTally& tally = targets_[t];
    visible_sum += tally.steps_visible / steps;
    targets.push_back({{"name", spec_.targets[t].name},
                       {"label", spec_.labels[spec_.targets[t].label]},
                       {"visible_fraction", tally.steps_visible / steps},
                       {"in_footprint_fraction", tally.steps_in_footprint / steps},
                       {"mean_coverage", static_cast<double>(tally.coverage) / steps}});
  }
  summary["targets"] = targets;
  Json uavs = Json::array();
  for (std::size_t i = 0; i < uavs_.size(); ++i) {
    uavs.push_back({{"name", spec_.uavs[i].name},
                    {"distance_m", uavs_[i].distance},
                    {"mean_visible_targets", static_cast<double>(uavs_[i].visible) / steps},
                    {"observations", uavs_[i].observations}});
  }
  summary["uavs"] = uavs;
  summary["team"] = {{"mean_visible_fraction",
                      targets_.empty() ? 0.0 : visible_sum / static_cast<double>(targets_.size())}};
  summary["timing"] = {{"wall_seconds", wall_seconds}};
  return summary.dump(2);
}

}  // namespace canopy::scenarios
