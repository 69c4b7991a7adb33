#include "scenarios/recorder.h"

#include <nlohmann/json.hpp>
#include <stdexcept>

namespace canopy::scenarios {
namespace {
using Json = nlohmann::json;

Json vec(const Vec2& v) { return Json::array({v.x(), v.y()}); }
Json sym(const Mat2& m) { return Json::array({m(0, 0), m(0, 1), m(1, 1)}); }  // upper triangle
}  // namespace

std::string recordLine(const Simulation& sim) {
  const ScenarioSpec& spec = sim.spec();
  const world::WorldSnapshot& truth = sim.truth();
  Json line;
  line["k"] = truth.step;
  line["t"] = truth.time;
  Json& targets = line["targets"] = Json::array();
  for (const world::TargetState& target : truth.targets) {
    targets.push_back({{"p", vec(target.position)}, {"v", vec(target.velocity)}});
  }
  Json& uavs = line["uavs"] = Json::array();
  for (std::size_t i = 0; i < truth.uavs.size(); ++i) {
    const world::UavState& uav = truth.uavs[i];
    uavs.push_back({{"p", vec(uav.position)}, {"v", vec(uav.velocity)}, {"yaw", uav.yaw},
                    {"cmd", vec(sim.world().commandedVelocity(static_cast<int>(i)))}});
  }
  Json& scans = line["scans"] = Json::array();
  for (const sensing::Scan& scan : sim.scans()) {
    Json observations = Json::array();
    for (const sensing::Observation& o : scan.observations) {
      Json obs = {{"label", spec.labels[o.label]}, {"z", vec(o.z)}, {"R", sym(o.R)}, {"truth", o.truth}};
      if (o.label == sensing::kTreeLabel) obs["radius"] = o.radius;
      observations.push_back(std::move(obs));
    }
    scans.push_back({{"uav", scan.uav},
                     {"in_footprint", scan.in_footprint},
                     {"visible", scan.visible},
                     {"obs", std::move(observations)}});
  }
  return line.dump();
}

Recorder::Recorder(const std::string& path) : out_(path, std::ios::binary | std::ios::trunc) {
  if (!out_) throw std::runtime_error("cannot write " + path);
}

void Recorder::write(const Simulation& sim) { out_ << recordLine(sim) << '\n'; }

}  // namespace canopy::scenarios
