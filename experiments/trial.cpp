#include "experiments/trial.h"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <limits>
#include <string>
#include <nlohmann/json.hpp>

#include "core/printable.h"
#include "sim/simulation.h"
#include "spec/error.h"
#include "spec/json_reader.h"

namespace canopy::experiments {
namespace {
using Json = nlohmann::json;
constexpr int kMaxMaskTargets = 64;

// Every number in `value` (a number or nested arrays of them) is an integer within [lo, hi],
// lo ≤ 0: get<T>() of a float past T's range (a seed of 3·10¹⁹, read as a double) is undefined
// behaviour, and of a larger integer it wraps.
void requireIntegers(const Json& value, std::int64_t lo, std::uint64_t hi, const std::string& file,
                     const std::string& field) {
  if (value.is_array()) {
    for (const Json& element : value) requireIntegers(element, lo, hi, file, field);
    return;
  }
  if (!value.is_number()) return;  // get<T>() names the wrong type
  bool in_range = false;
  if (value.is_number_unsigned()) {
    in_range = value.get<std::uint64_t>() <= hi;
  } else if (value.is_number_integer()) {
    const std::int64_t v = value.get<std::int64_t>();
    in_range = v >= lo && (v < 0 || static_cast<std::uint64_t>(v) <= hi);
  }
  if (!in_range) {
    throw spec::ScenarioError(file, field,
                              "not a trial result: expected a whole number from " +
                                  std::to_string(lo) + " to " + std::to_string(hi));
  }
}
}  // namespace

TrialCollector::TrialCollector(const spec::ScenarioSpec& spec) {
  result_.scenario = spec.name;
  result_.seed = spec.seed;
  result_.dt = spec.dt;
  result_.uavs = static_cast<int>(spec.uavs.size());
  result_.targets = static_cast<int>(spec.targets.size());
  result_.trees = static_cast<int>(spec.trees.size());
  result_.tree_first_seen.assign(spec.trees.size(), -1);
  masks_ = result_.targets <= kMaxMaskTargets;
}

void TrialCollector::onStep(const sim::StepRecord& record) {
  const int k = record.step;
  std::vector<TargetBits> visible(result_.uavs, 0), in_footprint(result_.uavs, 0);
  for (const sim::UavRecord& uav : record.uavs) {
    const sensing::Scan& scan = uav.scan;
    if (masks_) {
      for (const int t : scan.visible) visible[scan.uav] |= TargetBits{1} << t;
      for (const int t : scan.in_footprint) in_footprint[scan.uav] |= TargetBits{1} << t;
    }
    for (const sensing::Observation& o : scan.observations) {
      if (o.label == sensing::kTreeLabel && result_.tree_first_seen[o.truth] < 0) {
        result_.tree_first_seen[o.truth] = k;
      }
    }
  }
  TargetBits occluded = 0;
  if (masks_) {
    for (int t = 0; t < result_.targets; ++t) {
      if (record.targets[t].occluded) occluded |= TargetBits{1} << t;
    }
  }
  truth_.clear();
  for (const sim::TargetRecord& target : record.targets) truth_.push_back(target.position);
  double ospa = 0.0, trace = 0.0;
  for (const agents::AgentBelief& belief : record.beliefs) {
    estimates_.clear();
    for (const agents::TrackEstimate& track : belief.tracks) {
      estimates_.push_back(track.belief.x.head<2>());
      trace += track.belief.P.topLeftCorner<2, 2>().trace();
    }
    ospa += ospa_(truth_, estimates_);
  }
  const double agents = std::max<double>(1.0, static_cast<double>(record.beliefs.size()));
  result_.ospa.push_back(ospa / agents);
  result_.trace.push_back(trace / agents);
  const sim::TeamFigures team = team_.compute(truth_, record.beliefs);
  result_.team_ospa.push_back(team.ospa);
  result_.held.push_back(truth_.empty() ? 1.0 : team.held / static_cast<double>(truth_.size()));
  if (record.plan) {
    for (const auto& report : record.plan->reports) result_.plan_seconds.push_back(report.seconds);
  }
  result_.visible.push_back(std::move(visible));
  result_.in_footprint.push_back(std::move(in_footprint));
  result_.occluded.push_back(occluded);
}

TrialResult runTrial(const spec::ScenarioSpec& spec, const std::string& config_id) {
  const auto start = std::chrono::steady_clock::now();
  sim::Simulation sim(spec);
  TrialCollector collector(spec);
  sim::StepObserver* const observers[] = {&collector};
  sim::runToEnd(sim, observers);
  TrialResult result = collector.take();
  result.config_id = config_id;
  result.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

std::string trialToJson(const TrialResult& trial) {
  Json j;
  j["scenario"] = trial.scenario;
  j["config_id"] = trial.config_id;
  j["seed"] = trial.seed;
  j["dt"] = trial.dt;
  j["uavs"] = trial.uavs;
  j["targets"] = trial.targets;
  j["trees"] = trial.trees;
  j["visible"] = trial.visible;
  j["in_footprint"] = trial.in_footprint;
  j["occluded"] = trial.occluded;
  j["tree_first_seen"] = trial.tree_first_seen;
  j["ospa"] = trial.ospa;
  j["trace"] = trial.trace;
  j["team_ospa"] = trial.team_ospa;
  j["held"] = trial.held;
  return j.dump();
}

TrialResult trialFromJson(const std::string& text, const std::string& file) {
  TrialResult trial;
  try {
    const Json j = spec::parseBoundedJson(text);
    constexpr std::uint64_t kIntMax = std::numeric_limits<int>::max();
    constexpr std::uint64_t kU64Max = std::numeric_limits<std::uint64_t>::max();
    for (const char* field : {"uavs", "targets", "trees"}) {
      if (j.contains(field)) requireIntegers(j.at(field), 0, kIntMax, file, field);
    }
    if (j.contains("tree_first_seen"))
      requireIntegers(j.at("tree_first_seen"), -1, kIntMax, file, "tree_first_seen");
    for (const char* field : {"seed", "visible", "in_footprint", "occluded"}) {
      if (j.contains(field)) requireIntegers(j.at(field), 0, kU64Max, file, field);
    }
    trial.scenario = j.at("scenario").get<std::string>();
    trial.config_id = j.at("config_id").get<std::string>();
    trial.seed = j.at("seed").get<std::uint64_t>();
    trial.dt = j.at("dt").get<double>();
    trial.uavs = j.at("uavs").get<int>();
    trial.targets = j.at("targets").get<int>();
    trial.trees = j.at("trees").get<int>();
    trial.visible = j.at("visible").get<std::vector<std::vector<TargetBits>>>();
    trial.in_footprint = j.at("in_footprint").get<std::vector<std::vector<TargetBits>>>();
    trial.occluded = j.at("occluded").get<std::vector<TargetBits>>();
    trial.tree_first_seen = j.at("tree_first_seen").get<std::vector<int>>();
    trial.ospa = j.at("ospa").get<std::vector<double>>();
    trial.trace = j.at("trace").get<std::vector<double>>();
    if (j.contains("team_ospa")) trial.team_ospa = j.at("team_ospa").get<std::vector<double>>();
    if (j.contains("held")) trial.held = j.at("held").get<std::vector<double>>();
  } catch (const Json::exception& e) {
    throw spec::ScenarioError(file, "", "not a trial result: " + printable(e.what(), 200));
  } catch (const std::logic_error&) {  // JsonTooDeep, JsonDuplicateKey
    throw spec::ScenarioError(file, "", "not a trial result: nested too deep or a key twice");
  }
  const std::size_t steps = trial.occluded.size();
  if (trial.visible.size() != steps || trial.in_footprint.size() != steps ||
      trial.ospa.size() != steps || trial.trace.size() != steps ||
      (!trial.team_ospa.empty() && trial.team_ospa.size() != steps) ||
      trial.held.size() != trial.team_ospa.size()) {
    throw spec::ScenarioError(file, "", "not a trial result: per-step arrays differ in length");
  }
  for (std::size_t k = 0; k < steps; ++k) {
    if (trial.visible[k].size() != static_cast<std::size_t>(trial.uavs) ||
        trial.in_footprint[k].size() != static_cast<std::size_t>(trial.uavs)) {
      throw spec::ScenarioError(file, "step " + std::to_string(k),
                                "not a trial result: expected one set per UAV");
    }
  }
  return trial;
}

}  // namespace canopy::experiments
