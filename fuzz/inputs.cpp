#include "fuzz/inputs.h"

#include <stdlib.h>

#include <fstream>
#include <stdexcept>
#include <string>

#include "experiments/sweep.h"
#include "spec/error.h"
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

const std::vector<Target>& targets() {
  static const std::vector<Target> all = {{"scenario_loader", &loadScenarioInput},
                                          {"sweep_loader", &loadSweepInput},
                                          {"track_csv", &parseTrackInput}};
  return all;
}

}  // namespace canopy::fuzz
