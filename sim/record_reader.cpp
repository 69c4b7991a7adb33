#include "sim/record_reader.h"

#include <climits>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>

#include "core/text_file.h"
#include "spec/error.h"
#include "spec/json_text.h"
#include "spec/loader.h"
#include "spec/result_lines.h"

namespace canopy::sim {
namespace {

namespace fs = std::filesystem;
using spec::Json;
using spec::ScenarioError;

// Bounded like a scenario file: a regular file (not a FIFO, device, directory or link) of at
// most kMaxJsonBytes.
std::string readResultFile(const fs::path& path, const std::string& what) {
  return spec::readResultText(path, "the " + what + " that `canopy run` writes",
                              spec::kMaxJsonBytes);
}

// One record line's field, or a ScenarioError naming the line and the field.
class LineReader {
 public:
  LineReader(const fs::path& file, int line) : file_(file.string()), line_(line) {}

  [[noreturn]] void fail(const std::string& field, const std::string& expected) const {
    throw ScenarioError(file_,
                        "line " + std::to_string(line_) + (field.empty() ? "" : ": " + field),
                        "expected " + expected);
  }
  const Json& member(const Json& object, const std::string& key, const std::string& path) const {
    if (!object.is_object() || !object.contains(key)) fail(path, "a field '" + key + "'");
    return object[key];
  }
  double number(const Json& value, const std::string& path) const {
    if (!value.is_number()) fail(path, "a number");
    return value.get<double>();
  }
  Vec2 point(const Json& value, const std::string& path) const {
    if (!value.is_array() || value.size() != 2 || !value[0].is_number() || !value[1].is_number()) {
      fail(path, "[x, y] (two numbers)");
    }
    return {value[0].get<double>(), value[1].get<double>()};
  }
  // "wall:K", "trunk:K" or "uav:J" (sim/recorder.cpp).
  world::BodyRef contact(const Json& value, const std::string& path) const {
    static const std::pair<const char*, world::BodyKind> kKinds[] = {
        {"wall:", world::BodyKind::wall},
        {"trunk:", world::BodyKind::trunk},
        {"uav:", world::BodyKind::uav}};
    if (value.is_string()) {
      const std::string& text = value.get_ref<const std::string&>();
      for (const auto& [prefix, kind] : kKinds) {
        const std::size_t n = std::strlen(prefix);
        if (text.compare(0, n, prefix) != 0 || text.size() == n || text.size() > n + 9) continue;
        if (text.find_first_not_of("0123456789", n) != std::string::npos) continue;
        return {kind, std::stoi(text.substr(n))};
      }
    }
    fail(path, "\"wall:K\", \"trunk:K\" or \"uav:J\"");
  }
  const Json& list(const Json& object, const std::string& key, std::size_t size) const {
    const Json& value = member(object, key, key);
    if (!value.is_array() || value.size() != size) {
      fail(key, "a list of " + std::to_string(size) + " entries (as in the manifest's scenario)");
    }
    return value;
  }

 private:
  std::string file_;
  int line_;
};

}  // namespace

spec::ScenarioSpec readManifest(const fs::path& path) {
  const Json manifest = spec::parseJson(readResultFile(path, "manifest"), path.string());
  if (!manifest.is_object() || !manifest.contains("effective_config") ||
      !manifest["effective_config"].is_object()) {
    throw ScenarioError(path.string(), "effective_config",
                        "expected an object (the run's scenario)");
  }
  return spec::loadScenarioText(manifest["effective_config"].dump(),
                                path.string() + ": effective_config");
}

std::vector<world::WorldSnapshot> readRecordTruth(const fs::path& path,
                                                  const spec::ScenarioSpec& spec,
                                                  const LineRange& range) {
  std::vector<world::WorldSnapshot> steps;
  forEachRecordLine(path, range, [&](const std::string& line, int number) {
    const LineReader r(path, number);
    if (line.size() > spec::kMaxResultLineBytes)
      r.fail("", "a line of at most 256 MiB (one step of `canopy run`)");
    const std::optional<Json> parsed = spec::parseResultLine(line);  // std::bad_alloc: exit 1
    if (!parsed) {
      r.fail("", "one JSON object per line, nested at most " + std::to_string(spec::kMaxJsonDepth) +
                     " levels deep");
    }
    const Json& json = *parsed;
    if (!json.is_object()) r.fail("", "one JSON object per line");
    world::WorldSnapshot& s = steps.emplace_back();
    // Read as 64 bits, then narrowed: a step index of 2³² + 1 is refused, not read as 1.
    const std::optional<std::int64_t> k = spec::integerWithin(r.member(json, "k", "k"), 0, INT_MAX);
    if (!k) r.fail("k", "an integer step index from 0 to 2³¹ − 1");
    s.step = static_cast<int>(*k);
    s.time = r.number(r.member(json, "t", "t"), "t");
    const Json& uavs = r.list(json, "uavs", spec.uavs.size());
    for (std::size_t i = 0; i < uavs.size(); ++i) {
      const std::string at = "uavs." + std::to_string(i);
      world::UavState& uav = s.uavs.emplace_back();
      uav.position = r.point(r.member(uavs[i], "p", at + ".p"), at + ".p");
      uav.yaw = r.number(r.member(uavs[i], "yaw", at + ".yaw"), at + ".yaw");
      // A UAV with an altitude (issue 53) records it; the others fly at their fixed one.
      uav.z = spec.uavs[i].sensor.camera
                  ? r.number(r.member(uavs[i], "z", at + ".z"), at + ".z")
                  : spec.uavs[i].body.z;
      if (uavs[i].is_object() && uavs[i].contains("contacts")) {  // only at steps with one
        const Json& list = uavs[i]["contacts"];
        if (!list.is_array()) r.fail(at + ".contacts", "a list of \"kind:index\" strings");
        for (const Json& c : list) uav.contacts.push_back(r.contact(c, at + ".contacts"));
      }
    }
    const Json& targets = r.list(json, "targets", spec.targets.size());
    for (std::size_t t = 0; t < targets.size(); ++t) {
      const std::string at = "targets." + std::to_string(t) + ".p";
      s.targets.emplace_back().position = r.point(r.member(targets[t], "p", at), at);
    }
  });
  if (steps.empty()) throw ScenarioError(path.string(), "", "has no steps");
  return steps;
}

RunRecord readRun(const fs::path& run_dir, const LineRange& range) {
  std::error_code error;
  if (!fs::is_directory(run_dir, error)) {
    throw ScenarioError(run_dir.string(), "",
                        "no such directory (expected the --out directory of `canopy run`)");
  }
  RunRecord run;
  run.spec = readManifest(run_dir / "manifest.json");
  run.truth = readRecordTruth(recordFileOf(run_dir), run.spec, range);
  return run;
}

}  // namespace canopy::sim
