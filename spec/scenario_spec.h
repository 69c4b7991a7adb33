#pragma once
// ScenarioSpec: everything a scenario file says, validated and with defaults filled in. Constant
// for the life of a trial (the model, in MuJoCo's sense; World and agents hold the data).
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "agents/config.h"
#include "core/types.h"
#include "sensing/sensor.h"
#include "world/altitude_profile.h"
#include "world/defs.h"

namespace canopy::spec {

struct UavSpec {
  std::string name;
  world::UavDef body;               // start, yaw, yaw mode, v_max
  sensing::SensorDef sensor;        // footprint and quality (α, r0)
  std::optional<world::Path> path;  // scripted sweep, followed when no planner runs
  /// The altitudes its scripted path's points give (issue 53), flown when the path is.
  std::optional<world::AltitudeProfile> altitude_profile;
};

struct TargetSpec {
  std::string name;
  sensing::LabelId label = 1;  // index into ScenarioSpec::labels
  world::Path path;
};

/// An ownership assignment the analysis compares against (paper §IV): sets[i] holds the targets
/// (indices) owned by UAV i. With any_permutation, any order of the UAVs matches.
struct NamedOwnership {
  std::string name;
  std::vector<std::vector<int>> sets;
  bool any_permutation = false;
};

struct AnalysisSpec {
  int m = 5;                           // m of m-Ownership (steps)
  double oa_margin = 1.0;              // s, h of Occlusion_Aware around an occluded interval
  std::vector<NamedOwnership> states;  // e.g. M0 and M*
};

struct ScenarioSpec {
  std::string name;
  std::string description;
  std::filesystem::path file;  // where it was loaded from (empty if built in code)

  Aabb aoi;                // m
  double dt = 0.2;         // s, simulation step
  double duration = 20.0;  // s
  std::uint64_t seed = 1;  // the trial seed (overridden by --seed)

  std::vector<std::string> labels{"tree", "human"};  // labels[0] is always "tree"
  sensing::SensingConfig sensing;
  std::vector<UavSpec> uavs;
  std::vector<TargetSpec> targets;
  std::vector<world::TreeDef> trees;  // every occluder, explicit and generated
  /// Per included layout made by `canopy import`: "FILE: imported from …: N trees, …".
  std::vector<std::string> layout_sources;

  agents::TrackingConfig tracking;
  agents::FusionConfig fusion;
  agents::PlannerConfig planner;
  AnalysisSpec analysis;

  std::string effective_config;  // JSON: the file after overrides, defaults filled in

  /// K: the number of steps after the initial one (states k = 0..K).
  int steps() const;
  world::WorldDef worldDef() const;
  std::vector<sensing::LabelId> targetLabels() const;
};

}  // namespace canopy::spec
