#pragma once
// Private to scenarios/: readers for each section of a scenario file.
#include <string>
#include <vector>

#include "spec/json_reader.h"
#include "spec/json_text.h"
#include "spec/scenario_spec.h"

namespace canopy::spec::internal {

constexpr std::size_t kMaxUavs = 256;        // "uavs": 1 to kMaxUavs elements
constexpr std::size_t kMaxTargets = 100000;  // "targets": 0 to kMaxTargets elements

/// "occluders" read as the text is parsed: each entry is at least one tree of the tree budget
/// (`tree_limit` trees), so a list of more entries is refused before it is built.
ArrayLimit occluderListLimit(double tree_limit);

/// Applies one "dotted.path=value" override to the raw document.
void applyOverride(Json& document, const std::string& assignment);

/// A scripted UAV path's altitude at one of its points (issue 53), and the field that gave it.
struct ScriptedAltitude {
  world::TimedAltitude point;
  Field field;
};

/// altitudes: when given (a UAV's path), a waypoint may give "z" and a track row [t, x, y, z];
/// each appended here. Without it (a target's or a ground robot's path) neither is accepted.
world::Path readPath(const Field& field, const Aabb& aoi, double duration, bool check_inside,
                     std::vector<ScriptedAltitude>* altitudes = nullptr);
void readUavs(ObjectReader& root, ScenarioSpec& spec);
/// Returns each target's label name (ids are assigned once all labels are known).
std::vector<std::string> readTargets(ObjectReader& root, ScenarioSpec& spec);
/// Reads the occluder list (explicit trees, generators, includes); appends to spec.trees.
/// `effective` receives the flattened effective list (includes inlined).
/// `sources`, when given, receives one line per included layout that records its source (a
/// layout made by `canopy import`): what it holds and where from.
void readOccluders(const Field& list, const Aabb& aoi, std::vector<world::TreeDef>& trees,
                   Json& effective, std::vector<std::string>& include_stack,
                   std::vector<std::string>* sources = nullptr);
/// A layout's "footpaths": polylines of at least two points [[x, y], …] (m).
std::vector<std::vector<Vec2>> readFootpathLines(const Field& list);
/// The footpaths of the layout file `name_field` names (resolved as an include is).
std::vector<std::vector<Vec2>> readLayoutFootpaths(const Field& name_field);

/// Returns the clutter label's name.
std::string readSensing(ObjectReader& root, ScenarioSpec& spec);
void readTracking(ObjectReader& root, ScenarioSpec& spec);
void readFusion(ObjectReader& root, ScenarioSpec& spec);
void readPlanner(ObjectReader& root, ScenarioSpec& spec);
void readAnalysis(ObjectReader& root, ScenarioSpec& spec);

/// Index of the UAV or target named by `field` (a name or an index).
int uavIndex(const Field& field, const ScenarioSpec& spec);
int targetIndex(const Field& field, const ScenarioSpec& spec);

}  // namespace canopy::spec::internal
