#include "replay/run_folder.h"

#include <climits>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>

#include "core/text_file.h"
#include "sim/record_reader.h"
#include "spec/error.h"
#include "spec/json_text.h"
#include "spec/result_lines.h"

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

// Fields of one record line, each failure a ScenarioError naming the file, line and field.
class LineReader {
 public:
  LineReader(const fs::path& file, int line) : file_(file.string()), line_(line) {}

  [[noreturn]] void fail(const std::string& field, const std::string& expected) const {
    throw ScenarioError(file_,
                        "line " + std::to_string(line_) + (field.empty() ? "" : ": " + field),
                        "expected " + expected);
  }
  const Json& member(const Json& object, const char* key, const std::string& at) const {
    if (!object.is_object() || !object.contains(key))
      fail(at, std::string("a field '") + key + "'");
    return object[key];
  }
  double number(const Json& object, const char* key, const std::string& at) const {
    const Json& value = member(object, key, at);
    if (!value.is_number()) fail(at + "." + key, "a number");
    return value.get<double>();
  }
  // Read as 64 bits, then narrowed: 2³² + 1 is refused, not read as 1.
  int integer(const Json& value, const std::string& at, int lo = INT_MIN, int hi = INT_MAX,
              const std::string& expected = "an integer") const {
    const std::optional<std::int64_t> x = spec::integerWithin(value, lo, hi);
    if (!x) fail(at, expected);
    return static_cast<int>(*x);
  }
  Vec2 point(const Json& value, const std::string& at) const {
    if (!value.is_array() || value.size() != 2 || !value[0].is_number() || !value[1].is_number())
      fail(at, "[x, y] (two numbers)");
    return {value[0].get<double>(), value[1].get<double>()};
  }
  const Json& array(const Json& object, const char* key, const std::string& at) const {
    const Json& value = member(object, key, at);
    if (!value.is_array()) fail(at + "." + key, "a list");
    return value;
  }
  std::vector<double> numbers(const Json& value, std::size_t size, const std::string& at) const {
    if (!value.is_array() || value.size() != size)
      fail(at, "a list of " + std::to_string(size) + " numbers");
    std::vector<double> out;
    for (const Json& x : value) {
      if (!x.is_number()) fail(at, "a list of " + std::to_string(size) + " numbers");
      out.push_back(x.get<double>());
    }
    return out;
  }
  std::vector<Vec2> points(const Json& object, const char* key, const std::string& at) const {
    std::vector<Vec2> out;
    const Json& list = array(object, key, at);
    for (std::size_t i = 0; i < list.size(); ++i)
      out.push_back(point(list[i], at + "." + key + "." + std::to_string(i)));
    return out;
  }
  std::vector<int> indices(const Json& object, const char* key, int limit,
                           const std::string& at) const {
    std::vector<int> out;
    for (const Json& x : array(object, key, at))
      out.push_back(integer(x, at + "." + key, 0, limit - 1,
                            "target indices below " + std::to_string(limit)));
    return out;
  }
  std::string key(const Json& value, const std::string& at) const {
    constexpr std::int64_t kMin = INT64_MIN, kMax = INT64_MAX;
    const std::optional<std::int64_t> origin = value.is_array() && value.size() == 2
                                                   ? spec::integerWithin(value[0], kMin, kMax)
                                                   : std::nullopt;
    const std::optional<std::int64_t> serial =
        origin ? spec::integerWithin(value[1], kMin, kMax) : std::nullopt;
    if (!serial) fail(at, "a key [origin, serial] (two 64-bit integers)");
    return std::to_string(*origin) + ":" + std::to_string(*serial);
  }

 private:
  std::string file_;
  int line_;
};

RecordedTrack track(const LineReader& r, const Json& json, const std::string& at) {
  RecordedTrack t;
  t.key = r.key(r.member(json, "key", at), at + ".key");
  const Json& label = r.member(json, "label", at);
  if (!label.is_string()) r.fail(at + ".label", "a label");
  t.label = label.get<std::string>();
  const std::vector<double> x = r.numbers(r.member(json, "x", at), 4, at + ".x");
  const std::vector<double> P = r.numbers(r.member(json, "P", at), 10, at + ".P");
  t.position = {x[0], x[1]};
  t.velocity = {x[2], x[3]};
  t.P_pos = {P[0], P[1], P[4]};  // [P00, P01, P02, P03, P11, …]: P00, P01, P11
  return t;
}

RecordedMapEntry mapEntry(const LineReader& r, const Json& json, const std::string& at) {
  RecordedMapEntry e;
  e.key = r.key(r.member(json, "key", at), at + ".key");
  const std::vector<double> x = r.numbers(r.member(json, "x", at), 3, at + ".x");
  e.crown = {x[0], x[1], x[2]};
  if (json.contains("outline")) e.outline = r.points(json, "outline", at);
  return e;
}

RecordedPlan plan(const LineReader& r, const Json& json, int agents) {
  RecordedPlan p;
  p.epoch = r.integer(r.member(json, "epoch", "plan"), "plan.epoch");
  const Json& parts = r.array(json, "agents", "plan");
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const std::string at = "plan.agents." + std::to_string(i);
    RecordedPlan::Part& part = p.agents.emplace_back();
    part.agent = r.integer(r.member(parts[i], "agent", at), at + ".agent");
    if (part.agent < 0 || part.agent >= agents) r.fail(at + ".agent", "an agent index");
    part.cost = r.number(parts[i], "cost", at);
    part.velocities = r.points(parts[i], "velocities", at);
    const Json& joint = r.array(parts[i], "joint_epoch", at);
    for (const Json& e : joint) part.joint_epoch.push_back(r.integer(e, at + ".joint_epoch"));
    if (static_cast<int>(part.joint_epoch.size()) != agents)
      r.fail(at + ".joint_epoch", "one epoch per agent");
  }
  const Json& messages = r.array(json, "messages", "plan");
  for (std::size_t i = 0; i < messages.size(); ++i) {
    const std::string at = "plan.messages." + std::to_string(i);
    RecordedPlan::Message& m = p.messages.emplace_back();
    m.agent = r.integer(r.member(messages[i], "agent", at), at + ".agent");
    m.from = r.integer(r.member(messages[i], "from", at), at + ".from");
    if (m.agent < 0 || m.agent >= agents || m.from < 0 || m.from >= agents)
      r.fail(at, "agent indices below " + std::to_string(agents));
    m.epoch = r.integer(r.member(messages[i], "epoch", at), at + ".epoch");
    m.velocities = r.points(messages[i], "velocities", at);
  }
  return p;
}

RecordedStep step(const LineReader& r, const Json& json, const spec::ScenarioSpec& spec) {
  RecordedStep s;
  s.k = r.integer(r.member(json, "k", ""), "k", 0, INT_MAX, "a step index from 0 to 2³¹ − 1");
  s.t = r.number(json, "t", "");
  const int agents = static_cast<int>(spec.uavs.size());
  const int targets = static_cast<int>(spec.targets.size());
  const Json& truth = r.array(json, "targets", "");
  if (static_cast<int>(truth.size()) != targets)
    r.fail("targets", "one entry per target of the manifest's scenario");
  for (std::size_t t = 0; t < truth.size(); ++t) {
    const std::string at = "targets." + std::to_string(t);
    s.targets.push_back(r.point(r.member(truth[t], "p", at), at + ".p"));
  }
  const Json& uavs = r.array(json, "uavs", "");
  const Json& scans = r.array(json, "scans", "");
  const Json& beliefs = r.array(json, "agents", "");
  if (static_cast<int>(uavs.size()) != agents || scans.size() != uavs.size() ||
      beliefs.size() != uavs.size())
    r.fail("uavs", "uavs, scans and agents with one entry per UAV of the manifest's scenario");
  for (int i = 0; i < agents; ++i) {
    const std::size_t n = static_cast<std::size_t>(i);
    const std::string id = std::to_string(i);
    RecordedAgent& a = s.agents.emplace_back();
    a.position = r.point(r.member(uavs[n], "p", "uavs." + id), "uavs." + id + ".p");
    a.yaw = r.number(uavs[n], "yaw", "uavs." + id);
    if (uavs[n].is_object() && uavs[n].contains("z")) a.z = r.number(uavs[n], "z", "uavs." + id);
    if (uavs[n].is_object() && uavs[n].contains("contacts")) {  // only at steps with one
      const Json& contacts = uavs[n]["contacts"];
      if (!contacts.is_array()) r.fail("uavs." + id + ".contacts", "a list of names");
      for (const Json& c : contacts) {
        if (!c.is_string() || c.get_ref<const std::string&>().size() > 32)
          r.fail("uavs." + id + ".contacts", "names such as \"wall:3\"");
        a.contacts.push_back(c.get<std::string>());
      }
    }
    a.in_footprint = r.indices(scans[n], "in_footprint", targets, "scans." + id);
    a.visible = r.indices(scans[n], "visible", targets, "scans." + id);
    const std::string at = "agents." + id;
    const Json& tracks = r.array(beliefs[n], "tracks", at);
    for (std::size_t j = 0; j < tracks.size(); ++j)
      a.tracks.push_back(track(r, tracks[j], at + ".tracks." + std::to_string(j)));
    const Json& map = r.array(beliefs[n], "map", at);
    for (std::size_t j = 0; j < map.size(); ++j)
      a.map.push_back(mapEntry(r, map[j], at + ".map." + std::to_string(j)));
    a.planned_path = r.points(beliefs[n], "planned_path", at);
  }
  if (json.contains("plan")) s.plan = plan(r, json["plan"], agents);
  return s;
}

std::vector<RecordedStep> readRecord(const fs::path& path, const spec::ScenarioSpec& spec) {
  std::vector<RecordedStep> steps;
  sim::forEachRecordLine(path, {}, [&](const std::string& line, int number) {
    const LineReader r(path, number);
    if (line.size() > spec::kMaxResultLineBytes)
      r.fail("", "a line of at most 256 MiB (one step of `canopy run`)");
    const std::optional<Json> json = spec::parseResultLine(line);  // std::bad_alloc: exit 1
    if (!json || !json->is_object()) r.fail("", "one JSON object per line");
    steps.push_back(step(r, *json, spec));
    if (steps.back().k != static_cast<int>(steps.size()) - 1)
      r.fail("k", "step " + std::to_string(steps.size() - 1) + " (one line per step, in order)");
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
