#include "fuzz/inputs.h"

#include <stdlib.h>

#include <algorithm>
#include <fstream>
#include <stdexcept>
#include <string>

#include "experiments/sweep.h"
#include "experiments/trial.h"
#include "render/coverage_check.h"
#include "replay/run_folder.h"
#include "sim/compact_record.h"
#include "sim/record_line.h"
#include "sim/step_columns.h"
#include "sim/record_reader.h"
#include "sim/run.h"
#include "spec/error.h"
#include "spec/json_text.h"
#include "spec/loader.h"
#include "spec/track_csv.h"

namespace canopy::fuzz {
namespace fs = std::filesystem;
namespace {

class Sandbox {
 public:
  Sandbox() {
    std::string pattern = (fs::temp_directory_path() / "canopy-fuzz-XXXXXX").string();
    if (::mkdtemp(pattern.data()) == nullptr)
      throw std::runtime_error("cannot create a folder under " +
                               fs::temp_directory_path().string());
    dir_ = pattern;
    write("track.csv", "t,x,y\n0,-10,-12\n6,-4,-14\n12,2,-10\n");
    write("layouts/grove.json",
          R"({"occluders": [{"type": "disc", "centre": [0, 5], "radius": 3.0},)"
          R"( {"type": "grid", "origin": [-40, -30], "spacing": [8, 0], "rows": 1, "cols": 5,)"
          R"( "radius": [1.5, 2.5], "jitter": 0.5, "seed": 3}]})");
  }
  ~Sandbox() {
    std::error_code error;
    fs::remove_all(dir_, error);
  }
  Sandbox(const Sandbox&) = delete;
  Sandbox& operator=(const Sandbox&) = delete;

  const fs::path& dir() const { return dir_; }

 private:
  void write(const std::string& name, const std::string& text) {
    fs::create_directories((dir_ / name).parent_path());
    std::ofstream(dir_ / name, std::ios::binary) << text;
  }
  fs::path dir_;
};

}  // namespace

const fs::path& sandboxDir() {
  static const Sandbox sandbox;
  return sandbox.dir();
}

bool loadScenarioInput(std::string_view data) {
  const std::size_t nul = data.find('\0');
  const std::string text(data.substr(0, nul));
  spec::LoadOptions options;
  if (nul != std::string_view::npos) {
    std::string_view rest = data.substr(nul + 1);
    while (!rest.empty()) {
      const std::size_t end = rest.find('\n');
      if (end != 0) options.overrides.emplace_back(rest.substr(0, end));
      rest = end == std::string_view::npos ? std::string_view() : rest.substr(end + 1);
    }
  }
  try {
    spec::loadScenarioText(text, (sandboxDir() / "scenario.json").string(), options);
  } catch (const spec::ScenarioError&) {
    return false;
  }
  return true;
}

bool loadSweepInput(std::string_view data) {
  try {
    const experiments::SweepSpec sweep =
        experiments::loadSweepText(std::string(data), (sandboxDir() / "sweep.json").string());
    experiments::configurations(sweep);
  } catch (const spec::ScenarioError&) {
    return false;
  }
  return true;
}

bool parseTrackInput(std::string_view data) {
  try {
    spec::parseTrackCsv(std::string(data), (sandboxDir() / "track.csv").string());
  } catch (const spec::ScenarioError&) {
    return false;
  }
  return true;
}

namespace {

void writeFile(const fs::path& path, std::string_view bytes) {
  std::ofstream(path, std::ios::binary | std::ios::trunc)
      .write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

// The demo's effective configuration, loaded once.
const spec::ScenarioSpec& demo() {
  static const spec::ScenarioSpec spec = spec::loadScenario("demo");
  return spec;
}

}  // namespace

bool readResultInput(std::string_view data) {
  if (data.empty()) return false;
  const int kind = static_cast<unsigned char>(data[0]) % 5;
  const std::string_view bytes = data.substr(1);
  const fs::path dir = sandboxDir() / "result";
  fs::create_directories(dir);
  try {
    switch (kind) {
      case 0:
        writeFile(dir / "manifest.json", bytes);
        sim::readManifest(dir / "manifest.json");
        break;
      case 1:
        writeFile(dir / "record.jsonl", bytes);
        sim::readRecordTruth(dir / "record.jsonl", demo());
        break;
      case 2:
        experiments::trialFromJson(std::string(bytes), (dir / "trial_0000.json").string());
        break;
      case 3: {
        const std::string actual =
            "step,t,covered_px,visible_px,aoi_px,covered_fraction\n0,0,1,1,100,0.01\n"
            "1,0.2,2,1,100,0.02\n";
        const render::CoverageComparison result = render::compareCoverageCsv(
            std::string(bytes), actual, render::kDefaultCoverageTolerance, 5, "golden.csv");
        if (!result.bad_input.empty()) return false;
        if (result.first.size() > 5) throw std::logic_error("more differences listed than asked");
        for (const std::string& line : result.first)
          if (line.size() > 2 * render::kMaxListedLine)
            throw std::logic_error("a listed difference longer than its bound");
        break;
      }
      default:
        writeFile(dir / "sweep.json", bytes);
        experiments::loadSweepText(
            spec::readResultText(dir / "sweep.json", "the sweep.json of a sweep"),
            (dir / "sweep.json").string());
        break;
    }
  } catch (const spec::ScenarioError&) {
    return false;
  }
  return true;
}

namespace {

// The steps the truth reader reads from `path`, or −1 when it refuses the file.
long stepsRead(const fs::path& path) {
  try {
    return static_cast<long>(sim::readRecordTruth(path, demo()).size());
  } catch (const spec::ScenarioError&) {
    return -1;
  }
}

}  // namespace

bool readRecordInput(std::string_view data) {
  const fs::path dir = sandboxDir() / "record";
  fs::create_directories(dir);
  writeFile(dir / "record.jsonl", data);
  const long plain = stepsRead(dir / "record.jsonl");
  // The same lines in the compact form are read alike: the same steps, or refused too.
  std::string lines(data);
  if (!lines.empty() && lines.back() != '\n') lines += '\n';
  writeFile(dir / "record.jsonl.zst", sim::compactRecordOf(lines, {4096, 3}));
  if (stepsRead(dir / "record.jsonl.zst") != plain)
    throw std::logic_error("the compact record read otherwise than its plain lines");
  // The bytes themselves as a compact record: refused or read, never a crash.
  writeFile(dir / "raw.jsonl.zst", data);
  stepsRead(dir / "raw.jsonl.zst");
  // The bytes as a block of step columns (index version 2's content): decoded or refused.
  try {
    sim::StepColumnDecoder steps(data);
    sim::RecordLineWriter writer(steps.labels());
    sim::StepRecord step;
    std::string line;
    while (steps.next(step)) {
      line.clear();
      writer.write(step, line);
    }
  } catch (const std::exception&) {
  }
  return plain >= 0;
}

bool readReplayInput(std::string_view data) {
  const fs::path dir = sandboxDir() / "replay";
  if (!fs::exists(dir / "manifest.json")) {
    fs::create_directories(dir);
    writeFile(dir / "manifest.json", sim::manifestJson(demo(), "fuzz") + "\n");
  }
  const std::size_t nul = data.find('\0');
  const std::string_view record = data.substr(0, nul);
  writeFile(dir / "record.jsonl", record);
  if (nul != std::string_view::npos) {
    writeFile(dir / "summary.json", data.substr(nul + 1));
  } else {
    std::size_t lines = 0;  // as sim::forEachRecordLine counts them: the non-blank ones
    for (std::size_t at = 0; at < record.size();) {
      const std::size_t end = std::min(record.find('\n', at), record.size());
      if (record.substr(at, end - at).find_first_not_of(" \t\r") != std::string_view::npos) ++lines;
      at = end + 1;
    }
    std::string ospa = "[";
    for (std::size_t k = 0; k < lines; ++k) ospa += k ? ",0" : "0";
    std::string summary = "{\"uavs\": [";
    for (std::size_t i = 0; i < demo().uavs.size(); ++i)
      summary += std::string(i ? ", " : "") + "{\"ospa_m\": " + ospa + "]}";
    writeFile(dir / "summary.json", summary + "]}\n");
  }
  try {
    replay::readRunFolder(dir);
  } catch (const spec::ScenarioError&) {
    return false;
  }
  return true;
}

bool pythonEditInput(std::string_view data) {
  const std::size_t newline = data.find('\n');
  const std::string path(data.substr(0, newline));
  const std::string value_text(newline == std::string_view::npos ? std::string_view()
                                                                 : data.substr(newline + 1));
  spec::Json config = spec::parseBoundedJson(demo().effective_config);
  spec::Json value;
  try {
    value = spec::parseBoundedJson(value_text);
  } catch (const std::exception&) {
    return false;  // Python would not get here: its value is a Python object, always JSON
  }
  // A Python str is text: a path that is not valid UTF-8 cannot be typed (json.dumps would
  // escape what it holds; the loader then refuses the escape).
  try {
    (void)spec::Json(path).dump();
  } catch (const spec::Json::type_error&) {
    return false;
  }
  // Python's Scenario._parent: walk the dotted path; the last part is set.
  spec::Json* node = &config;
  std::size_t start = 0;
  for (;;) {
    const std::size_t dot = path.find('.', start);
    const std::string part = path.substr(start, dot == std::string::npos ? dot : dot - start);
    spec::Json* next = nullptr;
    if (node->is_array()) {
      if (part.empty() || part.size() > 9 ||
          part.find_first_not_of("0123456789") != std::string::npos)
        return false;  // KeyError in Python
      const std::size_t index = std::stoul(part);
      if (index >= node->size()) return false;
      next = &(*node)[index];
    } else if (node->is_object()) {
      if (dot != std::string::npos && !node->contains(part)) return false;
      next = &(*node)[part];
    } else {
      return false;
    }
    if (dot == std::string::npos) {
      *next = std::move(value);
      break;
    }
    node = next;
    start = dot + 1;
  }
  try {
    spec::loadScenarioText(config.dump(), "<python>");
  } catch (const spec::ScenarioError&) {
    return false;
  }
  return true;
}

const std::vector<Target>& targets() {
  static const std::vector<Target> all = {
      {"scenario_loader", &loadScenarioInput}, {"sweep_loader", &loadSweepInput},
      {"track_csv", &parseTrackInput},         {"result_files", &readResultInput},
      {"record_reader", &readRecordInput},     {"replay_reader", &readReplayInput},
      {"python_edits", &pythonEditInput}};
  return all;
}

}  // namespace canopy::fuzz
