#pragma once
// A finished run read back from its folder (manifest.json, record.jsonl, summary.json) as plain
// values: what the replay shows. The record's keys are docs/output-formats.md's.
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "core/types.h"
#include "spec/scenario_spec.h"

namespace canopy::replay {

/// One fused target track of an agent (record: agents[].tracks[]).
struct RecordedTrack {
  std::string key;  // "origin:serial"
  std::string label;
  Vec2 position = Vec2::Zero();                     // m
  Vec2 velocity = Vec2::Zero();                     // m/s
  Eigen::Vector3d P_pos = Eigen::Vector3d::Zero();  // m², the position block packed [Pxx, Pxy, Pyy]
};

/// One tree track of an agent's occlusion map (record: agents[].map[]).
struct RecordedMapEntry {
  std::string key;
  Eigen::Vector3d crown = Eigen::Vector3d::Zero();  // [cx, cy, r] (m)
  std::vector<Vec2> outline;  // polygons only: vertex offsets from the centre (m)
};

/// One agent at one step: its true pose, its scan and its fused belief.
struct RecordedAgent {
  Vec2 position = Vec2::Zero();            // m
  double yaw = 0.0;                        // rad
  double z = std::numeric_limits<double>::quiet_NaN();  // m, altitude (UAVs with one, issue 53)
  std::vector<std::string> contacts;       // what its body touched: "wall:3", "uav:1", …
  std::vector<int> in_footprint, visible;  // target indices
  std::vector<RecordedTrack> tracks;
  std::vector<RecordedMapEntry> map;
  std::vector<Vec2> planned_path;  // m
};

/// A planning epoch's plans and the intention messages sent at it (record: plan).
struct RecordedPlan {
  struct Part {
    int agent = 0;
    double cost = 0.0;             // m²
    std::vector<Vec2> velocities;  // m/s, one per action
    std::vector<int> joint_epoch;  // per teammate: the epoch of its plan this agent planned
                                   // against (−1: none had reached it)
  };
  /// A message sent at this epoch, in the order sent (SMA-NBO: the planning order).
  struct Message {
    int agent = 0, from = 0, epoch = 0;  // the UAV whose actions it holds, its sender, its epoch
    std::vector<Vec2> velocities;        // m/s
  };
  int epoch = 0;
  std::vector<Part> agents;
  std::vector<Message> messages;
};

struct RecordedStep {
  int k = 0;
  double t = 0.0;             // s
  std::vector<Vec2> targets;  // true positions (m)
  std::vector<RecordedAgent> agents;
  std::optional<RecordedPlan> plan;
};

struct RunFolder {
  std::filesystem::path dir;
  spec::ScenarioSpec spec;  // the manifest's effective configuration, loaded
  std::vector<RecordedStep> steps;
  std::vector<std::vector<double>> ospa;  // [agent][k] (m), summary.json's uavs[].ospa_m
};

/// Reads the run in `dir`. Throws ScenarioError naming the file (and line and field) when the
/// folder is missing, a file is missing, or a file is not what `canopy run` writes.
RunFolder readRunFolder(const std::filesystem::path& dir);

}  // namespace canopy::replay
