#pragma once
// What the loader reads, field by field: each read names its path, JSON type, accepted range and
// the default used when the field is absent. Filled while loading when LoadOptions::field_log is
// set; spec/schema.h turns it into the JSON Schema and the reference page.
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace canopy::spec {

/// What the loader read of one object in one file ("uavs[2]" of demo.json): the members it
/// required, every member it asked for, and the spelling a choice member had (or defaulted to).
/// The schema groups an object's instances by what they require, so that the variants of an
/// object (a disc or a grid occluder, a radius or a size footprint) are described apart.
struct ObjectShape {
  std::set<std::string> required;
  std::set<std::string> allowed;
  std::map<std::string, std::string> choices;
};

struct FieldInfo {
  std::string path;   // "uavs[].v_max" (every index written [])
  std::string type;   // number, integer, boolean, string, array, object
  std::string range;  // "> 0", "[0, 1]", "[1, 50]", "" for any
  std::optional<std::string>
      default_json;                  // the default as JSON text, when the field may be absent
  std::vector<std::string> choices;  // the spellings a string may take, if restricted
  bool required = false;             // read with no default
  bool default_varies = false;       // the default depends on the file (a name from its index, …)
  bool range_varies = false;  // the range depends on the file (a list as long as the UAVs, …)
  std::map<std::string, ObjectShape> instances;  // an object's instances, by "file#path"
};

/// Keyed by path; a field read several times (several UAVs) is one entry.
using FieldLog = std::map<std::string, FieldInfo>;

/// "uavs[0].path.waypoints[3]" → "uavs[].path.waypoints[]".
std::string fieldPattern(const std::string& path);

}  // namespace canopy::spec
