#include "replay/run_folder.h"

#include <nlohmann/json.hpp>

#include "core/text_file.h"
#include "sim/record_reader.h"
#include "sim/record_step_reader.h"
#include "spec/error.h"
#include "spec/json_text.h"

namespace canopy::replay {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;
using spec::ScenarioError;

// Bounded like a scenario file (spec::readResultText): a regular file, a record at most
// kMaxResultBytes, the other files at most kMaxJsonBytes.
std::string readText(const fs::path& path, const std::string& what) {
  return spec::readResultText(path, "the " + what + " that `canopy run` writes",
                              what == "record" ? spec::kMaxResultBytes : spec::kMaxJsonBytes);
}

Json parseWhole(const fs::path& path, const std::string& what) {
  Json json = spec::parseJson(readText(path, what), path.string());  // names depth, syntax
  if (!json.is_object())
    throw ScenarioError(path.string(), "", "is not a JSON object (not the " + what + " of a run)");
  return json;
}

// What the replay shows of a step read by the record's reader (sim/record_step_reader.h).
RecordedStep recordedStep(const sim::StepRecord& record, const std::vector<std::string>& labels) {
  RecordedStep s;
  s.k = record.step;
  s.t = record.time;
  for (const sim::TargetRecord& target : record.targets) s.targets.push_back(target.position);
  for (std::size_t i = 0; i < record.uavs.size(); ++i) {
    const sim::UavRecord& uav = record.uavs[i];
    RecordedAgent& a = s.agents.emplace_back();
    a.position = uav.position;
    a.yaw = uav.yaw;
    if (uav.altitude) a.z = uav.z;  // only UAVs whose scenario gives an altitude (issue 53)
    for (const world::BodyRef& c : uav.contacts)
      a.contacts.push_back(sim::codec::Contacts::name(c));
    a.in_footprint = uav.scan.in_footprint;
    a.visible = uav.scan.visible;
    const agents::AgentBelief& belief = record.beliefs[i];
    for (const agents::TrackEstimate& track : belief.tracks) {
      RecordedTrack& t = a.tracks.emplace_back();
      t.key = std::to_string(track.key.origin) + ":" + std::to_string(track.key.serial);
      t.label = labels.at(static_cast<std::size_t>(track.label));
      t.position = track.belief.x.head<2>();
      t.velocity = track.belief.x.tail<2>();
      t.P_pos = {track.belief.P(0, 0), track.belief.P(0, 1), track.belief.P(1, 1)};
    }
    for (const agents::TreeEstimate& tree : belief.trees) {
      RecordedMapEntry& e = a.map.emplace_back();
      e.key = std::to_string(tree.key.origin) + ":" + std::to_string(tree.key.serial);
      e.crown = tree.belief.x;
      for (int v = 0; v < tree.outline.vertices; ++v)
        e.outline.push_back(tree.outline.offsets[static_cast<std::size_t>(v)]);
    }
    a.planned_path = belief.planned_path;
  }
  if (record.plan) {
    RecordedPlan& p = s.plan.emplace();
    p.epoch = record.plan->epoch;
    for (const agents::planning::AgentPlanReport& report : record.plan->reports)
      p.agents.push_back({report.agent, report.cost, report.plan.velocities, report.joint_epoch});
    for (const agents::planning::IntentionMessage& m : record.plan->messages)
      p.messages.push_back({m.agent, m.from, m.epoch, m.plan.velocities});
  }
  return s;
}

std::vector<RecordedStep> readRecord(const fs::path& path, const spec::ScenarioSpec& spec) {
  std::vector<RecordedStep> steps;
  sim::forEachRecordStep(
      path, sim::shapeOf(spec), {}, [&](const sim::StepRecord& record, int number) {
        if (record.step != static_cast<int>(steps.size()))
          sim::failRecordLine(
              path.string(), number, "k",
              "step " + std::to_string(steps.size()) + " (one line per step, in order)");
        steps.push_back(recordedStep(record, spec.labels));
      });
  if (steps.empty()) throw ScenarioError(path.string(), "", "has no steps");
  return steps;
}

// summary.json's uavs[].ospa_m, one list per agent and one value per recorded step.
std::vector<std::vector<double>> readOspa(const fs::path& path, std::size_t agents,
                                          std::size_t steps) {
  const Json summary = parseWhole(path, "summary");
  const std::string file = path.string();
  if (!summary.contains("uavs") || !summary["uavs"].is_array() || summary["uavs"].size() != agents)
    throw ScenarioError(file, "uavs", "expected one entry per UAV of the manifest's scenario");
  std::vector<std::vector<double>> ospa;
  for (std::size_t i = 0; i < agents; ++i) {
    const Json& uav = summary["uavs"][i];
    const std::string at = "uavs." + std::to_string(i) + ".ospa_m";
    if (!uav.is_object() || !uav.contains("ospa_m") || !uav["ospa_m"].is_array() ||
        uav["ospa_m"].size() != steps)
      throw ScenarioError(file, at, "expected one OSPA value per step of record.jsonl");
    std::vector<double>& values = ospa.emplace_back();
    for (const Json& v : uav["ospa_m"]) {
      if (!v.is_number()) throw ScenarioError(file, at, "expected numbers");
      values.push_back(v.get<double>());
    }
  }
  return ospa;
}

}  // namespace

RunFolder readRunFolder(const fs::path& dir) {
  std::error_code error;
  if (!fs::is_directory(dir, error)) {
    throw ScenarioError(dir.string(), "",
                        "no such directory (expected the --out directory of `canopy run`)");
  }
  RunFolder run;
  run.dir = dir;
  run.spec = sim::readManifest(dir / "manifest.json");
  run.steps = readRecord(sim::recordFileOf(dir), run.spec);
  run.ospa = readOspa(dir / "summary.json", run.spec.uavs.size(), run.steps.size());
  return run;
}

}  // namespace canopy::replay
