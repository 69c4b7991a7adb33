#include "scenarios/recorder.h"

#include <nlohmann/json.hpp>

namespace canopy::scenarios {
namespace {
using Json = nlohmann::json;

Json vec(const Vec2& v) {
  return Json::array({v.x(), v.y()});
}
Json sym(const Mat2& m) {
  return Json::array({m(0, 0), m(0, 1), m(1, 1)});
}  // upper triangle

template <typename Vector>
Json values(const Vector& x) {
  Json a = Json::array();
  for (int r = 0; r < x.size(); ++r) a.push_back(x(r));
  return a;
}
template <typename Matrix>
Json upperTriangle(const Matrix& P) {  // row by row: P00, P01, …, P0n, P11, …
  Json a = Json::array();
  for (int r = 0; r < P.rows(); ++r) {
    for (int c = r; c < P.cols(); ++c) a.push_back(P(r, c));
  }
  return a;
}
Json key(const agents::TrackKey& k) {
  return Json::array({k.origin, k.serial});
}

Json beliefJson(const ScenarioSpec& spec, const agents::AgentBelief& belief) {
  Json tracks = Json::array(), map = Json::array(), path = Json::array();
  for (const agents::TrackEstimate& t : belief.tracks) {
    tracks.push_back({{"key", key(t.key)},
                      {"label", spec.labels[t.label]},
                      {"x", values(t.belief.x)},
                      {"P", upperTriangle(t.belief.P)}});
  }
  for (const agents::TreeEstimate& t : belief.trees) {
    map.push_back(
        {{"key", key(t.key)}, {"x", values(t.belief.x)}, {"P", upperTriangle(t.belief.P)}});
  }
  for (const Vec2& p : belief.planned_path) path.push_back(vec(p));
  return {{"tracks", tracks}, {"map", map}, {"planned_path", path}};
}

Json planJson(const agents::planning::TeamPlan& plan) {
  using agents::planning::Plan;
  auto velocities = [](const Plan& p) {
    Json a = Json::array();
    for (const Vec2& v : p.velocities) a.push_back(vec(v));
    return a;
  };
  Json agents = Json::array(), messages = Json::array();
  for (const auto& report : plan.reports) {
    agents.push_back({{"agent", report.agent},
                      {"velocities", velocities(report.plan)},
                      {"cost", report.cost},
                      {"joint_epoch", report.joint_epoch},
                      {"iterations", report.iterations},
                      {"evaluations", report.evaluations}});
  }
  for (const auto& m : plan.messages) {
    messages.push_back({{"from", m.from},
                        {"agent", m.agent},
                        {"epoch", m.epoch},
                        {"velocities", velocities(m.plan)}});
  }
  return {{"epoch", plan.epoch}, {"agents", agents}, {"messages", messages}};
}

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
    uavs.push_back({{"p", vec(uav.position)},
                    {"v", vec(uav.velocity)},
                    {"yaw", uav.yaw},
                    {"cmd", vec(sim.world().commandedVelocity(static_cast<int>(i)))}});
  }
  Json& scans = line["scans"] = Json::array();
  for (const sensing::Scan& scan : sim.scans()) {
    Json observations = Json::array();
    for (const sensing::Observation& o : scan.observations) {
      Json obs = {
          {"label", spec.labels[o.label]}, {"z", vec(o.z)}, {"R", sym(o.R)}, {"truth", o.truth}};
      if (o.label == sensing::kTreeLabel) obs["radius"] = o.radius;
      observations.push_back(std::move(obs));
    }
    scans.push_back({{"uav", scan.uav},
                     {"in_footprint", scan.in_footprint},
                     {"visible", scan.visible},
                     {"obs", std::move(observations)}});
  }
  Json& agents = line["agents"] = Json::array();
  for (const agents::AgentBelief& belief : sim.beliefs())
    agents.push_back(beliefJson(spec, belief));
  if (sim.plan()) line["plan"] = planJson(*sim.plan());
  return line.dump();
}

Recorder::Recorder(const std::filesystem::path& dir)
    : record_(dir / "record.jsonl"), timings_(dir / "timings.jsonl") {}

void Recorder::write(const Simulation& sim) {
  record_.write(recordLine(sim) + '\n');
  if (sim.plan()) {
    Json seconds = Json::array();
    for (const auto& report : sim.plan()->reports) seconds.push_back(report.seconds);
    timings_.write(
        Json{{"k", sim.truth().step}, {"epoch", sim.plan()->epoch}, {"plan_seconds", seconds}}
            .dump() +
        '\n');
  }
}

void Recorder::commit() {
  record_.commit();
  timings_.commit();
}

}  // namespace canopy::scenarios
